//! z-partitions: split schemes (Lloyd 2006 Eq 15, 16; Barroso & Celes Eq 19; uniform, practical,
//! Unreal's exponent) and the storage factors of ZP, ZP+W, FP+ZP+W (Lloyd 2006 Eq 17–23,
//! App. C), measured on cascades of twin maps.

use proptest::prelude::*;
use shadow_aliasing::analytic::partition::{
    fp_zp_w_overhead_asymptotic, optimal_storage_factor, scheme_storage_factor, shadow_map_count,
    splits_storage_factor, z_splits, zp_overhead_asymptotic, Scheme, SchemeLight, SplitScheme,
    Splits, MAX_PARTITIONS,
};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::measure::twin::{
    behind_cascade, behind_map, measured_fp_zp_w_behind, overhead_cascade, TwinWarp,
};
use shadow_aliasing::{Error, ViewFrustum};
use std::f64::consts::FRAC_PI_2;
mod common;
use common::{adaptive_limit, any_f64, close, config, frustum, REL};

fn scheme() -> impl Strategy<Value = SplitScheme> {
    prop_oneof![
        Just(SplitScheme::Uniform),
        Just(SplitScheme::SelfSimilar),
        (0.0f64..=1.0).prop_map(|lambda| SplitScheme::Practical { lambda }),
        (0.05f64..8.0).prop_map(|exponent| SplitScheme::Exponent { exponent }),
        (0.0f64..=FRAC_PI_2, 1.01f64..4.0)
            .prop_map(|(light_angle, ratio)| SplitScheme::Adaptive { light_angle, ratio }),
    ]
}

proptest! {
    #![proptest_config(config(128))]

    /// Every scheme either gives k + 1 strictly increasing planes from near to far, or a typed
    /// error (only the adaptive scheme, when α^{k−1} is too deep for f/n); never a panic.
    #[test]
    fn splits_are_increasing_from_near_to_far(
        n in 0.01f64..10.0, a in 1.5f64..1e5, k in 1usize..=MAX_PARTITIONS, s in scheme(),
    ) {
        match z_splits(n, n * a, k, s) {
            Ok(sp) => {
                let p = sp.planes();
                prop_assert_eq!(p.len(), k + 1);
                prop_assert_eq!(p[0], n);
                prop_assert_eq!(p[k], n * a);
                for w in p.windows(2) {
                    prop_assert!(w[1] > w[0]);
                }
                prop_assert_eq!(Splits::from_planes(p).unwrap(), sp);
            }
            Err(Error::NoSolution(_)) => {
                let adaptive = matches!(s, SplitScheme::Adaptive { .. });
                prop_assert!(adaptive);
            }
            Err(e) => prop_assert!(false, "{e}"),
        }
    }

    /// Eq 15, 16: self-similar partitions all have the ratio (f/n)^{1/k}; practical λ = 1 is
    /// self-similar and λ = 0 uniform; exponent 1 is uniform; Barroso's adaptive scheme at
    /// γ = π/2 is self-similar for any ratio α (his claim below Eq 19).
    #[test]
    fn scheme_identities(n in 0.01f64..10.0, a in 1.5f64..1e5, k in 1usize..=MAX_PARTITIONS, r in 1.01f64..8.0) {
        let f = n * a;
        let ss = z_splits(n, f, k, SplitScheme::SelfSimilar).unwrap();
        let want = a.powf(1.0 / k as f64);
        for &ri in &ss.ratios()[..k] {
            prop_assert!(close(ri, want, 1e-12));
        }
        let same = |x: &Splits, y: &Splits| x.planes().iter().zip(y.planes()).all(|(p, q)| close(*p, *q, 1e-12));
        let p1 = z_splits(n, f, k, SplitScheme::Practical { lambda: 1.0 }).unwrap();
        prop_assert!(same(&p1, &ss));
        let u = z_splits(n, f, k, SplitScheme::Uniform).unwrap();
        let p0 = z_splits(n, f, k, SplitScheme::Practical { lambda: 0.0 }).unwrap();
        prop_assert!(same(&p0, &u));
        let e1 = z_splits(n, f, k, SplitScheme::Exponent { exponent: 1.0 }).unwrap();
        prop_assert!(same(&e1, &u));
        let e_near1 = z_splits(n, f, k, SplitScheme::Exponent { exponent: 1.0 + 1e-12 }).unwrap();
        prop_assert!(e_near1.planes().iter().zip(u.planes()).all(|(p, q)| close(*p, *q, 1e-9)));
        let ad = z_splits(n, f, k, SplitScheme::Adaptive { light_angle: FRAC_PI_2, ratio: r }).unwrap();
        prop_assert!(same(&ad, &ss), "{:?} vs {:?}", ad.planes(), ss.planes());
    }

    /// The split schemes' planes evaluated by hand from their definitions (uniform
    /// n + (f − n) i/k; self-similar n (f/n)^{i/k}; practical λ·self-similar + (1 − λ)·uniform;
    /// exponent n + (f − n)(e^i − 1)/(e^k − 1), written with `exp_m1` so that e near 1 stays
    /// exact).
    #[test]
    fn splits_by_hand(
        n in 0.01f64..10.0, a in 1.5f64..1e5, k in 1usize..=MAX_PARTITIONS,
        lambda in 0.0f64..=1.0, e in 0.2f64..4.0,
    ) {
        let f = n * a;
        let (kf, le) = (k as f64, e.ln());
        for i in 0..=k {
            let t = i as f64 / kf;
            let uniform = n + (f - n) * t;
            let log = n * a.powf(t);
            let practical = lambda * log + (1.0 - lambda) * uniform;
            let exponent = if le == 0.0 { uniform } else { n + (f - n) * (i as f64 * le).exp_m1() / (kf * le).exp_m1() };
            for (s, want) in [
                (SplitScheme::Uniform, uniform),
                (SplitScheme::SelfSimilar, log),
                (SplitScheme::Practical { lambda }, practical),
                (SplitScheme::Exponent { exponent: e }, exponent),
            ] {
                let got = z_splits(n, f, k, s).unwrap().planes()[i];
                prop_assert!(close(got, want, 1e-12), "{s:?} plane {i}: {got} vs {want}");
            }
        }
    }

    /// Unreal's exponent e: each partition is e times as deep as the one before it.
    #[test]
    fn exponent_depths_grow_geometrically(n in 0.01f64..10.0, a in 1.5f64..1e4, k in 2usize..=8, e in 0.2f64..4.0) {
        let s = z_splits(n, n * a, k, SplitScheme::Exponent { exponent: e }).unwrap();
        let p = s.planes();
        for i in 1..k {
            prop_assert!(close((p[i + 1] - p[i]) / (p[i] - p[i - 1]), e, 1e-9));
        }
    }

    /// Eq 17, 18 (overhead) and Eq 20 (behind): the storage factor measured on self-similar
    /// cascades of twin maps (each fitted to its partition, n′ = ∞ for ZP, LiSPSM's n′ or any
    /// η ∈ [0, 1] for ZP+W), summed over partitions.
    #[test]
    fn eq17_eq18_eq20_equal_measured_cascades(v in frustum(), k in 1usize..=MAX_PARTITIONS, eta in 0.0f64..=1.0) {
        let sp = z_splits(v.near(), v.far(), k, SplitScheme::SelfSimilar).unwrap();
        let zp = overhead_cascade(&v, &sp, TwinWarp::Unwarped).unwrap().measured_storage_factor().unwrap();
        let eq17 = scheme_storage_factor(Scheme::Zp, SchemeLight::Overhead, &v, k).unwrap();
        prop_assert!(close(zp, eq17, REL), "ZP measured {zp}, Eq 17 {eq17}");
        let eq18 = scheme_storage_factor(Scheme::ZpW, SchemeLight::Overhead, &v, k).unwrap();
        for w in [TwinWarp::Lispsm, TwinWarp::Eta(eta)] {
            let zpw = overhead_cascade(&v, &sp, w).unwrap().measured_storage_factor().unwrap();
            prop_assert!(close(zpw, eq18, REL), "ZP+W measured {zpw}, Eq 18 {eq18}");
        }
        // Eq 19 (FP+ZP+W overhead): the light sees the bottom face alone, so the scheme is the
        // measured ZP+W cascade above, k((f/n)^{1/k} − 1)/(2 tan θ) by hand (the face partitions
        // themselves are measured in `faces::eq19_overhead`).
        let eq19 = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Overhead, &v, k).unwrap();
        let lispsm = overhead_cascade(&v, &sp, TwinWarp::Lispsm).unwrap().measured_storage_factor().unwrap();
        prop_assert!(close(eq19, lispsm, REL), "Eq 19 {eq19}, measured ZP+W {lispsm}");
        let by_hand = k as f64 * (v.alpha().powf(1.0 / k as f64) - 1.0) / (2.0 * v.tan_half_fov());
        prop_assert!(close(eq19, by_hand, 1e-9), "Eq 19 {eq19}, by hand {by_hand}");
        let behind = behind_cascade(&v, &sp).unwrap().measured_storage_factor().unwrap();
        let eq20 = scheme_storage_factor(Scheme::Zp, SchemeLight::Behind, &v, k).unwrap();
        prop_assert!(close(behind, eq20, REL), "ZP behind measured {behind}, Eq 20 {eq20}");
    }

    /// Any split (uniform, practical, exponent, adaptive): the per-partition closed forms summed
    /// equal the measured cascades; and the self-similar split has the least storage.
    #[test]
    fn splits_storage_factor_equals_measured_and_self_similar_is_least(
        v in frustum(), k in 1usize..=8, s in scheme(),
    ) {
        let Ok(sp) = z_splits(v.near(), v.far(), k, s) else { return Ok(()); };
        let ss = z_splits(v.near(), v.far(), k, SplitScheme::SelfSimilar).unwrap();
        for (light, warped) in [(SchemeLight::Overhead, false), (SchemeLight::Overhead, true), (SchemeLight::Behind, false)] {
            let closed = splits_storage_factor(&sp, v.half_fov(), light, warped).unwrap();
            let measured = match light {
                SchemeLight::Overhead => overhead_cascade(&v, &sp, if warped { TwinWarp::Lispsm } else { TwinWarp::Unwarped }),
                SchemeLight::Behind => behind_cascade(&v, &sp),
            }.unwrap().measured_storage_factor().unwrap();
            prop_assert!(close(closed, measured, REL), "{light:?} {warped}: {closed} vs {measured}");
            let best = splits_storage_factor(&ss, v.half_fov(), light, warped).unwrap();
            prop_assert!(best <= closed * (1.0 + 1e-12));
        }
    }

    /// Eq 21 with the crate's reading (S̄_overhead^{ZP+W} at θ = 45° for every θ): the measured
    /// FP+ZP+W with the light behind — four side faces, each self-similarly split and warped with
    /// LiSPSM's n′ (or any η ∈ [0, 1]) over the face, plus the near face — for any half field of
    /// view.
    #[test]
    fn eq21_fp_zp_w_behind_matches_face_twin_for_any_fov(v in frustum(), k in 1usize..=8, eta in 0.0f64..=1.0) {
        let sp = z_splits(v.near(), v.far(), k, SplitScheme::SelfSimilar).unwrap();
        let eq21 = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Behind, &v, k).unwrap();
        for w in [TwinWarp::Lispsm, TwinWarp::Eta(eta)] {
            let m = measured_fp_zp_w_behind(&v, &sp, w).unwrap();
            prop_assert!(close(m, eq21, REL), "measured {m}, Eq 21 {eq21}");
        }
    }

    /// Eq 18 → App. C: k((f/n)^{1/k} − 1)/(2 tan θ) decreases in k towards ln(f/n)/(2 tan θ),
    /// App. C's optimum written out here. The measured self-similar ZP+W cascades (LiSPSM per
    /// partition) approach it from above as 1/k: with x = ln(f/n)/k, (e^x − 1)/x − 1 lies in
    /// [x/2, (x/2) e^x], so S̄(k)/S̄_opt − 1 does too (to 10⁻⁹, the measurement's accuracy).
    #[test]
    fn zp_w_decreases_towards_the_optimum(v in frustum()) {
        let opt = optimal_storage_factor(&v).unwrap();
        let ln = v.alpha().ln();
        let by_hand = ln / (2.0 * v.tan_half_fov());
        prop_assert!(close(opt, by_hand, 1e-12), "App. C {opt}, by hand {by_hand}");
        let arm = scheme_storage_factor(Scheme::Optimal, SchemeLight::Overhead, &v, 1).unwrap();
        prop_assert!(close(arm, by_hand, 1e-12), "Optimal {arm}, by hand {by_hand}");
        let mut prev_measured = f64::INFINITY;
        for k in [1, 2, 4, 8, MAX_PARTITIONS] {
            let sp = z_splits(v.near(), v.far(), k, SplitScheme::SelfSimilar).unwrap();
            let m = overhead_cascade(&v, &sp, TwinWarp::Lispsm).unwrap().measured_storage_factor().unwrap();
            let x = ln / k as f64;
            let gap = m / by_hand - 1.0;
            prop_assert!(m < prev_measured, "k = {k}: measured {m} not below {prev_measured}");
            prop_assert!(
                gap >= 0.5 * x - 1e-9 && gap <= 0.5 * x * x.exp() + 1e-9,
                "k = {k}: measured {m}, optimum {by_hand}, gap {gap} for x = {x}"
            );
            prev_measured = m;
        }
        let mut prev = f64::INFINITY;
        for k in 1..=64 {
            let s = scheme_storage_factor(Scheme::ZpW, SchemeLight::Overhead, &v, k).unwrap();
            prop_assert!(s < prev && s > opt);
            prev = s;
        }
        let big = scheme_storage_factor(Scheme::ZpW, SchemeLight::Overhead, &v, 1 << 24).unwrap();
        prop_assert!(close(big, opt, 1e-6));
    }
}

/// §5.2 "Seams": in a self-similar ZP+W cascade with LiSPSM's n′ per partition, the measured
/// m_z does not change across a seam, while m_x jumps from 1 to √a (a = (f/n)^{1/k}); with
/// n′ = n (PSM) m_x does not change and m_z jumps by the factor a.
#[test]
fn seams_of_self_similar_cascades() {
    use shadow_aliasing::measure::point_error;
    use shadow_aliasing::Resolutions;
    let v = ViewFrustum::new(0.5, 500.0, 0.6).unwrap();
    let k = 3;
    let a = 1000f64.powf(1.0 / 3.0);
    let sp = z_splits(0.5, 500.0, k, SplitScheme::SelfSimilar).unwrap();
    for (warp, jump_x, jump_z) in [
        (TwinWarp::Lispsm, a.sqrt(), 1.0),
        (TwinWarp::Eta(1.0), 1.0, a),
    ] {
        let c = overhead_cascade(&v, &sp, warp).unwrap();
        for i in 1..k {
            let z = sp.planes()[i];
            let p = glam::DVec3::new(0.0, 0.0, -z);
            let (v0, m0) = c.get(i - 1).unwrap();
            let (v1, m1) = c.get(i).unwrap();
            let before = point_error(&v0, &m0, p, Resolutions::default()).unwrap();
            let after = point_error(&v1, &m1, p, Resolutions::default()).unwrap();
            assert!(close(after.mx / before.mx, jump_x, REL), "{warp:?} x");
            assert!(close(before.mz / after.mz, jump_z, REL), "{warp:?} z");
        }
    }
}

proptest! {
    #![proptest_config(config(128))]

    /// §5.3 (Fig 12): with j shadow maps, ZP overhead (j partitions) beats FP+ZP+W overhead (j/4
    /// z-partitions); behind, ZP's k (f/n)^{2/k} is least near k = 2 ln(f/n) and then grows,
    /// while FP+ZP+W keeps falling towards 2 ln(f/n) + 1, so it eventually wins.
    #[test]
    fn fig12_claims(v in frustum()) {
        for j in (4..=64).step_by(4) {
            let zp = scheme_storage_factor(Scheme::Zp, SchemeLight::Overhead, &v, j).unwrap();
            let fp = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Overhead, &v, j / 4).unwrap();
            prop_assert!(zp < fp, "j = {j}: ZP {zp} FP+ZP+W {fp}");
        }
        let ln = v.alpha().ln();
        let behind = |k| scheme_storage_factor(Scheme::Zp, SchemeLight::Behind, &v, k).unwrap();
        let kmin = (2.0 * ln).ceil().max(1.0) as usize;
        prop_assert!(behind(kmin + 1) < behind(kmin + 2));
        let fp_limit = 2.0 * ln + 1.0;
        let fp_big = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Behind, &v, 1 << 20).unwrap();
        prop_assert!(close(fp_big, fp_limit, 1e-5));
        // min_k k (f/n)^{2/k} ≥ 2 e ln(f/n) > 2 ln(f/n) + 1 once ln(f/n) > 1/(2(e − 1)).
        if ln > 0.5 / (std::f64::consts::E - 1.0) {
            for k in 1..=kmin + 2 {
                prop_assert!(fp_limit < behind(k));
            }
        }
    }
}

/// Eq 20 with k = 1: the measured uniform map with the light behind gives (f/n)².
#[test]
fn measured_uniform_map_behind_is_alpha_squared() {
    for (n, f, th) in [(1.0, 100.0, 0.5), (0.1, 1000.0, 1.2), (3.0, 4.0, 0.05)] {
        let v = ViewFrustum::new(n, f, th).unwrap();
        let m = frustum_max(&v, &behind_map(&v).unwrap()).unwrap();
        assert!(close(m.storage_factor, (f / n) * (f / n), REL));
        assert!(close(m.max_mx, f / n, REL) && close(m.max_mz, f / n, REL));
    }
}

/// Hand values at f/n = 1000, θ = 30° (Lloyd 2006 Fig 12's frustum), k = 4.
#[test]
fn hand_values_fig12() {
    let v = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap();
    let a = 1000f64.powf(0.25);
    let t2 = 2.0 * 30f64.to_radians().tan();
    let s = |sc, l| scheme_storage_factor(sc, l, &v, 4).unwrap();
    assert!(close(
        s(Scheme::Zp, SchemeLight::Overhead),
        4.0 * a * (a - 1.0) / t2,
        1e-14
    ));
    assert!(close(
        s(Scheme::ZpW, SchemeLight::Overhead),
        4.0 * (a - 1.0) / t2,
        1e-14
    ));
    assert!(close(
        s(Scheme::Zp, SchemeLight::Behind),
        4.0 * a * a,
        1e-14
    ));
    assert!(close(
        s(Scheme::ZpW, SchemeLight::Behind),
        4.0 * a * a,
        1e-14
    ));
    assert!(close(
        s(Scheme::FpZpW, SchemeLight::Behind),
        2.0 * 4.0 * (a - 1.0) + 1.0,
        1e-14
    ));
    assert!(close(
        optimal_storage_factor(&v).unwrap(),
        1000f64.ln() / t2,
        1e-15
    ));
    assert_eq!(
        shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, 4).unwrap(),
        17
    );
    assert_eq!(
        shadow_map_count(Scheme::ZpW, SchemeLight::Overhead, 4).unwrap(),
        4
    );
    // No closed form for the optimum with the light behind.
    let e = scheme_storage_factor(Scheme::Optimal, SchemeLight::Behind, &v, 1).unwrap_err();
    assert!(matches!(e, Error::NoClosedForm(_)), "{e}");
    assert!(scheme_storage_factor(Scheme::Zp, SchemeLight::Overhead, &v, 0).is_err());
}

/// Adaptive at γ = 0 (Barroso Eq 19): partitions 2..k all have depth ratio α; and the first
/// partition runs from n to the second's near plane (the paper's "f_1 = f_2" must be f_1 = n_2).
#[test]
fn adaptive_parallel_light() {
    let s = adaptive_limit(4);
    assert_eq!(s.planes(), &[1.0, 125.0, 250.0, 500.0, 1000.0]);
    assert_eq!(s.range(0), (1.0, 125.0));
}

/// Barroso Eq 19 between the two limits (docs/errata.md, "Eq 19, what is interpolated"): the text
/// calls it "linearly interpolating the distance of each subdivision between the optimal and limit
/// cases", but Eq 19 interpolates each plane from the already interpolated next one, so the planes
/// are not the blend of the optimal and limit partitions. n = 1, f = 1000, k = 3, α = 2,
/// γ = π/4 (λ = ½), by hand: n_3 = ½·1000^{2/3} + ½·1000/2 = 300 (the blend of 100 and 500 too),
/// n_2 = ½·300^{1/2} + ½·300/2 = 83.660, where the blend of the optimal 10 and the limit 250 is 130.
#[test]
fn adaptive_interpolates_plane_by_plane() {
    let s = z_splits(
        1.0,
        1000.0,
        3,
        SplitScheme::Adaptive {
            light_angle: FRAC_PI_2 / 2.0,
            ratio: 2.0,
        },
    )
    .unwrap();
    let p = s.planes();
    assert!((p[2] - 300.0).abs() < 1e-9, "{}", p[2]);
    let by_hand = 0.5 * 300f64.sqrt() + 0.5 * 150.0;
    assert!(
        (p[1] - by_hand).abs() < 1e-9 && (p[1] - 83.660).abs() < 1e-3,
        "{}",
        p[1]
    );
    let optimal = z_splits(1.0, 1000.0, 3, SplitScheme::SelfSimilar).unwrap();
    let limit = adaptive_limit(3);
    let blend = 0.5 * optimal.planes()[1] + 0.5 * limit.planes()[1];
    assert!((blend - 130.0).abs() < 1e-9);
    assert!(p[1] < 0.65 * blend);
}

// ---------------------------------------------------------------------------------------------
// Errata (docs/errata.md, "Lloyd et al. 2006").
// ---------------------------------------------------------------------------------------------

/// Eq 21 prints "4 S̄_overhead^{ZP+W} + 1, with θ = 45°". Read as S̄_overhead at the frustum's own
/// θ it is wrong for θ ≠ 45°: at f/n = 1000, θ = 30°, k = 1 it gives 4·999/(2 tan 30°) + 1 =
/// 3461.64; the measured face partitions give 4·999/2 + 1 = 1999 (the same as at θ = 45°).
#[test]
fn errata_eq21_holds_with_overhead_at_45_degrees_for_any_fov() {
    for deg in [10.0f64, 30.0, 45.0, 70.0] {
        let v = ViewFrustum::new(1.0, 1000.0, deg.to_radians()).unwrap();
        let sp = z_splits(1.0, 1000.0, 1, SplitScheme::SelfSimilar).unwrap();
        let m = measured_fp_zp_w_behind(&v, &sp, TwinWarp::Lispsm).unwrap();
        assert!(close(m, 1999.0, REL), "θ = {deg}°: measured {m}");
        let own_theta =
            4.0 * scheme_storage_factor(Scheme::ZpW, SchemeLight::Overhead, &v, 1).unwrap() + 1.0;
        if deg == 30.0 {
            assert!(close(
                own_theta,
                4.0 * 999.0 / (2.0 * deg.to_radians().tan()) + 1.0,
                1e-12
            ));
            assert!((own_theta - 3461.6375).abs() < 1e-3);
        }
    }
}

/// Eq 22, 23 print S̄_ZP ≈ j (f/n)^{2/j} and S̄_FP+ZP+W ≈ j (f/n)^{4/j}, dropping the constants
/// 1/(2 tan θ) and 1/(8 tan θ) (FP+ZP+W has j/4 z-partitions). At f/n = 10⁶, θ = 30°, j = 8:
/// Eq 17 gives 180.13 against the printed 252.98, Eq 18 with k = 2 gives 1730.3 against the
/// printed 8000; the corrected asymptotes' ratios to the exact values are 1 − (f/n)^{−1/j} and
/// 1 − (f/n)^{−4/j}, tending to 1.
#[test]
fn errata_eq22_eq23_drop_constant_factors() {
    let th = 30f64.to_radians();
    let j = 8usize;
    let jf = j as f64;
    for alpha in [1e3, 1e6, 1e12, 1e24] {
        let v = ViewFrustum::new(1.0, alpha, th).unwrap();
        let zp = scheme_storage_factor(Scheme::Zp, SchemeLight::Overhead, &v, j).unwrap();
        let fp = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Overhead, &v, j / 4).unwrap();
        let c22 = zp / zp_overhead_asymptotic(&v, j).unwrap();
        let c23 = fp / fp_zp_w_overhead_asymptotic(&v, j).unwrap();
        assert!(close(c22, 1.0 - alpha.powf(-1.0 / jf), 1e-12), "{c22}");
        assert!(close(c23, 1.0 - alpha.powf(-4.0 / jf), 1e-12), "{c23}");
        if alpha == 1e6 {
            assert!((zp - 180.1289).abs() < 1e-3 && (fp - 1730.3188).abs() < 1e-3);
            let printed22 = jf * alpha.powf(2.0 / jf);
            let printed23 = jf * alpha.powf(4.0 / jf);
            assert!((printed22 - 252.9822).abs() < 1e-3 && printed23 == 8000.0);
        }
    }
}

proptest! {
    #![proptest_config(config(128))]

    /// No input makes the splits or the scheme storage factors panic or return NaN or ±∞.
    #[test]
    fn never_nan_or_infinite(n in any_f64(), f in any_f64(), p in any_f64(), q in any_f64(), k in 0usize..40) {
        for s in [
            SplitScheme::Uniform,
            SplitScheme::SelfSimilar,
            SplitScheme::Practical { lambda: p },
            SplitScheme::Exponent { exponent: p },
            SplitScheme::Adaptive { light_angle: p, ratio: q },
        ] {
            if let Ok(sp) = z_splits(n, f, k, s) {
                prop_assert!(sp.planes().iter().all(|z| z.is_finite() && *z > 0.0));
            }
        }
        if let Ok(v) = ViewFrustum::new(n, f, p) {
            for sc in [Scheme::Zp, Scheme::ZpW, Scheme::FpZpW, Scheme::Optimal] {
                for l in [SchemeLight::Overhead, SchemeLight::Behind] {
                    prop_assert!(scheme_storage_factor(sc, l, &v, k).map_or(true, f64::is_finite));
                }
            }
            prop_assert!(zp_overhead_asymptotic(&v, k).map_or(true, f64::is_finite));
            prop_assert!(fp_zp_w_overhead_asymptotic(&v, k).map_or(true, f64::is_finite));
        }
    }
}

/// x^{2/3} to ≈ 0.5 ulp: y = ∛x, one Newton step on y³ = x with the residual from exact
/// products (`mul_add`), then y² = y₀² + 2 y₀ δ from an exact square. `powf(x, 2/3)` is off
/// by ≈ 10⁻¹⁶ · ln x relative, because 2/3 is not a binary fraction.
fn pow_2_3(x: f64) -> f64 {
    let y = x.cbrt();
    let y2 = y * y;
    let y2_lo = y.mul_add(y, -y2);
    let y3 = y2 * y;
    let y3_lo = y2.mul_add(y, -y3) + y2_lo * y;
    let delta = ((x - y3) - y3_lo) / (3.0 * y2);
    y2 + (y2_lo + 2.0 * y * delta)
}

/// Barroso & Celes Eq 19 as printed (with the crate's reading, see `z_splits`), every power
/// by `powf` (by [`pow_2_3`] for i = 3): z_{i−1} = λ n (z_i/n)^{(i−1)/i} + (1 − λ) z_i/α, z_k = f. None if the planes
/// are not increasing by at least 10⁻¹² relative (too close to the `NoSolution` edge to
/// compare).
fn eq19_by_powf(n: f64, f: f64, k: usize, gamma: f64, ratio: f64) -> Option<Vec<f64>> {
    // λ and 1 − λ each as one division (1 − λ without cancellation near γ = π/2).
    let l = gamma / FRAC_PI_2;
    let one_minus_l = (FRAC_PI_2 - gamma) / FRAC_PI_2;
    let mut p = vec![0.0; k + 1];
    p[k] = f;
    for i in (2..=k).rev() {
        let x = p[i] / n;
        let pow = if i == 3 {
            pow_2_3(x)
        } else {
            x.powf((i - 1) as f64 / i as f64)
        };
        p[i - 1] = l * n * pow + one_minus_l * p[i] / ratio;
    }
    p[0] = n;
    p.windows(2)
        .all(|w| w[1] > w[0] * (1.0 + 1e-12))
        .then_some(p)
}

proptest! {
    #![proptest_config(config(128))]

    /// The adaptive planes (x^{(i−1)/i} by square roots for i = 2, 4, by x · x^{−1/3} with a
    /// Newton inverse cube root for i = 3, `powf` otherwise; the recurrence in units of n)
    /// agree with Eq 19 evaluated by `powf` to 10⁻¹⁴ relative, from f/n just above 1 to
    /// f/n = 10³⁰⁰, and give `NoSolution` exactly where that evaluation is not increasing.
    #[test]
    fn adaptive_planes_match_eq19_by_powf(
        n in prop_oneof![0.01f64..10.0, (-300.0f64..0.0).prop_map(|e| 10f64.powf(e))],
        la in prop_oneof![-9.0f64..0.0, 0.0f64..300.0],
        k in 2usize..=MAX_PARTITIONS,
        gamma in prop_oneof![0.0f64..=FRAC_PI_2, Just(0.0), Just(FRAC_PI_2)],
        ratio in 1.001f64..8.0,
    ) {
        let f = n * (1.0 + 10f64.powf(la));
        prop_assume!(f.is_finite() && f > n);
        let got = z_splits(n, f, k, SplitScheme::Adaptive { light_angle: gamma, ratio });
        if let Some(want) = eq19_by_powf(n, f, k, gamma, ratio) {
            let got = got.unwrap();
            for (i, (g, w)) in got.planes().iter().zip(&want).enumerate() {
                prop_assert!(close(*g, *w, 1e-14), "plane {i}: {g} vs {w} ({:e})", (g - w).abs() / w);
            }
        } else if let Ok(sp) = got {
            // Near the edge: still strictly increasing, as the contract says.
            prop_assert!(sp.planes().windows(2).all(|w| w[1] > w[0]));
        }
    }
}

/// Eq 19 with k = 3 by hand (the x^{2/3} plane): n = 1, f = 64, γ = π/2 (λ = 1): z₂ = 64^{2/3}
/// = 16, z₁ = 16^{1/2} = 4 — the self-similar planes; with γ = 0, α = 2: 64, 32, 16.
#[test]
fn adaptive_k3_by_hand() {
    let s = z_splits(
        1.0,
        64.0,
        3,
        SplitScheme::Adaptive {
            light_angle: FRAC_PI_2,
            ratio: 3.0,
        },
    )
    .unwrap();
    let p = s.planes();
    assert!(close(p[1], 4.0, 1e-15) && close(p[2], 16.0, 1e-15), "{p:?}");
    let s = z_splits(
        1.0,
        64.0,
        3,
        SplitScheme::Adaptive {
            light_angle: 0.0,
            ratio: 2.0,
        },
    )
    .unwrap();
    assert_eq!(s.planes(), &[1.0, 16.0, 32.0, 64.0]);
}

/// The k = 4 paths report the same errors as the others: f/n = 1 + 2ε puts (f/n)^{1/4} at 1
/// (√(1 + 2ε) = 1 + ε, √(1 + ε) rounds to 1), so planes 0 and 1 coincide (`Degenerate`); an
/// adaptive ratio too deep for f/n = 10 is `NoSolution` (γ = 0, α = 4: 10, 2.5, 0.625, 0.15625;
/// the first plane out of order, from the near side, is plane 1).
#[test]
fn four_partitions_report_the_common_errors() {
    let f = 1.0 + 2.0 * f64::EPSILON;
    match z_splits(1.0, f, 4, SplitScheme::SelfSimilar) {
        Err(Error::Degenerate(m)) => assert!(m.contains("planes 0 and 1 coincide"), "{m}"),
        other => panic!("{other:?}"),
    }
    let deep = SplitScheme::Adaptive {
        light_angle: 0.0,
        ratio: 4.0,
    };
    match z_splits(1.0, 10.0, 4, deep) {
        Err(Error::NoSolution(m)) => assert!(
            m.contains("puts plane 1 at 0.15625 but plane 0 at 1"),
            "{m}"
        ),
        other => panic!("{other:?}"),
    }
}

/// The review's case near γ = π/2, where 1 − λ = 0.0297 and a one-ulp error in λ grows 33×:
/// n = 0.01, f = 0.01 (1 + 10^13.751307336893603), k = 4, γ = 1.524098738043311, α = 1.001.
/// Expected planes from Eq 19 in 60-digit decimal arithmetic (Python `decimal`, the inputs'
/// exact binary values, π/2 read as `FRAC_PI_2`, x^{(i−1)/i} as exp(ln x (i−1)/i)):
/// 14994331.29779288413, 504804775.74696225913, 16950971857.31791001641. With λ = γ · (2/π)
/// and 1 − λ by subtraction (before the fix) plane 1 was 14994331.29779279, 6·10⁻¹⁵ off.
#[test]
fn adaptive_planes_near_half_pi_are_exact() {
    let f = 0.01 * (1.0 + 10f64.powf(13.751307336893603));
    let s = z_splits(
        0.01,
        f,
        4,
        SplitScheme::Adaptive {
            light_angle: 1.524098738043311,
            ratio: 1.001,
        },
    )
    .unwrap();
    let want = [
        14_994_331.297_792_884,
        504_804_775.746_962_26,
        16_950_971_857.317_91,
    ];
    for (i, w) in want.iter().enumerate() {
        let got = s.planes()[i + 1];
        assert!(close(got, *w, 1e-15), "plane {}: {got} vs {w}", i + 1);
    }
}

/// Eq 23's j (shadow maps) describes a scheme only for j = 4k, k z-partitions per face (the
/// paper: "one z-partitioning for every four shadow maps"; its j leaves out the near face's map,
/// which `shadow_map_count` counts: 4k + 1). At f/n = 10⁶, θ = 30°: Eq 18 gives 866 024.5 (k = 1)
/// and 1730.32 (k = 2), Eq 23 with its constant j (f/n)^{4/j}/(8 tan θ) 866 025.4 (j = 4) and
/// 1732.05 (j = 8); j = 6 gives 12 990.4, the value of 1.5 partitions per face, no scheme; and
/// j = 9, the crate's map count for k = 2, gives 904.44, half of the scheme's 1730.32.
#[test]
fn errata_eq23_needs_j_a_multiple_of_4() {
    let th = 30f64.to_radians();
    let v = ViewFrustum::new(1.0, 1e6, th).unwrap();
    let eq23 = |j: f64| j * 1e6f64.powf(4.0 / j) / (8.0 * th.tan());
    for k in [1usize, 2, 3, 5] {
        let j = 4 * k;
        let exact = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Overhead, &v, k).unwrap();
        // Eq 18 with k = j/4, by hand, and its large-f/n form.
        let eq18 = k as f64 * (1e6f64.powf(1.0 / k as f64) - 1.0) / (2.0 * th.tan());
        assert!(close(exact, eq18, 1e-12));
        assert!(close(
            exact / eq23(j as f64),
            1.0 - 1e6f64.powf(-4.0 / j as f64),
            1e-12
        ));
        assert!(close(
            fp_zp_w_overhead_asymptotic(&v, j).unwrap(),
            eq23(j as f64),
            1e-12
        ));
        assert_eq!(
            shadow_map_count(Scheme::FpZpW, SchemeLight::Behind, k).unwrap(),
            j + 1
        );
    }
    let k1 = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Overhead, &v, 1).unwrap();
    let k2 = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Overhead, &v, 2).unwrap();
    assert!((k1 - 866_024.5).abs() < 0.05 && (k2 - 1730.32).abs() < 5e-3);
    assert!((eq23(4.0) - 866_025.4).abs() < 0.05 && (eq23(8.0) - 1732.05).abs() < 5e-3);
    // j = 6 lies between the k = 1 and k = 2 schemes, equal to neither.
    assert!((eq23(6.0) - 12_990.4).abs() < 0.05 && eq23(6.0) < k1 && eq23(6.0) > k2);
    // j = 4k + 1 (the near face counted) halves the k = 2 value.
    assert!((eq23(9.0) - 904.44).abs() < 5e-3 && eq23(9.0) < 0.53 * k2);
    // The crate refuses both: they describe no scheme.
    for j in [0, 6, 9, 13] {
        match fp_zp_w_overhead_asymptotic(&v, j) {
            Err(shadow_aliasing::Error::InvalidArgument { name, .. }) => {
                assert_eq!(name, "shadow_maps")
            }
            other => panic!("j = {j}: {other:?}"),
        }
    }
}
