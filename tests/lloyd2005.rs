//! Lloyd, Yoon, Tuft & Manocha 2005, "Subdivided Shadow Maps" (UNC TR05-024): every closed
//! form against the measured warping frustum (near = 1, far = α), against Lloyd 2006's
//! general-n forms, and the errata.

use proptest::prelude::*;
use shadow_aliasing::analytic::eta::n_prime_from_eta;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::analytic::subdivided::{
    allocate_texels, allocate_texels_whole, distribution_g, error_m, face_subdivision_planes,
    g_min, max_error, max_error_depth, max_mx_normalised, mx_normalised, n_from_xi, n_opt,
    subdivided_max_error, xi_from_n,
};
use shadow_aliasing::measure::twin::overhead_map;
use shadow_aliasing::measure::{frustum_max, point_error, ShadowMap};
use shadow_aliasing::{NPrime, Resolutions, ViewFrustum};
mod common;
use common::{any_f64, close, config, REL};

/// α log-uniform in [1.01, 10⁴].
fn alpha() -> impl Strategy<Value = f64> {
    (0.0043f64..4.0).prop_map(|l| 10f64.powf(l))
}

fn half_fov() -> impl Strategy<Value = f64> {
    (1.0f64..80.0).prop_map(f64::to_radians)
}

fn xi() -> impl Strategy<Value = f64> {
    prop_oneof![7 => -0.999f64..=1.0, 1 => Just(-1.0)]
}

/// The measured error of the normalised frustum [1, α] warped with n at depth z, on the view
/// axis: (m_x, m_z).
fn measured(alpha: f64, th: f64, n: NPrime, z: f64, res: Resolutions) -> (f64, f64) {
    let v = ViewFrustum::new(1.0, alpha, th).unwrap();
    let map = overhead_map(&v, n).unwrap();
    let p = point_error(&v, &map, glam::DVec3::new(0.0, 0.0, -z), res).unwrap();
    (p.mx, p.mz)
}

proptest! {
    #![proptest_config(config(128))]

    /// Eq 2, 3: m = (r_p/r_s)(α − 1)/(2 tan θ) g(z) is the measured error along the warp
    /// (the crate's m_z with res_t = r_s); Eq 8 is the measured x error (res_s = r_t).
    #[test]
    fn eq2_eq3_eq8_equal_the_measured_warp(
        a in alpha(), th in half_fov(), x in xi(), fz in 0.0f64..=1.0,
        rp in 1.0f64..4096.0, rs in 1.0f64..4096.0, rt in 1.0f64..4096.0,
    ) {
        let n = n_from_xi(a, x).unwrap();
        let z = (1.0 + fz * (a - 1.0)).min(a);
        let (mx_m, mz_m) = measured(a, th, n, z, Resolutions::new(rp, rt, rs).unwrap());
        let m = error_m(a, th, n, z, rp, rs).unwrap();
        prop_assert!(close(m, mz_m, REL), "Eq 2 {m} measured {mz_m}");
        let g = distribution_g(a, n, z).unwrap();
        prop_assert!(close(g, mz_m * rs / rp * 2.0 * th.tan() / (a - 1.0), REL));
        let cx = mx_normalised(a, n, z, rp, rt).unwrap();
        prop_assert!(close(cx, mx_m, REL), "Eq 8 {cx} measured {mx_m}");
    }

    /// Eq 5 and Eq 9: the measured maxima over the frustum vertices with n = n(ξ) (Eq 4).
    #[test]
    fn eq5_eq9_equal_the_measured_maxima(a in alpha(), th in half_fov(), x in xi()) {
        let n = n_from_xi(a, x).unwrap();
        let v = ViewFrustum::new(1.0, a, th).unwrap();
        let m = frustum_max(&v, &overhead_map(&v, n).unwrap()).unwrap();
        let e5 = max_error(a, th, x, 1.0, 1.0).unwrap();
        prop_assert!(close(e5, m.max_mz, REL), "Eq 5 {e5} measured {}", m.max_mz);
        let e9 = max_mx_normalised(a, x, 1.0, 1.0).unwrap();
        prop_assert!(close(e9, m.max_mx, REL), "Eq 9 {e9} measured {}", m.max_mx);
    }

    /// §3.2: ξ(n(ξ)) = ξ; and ξ is the linear interpolation of max g that defines it, with g
    /// measured: g = m_z 2 tan θ/(α − 1) (Eq 2, unit resolutions) on the view axis at the near
    /// plane (n ≥ n_opt, ξ ≤ 0) or the far plane (ξ > 0) of the frustum [near, near·α] warped
    /// with n′ = n(ξ)·near, and g₀ = 1/√α (§3.1), for any near: n(ξ) scaled by near has the
    /// measured ξ at every scale.
    #[test]
    fn xi_roundtrip_and_definition_from_the_measured_g(
        a in alpha(), th in half_fov(), x in xi(), near in 0.01f64..10.0,
    ) {
        let n = n_from_xi(a, x).unwrap();
        prop_assert!((xi_from_n(a, n).unwrap() - x).abs() < 1e-9);
        let np = match n.as_finite() {
            Some(v) => NPrime::finite(v * near).unwrap(),
            None => n,
        };
        let v = ViewFrustum::new(near, near * a, th).unwrap();
        let g_at = |map: &ShadowMap, z: f64| {
            let m = point_error(&v, map, glam::DVec3::new(0.0, 0.0, -z), Resolutions::default());
            m.unwrap().mz * 2.0 * th.tan() / (a - 1.0)
        };
        let map = overhead_map(&v, np).unwrap();
        let g0 = 1.0 / a.sqrt();
        let def = if x <= 0.0 {
            (g0 - g_at(&map, v.near())) / (1.0 - g0)
        } else {
            (g_at(&map, v.far()) - g0) / (1.0 - g0)
        };
        prop_assert!((def - x).abs() < 1e-6, "definition from the measured g {def} vs ξ {x}");
        // g₀ and n_opt (§3.1): warped with n′ = n_opt·near, the measured g is g₀ on both planes.
        let opt = overhead_map(&v, NPrime::finite(n_opt(a).unwrap() * near).unwrap()).unwrap();
        for z in [v.near(), v.far()] {
            let g = g_at(&opt, z);
            prop_assert!(close(g, g_min(a).unwrap(), REL) && close(g, g0, REL), "z = {z}: g {g}, g₀ {g0}");
        }
    }

    /// Lloyd 2005's normalised forms (near = 1, far = α) describe every frustum of ratio α:
    /// Eq 8 (m_x) and Eq 2 (m, here m_z) at depth z equal the errors measured at depth z·near
    /// (any x, y) on the frustum [near, near·α] warped with n′ = n·near, and Eq 5 its measured
    /// maximum M_z over the vertices (= Lloyd 2006 Eq 7, 8, 10, whose own twins are in
    /// tests/lloyd2006.rs).
    #[test]
    fn normalised_forms_equal_the_measured_warp_at_any_near(
        a in alpha(), th in half_fov(), x in xi(), near in 0.01f64..10.0, fz in 0.0f64..=1.0,
        fx in -1.0f64..=1.0, fy in -1.0f64..=1.0,
    ) {
        let n = n_from_xi(a, x).unwrap();
        let np = match n.as_finite() { Some(v) => NPrime::finite(v * near).unwrap(), None => n };
        let z = (1.0 + fz * (a - 1.0)).min(a);
        let v = ViewFrustum::new(near, near * a, th).unwrap();
        let map = overhead_map(&v, np).unwrap();
        let zz = (z * near).clamp(v.near(), v.far());
        let h = zz * v.tan_half_fov();
        let r = Resolutions::default();
        let m = point_error(&v, &map, glam::DVec3::new(fx * h, fy * h, -zz), r).unwrap();
        let eq8 = mx_normalised(a, n, z, 1.0, 1.0).unwrap();
        prop_assert!(close(eq8, m.mx, REL), "Eq 8 {eq8} measured {}", m.mx);
        let eq2 = error_m(a, th, n, z, 1.0, 1.0).unwrap();
        prop_assert!(close(eq2, m.mz, REL), "Eq 2 {eq2} measured {}", m.mz);
        let eq5 = max_error(a, th, x, 1.0, 1.0).unwrap();
        let measured = frustum_max(&v, &map).unwrap().max_mz;
        prop_assert!(close(eq5, measured, REL), "Eq 5 {eq5} measured {measured}");
    }

    /// Eq 7: k self-similar face subdivisions, each warped with the same ξ over its own range
    /// and given r_s/k texels, measured: every subdivision has the same maximum error (so Eq 6
    /// gives 1/k each), and that error is Eq 7.
    #[test]
    fn eq7_equals_the_measured_subdivisions(
        a in alpha(), th in half_fov(), x in xi(), k in 1usize..=8, rs in 1.0f64..4096.0,
    ) {
        let planes = face_subdivision_planes(a, k).unwrap();
        let mut errs = [0.0; 8];
        for (i, e) in errs.iter_mut().enumerate().take(k) {
            let (z0, z1) = planes.range(i);
            let sub = ViewFrustum::new(z0, z1, th).unwrap();
            let np = n_prime_from_eta(z0, z1, x).unwrap();
            *e = frustum_max(&sub, &overhead_map(&sub, np).unwrap()).unwrap().max_mz;
        }
        let mut alloc = [0.0; 8];
        allocate_texels(&errs[..k], rs, &mut alloc[..k]).unwrap();
        let want = subdivided_max_error(a, k, x, th, 1.0, rs).unwrap();
        for i in 0..k {
            prop_assert!(close(alloc[i], rs / k as f64, 1e-9), "allocation {} of {rs}", alloc[i]);
            // Error at r_si texels = error at 1 texel / r_si.
            prop_assert!(close(errs[i] / alloc[i], want, REL), "{} vs Eq 7 {want}", errs[i] / alloc[i]);
        }
    }

    /// Eq 6: the allocation sums to the total and equalises the measured maximum errors of
    /// subdivisions of different depth ratios (frustum subdivisions of different sizes).
    #[test]
    fn eq6_equalises_measured_errors(
        alphas in proptest::collection::vec(1.5f64..500.0, 1..6), th in half_fov(), x in xi(),
        total in 16.0f64..4096.0,
    ) {
        let k = alphas.len();
        let mut errs = [0.0; 6];
        for (e, &a) in errs.iter_mut().zip(&alphas) {
            let v = ViewFrustum::new(1.0, a, th).unwrap();
            *e = frustum_max(&v, &overhead_map(&v, n_from_xi(a, x).unwrap()).unwrap()).unwrap().max_mz;
        }
        let mut out = [0.0; 6];
        allocate_texels(&errs[..k], total, &mut out[..k]).unwrap();
        let sum: f64 = out[..k].iter().sum();
        prop_assert!(close(sum, total, 1e-12));
        for i in 0..k {
            let v = ViewFrustum::new(1.0, alphas[i], th).unwrap();
            let map = overhead_map(&v, n_from_xi(alphas[i], x).unwrap()).unwrap();
            let mut m = 0.0f64;
            for c in v.corners() {
                let r = Resolutions::new(1.0, 1.0, out[i]).unwrap();
                m = m.max(point_error(&v, &map, c, r).unwrap().mz);
            }
            let all: f64 = errs[..k].iter().sum::<f64>() / total;
            prop_assert!(close(m, all, REL), "subdivision {i}: {m} vs {all}");
        }
        let mut whole = [0u32; 6];
        allocate_texels_whole(&errs[..k], total as u32, &mut whole[..k]).unwrap();
        prop_assert_eq!(whole[..k].iter().map(|&w| u64::from(w)).sum::<u64>(), u64::from(total as u32));
    }

    /// Eq 6 with a different ξ_i in each subdivision (§4 assumes one ξ; §4.1 uses one): the
    /// allocation still equalises the measured maximum errors, and the common maximum is
    /// Σ_i m_max(α_i, ξ_i) (Eq 5 per subdivision, each with all the texels) — Eq 7
    /// is the special case α_i = α^{1/k}, ξ_i = ξ. "More texels to larger subdivisions" then no
    /// longer follows: α = (100, 50) with ξ = (0, 1) gives the smaller one 49/(9.9 + 49) = 83 %.
    #[test]
    fn eq6_equalises_measured_errors_with_a_xi_per_subdivision(
        parts in proptest::collection::vec((1.5f64..500.0, xi()), 1..6), th in half_fov(),
        total in 16.0f64..4096.0,
    ) {
        let k = parts.len();
        let mut errs = [0.0; 6];
        for (e, &(a, x)) in errs.iter_mut().zip(&parts) {
            *e = max_error(a, th, x, 1.0, 1.0).unwrap();
        }
        let mut out = [0.0; 6];
        allocate_texels(&errs[..k], total, &mut out[..k]).unwrap();
        let all: f64 = errs[..k].iter().sum::<f64>() / total;
        for (i, &(a, x)) in parts.iter().enumerate() {
            let v = ViewFrustum::new(1.0, a, th).unwrap();
            let map = overhead_map(&v, n_from_xi(a, x).unwrap()).unwrap();
            let r = Resolutions::new(1.0, 1.0, out[i]).unwrap();
            let mut m = 0.0f64;
            for c in v.corners() {
                m = m.max(point_error(&v, &map, c, r).unwrap().mz);
            }
            prop_assert!(close(m, all, REL), "subdivision {i}: {m} vs {all}");
        }
    }

    /// Eq 7 decreases with k for every ξ and tends to (r_p/r_s) ln α / (2 tan θ).
    #[test]
    fn eq7_decreases_in_k(a in 1.5f64..1e4, th in half_fov(), x in xi()) {
        let mut prev = f64::INFINITY;
        for k in 1..=32 {
            let e = subdivided_max_error(a, k, x, th, 1.0, 1.0).unwrap();
            prop_assert!(e < prev);
            prev = e;
        }
        let lim = a.ln() / (2.0 * th.tan());
        prop_assert!(prev > lim);
        let far = subdivided_max_error(a, 1 << 20, x, th, 1.0, 1.0).unwrap();
        prop_assert!(close(far, lim, 1e-5), "{far} vs {lim}");
    }
}

/// Hand values (α = 100): n_opt = 11, g₀ = 0.1, z_i = 100^{i/2} = 1, 10, 100.
#[test]
fn hand_values() {
    assert_eq!(n_opt(100.0).unwrap(), 11.0);
    assert_eq!(g_min(100.0).unwrap(), 0.1);
    assert_eq!(
        face_subdivision_planes(100.0, 2).unwrap().planes(),
        &[1.0, 10.0, 100.0]
    );
    assert_eq!(
        face_subdivision_planes(100.0, 2).unwrap(),
        z_splits(1.0, 100.0, 2, SplitScheme::SelfSimilar).unwrap()
    );
    // g = 1 at z = α for n = 1 and at z = 1 for n = ∞ (§3.1).
    assert_eq!(
        distribution_g(100.0, NPrime::finite(1.0).unwrap(), 100.0).unwrap(),
        1.0
    );
    assert_eq!(distribution_g(100.0, NPrime::UNWARPED, 1.0).unwrap(), 1.0);
}

// ---------------------------------------------------------------------------------------------
// Errata (docs/errata.md, "Lloyd et al. 2005").
// ---------------------------------------------------------------------------------------------

/// §3.2 says m_max is taken at z = α for ξ ≤ 0 and at z = 1 for ξ > 0; it is the other way
/// round. α = 100, ξ = −0.5 (n = 121): g(1) = 0.55, g(α) = 0.01818…; Eq 5 gives 0.55.
#[test]
fn errata_s3_2_max_location_swapped() {
    let a = 100.0;
    let n = n_from_xi(a, -0.5).unwrap();
    assert_eq!(n, NPrime::finite(121.0).unwrap());
    let th = std::f64::consts::FRAC_PI_4;
    let (_, near) = measured(a, th, n, 1.0, Resolutions::default());
    let (_, far) = measured(a, th, n, a, Resolutions::default());
    let scale = (a - 1.0) / (2.0 * th.tan());
    assert!(close(near / scale, 0.55, 1e-12));
    assert!(close(far / scale, 2.0 / 110.0, 1e-12));
    assert!(close(max_error(a, th, -0.5, 1.0, 1.0).unwrap(), near, REL));
    assert_eq!(max_error_depth(a, -0.5).unwrap(), 1.0);
    // ξ = +0.5 (n = 11/6): the far plane holds the maximum.
    let n = n_from_xi(a, 0.5).unwrap();
    let (_, near) = measured(a, th, n, 1.0, Resolutions::default());
    let (_, far) = measured(a, th, n, a, Resolutions::default());
    assert!(far > near);
    assert_eq!(max_error_depth(a, 0.5).unwrap(), a);
}

/// §4.1 says the x error is optimal at ξ = −1 "as in PSMs"; PSM is n = 1, ξ = +1. Measured at
/// α = 100: M_x = 1 at ξ = +1 and 100 at ξ = −1.
#[test]
fn errata_s4_1_x_error_optimal_at_xi_plus_one() {
    let a = 100.0;
    let th = 0.5;
    let at = |x: f64| {
        let v = ViewFrustum::new(1.0, a, th).unwrap();
        frustum_max(&v, &overhead_map(&v, n_from_xi(a, x).unwrap()).unwrap())
            .unwrap()
            .max_mx
    };
    assert!(close(at(1.0), 1.0, REL));
    assert!(close(at(-1.0), 100.0, REL));
    assert_eq!(n_from_xi(a, 1.0).unwrap(), NPrime::finite(1.0).unwrap());
}

/// §3.1 says a perspective projection gives "texel spacing proportional to 1/z²"; the spacing
/// dz/ds grows as (z + c)² (the Appendix's own conclusion, z² for PSM). Measured for PSM at
/// α = 100: w_lz(far)/w_lz(near) = 10⁴, not 10⁻⁴.
#[test]
fn errata_s3_1_texel_spacing_grows_as_z_squared() {
    let v = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let map = overhead_map(&v, NPrime::finite(1.0).unwrap()).unwrap();
    let r = Resolutions::default();
    let w = |z: f64| {
        point_error(&v, &map, glam::DVec3::new(0.0, 0.0, -z), r)
            .unwrap()
            .w_lt
    };
    assert!(close(w(100.0) / w(1.0), 1e4, REL));
    assert!(close(w(10.0) / w(1.0), 100.0, REL));
}

/// §3.1's s(z′) = ½ + (f+n)/(2(f−n)) + fn/(z′(f−n)) has the sign of the last term wrong (as Lloyd
/// 2006 Eq 6): printed s(n) = 4 and s(f) = 3 at n = 1, f = 2 (warp near and far); with − it is
/// 0 and 1.
#[test]
fn errata_s3_1_parameterisation_sign() {
    let (n, f) = (1.0f64, 2.0f64);
    let printed = |z: f64| 0.5 + (f + n) / (2.0 * (f - n)) + f * n / (z * (f - n));
    let right = |z: f64| 0.5 + (f + n) / (2.0 * (f - n)) - f * n / (z * (f - n));
    assert_eq!((printed(n), printed(f)), (4.0, 3.0));
    assert_eq!((right(n), right(f)), (0.0, 1.0));
}

/// §3.1 derives the optimal parameterisation as "s = ∫₀¹ ds = ∫₁^z dz/z = ln z", which spans
/// [0, ln α], not [0, 1]; normalised, s = ln z / ln α (as Lloyd 2006 App. C does), and the error
/// is then (r_p/r_s) ln α / (2 tan θ), the k → ∞ limit of Eq 7: 2.3026 at α = 100, θ = 45°,
/// where the unnormalised s = ln z would claim (r_p/r_s)/(2 tan θ) = 0.5.
#[test]
fn errata_s3_1_log_parameterisation_unnormalised() {
    let a = 100.0f64;
    let th = std::f64::consts::FRAC_PI_4;
    let limit = subdivided_max_error(a, 1 << 24, 0.0, th, 1.0, 1.0).unwrap();
    assert!(close(limit, a.ln() / (2.0 * th.tan()), 1e-9));
    // dz/ds of s = ln z is z: m = (r_p/r_s) z / (2 z tan θ) = 0.5 at θ = 45°, below the limit
    // that any map covering [1, α] with one s-unit can reach.
    let unnormalised = 1.0 / (2.0 * th.tan());
    assert!(close(unnormalised, 0.5, 1e-15) && unnormalised < limit);
}

proptest! {
    #![proptest_config(config(128))]

    /// No input makes a Lloyd 2005 closed form panic or return NaN or ±∞.
    #[test]
    fn never_nan_or_infinite(a in any_f64(), n in any_f64(), z in any_f64(), th in any_f64(), x in any_f64(), k in 0usize..100) {
        let ok = |r: Result<f64, shadow_aliasing::Error>| r.map_or(true, f64::is_finite);
        let nw = NPrime::new(n).unwrap_or(NPrime::UNWARPED);
        prop_assert!(ok(distribution_g(a, nw, z)));
        prop_assert!(ok(error_m(a, th, nw, z, 1.0, 1.0)));
        prop_assert!(ok(xi_from_n(a, nw)));
        prop_assert!(ok(max_error(a, th, x, 1.0, 1.0)));
        prop_assert!(ok(subdivided_max_error(a, k, x, th, 1.0, 1.0)));
        prop_assert!(ok(mx_normalised(a, nw, z, 1.0, 1.0)));
        prop_assert!(ok(max_mx_normalised(a, x, 1.0, 1.0)));
        let mut out = [0.0; 2];
        if allocate_texels(&[a, n], z, &mut out).is_ok() {
            prop_assert!(out.iter().all(|v| v.is_finite()));
        }
    }
}

/// Checked, right (docs/errata.md, Lloyd 2005 "Eq 4, 5 at ξ = 0"): both branches of Eq 4 give
/// n_opt = 1 + √α at ξ = 0 and meet continuously; both branches of §3.2's ξ(n) vanish at n_opt;
/// Eq 5 is continuous there with m_max = (r_p/r_s)(α − 1)/(2 tan θ)/√α, the measured maximum of
/// the LiSPSM warp on both planes. At α = 100, θ = 45°: n(0) = 11, n(±1e-9) = 11 ∓ 9.9e-7 … and
/// m_max(0) = 4.95.
#[test]
fn eq4_eq5_are_continuous_at_xi_zero() {
    let a = 100.0;
    let q = std::f64::consts::FRAC_PI_4;
    assert_eq!(n_from_xi(a, 0.0).unwrap(), NPrime::finite(11.0).unwrap());
    let left = n_from_xi(a, -1e-9).unwrap().value();
    let right = n_from_xi(a, 1e-9).unwrap().value();
    // dn/dξ = −(√α + 1 + α − 1) = −110 on the left, −√α(√α + 1) = −110 on the right.
    assert!((left - (11.0 + 110e-9)).abs() < 1e-12, "{left}");
    assert!((right - (11.0 - 110e-9)).abs() < 1e-12, "{right}");
    assert_eq!(xi_from_n(a, NPrime::finite(11.0).unwrap()).unwrap(), 0.0);
    let (m0, ml, mr) = (
        max_error(a, q, 0.0, 1.0, 1.0).unwrap(),
        max_error(a, q, -1e-9, 1.0, 1.0).unwrap(),
        max_error(a, q, 1e-9, 1.0, 1.0).unwrap(),
    );
    assert!((m0 - 4.95).abs() < 1e-12 && (ml - m0).abs() < 1e-6 && (mr - m0).abs() < 1e-6);
    // The measured warp at n = 11 has that maximum on both planes.
    let v = ViewFrustum::new(1.0, a, q).unwrap();
    let m = overhead_map(&v, NPrime::finite(11.0).unwrap()).unwrap();
    for z in [1.0, a] {
        let e = point_error(
            &v,
            &m,
            glam::DVec3::new(0.0, 0.0, -z),
            Resolutions::default(),
        )
        .unwrap();
        assert!((e.mz - 4.95).abs() < 1e-9, "{}", e.mz);
    }
}

/// Eq 6 with ξ per subdivision, by hand: α = (100, 50), ξ = (0, 1), θ = 45°: Eq 5 gives
/// 99/2 · 0.1 = 4.95 and 49/2 · 1 = 24.5, so the smaller subdivision gets 24.5/29.45 = 83.2 % of
/// the texels, and both end at the error 29.45 (in units of one whole map).
#[test]
fn eq6_with_different_xi_by_hand() {
    let q = std::f64::consts::FRAC_PI_4;
    let e = [
        max_error(100.0, q, 0.0, 1.0, 1.0).unwrap(),
        max_error(50.0, q, 1.0, 1.0, 1.0).unwrap(),
    ];
    assert!((e[0] - 4.95).abs() < 1e-12 && (e[1] - 24.5).abs() < 1e-12);
    let mut out = [0.0; 2];
    allocate_texels(&e, 1.0, &mut out).unwrap();
    assert!((out[1] - 24.5 / 29.45).abs() < 1e-12 && out[1] > 0.83);
}

/// Double-double arithmetic (value = hi + lo, |lo| ≤ ulp(hi)/2) for an independent,
/// high-accuracy Eq 7 (`subdivided_max_error_matches_a_double_double_reference`).
mod dd {
    pub type Dd = (f64, f64);

    fn quick_two_sum(a: f64, b: f64) -> Dd {
        let s = a + b;
        (s, b - (s - a))
    }

    fn two_prod(a: f64, b: f64) -> Dd {
        let p = a * b;
        (p, a.mul_add(b, -p))
    }

    pub fn mul(a: Dd, b: Dd) -> Dd {
        let (p, e) = two_prod(a.0, b.0);
        quick_two_sum(p, e + (a.0 * b.1 + a.1 * b.0))
    }

    /// x^e for e ≥ 1 by repeated squaring, every product in double-double.
    pub fn powi(x: f64, e: u32) -> Dd {
        let mut acc: Dd = (1.0, 0.0);
        let mut base: Dd = (x, 0.0);
        let mut e = e;
        while e > 0 {
            if e & 1 == 1 {
                acc = mul(acc, base);
            }
            base = mul(base, base);
            e >>= 1;
        }
        acc
    }

    /// s = α^{1/m} as double-double: one Newton step in double-double from `powf`
    /// (s ← s + (α − s^m) / (m s^{m−1})), which squares powf's ≈ 10⁻¹⁶ error away.
    pub fn root(alpha: f64, m: u32) -> Dd {
        let y = alpha.powf(1.0 / f64::from(m));
        let ym = powi(y, m);
        // α − ym.0 is exact (Sterbenz: ym.0 is within a factor 2 of α).
        let resid = (alpha - ym.0) - ym.1;
        let delta = resid / (f64::from(m) * ym.0) * y;
        quick_two_sum(y, delta)
    }
}

/// Eq 7 by an independent route at high accuracy: s = α^{1/2k} in double-double (Newton on
/// s^{2k} = α), s − 1 without cancellation (s.hi − 1 is exact for s.hi ≤ 2, then + s.lo),
/// α^{1/k} − 1 = (s − 1)(s + 1). Relative error a few 10⁻¹⁶.
fn eq7_reference(a: f64, k: usize, xi: f64, th: f64, rp: f64, rs: f64) -> f64 {
    let s = dd::root(a, 2 * k as u32);
    let sm1 = (s.0 - 1.0) + s.1;
    let ak_m1 = sm1 * (s.0 + 1.0 + s.1);
    k as f64 * rp / rs * ak_m1 * (1.0 + xi.abs() * sm1) / (2.0 * th.tan() * (s.0 + s.1))
}

/// α for the accuracy tests: just above 1 (α − 1 from 10⁻¹² to 10⁻¹), moderate, and huge.
fn alpha_wide() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-12.0f64..-1.0).prop_map(|e| 1.0 + 10f64.powf(e)),
        (0.0043f64..6.0).prop_map(|e| 10f64.powf(e)),
        (6.0f64..307.0).prop_map(|e| 10f64.powf(e)),
    ]
}

proptest! {
    #![proptest_config(config(128))]

    /// Eq 7's value is accurate to 10⁻¹⁴ relative against a double-double evaluation, from
    /// α − 1 = 10⁻¹² to α = 10³⁰⁷: for k = 1, 2, 4, 8, 16 (square roots and the exact
    /// identity α^{1/k} − 1 = (α − 1)/∏(α^{1/2^j} + 1)) at every α; for the other k (ln α
    /// and exp_m1) up to α = 10⁶ — beyond, ln α's rounding (≈ 10⁻¹⁶ · ln α / 2k relative)
    /// is what limits them, 4·10⁻¹⁵ · max(1, ln α / 2k) is checked.
    #[test]
    fn subdivided_max_error_matches_a_double_double_reference(
        a in alpha_wide(), k in 1usize..=16, x in -1.0f64..=1.0, th in 0.01f64..1.5,
        rp in 0.5f64..4096.0, rs in 0.5f64..4096.0,
    ) {
        let got = subdivided_max_error(a, k, x, th, rp, rs).unwrap();
        let want = eq7_reference(a, k, x, th, rp, rs);
        let tol = if k.is_power_of_two() || a <= 1e6 {
            1e-14
        } else {
            4e-15 * (a.ln() / (2.0 * k as f64)).max(1.0)
        };
        prop_assert!(close(got, want, tol), "α={a} k={k}: {got} vs {want} ({:e})", (got - want).abs() / want);
    }
}

/// Eq 7 near α = 1 by hand: α = 1 + ε, k = 4, ξ = 0, θ = 45°: α^{1/4} − 1 = ε/4 − 3ε²/32 + …,
/// √(α^{1/4}) = 1 + ε/8 + …, so m_max = 4 (ε/4 − 3ε²/32)(1 − ε/8)/2 = ε/2 − ε²/4 + O(ε³).
#[test]
fn subdivided_max_error_near_alpha_one_by_hand() {
    let q = std::f64::consts::FRAC_PI_4;
    for eps in [1e-8f64, 1e-10, 1e-12] {
        let a = 1.0 + eps;
        // The ε the function sees: α − 1, exact (Sterbenz). The series' next term is O(ε³),
        // below 10⁻¹⁶ relative here.
        let e = a - 1.0;
        let m = subdivided_max_error(a, 4, 0.0, q, 1.0, 1.0).unwrap();
        let want = e / 2.0 - e * e / 4.0;
        assert!(close(m, want, 1e-14), "ε={eps}: {m} vs {want}");
    }
}

/// The library names its arguments as the eval contract does (Lloyd 2005's ξ is the contract's
/// `eta`, r_s its `res_s`), so that eval passes its errors through unchanged.
#[test]
fn argument_names_are_the_contracts() {
    let name = |r: Result<f64, shadow_aliasing::Error>| match r {
        Err(shadow_aliasing::Error::InvalidArgument { name, .. }) => name,
        other => panic!("{other:?}"),
    };
    assert_eq!(
        name(subdivided_max_error(100.0, 3, -2.0, 0.5, 1.0, 1.0)),
        "eta"
    );
    assert_eq!(
        name(subdivided_max_error(100.0, 3, 0.0, 0.5, 1.0, -1.0)),
        "res_s"
    );
    assert_eq!(name(max_error(100.0, 0.5, 1.5, 1.0, 1.0)), "eta");
    assert_eq!(name(max_error(100.0, 0.5, 0.0, 1.0, 0.0)), "res_s");
    assert_eq!(name(max_error_depth(100.0, f64::NAN)), "eta");
    assert_eq!(name(max_mx_normalised(100.0, 2.0, 1.0, 1.0)), "eta");
    assert!(matches!(
        n_from_xi(100.0, 3.0),
        Err(shadow_aliasing::Error::InvalidArgument { name: "eta", .. })
    ));
}
