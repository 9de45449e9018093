//! Barroso & Celes 2007 §3.1 against the numeric twin: the tilted light's warping frustum built
//! as a matrix (`measure::tilted_twin`) and measured with exact derivatives.

mod common;
use common::{rel, tilted_view};
use glam::DVec3;
use proptest::prelude::*;
use shadow_aliasing::analytic::global::zhang_ep;
use shadow_aliasing::analytic::tilted::{
    falloff_r, gamma_lim, generalized_n_prime, n_prime_1, n_prime_2, n_prime_axis_minimax,
    n_prime_equal_error, tilted_mz, tilted_mz_perpendicular, tilted_psi, tilted_xi,
    warp_depth_range, Falloff,
};
use shadow_aliasing::measure::tilted_twin::{mz_along_view_axis, tilted_warp, TiltSide};
use shadow_aliasing::measure::{frustum_max, point_error};
use shadow_aliasing::{Error, LightAngle, NPrime, Resolutions, ViewFrustum};
use std::f64::consts::{FRAC_PI_2, FRAC_PI_6};

#[derive(Debug, Clone, Copy)]
struct Config {
    view: ViewFrustum,
    gamma: f64,
    n_prime: f64,
    z: f64,
    res: Resolutions,
}

/// A random configuration: a `common::tilted_view`, γ, n′, a depth z and resolutions.
fn configs() -> impl Strategy<Value = Config> {
    (
        tilted_view(),
        0.0f64..=1.0, // γ/(π/2)
        -2.0f64..2.5, // log10(n′/n)
        0.0f64..=1.0, // (z − n)/(f − n)
        (0.1f64..10.0, 0.1f64..10.0),
    )
        .prop_map(|(view, g, lp, w, (ri, rt))| {
            let (n, f) = (view.near(), view.far());
            let gamma = g * FRAC_PI_2;
            // The twin evaluates t = A + B/z′ through a 4×4 matrix, which loses about
            // log10(f′/n′) digits of the measured gradient; f′/n′ ≤ 10⁵ keeps it good to 1e-10.
            let mu = warp_depth_range(&view, LightAngle::new(gamma).unwrap()).unwrap();
            Config {
                view,
                gamma,
                n_prime: (n * 10f64.powf(lp)).max(1e-5 * mu),
                z: (n + w * (f - n)).clamp(n, f),
                res: Resolutions::new(ri, 1.0, rt).unwrap(),
            }
        })
}

/// Lloyd 2006 Eq 8, written out: m_z = (res_i/res_t)(f − n)/(2 tan θ)(n′ + z − n)²/(z n′(n′ + f − n)).
fn lloyd_eq8(n: f64, f: f64, tan: f64, np: f64, z: f64, res: Resolutions) -> f64 {
    res.image() / res.t() * (f - n) / (2.0 * tan) * (np + z - n).powi(2) / (z * np * (np + f - n))
}

proptest! {
    #![proptest_config(common::config(256))]

    /// Eq 12 is the texel width along the view axis (Eq 6) of the twin, on the axis, for every
    /// γ ∈ (0, π/2], n′ > 0 and both sides of the viewer; unwarped too.
    #[test]
    fn eq12_is_the_along_axis_width_of_the_twin(c in configs()) {
        prop_assume!(c.gamma > 1e-6);
        let g = LightAngle::new(c.gamma).unwrap();
        let p = DVec3::new(0.0, 0.0, -c.z);
        for np in [NPrime::finite(c.n_prime).unwrap(), NPrime::UNWARPED] {
            let closed = tilted_mz(&c.view, np, g, c.z, c.res).unwrap();
            for side in [TiltSide::InFront, TiltSide::Behind] {
                let w = tilted_warp(&c.view, g, side, np).unwrap();
                let meas = mz_along_view_axis(&c.view, &w.shadow, p, c.res).unwrap();
                prop_assert!(rel(closed, meas) < 1e-9, "{closed} vs {meas} ({np:?}, {side:?})");
            }
        }
    }

    /// Eq 12 × sin γ is the crate's perpendicular m_z (distance between t-isolines ⊥ light), for
    /// every γ ∈ [0, π/2], and twice it is Zhang's E_p^pers at y = 0 (unit resolutions).
    #[test]
    fn eq12_times_sin_gamma_is_the_perpendicular_measurement(c in configs()) {
        let g = LightAngle::new(c.gamma).unwrap();
        let np = NPrime::finite(c.n_prime).unwrap();
        let perp = tilted_mz_perpendicular(&c.view, np, g, c.z, c.res).unwrap();
        let w = tilted_warp(&c.view, g, TiltSide::Behind, np).unwrap();
        let m = point_error(&c.view, &w.shadow, DVec3::new(0.0, 0.0, -c.z), c.res).unwrap();
        prop_assert!(rel(perp, m.mz) < 1e-9, "{perp} vs {}", m.mz);
        if c.gamma > 1e-6 {
            let b = tilted_mz(&c.view, np, g, c.z, c.res).unwrap();
            prop_assert!(rel(b * c.gamma.sin(), perp) < 1e-12);
        }
        let unit = tilted_mz_perpendicular(&c.view, np, g, c.z, Resolutions::default()).unwrap();
        let ep = zhang_ep(&c.view, np, g, 0.0, c.z).unwrap();
        prop_assert!(rel(2.0 * unit, ep) < 1e-9);
    }

    /// ξ ψ²/z written from the parts (Eq 10, 11, 12) is the same function; ψ is the twin's warp
    /// depth z′ and f′ − n′ the twin's depth range.
    #[test]
    fn parts_match_the_twin(c in configs()) {
        prop_assume!(c.gamma > 1e-6);
        let g = LightAngle::new(c.gamma).unwrap();
        let w = tilted_warp(&c.view, g, TiltSide::Behind, NPrime::finite(c.n_prime).unwrap()).unwrap();
        let psi = tilted_psi(&c.view, c.n_prime, g, c.z).unwrap();
        let zp = DVec3::new(0.0, 0.0, -c.z).dot(w.warp_axis) - w.z_min + c.n_prime;
        prop_assert!(rel(psi, zp) < 1e-9);
        prop_assert!(rel(warp_depth_range(&c.view, g).unwrap(), w.depth_range) < 1e-9);
        let xi = tilted_xi(&c.view, c.n_prime, g, c.res).unwrap();
        let m = tilted_mz(&c.view, NPrime::finite(c.n_prime).unwrap(), g, c.z, c.res).unwrap();
        prop_assert!(rel(xi * psi * psi / c.z, m) < 1e-12);
    }

    /// No input makes a public function panic or return a non-finite number.
    #[test]
    fn any_input_is_an_error_or_finite(
        c in configs(),
        np in proptest::num::f64::ANY,
        z in proptest::num::f64::ANY,
        g in proptest::num::f64::ANY,
    ) {
        let gammas = [LightAngle::new(g).ok(), LightAngle::new(c.gamma).ok()];
        for gamma in gammas.into_iter().flatten() {
            for n_prime in [NPrime::finite(np).ok(), Some(NPrime::new(np).unwrap_or(NPrime::UNWARPED))].into_iter().flatten() {
                for zz in [z, c.z] {
                    for v in [
                        tilted_mz(&c.view, n_prime, gamma, zz, c.res),
                        tilted_mz_perpendicular(&c.view, n_prime, gamma, zz, c.res),
                        tilted_psi(&c.view, np, gamma, zz),
                        tilted_xi(&c.view, np, gamma, c.res),
                    ]
.into_iter()
.flatten()
{
prop_assert!(v.is_finite());
}
                }
            }
            for fo in [Falloff::Zhang, Falloff::Barroso] {
                if let Some(v) = generalized_n_prime(&c.view, gamma, fo).as_finite() {
                    prop_assert!(v.is_finite() && v > 0.0);
                }
            }
            if let Some(v) = n_prime_axis_minimax(&c.view, gamma).as_finite() {
                prop_assert!(v.is_finite() && v > 0.0);
            }
        }
    }

    /// Overhead, Barroso's m_z is Lloyd 2006 Eq 8 and n′₁ is n + √(fn).
    #[test]
    fn overhead_is_lloyd(c in configs()) {
        let (n, f) = (c.view.near(), c.view.far());
        let up = LightAngle::new(FRAC_PI_2).unwrap();
        prop_assert!(rel(n_prime_1(&c.view, up), n + (f * n).sqrt()) < 1e-12);
        let np = c.n_prime.max(n);
        let m = tilted_mz(&c.view, NPrime::finite(np).unwrap(), up, c.z, c.res).unwrap();
        prop_assert!(rel(m, lloyd_eq8(n, f, c.view.tan_half_fov(), np, c.z, c.res)) < 1e-12);
    }

    /// Eq 13: at n′₁ (γ ≥ φ) or n′₂ (γ < φ), when positive, the measured along-axis m_z is equal
    /// on the near and far planes. Where n′* ≤ n′_eq any other n′ has a larger maximum of the
    /// two; otherwise n′* ([`n_prime_axis_minimax`]) does better.
    #[test]
    fn eq13_equalises_near_and_far_on_the_twin(c in configs()) {
        prop_assume!(c.gamma > 1e-3);
        let g = LightAngle::new(c.gamma).unwrap();
        let np = match n_prime_equal_error(&c.view, g).map(NPrime::as_finite) {
            Ok(Some(v)) => v,
            Ok(None) => unreachable!(),
            Err(Error::NoSolution(_)) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        let v = &c.view;
        let at = |np: f64, z: f64| {
            let w = tilted_warp(v, g, TiltSide::Behind, NPrime::finite(np).unwrap()).unwrap();
            mz_along_view_axis(v, &w.shadow, DVec3::new(0.0, 0.0, -z), Resolutions::default()).unwrap()
        };
        let (mn, mf) = (at(np, v.near()), at(np, v.far()));
        prop_assert!(rel(mn, mf) < 1e-9, "{mn} vs {mf}");
        let opt = n_prime_axis_minimax(v, g).value();
        let max_at = |np: f64| at(np, v.near()).max(at(np, v.far()));
        if rel(opt, np) < 1e-12 {
            for k in [0.98, 1.02] {
                prop_assert!(max_at(np * k) > mn);
            }
        } else {
            prop_assert!(opt > np && max_at(opt) < mn);
        }
    }

    /// The axis minimax n′ beats its neighbours on the twin (measured along the view axis), for
    /// every γ, including where Eq 13 has no positive solution.
    #[test]
    fn axis_minimax_is_a_minimum_on_the_twin(c in configs()) {
        prop_assume!(c.gamma > 1e-3);
        let g = LightAngle::new(c.gamma).unwrap();
        let v = &c.view;
        let max_at = |np: NPrime| {
            let w = tilted_warp(v, g, TiltSide::Behind, np).unwrap();
            let m = |z: f64| mz_along_view_axis(v, &w.shadow, DVec3::new(0.0, 0.0, -z), Resolutions::default()).unwrap();
            m(v.near()).max(m(v.far()))
        };
        let opt = n_prime_axis_minimax(v, g);
        let best = max_at(opt);
        if let Some(o) = opt.as_finite() {
            for k in [0.9, 0.99, 1.01, 1.1] {
                prop_assert!(max_at(NPrime::finite(o * k).unwrap()) >= best * (1.0 - 1e-12));
            }
        }
        prop_assert!(max_at(NPrime::UNWARPED) >= best * (1.0 - 1e-12));
    }

    /// The fall-offs r(γ) (Eq 17, 18) rise from 0 at γ = 0 to 1 at γ_lim, and Eq 18 lies below
    /// Eq 17 (it "descends faster"); the generalised n′ (Eq 16) is n′₁ above γ_lim, continuous
    /// there, LiSPSM's overhead, and grows without bound as γ → 0.
    #[test]
    fn generalised_n_prime_properties(c in configs(), u in 0.0f64..1.0) {
        let gl = gamma_lim(&c.view);
        let gamma = u * gl;
        let (z, b) = (falloff_r(Falloff::Zhang, gamma, gl), falloff_r(Falloff::Barroso, gamma, gl));
        prop_assert!((0.0..=1.0).contains(&z) && b <= z + 1e-15);
        prop_assert!(falloff_r(Falloff::Zhang, gamma * 0.5, gl) <= z);
        prop_assert!(falloff_r(Falloff::Barroso, gamma * 0.5, gl) <= b);
        let at_lim = n_prime_1(&c.view, LightAngle::new(gl).unwrap());
        prop_assert!(at_lim > 0.0);
        for fo in [Falloff::Zhang, Falloff::Barroso] {
            let below = generalized_n_prime(&c.view, LightAngle::new(gl * (1.0 - 1e-12)).unwrap(), fo);
            prop_assert!(rel(below.value(), at_lim) < 1e-9);
            let v = generalized_n_prime(&c.view, LightAngle::new(gamma).unwrap(), fo);
            prop_assert!(v.value() >= at_lim * (1.0 - 1e-12));
            let above = gl + (FRAC_PI_2 - gl) * u;
            let g = LightAngle::new(above).unwrap();
            prop_assert_eq!(generalized_n_prime(&c.view, g, fo), NPrime::finite(n_prime_1(&c.view, g)).unwrap());
        }
    }
}

proptest! {
    #![proptest_config(common::config(256))]

    /// Eq 15 to 18 as printed, evaluated here: γ_lim = atan((f + n) tan φ/(f − n)); Zhang's
    /// r = sin((γ/γ_lim) π/2) (Eq 17) and Barroso's r = [1 + sin((γ/γ_lim − 1) π/2)]² (Eq 18,
    /// which the crate evaluates as 4 sin⁴(γ π/(4 γ_lim))); n′ = (n + √(fn)) sin γ − n tan φ cos γ
    /// above γ_lim and n′₁(γ_lim)/r(γ) below it (Eq 16). γ/γ_lim ≥ 0.01, where the printed
    /// Eq 18 loses at most 10⁻¹² to cancellation.
    #[test]
    fn eq15_to_eq18_by_hand(view in tilted_view(), u in 0.01f64..=1.0, w in 0.0f64..=1.0) {
        let (n, f, t) = (view.near(), view.far(), view.tan_half_fov());
        let gl = ((f + n) * t / (f - n)).atan();
        prop_assert!(rel(gamma_lim(&view), gl) < 1e-13, "γ_lim {} vs {gl}", gamma_lim(&view));
        let n1 = |g: f64| (n + (f * n).sqrt()) * g.sin() - n * t * g.cos();
        let gamma = u * gl;
        let zhang = (u * FRAC_PI_2).sin();
        let barroso = (1.0 + ((u - 1.0) * FRAC_PI_2).sin()).powi(2);
        prop_assert!(rel(falloff_r(Falloff::Zhang, gamma, gl), zhang) < 1e-12);
        prop_assert!(rel(falloff_r(Falloff::Barroso, gamma, gl), barroso) < 1e-12);
        for (fo, r) in [(Falloff::Zhang, zhang), (Falloff::Barroso, barroso)] {
            let below = generalized_n_prime(&view, LightAngle::new(gamma).unwrap(), fo);
            if u < 1.0 {
                prop_assert!(rel(below.value(), n1(gl) / r) < 1e-9, "{fo:?} γ = {gamma}: {below:?} vs {}", n1(gl) / r);
            }
            let above = gl + w * (FRAC_PI_2 - gl);
            let n_above = generalized_n_prime(&view, LightAngle::new(above).unwrap(), fo);
            prop_assert!(rel(n_above.value(), n1(above)) < 1e-9, "{fo:?} γ = {above}: {n_above:?} vs {}", n1(above));
        }
    }
}

/// γ_lim (Eq 15) is where, in the light's view, the near face's far edge meets the far face's
/// near edge: with the light behind the viewer, the near-top and far-bottom corners have the same
/// coordinate along the warp axis. And it exceeds φ, as Barroso requires.
#[test]
fn gamma_lim_is_where_near_and_far_faces_meet() {
    for (n, f, phi) in [(1.0, 100.0, FRAC_PI_6), (0.3, 2.0, 0.1), (2.0, 2000.0, 1.2)] {
        let view = ViewFrustum::new(n, f, phi).unwrap();
        let gl = gamma_lim(&view);
        assert!(gl > phi && gl < FRAC_PI_2);
        let w = tilted_warp(
            &view,
            LightAngle::new(gl).unwrap(),
            TiltSide::Behind,
            NPrime::UNWARPED,
        )
        .unwrap();
        let c = view.corners();
        // corners(): near plane (−x−y, +x−y, +x+y, −x+y), then far.
        let near_top = c[2].dot(w.warp_axis);
        let far_bottom = c[4].dot(w.warp_axis);
        assert!(
            rel(near_top, far_bottom) < 1e-12,
            "{near_top} vs {far_bottom}"
        );
    }
}

/// Eq 13's two branches meet at γ = φ (both √(fn) sin φ); n′₂ is negative near parallel light
/// (Barroso's remark); n′(γ) of Eq 16 first decreases as the light tilts from overhead (the warp
/// becomes stronger, Fig 7), then increases below γ_lim. Numbers at n = 1, f = 100, φ = π/6
/// (Fig 7): n′ = 11 overhead, 9.238 at 60°, n′₁(γ_lim = 30.50°) = 5.085; at 10° Zhang's fall-off
/// gives 10.32 and Barroso's 302.2.
#[test]
fn figure_7_shape() {
    let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6).unwrap();
    let at = |deg: f64| LightAngle::new(f64::to_radians(deg)).unwrap();
    let s = (100.0f64).sqrt() * 0.5;
    assert!(rel(n_prime_1(&view, LightAngle::new(FRAC_PI_6).unwrap()), s) < 1e-12);
    assert!(
        rel(
            n_prime_2(&view, LightAngle::new(FRAC_PI_6).unwrap()).unwrap(),
            s
        ) < 1e-12
    );
    assert!(n_prime_2(&view, at(10.0)).unwrap() < 0.0);
    assert!(matches!(
        n_prime_equal_error(&view, at(10.0)),
        Err(Error::NoSolution(_))
    ));
    assert!((gamma_lim(&view).to_degrees() - 30.4987).abs() < 1e-4);
    let nz = |deg: f64| generalized_n_prime(&view, at(deg), Falloff::Zhang).value();
    let nb = |deg: f64| generalized_n_prime(&view, at(deg), Falloff::Barroso).value();
    assert!((nz(90.0) - 11.0).abs() < 1e-12);
    assert!((nz(60.0) - 9.2376).abs() < 1e-4);
    assert!((nz(gamma_lim(&view).to_degrees()) - 5.0852).abs() < 1e-4);
    assert!((nz(10.0) - 10.324).abs() < 1e-3);
    assert!((nb(10.0) - 302.17).abs() < 1e-2);
    let mut prev = nz(90.0);
    for deg in [80.0, 70.0, 60.0, 50.0, 40.0, 31.0] {
        assert!(nz(deg) < prev);
        prev = nz(deg);
    }
    for deg in [25.0, 15.0, 5.0, 1.0, 0.0] {
        assert!(nz(deg) > prev && nb(deg) >= nz(deg));
        prev = nz(deg);
    }
    assert_eq!(
        generalized_n_prime(&view, at(0.0), Falloff::Barroso),
        NPrime::UNWARPED
    );
}

/// Erratum: Eq 12 measures the texel along the view axis (Eq 6), not perpendicular to the light
/// as Eq 3's perspective aliasing and Lloyd 2006 §4.4 do; the two differ by sin γ. At n = 1,
/// f = 100, φ = 30°, γ = 45°, n′ = n′₁ = 7.370, z = n: Eq 12 gives 9.429, the perpendicular
/// measurement 6.667 (the along-axis measurement of the twin, 9.429).
#[test]
fn eq12_is_along_the_view_axis_not_perpendicular() {
    let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6).unwrap();
    let g = LightAngle::new(45f64.to_radians()).unwrap();
    let np = n_prime_1(&view, g);
    assert!((np - 7.370).abs() < 1e-3);
    let w = tilted_warp(&view, g, TiltSide::Behind, NPrime::finite(np).unwrap()).unwrap();
    let p = DVec3::new(0.0, 0.0, -1.0);
    let perp = point_error(&view, &w.shadow, p, Resolutions::default())
        .unwrap()
        .mz;
    let along = mz_along_view_axis(&view, &w.shadow, p, Resolutions::default()).unwrap();
    let eq12 = tilted_mz(
        &view,
        NPrime::finite(np).unwrap(),
        g,
        1.0,
        Resolutions::default(),
    )
    .unwrap();
    assert!((eq12 - 9.429).abs() < 1e-3, "{eq12}");
    assert!((perp - 6.6675).abs() < 1e-4, "{perp}");
    assert!(rel(eq12, along) < 1e-12);
}

/// Erratum: Eq 13 equalises m_z on the view axis only. Over the frustum the maximum is at the
/// vertices (Zhang's G depends on y), and n′₁ does not minimise it: at n = 1, f = 100, φ = 30°,
/// γ = 60°, n′₁ = 9.238 gives a measured maximum (perpendicular, over the eight vertices)
/// M_z = 13.37, while n′ = 12.11 gives 10.43.
#[test]
fn eq13_does_not_minimise_the_frustum_maximum() {
    let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6).unwrap();
    let g = LightAngle::new(60f64.to_radians()).unwrap();
    let mz = |np: f64| {
        let w = tilted_warp(&view, g, TiltSide::Behind, NPrime::finite(np).unwrap()).unwrap();
        frustum_max(&view, &w.shadow).unwrap().max_mz
    };
    let n1 = n_prime_1(&view, g);
    assert!((n1 - 9.2376).abs() < 1e-4);
    assert!((mz(n1) - 13.37).abs() < 1e-2, "{}", mz(n1));
    assert!((mz(12.11) - 10.43).abs() < 1e-2, "{}", mz(12.11));
}

#[test]
fn domain_errors() {
    let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6).unwrap();
    let g = LightAngle::new(1.0).unwrap();
    let res = Resolutions::default();
    let name = |r: Result<f64, Error>| match r {
        Err(Error::InvalidArgument { name, .. }) => name,
        other => panic!("{other:?}"),
    };
    assert_eq!(
        name(NPrime::finite(0.0).and_then(|n| tilted_mz(&view, n, g, 2.0, res))),
        "n_prime"
    );
    assert_eq!(
        name(NPrime::finite(f64::NAN).and_then(|n| tilted_mz(&view, n, g, 2.0, res))),
        "n_prime"
    );
    assert_eq!(
        name(tilted_mz(&view, NPrime::finite(1.0).unwrap(), g, 0.5, res)),
        "z"
    );
    assert_eq!(
        name(tilted_mz(
            &view,
            NPrime::finite(1.0).unwrap(),
            g,
            f64::NAN,
            res
        )),
        "z"
    );
    let g0 = LightAngle::new(0.0).unwrap();
    assert_eq!(
        name(tilted_mz(&view, NPrime::UNWARPED, g0, 2.0, res)),
        "light_angle"
    );
    assert_eq!(name(tilted_xi(&view, 1.0, g0, res)), "light_angle");
    assert_eq!(name(tilted_psi(&view, -1.0, g, 2.0)), "n_prime");
    // Perpendicular m_z is finite at γ = 0 and equals the twin there.
    let w = tilted_warp(&view, g0, TiltSide::Behind, NPrime::finite(3.0).unwrap()).unwrap();
    let m = point_error(&view, &w.shadow, DVec3::new(0.0, 0.0, -7.0), res).unwrap();
    let c = tilted_mz_perpendicular(&view, NPrime::finite(3.0).unwrap(), g0, 7.0, res).unwrap();
    assert!(rel(c, m.mz) < 1e-12);
    assert!(mz_along_view_axis(&view, &w.shadow, DVec3::new(0.0, 0.0, -7.0), res).is_err());
}

/// Erratum: Eq 13 ("the maximum … can be minimized by making its value equal on those
/// extremes") holds only when m_z(n) is already increasing in n′ at the equal-error n′. At n = 1,
/// f = 100, φ = 30°, γ = 28°, n′₂ = 0.6649 equalises the along-axis errors at 73.51, while
/// n′ = 4.935 has maximum 31.73 (measured on the twin). And where n′₂ ≤ 0 (γ = 20°), which
/// Barroso reads as "impossible to satisfy", the maximum still has a finite minimiser n′ = 32.68
/// (maximum 167.73, unwarped 274.75).
#[test]
fn eq13_is_not_always_the_minimax() {
    let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6).unwrap();
    let max_at = |g: LightAngle, np: NPrime| {
        let w = tilted_warp(&view, g, TiltSide::Behind, np).unwrap();
        let m = |z: f64| {
            mz_along_view_axis(
                &view,
                &w.shadow,
                DVec3::new(0.0, 0.0, -z),
                Resolutions::default(),
            )
            .unwrap()
        };
        m(1.0).max(m(100.0))
    };
    let g = LightAngle::new(28f64.to_radians()).unwrap();
    let n2 = n_prime_2(&view, g).unwrap();
    assert!((n2 - 0.6649).abs() < 1e-4);
    assert!(
        (max_at(g, NPrime::finite(n2).unwrap()) - 73.51).abs() < 1e-2,
        "{}",
        max_at(g, NPrime::finite(n2).unwrap())
    );
    let opt = n_prime_axis_minimax(&view, g);
    assert!((opt.value() - 4.9349).abs() < 1e-4, "{}", opt.value());
    assert!((max_at(g, opt) - 31.73).abs() < 1e-2, "{}", max_at(g, opt));
    let g = LightAngle::new(20f64.to_radians()).unwrap();
    assert!(n_prime_2(&view, g).unwrap() < 0.0);
    let opt = n_prime_axis_minimax(&view, g);
    assert!((opt.value() - 32.68).abs() < 1e-2);
    assert!((max_at(g, opt) - 167.73).abs() < 1e-2, "{}", max_at(g, opt));
    assert!(
        (max_at(g, NPrime::UNWARPED) - 274.75).abs() < 1e-2,
        "{}",
        max_at(g, NPrime::UNWARPED)
    );
    // Marginally on the n′₁ branch too, for a wide field of view: n = 1, f = 2, φ = 1.2,
    // γ = 1.25: 0.50535 at n′₁ = 1.480, 0.50519 at n′* = 1.559.
    let wide = ViewFrustum::new(1.0, 2.0, 1.2).unwrap();
    let g = LightAngle::new(1.25).unwrap();
    let m = |np: NPrime| {
        let r = Resolutions::default();
        tilted_mz(&wide, np, g, 1.0, r)
            .unwrap()
            .max(tilted_mz(&wide, np, g, 2.0, r).unwrap())
    };
    let (n1, opt) = (n_prime_1(&wide, g), n_prime_axis_minimax(&wide, g));
    assert!((n1 - 1.480).abs() < 1e-3 && (opt.value() - 1.559).abs() < 1e-3);
    assert!((m(NPrime::finite(n1).unwrap()) - 0.50535).abs() < 1e-5);
    assert!((m(opt) - 0.50519).abs() < 1e-5);
}

/// Erratum (notation, Eq 14 and 16): the constraints of Eq 14 and the second branch of Eq 16
/// call the fall-off warp parameter n′₂, the name Eq 13 gives to the equal-error solution for
/// γ < φ_y, a different function. At n = 1, f = 100, φ_y = 30°, γ = 20°: Eq 13's n′₂ = −16.63
/// (no warp equalises the errors), Eq 16's "n′₂" = n′₁(γ_lim)/r(γ) = 5.931 (Eq 17) or 21.60
/// (Eq 18), with γ_lim = 30.50° and n′₁(γ_lim) = 5.085. The crate keeps `n_prime_2` for Eq 13 and
/// calls Eq 16 `generalized_n_prime`.
#[test]
fn eq16_reuses_the_name_n_prime_2() {
    let view = ViewFrustum::new(1.0, 100.0, FRAC_PI_6).unwrap();
    let g = LightAngle::new(20f64.to_radians()).unwrap();
    let eq13 = n_prime_2(&view, g).unwrap();
    assert!((eq13 + 16.631).abs() < 1e-3);
    let gl = gamma_lim(&view);
    assert!((gl.to_degrees() - 30.4987).abs() < 1e-4);
    let at_lim = n_prime_1(&view, LightAngle::new(gl).unwrap());
    assert!((at_lim - 5.0852).abs() < 1e-4);
    let zhang = generalized_n_prime(&view, g, Falloff::Zhang).value();
    let barroso = generalized_n_prime(&view, g, Falloff::Barroso).value();
    // By hand: n′₁(γ_lim) / sin((γ/γ_lim)·π/2) and n′₁(γ_lim) / [1 + sin((γ/γ_lim − 1)·π/2)]².
    let u = 20f64.to_radians() / gl;
    assert!(rel(zhang, at_lim / (u * FRAC_PI_2).sin()) < 1e-12 && (zhang - 5.9314).abs() < 1e-4);
    let r18 = (1.0 + ((u - 1.0) * FRAC_PI_2).sin()).powi(2);
    assert!(rel(barroso, at_lim / r18) < 1e-12 && (barroso - 21.597).abs() < 1e-3);
    assert!(eq13 < 0.0 && zhang > 0.0 && barroso > 0.0);
}

/// §2.4: "the maximum aliasing error in each partition is proportional to its f/n ratio". The
/// measured maxima of a partition depend on f/n alone ([1, 4] and [10, 40] agree) and grow with
/// it, which is all the self-similar optimum needs, but only the unwarped M_x is proportional to
/// it. θ = 30°, ratio 4 → 16: LiSPSM M_z 1.299 → 3.248 (× 2.5), M_x 2 → 4 (√(f/n)), S̄ 2.598 →
/// 12.99 (× 5, f/n − 1); unwarped M_z 2.598 → 12.99 (× 5), M_x 4 → 16 (× 4).
#[test]
fn errata_s2_4_partition_error_not_proportional_to_ratio() {
    use shadow_aliasing::measure::twin::overhead_map;
    let th = 30f64.to_radians();
    let measure = |n: f64, f: f64, warped: bool| {
        let v = ViewFrustum::new(n, f, th).unwrap();
        let np = if warped {
            NPrime::finite(v.n_prime_lispsm()).unwrap()
        } else {
            NPrime::UNWARPED
        };
        frustum_max(&v, &overhead_map(&v, np).unwrap()).unwrap()
    };
    for warped in [true, false] {
        let (a, b, c) = (
            measure(1.0, 4.0, warped),
            measure(10.0, 40.0, warped),
            measure(1.0, 16.0, warped),
        );
        // Scale invariance: only the ratio matters.
        assert!(rel(a.max_mz, b.max_mz) < 1e-9 && rel(a.max_mx, b.max_mx) < 1e-9);
        let (rz, rx, rs) = (
            c.max_mz / a.max_mz,
            c.max_mx / a.max_mx,
            c.storage_factor / a.storage_factor,
        );
        if warped {
            assert!((a.max_mz - 1.299).abs() < 1e-3 && (c.max_mz - 3.248).abs() < 1e-3);
            assert!(rel(rz, 2.5) < 1e-9 && rel(rx, 2.0) < 1e-9 && rel(rs, 5.0) < 1e-9);
            assert!((a.storage_factor - 2.598).abs() < 1e-3);
            assert!((c.storage_factor - 12.99).abs() < 1e-2);
        } else {
            assert!((a.max_mz - 2.598).abs() < 1e-3 && (c.max_mz - 12.99).abs() < 1e-2);
            assert!(rel(rz, 5.0) < 1e-9 && rel(rx, 4.0) < 1e-9);
        }
    }
}

/// Eq 13's n′ can lie below n (n′₁ when √(f n) sin γ is small: narrow fields of view or small
/// f/n), and there it is right: the centre of projection sits n′ before the frustum's nearest
/// extent along the warp axis, not before the near plane, and n′₁ is still the along-axis
/// minimax. n = 1, f = 100, φ = 1°, γ = 2°: n′₁ = 0.3665 (Eq 16 uses it, γ_lim = 1.020°), along-axis
/// maximum 308.43 against 713.00 at n′ = n; n = 1, f = 2, φ = 30°, γ = 35°: n′₁ = 0.9118,
/// 2.1783 against 2.1810 at n′ = n. The crate returns these values unclamped.
#[test]
fn errata_eq13_n_prime_below_near_is_right() {
    let axis_max = |v: &ViewFrustum, g: LightAngle, np: f64| {
        let w = tilted_warp(v, g, TiltSide::InFront, NPrime::finite(np).unwrap()).unwrap();
        let at = |z: f64| {
            mz_along_view_axis(
                v,
                &w.shadow,
                DVec3::new(0.0, 0.0, -z),
                Resolutions::default(),
            )
            .unwrap()
        };
        (at(v.near()), at(v.far()))
    };
    let cases = [
        (100.0, 1.0f64, 2.0f64, 0.3665, 308.43, 713.00),
        (2.0, 30.0, 35.0, 0.9118, 2.1783, 2.1810),
    ];
    for (f, phi, gamma, n1_expect, at_n1, at_n) in cases {
        let v = ViewFrustum::new(1.0, f, phi.to_radians()).unwrap();
        let g = LightAngle::new(gamma.to_radians()).unwrap();
        let n1 = n_prime_1(&v, g);
        assert!((n1 - n1_expect).abs() < 1e-4 && n1 < v.near(), "{n1}");
        assert_eq!(
            n_prime_equal_error(&v, g).unwrap(),
            NPrime::finite(n1).unwrap()
        );
        assert_eq!(n_prime_axis_minimax(&v, g), NPrime::finite(n1).unwrap());
        let (a, b) = axis_max(&v, g, n1);
        assert!(rel(a, b) < 1e-9, "{a} {b}");
        assert!(rel(a, at_n1) < 5e-5, "{a}");
        let (an, bn) = axis_max(&v, g, v.near());
        assert!(rel(an.max(bn), at_n) < 5e-5, "{an}");
        // A minimum: both neighbours are worse.
        for np in [0.9 * n1, 1.1 * n1] {
            let (x, y) = axis_max(&v, g, np);
            assert!(x.max(y) > a);
        }
    }
    let v = ViewFrustum::new(1.0, 100.0, 1f64.to_radians()).unwrap();
    let g = LightAngle::new(2f64.to_radians()).unwrap();
    assert!((gamma_lim(&v).to_degrees() - 1.020).abs() < 1e-3);
    let gen = generalized_n_prime(&v, g, Falloff::Barroso).value();
    assert!(rel(gen, n_prime_1(&v, g)) < 1e-12);
}

/// n′₁ of Eq 13 needs no `Result`: a valid frustum keeps A = n + √(f n) and B = n tan φ_y finite,
/// and A sin γ − B cos γ lies in [−B, A]. At the edges of the frustum's domain (near planes and
/// depth ratios as small and as large as it accepts) it is finite and inside that interval, and at
/// γ = π/2 it is A and at γ = 0 it is −B (hand values: sin, cos exactly 1 and 0 there, up to the
/// rounding of cos(π/2) ≈ 6e−17).
#[test]
fn n_prime_1_is_finite_on_the_whole_domain() {
    let frusta = [
        (1e-300, 1e-299, 0.5),
        (1e-150, 1e150, 1.5),
        (1.0, 1e307, 0.1),
        (1e300, 1.5e300, 1.0),
        (1.0, 100.0, FRAC_PI_6),
    ];
    for (n, f, th) in frusta {
        let v = ViewFrustum::new(n, f, th).unwrap();
        let a = v.n_prime_lispsm();
        let b = n * v.tan_half_fov();
        for g in [0.0, 1e-9, 0.3, FRAC_PI_6, 1.2, FRAC_PI_2] {
            let n1 = n_prime_1(&v, LightAngle::new(g).unwrap());
            assert!(
                n1.is_finite() && n1 >= -b && n1 <= a,
                "{n} {f} {th} γ = {g}: {n1}"
            );
        }
        assert_eq!(n_prime_1(&v, LightAngle::new(0.0).unwrap()), -b);
        let top = n_prime_1(&v, LightAngle::new(FRAC_PI_2).unwrap());
        assert!((top - a).abs() <= 1e-15 * a + 1e-16 * b, "{top} vs {a}");
    }
}
