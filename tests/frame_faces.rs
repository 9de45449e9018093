//! Face partitions through the frame API (issue 9): the frustum-only builder reproduced when
//! nothing bounds the scene, every point of a focused scene covered by the map of the face its
//! light ray passes (found by a ray–quad test, not the frame's clipper), random scenes with every
//! B_i vertex and every caster point that can shadow B_i inside the clip volume, and the typed
//! refusals.

use glam::{DMat4, DVec3, DVec4};
use proptest::prelude::*;
use shadow_aliasing::frame::{
    frame, Bound, Camera, Focus, FrameInput, FrameMap, FrameScheme, MAX_FACE_K,
};
use shadow_aliasing::maps::faces::{face_partitions, Face, FaceWarp};
use shadow_aliasing::{Error, ViewFrustum};

mod common;
use common::scene::{
    aabb, box_planes_eye, clip_coords, frustum_planes, random_scene, scene_params, shadowing_points,
};

fn faces_input(cam: Camera, l: DVec3, rule: FaceWarp, k: usize) -> FrameInput<'static> {
    FrameInput::new(cam, l, 1024, 1024).scheme(FrameScheme::Faces { rule, k })
}

/// The largest entry of `|a − b|` relative to the largest entry of `|b|`.
fn rel_diff(a: DMat4, b: DMat4) -> f64 {
    let scale = b.abs().to_cols_array().into_iter().fold(0.0, f64::max);
    let d = (a - b)
        .abs()
        .to_cols_array()
        .into_iter()
        .fold(0.0, f64::max);
    d / scale
}

#[test]
fn no_bounds_reproduce_the_frustum_only_face_partitions() {
    let eye = DVec3::new(1.0, 3.0, 2.0);
    let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(-2.0, 0.0, -30.0), DVec3::Y);
    let cam = Camera::new(view, 0.5, 200.0, 0.5, 1.6).unwrap();
    let vf = *cam.view();
    let lights = [
        DVec3::new(0.0, -1.0, 0.0),
        DVec3::new(0.3, -0.8, -0.4),
        DVec3::new(-0.2, -0.3, 0.9),
        DVec3::new(0.05, -0.1, -1.0),
        DVec3::new(0.9, -0.2, 0.1),
    ];
    let mut compared = 0;
    for lw in lights {
        for rule in [FaceWarp::Lispsm, FaceWarp::Psm, FaceWarp::Uniform] {
            for k in 1..=MAX_FACE_K {
                let f = frame(&faces_input(cam, lw, rule, k)).unwrap();
                let want = face_partitions(&vf, f.light_dir_eye(), rule, k).unwrap();
                assert_eq!(f.len(), want.len(), "{lw} {rule:?} {k}");
                assert_eq!(f.slots().len(), want.len());
                for (got, w) in f.maps().iter().zip(want.iter()) {
                    assert_eq!(got.face, Some(w.face));
                    assert_eq!(got.split, (w.shadow.near(), w.shadow.far()));
                    let d = rel_diff(got.shadow.matrix(), w.shadow.matrix());
                    assert!(d <= 1e-12, "{lw} {rule:?} {k} {:?}: {d:e}", w.face);
                    let s = (got.storage_factor - w.storage_factor()).abs();
                    assert!(
                        s <= 1e-9 * w.storage_factor(),
                        "{:?}: {} vs {}",
                        w.face,
                        got.storage_factor,
                        w.storage_factor()
                    );
                    assert_eq!(got.world_to_clip, got.shadow.matrix() * view);
                    compared += 1;
                }
            }
        }
    }
    assert!(compared > 100, "{compared}");
}

/// Whether the ray `p + s d`, s ≥ 0 or s ≤ 0 (`both`), meets the convex planar quad `q`.
fn ray_meets_quad(p: DVec3, d: DVec3, q: &[DVec3; 4]) -> bool {
    let n = (q[1] - q[0]).cross(q[3] - q[0]);
    let den = n.dot(d);
    if den.abs() < 1e-12 {
        return false;
    }
    let s = n.dot(q[0] - p) / den;
    let x = p + s * d;
    // Inside when on the same side of every edge (tolerance relative to the quad's size).
    let size = (q[2] - q[0]).length();
    (0..4).all(|i| {
        let (a, b) = (q[i], q[(i + 1) % 4]);
        (b - a).cross(x - a).dot(n) >= -1e-9 * size * n.length()
    })
}

/// The map of the face part whose quad the light ray through `p` crosses (the faces the frame
/// chose are the light's front faces when `L.z < 0`, its back faces otherwise).
fn map_of<'f>(
    maps: &[&'f FrameMap],
    view: &ViewFrustum,
    p: DVec3,
    l: DVec3,
) -> Option<&'f FrameMap> {
    maps.iter().copied().find(|m| {
        let face = m.face.unwrap();
        let q = face.vertices(view, m.split.0, m.split.1);
        ray_meets_quad(p, l, &q)
    })
}

#[test]
fn every_point_of_a_focused_scene_lies_in_the_map_of_its_face() {
    let eye = DVec3::new(0.0, 6.0, 0.0);
    let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(0.0, 0.0, -40.0), DVec3::Y);
    let cam = Camera::new(view, 0.5, 500.0, 0.45, 1.5).unwrap();
    let vf = *cam.view();
    // Receivers: a ground slab 80 × 80 ahead of the camera, far nearer than the far plane.
    let ground = [aabb([-40.0, -1.0, -80.0], [40.0, 0.0, 0.0])];
    // A 41 × 3 × 41 grid over the slab (its faces included).
    let grid: Vec<DVec3> = (0..=40)
        .flat_map(|i| (0..3).flat_map(move |j| (0..=40).map(move |k| (i, j, k))))
        .map(|(i, j, k)| {
            DVec3::new(
                -40.0 + 2.0 * f64::from(i),
                -0.5 * f64::from(j),
                -2.0 * f64::from(k),
            )
        })
        .collect();
    let mut inside = 0;
    for lw in [
        DVec3::new(0.1, -0.3, -1.0), // from behind: front faces
        DVec3::new(0.4, -1.0, 0.3),  // from above, ahead
        DVec3::new(-0.3, -0.2, 0.9), // from in front: back faces
    ] {
        for k in 1..=MAX_FACE_K {
            let input = faces_input(cam, lw, FaceWarp::Lispsm, k).receivers(Bound::Boxes(&ground));
            let f = frame(&input).unwrap();
            assert_eq!(f.focus(), Focus::Body);
            let l = f.light_dir_eye();
            let maps: Vec<&FrameMap> = f.maps().iter().collect();
            // The focused maps cover less than the whole frustum: their bodies end near the slab.
            for m in &maps {
                assert!(m.body().iter().all(|p| -p.z <= 80.0 * 1.2 + 6.0));
            }
            for &w in &grid {
                let p = view.transform_point3(w);
                let z = -p.z;
                let (t, ta) = (vf.tan_half_fov(), vf.tan_half_fov() * vf.aspect());
                if z < vf.near() || z > vf.far() || p.x.abs() > z * ta || p.y.abs() > z * t {
                    continue;
                }
                let m = map_of(&maps, &vf, p, l).unwrap_or_else(|| {
                    panic!("no face part's quad on the ray of {p} ({lw}, k {k})")
                });
                let h = m.shadow.matrix() * p.extend(1.0);
                assert!(h.w > 0.0);
                let q = h.truncate() / h.w;
                assert!(
                    q.abs().max_element() <= 1.0 + 1e-9,
                    "{p} → {q} in the {:?} map",
                    m.face
                );
                inside += 1;
            }
        }
    }
    assert!(inside > 5000, "{inside}");
}

#[test]
fn refusals_and_empty_scenes() {
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5, 1.0).unwrap();
    let l = DVec3::new(0.2, -1.0, -0.3);
    for k in [0, MAX_FACE_K + 1] {
        let e = frame(&faces_input(cam, l, FaceWarp::Lispsm, k)).unwrap_err();
        assert!(matches!(e, Error::InvalidArgument { name: "k", .. }), "{e}");
    }
    let planes = [DVec4::new(0.0, 1.0, 0.0, -1.0); 9];
    let e = frame(&faces_input(cam, l, FaceWarp::Lispsm, 1).receivers(Bound::Polytope(&planes)))
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::InvalidArgument {
                name: "receivers",
                ..
            }
        ),
        "{e}"
    );
    // Behind the camera: no map needed.
    let behind = [aabb([-5.0, -5.0, 10.0], [5.0, 5.0, 20.0])];
    let f =
        frame(&faces_input(cam, l, FaceWarp::Lispsm, 2).receivers(Bound::Boxes(&behind))).unwrap();
    assert!(f.is_empty());
    assert_eq!(f.focus(), Focus::Empty);
    assert_eq!(f.storage_factor(), None);
}

/// The planes of the convex region of eye space whose points' light rays cross the quad `q`
/// (its edges swept along `l`), outward, written independently of the frame's own.
fn prism_planes(q: &[DVec3; 4], l: DVec3) -> Vec<DVec4> {
    let c = 0.25 * (q[0] + q[1] + q[2] + q[3]);
    (0..4)
        .filter_map(|i| {
            let e = q[(i + 1) % 4] - q[i];
            let n = l.cross(e);
            (n.length() > 1e-9 * e.length()).then(|| {
                let n = if n.dot(c - q[i]) > 0.0 { -n } else { n };
                n.extend(-n.dot(q[i]))
            })
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 128, failure_persistence: None, ..ProptestConfig::default() })]

    /// Random cameras, lights and boxes: every face map's B_i vertices inside the clip volume,
    /// and every sampled caster point whose ray along the light meets B_i, so that it can shadow
    /// it (the visible frustum ∩ the receivers' box ∩ the face part's prism, by the planes above),
    /// inside it too. About 3 700 caster points per run can shadow a B_i.
    #[test]
    fn random_scenes_map_inside(
        params in scene_params(),
        k in 1usize..=MAX_FACE_K,
        rule_i in 0usize..3,
        samples in prop::collection::vec(prop::array::uniform3(0.0f64..1.0), 100),
    ) {
        let Some(sc) = random_scene(&params) else {
            return Ok(());
        };
        let (view, cam, l) = (sc.view, sc.camera, sc.light);
        let (r, c) = ([sc.receivers], [sc.casters]);
        let rule = [FaceWarp::Lispsm, FaceWarp::Psm, FaceWarp::Uniform][rule_i];
        let input = faces_input(cam, l, rule, k)
            .receivers(Bound::Boxes(&r))
            .casters(Bound::Boxes(&c));
        let f = match frame(&input) {
            Ok(f) => f,
            Err(e) => { prop_assert!(!e.to_string().is_empty()); return Ok(()); }
        };
        let le = f.light_dir_eye();
        let vf = *cam.view();
        let mut b_planes = frustum_planes(&vf).to_vec();
        b_planes.extend_from_slice(&box_planes_eye(&r[0], view));
        for m in f.maps().iter() {
            prop_assert!(m.world_to_clip.is_finite() && m.storage_factor.is_finite() && m.storage_factor > 0.0);
            prop_assert!(m.texel_world.is_finite() && m.texel_world > 0.0);
            let face = m.face.unwrap();
            prop_assert!(face != Face::Far);
            for p in m.body() {
                let q = clip_coords(m.shadow.matrix(), *p);
                prop_assert!(q.is_some_and(|q| q.abs().max_element() <= 1.0 + 1e-7), "B_i vertex {p} → {q:?}");
            }
            let quad = face.vertices(&vf, m.split.0, m.split.1);
            let mut planes = b_planes.clone();
            planes.extend(prism_planes(&quad, le));
            let scale = vf.far();
            for pe in shadowing_points(&samples, &c[0], view, le, &planes, 1e-9 * scale) {
                let q = clip_coords(m.shadow.matrix(), pe);
                prop_assert!(q.is_some_and(|q| q.abs().max_element() <= 1.0 + 1e-6), "caster {pe} → {q:?} ({face:?})");
            }
        }
    }
}
