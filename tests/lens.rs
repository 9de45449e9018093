//! The per-pixel error lens (`FrameMap::error_lens_at`, issue 32 item 4) against the crate's
//! independent measurement `measure::surface_footprint` (the exact Jacobian screen pixel →
//! surface → texel from the camera's and the map's matrices, written separately), and its colour
//! ramp against the viridis table by hand.

use glam::{DMat4, DVec3, DVec4};
use proptest::prelude::*;
use shadow_aliasing::frame::lens::lens_colour;
use shadow_aliasing::frame::{frame, Bound, Frame, FrameInput};
use shadow_aliasing::maps::ClipDepth;
use shadow_aliasing::measure::footprint::{surface_footprint, Grids};
use shadow_aliasing::Error;

mod common;
use common::scene::{random_scene, scene_params, schemes, RandomScene, SceneParams};
use common::Lcg;

const MAP_RES: u32 = 1024;
const IMAGE_H: u32 = 1080;

fn random_frame(params: &SceneParams, scheme_i: usize) -> Option<(RandomScene, Frame)> {
    let sc = random_scene(params)?;
    let (r, c) = ([sc.receivers], [sc.casters]);
    let input = FrameInput::new(sc.camera, sc.light, MAP_RES, IMAGE_H)
        .receivers(Bound::Boxes(&r))
        .casters(Bound::Boxes(&c))
        .scheme(schemes(scheme_i))
        .measure(true);
    let f = frame(&input).ok()?;
    Some((sc, f))
}

/// The camera's world → clip for `surface_footprint`: OpenGL's perspective with the camera's
/// vertical field of view on a square image of `IMAGE_H` pixels (the pixels are square, so a
/// pixel's size does not depend on the aspect).
fn camera_clip(sc: &RandomScene) -> DMat4 {
    let v = sc.camera.view();
    let (f, n, z) = (1.0 / v.half_fov().tan(), v.near(), v.far());
    let proj = DMat4::from_rows(
        DVec4::new(f, 0.0, 0.0, 0.0),
        DVec4::new(0.0, f, 0.0, 0.0),
        DVec4::new(0.0, 0.0, (z + n) / (n - z), 2.0 * z * n / (n - z)),
        DVec4::new(0.0, 0.0, -1.0, 0.0),
    );
    proj * sc.camera.world_to_eye()
}

/// A random point of B in world space (a random convex combination of its vertices, which the
/// map holds in eye space).
fn point_of(body: &[DVec3], eye_to_world: DMat4, rng: &mut Lcg) -> DVec3 {
    let w: Vec<f64> = body.iter().map(|_| rng.next() + 1e-3).collect();
    let sum: f64 = w.iter().sum();
    let p: DVec3 = body.iter().zip(&w).map(|(p, w)| *p * (*w / sum)).sum();
    eye_to_world.transform_point3(p)
}

proptest! {
    #![proptest_config(common::config(48))]

    /// Random scenes, every scheme, random points of B and random normals (at least 0.1 from
    /// edge-on to the light and to the camera): the lens is `surface_footprint`'s error
    /// `1/σ_min(J)` with the same camera and map, to 10⁻⁶ relative.
    #[test]
    fn lens_is_the_surface_footprint_error(
        params in scene_params(),
        scheme_i in 0usize..7,
        seed in any::<u64>(),
    ) {
        let Some((sc, f)) = random_frame(&params, scheme_i) else {
            return Ok(());
        };
        let cam = camera_clip(&sc);
        let e2w = sc.camera.world_to_eye().inverse();
        let eye = e2w.transform_point3(DVec3::ZERO);
        let l = sc.light.normalize();
        let grids = Grids::new(IMAGE_H, IMAGE_H, MAP_RES, MAP_RES).unwrap();
        let mut rng = Lcg(seed);
        let mut checked = 0;
        for m in f.maps().iter() {
            let light = m.world_to_clip(ClipDepth::NegOneToOne);
            for _ in 0..16 {
                let p = point_of(m.body(), e2w, &mut rng);
                let n = rng.unit();
                if n.dot(l).abs() < 0.1 || n.dot((eye - p).normalize()).abs() < 0.1 {
                    continue;
                }
                let Ok(fp) = surface_footprint(&cam, &light, grids, p, n) else {
                    continue;
                };
                let want = fp.error().unwrap();
                let got = m.error_lens_at(p, n, &sc.camera, IMAGE_H).unwrap();
                prop_assert!(
                    (got - want).abs() <= 1e-6 * want,
                    "lens {got} vs footprint {want} at {p} n {n} (scheme {scheme_i})"
                );
                checked += 1;
            }
        }
        prop_assert!(checked > 0 || f.maps().is_empty());
    }
}

/// A frame of a fixed scene: camera at (0, 2, 0) looking down −z, ground box, light from above.
fn fixed() -> (RandomScene, Frame) {
    let params = SceneParams {
        eye: [0.0, 2.0, 10.0],
        target: [10.0, 0.5, 10.0],
        near: 0.1,
        ratio: 500.0,
        fov_deg: 30.0,
        aspect: 1.5,
        light: [0.3, -1.0, -0.2],
        rmin: [-50.0, -1.0, -100.0],
        rsize: [100.0, 1.0, 100.0],
        cmin: [10.0, 1.0, 10.0],
        csize: [4.0, 3.0, 4.0],
    };
    random_frame(&params, 0).unwrap()
}

/// The frame's reported maximum is Lloyd's perspective factor; the lens multiplies it by the
/// surface's projection factor, unbounded at grazing light. A lit surface facing the camera, its
/// normal 10⁻³ from perpendicular to the light, has a lens far above the maximum: the maximum is
/// not a bound on the lens over surfaces.
#[test]
fn a_grazing_lit_surface_exceeds_the_perspective_maximum() {
    let (sc, f) = fixed();
    let m = f.maps().iter().next().unwrap();
    let eye = sc
        .camera
        .world_to_eye()
        .inverse()
        .transform_point3(DVec3::ZERO);
    let l = sc.light.normalize();
    let e2w = sc.camera.world_to_eye().inverse();
    let p = e2w.transform_point3(m.body().iter().sum::<DVec3>() / m.body().len() as f64);
    let to_eye = (eye - p).normalize();
    let across = (to_eye - to_eye.dot(l) * l).normalize();
    let n = (across - 1e-3 * l).normalize();
    assert!(n.dot(-l) > 0.0 && n.dot(to_eye) > 0.0);
    let lens = m.error_lens_at(p, n, &sc.camera, IMAGE_H).unwrap();
    assert!(
        lens > 10.0 * m.max_error_pixels,
        "lens {lens}, maximum {}",
        m.max_error_pixels
    );
}

/// Bad input gets a typed error naming the argument; a point behind the camera and a surface
/// edge-on to the light are degenerate.
#[test]
fn lens_refuses_bad_input() {
    let (sc, f) = fixed();
    let m = f.maps().iter().next().unwrap();
    let p = sc
        .camera
        .world_to_eye()
        .inverse()
        .transform_point3(m.body()[0]);
    let name = |r: Result<f64, Error>| match r {
        Err(Error::InvalidArgument { name, .. }) => name,
        other => panic!("expected InvalidArgument, got {other:?}"),
    };
    let up = DVec3::Y;
    assert_eq!(
        name(m.error_lens_at(DVec3::NAN, up, &sc.camera, IMAGE_H)),
        "p"
    );
    assert_eq!(
        name(m.error_lens_at(p, DVec3::ZERO, &sc.camera, IMAGE_H)),
        "n"
    );
    assert_eq!(name(m.error_lens_at(p, up, &sc.camera, 0)), "image_height");
    let eye = sc
        .camera
        .world_to_eye()
        .inverse()
        .transform_point3(DVec3::ZERO);
    let behind = eye + (eye - p);
    assert!(matches!(
        m.error_lens_at(behind, up, &sc.camera, IMAGE_H),
        Err(Error::Degenerate(_))
    ));
    let l = sc.light.normalize();
    let edge_on = l.any_orthonormal_vector();
    match m.error_lens_at(p, edge_on, &sc.camera, IMAGE_H) {
        Err(Error::Degenerate(_)) => {}
        Ok(v) => assert!(v > 1e12, "edge-on to the light gave {v}"),
        other => panic!("{other:?}"),
    }
}

/// The ramp by hand: viridis's ten colours at 2⁻⁴ … 2⁵ pixels, 1 pixel `#26828e`, halfway in
/// log₂ the mean of two neighbours, clamped at both ends, not finite the last colour.
#[test]
fn lens_ramp_by_hand() {
    let rgb = |c: u32| {
        [
            f64::from(c >> 16) / 255.0,
            f64::from((c >> 8) & 0xff) / 255.0,
            f64::from(c & 0xff) / 255.0,
        ]
    };
    let near = |a: [f64; 3], b: [f64; 3]| a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-12);
    assert!(near(lens_colour(1.0), rgb(0x26828e)));
    assert!(near(lens_colour(1.0 / 16.0), rgb(0x440154)));
    assert!(near(lens_colour(1e-9), rgb(0x440154)));
    assert!(near(lens_colour(0.0), rgb(0x440154)));
    assert!(near(lens_colour(32.0), rgb(0xfde725)));
    assert!(near(lens_colour(1e9), rgb(0xfde725)));
    assert!(near(lens_colour(f64::INFINITY), rgb(0xfde725)));
    assert!(near(lens_colour(f64::NAN), rgb(0xfde725)));
    assert!(near(lens_colour(4.0), rgb(0x35b779)));
    assert!(near(lens_colour(8.0), rgb(0x6ece58)));
    // √2 pixels: halfway between #26828e (1 px) and #1f9e89 (2 px).
    let mid = [
        (f64::from(0x26) + f64::from(0x1f)) / 510.0,
        (f64::from(0x82) + f64::from(0x9e)) / 510.0,
        (f64::from(0x8e) + f64::from(0x89)) / 510.0,
    ];
    assert!(near(lens_colour(2f64.sqrt()), mid));
}

/// Where the projection factor is 1 the lens is the perspective factor, so its maximum over B is
/// the frame's `max_error_pixels`: with the light travelling along the view axis f and the
/// surface facing the camera (n = −f), the surface is the plane ⊥ l and the camera sees it square
/// on (a one-texel step along s is m_x pixels: measure::footprint's docs). The lens is the larger
/// singular value of the two texel steps, at least both per-axis factors (m_x the edge along s;
/// m_z the distance between lines of constant t, at most the edge along t), and equal to the larger
/// where the texel's edges are orthogonal, as they are for these frames' maps (the light along
/// the view leaves nothing to warp). So the largest lens over B's vertices is
/// `max_error_pixels`, to 10⁻⁹ relative, for every map of each scheme.
#[test]
fn lens_at_the_worst_vertex_is_the_frames_maximum_where_the_projection_factor_is_one() {
    let view = glam::dcamera::rh::view::look_at_mat4(
        DVec3::new(1.0, 3.0, 5.0),
        DVec3::new(1.0, 3.0, -5.0),
        DVec3::Y,
    );
    let camera = shadow_aliasing::frame::Camera::new(view, 0.5, 200.0, 0.5, 1.5).unwrap();
    let forward = DVec3::NEG_Z;
    let boxes =
        [shadow_aliasing::frame::Aabb::new([-40.0, -1.0, -150.0], [40.0, 8.0, 0.0]).unwrap()];
    let e2w = view.inverse();
    let mut checked = 0;
    for scheme_i in [0, 1, 3, 4] {
        let input = FrameInput::new(camera, forward, MAP_RES, IMAGE_H)
            .receivers(Bound::Boxes(&boxes))
            .casters(Bound::Boxes(&boxes))
            .scheme(schemes(scheme_i))
            .measure(true);
        let f = frame(&input).unwrap();
        for m in f.maps().iter() {
            let worst = m
                .body()
                .iter()
                .map(|p| {
                    m.error_lens_at(e2w.transform_point3(*p), -forward, &camera, IMAGE_H)
                        .unwrap()
                })
                .fold(0.0f64, f64::max);
            let want = m.max_error_pixels;
            assert!(
                (worst - want).abs() <= 1e-9 * want,
                "scheme {scheme_i}: lens {worst} against max_error_pixels {want}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 7, "{checked} maps");
}
