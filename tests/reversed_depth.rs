//! Reversed depth (issue 23 item 2): `ClipDepth::Reversed` puts 1 at the end of the map nearest
//! the light and 0 at the farthest, in the builders, the frame (casters included) and the
//! command line. Expected values: the order of points along the light (nearest = smallest
//! `l · p`), hand computations, and the other conventions' matrices.

use glam::{DMat4, DVec3};
use shadow_aliasing::frame::{frame, Aabb, Bound, Camera, FrameInput, FrameScheme};
use shadow_aliasing::maps::{warp, ClipDepth, WarpRule};
use shadow_aliasing::ViewFrustum;

mod common;

fn depth(m: &DMat4, p: DVec3) -> f64 {
    let h = *m * p.extend(1.0);
    h.z / h.w
}

#[test]
fn builders_put_one_nearest_the_light() {
    let view = ViewFrustum::new(0.5, 80.0, 0.6).unwrap();
    let l = DVec3::new(0.3, -1.0, 0.45).normalize();
    for rule in [WarpRule::Uniform, WarpRule::Lispsm, WarpRule::Minimax] {
        let s = warp(&view, l, rule).unwrap();
        let (gl, rev) = (s.matrix(), s.with_clip_depth(ClipDepth::Reversed));
        assert_eq!(rev, ClipDepth::Reversed.convert(&gl));
        let corners = view.corners();
        for c in corners {
            let z = depth(&rev, c);
            assert!((-1e-9..=1.0 + 1e-9).contains(&z), "{rule:?}: {z}");
            // x, y, w unchanged: the same texel.
            let (a, b) = (gl * c.extend(1.0), rev * c.extend(1.0));
            assert_eq!((a.x, a.y, a.w), (b.x, b.y, b.w));
            // 1 − the [0, 1] depth.
            let z01 = depth(&s.with_clip_depth(ClipDepth::ZeroToOne), c);
            assert!((z - (1.0 - z01)).abs() < 1e-12, "{rule:?}");
        }
        if rule == WarpRule::Uniform {
            // Orthographic: the corner first hit by the light (smallest l·p) at 1, the last at 0.
            let by_l = |f: fn(f64, f64) -> bool| {
                *corners
                    .iter()
                    .reduce(|a, b| if f(a.dot(l), b.dot(l)) { a } else { b })
                    .unwrap()
            };
            let (first, last) = (by_l(|a, b| a <= b), by_l(|a, b| a >= b));
            assert!((depth(&rev, first) - 1.0).abs() < 1e-9);
            assert!(depth(&rev, last).abs() < 1e-9);
            // And monotone: later along the light is smaller.
            for a in corners {
                for b in corners {
                    if a.dot(l) < b.dot(l) - 1e-9 {
                        assert!(depth(&rev, a) > depth(&rev, b));
                    }
                }
            }
        }
    }
}

/// A camera above the ground looking down −Z; a small caster box high above the ground, inside
/// the view's light footprint.
fn scene() -> (Camera, [Aabb; 1], [Aabb; 2]) {
    let view = glam::dcamera::rh::view::look_at_mat4(
        DVec3::new(0.0, 3.0, 0.0),
        DVec3::new(0.0, 1.0, -10.0),
        DVec3::Y,
    );
    let cam = Camera::new(view, 0.2, 60.0, 0.5, 1.5).unwrap();
    let ground = Aabb::new([-60.0, -1.0, -70.0], [60.0, 0.0, 5.0]).unwrap();
    let caster = Aabb::new([-1.0, 8.0, -16.0], [1.0, 9.0, -14.0]).unwrap();
    (cam, [ground], [ground, caster])
}

#[test]
fn casters_toward_the_light_map_to_the_near_end_one() {
    let (cam, receivers, casters) = scene();
    let sun = DVec3::new(0.2, -1.0, -0.1);
    let caster_corners = |cam: &Camera| {
        let b = casters[1];
        let w2e = cam.world_to_eye();
        [b.min.x, b.max.x].into_iter().flat_map(move |x| {
            [b.min.y, b.max.y].into_iter().flat_map(move |y| {
                [b.min.z, b.max.z]
                    .into_iter()
                    .map(move |z| w2e.transform_point3(DVec3::new(x, y, z)))
            })
        })
    };
    for clamp in [false, true] {
        let input = FrameInput::new(cam, sun, 1024, 720)
            .receivers(Bound::Boxes(&receivers))
            .casters(Bound::Boxes(&casters))
            .depth_clamp(clamp)
            .scheme(FrameScheme::Single(WarpRule::Uniform));
        let f = frame(&input).unwrap();
        let m = &f.maps()[0];
        let rev = m.shadow.with_clip_depth(ClipDepth::Reversed);
        assert_eq!(
            m.world_to_clip(ClipDepth::Reversed),
            ClipDepth::Reversed.convert(&m.world_to_clip)
        );
        // B lies in [0, 1]; its vertex last along the light at 0.
        let l = f.light_dir_eye();
        let zb: Vec<f64> = m.body().iter().map(|p| depth(&rev, *p)).collect();
        assert!(
            zb.iter().all(|z| (-1e-9..=1.0 + 1e-9).contains(z)),
            "{zb:?}"
        );
        let last = m
            .body()
            .iter()
            .max_by(|a, b| a.dot(l).total_cmp(&b.dot(l)))
            .unwrap();
        assert!(
            depth(&rev, *last).abs() < 1e-9,
            "{} {zb:?}",
            depth(&rev, *last)
        );
        // The caster's corner nearest the light: at 1 when the map covers the casters; beyond
        // 1 (clamped to 1 by the device) with depth clamp, B's nearest vertex then at 1.
        let zc = caster_corners(&cam)
            .map(|p| depth(&rev, p))
            .fold(f64::MIN, f64::max);
        let zb_max = zb.iter().copied().fold(f64::MIN, f64::max);
        if clamp {
            assert!(zc > 1.0 + 1e-3, "{zc}");
            assert!((zb_max - 1.0).abs() < 1e-9, "{zb_max}");
        } else {
            assert!((zc - 1.0).abs() < 1e-9, "{zc}");
            assert!(zb_max < 1.0 - 1e-3, "{zb_max}");
        }
        // The [0, 1] map says the same, mirrored.
        let z01 = m.shadow.with_clip_depth(ClipDepth::ZeroToOne);
        for p in caster_corners(&cam) {
            assert!((depth(&rev, p) - (1.0 - depth(&z01, p))).abs() < 1e-12);
        }
    }
}

#[cfg(feature = "cli")]
#[test]
fn cli_prints_the_reversed_matrix() {
    use common::cli::warp_json;
    // Light straight down on the lower half of the view between depths 2 and 5 (tan θ = 1): B's
    // top (y = 0) is nearest the light, its bottom vertex (0, −5, −5) farthest.
    let rx = [
        "--receivers",
        "-100,-100,-5,100,0,-2",
        "--clip-depth",
        "reversed",
    ];
    let v = warp_json("0.7853981633974483", "0,-1,0", "uniform", &rx);
    let cols: Vec<f64> = v["partitions"][0]["matrix"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let m = DMat4::from_cols_slice(&cols);
    for (p, want) in [
        (DVec3::new(0.0, 0.0, -3.0), 1.0),
        (DVec3::new(0.0, -5.0, -5.0), 0.0),
        (DVec3::new(1.0, -2.5, -4.0), 0.5),
    ] {
        assert!((depth(&m, p) - want).abs() < 1e-12, "{p}: {}", depth(&m, p));
    }
    // Without a scene: the default matrix with row 2 replaced by (row 3 − row 2)/2.
    let gl = warp_json("0.6", "0.3,-1,0.2", "lispsm", &[]);
    let rev = warp_json("0.6", "0.3,-1,0.2", "lispsm", &["--clip-depth", "reversed"]);
    let mat = |v: &serde_json::Value| {
        let c: Vec<f64> = v["partitions"][0]["matrix"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect();
        DMat4::from_cols_slice(&c)
    };
    let (a, b) = (mat(&gl), mat(&rev));
    for r in [0, 1, 3] {
        assert_eq!(a.row(r), b.row(r));
    }
    assert!((b.row(2) - 0.5 * (a.row(3) - a.row(2))).abs().max_element() < 1e-15);
    let (code, _, err) = common::cli::run(&common::cli::warp_args(
        "0.6",
        "0,-1,0",
        "uniform",
        &["--clip-depth", "reverse"],
    ));
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("--clip-depth") && err.contains("reversed"),
        "{err}"
    );
}
