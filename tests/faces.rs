//! Face partitions (Lloyd 2006 §5.1, Lloyd 2005 §4): which faces, their bisector warps, the
//! partitions' vertices in the clip volume and the frustum covered for random cameras and lights,
//! and Lloyd 2006 Eq 19 (overhead) and Eq 21 (behind) from the measurement of the built matrices.

mod common;
use common::faces::faces_with_axis;
use common::{config, n_ln_alpha_theta_k};
use glam::{DMat4, DVec3, DVec4};
use proptest::prelude::*;
use shadow_aliasing::analytic::partition::{scheme_storage_factor, Scheme, SchemeLight};
use shadow_aliasing::maps::faces::{face_axis, face_partitions, visible_faces, Face, FaceWarp};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::measure::{point_error, ShadowMap};
use shadow_aliasing::numeric::EDGE_ON;
use shadow_aliasing::scheme::{scheme, seams, Partition, Region};
use shadow_aliasing::{Resolutions, ViewFrustum};

fn clip(m: &DMat4, p: DVec3) -> Option<DVec3> {
    let h = *m * DVec4::new(p.x, p.y, p.z, 1.0);
    (h.w > 0.0 && h.is_finite()).then(|| h.truncate() / h.w)
}

/// `common::light` with a light a hair from the view's perpendicular plane.
fn light() -> impl Strategy<Value = DVec3> {
    common::light(DVec3::new(0.0, -1.0, 1e-8))
}

/// `common::camera`, a fifth of them with a half field of view near π/2.
fn camera() -> impl Strategy<Value = ViewFrustum> {
    common::camera(prop_oneof![
        4 => 1f64.to_radians()..80f64.to_radians(),
        // Half fields of view near π/2: a slab far wider than deep.
        1 => (2.0f64..9.0).prop_map(|u| std::f64::consts::FRAC_PI_2 - 10f64.powf(-u)),
    ])
}

/// The point where the light ray through `p` crosses the plane of `face` (eye space).
fn ray_hits_face(view: &ViewFrustum, face: Face, p: DVec3, l: DVec3) -> Option<DVec3> {
    let nrm = face.outward_normal(view);
    let offset = match face {
        Face::Near => -view.near(), // plane z = −n: N·x = −n
        Face::Far => view.far(),    // plane z = −f, N = −Z: N·x = f
        _ => 0.0,
    };
    let denom = nrm.dot(l);
    if denom.abs() < 1e-15 {
        return None;
    }
    let s = (offset - nrm.dot(p)) / denom;
    Some(p + s * l)
}

proptest! {
    #![proptest_config(config(1024))]

    /// Every face partition maps its face part's vertices, swept along the light through the
    /// frustum, into the clip volume; the partitions cover the frustum: a random point inside it
    /// lies in the clip volume of the partition whose face part its light ray crosses.
    #[test]
    fn partitions_hold_their_faces_and_cover_the_frustum(
        view in camera(),
        l in light(),
        k in 1usize..=6,
        rule in prop_oneof![Just(FaceWarp::Lispsm), Just(FaceWarp::Psm), Just(FaceWarp::Uniform)],
        u in proptest::collection::vec((0.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0), 8),
    ) {
        let parts = match face_partitions(&view, l, rule, k) {
            Ok(p) => p,
            // Thin frusta cannot hold k distinct self-similar planes: a typed error.
            Err(shadow_aliasing::Error::Degenerate(m)) if m.contains("coincide") => return Ok(()),
            // Near π/2 a face seen at a grazing angle is a sliver thinner than fit_warp's 10⁻¹²
            // of the swept points' extent: refused with a typed error, never an empty success.
            Err(shadow_aliasing::Error::Degenerate(m)) if view.half_fov() > 1.5 => {
                eprintln!("refused: {m}");
                return Ok(());
            }
            Err(e) => panic!("{e}"),
        };
        prop_assert!(!parts.is_empty());
        let l = l.normalize();
        let extent = view.far() * (1.0 + view.tan_half_fov() * (1.0 + view.aspect()));
        for p in parts.iter() {
            for v in p.vertices {
                for s in [-2.0 * extent, 0.0, 2.0 * extent] {
                    let q = v + s * l;
                    // Only points of the swept face part that are inside the frustum matter.
                    if !view.contains(q, 1e-12) {
                        continue;
                    }
                    let c = clip(&p.shadow.matrix(), q).expect("w > 0");
                    // fit_warp's documented rounding bound, as in tests/builders.rs.
                    let tol = 1e-8;
                    prop_assert!(c.abs().max_element() <= 1.0 + tol, "{:?}: {q} → {c}", p.face);
                }
            }
            prop_assert!(p.error.max_mx.is_finite() && p.error.max_mx > 0.0);
            prop_assert!(p.error.max_mz.is_finite() && p.error.max_mz > 0.0);
        }
        // Coverage.
        let t = view.tan_half_fov();
        for (a, b, c) in u {
            let z = view.near() * (view.far() / view.near()).powf(a);
            let p = DVec3::new(b * z * t * view.aspect() * 0.999, c * z * t * 0.999, -z);
            let mut found = false;
            for part in parts.iter() {
                if let Some(cl) = clip(&part.shadow.matrix(), p) {
                    if cl.abs().max_element() <= 1.0 + 1e-9 {
                        found = true;
                        break;
                    }
                }
            }
            // Points within EDGE_ON of a skipped edge-on face may be uncovered; otherwise found.
            if !found {
                let skipped = Face::ALL.iter().any(|f| {
                    f.outward_normal(&view).dot(l).abs() <= EDGE_ON
                        && ray_hits_face(&view, *f, p, l).is_some()
                });
                prop_assert!(skipped, "point {p} is in no partition");
            }
        }
    }
}

/// Which faces: Lloyd 2006 §5.1 front faces when v·y < 0, back faces otherwise.
#[test]
fn face_selection() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let f = |l: DVec3| visible_faces(&view, l).unwrap();
    // Overhead: v·y = 0, back faces: the bottom face only (near, left, right edge-on).
    let over = f(DVec3::NEG_Y);
    assert!(!over.front);
    assert_eq!(over.faces(), &[Face::Bottom]);
    // Behind (light travels along −Z): front faces, the four sides and the near face.
    let behind = f(DVec3::NEG_Z);
    assert!(behind.front);
    assert_eq!(
        behind.faces(),
        &[Face::Bottom, Face::Right, Face::Top, Face::Left, Face::Near]
    );
    // In front (light travels toward the camera): back faces, again four sides and the near face.
    let front = f(DVec3::Z);
    assert!(!front.front);
    assert_eq!(front.faces().len(), 5);
    // Behind and above: front faces with N·L < 0, the top and the near face (and no bottom).
    // The side faces' normals lean towards +Z (t a), so the light from behind sees them too.
    let above_behind = f(DVec3::new(0.0, -1.0, -1.0));
    assert_eq!(
        above_behind.faces(),
        &[Face::Right, Face::Top, Face::Left, Face::Near]
    );
    // Above and in front, tan θ = 0.546 < 1: back faces, all but the top (N·L = −1 + t < 0).
    let above_front = f(DVec3::new(0.0, -1.0, 1.0));
    assert_eq!(
        above_front.faces(),
        &[Face::Bottom, Face::Right, Face::Left, Face::Near]
    );
    // Side light from +X (travelling −X), slightly behind: N·L < 0 for all but the left face.
    let side = f(DVec3::new(-1.0, 0.0, -0.01));
    assert_eq!(
        side.faces(),
        &[Face::Bottom, Face::Right, Face::Top, Face::Near]
    );
    assert!(visible_faces(&view, DVec3::ZERO).is_err());
}

/// The bisector of the projected side edges (Lloyd 2006 §5.1): with the light behind, the top
/// face's axis is +Y, the right face's +X; overhead, the bottom face's axis is the view direction.
#[test]
fn bisector_axes() {
    let view = ViewFrustum::new(1.0, 50.0, 0.7).unwrap();
    let unit = |v: DVec3| v.normalize();
    let behind = DVec3::NEG_Z;
    assert!((unit(face_axis(&view, Face::Top, behind).unwrap()) - DVec3::Y).length() < 1e-15);
    assert!((unit(face_axis(&view, Face::Right, behind).unwrap()) - DVec3::X).length() < 1e-15);
    let over = DVec3::NEG_Y;
    assert!((unit(face_axis(&view, Face::Bottom, over).unwrap()) - DVec3::NEG_Z).length() < 1e-15);
    // A light along a side edge makes that edge's projection vanish.
    let edge = DVec3::new(view.tan_half_fov(), view.tan_half_fov(), -1.0);
    assert!(face_axis(&view, Face::Top, edge).is_err());
    // Tilted: the axis bisects the projected edges (equal angles to both).
    let l = DVec3::new(0.3, -0.2, -1.0).normalize();
    let [e0, e1] = Face::Top.side_edges(&view).unwrap();
    let a = unit(face_axis(&view, Face::Top, l).unwrap());
    let p0 = unit(e0 - e0.dot(l) * l);
    let p1 = unit(e1 - e1.dot(l) * l);
    assert!((a.dot(p0) - a.dot(p1)).abs() < 1e-14);
    assert!(a.dot(l).abs() < 1e-14);
}

fn measured_sum(view: &ViewFrustum, l: DVec3, rule: FaceWarp, k: usize) -> f64 {
    // The ground truth: measure::point_error at each partition's vertices.
    let parts = face_partitions(view, l, rule, k).unwrap();
    let mut total = 0.0;
    for p in parts.iter() {
        let sm = ShadowMap::new(p.shadow.matrix(), l).unwrap();
        let (mut mx, mut mz) = (0.0f64, 0.0f64);
        for v in p.vertices {
            let e = point_error(view, &sm, v, Resolutions::default()).unwrap();
            mx = mx.max(e.mx);
            mz = mz.max(e.mz);
        }
        assert!((mx * mz - p.storage_factor()).abs() <= 1e-9 * mx * mz);
        total += mx * mz;
    }
    total
}

proptest! {
    #![proptest_config(config(96))]

    /// Lloyd 2006 Eq 19: overhead, FP+ZP+W = ZP+W = k((f/n)^{1/k} − 1)/(2 tan θ) (one face seen);
    /// without warping the face map is the frustum's uniform map, Eq 17,
    /// k (f/n)^{1/k}((f/n)^{1/k} − 1)/(2 tan θ).
    #[test]
    fn eq19_overhead(
        (n, lr, th, k) in n_ln_alpha_theta_k(),
    ) {
        let alpha = lr.exp();
        let view = ViewFrustum::new(n, n * alpha, th).unwrap();
        let r = alpha.powf(1.0 / k as f64);
        let t = th.tan();
        let zpw = k as f64 * (r - 1.0) / (2.0 * t);
        let zp = k as f64 * r * (r - 1.0) / (2.0 * t);
        let l = DVec3::NEG_Y;
        // The closed form, `scheme_storage_factor(FpZpW, Overhead, …)`, against the measured
        // face partitions of both warping rules.
        let eq19 = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Overhead, &view, k).unwrap();
        for (rule, expect) in [(FaceWarp::Lispsm, zpw), (FaceWarp::Psm, zpw), (FaceWarp::Uniform, zp)] {
            let got = measured_sum(&view, l, rule, k);
            prop_assert!((got - expect).abs() <= 1e-9 * expect, "{rule:?}: {got} vs {expect}");
            if !matches!(rule, FaceWarp::Uniform) {
                prop_assert!((eq19 - got).abs() <= 1e-9 * got, "{rule:?}: Eq 19 {eq19} vs measured {got}");
            }
        }
        // The scheme layer gives the same for every warping rule.
        let s = scheme(&view, l, WarpRule::Lispsm, Partition::Faces, k).unwrap();
        prop_assert!((s.storage_factor() - zpw).abs() <= 1e-9 * zpw);
    }

    /// Lloyd 2006 Eq 21: light behind, θ = 45°: S̄ = 4 S̄_ZP+W,overhead + 1 =
    /// 4 k((f/n)^{1/k} − 1)/(2 tan 45°) + 1. For any other θ (square image) each side face is
    /// still an overhead frustum of half field of view 45° (module docs of `maps::faces`), so the
    /// measurement gives 4 k((f/n)^{1/k} − 1)/2 + 1 whatever θ.
    #[test]
    fn eq21_behind(
        (n, lr, th, k) in n_ln_alpha_theta_k(),
    ) {
        let alpha = lr.exp();
        let r = alpha.powf(1.0 / k as f64);
        let view45 = ViewFrustum::new(n, n * alpha, std::f64::consts::FRAC_PI_4).unwrap();
        let zpw_overhead_45 = k as f64 * (r - 1.0) / (2.0 * std::f64::consts::FRAC_PI_4.tan());
        let eq21 = 4.0 * zpw_overhead_45 + 1.0;
        let l = DVec3::NEG_Z;
        let got = measured_sum(&view45, l, FaceWarp::Lispsm, k);
        prop_assert!((got - eq21).abs() <= 1e-9 * eq21, "{got} vs Eq 21 {eq21}");
        let view = ViewFrustum::new(n, n * alpha, th).unwrap();
        let any_theta = 4.0 * k as f64 * (r - 1.0) / 2.0 + 1.0;
        let got = measured_sum(&view, l, FaceWarp::Lispsm, k);
        prop_assert!((got - any_theta).abs() <= 1e-9 * any_theta);
        // PSM per face (n′ = d_n) lies in the minimal range too.
        let got = measured_sum(&view, l, FaceWarp::Psm, k);
        prop_assert!((got - any_theta).abs() <= 1e-9 * any_theta);
    }
}

/// The near face from behind: a square seen face-on, S̄ = 1 exactly (the "+1" of Eq 21).
#[test]
fn near_face_from_behind_is_one() {
    let view = ViewFrustum::new(0.3, 30.0, 0.4).unwrap();
    let parts = face_partitions(&view, DVec3::NEG_Z, FaceWarp::Lispsm, 3).unwrap();
    let near: Vec<_> = parts.iter().filter(|p| p.face == Face::Near).collect();
    assert_eq!(near.len(), 1);
    assert!((near[0].storage_factor() - 1.0).abs() < 1e-12);
    assert_eq!(parts.len(), 4 * 3 + 1);
}

/// The face maximum is at the face's vertices: dense sampling of each face part finds no larger
/// error (Lloyd 2006 §4.4's claim, on faces), and points behind the face along the light have
/// smaller error than the face point they share a texel with.
#[test]
fn face_maxima_at_vertices() {
    let view = ViewFrustum::new(1.0, 200.0, 0.5).unwrap();
    for l in [
        DVec3::new(0.3, -0.4, -1.0),
        DVec3::new(-0.2, 0.5, 1.0),
        DVec3::new(0.9, -0.2, -0.3),
    ] {
        let l = l.normalize();
        let parts = face_partitions(&view, l, FaceWarp::Lispsm, 2).unwrap();
        for p in parts.iter() {
            let sm = ShadowMap::new(p.shadow.matrix(), l).unwrap();
            let [v0, v1, v2, v3] = p.vertices;
            for i in 0..=8 {
                for j in 0..=8 {
                    let (a, b) = (i as f64 / 8.0, j as f64 / 8.0);
                    let q = (v0 * (1.0 - a) + v1 * a) * (1.0 - b) + (v3 * (1.0 - a) + v2 * a) * b;
                    let e = point_error(&view, &sm, q, Resolutions::default()).unwrap();
                    assert!(e.mx <= p.error.max_mx * (1.0 + 1e-9));
                    assert!(e.mz <= p.error.max_mz * (1.0 + 1e-9));
                    // Deeper along the light ray (inside the frustum): smaller error.
                    let inward = if visible_faces(&view, l).unwrap().front {
                        1.0
                    } else {
                        -1.0
                    };
                    let deeper = q + inward * 0.05 * view.far() * l;
                    if view.contains(deeper, 0.0) && deeper.z < q.z {
                        let e2 = point_error(&view, &sm, deeper, Resolutions::default()).unwrap();
                        assert!(e2.mx <= e.mx * (1.0 + 1e-9) && e2.mz <= e.mz * (1.0 + 1e-9));
                    }
                }
            }
        }
    }
}

/// Seams of face partitions exist between z-parts of a face, between neighbouring faces, and
/// between the near face and the sides; from behind at θ = 45° neighbouring faces are mirror
/// images, so the error is continuous across their shared edges.
#[test]
fn face_seams() {
    let view = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_4).unwrap();
    let r = scheme(&view, DVec3::NEG_Z, WarpRule::Lispsm, Partition::Faces, 2).unwrap();
    assert_eq!(r.partitions().len(), 9);
    let s = seams(&view, &r).unwrap();
    // 4 faces × 1 z-seam, 4 neighbouring pairs × 2 parts, 4 near-face seams.
    assert_eq!(s.as_slice().len(), 4 + 8 + 4);
    for seam in s.as_slice() {
        let (ra, rb) = (r.partitions()[seam.a].region, r.partitions()[seam.b].region);
        assert!(seam.jump_mx >= 1.0 && seam.jump_mz >= 1.0);
        if let (Region::Face(fa), Region::Face(fb)) = (ra, rb) {
            if fa != fb && fa != Face::Near && fb != Face::Near {
                // Mirror-symmetric neighbours: m_x and m_z swap roles at most; their product
                // (the texel area over the pixel area) agrees.
                let pa = &r.partitions()[seam.a];
                let pb = &r.partitions()[seam.b];
                assert!((pa.storage_factor - pb.storage_factor).abs() < 1e-9 * pa.storage_factor);
            }
        }
    }
}

/// S̄ of a uniform map fitted to the far face, measured over the whole frustum with the ground
/// truth (each light ray crosses the far face and the near plane, so every corner is covered).
fn far_face_storage(view: &ViewFrustum, l: DVec3) -> f64 {
    use shadow_aliasing::maps::{fit_warp, light_space};
    use shadow_aliasing::NPrime;
    let ls = light_space(l, DVec3::Y).unwrap();
    let far = Face::Far.vertices(view, view.near(), view.far());
    let mut pts = far.to_vec();
    for v in far {
        pts.push(v + 3.0 * view.far() * l);
        pts.push(v - 3.0 * view.far() * l);
    }
    let m = fit_warp(&pts, &ls, NPrime::UNWARPED).unwrap();
    let sm = ShadowMap::new(m, l).unwrap();
    let (mut mx, mut mz) = (0.0f64, 0.0f64);
    for c in view.corners() {
        let e = point_error(view, &sm, c, Resolutions::default()).unwrap();
        mx = mx.max(e.mx);
        mz = mz.max(e.mz);
    }
    mx * mz
}

/// Errata (docs/errata.md, Lloyd 2006 §5.1 and Lloyd 2005 §4.1): which faces. With y toward the
/// light, v·y < 0 is the light travelling along the view; the front faces (four sides and the
/// near face) give Eq 21; reading y as the direction light travels swaps the choice to the back
/// faces, the far face alone, whose uniform map has S̄ = (f/n)². Lloyd 2005's "4 sides and the
/// near (or far) plane" likewise: the far plane is never the right face, from the front the back
/// faces (sides and near) give the same S̄ as from behind.
#[test]
fn errata_face_choice_never_the_far_face() {
    let view = ViewFrustum::new(1.0, 1000.0, std::f64::consts::FRAC_PI_4).unwrap();
    let eq21 = 4.0 * 999.0 / 2.0 + 1.0;
    for l in [DVec3::NEG_Z, DVec3::Z] {
        let crate_choice = face_partitions(&view, l, FaceWarp::Lispsm, 1)
            .unwrap()
            .storage_factor();
        assert!((crate_choice - eq21).abs() < 1e-9 * eq21, "{crate_choice}");
        let far = far_face_storage(&view, l);
        assert!((far - 1e6).abs() < 1e-6 * 1e6, "far face {far}");
    }
}

/// Errata (docs/errata.md, Lloyd 2006 §5.1): "the bisector of the projected edge vectors
/// e′₀ + e′₁". The projected edges differ in length once the light is tilted sideways, and their
/// sum is then not the bisector: at f/n = 100, θ = 30°, light at elevation 15°, azimuth 165°
/// the sum gives Σ S̄ = 2359.6 and the unit-vector bisector 287.05; at elevation 3°, azimuth 25°
/// the sum leaves a vertex of a face behind the projected eye and no warp fits at all. Over a
/// 30 × 72 grid of the hemisphere (elevation 3i°, i = 0…29, horizon in and zenith out; azimuth
/// 5j°, j = 0…71) the sum fails at 112 directions and is worse than the unit-vector bisector by
/// more than 10⁻⁹ at 2022 of the other 2048 (2023 counting a rounding-level difference; 3 ties,
/// 22 where it is better); the unit-vector bisector fits everywhere. The crate's
/// `face_partitions` keeps, per face part, the better of ê′₀ + ê′₁ and the face's depth axis
/// (`face_depth_axis`), so it is never above the unit-vector value (185.73 here).
#[test]
fn errata_s5_1_bisector_of_unit_vectors() {
    use shadow_aliasing::scheme::sweep::light_dir_from_angles;
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians()).unwrap();
    let l = light_dir_from_angles(15f64.to_radians(), 165f64.to_radians());
    let unit = faces_with_axis(&view, l, true).unwrap();
    let raw = faces_with_axis(&view, l, false).unwrap();
    let built = face_partitions(&view, l, FaceWarp::Lispsm, 1)
        .unwrap()
        .storage_factor();
    assert!(built <= unit * (1.0 + 1e-12), "{built} vs {unit}");
    assert!((built - 185.73).abs() < 1e-2, "{built}");
    assert!((unit - 287.05).abs() < 1e-2, "{unit}");
    assert!((raw - 2359.6).abs() < 0.1, "{raw}");
    let l = light_dir_from_angles(3f64.to_radians(), 25f64.to_radians());
    assert!(faces_with_axis(&view, l, false).is_none());
    assert!(faces_with_axis(&view, l, true).is_some());
    let (mut fails, mut worse, mut worse_at_all, mut ties, mut better) = (0, 0, 0, 0, 0);
    for i in 0..30 {
        for j in 0..72 {
            let (el, az) = (f64::from(3 * i).to_radians(), f64::from(5 * j).to_radians());
            let l = light_dir_from_angles(el, az);
            let unit = faces_with_axis(&view, l, true).unwrap_or_else(|| panic!("({i}, {j})"));
            let Some(raw) = faces_with_axis(&view, l, false) else {
                fails += 1;
                continue;
            };
            worse += usize::from(raw > unit * (1.0 + 1e-9));
            worse_at_all += usize::from(raw > unit);
            ties += usize::from(raw == unit);
            better += usize::from(raw < unit);
        }
    }
    assert_eq!(fails, 112);
    assert_eq!(fails + worse_at_all + ties + better, 30 * 72);
    assert_eq!((worse, worse_at_all, ties, better), (2022, 2023, 3, 22));
}

/// Errata (docs/errata.md, Lloyd 2006 §5.1, "the face's n′ is not stated"). From behind at
/// θ = 30°, f/n = 1000, warping each side face with the view frustum's own n′ = n + √(f n) =
/// 32.62 instead of the face's d_n + √(d_n d_f) = tan θ (n + √(f n)) = 18.83 puts it above the face's minimal
/// range: by Eq 12 for the face (an overhead frustum with half field of view 45°, near n tan θ,
/// far f tan θ) each face then costs 499.5 · n′² d_f/(d_n (n′ + d_f − d_n)²) = 1431.5 instead of
/// 499.5, Σ S̄ = 5727 instead of 1999.
#[test]
fn errata_s5_1_face_n_prime_is_the_faces_own() {
    use shadow_aliasing::maps::{fit_warp, light_space};
    use shadow_aliasing::measure::vertex::vertex_max;
    use shadow_aliasing::NPrime;
    let (n, f, th) = (1.0f64, 1000.0f64, 30f64.to_radians());
    let view = ViewFrustum::new(n, f, th).unwrap();
    let l = DVec3::NEG_Z;
    let t = th.tan();
    let (dn, df) = (n * t, f * t);
    let n_view = n + (f * n).sqrt();
    let per_face = (f / n - 1.0) / 2.0 * n_view * n_view * df / (dn * (n_view + df - dn).powi(2));
    assert!((per_face - 1431.5).abs() < 0.1, "{per_face}");
    let mut total = 1.0; // the near face
    for face in [Face::Bottom, Face::Right, Face::Top, Face::Left] {
        let v = face.vertices(&view, n, f);
        let ls = light_space(l, face_axis(&view, face, l).unwrap()).unwrap();
        let mut pts = v.to_vec();
        for q in v {
            pts.push(q + 3.0 * f * l);
            pts.push(q - 3.0 * f * l);
        }
        let m = fit_warp(&pts, &ls, NPrime::finite(n_view).unwrap()).unwrap();
        let e = vertex_max(&m, l, t, &v).unwrap().storage_factor;
        assert!(
            (e - per_face).abs() < 1e-9 * per_face,
            "{face:?}: {e} vs {per_face}"
        );
        total += e;
    }
    assert!((total - (4.0 * per_face + 1.0)).abs() < 1e-6 * total);
    assert!((total - 5727.0).abs() < 1.0, "{total}");
    let crate_choice = face_partitions(&view, l, FaceWarp::Lispsm, 1)
        .unwrap()
        .storage_factor();
    assert!((crate_choice - 1999.0).abs() < 1e-9 * 1999.0);
}

/// A light along a side edge of the frustum (from behind, along the ray through the +x+y corner):
/// the two faces sharing that edge are edge-on and skipped, the others cover the frustum.
#[test]
fn light_along_a_side_edge() {
    let view = ViewFrustum::new(0.5, 50.0, 0.6).unwrap();
    let t = view.tan_half_fov();
    let l = DVec3::new(t, t, -1.0).normalize();
    let vis = visible_faces(&view, l).unwrap();
    assert_eq!(vis.faces(), &[Face::Bottom, Face::Left, Face::Near]);
    let parts = face_partitions(&view, l, FaceWarp::Lispsm, 3).unwrap();
    assert_eq!(parts.len(), 2 * 3 + 1);
    for (i, (a, b, c)) in [
        (0.1, 0.9, 0.95),
        (0.5, -0.3, 0.2),
        (0.99, 0.99, 0.99),
        (0.0, -0.9, 0.9),
    ]
    .into_iter()
    .enumerate()
    {
        let z: f64 = 0.5 * 100f64.powf(a);
        let p = DVec3::new(b * z * t, c * z * t, -z);
        let inside = parts.iter().any(|part| {
            clip(&part.shadow.matrix(), p).is_some_and(|q| q.abs().max_element() <= 1.0 + 1e-9)
        });
        assert!(inside, "point {i} {p}");
    }
    assert!(parts.storage_factor().is_finite());
}

/// No jump where the choice switches between front and back faces (v·y = 0, the light
/// perpendicular to the view) nor where faces appear edge-on: Σ S̄ is continuous and, by the
/// frustum's symmetry, even in the tilt (f/n = 100, θ = 0.5, k = 2: 16.4744 overhead).
#[test]
fn storage_is_continuous_through_the_face_switch() {
    let view = ViewFrustum::new(1.0, 100.0, 0.5).unwrap();
    let s = |l: DVec3| {
        face_partitions(&view, l, FaceWarp::Lispsm, 2)
            .unwrap()
            .storage_factor()
    };
    let at0 = s(DVec3::NEG_Y);
    for e in [1e-8, 1e-6, 2e-6, 1e-5] {
        let behind = s(DVec3::new(0.0, -1.0, -e));
        let front = s(DVec3::new(0.0, -1.0, e));
        assert!(
            (behind - front).abs() < 1e-9 * at0,
            "{e}: {behind} vs {front}"
        );
        assert!(
            (behind - at0).abs() < 10.0 * e * at0,
            "{e}: {behind} vs {at0}"
        );
        let left = s(DVec3::new(-e, -1.0, -0.3));
        let right = s(DVec3::new(e, -1.0, -0.3));
        assert!((left - right).abs() < 1e-9 * left);
    }
}

/// Σ S̄ of FP+ZP+W (LiSPSM per face part, k self-similar z-partitions per side face) for the light
/// at sweep angles `(el, az)` (radians, `measure::sweep` convention: D = (cos el sin az, sin el,
/// cos el cos az) towards the source, light travelling −D); el is clamped to the hemisphere.
fn fp_storage(view: &ViewFrustum, k: usize, el: f64, az: f64) -> f64 {
    use shadow_aliasing::scheme::sweep::light_dir_from_angles;
    let el = el.clamp(0.0, std::f64::consts::FRAC_PI_2);
    face_partitions(view, light_dir_from_angles(el, az), FaceWarp::Lispsm, k)
        .unwrap_or_else(|e| panic!("el {el}, az {az}: {e}"))
        .storage_factor()
}

/// Nelder–Mead maximisation of `f` over (el, az) from `x0` with an initial simplex of edge `h`:
/// the largest value seen and where.
fn nelder_mead_max(
    f: &dyn Fn(f64, f64) -> f64,
    x0: [f64; 2],
    h: f64,
    iters: usize,
) -> (f64, [f64; 2]) {
    let g = |p: [f64; 2]| -f(p[0], p[1]);
    let mut p = [x0, [x0[0] + h, x0[1]], [x0[0], x0[1] + h]];
    let mut v = p.map(g);
    for _ in 0..iters {
        let mut idx = [0, 1, 2];
        idx.sort_by(|&a, &b| v[a].total_cmp(&v[b]));
        let [b, m, w] = idx;
        let c = [(p[b][0] + p[m][0]) / 2.0, (p[b][1] + p[m][1]) / 2.0];
        let at = |t: f64| [c[0] + t * (p[w][0] - c[0]), c[1] + t * (p[w][1] - c[1])];
        let r = at(-1.0);
        let vr = g(r);
        if vr < v[b] {
            let e = at(-2.0);
            let ve = g(e);
            (p[w], v[w]) = if ve < vr { (e, ve) } else { (r, vr) };
        } else if vr < v[m] {
            (p[w], v[w]) = (r, vr);
        } else {
            let cc = at(0.5);
            let vc = g(cc);
            if vc < v[w] {
                (p[w], v[w]) = (cc, vc);
            } else {
                for i in [m, w] {
                    p[i] = [(p[i][0] + p[b][0]) / 2.0, (p[i][1] + p[b][1]) / 2.0];
                    v[i] = g(p[i]);
                }
            }
        }
    }
    let i = (0..3).min_by(|&a, &b| v[a].total_cmp(&v[b])).unwrap();
    (
        -v[i],
        [p[i][0].clamp(0.0, std::f64::consts::FRAC_PI_2), p[i][1]],
    )
}

/// The worst Σ S̄ of FP+ZP+W over the hemisphere: a grid of `step_deg` in elevation (both ends)
/// and azimuth, then Nelder–Mead from the `starts` largest grid values (and from their
/// neighbourhood, the simplex spanning half a grid step). Returns (S̄, el, az).
fn worst_case(view: &ViewFrustum, k: usize, step_deg: f64, starts: usize) -> (f64, f64, f64) {
    worst_case_of(&|el, az| fp_storage(view, k, el, az), step_deg, starts).1
}

/// `worst_case` of any `f(el, az)`: the grid's largest value and the largest Nelder–Mead found
/// from it, each as (value, el, az).
fn worst_case_of(
    f: &dyn Fn(f64, f64) -> f64,
    step_deg: f64,
    starts: usize,
) -> ((f64, f64, f64), (f64, f64, f64)) {
    let (ne, na) = (
        (90.0 / step_deg).round() as usize,
        (360.0 / step_deg).round() as usize,
    );
    let mut grid = Vec::with_capacity((ne + 1) * na);
    for i in 0..=ne {
        for j in 0..na {
            let (el, az) = (
                (i as f64 * step_deg).to_radians(),
                (j as f64 * step_deg).to_radians(),
            );
            grid.push((f(el, az), el, az));
        }
    }
    grid.sort_by(|a, b| b.0.total_cmp(&a.0));
    let mut best = grid[0];
    for &(_, el, az) in grid.iter().take(starts) {
        let (v, [e, a]) = nelder_mead_max(f, [el, az], (0.5 * step_deg).to_radians(), 120);
        if v > best.0 {
            best = (v, e, a);
        }
    }
    (grid[0], best)
}

/// The light-behind value of FP+ZP+W (module docs of `maps::faces`, Eq 21 for any θ):
/// 4 k((f/n)^{1/k} − 1)/2 + 1.
fn behind_closed_form(alpha: f64, k: usize) -> f64 {
    2.0 * k as f64 * (alpha.powf(1.0 / k as f64) - 1.0) + 1.0
}

/// The worst case over the hemisphere that docs/partitions.md and docs/errata.md (Lloyd 2006 §5.3,
/// #17) state, per (f/n, θ in degrees): the smallest and largest worst/behind ratio over
/// k = 1..8 and half a unit of the last digit they print. At θ ≥ 30° the light behind (or in
/// front) is the worst direction, 1.000×; at θ = 10° the ratio grows from 2.19 (k = 1) to 2.32
/// (k = 8).
const DOCUMENTED_WORST: [(f64, f64, f64, f64, f64); 5] = [
    (1000.0, 30.0, 1.000, 1.000, 5e-4),
    (100.0, 45.0, 1.000, 1.000, 5e-4),
    (1e4, 60.0, 1.000, 1.000, 5e-4),
    (1e6, 30.0, 1.000, 1.000, 5e-4),
    (1000.0, 10.0, 2.19, 2.32, 5e-3),
];

/// docs/partitions.md's table, f/n = 1000, θ = 30°: the worst Σ S̄ (= the light-behind value) for
/// k = 1..8, to the digits printed.
const DOCUMENTED_WORST_1000_30: [f64; 8] =
    [1999.0, 123.49, 55.00, 37.99, 30.81, 26.95, 24.56, 22.94];

/// Searches the worst Σ S̄ of FP+ZP+W (`worst_case`, a `step_deg` grid and Nelder–Mead from its
/// `starts` largest values) for k = 1..8 at each `(f/n, θ°, smallest, largest ratio, tolerance)`
/// of `cases` and asserts the ratios to the light-behind value the docs print: the smallest and
/// largest over k each to the tolerance, none above the largest, and at f/n = 1000, θ = 30° the
/// worst S̄ of the table. Prints what it measures.
fn assert_documented_worst(cases: &[(f64, f64, f64, f64, f64)], step_deg: f64, starts: usize) {
    for &(alpha, deg, lo, hi, tol) in cases {
        let view = ViewFrustum::new(1.0, alpha, deg.to_radians()).unwrap();
        let (mut min, mut max) = (f64::INFINITY, 0.0f64);
        for k in 1..=8 {
            let behind = fp_storage(&view, k, 0.0, 0.0);
            let expect = behind_closed_form(alpha, k);
            assert!((behind - expect).abs() < 1e-9 * expect, "k = {k}: {behind}");
            let (worst, el, az) = worst_case(&view, k, step_deg, starts);
            let ratio = worst / behind;
            let at = format!(
                "f/n {alpha}, θ {deg}°, k {k}: worst {worst:.4} at ({:.3}°, {:.3}°), {ratio:.4} × behind {behind:.4}",
                el.to_degrees(),
                az.to_degrees()
            );
            println!("{at}");
            assert!(ratio >= 1.0 - 1e-12 && ratio < hi + tol, "{at}");
            if (alpha, deg) == (1000.0, 30.0) {
                let table = DOCUMENTED_WORST_1000_30[k - 1];
                assert!((worst - table).abs() < 0.005, "{at}: table {table}");
            }
            (min, max) = (min.min(ratio), max.max(ratio));
        }
        assert!(
            (min - lo).abs() < tol && (max - hi).abs() < tol,
            "f/n {alpha}, θ {deg}°: {min}–{max}"
        );
    }
}

/// Lloyd 2006 §5.3: "the worst case S̄ was within a factor of 2–3" of the light-behind value. With
/// Lloyd's bisector alone a face seen nearly edge-on next to a side edge along the light (source
/// at elevation 26.565°, azimuth 150°, f/n = 1000, θ = 30°) had its vertices on the near-parallel
/// edge collapse onto the projected eye: d_n → 0, n′ → 0, and Σ S̄ reached 19072 (k = 1, 9.5×),
/// 4835 (k = 4, 127×), 6241 (k = 8, 272×) in a sliver a 1° grid misses
/// (`errata_s5_3_bisector_alone_worst_case`). With the face's depth axis among the
/// candidates the worst case over the hemisphere is the light-behind (or in-front) value itself,
/// 1.000×, for every k = 1..8 at f/n = 1000, θ = 30° and the other wide fields of view of
/// `DOCUMENTED_WORST`, and 2.19× to 2.32× at θ = 10°. Checked here with a reduced search (a 10°
/// grid, Nelder–Mead from its two largest values; a few seconds unoptimised), which finds the
/// same as `worst_case_within_3x_of_behind_exhaustive`.
#[test]
fn worst_case_within_3x_of_behind() {
    assert_documented_worst(&DOCUMENTED_WORST, 10.0, 2);
}

/// Σ S̄ of FP+ZP+W with Lloyd's bisector alone, the construction before the depth axis: every side
/// face part warped along ê′₀ + ê′₁ (`face_axis`, errata #13's unit-vector bisector) with
/// n′ = d_n + √(d_n d_f) from its extent along it, no second candidate; the faces
/// (`visible_faces`) and the near face's map as `face_partitions` chooses them. Light at sweep
/// angles (el, az), el clamped to the hemisphere as in `fp_storage`. Panics where the construction
/// gives no map.
fn bisector_storage(view: &ViewFrustum, k: usize, el: f64, az: f64) -> f64 {
    use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
    use shadow_aliasing::maps::{fit_warp, light_space};
    use shadow_aliasing::measure::vertex::vertex_max;
    use shadow_aliasing::scheme::sweep::light_dir_from_angles;
    use shadow_aliasing::NPrime;
    let el = el.clamp(0.0, std::f64::consts::FRAC_PI_2);
    let l = light_dir_from_angles(el, az);
    let splits = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar).unwrap();
    let mut total = 0.0;
    for &face in visible_faces(view, l).unwrap().faces() {
        if face.side_edges(view).is_none() {
            let built = face_partitions(view, l, FaceWarp::Lispsm, 1).unwrap();
            total += built
                .iter()
                .find(|p| p.face == face)
                .unwrap()
                .storage_factor();
            continue;
        }
        let axis = face_axis(view, face, l).unwrap_or_else(|e| panic!("el {el}, az {az}: {e}"));
        let ls = light_space(l, axis).unwrap();
        for j in 0..k {
            let (a, b) = splits.range(j);
            let v = face.vertices(view, a, b);
            let (mut dn, mut df) = (f64::INFINITY, f64::NEG_INFINITY);
            for q in v {
                dn = dn.min(ls.z.dot(q));
                df = df.max(ls.z.dot(q));
            }
            let mut pts = v.to_vec();
            for q in v {
                pts.push(q + 3.0 * view.far() * l);
                pts.push(q - 3.0 * view.far() * l);
            }
            let m = fit_warp(&pts, &ls, NPrime::finite(dn + (dn * df).sqrt()).unwrap()).unwrap();
            total += vertex_max(&m, l, view.tan_half_fov(), &v)
                .unwrap_or_else(|| panic!("el {el}, az {az}: {face:?} part {j} singular"))
                .storage_factor;
        }
    }
    total
}

/// Errata (docs/errata.md, Lloyd 2006 §5.3 "within a factor of 2–3", #17): with Lloyd's bisector
/// alone (`bisector_storage`; f/n = 1000, θ = 30°) Nelder–Mead from the four largest values of a
/// 1° grid finds 19072 (9.5×) at k = 1, 4835 (127×) at k = 4, 6241 (272×) at k = 8, at elevation
/// 26.565° and azimuth 30°, 150°, 210° or 330° (the sliver next to a side edge, cut off where the
/// nearly edge-on face is skipped); 0.005° below the edge, at (26.560°, 150°), it is 404.4 (k = 4)
/// and 491.6 (k = 8); the 1° grid itself shows only 1.64×, 2.69× and 4.07×, at elevation 26° and
/// azimuth 29°, 151°, 209° or 331°. The crate's `face_partitions` (depth axis among the
/// candidates) stays at or below the light-behind value at each of these worst directions.
#[test]
fn errata_s5_3_bisector_alone_worst_case() {
    use shadow_aliasing::scheme::sweep::light_dir_from_angles;
    let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap();
    // At k = 1 the construction is the unit-vector bisector of errata #13.
    for (el, az) in [(15.0, 165.0), (26.0, 209.0), (40.0, 10.0)] {
        let (el, az) = (f64::to_radians(el), f64::to_radians(az));
        let own = bisector_storage(&view, 1, el, az);
        let unit = faces_with_axis(&view, light_dir_from_angles(el, az), true).unwrap();
        assert!((own - unit).abs() < 1e-9 * unit, "{own} vs {unit}");
    }
    let near = |x: f64, targets: &[f64], tol: f64| targets.iter().any(|t| (x - t).abs() < tol);
    // (k, worst found, its ratio to behind and half a unit of its last printed digit, the 1° grid's
    // largest ratio)
    for (k, worst, ratio, digit, grid_ratio) in [
        (1, 19072.0, 9.5, 0.05, 1.64),
        (4, 4835.0, 127.0, 0.5, 2.69),
        (8, 6241.0, 272.0, 0.5, 4.07),
    ] {
        let behind = behind_closed_form(1000.0, k);
        assert!((bisector_storage(&view, k, 0.0, 0.0) - behind).abs() < 1e-9 * behind);
        let f = |el: f64, az: f64| bisector_storage(&view, k, el, az);
        let ((g, g_el, g_az), (v, el, az)) = worst_case_of(&f, 1.0, 4);
        let (el_deg, az_deg) = (el.to_degrees(), az.to_degrees().rem_euclid(360.0));
        let at = format!("k = {k}: {v} at ({el_deg}°, {az_deg}°), grid {g} at ({g_el}, {g_az})");
        assert!((v - worst).abs() < 0.5, "{at}");
        assert!((v / behind - ratio).abs() < digit, "{at}");
        assert!((el_deg - 26.565).abs() < 1e-3, "{at}");
        assert!(near(az_deg, &[30.0, 150.0, 210.0, 330.0], 1e-3), "{at}");
        assert!((g / behind - grid_ratio).abs() < 0.005, "{at}");
        assert!((g_el.to_degrees() - 26.0).abs() < 1e-9, "{at}");
        let g_az = g_az.to_degrees();
        assert!(near(g_az, &[29.0, 151.0, 209.0, 331.0], 1e-9), "{at}");
        let fixed = fp_storage(&view, k, el, az);
        assert!(fixed <= behind * (1.0 + 1e-9), "{at}: crate {fixed}");
    }
    for (k, expect) in [(4, 404.4), (8, 491.6)] {
        let s = bisector_storage(&view, k, 26.56f64.to_radians(), 150f64.to_radians());
        assert!((s - expect).abs() < 0.05, "k = {k}: {s}");
    }
}

/// A light approaching a side edge of the frustum (here the +x+y edge, shared by the right and
/// top faces, from the far end: f/n = 1000, θ = 30°, the elevation 26.565°, azimuth
/// 150°). The two faces turn edge-on and their prisms vanish, so Σ S̄ must tend to its value with
/// the light on the edge, where both are skipped; each of them seen at an angle δ off the edge has
/// its depth axis coordinate z h with h ∝ δ (the projected eye's distance from the projected near
/// edge), which scales its maps' t range by δ: m_z ∝ δ, m_x unchanged, so its S̄ ∝ δ.
/// With Lloyd's bisector alone the vertices on the edge collapse onto the projected eye instead,
/// d_n → 0, and Σ S̄ grew as δ^(−1/2) until `EDGE_ON` cut it off: k = 4, 117 at δ = 10⁻², 1761 at
/// δ = 10⁻⁵, 38.6 on the edge.
#[test]
fn no_jump_at_a_side_edge() {
    let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap();
    let t = view.tan_half_fov();
    let edge = DVec3::new(t, t, -1.0).normalize();
    for k in [1, 4, 8] {
        let on_edge = face_partitions(&view, -edge, FaceWarp::Lispsm, k).unwrap();
        assert_eq!(
            on_edge.faces.faces(),
            &[Face::Bottom, Face::Left, Face::Near]
        );
        let s0 = on_edge.storage_factor();
        let mut seen = 0;
        for deg in (0..360).step_by(15) {
            let a = f64::from(deg).to_radians();
            let u = DVec3::new(a.cos(), a.sin(), 0.0);
            let u = (u - u.dot(edge) * edge).normalize();
            let thin = |d: f64| {
                let p = face_partitions(&view, -(edge + d * u).normalize(), FaceWarp::Lispsm, k)
                    .unwrap();
                let edge_on: f64 = p
                    .iter()
                    .filter(|q| matches!(q.face, Face::Right | Face::Top))
                    .map(|q| q.storage_factor())
                    .sum();
                (p.storage_factor(), edge_on)
            };
            for d in [1e-2, 1e-3, 1e-4, 1e-5] {
                let (s, _) = thin(d);
                assert!(
                    (s - s0).abs() <= 5.0 * d * s0,
                    "k {k}, {deg}°, δ {d}: {s} vs {s0}"
                );
            }
            let (_, e3) = thin(1e-3);
            let (_, e4) = thin(1e-4);
            if e3 > 0.0 {
                assert!((e3 / e4 - 10.0).abs() < 0.1, "k {k}, {deg}°: {e3} / {e4}");
                seen += 1;
            }
        }
        // Off the edge on the light's side of either face plane, one or both faces are seen.
        assert!(seen >= 12, "{seen}");
        // The direction, 0.005° below the edge: 404.4 (k = 4) and 491.6 (k = 8) before.
        use shadow_aliasing::scheme::sweep::light_dir_from_angles;
        let l = light_dir_from_angles(26.56f64.to_radians(), 150f64.to_radians());
        let s = face_partitions(&view, l, FaceWarp::Lispsm, k)
            .unwrap()
            .storage_factor();
        assert!((s - s0).abs() <= 1e-3 * s0, "k {k}: {s} vs {s0}");
    }
}

/// Half FOV near π/2: the frustum is a slab much wider than deep and every face's |N·L| is
/// tiny for an overhead light (the bottom face's is cos θ), so the absolute `EDGE_ON` skipped all
/// faces once tan θ > 10⁶ and `face_partitions` returned zero maps with Σ S̄ = 0. The bottom face
/// is then the whole footprint (half the silhouette), so it is kept, and overhead the result is
/// Lloyd 2006 Eq 19, k((f/n)^{1/k} − 1)/(2 tan θ); every other light gives maps or, beyond what
/// f64 can fit, a typed error — never an empty success.
#[test]
fn half_fov_near_a_right_angle_gives_maps_or_a_typed_error() {
    use shadow_aliasing::Error;
    let k = 3;
    for eps in [1e-3, 1e-6, 1e-7, 1e-9, 1e-12] {
        let th = std::f64::consts::FRAC_PI_2 - eps;
        let view = ViewFrustum::new(1.0, 100.0, th).unwrap();
        let eq19 = k as f64 * (100f64.powf(1.0 / k as f64) - 1.0) / (2.0 * th.tan());
        for l in [
            DVec3::NEG_Y,
            DVec3::X,
            DVec3::NEG_Z,
            DVec3::Z,
            DVec3::new(0.3, -0.8, -0.5),
            DVec3::new(0.0, -1.0, 1e-3),
            DVec3::new(-0.2, -0.9, 0.1),
        ] {
            match face_partitions(&view, l, FaceWarp::Lispsm, k) {
                Ok(p) => {
                    assert!(!p.is_empty(), "{eps:e}, {l}");
                    let s = p.storage_factor();
                    assert!(s.is_finite() && s > 0.0, "{eps:e}, {l}: {s}");
                    if l == DVec3::NEG_Y || l == DVec3::X {
                        assert_eq!(p.len(), k, "{eps:e}, {l}");
                        assert!(
                            (s - eq19).abs() < 1e-6 * eq19,
                            "{eps:e}, {l}: {s} vs {eq19}"
                        );
                    }
                }
                Err(Error::Degenerate(_)) => assert!(eps < 1e-9, "{eps:e}, {l}"),
                Err(e) => panic!("{eps:e}, {l}: {e}"),
            }
        }
    }
}

/// The exhaustive variant of `worst_case_within_3x_of_behind`: a 2° grid and Nelder–Mead from
/// its 12 largest values, k = 1..8, for the same (f/n, θ) and documented ratios, and the narrower
/// fields of view docs/partitions.md quotes (largest ratio over k): 2.75 at θ = 8°, 3.06 at 7°,
/// 4.1 at 5°, 10 at 2° (f/n = 1000). About 75 s unoptimised; run it with
/// `cargo test --locked --all-features --test faces worst_case_within_3x_of_behind_exhaustive -- --ignored --nocapture`.
#[test]
#[ignore = "exhaustive: about 75 s in a debug build"]
fn worst_case_within_3x_of_behind_exhaustive() {
    assert_documented_worst(&DOCUMENTED_WORST, 2.0, 12);
    // (θ°, the largest ratio as printed, half a unit of its last digit)
    for (deg, hi, digit) in [
        (8.0, 2.75, 0.005),
        (7.0, 3.06, 0.005),
        (5.0, 4.1, 0.05),
        (2.0, 10.0, 0.5),
    ] {
        let view = ViewFrustum::new(1.0, 1000.0, f64::to_radians(deg)).unwrap();
        let max = (1..=8)
            .map(|k| worst_case(&view, k, 2.0, 12).0 / behind_closed_form(1000.0, k))
            .fold(0.0, f64::max);
        println!("f/n 1000, θ {deg}°: largest worst/behind over k = 1..8 {max:.4}");
        assert!((max - hi).abs() < digit, "θ {deg}°: {max} vs {hi}");
    }
}

/// Where 3× cannot hold: overhead, the light sees the bottom face alone, whose best warp per
/// z-partition is Lloyd 2006 Eq 19 (= Eq 18, the minimal range of Eq 12), k((f/n)^{1/k} − 1)/(2 tan θ),
/// while behind Eq 21 gives 2k((f/n)^{1/k} − 1) + 1 for any θ. Their ratio tends to 1/(4 tan θ)
/// as f/n grows, above 3 once tan θ < 1/12 (θ < 4.76°), for any face scheme that keeps Lloyd's
/// optimal maps behind. At θ = 4°, f/n = 1000 the measured ratio is 3.57 (k = 1) to 3.42 (k = 8).
#[test]
fn narrow_fov_overhead_alone_exceeds_3x_behind() {
    let (alpha, th) = (1000.0f64, 4f64.to_radians());
    let view = ViewFrustum::new(1.0, alpha, th).unwrap();
    for k in 1..=8 {
        let r = alpha.powf(1.0 / k as f64);
        let eq19 = k as f64 * (r - 1.0) / (2.0 * th.tan());
        let behind = behind_closed_form(alpha, k);
        let over = fp_storage(&view, k, std::f64::consts::FRAC_PI_2, 0.0);
        let back = fp_storage(&view, k, 0.0, 0.0);
        assert!((over - eq19).abs() < 1e-9 * eq19, "k {k}: {over} vs {eq19}");
        assert!(
            (back - behind).abs() < 1e-9 * behind,
            "k {k}: {back} vs {behind}"
        );
        assert!(over / back > 3.0, "k {k}: {}", over / back);
    }
}
