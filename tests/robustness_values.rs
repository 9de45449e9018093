//! Values that are `Ok` must be finite and valid (issue 11, "Values that are Ok but not finite or
//! not valid"): each test is a reproduction of a configuration that used to answer `Ok` with an
//! infinite, NaN or wrong value, with its expected value derived independently (by hand, from a
//! closed form, or by dense sampling).

use glam::DVec3;
use shadow_aliasing::analytic::overhead::storage_factor;
use shadow_aliasing::maps::cascades::bounding_sphere;
use shadow_aliasing::maps::light_space;
use shadow_aliasing::maps::minimax::{minimax_mz_n_prime, minimax_n_prime};
use shadow_aliasing::maps::{warp, WarpRule};
use shadow_aliasing::measure::{frustum_max, frustum_max_sampled, point_error, ROUNDING_TOLERANCE};
use shadow_aliasing::{Error, NPrime, Resolutions, ViewFrustum};
use std::f64::consts::FRAC_PI_2;

fn arg_name(e: &Error) -> &'static str {
    match e {
        Error::InvalidArgument { name, .. } => name,
        other => panic!("expected InvalidArgument, got {other}"),
    }
}

/// `ViewFrustum::new(5e-324, 1e-9, 5e-324)` was accepted with `alpha()` = ∞. Every quantity the
/// type derives must be finite (and the near plane's extent, the image beam width at near, normal).
#[test]
fn frustum_refuses_derived_quantities_out_of_range() {
    let e = ViewFrustum::new(5e-324, 1e-9, 5e-324).unwrap_err();
    assert_eq!(arg_name(&e), "half_fov", "{e}");
    // f/n overflows (by hand: 1e-9 / 5e-324 = 2·10³¹⁴).
    let e = ViewFrustum::new(5e-324, 1e-9, 0.5).unwrap_err();
    assert_eq!(arg_name(&e), "far", "{e}");
    // f/n = 2·10²³ is finite, but n tan θ = 5e-324 · 0.546 is not a normal number.
    let e = ViewFrustum::new(5e-324, 1e-300, 0.5).unwrap_err();
    assert_eq!(arg_name(&e), "near", "{e}");
    // tan θ subnormal.
    let e = ViewFrustum::new(1.0, 2.0, 1e-310).unwrap_err();
    assert_eq!(arg_name(&e), "half_fov", "{e}");
    // n + √(f n) overflows although f/n = 1.05 does not: by hand 1.7e308 + 1.74e308 > f64::MAX.
    let e = ViewFrustum::new(1.7e308, 1.79e308, 1e-10).unwrap_err();
    assert_eq!(arg_name(&e), "far", "{e}");
    // The same checks guard a z-partition's sub-frustum.
    let v = ViewFrustum::new(1.0, 2.0, 0.5).unwrap();
    assert!(v.with_depth_range(5e-324, 1e-300).is_err());
    // The edge that stays valid: n = 1e-300, f = 1 has α = 1e300 and n′ = n + 1e-150.
    let v = ViewFrustum::new(1e-300, 1.0, 0.5).unwrap();
    assert!((v.alpha() - 1e300).abs() <= 1e285);
    assert!((v.n_prime_lispsm() - 1e-150).abs() <= 1e-165);
}

/// Over a grid of extreme values, every accepted frustum has finite, positive accessors and a near
/// plane of positive extent (four distinct corners).
#[test]
fn accepted_frusta_have_finite_valid_accessors() {
    let depths = [
        5e-324, 1e-310, 2.3e-308, 1e-300, 1e-150, 1.0, 1e150, 1e300, 1.7e308, 1.79e308,
    ];
    let fovs = [
        5e-324,
        1e-310,
        1e-300,
        1e-8,
        0.5,
        1.5,
        FRAC_PI_2.next_down(),
    ];
    let mut accepted = 0;
    for &n in &depths {
        for &f in &depths {
            for &th in &fovs {
                for aspect in [1e-300, 1e-3, 1.0, 16.0 / 9.0, 1e300] {
                    let Ok(v) = ViewFrustum::with_aspect(n, f, th, aspect) else {
                        continue;
                    };
                    accepted += 1;
                    let what = format!("n={n} f={f} θ={th} aspect={aspect}");
                    for x in [v.alpha(), v.tan_half_fov(), v.n_prime_lispsm()] {
                        assert!(x.is_finite() && x > 0.0, "{what}: {x}");
                    }
                    assert!(v.n_prime_lispsm() >= v.near(), "{what}");
                    let c = v.corners();
                    assert!(c.iter().all(|p| p.is_finite()), "{what}");
                    assert!(c[0].x < c[1].x && c[1].y < c[2].y, "{what}: {c:?}");
                    assert!(c[4].x < c[5].x && c[5].y < c[6].y, "{what}: {c:?}");
                }
            }
        }
    }
    assert!(accepted > 50, "{accepted}");
}

/// `minimax_n_prime(ViewFrustum::new(1e-300, 0.5, π/2 − 1 ulp), (0, −1, −1e-9))` answered `Ok` with
/// non-finite maxima: `u_h · gx` (8·10¹⁵ · 10³⁰⁰) overflowed before the division by tan θ, so S̄
/// was ∞ at every n′ and the search kept n′ = ∞ with M_x = ∞. With the light exactly overhead
/// the optimum is Lloyd 2006 Eq 12 at n′ = n + √(f n) (S̄ = 7.08·10²⁸³, representable); with the
/// 10⁻⁹ tilt (the light-space extent grows to 8·10⁶ f) it overflows, and the answer is a typed error.
#[test]
fn minimax_answers_finite_maxima_or_an_error() {
    let view = ViewFrustum::new(1e-300, 0.5, FRAC_PI_2.next_down()).unwrap();
    let expected = storage_factor(&view, NPrime::finite(view.n_prime_lispsm()).unwrap()).unwrap();
    assert!(expected.is_finite());
    let o = minimax_n_prime(&view, DVec3::NEG_Y).unwrap();
    assert!(o.max_mx.is_finite() && o.max_mz.is_finite());
    assert!(
        (o.storage_factor() - expected).abs() <= 1e-6 * expected,
        "{} vs {expected}",
        o.storage_factor()
    );
    let l = DVec3::new(0.0, -1.0, -1e-9);
    for r in [minimax_n_prime(&view, l), minimax_mz_n_prime(&view, l)] {
        match r {
            Ok(o) => assert!(
                o.max_mx.is_finite() && o.max_mz.is_finite() && o.storage_factor().is_finite(),
                "{o:?}"
            ),
            Err(e) => assert!(matches!(e, Error::Degenerate(_)), "{e}"),
        }
    }
}

/// `light_space` of vectors with components near 10⁻¹⁵⁸ returned a "unit" light direction of
/// length 1 + 8·10⁻⁹ (the sum of squares was subnormal). The frame depends on directions only, so
/// every scale gives the hand-computed frame.
#[test]
fn light_space_is_scale_invariant() {
    let r3 = 1.0 / 3f64.sqrt();
    let r2 = 1.0 / 2f64.sqrt();
    // By hand: y = −l/|l|; z = a − (a·y) y normalised; x = y × z.
    let cases = [
        (
            DVec3::new(0.0, -1.0, 0.0),
            DVec3::new(0.0, 0.0, -1.0),
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
            DVec3::new(0.0, 0.0, -1.0),
        ),
        (
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 1.0),
            // y = (−1, −1, 0)/√2; a = (0, 1, 1)/√2, a·y = −1/2, z ∝ a + y/2 = (−1, 1, 2)/(2√2).
            DVec3::new(-1.0, 1.0, -1.0) * r3,
            DVec3::new(-r2, -r2, 0.0),
            DVec3::new(-1.0, 1.0, 2.0) / 6f64.sqrt(),
        ),
    ];
    for (l, a, x, y, z) in cases {
        for s in [1.0, 1e-158, 1e-160, 1e-300, 1e-320, 1e155, 1e300] {
            let ls = light_space(l * s, a * s).unwrap_or_else(|e| panic!("scale {s}: {e}"));
            for (got, want) in [(ls.x, x), (ls.y, y), (ls.z, z)] {
                assert!((got - want).length() < 1e-15, "scale {s}: {got} vs {want}");
            }
            assert!(ls.rotation().is_finite());
        }
    }
    // Zero and non-finite vectors are still refused.
    assert!(light_space(DVec3::ZERO, DVec3::NEG_Z).is_err());
    assert!(light_space(DVec3::NEG_Y, DVec3::new(f64::INFINITY, 0.0, 0.0)).is_err());
}

/// `bounding_sphere` squared lengths: at n = 1e280, f = 1e300 (f − c)² overflowed to an infinite
/// radius. The sphere scales with the frustum, so by hand in units of 10³⁰⁰: with k² = 2 tan²θ,
/// c′ = (10⁻²⁰ + 1)(1 + k²)/2, R′ = √((1 − c′)² + k²).
#[test]
fn bounding_sphere_of_huge_frustum_is_finite() {
    let view = ViewFrustum::new(1e280, 1e300, 0.5).unwrap();
    let (c, r) = bounding_sphere(&view, 1e280, 1e300).unwrap();
    let t = 0.5f64.tan();
    let k2 = 2.0 * t * t;
    let c1 = 0.5 * (1e-20 + 1.0) * (1.0 + k2);
    let r1 = ((1.0 - c1).powi(2) + k2).sqrt();
    assert!(r.is_finite() && c.is_finite());
    assert!((c / 1e300 - c1).abs() <= 1e-14, "{c}");
    assert!((r / 1e300 - r1).abs() <= 1e-14, "{r}");
    // Every corner lies inside (scaled down to avoid overflow).
    for p in view.corners() {
        let d = (p / 1e300 - DVec3::new(0.0, 0.0, -c / 1e300)).length();
        assert!(d <= r / 1e300 * (1.0 + 1e-14), "{p}: {d}");
    }
    // The brief's input: a subnormal near plane is refused by the sub-frustum's validation.
    let v = ViewFrustum::new(1.0, 2.0, 0.5).unwrap();
    assert!(bounding_sphere(&v, 5e-324, 1e300).is_err());
    // A radius that does not fit in f64 (by hand: far · tan θ · √2 = 1.5e308 · 1 · √2 > f64::MAX).
    let v = ViewFrustum::new(1.0, 1.5e308, std::f64::consts::FRAC_PI_4).unwrap();
    let e = bounding_sphere(&v, 1.0, 1.5e308).unwrap_err();
    assert!(matches!(e, Error::Degenerate(_)), "{e}");
}

/// With half the field of view one ulp below π/2 the "exact" vertex maximum M_z was 2.2·10¹⁵ while
/// dense sampling found 2.8·10¹⁵: the warp's t varies over the 10¹⁶-wide frustum by a few ulps of
/// 1, and the derivative cancels to noise. Where rounding can change the widths by more than
/// `ROUNDING_TOLERANCE`, the measurement is a typed error.
#[test]
fn frustum_max_refuses_ill_conditioned_maps() {
    let l = DVec3::new(0.0, -1.0, -1.0);
    let view = ViewFrustum::new(1.0, 2.0, FRAC_PI_2.next_down()).unwrap();
    let s = warp(&view, l, WarpRule::Lispsm).unwrap().shadow_map();
    let e = frustum_max(&view, &s).unwrap_err();
    assert!(matches!(e, Error::Degenerate(_)), "{e}");
    assert!(e.to_string().contains("ill-conditioned"), "{e}");
    for c in view.corners() {
        assert!(point_error(&view, &s, c, Resolutions::default()).is_err());
    }
    // Where the answer is accepted it is the dense sampling's maximum, to the tolerance.
    for th in [1.0, 1.5, 1.57, FRAC_PI_2 - 1e-6, FRAC_PI_2 - 1e-9] {
        let view = ViewFrustum::new(1.0, 2.0, th).unwrap();
        for r in [WarpRule::Lispsm, WarpRule::Eta(-0.5), WarpRule::Uniform] {
            let s = warp(&view, l, r).unwrap().shadow_map();
            let (Ok(exact), Ok(dense)) =
                (frustum_max(&view, &s), frustum_max_sampled(&view, &s, 17))
            else {
                continue;
            };
            let tol = 4.0 * ROUNDING_TOLERANCE;
            for (a, b) in [(exact.max_mx, dense.max_mx), (exact.max_mz, dense.max_mz)] {
                assert!(
                    b <= a * (1.0 + tol),
                    "θ={th} {r:?}: vertices {a} < sampled {b}"
                );
            }
        }
    }
}

/// The `[0, 1]`-depth form of a map is as valid as the OpenGL form it comes from (fuzz finding,
/// docs/fuzzing.md): at n = 2.2·10⁻³⁰⁸, f = π/2 (f/n = 7·10³⁰⁷), θ = 1.043, a tiny light and
/// `Lispsm`, the OpenGL matrix passed the clip check but its `[0, 1]` form, depth row
/// (M₂ + M₃)/2, put a corner at z = −0.00175. Every builder now checks both forms: the map is
/// either inside in both, or a typed `Degenerate`.
#[test]
fn zero_to_one_depth_is_checked_too() {
    use shadow_aliasing::maps::ClipDepth;
    let view = ViewFrustum::new(
        2.2250738585072014e-308,
        1.5707963267948963,
        1.0430829673124253,
    )
    .unwrap();
    let l = DVec3::new(
        -0.00000009999847412109375,
        -0.00000000037384033203125,
        -0.00000008085479736328126,
    );
    for rule in [
        WarpRule::Lispsm,
        WarpRule::Uniform,
        WarpRule::Psm,
        WarpRule::Minimax,
    ] {
        match warp(&view, l, rule) {
            Ok(s) => {
                let m01 = s.with_clip_depth(ClipDepth::ZeroToOne);
                for c in view.corners() {
                    let h = m01 * c.extend(1.0);
                    let z = h.z / h.w;
                    assert!((-1e-6..=1.0 + 1e-6).contains(&z), "{rule:?}: {c} → z = {z}");
                }
            }
            Err(Error::Degenerate(m)) => assert!(m.contains("cannot be represented"), "{m}"),
            Err(e) => panic!("{rule:?}: {e:?}"),
        }
    }
}

/// Fuzz finding (docs/fuzzing.md): `face_partitions` answered `Ok` with no partitions at
/// n = 2.2·10⁻³⁰⁸, f = θ = π/2 − 1 ulp, light (π/2 − 1 ulp, π/2 − 1 ulp, −0). An empty result is
/// never a success: maps, or a typed error.
#[test]
fn face_partitions_are_never_empty() {
    use shadow_aliasing::maps::faces::{face_partitions, FaceWarp};
    let hp = 1.5707963267948963;
    let Ok(view) = ViewFrustum::new(2.2250738585072014e-308, hp, hp) else {
        return;
    };
    for warp in [FaceWarp::Uniform, FaceWarp::Psm, FaceWarp::Lispsm] {
        for k in [1, 3] {
            match face_partitions(&view, DVec3::new(hp, hp, -0.0), warp, k) {
                Ok(f) => assert!(!f.is_empty(), "{warp:?} k = {k}: empty"),
                Err(e) => assert!(!e.to_string().is_empty()),
            }
        }
    }
}

/// Fuzz finding: at aspect 2.2·10⁻³⁰⁸ (n = 1, f = θ = π/2 − 1 ulp, light (0, −6.5·10³⁰⁰, 10⁹))
/// the minimax optimum had M_x = 2.8·10⁻³⁰⁸ and M_z = 6.5·10⁻¹⁷, whose product, the storage
/// factor, underflows to 0: no valid answer, so `Degenerate`, not `Ok` with S̄ = 0.
#[test]
fn minimax_refuses_an_underflowing_storage_factor() {
    let hp = 1.5707963267948963;
    let Ok(view) = ViewFrustum::with_aspect(1.0, hp, hp, 2.2250738585072014e-308) else {
        return;
    };
    let l = DVec3::new(0.0, -6.486014777691532e300, 996063232.421875);
    for r in [minimax_n_prime(&view, l), minimax_mz_n_prime(&view, l)] {
        match r {
            Ok(o) => assert!(o.storage_factor().is_normal(), "{o:?}"),
            Err(e) => assert!(matches!(e, Error::Degenerate(_)), "{e:?}"),
        }
    }
}

/// Fuzz finding: the bounding sphere of a thin, distant partition (θ = 1.25·10⁻⁸, aspect
/// 0.00527, [7.556001431·10⁷⁸, 7.556002913·10⁷⁸]) left a corner 1.2·10⁻⁹ R outside (the centre
/// is ≈ 10⁷ R from the eye, and its rounding alone is 10⁻⁹ R). Every corner is inside now, in
/// units of R.
#[test]
fn bounding_sphere_contains_its_corners_as_computed() {
    let (a, b) = (7556001431015456e63, 7556002913165484e63);
    let view = ViewFrustum::with_aspect(a * 0.5, b * 2.0, 1.25e-8, 0.00527252197265625).unwrap();
    let (c, r) = bounding_sphere(&view, a, b).unwrap();
    let sub = view.with_depth_range(a, b).unwrap();
    for p in sub.corners() {
        let d = (p / r - DVec3::new(0.0, 0.0, -c / r)).length();
        assert!(d <= 1.0, "{p}: {d} R");
    }
}
