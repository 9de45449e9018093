//! z-partitions (cascades): every partition's corners in its clip volume for random cameras and
//! lights; Lloyd 2006 Eq 17, 18 (light overhead) and Eq 20 (light behind) from the measurement of
//! the built matrices; overlap; explicit fractions; stable cascades and what they cost.

mod common;
use common::{config, n_ln_alpha_theta_k};
use glam::{DMat3, DMat4, DVec3, DVec4};
use proptest::prelude::*;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::maps::cascades::{
    bounding_sphere, cascades, splits_from_fractions, stable_cascade,
};
use shadow_aliasing::maps::{Falloff, WarpRule};
use shadow_aliasing::measure::{frustum_max, frustum_max_sampled};
use shadow_aliasing::scheme::{scheme, seams, Partition};
use shadow_aliasing::ViewFrustum;

const RULES: [WarpRule; 11] = [
    WarpRule::MinimaxMz,
    WarpRule::Uniform,
    WarpRule::Psm,
    WarpRule::Lispsm,
    WarpRule::Lispsm,
    WarpRule::Eta(0.5),
    WarpRule::Barroso(Falloff::Barroso),
    WarpRule::LispsmReference,
    WarpRule::Filament,
    WarpRule::Ogre,
    WarpRule::Minimax,
];

/// Rounding: the same bound as tests/builders.rs and `maps::warp::fit_warp`'s documented
/// precision. With f/n near 10⁶ and PSM's n′ = n, w spans six decades and the extreme corners
/// land within about 10⁻⁹ of the faces (seen: 1.4·10⁻⁹ in depth at f/n = 8.2·10⁵ with the light
/// 10⁻⁹ off parallel); 10⁻⁸ is far below a GPU's f32 resolution (6·10⁻⁸).
fn assert_in_clip(m: &DMat4, p: DVec3, ctx: &str) {
    let h = *m * DVec4::new(p.x, p.y, p.z, 1.0);
    assert!(h.w > 0.0 && h.is_finite(), "{ctx}: w = {} at {p}", h.w);
    let c = h.truncate() / h.w;
    let tol = 1e-8;
    assert!(
        c.abs().max_element() <= 1.0 + tol,
        "{ctx}: corner {p} maps to {c}"
    );
}

/// `common::light` with a direction a hair from antiparallel to the view.
fn light() -> impl Strategy<Value = DVec3> {
    common::light(DVec3::new(0.0, 1e-7, 1.0))
}

/// Near in [1e−3, 10], f/n log-uniform in [1.01, 10⁶], half fov in [1°, 80°], aspect in [0.5, 2].
fn camera() -> impl Strategy<Value = ViewFrustum> {
    common::camera(1f64.to_radians()..80f64.to_radians())
}

fn split_scheme() -> impl Strategy<Value = SplitScheme> {
    prop_oneof![
        Just(SplitScheme::Uniform),
        Just(SplitScheme::SelfSimilar),
        (0.0f64..=1.0).prop_map(|lambda| SplitScheme::Practical { lambda }),
        (1.0f64..3.0).prop_map(|exponent| SplitScheme::Exponent { exponent }),
    ]
}

proptest! {
    #![proptest_config(config(2048))]

    /// Every partition's matrix maps its (overlap-extended) sub-frustum's eight corners into the
    /// clip volume, with finite, positive measured errors.
    #[test]
    fn every_partition_contains_its_corners(
        view in camera(),
        l in light(),
        k in 1usize..=8,
        sch in split_scheme(),
        rule_i in 0usize..RULES.len(),
        overlap in prop_oneof![Just(0.0), 0.0f64..0.5],
    ) {
        let rule = RULES[rule_i];
        // Very thin frusta cannot hold many distinct planes: the splitter says so (typed error).
        let splits = match z_splits(view.near(), view.far(), k, sch) {
            Ok(s) => s,
            Err(shadow_aliasing::Error::Degenerate(_)) => return Ok(()),
            Err(e) => panic!("{e}"),
        };
        let c = cascades(&view, l, &splits, rule, overlap).unwrap();
        prop_assert_eq!(c.k(), k);
        let mut prev_far = view.near();
        for (i, part) in c.iter().enumerate() {
            prop_assert_eq!(part.split_near, prev_far);
            prev_far = part.split_far;
            let sub = view.with_depth_range(part.shadow.near(), part.shadow.far()).unwrap();
            for p in sub.corners() {
                assert_in_clip(&part.shadow.matrix(), p, &format!("partition {i} of {k}, {rule:?}"));
            }
            prop_assert!(part.error.max_mx.is_finite() && part.error.max_mx > 0.0);
            prop_assert!(part.error.max_mz.is_finite() && part.error.max_mz > 0.0);
        }
        prop_assert!((prev_far - view.far()).abs() <= 1e-12 * view.far());
        prop_assert!(c.storage_factor().is_finite());
    }

    /// The scheme layer, every partitioning: each map holds its region's vertices (sub-frustum
    /// corners, or the face part's vertices), every reported number is finite, the sum is the
    /// sum; the only errors are the typed ones the docs name.
    #[test]
    fn every_scheme_is_finite_and_holds_its_region(
        view in camera(),
        l in light(),
        k in 1usize..=6,
        part_i in 0usize..6,
        lambda in 0.0f64..=1.0,
        rule_i in 0usize..RULES.len(),
    ) {
        let partition = [
            Partition::Single,
            Partition::Uniform,
            Partition::Log,
            Partition::Practical(lambda),
            Partition::Adaptive,
            Partition::Faces,
        ][part_i];
        let rule = RULES[rule_i];
        let r = match scheme(&view, l, rule, partition, k) {
            Ok(r) => r,
            // Planes that coincide in f64 (f/n ≈ 1 with many partitions) and Barroso's planes
            // that do not exist for this f/n and k.
            Err(shadow_aliasing::Error::Degenerate(m)) if m.contains("coincide") => return Ok(()),
            Err(shadow_aliasing::Error::NoSolution(_)) if partition == Partition::Adaptive => {
                return Ok(())
            }
            Err(e) => panic!("{partition:?} {rule:?}: {e}"),
        };
        let mut sum = 0.0;
        prop_assert!(!r.partitions().is_empty());
        for p in r.partitions() {
            prop_assert!(p.matrix.is_finite());
            for v in [p.near, p.far, p.max_mx, p.max_mz, p.storage_factor] {
                prop_assert!(v.is_finite());
            }
            prop_assert!(p.max_mx > 0.0 && p.max_mz > 0.0);
            sum += p.storage_factor;
            let points: Vec<DVec3> = common::region_points(&view, p);
            for q in points {
                assert_in_clip(&p.matrix, q, &format!("{partition:?} {rule:?} {:?}", p.region));
            }
        }
        prop_assert!((sum - r.storage_factor()).abs() <= 1e-12 * sum);
        let s = seams(&view, &r).unwrap();
        for seam in s.as_slice() {
            prop_assert!(seam.jump_mx.is_finite() && seam.jump_mx >= 1.0);
            prop_assert!(seam.jump_mz.is_finite() && seam.jump_mz >= 1.0);
        }
    }

    /// Lloyd 2006 Eq 17 and 18, light overhead, self-similar planes:
    /// S̄_ZP = k (f/n)^{1/k} ((f/n)^{1/k} − 1)/(2 tan θ) without warping,
    /// S̄_ZP+W = k ((f/n)^{1/k} − 1)/(2 tan θ) with n′ = n′_LSPSM per partition. Measured with
    /// `measure::frustum_max` (the crate's ground truth) on each partition's matrix.
    #[test]
    fn eq17_eq18_overhead(
        (n, lr, th, k) in n_ln_alpha_theta_k(),
    ) {
        let alpha = lr.exp();
        let view = ViewFrustum::new(n, n * alpha, th).unwrap();
        let r = alpha.powf(1.0 / k as f64);
        let t = th.tan();
        let zp = k as f64 * r * (r - 1.0) / (2.0 * t);
        let zpw = k as f64 * (r - 1.0) / (2.0 * t);
        let splits = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar).unwrap();
        let l = DVec3::new(0.0, -1.0, 0.0);
        for (rule, expect) in [
            (WarpRule::Uniform, zp),
            (WarpRule::Lispsm, zpw),
            (WarpRule::Lispsm, zpw),
            (WarpRule::Psm, zpw),
            (WarpRule::MinimaxMz, zpw),
        ] {
            let c = cascades(&view, l, &splits, rule, 0.0).unwrap();
            let mut measured = 0.0;
            for part in c.iter() {
                let sub = view.with_depth_range(part.shadow.near(), part.shadow.far()).unwrap();
                let e = frustum_max(&sub, &part.shadow.shadow_map()).unwrap();
                prop_assert!((e.storage_factor - part.storage_factor()).abs() <= 1e-9 * e.storage_factor);
                measured += e.storage_factor;
            }
            prop_assert!(
                (measured - expect).abs() <= 1e-9 * expect,
                "{rule:?}: measured {measured}, Eq 17/18 {expect}"
            );
            prop_assert!((c.storage_factor() - expect).abs() <= 1e-9 * expect);
        }
    }

    /// Lloyd 2006 Eq 20, light behind: S̄_ZP = k (f/n)^{2/k}; ZP+W falls back to it (no warp is
    /// possible: the frustum looks square), here with the 1/sin γ rule.
    #[test]
    fn eq20_behind(
        (n, lr, th, k) in n_ln_alpha_theta_k(),
    ) {
        let alpha = lr.exp();
        let view = ViewFrustum::new(n, n * alpha, th).unwrap();
        let expect = k as f64 * alpha.powf(2.0 / k as f64);
        let splits = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar).unwrap();
        for rule in [WarpRule::Uniform, WarpRule::Lispsm] {
            let c = cascades(&view, DVec3::new(0.0, 0.0, -1.0), &splits, rule, 0.0).unwrap();
            let mut measured = 0.0;
            for part in c.iter() {
                let sub = view.with_depth_range(part.shadow.near(), part.shadow.far()).unwrap();
                measured += frustum_max(&sub, &part.shadow.shadow_map()).unwrap().storage_factor;
            }
            prop_assert!(
                (measured - expect).abs() <= 1e-9 * expect,
                "{rule:?}: measured {measured}, Eq 20 {expect}"
            );
        }
    }

    /// Seams (Lloyd 2006 §5.2), light overhead, self-similar planes of ratio r = (f/n)^{1/k}:
    /// with n′ = n′_LSPSM "there is no change in z error at a seam" and m_x jumps from 1 (far end
    /// of partition i, Eq 7 at z = f_i) to m_x(n_{i+1}) = r n′/(n′ + f − n)/… = √r;
    /// with n′ = n "there is no change in x error" and m_z jumps by r
    /// (Eq 8: (r − 1)/(2 tan θ) at the far end of i, (r − 1)/(2 r tan θ) at the near end of i + 1).
    #[test]
    fn seams_overhead(
        lr in (2f64).ln()..(1e4f64).ln(),
        th in 5f64.to_radians()..75f64.to_radians(),
        k in 2usize..=6,
    ) {
        let alpha = lr.exp();
        let view = ViewFrustum::new(1.0, alpha, th).unwrap();
        let r = alpha.powf(1.0 / k as f64);
        let l = DVec3::new(0.0, -1.0, 0.0);
        let lis = scheme(&view, l, WarpRule::Lispsm, Partition::Log, k).unwrap();
        let s = seams(&view, &lis).unwrap();
        prop_assert_eq!(s.as_slice().len(), k - 1);
        for seam in s.as_slice() {
            prop_assert_eq!(seam.b, seam.a + 1);
            prop_assert!((seam.jump_mz - 1.0).abs() <= 1e-9);
            prop_assert!((seam.jump_mx - r.sqrt()).abs() <= 1e-9 * r);
        }
        let psm = scheme(&view, l, WarpRule::Psm, Partition::Log, k).unwrap();
        for seam in seams(&view, &psm).unwrap().as_slice() {
            prop_assert!((seam.jump_mx - 1.0).abs() <= 1e-9);
            prop_assert!((seam.jump_mz - r).abs() <= 1e-9 * r);
        }
    }
}

/// The vertices suffice: a dense sampling of each partition finds no larger error.
#[test]
fn vertex_maxima_agree_with_dense_sampling() {
    let view = ViewFrustum::new(0.5, 300.0, 0.6).unwrap();
    let splits = z_splits(0.5, 300.0, 4, SplitScheme::Practical { lambda: 0.7 }).unwrap();
    for l in [
        DVec3::new(0.3, -1.0, -0.2),
        DVec3::new(-0.5, -0.4, 0.7),
        DVec3::new(0.1, -0.2, -1.0),
    ] {
        for rule in [WarpRule::Lispsm, WarpRule::Uniform, WarpRule::Minimax] {
            let c = cascades(&view, l, &splits, rule, 0.1).unwrap();
            for part in c.iter() {
                let sub = view
                    .with_depth_range(part.shadow.near(), part.shadow.far())
                    .unwrap();
                let dense = frustum_max_sampled(&sub, &part.shadow.shadow_map(), 9).unwrap();
                assert!(dense.max_mx <= part.error.max_mx * (1.0 + 1e-9));
                assert!(dense.max_mz <= part.error.max_mz * (1.0 + 1e-9));
            }
        }
    }
}

/// Overlap: partition i is fitted to [z_i, z_{i+1} + o (z_{i+1} − z_i)], the last to far.
#[test]
fn overlap_extends_each_partition_by_its_fraction() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let splits = z_splits(1.0, 100.0, 2, SplitScheme::SelfSimilar).unwrap();
    let c = cascades(
        &view,
        DVec3::new(0.2, -1.0, 0.1),
        &splits,
        WarpRule::Lispsm,
        0.25,
    )
    .unwrap();
    let p0 = c.get(0).unwrap();
    let p1 = c.get(1).unwrap();
    assert_eq!((p0.split_near, p0.split_far), (1.0, 10.0));
    assert!((p0.shadow.far() - (10.0 + 0.25 * 9.0)).abs() < 1e-12);
    assert_eq!((p1.shadow.near(), p1.shadow.far()), (10.0, 100.0));
    assert!(c.get(2).is_none());
    assert!(cascades(&view, DVec3::NEG_Y, &splits, WarpRule::Lispsm, 1.0).is_err());
    assert!(cascades(&view, DVec3::NEG_Y, &splits, WarpRule::Lispsm, f64::NAN).is_err());
    assert!(cascades(&view, DVec3::ZERO, &splits, WarpRule::Lispsm, 0.0).is_err());
    // Planes outside the view's depth range are refused.
    let wide = z_splits(0.5, 100.0, 2, SplitScheme::Uniform).unwrap();
    assert!(cascades(&view, DVec3::NEG_Y, &wide, WarpRule::Lispsm, 0.0).is_err());
}

/// Explicit fractions of the depth range, by hand.
#[test]
fn fractions_by_hand() {
    let view = ViewFrustum::new(2.0, 42.0, 0.5).unwrap();
    let s = splits_from_fractions(&view, &[0.05, 0.25, 0.5]).unwrap();
    assert_eq!(s.planes(), &[2.0, 4.0, 12.0, 22.0, 42.0]);
    assert_eq!(
        splits_from_fractions(&view, &[]).unwrap().planes(),
        &[2.0, 42.0]
    );
    assert!(splits_from_fractions(&view, &[0.5, 0.5]).is_err());
    assert!(splits_from_fractions(&view, &[0.0]).is_err());
    assert!(splits_from_fractions(&view, &[1.0]).is_err());
    assert!(splits_from_fractions(&view, &[f64::NAN]).is_err());
    assert!(splits_from_fractions(&view, &[0.01; 16]).is_err());
    // Light overhead, uniform maps on [2, 4], [4, 12], [12, 22], [22, 42]: Eq 12 with n′ = ∞ per
    // partition, S̄_i = (f_i/n_i − 1) f_i/(2 n_i tan θ).
    let c = cascades(&view, DVec3::NEG_Y, &s, WarpRule::Uniform, 0.0).unwrap();
    let t = 0.5f64.tan();
    let expect: f64 = [(2.0, 4.0), (4.0, 12.0), (12.0, 22.0), (22.0, 42.0)]
        .iter()
        .map(|&(a, b): &(f64, f64)| (b / a - 1.0) * b / (2.0 * a * t))
        .sum();
    assert!((c.storage_factor() - expect).abs() < 1e-9 * expect);
}

/// The minimal bounding sphere: every corner inside, two corners (or the far cap) on it.
#[test]
fn bounding_sphere_is_minimal() {
    for (n, f, th, a) in [
        (1.0, 3.0, 0.5f64.atan(), 1.0),
        (1.0, 1000.0, 0.5, 1.0),
        (0.1, 0.2, 1.2, 1.7),
        (5.0, 6.0, 0.1, 0.5),
    ] {
        let view = ViewFrustum::with_aspect(n, f, th, a).unwrap();
        let (c, r) = bounding_sphere(&view, n, f).unwrap();
        let center = DVec3::new(0.0, 0.0, -c);
        let sub = view.with_depth_range(n, f).unwrap();
        let d: Vec<f64> = sub
            .corners()
            .iter()
            .map(|p| (*p - center).length())
            .collect();
        let far_on = (d[4] - r).abs() < 1e-12 * r;
        assert!(d.iter().all(|&x| x <= r * (1.0 + 1e-12)));
        assert!(far_on, "far corners on the sphere");
        // Either the near corners are on it too, or the centre sits on the far plane.
        assert!((d[0] - r).abs() < 1e-12 * r || (c - f).abs() < 1e-12 * f);
    }
}

fn rotation(yaw: f64, pitch: f64) -> DMat3 {
    DMat3::from_rotation_y(yaw) * DMat3::from_rotation_x(pitch)
}

/// Stable cascades: the map contains the partition; moving or turning the camera shifts the
/// world → clip map by whole texels only; S̄ is the hand value of an orthographic map of side
/// 2R_map seen from anywhere, (R_map/(n_i tan θ))², and costs at least the tight fit.
#[test]
fn stable_cascades_snap_to_whole_texels() {
    let view = ViewFrustum::new(0.5, 200.0, 0.6).unwrap();
    let splits = z_splits(0.5, 200.0, 4, SplitScheme::Practical { lambda: 0.8 }).unwrap();
    let light_world = DVec3::new(0.3, -1.0, 0.45);
    let res = 1024u32;
    let poses = [
        (DVec3::new(0.0, 2.0, 0.0), 0.0, 0.0),
        (DVec3::new(13.37, 2.5, -7.1), 0.7, -0.2),
        (DVec3::new(13.39, 2.5, -7.13), 0.71, -0.19),
        (DVec3::new(-150.0, 10.0, 42.0), -2.5, 0.4),
    ];
    let probes = [
        DVec3::new(1.0, 0.0, 3.0),
        DVec3::new(-20.0, 5.0, 17.0),
        DVec3::new(40.0, -1.0, -8.0),
    ];
    for i in 0..splits.k() {
        let (a, b) = splits.range(i);
        let mut clips: Vec<Vec<DVec3>> = Vec::new();
        let mut texel = 0.0;
        for &(pos, yaw, pitch) in &poses {
            let rot = rotation(yaw, pitch);
            // eye → world = T(pos) R; world → eye its inverse.
            let eye_to_world = DMat4::from_translation(pos) * DMat4::from_mat3(rot);
            let world_to_eye = eye_to_world.inverse();
            let s = stable_cascade(&view, world_to_eye, light_world, a, b, res).unwrap();
            let sub = view.with_depth_range(a, b).unwrap();
            for p in sub.corners() {
                assert_in_clip(&s.shadow.matrix(), p, "stable cascade");
            }
            let t = view.tan_half_fov();
            let r_map = s.radius * f64::from(res) / f64::from(res - 2);
            let expect = (r_map / (a * t)).powi(2);
            assert!((s.storage_factor - expect).abs() < 1e-9 * expect);
            assert!(s.storage_loss() >= 1.0);
            texel = s.texel;
            let m = s.shadow.matrix() * world_to_eye;
            clips.push(
                probes
                    .iter()
                    .map(|p| {
                        let h = m * DVec4::new(p.x, p.y, p.z, 1.0);
                        h.truncate() / h.w
                    })
                    .collect(),
            );
        }
        // Texel edge in clip units is 2/res: clip differences are whole multiples of it.
        let _ = texel;
        for c in &clips[1..] {
            for (p, q) in c.iter().zip(&clips[0]) {
                for d in [p.x - q.x, p.y - q.y] {
                    let texels = d * f64::from(res) / 2.0;
                    assert!(
                        (texels - texels.round()).abs() < 1e-6,
                        "shift of {texels} texels"
                    );
                }
            }
        }
    }
    let w2e = DMat4::IDENTITY;
    assert!(stable_cascade(&view, w2e, light_world, 1.0, 2.0, 2).is_err());
    assert!(stable_cascade(
        &view,
        DMat4::from_scale(DVec3::splat(2.0)),
        light_world,
        1.0,
        2.0,
        64
    )
    .is_err());
    assert!(stable_cascade(&view, w2e, DVec3::ZERO, 1.0, 2.0, 64).is_err());
    assert!(stable_cascade(&view, w2e, light_world, 2.0, 1.0, 64).is_err());
}

/// With the light overhead the tight fit of partition [n_i, f_i] has S̄ = (f_i/n_i − 1) f_i /
/// (2 n_i tan θ) (Eq 12, n′ = ∞); the stable map's loss is the ratio to the hand value above.
#[test]
fn stable_cascade_loss_by_hand() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let s = stable_cascade(&view, DMat4::IDENTITY, DVec3::NEG_Y, 1.0, 10.0, 2048).unwrap();
    let t = 0.5f64.tan();
    let tight = 9.0 * 10.0 / (2.0 * t);
    assert!((s.tight_storage_factor - tight).abs() < 1e-9 * tight);
    let r_map = s.radius * 2048.0 / 2046.0;
    let stable = (r_map / t).powi(2);
    assert!((s.storage_loss() - stable / tight).abs() < 1e-9 * stable / tight);
}

/// Both clip-depth conventions: [0, 1] depth is (z + w)/2 of the OpenGL one, x, y, w unchanged;
/// the single-precision matrix agrees to f32 rounding.
#[test]
fn clip_depth_conventions() {
    use shadow_aliasing::maps::ClipDepth;
    let view = ViewFrustum::new(0.5, 80.0, 0.7).unwrap();
    let r = scheme(
        &view,
        DVec3::new(0.4, -0.7, -0.3),
        WarpRule::Lispsm,
        Partition::Faces,
        2,
    )
    .unwrap();
    for p in r.partitions() {
        let gl = p.matrix_with_clip_depth(ClipDepth::NegOneToOne);
        let zo = p.matrix_with_clip_depth(ClipDepth::ZeroToOne);
        assert_eq!(gl, p.matrix);
        let f32m = p.to_mat4(ClipDepth::ZeroToOne);
        let pts: Vec<DVec3> = common::region_points(&view, p);
        for q in pts {
            let a = gl * DVec4::new(q.x, q.y, q.z, 1.0);
            let b = zo * DVec4::new(q.x, q.y, q.z, 1.0);
            assert!((b.z - 0.5 * (a.z + a.w)).abs() < 1e-12 * a.w.abs().max(1.0));
            assert_eq!((a.x, a.y, a.w), (b.x, b.y, b.w));
            let d = b.z / b.w;
            assert!((-1e-9..=1.0 + 1e-9).contains(&d), "depth {d}");
            let c = f32m * glam::Vec4::new(q.x as f32, q.y as f32, q.z as f32, 1.0);
            assert!(((c.z / c.w) as f64 - d).abs() < 1e-4);
        }
    }
}

proptest! {
    #![proptest_config(config(128))]

    /// Any split planes (uniform, practical, Unreal's exponent), light overhead: the measured S̄ of
    /// the cascades is Eq 12 summed over the partitions (`analytic::partition::splits_storage_factor`),
    /// uniform maps and maps warped with n′ ≤ n′_LSPSM of each partition; light behind, (f_i/n_i)²
    /// summed (Eq 20 per partition). And the scheme layer against Lloyd 2006 Eq 17–21 as the
    /// analytic module states them (`scheme_storage_factor`).
    #[test]
    fn measured_schemes_equal_the_closed_forms(
        n in 0.05f64..5.0,
        lr in (2f64).ln()..(1e4f64).ln(),
        th in 10f64.to_radians()..70f64.to_radians(),
        k in 1usize..=6,
        sch in split_scheme(),
    ) {
        use shadow_aliasing::analytic::partition::{
            scheme_storage_factor, splits_storage_factor, Scheme, SchemeLight,
        };
        let view = ViewFrustum::new(n, n * lr.exp(), th).unwrap();
        let splits = match z_splits(view.near(), view.far(), k, sch) {
            Ok(s) => s,
            Err(_) => return Ok(()),
        };
        for (light, l) in [(SchemeLight::Overhead, DVec3::NEG_Y), (SchemeLight::Behind, DVec3::NEG_Z)] {
            for (rule, warped) in [(WarpRule::Uniform, false), (WarpRule::Lispsm, true)] {
                let got = cascades(&view, l, &splits, rule, 0.0).unwrap().storage_factor();
                let want = splits_storage_factor(&splits, th, light, warped).unwrap();
                prop_assert!((got - want).abs() <= 1e-9 * want, "{light:?} {rule:?}: {got} vs {want}");
            }
            for (scheme_, rule, partition) in [
                (Scheme::Zp, WarpRule::Uniform, Partition::Log),
                (Scheme::ZpW, WarpRule::Lispsm, Partition::Log),
                (Scheme::FpZpW, WarpRule::Lispsm, Partition::Faces),
            ] {
                let got = scheme(&view, l, rule, partition, k).unwrap().storage_factor();
                let want = scheme_storage_factor(scheme_, light, &view, k).unwrap();
                prop_assert!((got - want).abs() <= 1e-9 * want, "{scheme_:?} {light:?}: {got} vs {want}");
            }
        }
    }
}

/// Barroso & Celes Eq 19 through the scheme layer: with the light overhead (γ = π/2) the adaptive
/// planes are the self-similar ones, so S̄ is Eq 18's; with the light behind (γ = 0) they are
/// f, f/α, f/α², … (α = 2), and S̄ is Eq 20 per partition, Σ (f_i/n_i)²: at n = 1, f = 100, k = 3
/// the planes are 1, 25, 50, 100 and S̄ = 25² + 2² + 2² = 633.
#[test]
fn adaptive_partitions_by_hand() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let over = DVec3::NEG_Y;
    let a = scheme(&view, over, WarpRule::Lispsm, Partition::Adaptive, 3).unwrap();
    let l = scheme(&view, over, WarpRule::Lispsm, Partition::Log, 3).unwrap();
    assert!((a.storage_factor() - l.storage_factor()).abs() < 1e-9 * l.storage_factor());
    let eq18 = 3.0 * (100f64.powf(1.0 / 3.0) - 1.0) / (2.0 * 0.5f64.tan());
    assert!((a.storage_factor() - eq18).abs() < 1e-9 * eq18);
    let behind = scheme(
        &view,
        DVec3::NEG_Z,
        WarpRule::Lispsm,
        Partition::Adaptive,
        3,
    )
    .unwrap();
    let planes: Vec<(f64, f64)> = behind
        .partitions()
        .iter()
        .map(|p| (p.near, p.far))
        .collect();
    assert_eq!(planes, vec![(1.0, 25.0), (25.0, 50.0), (50.0, 100.0)]);
    assert!((behind.storage_factor() - 633.0).abs() < 1e-9 * 633.0);
    // f/n = 10 cannot hold five partitions, four of ratio 2 behind the first (10, 5, 2.5, 1.25,
    // 0.625 < near):
    // a typed error.
    let short = ViewFrustum::new(1.0, 10.0, 0.5).unwrap();
    assert!(matches!(
        scheme(
            &short,
            DVec3::NEG_Z,
            WarpRule::Lispsm,
            Partition::Adaptive,
            5
        ),
        Err(shadow_aliasing::Error::NoSolution(_))
    ));
}

/// Stable cascades for all partitions: one per partition, each no better than its tight fit,
/// the sums the sums; planes outside the view refused.
#[test]
fn stable_cascades_for_all_partitions() {
    use shadow_aliasing::maps::cascades::stable_cascades;
    let view = ViewFrustum::new(0.5, 200.0, 0.6).unwrap();
    let splits = z_splits(0.5, 200.0, 5, SplitScheme::SelfSimilar).unwrap();
    let camera =
        glam::dcamera::rh::view::look_at_mat4(DVec3::new(3.0, 2.0, 5.0), DVec3::ZERO, DVec3::Y);
    let light = DVec3::new(0.3, -1.0, 0.2);
    let c = stable_cascades(&view, camera, light, &splits, 1024).unwrap();
    assert_eq!(c.k(), 5);
    let mut sum = 0.0;
    for (i, s) in c.iter().enumerate() {
        let (a, b) = splits.range(i);
        let one = stable_cascade(&view, camera, light, a, b, 1024).unwrap();
        assert_eq!(*s, one);
        assert!(s.storage_loss() >= 1.0);
        sum += s.storage_factor;
    }
    assert!((c.storage_factor() - sum).abs() <= 1e-12 * sum);
    assert!(c.storage_factor() >= c.tight_storage_factor());
    let wide = z_splits(0.25, 200.0, 2, SplitScheme::Uniform).unwrap();
    assert!(stable_cascades(&view, camera, light, &wide, 1024).is_err());
}
