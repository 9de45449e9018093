//! Culling volumes per map (issue 23, item 4), against tests written independently of the frame:
//! a Cyrus–Beck ray test on the slice's and the receivers' box's own planes decides which caster
//! points can shadow B, and the volumes must hold every such point (and B), and no point whose
//! ray misses B grown by a margin; the receivers' volume is the slice ∩ the box, decided by their
//! planes; by hand, a box off to the side, one under the ground and one above every caster (with
//! and without depth clamp) are culled or kept as the scene says.

use glam::{DMat4, DVec3, DVec4};
use proptest::prelude::*;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame, Bound, Camera, CascadeSplits, FrameInput, FrameScheme, MAX_CULL_PLANES,
};
use shadow_aliasing::maps::faces::FaceWarp;
use shadow_aliasing::maps::{TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::Error;

mod common;
use common::scene::{
    aabb, box_planes_eye, frustum_planes, random_scene, ray_meets, scene_params, shadowing_points,
};

/// `planes` pushed outward by `d` (any normal length).
fn grown(planes: &[DVec4], d: f64) -> Vec<DVec4> {
    planes
        .iter()
        .map(|p| *p - DVec4::new(0.0, 0.0, 0.0, d * p.truncate().length()))
        .collect()
}

/// Whether `p` is inside every plane by at least `margin` (`margin < 0`: outside one by more).
fn inside_by(planes: &[DVec4], p: DVec3, margin: f64) -> bool {
    planes
        .iter()
        .all(|pl| pl.truncate().dot(p) + pl.w <= -margin * pl.truncate().length())
}

fn schemes(i: usize) -> FrameScheme<'static> {
    match i {
        0 => FrameScheme::Single(WarpRule::Lispsm),
        1 => FrameScheme::Single(WarpRule::Uniform),
        2 => FrameScheme::Single(WarpRule::Psm),
        3 => FrameScheme::Single(WarpRule::Minimax),
        4 => FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::SelfSimilar,
                k: 3,
                overlap: 0.1,
            },
            rule: WarpRule::Lispsm,
        },
        5 => FrameScheme::Stable(CascadeSplits::Scheme {
            scheme: SplitScheme::Practical { lambda: 0.7 },
            k: 3,
            overlap: 0.0,
        }),
        _ => FrameScheme::Faces {
            rule: FaceWarp::Lispsm,
            k: 2,
        },
    }
}

proptest! {
    #![proptest_config(common::config(192))]

    /// Random cameras, lights, receivers and casters, every scheme, with and without depth clamp.
    /// Casters' volume: B's vertices and every sampled caster point whose ray along the light
    /// meets B (Cyrus–Beck on the slice's and the box's planes) inside; every sampled point whose
    /// ray misses B grown by 10⁻⁶ of the frustum's far distance outside; a caster box with a
    /// point inside is never culled. Receivers' volume: B's vertices inside; the sampled points
    /// 10⁻⁶ inside the slice and the box inside, those 10⁻⁶ outside one of their planes outside.
    /// (Face partitions' B_i is also cut by its face part's prism, which the test does not
    /// rebuild: there only B's vertices are checked.)
    #[test]
    fn volumes_hold_what_can_shadow_the_body_and_nothing_else(
        params in scene_params(),
        scheme_i in 0usize..7,
        clamp in any::<bool>(),
        samples in prop::collection::vec(prop::array::uniform3(0.0f64..1.0), 120),
    ) {
        let Some(sc) = random_scene(&params) else {
            return Ok(());
        };
        let (view, cam) = (sc.view, sc.camera);
        let (r, c) = ([sc.receivers], [sc.casters]);
        let input = FrameInput::new(cam, sc.light, 1024, 1024)
            .receivers(Bound::Boxes(&r))
            .casters(Bound::Boxes(&c))
            .depth_clamp(clamp)
            .scheme(schemes(scheme_i));
        let Ok(f) = frame(&input) else {
            return Ok(());
        };
        let e2w = view.inverse();
        let le = f.light_dir_eye();
        let vf = *cam.view();
        let scale = vf.far();
        for m in f.maps().iter() {
            let (cv, rv) = (m.casters_volume(), m.receivers_volume());
            prop_assert!(!cv.planes().is_empty() && cv.planes().len() <= MAX_CULL_PLANES);
            for p in cv.planes().iter().chain(rv.planes()) {
                prop_assert!(p.is_finite() && (p.truncate().length() - 1.0).abs() < 1e-9, "{p}");
            }
            for v in m.body() {
                let w = e2w.transform_point3(*v);
                prop_assert!(cv.contains(w), "B vertex {w} outside the casters' volume");
                prop_assert!(rv.contains(w), "B vertex {w} outside the receivers' volume");
            }
            if m.face.is_some() {
                continue;
            }
            let Ok(sub) = vf.with_depth_range(m.shadow.near().max(vf.near()), m.shadow.far().min(vf.far())) else {
                continue;
            };
            let mut planes = Vec::new();
            planes.extend_from_slice(&frustum_planes(&sub));
            planes.extend_from_slice(&box_planes_eye(&r[0], view));
            let mut any_inside = false;
            for pe in shadowing_points(&samples, &c[0], view, le, &planes, 1e-9 * scale) {
                let w = e2w.transform_point3(pe);
                prop_assert!(cv.contains(w), "caster point {w} that can shadow B is culled");
                any_inside = true;
            }
            if any_inside {
                prop_assert!(cv.intersects_aabb(&c[0]), "a caster box that can shadow B is culled");
            }
            let margin = 1e-6 * scale;
            let wide = grown(&planes, margin);
            for s in &samples {
                // Points across a box around the caster box and B's slice.
                let lo = c[0].min.min(r[0].min) - DVec3::splat(0.5 * scale);
                let hi = c[0].max.max(r[0].max) + DVec3::splat(0.5 * scale);
                let w = lo + (hi - lo) * DVec3::from(*s);
                let pe = view.transform_point3(w);
                if !ray_meets(pe, le, &wide, 0.0) {
                    prop_assert!(!cv.contains(w), "{w}: its ray misses B, yet it is in the casters' volume");
                }
                if inside_by(&planes, pe, margin) {
                    prop_assert!(rv.contains(w), "{w} in the slice and the box, not in the receivers' volume");
                } else if !inside_by(&planes, pe, -margin) {
                    prop_assert!(!rv.contains(w), "{w} outside the slice or the box, in the receivers' volume");
                }
            }
        }
    }
}

/// Camera at the world origin looking down −Z: world = eye, n = 1, f = 10, tan θ = 1.
fn identity_camera() -> Camera {
    Camera::new(DMat4::IDENTITY, 1.0, 10.0, std::f64::consts::FRAC_PI_4, 1.0).unwrap()
}

/// A ground y ∈ [−1, 0] from z = −1 to −9 under a sun straight down, a tower up to y = 30 over
/// its middle. By hand: B is the ground inside the frustum (|x| ≤ −z ≤ 9), the light sweeps it
/// straight up, and the map's depth reaches the tower's top. A warped map's depth y/w has w
/// linear in −z, here 1 + ρ(−z − 1) for some ρ ≥ 0, so over the tower's z ∈ [−6, −4] it varies
/// by less than 5/3: a box at y ≥ 100 above the tower has y/w above the tower's largest.
#[test]
fn boxes_by_hand_are_culled_or_kept() {
    let ground = [aabb([-20.0, -1.0, -9.0], [20.0, 0.0, -1.0])];
    let tower = aabb([-1.0, 0.0, -6.0], [1.0, 30.0, -4.0]);
    let casters = [ground[0], tower];
    let base = FrameInput::new(identity_camera(), DVec3::new(0.0, -1.0, 0.0), 1024, 1024)
        .receivers(Bound::Boxes(&ground))
        .casters(Bound::Boxes(&casters));
    for scheme in [
        FrameScheme::Single(WarpRule::Lispsm),
        FrameScheme::Single(WarpRule::Uniform),
        FrameScheme::Stable(CascadeSplits::Scheme {
            scheme: SplitScheme::SelfSimilar,
            k: 1,
            overlap: 0.0,
        }),
        FrameScheme::Tsm(TsmOptions {
            focus: 3.0,
            search: TsmSearch::EightyPercent,
        }),
    ] {
        for clamp in [false, true] {
            let f = frame(&base.scheme(scheme).depth_clamp(clamp)).unwrap();
            let m = &f.maps()[0];
            let cv = m.casters_volume();
            let culled = |lo: [f64; 3], hi: [f64; 3]| !cv.intersects_aabb(&aabb(lo, hi));
            // The tower and the ground are kept.
            assert!(!culled([-1.0, 0.0, -6.0], [1.0, 30.0, -4.0]), "{scheme:?}");
            assert!(!culled([-20.0, -1.0, -9.0], [20.0, 0.0, -1.0]));
            // Off to the side: x ∈ [40, 42] is beyond the frustum's |x| ≤ 9 at every depth.
            assert!(culled([40.0, 0.0, -6.0], [42.0, 5.0, -4.0]), "{scheme:?}");
            // Behind the camera (z > 0), straight above nothing the camera sees.
            assert!(culled([-1.0, 1.0, 3.0], [1.0, 5.0, 5.0]));
            // Under the ground, away from the light: it shadows nothing visible.
            assert!(culled([-1.0, -5.0, -6.0], [1.0, -2.0, -4.0]));
            // Above every caster (the tower's top at 30 sets the map's near depth): outside the
            // depth range, which the device clips; with depth clamp it is drawn at the near
            // depth, so it is kept.
            assert_eq!(
                culled([-1.0, 100.0, -6.0], [1.0, 110.0, -4.0]),
                !clamp,
                "{scheme:?}"
            );
            // The receivers' volume holds the ground's part in view, not what is beyond it.
            let rv = m.receivers_volume();
            assert!(rv.contains(DVec3::new(0.0, -0.5, -5.0)));
            assert!(!rv.contains(DVec3::new(0.0, 2.0, -5.0)));
            assert!(!rv.contains(DVec3::new(15.0, -0.5, -5.0)));
            assert!(!rv.intersects_aabb(&aabb([-1.0, 1.0, -6.0], [1.0, 30.0, -4.0])));
        }
    }
}

/// A margin grows every plane by the distance given; a negative or NaN one is refused by name.
#[test]
fn grown_volumes_keep_a_margin() {
    let ground = [aabb([-20.0, -1.0, -9.0], [20.0, 0.0, -1.0])];
    let f = frame(
        &FrameInput::new(identity_camera(), DVec3::new(0.0, -1.0, 0.0), 1024, 1024)
            .receivers(Bound::Boxes(&ground))
            .scheme(FrameScheme::Single(WarpRule::Uniform)),
    )
    .unwrap();
    let m = &f.maps()[0];
    let cv = m.casters_volume();
    let g = cv.grown(0.5).unwrap();
    for (a, b) in cv.planes().iter().zip(g.planes()) {
        assert_eq!(a.truncate(), b.truncate());
        assert_eq!(b.w, a.w - 0.5);
    }
    // The ground's edge in view at the far plane is x = 9: 0.4 beyond it is culled, and kept
    // with a margin of 0.5.
    let beside = aabb([9.4, -0.5, -8.9], [9.45, -0.4, -8.8]);
    assert!(!cv.intersects_aabb(&beside));
    assert!(g.intersects_aabb(&beside));
    for bad in [-1.0, f64::NAN, f64::INFINITY] {
        match cv.grown(bad) {
            Err(Error::InvalidArgument { name, .. }) => assert_eq!(name, "distance"),
            other => panic!("{bad}: {other:?}"),
        }
    }
}
