//! Lloyd, Tuft, Yoon & Manocha 2006, "Warping and Partitioning for Low Error Shadow Maps":
//! every closed form of §4 against its numeric twin (the warping-frustum matrix measured by
//! `measure::point_error`), the identities of the η parameterisation, and the errata.

use proptest::prelude::*;
use shadow_aliasing::analytic::eta::{
    eta_from_n_prime, n_prime_from_eta, n_prime_lispsm, n_prime_psm,
};
use shadow_aliasing::analytic::overhead::{
    budget_error, budget_resolution, critical_resolution, max_mx, max_mz, mx, mz, storage_factor,
};
use shadow_aliasing::measure::twin::overhead_map;
use shadow_aliasing::measure::{frustum_max, frustum_max_sampled, point_error};
use shadow_aliasing::{NPrime, Resolutions, ViewFrustum};
mod common;
use common::{any_f64, close, config, frustum, REL};

fn resolutions() -> impl Strategy<Value = Resolutions> {
    (1.0f64..4096.0, 1.0f64..4096.0, 1.0f64..4096.0)
        .prop_map(|(i, s, t)| Resolutions::new(i, s, t).unwrap())
}

/// η ∈ [−0.999, 1], or exactly −1 (unwarped) one time in eight.
fn eta() -> impl Strategy<Value = f64> {
    prop_oneof![7 => -0.999f64..=1.0, 1 => Just(-1.0)]
}

proptest! {
    #![proptest_config(config(128))]

    /// Eq 7, 8: m_x and m_z at any point of the frustum equal the measured errors of the
    /// warping frustum with the same n′ (any resolutions).
    #[test]
    fn eq7_eq8_equal_the_measured_warp_pointwise(
        v in frustum(), e in eta(), res in resolutions(),
        fz in 0.0f64..=1.0, fx in -1.0f64..=1.0, fy in -1.0f64..=1.0,
    ) {
        let np = n_prime_from_eta(v.near(), v.far(), e).unwrap();
        let map = overhead_map(&v, np).unwrap();
        let z = v.near() + fz * (v.far() - v.near());
        let z = z.min(v.far());
        let h = z * v.tan_half_fov();
        let p = glam::DVec3::new(fx * h, fy * h, -z);
        let m = point_error(&v, &map, p, res).unwrap();
        let cx = mx(v.near(), v.far(), np, z, res).unwrap();
        let cz = mz(&v, np, z, res).unwrap();
        prop_assert!(close(m.mx, cx, REL), "m_x measured {} closed {}", m.mx, cx);
        prop_assert!(close(m.mz, cz, REL), "m_z measured {} closed {}", m.mz, cz);
    }

    /// Eq 9, 10, 12: M_x, M_z and S̄ equal the measured maxima over the frustum vertices.
    #[test]
    fn eq9_eq10_eq12_equal_the_measured_maxima(v in frustum(), e in eta()) {
        let np = n_prime_from_eta(v.near(), v.far(), e).unwrap();
        let r = Resolutions::default();
        let m = frustum_max(&v, &overhead_map(&v, np).unwrap()).unwrap();
        prop_assert!(close(m.max_mx, max_mx(v.near(), v.far(), np, r).unwrap(), REL));
        prop_assert!(close(m.max_mz, max_mz(&v, np, r).unwrap(), REL));
        prop_assert!(close(m.storage_factor, storage_factor(&v, np).unwrap(), REL));
    }

    /// η(n′(η)) = η and n′(η(n′)) = n′.
    #[test]
    fn eta_and_n_prime_are_inverse(v in frustum(), e in eta(), nu in 1.0f64..1e6) {
        let (n, f) = (v.near(), v.far());
        let np = n_prime_from_eta(n, f, e).unwrap();
        let back = eta_from_n_prime(n, f, np).unwrap();
        prop_assert!((back - e).abs() <= 1e-9, "η = {e} → n′ = {np:?} → η = {back}");
        let np2 = NPrime::finite(n * nu).unwrap();
        let e2 = eta_from_n_prime(n, f, np2).unwrap();
        let back2 = n_prime_from_eta(n, f, e2).unwrap();
        prop_assert!(close(back2.value(), n * nu, 1e-8), "{} vs {}", back2.value(), n * nu);
    }

    /// App. B defines η by interpolating the *measured* maximum z error M_z linearly between
    /// n′ = ∞ (η = −1), n′_LSPSM (0) and n′ = n (1). Computed from the twin, it is Eq 11's η
    /// (n′ from η), and App. B's η(n′) of any n′ ≥ n.
    #[test]
    fn app_b_definition_from_measured_mz_gives_eq11(v in frustum(), e in eta(), nu in 1.0f64..1e6) {
        let (n, f) = (v.near(), v.far());
        let mz_of = |np: NPrime| frustum_max(&v, &overhead_map(&v, np).unwrap()).unwrap().max_mz;
        let l = NPrime::finite(n + (f * n).sqrt()).unwrap();
        let (ml, minf, mn) = (mz_of(l), mz_of(NPrime::UNWARPED), mz_of(NPrime::finite(n).unwrap()));
        let eta_b = |np: NPrime| {
            let m = mz_of(np);
            if np.value() > l.value() {
                (ml - m) / (minf - ml)
            } else {
                (m - ml) / (mn - ml)
            }
        };
        let np = n_prime_from_eta(n, f, e).unwrap();
        let measured = eta_b(np);
        prop_assert!((measured - e).abs() < 1e-6, "App. B η = {measured}, Eq 11 η = {e}");
        let np = NPrime::finite(n * nu).unwrap();
        let (measured, closed) = (eta_b(np), eta_from_n_prime(n, f, np).unwrap());
        prop_assert!((measured - closed).abs() < 1e-6, "n′ = {np:?}: App. B η = {measured}, η(n′) = {closed}");
    }

    /// §4.3: S̄ does not depend on n′ for n ≤ n′ ≤ n′_LSPSM (η ∈ [0, 1]): measured S̄ is
    /// (f/n − 1)/(2 tan θ).
    #[test]
    fn storage_factor_is_flat_below_lispsm(v in frustum(), e in 0.0f64..=1.0) {
        let np = n_prime_from_eta(v.near(), v.far(), e).unwrap();
        let s = frustum_max(&v, &overhead_map(&v, np).unwrap()).unwrap().storage_factor;
        let flat = (v.alpha() - 1.0) / (2.0 * v.tan_half_fov());
        prop_assert!(close(s, flat, REL), "S̄ = {s}, flat {flat}");
    }

    /// At n′_LSPSM the measured m_z is the same on the near and far planes (§4.3, Eq 10's
    /// regimes meet), and it is the smallest M_z of all n′.
    #[test]
    fn mz_equal_on_near_and_far_planes_at_lispsm(v in frustum(), e in eta()) {
        let l = NPrime::finite(n_prime_lispsm(v.near(), v.far()).unwrap()).unwrap();
        let map = overhead_map(&v, l).unwrap();
        let r = Resolutions::default();
        let near = point_error(&v, &map, glam::DVec3::new(0.0, 0.0, -v.near()), r).unwrap().mz;
        let far = point_error(&v, &map, glam::DVec3::new(0.0, 0.0, -v.far()), r).unwrap().mz;
        prop_assert!(close(near, far, REL), "near {near} far {far}");
        let other = n_prime_from_eta(v.near(), v.far(), e).unwrap();
        let m_other = frustum_max(&v, &overhead_map(&v, other).unwrap()).unwrap().max_mz;
        prop_assert!(m_other >= near * (1.0 - REL));
    }

    /// PSM (§4.1, n′_PSM = n, the warping frustum's centre of projection at the eye): the
    /// measured m_x is 1 (res_i = res_s) at every vertex of the frustum and at any point inside.
    #[test]
    fn psm_measured_mx_is_one_everywhere(
        v in frustum(), fz in 0.0f64..=1.0, fx in -1.0f64..=1.0, fy in -1.0f64..=1.0,
    ) {
        let psm = NPrime::finite(n_prime_psm(v.near(), v.far()).unwrap()).unwrap();
        let map = overhead_map(&v, psm).unwrap();
        let z = (v.near() + fz * (v.far() - v.near())).min(v.far());
        let h = z * v.tan_half_fov();
        let inside = glam::DVec3::new(fx * h, fy * h, -z);
        for p in v.corners().into_iter().chain([inside]) {
            let m = point_error(&v, &map, p, Resolutions::default()).unwrap();
            prop_assert!(close(m.mx, 1.0, REL), "{p}: m_x = {}", m.mx);
        }
    }

    /// Eq 10's regimes: the measured maximum of m_z lies on the far plane for n′ ≤ n′_LSPSM
    /// (η ≥ 0) and on the near plane for n′ > n′_LSPSM (η < 0), as the text says.
    #[test]
    fn eq10_max_plane_switches_at_lispsm(v in frustum(), e in eta()) {
        let np = n_prime_from_eta(v.near(), v.far(), e).unwrap();
        let map = overhead_map(&v, np).unwrap();
        let r = Resolutions::default();
        let near = point_error(&v, &map, glam::DVec3::new(0.0, 0.0, -v.near()), r).unwrap().mz;
        let far = point_error(&v, &map, glam::DVec3::new(0.0, 0.0, -v.far()), r).unwrap().mz;
        if e > 1e-6 {
            prop_assert!(far > near, "η = {e}: far {far} ≤ near {near}");
        } else if e < -1e-6 {
            prop_assert!(near > far, "η = {e}: near {near} ≤ far {far}");
        }
    }

    /// Eq 13, 14: the critical resolution makes the measured M_x = M_z = 1, and the budget
    /// resolution makes both equal res_i √(S̄ / S₀) with res_s res_t = S₀.
    #[test]
    fn eq13_eq14_critical_and_budget_resolution(
        v in frustum(), e in eta(), ri in 64.0f64..4096.0, s0 in 1e4f64..1e8,
    ) {
        let np = n_prime_from_eta(v.near(), v.far(), e).unwrap();
        let map = overhead_map(&v, np).unwrap();
        let max_at = |res: Resolutions| {
            let mut m = (0.0f64, 0.0f64);
            for c in v.corners() {
                let p = point_error(&v, &map, c, res).unwrap();
                m = (m.0.max(p.mx), m.1.max(p.mz));
            }
            m
        };
        let c = critical_resolution(&v, np, ri).unwrap();
        let (cx, cz) = max_at(Resolutions::new(ri, c.res_s, c.res_t).unwrap());
        prop_assert!(close(cx, 1.0, REL) && close(cz, 1.0, REL), "{cx} {cz}");
        let b = budget_resolution(&v, np, s0).unwrap();
        prop_assert!(close(b.res_s * b.res_t, s0, REL));
        let (bx, bz) = max_at(Resolutions::new(ri, b.res_s, b.res_t).unwrap());
        let want = budget_error(&v, np, s0, ri).unwrap();
        prop_assert!(close(bx, want, REL) && close(bz, want, REL), "{bx} {bz} {want}");
    }
}

/// n′(0) = n + √(fn), n′(−1) = ∞, n′(1) = n (Fig 6 caption, Eq 11).
#[test]
fn n_prime_special_values() {
    for (n, f) in [(1.0, 100.0), (0.3, 7.0), (2.0, 2000.0)] {
        let l = n_prime_lispsm(n, f).unwrap();
        assert_eq!(l, n + (f * n).sqrt());
        assert_eq!(n_prime_psm(n, f).unwrap(), n);
        match n_prime_from_eta(n, f, 0.0).unwrap().as_finite() {
            Some(v) => assert!(close(v, l, 1e-15)),
            None => panic!("η = 0 is finite"),
        }
        assert_eq!(n_prime_from_eta(n, f, -1.0).unwrap(), NPrime::UNWARPED);
        match n_prime_from_eta(n, f, 1.0).unwrap().as_finite() {
            Some(v) => assert!(close(v, n_prime_psm(n, f).unwrap(), 1e-15)),
            None => panic!("η = 1 is finite"),
        }
        assert_eq!(eta_from_n_prime(n, f, NPrime::UNWARPED).unwrap(), -1.0);
        assert_eq!(
            eta_from_n_prime(n, f, NPrime::finite(n).unwrap()).unwrap(),
            1.0
        );
    }
}

/// The vertices suffice (§4.4): a dense grid finds the same maxima.
#[test]
fn vertices_suffice_for_the_overhead_warp() {
    let v = ViewFrustum::new(0.5, 60.0, 0.7).unwrap();
    for e in [-1.0, -0.6, 0.0, 0.4, 1.0] {
        let np = n_prime_from_eta(v.near(), v.far(), e).unwrap();
        let map = overhead_map(&v, np).unwrap();
        let a = frustum_max(&v, &map).unwrap();
        let b = frustum_max_sampled(&v, &map, 9).unwrap();
        assert!(close(a.storage_factor, b.storage_factor, REL));
    }
}

/// Bad inputs are typed errors naming the argument.
#[test]
fn domain_errors() {
    let v = ViewFrustum::new(1.0, 10.0, 0.5).unwrap();
    let r = Resolutions::default();
    let msg = mx(1.0, 10.0, NPrime::finite(0.5).unwrap(), 2.0, r)
        .unwrap_err()
        .to_string();
    assert!(msg.starts_with("n_prime must be at least near"), "{msg}");
    let msg = mz(&v, NPrime::UNWARPED, 11.0, r).unwrap_err().to_string();
    assert_eq!(msg, "z must lie in [near, far] = [1, 10] (got 11)");
    assert!(n_prime_from_eta(1.0, 10.0, f64::NAN).is_err());
    assert!(n_prime_from_eta(2.0, 1.0, 0.0).is_err());
    assert!(budget_resolution(&v, NPrime::UNWARPED, 0.0).is_err());
    assert!(critical_resolution(&v, NPrime::UNWARPED, -1.0).is_err());
}

// ---------------------------------------------------------------------------------------------
// Errata (docs/errata.md, "Lloyd et al. 2006").
// ---------------------------------------------------------------------------------------------

/// Eq 2 as transcribed: w_i(z) = (2 tan θ / res_i)(z/n). With that width, m_x at the near plane
/// would be n times Eq 7; the measurement (pixel width 2 z tan θ / res_i) gives Eq 7.
#[test]
fn errata_eq2_pixel_width_has_no_over_n() {
    let v = ViewFrustum::new(2.0, 100.0, 30f64.to_radians()).unwrap();
    let np = NPrime::finite(v.n_prime_lispsm()).unwrap();
    let map = overhead_map(&v, np).unwrap();
    let p = point_error(
        &v,
        &map,
        glam::DVec3::new(0.0, 0.0, -2.0),
        Resolutions::default(),
    )
    .unwrap();
    let eq7 = mx(2.0, 100.0, np, 2.0, Resolutions::default()).unwrap();
    // Lloyd's light beam width w_lx over the transcribed pixel width (z/n)·2 tan θ.
    let printed = p.w_ls / (2.0 * v.tan_half_fov() * 2.0 / 2.0);
    assert!(close(p.mx, eq7, REL));
    assert!(close(printed, 2.0 * eq7, REL)); // n = 2 times too large
                                             // Numbers for the errata page: n = 2, f = 100, θ = 30°, n′ = n′_LSPSM = 16.142…: Eq 7
                                             // gives 7.071 at z = n, the transcribed width 14.142.
    let l = 2.0 + 200f64.sqrt();
    assert!(close(eq7, 100.0 * l / (2.0 * (l + 98.0)), 1e-12));
}

/// Eq 5, 6 as transcribed: s = x/(z′ tan θ′) + ½, tan θ′ = (f′/f) tan θ and
/// t = (f′+n′)/(2(f′−n′)) + f′n′/(z′(f′−n′)) + ½ do not map the frustum onto [0, 1]², and the
/// printed tan θ′ gives the wrong m_x. The crate's map (s = x/(2 z′ tan θ′) + ½,
/// tan θ′ = (f/f′) tan θ, − before f′n′) does, and its measured m_x is Eq 7.
#[test]
fn errata_eq5_eq6_warping_frustum_map() {
    let (n, f, np) = (1.0f64, 100.0f64, 11.0f64);
    let th = std::f64::consts::FRAC_PI_4;
    let fp = np + f - n;
    // Printed t at the near and far planes (z′ = n′, f′): 2.2̄ and 1.2̄, not 0 and 1.
    let t_printed = |zp: f64| (fp + np) / (2.0 * (fp - np)) + fp * np / (zp * (fp - np)) + 0.5;
    let t_right = |zp: f64| (fp + np) / (2.0 * (fp - np)) - fp * np / (zp * (fp - np)) + 0.5;
    assert!(close(
        t_printed(np),
        (fp + np) / (2.0 * (fp - np)) + fp / (fp - np) + 0.5,
        1e-15
    ));
    assert!(close(t_printed(np), 20.0 / 9.0, 1e-12) && close(t_printed(fp), 11.0 / 9.0, 1e-12));
    assert!(t_right(np).abs() < 1e-12 && (t_right(fp) - 1.0).abs() < 1e-12);
    // Printed s at the far corner x = f tan θ, z′ = f′: with tan θ′ = (f′/f) tan θ.
    let tan_printed = fp / f * th.tan();
    let s_printed = f * th.tan() / (fp * tan_printed) + 0.5;
    assert!(close(s_printed, 0.5 + (f / fp).powi(2), 1e-12)); // 1.326…, outside [0, 1]

    // m_x at z = n from the printed s and tan θ′: w_lx = (ds/dx)⁻¹/res_s = z′ tan θ′_printed/res_s
    // against the pixel width w_i = 2 z tan θ/res_i (unit resolutions), z = n, z′ = n′.
    let v = ViewFrustum::new(n, f, th).unwrap();
    let h = 1e-6;
    let s_of_x = |x: f64| x / (np * tan_printed) + 0.5; // printed Eq 5 at z′ = n′
    let dx_ds = 2.0 * h / (s_of_x(h) - s_of_x(-h));
    let w_i = 2.0 * n * th.tan();
    let mx_printed = dx_ds / w_i; // = n′ f′/(2 n f) = 6.05
    let measured =
        frustum_max(&v, &overhead_map(&v, NPrime::finite(np).unwrap()).unwrap()).unwrap();
    assert!(close(mx_printed, np * fp / (2.0 * n * f), 1e-9));
    assert!(close(mx_printed, 6.05, 1e-9));
    assert!(close(measured.max_mx, 10.0, REL)); // Eq 7, 9: f n′/(n f′) = 10
}

/// Eq 9, 10 as transcribed: M_x = (res_i/res_s) f n′/(n′ + f − n) and a factor n in front of
/// M_z's (f − n)/(2 tan θ) (probably Eq 9's denominator n displaced in the transcription). Both
/// are dimensionally wrong and differ from the measurement by the factor n when n ≠ 1.
#[test]
fn errata_eq9_eq10_factor_n() {
    let v = ViewFrustum::new(2.0, 100.0, 30f64.to_radians()).unwrap();
    let (n, f) = (2.0, 100.0);
    let np = v.n_prime_lispsm();
    let m = frustum_max(&v, &overhead_map(&v, NPrime::finite(np).unwrap()).unwrap()).unwrap();
    let mx_printed = f * np / (np + f - n);
    let mx_right = f * np / (n * (np + f - n));
    assert!(close(m.max_mx, mx_right, REL));
    assert!(close(mx_printed, n * m.max_mx, REL));
    let k = (f - n) / (2.0 * v.tan_half_fov());
    let mz_printed = n * k * (np + f - n) / (np * f);
    assert!(close(m.max_mz, k * (np + f - n) / (np * f), REL));
    assert!(close(mz_printed, n * m.max_mz, REL));
    // Numbers: M_x printed 14.142…, measured 7.071…; M_z printed 12.002…, measured 6.001…
    assert!(close(m.max_mx, 50f64.sqrt(), 1e-12));
    assert!((m.max_mz - 6.00125).abs() < 1e-5 && (mz_printed - 12.0025).abs() < 1e-4);
}

/// App. C gives the optimal map's errors as m_x = 1/res_s and m_z = (1/res_t) ln(f/n)/(2 tan θ),
/// dropping res_i (right only for res_i = 1). Its x map is PSM's (n′ = n), whose measured m_x is
/// res_i/res_s everywhere: 1 at res_i = res_s = 1024, where the printed form gives 1/1024.
#[test]
fn errata_app_c_drops_res_i() {
    let v = ViewFrustum::new(1.0, 1000.0, 0.5).unwrap();
    let map = overhead_map(&v, NPrime::finite(1.0).unwrap()).unwrap();
    let r = Resolutions::new(1024.0, 1024.0, 1024.0).unwrap();
    for z in [1.0, 30.0, 1000.0] {
        let p = point_error(
            &v,
            &map,
            glam::DVec3::new(0.3 * z * 0.5f64.tan(), 0.0, -z),
            r,
        )
        .unwrap();
        assert!(close(p.mx, 1.0, REL), "m_x = {}", p.mx);
    }
    assert!(close(
        max_mx(1.0, 1000.0, NPrime::finite(1.0).unwrap(), r).unwrap(),
        1.0,
        1e-15
    ));
}

proptest! {
    #![proptest_config(config(128))]

    /// No input makes a closed form panic or return NaN or ±∞: each answers a finite value or a
    /// typed error.
    #[test]
    fn never_nan_or_infinite(n in any_f64(), f in any_f64(), th in any_f64(), np in any_f64(), z in any_f64(), e in any_f64()) {
        let ok = |r: Result<f64, shadow_aliasing::Error>| r.map_or(true, f64::is_finite);
        let np = NPrime::new(np).unwrap_or(NPrime::UNWARPED);
        let r = Resolutions::default();
        prop_assert!(ok(mx(n, f, np, z, r)));
        prop_assert!(ok(max_mx(n, f, np, r)));
        prop_assert!(ok(n_prime_lispsm(n, f)));
        prop_assert!(ok(eta_from_n_prime(n, f, np)));
        if let Ok(p) = n_prime_from_eta(n, f, e) {
            prop_assert!(p.value() > 0.0 && (p.is_unwarped() || p.value().is_finite()));
        }
        if let Ok(v) = ViewFrustum::new(n, f, th) {
            prop_assert!(ok(mz(&v, np, z, r)));
            prop_assert!(ok(max_mz(&v, np, r)));
            prop_assert!(ok(storage_factor(&v, np)));
            prop_assert!(ok(budget_error(&v, np, e, 1.0)));
            if let Ok(b) = budget_resolution(&v, np, e) {
                prop_assert!(b.res_s.is_finite() && b.res_t.is_finite());
            }
        }
    }
}

/// Eq 13, 14 by hand (checked, right; docs/errata.md): n = 1, f = 100, θ = 45°, n′ = 11,
/// res_i = 1024, S₀ = 2048². M_x = 10, M_z = 4.95 (unit resolutions), so res*_s/res*_t = 10/4.95
/// whatever res_i, res_s = 2048 √(10/4.95) = 2910.9, res_t = 1440.9, and both measured maxima
/// are res_i √(S̄/S₀) = 1024 √49.5 / 2048 = 3.5178: the error is split equally, as the text says.
#[test]
fn eq13_eq14_by_hand() {
    let v = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_4).unwrap();
    let l = NPrime::finite(11.0).unwrap();
    let s0 = 2048.0 * 2048.0;
    let b = budget_resolution(&v, l, s0).unwrap();
    assert!((b.res_s - 2910.9004).abs() < 1e-3 && (b.res_t - 1440.8957).abs() < 1e-3);
    let r = Resolutions::new(1024.0, b.res_s, b.res_t).unwrap();
    let m = frustum_max(&v, &overhead_map(&v, l).unwrap()).unwrap();
    // The twin measures with unit resolutions: scale by res_i / res_s and res_i / res_t.
    let (mx, mz) = (m.max_mx * r.image() / r.s(), m.max_mz * r.image() / r.t());
    assert!(
        (mx - 3.5178).abs() < 1e-4 && (mz - 3.5178).abs() < 1e-4,
        "{mx} {mz}"
    );
    assert!((budget_error(&v, l, s0, 1024.0).unwrap() - 3.5178).abs() < 1e-4);
}

/// Erratum (§4.4, the reason the vertices suffice): "It is sufficient to check just the vertices
/// because the beam widths increase monotonically over the convex view frustum". The beam widths
/// w_i, w_lx, w_lz do increase, but the errors m = w_l/w_i are ratios of increasing functions and
/// are not monotone: with LiSPSM's n′ = 11 at n = 1, f = 100, θ = 45° the measured m_z on the
/// axis is 4.95 at z = 1, 1.636 at z = 10 and 4.95 at z = 100. The conclusion holds for another
/// reason: m_z ∝ (a·p + c)²/(v·p) is a square over a positive linear function (convex) and m_x a
/// ratio of linear functions (quasi-linear), so their maxima over a convex polytope lie at its
/// vertices. Checked with a dense grid for tilted lights too (any light angle, both sides,
/// n′ from Barroso's rule, from the axis minimax and unwarped).
#[test]
fn errata_s4_4_vertices_suffice_by_convexity_not_monotonicity() {
    use shadow_aliasing::analytic::tilted::{generalized_n_prime, n_prime_axis_minimax, Falloff};
    use shadow_aliasing::measure::tilted_twin::{tilted_warp, TiltSide};
    use shadow_aliasing::LightAngle;
    let v = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_4).unwrap();
    let map = overhead_map(&v, NPrime::finite(11.0).unwrap()).unwrap();
    let at = |z: f64| {
        point_error(
            &v,
            &map,
            glam::DVec3::new(0.0, 0.0, -z),
            Resolutions::default(),
        )
        .unwrap()
        .mz
    };
    let (a, b, c) = (at(1.0), at(10.0), at(100.0));
    assert!((a - 4.95).abs() < 1e-9 && (c - 4.95).abs() < 1e-9);
    assert!((b - 49.5 * 400.0 / 12100.0).abs() < 1e-9 && (b - 1.636).abs() < 1e-3);
    assert!(b < a && b < c); // not monotone in z
    let view = ViewFrustum::new(0.7, 40.0, 0.6).unwrap();
    for deg in [3.0, 20.0, 34.0, 50.0, 75.0, 90.0] {
        let g = LightAngle::new(f64::to_radians(deg)).unwrap();
        for side in [TiltSide::InFront, TiltSide::Behind] {
            for np in [
                generalized_n_prime(&view, g, Falloff::Barroso),
                n_prime_axis_minimax(&view, g),
                NPrime::UNWARPED,
            ] {
                let w = tilted_warp(&view, g, side, np).unwrap();
                let vert = frustum_max(&view, &w.shadow).unwrap();
                let grid = frustum_max_sampled(&view, &w.shadow, 9).unwrap();
                assert!(
                    grid.max_mx <= vert.max_mx * (1.0 + 1e-9),
                    "{deg}° {side:?} {np:?}"
                );
                assert!(
                    grid.max_mz <= vert.max_mz * (1.0 + 1e-9),
                    "{deg}° {side:?} {np:?}"
                );
            }
        }
    }
}

/// Erratum (§4.4, Fig 7's description): "Figure 7 shows S̄ over the entire hemisphere of light
/// directions above a viewer with and without warping (n′ = ∞ and n′ = n′_LSPSM, respectively)"
/// pairs the two the wrong way round: n′ = ∞ is the map *without* warping. Overhead at n = 1,
/// f = 100, θ = 30°: n′ = ∞ gives S̄ = 99·100/(2 tan 30°) = 8573.65, n′_LSPSM = 11 gives 85.737
/// (measured on the twin, Eq 12), and the text's own next sentence ("without warping, the error
/// is high over all light directions") needs the larger one to be the unwarped map.
#[test]
fn errata_s4_4_fig7_with_and_without_warping_swapped() {
    let v = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_6).unwrap();
    let unwarped = frustum_max(&v, &overhead_map(&v, NPrime::UNWARPED).unwrap())
        .unwrap()
        .storage_factor;
    let lispsm = frustum_max(
        &v,
        &overhead_map(&v, NPrime::finite(11.0).unwrap()).unwrap(),
    )
    .unwrap()
    .storage_factor;
    assert!((unwarped - 8573.65).abs() < 0.01, "{unwarped}");
    assert!((lispsm - 85.7365).abs() < 1e-3, "{lispsm}");
    assert!(close(
        unwarped,
        storage_factor(&v, NPrime::UNWARPED).unwrap(),
        REL
    ));
    assert!(close(
        lispsm,
        storage_factor(&v, NPrime::finite(11.0).unwrap()).unwrap(),
        REL
    ));
}

/// §4.3: "for values of n′ ≤ n′_LSPSM in Eq. 12, S̄ is minimal and does not depend on n′" (PSM,
/// LiSPSM and some TSMs equivalent) holds for the light overhead only. Away from it the measured
/// S̄ of maps fitted with explicit n′ (PSM's n′ = n = 1, n′ = 6, LiSPSM's n′ = n + √(f n) = 11)
/// differ: n = 1, f = 100, θ = 30°, the light 45° above the horizon behind the viewer: 642.11,
/// 360.55, 311.67; overhead all three are Eq 12's 99/(2 tan 30°) = 85.737.
#[test]
fn errata_s4_3_equivalence_only_overhead() {
    use glam::DVec3;
    use shadow_aliasing::maps::{fit_warp, light_space};
    use shadow_aliasing::measure::ShadowMap;
    use shadow_aliasing::scheme::sweep::light_dir_from_angles;
    let v = ViewFrustum::new(1.0, 100.0, 30f64.to_radians()).unwrap();
    let s_bar = |l: DVec3, np: f64| {
        let ls = light_space(l, DVec3::NEG_Z).unwrap();
        let m = fit_warp(&v.corners(), &ls, NPrime::finite(np).unwrap()).unwrap();
        frustum_max(&v, &ShadowMap::new(m, l).unwrap())
            .unwrap()
            .storage_factor
    };
    let n_primes = [1.0, 6.0, 1.0 + (100.0f64).sqrt()];
    let eq12 = 99.0 / (2.0 * 30f64.to_radians().tan());
    for np in n_primes {
        assert!(close(s_bar(DVec3::NEG_Y, np), eq12, REL));
    }
    let behind = light_dir_from_angles(45f64.to_radians(), 0.0);
    let s: Vec<f64> = n_primes.iter().map(|&np| s_bar(behind, np)).collect();
    assert!((s[0] - 642.11).abs() < 5e-3, "{}", s[0]);
    assert!((s[1] - 360.55).abs() < 5e-3, "{}", s[1]);
    assert!((s[2] - 311.67).abs() < 5e-3, "{}", s[2]);
    assert!(s[0] > 2.0 * s[2]);
}

/// App. C's w_lz line, garbled in the transcription ("1/res_t z log(f/n) n"): from
/// t = ln(z/n)/ln(f/n), dz/dt = z ln(f/n) (central differences of t), so w_lz = z ln(f/n)/res_t and
/// m_z = ln(f/n)/(2 tan θ) with w_i = 2 z tan θ (unit resolutions). n = 2, f = 200, θ = 30°,
/// z = 20: dz/dt = 92.103; read as z/ln(f/n), 4.343; with Eq 2's stray /n, z ln(f/n)/n = 46.05.
#[test]
fn errata_app_c_w_lz_line() {
    use shadow_aliasing::analytic::partition::optimal_storage_factor;
    let (n, f, th) = (2.0f64, 200.0f64, 30f64.to_radians());
    let t = |z: f64| (z / n).ln() / (f / n).ln();
    assert!(t(n).abs() < 1e-15 && (t(f) - 1.0).abs() < 1e-15);
    for z in [2.5, 20.0, 150.0] {
        let h = 1e-5 * z;
        let dz_dt = 2.0 * h / (t(z + h) - t(z - h));
        assert!(close(dz_dt, z * (f / n).ln(), 1e-8), "{dz_dt}");
        let m_z = dz_dt / (2.0 * z * th.tan());
        let v = ViewFrustum::new(n, f, th).unwrap();
        assert!(close(m_z, optimal_storage_factor(&v).unwrap(), 1e-8));
        assert!(close(m_z, 3.988, 1e-4));
        // The two other readings of the garbled line are not dz/dt.
        assert!(z / (f / n).ln() < 0.05 * dz_dt && close(z * (f / n).ln() / n, dz_dt / n, 1e-8));
    }
    let z = 20.0;
    assert!((z * (f / n).ln() - 92.103).abs() < 1e-3);
    assert!((z / (f / n).ln() - 4.343).abs() < 1e-3);
    assert!((z * (f / n).ln() / n - 46.05).abs() < 1e-2);
}
