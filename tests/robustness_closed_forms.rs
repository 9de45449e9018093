//! Robustness of every public closed form (and numeric twin) of the analytic modules, the warp
//! parameter and the twins: thrown arbitrary `f64` (all of `proptest::num::f64::ANY`, plus the
//! edges a renderer or a JSON request can produce: ±0, subnormals, 1e±300, `f64::MAX`, ±∞, NaN,
//! f/n = 1 + 1e-15, θ a few ulps below π/2), each function either answers a finite value (or an
//! [`NPrime`]: `Finite` holds a finite positive number) or a typed [`Error`], and never panics.
//!
//! Validated inputs ([`ViewFrustum`], [`LightAngle`], [`Resolutions`]) are built from the same
//! arbitrary numbers; whenever a constructor accepts them, every function taking them is called.

mod common;
use common::config;
use proptest::prelude::*;
use shadow_aliasing::analytic::eta::{
    eta_from_n_prime, n_prime_from_eta, n_prime_lispsm, n_prime_psm,
};
use shadow_aliasing::analytic::global::{
    zhang_ep, zhang_ep_local, zhang_eq, zhang_eq_local, zhang_f_p, zhang_f_q, zhang_factorisation,
    zhang_g, zhang_mu, zhang_tan_phi_w, zhang_z_w, SurfaceSlope,
};
use shadow_aliasing::analytic::overhead::{
    budget_error, budget_resolution, critical_resolution, max_mx, max_mz, mx, mz, storage_factor,
};
use shadow_aliasing::analytic::partition::{
    fp_zp_w_overhead_asymptotic, optimal_storage_factor, scheme_storage_factor, shadow_map_count,
    splits_storage_factor, z_splits, zp_overhead_asymptotic, Scheme, SchemeLight, SplitScheme,
    Splits, MAX_PARTITIONS,
};
use shadow_aliasing::analytic::subdivided::{self, allocate_texels, allocate_texels_whole};
use shadow_aliasing::analytic::tilted::{
    falloff_r, gamma_lim, generalized_n_prime, n_prime_1, n_prime_2, n_prime_axis_minimax,
    n_prime_equal_error, tilted_mz, tilted_mz_perpendicular, tilted_psi, tilted_xi,
    warp_depth_range, Falloff,
};
use shadow_aliasing::analytic::tsm::{tsm_eta, tsm_focus_line, tsm_projection};
use shadow_aliasing::measure::tilted_twin::{
    aliasing_functions, mz_along_view_axis, tilted_light_frame, tilted_warp, TiltSide,
};
use shadow_aliasing::measure::twin::{
    behind_cascade, behind_face_map, behind_map, face_max, measured_fp_zp_w_behind,
    overhead_cascade, overhead_map, SideFace, TwinWarp,
};
use shadow_aliasing::{Error, LightAngle, NPrime, Resolutions, ViewFrustum};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

/// The largest f64 below π/2 (θ "a few ulps" from a right angle).
fn below_half_pi() -> f64 {
    f64::from_bits(FRAC_PI_2.to_bits() - 1)
}

/// The edge values, each as likely as any other.
fn edges() -> Vec<f64> {
    vec![
        0.0,
        -0.0,
        f64::MIN_POSITIVE,
        5e-324,
        -5e-324,
        1e-300,
        1e-15,
        0.5,
        1.0,
        -1.0,
        1.0 + 1e-15,
        1.0 + f64::EPSILON,
        1.0 - f64::EPSILON / 2.0,
        2.0,
        100.0,
        1e6,
        1e15,
        1e300,
        -1e300,
        f64::MAX,
        f64::MIN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NAN,
        FRAC_PI_2,
        below_half_pi(),
        FRAC_PI_2 - 1e-15,
        FRAC_PI_4,
        0.6,
    ]
}

/// Any f64: the whole of `f64::ANY`, log-uniform magnitudes of both signs, or an edge value.
fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        proptest::num::f64::ANY,
        (-320.0f64..308.0, any::<bool>()).prop_map(|(e, neg)| {
            let v = 10f64.powf(e);
            if neg {
                -v
            } else {
                v
            }
        }),
        proptest::sample::select(edges()),
    ]
}

/// A view frustum from arbitrary numbers, mostly valid: near and far from the edges and from
/// magnitudes 1e±300, far also as near·(1 + 1e-15) and near·f64::MAX-ish, half_fov anywhere in
/// (0, π/2) including its ends' neighbours.
fn view() -> impl Strategy<Value = (f64, f64, f64)> {
    let fov = prop_oneof![
        proptest::sample::select(vec![
            5e-324,
            1e-300,
            1e-15,
            0.01,
            FRAC_PI_4,
            1.2,
            FRAC_PI_2 - 1e-15,
            below_half_pi(),
            FRAC_PI_2,
            0.0,
            -0.0,
            f64::NAN,
        ]),
        0.0f64..FRAC_PI_2,
        any_f64(),
    ];
    let near = prop_oneof![(-320.0f64..308.0).prop_map(|e| 10f64.powf(e)), any_f64(),];
    let ratio = prop_oneof![
        proptest::sample::select(vec![
            1.0 + 1e-15,
            1.0 + f64::EPSILON,
            1.000001,
            2.0,
            1e3,
            1e6,
            1e15,
            1e300,
            f64::MAX,
        ]),
        (0.0f64..308.0).prop_map(|e| 10f64.powf(e)),
    ];
    (near, ratio, any_f64(), any::<bool>(), fov).prop_map(|(n, r, f, use_ratio, t)| {
        if use_ratio {
            (n, n * r, t)
        } else {
            (n, f, t)
        }
    })
}

/// Errors are typed: one of the crate's variants, an invalid argument naming the argument, a
/// message that is not empty.
fn typed(what: &str, e: &Error) -> Result<(), TestCaseError> {
    match e {
        Error::InvalidArgument { name, reason } => {
            prop_assert!(!name.is_empty() && !reason.is_empty(), "{what}: {e:?}");
        }
        Error::NoSolution(m) | Error::NoClosedForm(m) | Error::Degenerate(m) => {
            prop_assert!(!m.is_empty(), "{what}: {e:?}");
        }
        other => prop_assert!(false, "{what}: unexpected error {other:?}"),
    }
    Ok(())
}

/// Ok values finite, errors typed.
fn ok_finite(what: &str, r: Result<f64, Error>) -> Result<(), TestCaseError> {
    match r {
        Ok(v) => prop_assert!(v.is_finite(), "{what} returned {v}"),
        Err(e) => typed(what, &e)?,
    }
    Ok(())
}

fn n_prime_ok(what: &str, n: NPrime) -> Result<(), TestCaseError> {
    if let Some(v) = n.as_finite() {
        prop_assert!(
            v.is_finite() && v > 0.0,
            "{what} returned NPrime::finite({v}).unwrap()"
        );
    }
    Ok(())
}

fn n_prime_result_ok(what: &str, r: Result<NPrime, Error>) -> Result<(), TestCaseError> {
    match r {
        Ok(n) => n_prime_ok(what, n),
        Err(e) => typed(what, &e),
    }
}

/// The n′ an arbitrary `v` can become: an invalid payload is unrepresentable (`NPrime` is closed),
/// so the constructors refuse it with a typed error.
fn n_primes(v: f64) -> [NPrime; 3] {
    [
        NPrime::finite(v).unwrap_or(NPrime::UNWARPED),
        NPrime::new(v).unwrap_or(NPrime::UNWARPED),
        NPrime::UNWARPED,
    ]
}

fn resolutions(a: f64, b: f64, c: f64) -> Vec<Resolutions> {
    let mut out = vec![Resolutions::default()];
    if let Ok(r) = Resolutions::new(a, b, c) {
        out.push(r);
    }
    out
}

proptest! {
    #![proptest_config(config(192))]

    /// Lloyd 2006 (overhead.rs) and the warp parameter (warp.rs).
    #[test]
    fn overhead_and_warp(
        (n, f, th) in view(),
        np in any_f64(),
        z in any_f64(),
        e in any_f64(),
        r in (any_f64(), any_f64(), any_f64()),
        budget in any_f64(),
    ) {
        for (near, far) in [(n, f), (np, z), (e, np)] {
            ok_finite("n_prime_lispsm", n_prime_lispsm(near, far))?;
            ok_finite("n_prime_psm", n_prime_psm(near, far))?;
            n_prime_result_ok("n_prime_from_eta", n_prime_from_eta(near, far, e))?;
            for p in n_primes(np) {
                ok_finite("eta_from_n_prime", eta_from_n_prime(near, far, p))?;
                for res in resolutions(r.0, r.1, r.2) {
                    ok_finite("overhead::mx", mx(near, far, p, z, res))?;
                    ok_finite("overhead::max_mx", max_mx(near, far, p, res))?;
                }
            }
        }
        let Ok(v) = ViewFrustum::new(n, f, th) else { return Ok(()) };
        let lispsm = NPrime::finite(v.n_prime_lispsm()).unwrap();
        for p in n_primes(np).into_iter().chain([lispsm]) {
            for zz in [z, n, f, 0.5 * (n + f)] {
                for res in resolutions(r.0, r.1, r.2) {
                    ok_finite("overhead::mz", mz(&v, p, zz, res))?;
                    ok_finite("overhead::mx", mx(n, f, p, zz, res))?;
                }
            }
            ok_finite("max_mz", max_mz(&v, p, Resolutions::default()))?;
            ok_finite("storage_factor", storage_factor(&v, p))?;
            for ri in [r.0, 1.0, 1e300] {
                if let Ok(c) = critical_resolution(&v, p, ri) {
                    prop_assert!(c.res_s.is_finite() && c.res_t.is_finite());
                }
                ok_finite("budget_error", budget_error(&v, p, budget, ri))?;
            }
            if let Ok(b) = budget_resolution(&v, p, budget) {
                prop_assert!(b.res_s.is_finite() && b.res_t.is_finite());
            }
        }
        n_prime_result_ok("n_prime_from_eta", n_prime_from_eta(n, f, e))?;
    }

    /// Lloyd 2005 (subdivided.rs).
    #[test]
    fn subdivided_closed_forms(
        a in any_f64(),
        nw in any_f64(),
        z in any_f64(),
        th in any_f64(),
        xi in any_f64(),
        r in (any_f64(), any_f64()),
        k in prop_oneof![0usize..40, Just(usize::MAX), Just(1usize << 40)],
        total in any_f64(),
        whole in any::<u32>(),
    ) {
        ok_finite("n_opt", subdivided::n_opt(a))?;
        ok_finite("g_min", subdivided::g_min(a))?;
        for alpha in [a, 1.0 + 1e-15, 1e300, 100.0] {
            for p in n_primes(nw) {
                for zz in [z, 1.0, alpha] {
                    ok_finite("distribution_g", subdivided::distribution_g(alpha, p, zz))?;
                    ok_finite("error_m", subdivided::error_m(alpha, th, p, zz, r.0, r.1))?;
                    ok_finite("error_m", subdivided::error_m(alpha, 0.6, p, zz, 1.0, 1.0))?;
                    ok_finite("subdivided::mx_normalised", subdivided::mx_normalised(alpha, p, zz, r.0, r.1))?;
                }
                ok_finite("xi_from_n", subdivided::xi_from_n(alpha, p))?;
            }
            n_prime_result_ok("n_from_xi", subdivided::n_from_xi(alpha, xi))?;
            ok_finite("max_error_depth", subdivided::max_error_depth(alpha, xi))?;
            for t in [th, below_half_pi(), 5e-324] {
                ok_finite("max_error", subdivided::max_error(alpha, t, xi, r.0, r.1))?;
                ok_finite("max_error", subdivided::max_error(alpha, t, 0.0, 1.0, 1.0))?;
                ok_finite(
                    "subdivided_max_error",
                    subdivided::subdivided_max_error(alpha, k, xi, t, r.0, r.1),
                )?;
                ok_finite(
                    "subdivided_max_error",
                    subdivided::subdivided_max_error(alpha, k, 1.0, t, 1.0, 1.0),
                )?;
            }
            ok_finite("subdivided::max_mx_normalised", subdivided::max_mx_normalised(alpha, xi, r.0, r.1))?;
            if let Ok(s) = subdivided::face_subdivision_planes(alpha, k) {
                prop_assert!(s.planes().iter().all(|p| p.is_finite() && *p > 0.0));
            }
        }
        let errors = [a, nw, z, f64::MAX, 5e-324];
        for n in 1..=errors.len() {
            let mut out = [f64::NAN; 5];
            if allocate_texels(&errors[..n], total, &mut out[..n]).is_ok() {
                prop_assert!(out[..n].iter().all(|v| v.is_finite() && *v >= 0.0));
            }
            let mut w = [0u32; 5];
            if allocate_texels_whole(&errors[..n], whole, &mut w[..n]).is_ok() {
                prop_assert_eq!(w[..n].iter().map(|&v| u64::from(v)).sum::<u64>(), u64::from(whole));
            }
        }
        prop_assert!(allocate_texels(&[], 1.0, &mut []).is_err());
        prop_assert!(allocate_texels(&[1.0], 1.0, &mut [0.0; 2]).is_err());
    }

    /// Splits and scheme storage factors (partition.rs).
    #[test]
    fn partition_closed_forms(
        (n, f, th) in view(),
        p in any_f64(),
        q in any_f64(),
        k in prop_oneof![0usize..=MAX_PARTITIONS + 2, Just(usize::MAX)],
        i in any::<usize>(),
        planes in proptest::collection::vec(any_f64(), 0..20),
    ) {
        let schemes = [
            SplitScheme::Uniform,
            SplitScheme::SelfSimilar,
            SplitScheme::Practical { lambda: p },
            SplitScheme::Practical { lambda: 0.5 },
            SplitScheme::Adaptive { light_angle: p, ratio: q },
            SplitScheme::Adaptive { light_angle: 0.0, ratio: 1.0 + 1e-15 },
            SplitScheme::Adaptive { light_angle: FRAC_PI_4, ratio: 2.0 },
            SplitScheme::Exponent { exponent: q },
            SplitScheme::Exponent { exponent: 1.0 + 1e-15 },
            SplitScheme::Exponent { exponent: 1e300 },
            SplitScheme::Exponent { exponent: 5e-324 },
        ];
        let mut good = Vec::new();
        for s in schemes {
            for (near, far) in [(n, f), (p, q)] {
                if let Ok(sp) = z_splits(near, far, k, s) {
                    let pl = sp.planes();
                    prop_assert_eq!(pl.len(), k + 1);
                    prop_assert!(pl.iter().all(|z| z.is_finite() && *z > 0.0));
                    prop_assert!(pl.windows(2).all(|w| w[0] < w[1]));
                    let (a, b) = sp.range(i);
                    prop_assert!(a < b);
                    prop_assert!(sp.ratios().iter().all(|r| r.is_finite()));
                    good.push(sp);
                }
            }
        }
        if let Ok(sp) = Splits::from_planes(&planes) {
            prop_assert!(sp.planes().windows(2).all(|w| w[0] < w[1]));
            let _ = sp.range(i);
            prop_assert!(sp.ratios().iter().all(|r| r.is_finite()));
            good.push(sp);
        }
        for sp in &good {
            for light in [SchemeLight::Overhead, SchemeLight::Behind] {
                for warped in [false, true] {
                    for t in [th, p, below_half_pi(), 5e-324] {
                        ok_finite("splits_storage_factor", splits_storage_factor(sp, t, light, warped))?;
                    }
                }
            }
        }
        for scheme in [Scheme::Zp, Scheme::ZpW, Scheme::FpZpW, Scheme::Optimal] {
            for light in [SchemeLight::Overhead, SchemeLight::Behind] {
                let _ = shadow_map_count(scheme, light, k);
            }
        }
        let Ok(v) = ViewFrustum::new(n, f, th) else { return Ok(()) };
        for scheme in [Scheme::Zp, Scheme::ZpW, Scheme::FpZpW, Scheme::Optimal] {
            for light in [SchemeLight::Overhead, SchemeLight::Behind] {
                for kk in [k, 1, 4, usize::MAX] {
                    ok_finite("scheme_storage_factor", scheme_storage_factor(scheme, light, &v, kk))?;
                }
            }
        }
        ok_finite("optimal_storage_factor", optimal_storage_factor(&v))?;
        for j in [k, 1, 8, usize::MAX] {
            ok_finite("zp_overhead_asymptotic", zp_overhead_asymptotic(&v, j))?;
            ok_finite("fp_zp_w_overhead_asymptotic", fp_zp_w_overhead_asymptotic(&v, j))?;
        }
    }

    /// Barroso & Celes (tilted.rs).
    #[test]
    fn tilted_closed_forms(
        (n, f, th) in view(),
        np in any_f64(),
        z in any_f64(),
        g in any_f64(),
        r in (any_f64(), any_f64(), any_f64()),
        u in any_f64(),
        ul in any_f64(),
        name in ".{0,12}",
    ) {
        for name in [name.as_str(), "zhang", "barroso", "", "Zhang"] {
            if let Err(e) = name.parse::<Falloff>() {
                typed("Falloff::from_str", &e)?;
            }
        }
        for fo in [Falloff::Zhang, Falloff::Barroso] {
            let v = falloff_r(fo, u, ul);
            prop_assert!(v.is_finite() && (0.0..=1.0).contains(&v), "falloff_r = {}", v);
        }
        let Ok(v) = ViewFrustum::new(n, f, th) else { return Ok(()) };
        ok_finite("gamma_lim", Ok(gamma_lim(&v)))?;
        for gamma in [g, 0.0, 1e-300, FRAC_PI_2, below_half_pi(), th, gamma_lim(&v)]
            .into_iter()
            .filter_map(|x| LightAngle::new(x).ok())
        {
            ok_finite("warp_depth_range", warp_depth_range(&v, gamma))?;
            ok_finite("n_prime_1", Ok(n_prime_1(&v, gamma)))?;
            ok_finite("n_prime_2", n_prime_2(&v, gamma))?;
            n_prime_result_ok("n_prime_equal_error", n_prime_equal_error(&v, gamma))?;
            n_prime_ok("n_prime_axis_minimax", n_prime_axis_minimax(&v, gamma))?;
            for fo in [Falloff::Zhang, Falloff::Barroso] {
                n_prime_ok("generalized_n_prime", generalized_n_prime(&v, gamma, fo))?;
            }
            for p in n_primes(np).into_iter().chain([NPrime::finite(v.near()).unwrap()]) {
                for zz in [z, v.near(), v.far()] {
                    for res in resolutions(r.0, r.1, r.2) {
                        ok_finite("tilted_mz", tilted_mz(&v, p, gamma, zz, res))?;
                        ok_finite(
                            "tilted_mz_perpendicular",
                            tilted_mz_perpendicular(&v, p, gamma, zz, res),
                        )?;
                    }
                }
            }
            for npf in [np, v.near(), 1e300, 5e-324] {
                for zz in [z, v.near(), v.far()] {
                    ok_finite("tilted_psi", tilted_psi(&v, npf, gamma, zz))?;
                }
                ok_finite("tilted_xi", tilted_xi(&v, npf, gamma, Resolutions::default()))?;
            }
        }
    }

    /// Zhang et al. (global.rs).
    #[test]
    fn zhang_closed_forms(
        (n, f, th) in view(),
        l in any_f64(),
        y in any_f64(),
        z in any_f64(),
        x in any_f64(),
        g in any_f64(),
        k in (any_f64(), any_f64()),
    ) {
        let Ok(v) = ViewFrustum::new(n, f, th) else { return Ok(()) };
        for theta in [g, 0.0, 1e-300, FRAC_PI_2, below_half_pi(), th]
            .into_iter()
            .filter_map(|x| LightAngle::new(x).ok())
        {
            ok_finite("zhang_mu", zhang_mu(&v, theta))?;
            for lam in [l, v.near(), 1e300, 5e-324] {
                ok_finite("zhang_tan_phi_w", zhang_tan_phi_w(&v, lam, theta))?;
                ok_finite("zhang_f_q", zhang_f_q(&v, lam, theta))?;
                ok_finite("zhang_f_p", zhang_f_p(&v, lam, theta))?;
                for yy in [y, 0.0, v.near() * v.tan_half_fov()] {
                    ok_finite("zhang_g", zhang_g(&v, lam, theta, yy))?;
                    for zz in [z, v.near(), v.far()] {
                        ok_finite("zhang_z_w", zhang_z_w(&v, lam, theta, yy, zz))?;
                        for slope in [SurfaceSlope { k_x: k.0, k_y: k.1 }, SurfaceSlope { k_x: 1.0, k_y: 0.0 }] {
                            if let Ok(fa) = zhang_factorisation(&v, lam, theta, x, yy, zz, slope) {
                                for q in [fa.eq_pers, fa.eq_proj, fa.ep_pers, fa.ep_proj, fa.e_q(), fa.e_p()] {
                                    prop_assert!(q.is_finite(), "factorisation {:?}", fa);
                                }
                            }
                            let _ = zhang_factorisation(&v, lam, theta, 0.0, yy, zz, slope);
                        }
                    }
                }
            }
            for lam in n_primes(l) {
                for (yy, zz) in [(y, z), (0.0, z), (0.0, v.near()), (0.0, v.far())] {
                    ok_finite("zhang_eq", zhang_eq(&v, lam, theta, yy, zz))?;
                    ok_finite("zhang_ep", zhang_ep(&v, lam, theta, yy, zz))?;
                    ok_finite("zhang_eq_local", zhang_eq_local(&v, lam, zz))?;
                    ok_finite("zhang_ep_local", zhang_ep_local(&v, lam, zz))?;
                }
            }
        }
    }

    /// Martin & Tan (tsm.rs).
    #[test]
    fn tsm_closed_forms(lambda in any_f64(), d in any_f64(), xi in any_f64(), e in any_f64()) {
        for (l, dd) in [(lambda, d), (lambda, 0.5 * lambda), (1.0, d)] {
            for x in [xi, -0.6, 1.0 - 1e-16, -1.0 + 1e-16] {
                n_prime_result_ok("tsm_eta", tsm_eta(l, dd, x))?;
            }
            for et in n_primes(e) {
                ok_finite("tsm_focus_line", tsm_focus_line(l, et, dd))?;
            }
            if let Ok(m) = tsm_projection(l, e) {
                prop_assert!(m.iter().flatten().all(|v| v.is_finite()));
            }
        }
    }

    /// The numeric twins (measure/twin.rs, measure/tilted_twin.rs): errors or finite matrices.
    #[test]
    fn twins(
        (n, f, th) in view(),
        np in any_f64(),
        g in any_f64(),
        pt in (any_f64(), any_f64(), any_f64()),
        k in 0usize..4,
    ) {
        let Ok(v) = ViewFrustum::new(n, f, th) else { return Ok(()) };
        for p in n_primes(np).into_iter().chain([NPrime::finite(v.near()).unwrap()]) {
            if let Ok(m) = overhead_map(&v, p) {
                prop_assert!(m.matrix().is_finite());
            }
            for face in SideFace::ALL {
                if let Ok(c) = face.corners(&v) {
                    prop_assert!(c.iter().all(|c| c.is_finite()));
                }
                if let Ok(m) = behind_face_map(&v, face, p) {
                    prop_assert!(m.matrix().is_finite());
                    if let Ok(e) = face_max(&v, face, &m) {
                        prop_assert!(e.storage_factor.is_finite());
                    }
                }
            }
            for gamma in [g, 0.0, FRAC_PI_2, below_half_pi()]
                .into_iter()
                .filter_map(|x| LightAngle::new(x).ok())
            {
                let (a, b) = tilted_light_frame(gamma, TiltSide::InFront);
                prop_assert!(a.is_finite() && b.is_finite());
                for side in [TiltSide::InFront, TiltSide::Behind] {
                    if let Ok(w) = tilted_warp(&v, gamma, side, p) {
                        prop_assert!(w.shadow.matrix().is_finite());
                        let point = glam::DVec3::new(pt.0, pt.1, pt.2);
                        for q in [point, glam::DVec3::new(0.0, 0.0, -v.near())] {
                            ok_finite("mz_along_view_axis", mz_along_view_axis(&v, &w.shadow, q, Resolutions::default()))?;
                            if let Ok(a) = aliasing_functions(&v, &w.shadow, q, point) {
                                prop_assert!(a.e_q.is_finite() && a.e_p.is_finite());
                            }
                        }
                    }
                }
            }
        }
        if let Ok(m) = behind_map(&v) {
            prop_assert!(m.matrix().is_finite());
        }
        if k > 0 {
            if let Ok(sp) = z_splits(v.near(), v.far(), k, SplitScheme::SelfSimilar) {
                for w in [TwinWarp::Unwarped, TwinWarp::Lispsm, TwinWarp::Eta(0.5)] {
                    if let Ok(c) = overhead_cascade(&v, &sp, w) {
                        ok_finite("measured_storage_factor", c.measured_storage_factor())?;
                        prop_assert_eq!(c.k(), k);
                        for i in 0..=k {
                            if let Some((pv, pm)) = c.get(i) {
                                prop_assert!(pv.near() < pv.far() && pm.matrix().is_finite());
                            }
                        }
                    }
                    ok_finite("measured_fp_zp_w_behind", measured_fp_zp_w_behind(&v, &sp, w))?;
                }
                if let Ok(c) = behind_cascade(&v, &sp) {
                    ok_finite("measured_storage_factor", c.measured_storage_factor())?;
                }
            }
        }
    }
}
