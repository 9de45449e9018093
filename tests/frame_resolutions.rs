//! A resolution per map (`FrameInput::map_resolutions`, issue 32: engines whose maps need not
//! share one resolution). Each map's figures follow its own resolution, checked from the matrix
//! alone: its error by central differences at B's vertices (`common::audit`), its texel by the
//! lengths of the matrix's s and t rows. The matrices of maps that do not snap to their texels
//! are those of one shared resolution; stable cascades snap to their own texels and stay bit for
//! bit under a sub-texel move; the GPU record carries the resolution; bad lists are refused
//! naming `map_resolutions`.

mod common;

use glam::{DMat4, DVec3};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame, frame_into, Aabb, Bound, Camera, CascadeSplits, ClipmapOptions, Frame, FrameInput,
    FrameScheme,
};
use shadow_aliasing::maps::faces::FaceWarp;
use shadow_aliasing::maps::{ClipDepth, WarpRule};
use shadow_aliasing::Error;

const H: u32 = 1080;
const EACH: [u32; 3] = [2048, 1024, 512];

fn ground() -> [Aabb; 1] {
    [Aabb::new(
        DVec3::new(-100.0, -1.0, -100.0),
        DVec3::new(100.0, 0.0, 100.0),
    )
    .unwrap()]
}

fn camera(eye: DVec3) -> Camera {
    let e = eye + DVec3::new(0.0, 3.0, 0.0);
    let view = glam::dcamera::rh::view::look_at_mat4(e, e + DVec3::new(0.3, -1.0, -10.0), DVec3::Y);
    Camera::new(view, 0.5, 300.0, 0.6, 16.0 / 9.0).unwrap()
}

fn cascades(rule: WarpRule) -> FrameScheme<'static> {
    FrameScheme::Cascades {
        splits: CascadeSplits::Scheme {
            scheme: SplitScheme::Practical { lambda: 0.7 },
            k: 3,
            overlap: 0.0,
        },
        rule,
    }
}

const STABLE: FrameScheme<'static> = FrameScheme::Stable(CascadeSplits::Scheme {
    scheme: SplitScheme::Practical { lambda: 0.7 },
    k: 3,
    overlap: 0.0,
});

fn input<'a>(cam: Camera, g: &'a [Aabb], s: FrameScheme<'a>) -> FrameInput<'a> {
    FrameInput::new(cam, DVec3::new(0.4, -0.8, -0.3), 1024, H)
        .receivers(Bound::Boxes(g))
        .casters(Bound::Boxes(g))
        .scheme(s)
}

/// The largest error over the map's body in pixels at `res` texels, from the matrix alone.
fn audited(m: &shadow_aliasing::frame::FrameMap, inp: &FrameInput<'_>, res: u32) -> f64 {
    common::audit::body_max(m, inp) * f64::from(H) / f64::from(res)
}

/// An orthographic map's texel edges in world units, from its world → clip matrix alone: clip
/// s spans 2 over `res` texels, and a world step moves it by the s row's (x, y, z) (the light
/// along the map's depth axis, so the rows lie across it).
fn ortho_texel(m: &DMat4, res: u32) -> f64 {
    let row = |i: usize| DVec3::new(m.col(0)[i], m.col(1)[i], m.col(2)[i]);
    let r = f64::from(res);
    (2.0 / (r * row(0).length())).max(2.0 / (r * row(1).length()))
}

#[test]
fn each_map_has_its_own_resolutions_figures() {
    let g = ground();
    for rule in [WarpRule::Uniform, WarpRule::Lispsm] {
        let one = input(camera(DVec3::ZERO), &g, cascades(rule));
        let each = one.map_resolutions(&EACH);
        let (f1, fe) = (frame(&one).unwrap(), frame(&each).unwrap());
        assert_eq!(fe.maps().len(), 3, "{rule:?}");
        for (i, (a, b)) in f1.maps().iter().zip(fe.maps().iter()).enumerate() {
            // The warp and the fit do not depend on the resolution.
            assert_eq!(
                a.world_to_clip(ClipDepth::NegOneToOne),
                b.world_to_clip(ClipDepth::NegOneToOne),
                "{rule:?} map {i}"
            );
            let fd = audited(b, &each, EACH[i]);
            assert!(
                (b.max_error_pixels - fd).abs() <= 1e-5 * fd,
                "{rule:?} map {i}: {} px reported, {fd} px audited at {} texels",
                b.max_error_pixels,
                EACH[i]
            );
            let rec = b.gpu(ClipDepth::ZeroToOne);
            assert_eq!(rec.resolution, EACH[i], "{rule:?} map {i}'s record");
            assert_eq!(a.gpu(ClipDepth::ZeroToOne).resolution, 1024);
            if rule == WarpRule::Uniform {
                let t = ortho_texel(&b.world_to_clip(ClipDepth::NegOneToOne), EACH[i]);
                assert!(
                    (b.texel_world - t).abs() <= 1e-9 * t,
                    "map {i}: texel {} against {t} from the matrix",
                    b.texel_world
                );
                // The bias follows the texel: the same map's normal offset at 1024 scaled by
                // 1024 / its resolution (the offset is proportional to the texel's edges).
                let (ba, bb) = (
                    a.bias(0.0, ClipDepth::ZeroToOne).unwrap(),
                    b.bias(0.0, ClipDepth::ZeroToOne).unwrap(),
                );
                let want = ba.texel_extent.0 * 1024.0 / f64::from(EACH[i]);
                assert!((bb.texel_extent.0 - want).abs() <= 1e-12 * want, "map {i}");
            }
        }
    }
}

#[test]
fn stable_cascades_snap_to_their_own_texels_and_stay_put() {
    let g = ground();
    let a = input(camera(DVec3::ZERO), &g, STABLE).map_resolutions(&EACH);
    // A move of a small fraction of the finest texel (at most a few centimetres here).
    let fa = frame(&a).unwrap();
    let finest = fa
        .maps()
        .iter()
        .map(|m| m.texel_world)
        .fold(f64::INFINITY, f64::min);
    let b = input(camera(DVec3::new(1e-3 * finest, 0.0, 0.0)), &g, STABLE).map_resolutions(&EACH);
    let mut out = Frame::default();
    frame_into(&a, &mut out).unwrap();
    frame_into(&b, &mut out).unwrap();
    let kept = out.maps().iter().skip(1).filter(|m| m.unchanged()).count();
    assert_eq!(kept, 2, "the cascades after the first keep their bits");
    for (i, m) in out.maps().iter().enumerate() {
        // A stable map's square is its slice's bounding sphere plus one texel: half-width
        // h = r res / (res − 2), so a texel 2h / res; its edge from the matrix.
        let t = ortho_texel(&m.world_to_clip(ClipDepth::NegOneToOne), EACH[i]);
        assert!((m.texel_world - t).abs() <= 1e-9 * t, "map {i}");
        assert_eq!(m.gpu(ClipDepth::Reversed).resolution, EACH[i]);
        // The square is snapped to whole texels of its own resolution along the world-fixed
        // light axes: the world origin falls on a texel corner, at a whole number of texels
        // (clip s spans 2 over `res` texels) from the centre.
        let o = m.world_to_clip(ClipDepth::NegOneToOne).w_axis;
        for (axis, c) in [("s", o.x), ("t", o.y)] {
            let texels = c / o.w * f64::from(EACH[i]) / 2.0;
            assert!(
                (texels - texels.round()).abs() < 1e-6,
                "map {i}: the origin at {texels} texels along {axis}"
            );
        }
    }
    // The same cascades at one resolution are other squares (each snapped to a 1024 texel).
    let one = frame(&input(camera(DVec3::ZERO), &g, STABLE)).unwrap();
    assert_ne!(
        one.maps()[2].world_to_clip(ClipDepth::NegOneToOne),
        fa.maps()[2].world_to_clip(ClipDepth::NegOneToOne)
    );
}

#[test]
fn a_changed_resolution_changes_only_its_map() {
    let g = ground();
    let cam = camera(DVec3::ZERO);
    let a = input(cam, &g, cascades(WarpRule::Uniform)).map_resolutions(&EACH);
    let other = [2048, 2048, 512];
    let b = input(cam, &g, cascades(WarpRule::Uniform)).map_resolutions(&other);
    let mut out = Frame::default();
    frame_into(&a, &mut out).unwrap();
    frame_into(&b, &mut out).unwrap();
    let flags: Vec<bool> = out.maps().iter().map(|m| m.unchanged()).collect();
    assert_eq!(flags, [true, false, true]);
}

#[test]
fn face_partitions_take_one_resolution_per_slot() {
    let g = ground();
    let s = FrameScheme::Faces {
        rule: FaceWarp::Lispsm,
        k: 1,
    };
    let base = input(camera(DVec3::ZERO), &g, s);
    let slots = frame(&base).unwrap().slots().len();
    let each: Vec<u32> = (0..slots as u32).map(|i| 256 << (i % 4)).collect();
    let f = frame(&base.map_resolutions(&each)).unwrap();
    assert!(!f.is_empty());
    for (i, slot) in f.slots().iter().enumerate() {
        if let Some(m) = slot {
            assert_eq!(m.gpu(ClipDepth::ZeroToOne).resolution, each[i], "slot {i}");
            let fd = audited(m, &base, each[i]);
            assert!((m.max_error_pixels - fd).abs() <= 1e-5 * fd, "slot {i}");
        }
    }
    // Fewer entries than slots.
    refused(&base.map_resolutions(&each[..slots - 1]), "entries");
}

fn refused(inp: &FrameInput<'_>, words: &str) {
    match frame(inp) {
        Err(Error::InvalidArgument { name, reason }) => {
            assert_eq!(name, "map_resolutions", "{reason}");
            assert!(reason.contains(words), "{reason}");
        }
        other => panic!("expected map_resolutions refused, got {other:?}"),
    }
}

/// Equal-error planes are placed by the maps' errors at one resolution (`map_resolution`), so
/// they are the same planes whatever each map's own resolution is.
#[test]
fn equal_error_planes_do_not_depend_on_the_maps_resolutions() {
    let g = ground();
    let cam = camera(DVec3::ZERO);
    for s in [
        FrameScheme::Cascades {
            splits: CascadeSplits::EqualError { k: 3 },
            rule: WarpRule::Uniform,
        },
        FrameScheme::Stable(CascadeSplits::EqualError { k: 3 }),
    ] {
        let one = frame(&input(cam, &g, s)).unwrap();
        let each = frame(&input(cam, &g, s).map_resolutions(&EACH)).unwrap();
        assert_eq!(each.maps().len(), 3);
        for (i, (a, b)) in one.maps().iter().zip(each.maps().iter()).enumerate() {
            assert_eq!(a.split, b.split, "{s:?} map {i}");
            assert_eq!(b.resolution(), EACH[i]);
        }
        // The planes equalise the errors at one resolution: at 1024 the three maps' errors agree
        // (to the search's tolerance; stable cascades to their grid's).
        let e: Vec<f64> = one.maps().iter().map(|m| m.max_error_pixels).collect();
        let (lo, hi) = e
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(l, h), &x| (l.min(x), h.max(x)));
        assert!(hi <= 1.05 * lo, "{s:?}: {e:?}");
    }
}

#[test]
fn bad_lists_are_refused_by_name() {
    let g = ground();
    let cam = camera(DVec3::ZERO);
    let c = input(cam, &g, cascades(WarpRule::Uniform));
    refused(&c.map_resolutions(&[1024, 1024]), "3 partitions");
    refused(
        &c.map_resolutions(&[1024, 1024, 1024, 1024]),
        "3 partitions",
    );
    refused(&c.map_resolutions(&[1024, 2, 1024]), "at least 3 texels");
    refused(&c.map_resolutions(&[]), "0 entries");
    let single = input(cam, &g, FrameScheme::Single(WarpRule::Lispsm));
    refused(&single.map_resolutions(&[512, 512]), "1 partitions");
    // Face partitions with nothing in view check their list all the same.
    let away = [Aabb::new([1e4, 1e4, 1e4], [1e4 + 1.0, 1e4 + 1.0, 1e4 + 1.0]).unwrap()];
    let faces = FrameInput::new(cam, DVec3::new(0.4, -0.8, -0.3), 1024, H)
        .receivers(Bound::Boxes(&away))
        .scheme(FrameScheme::Faces {
            rule: FaceWarp::Lispsm,
            k: 1,
        });
    assert!(frame(&faces).unwrap().is_empty());
    refused(&faces.map_resolutions(&[0]), "at least 3 texels");
    refused(&faces.map_resolutions(&[1024]), "entries");
    let clip = FrameScheme::Clipmap(ClipmapOptions::default());
    let clip = FrameInput::new(cam, DVec3::new(0.4, -0.8, -0.3), 16384, H)
        .receivers(Bound::Boxes(&g))
        .scheme(clip);
    refused(&clip.map_resolutions(&[16384; 8]), "clipmap");
}
