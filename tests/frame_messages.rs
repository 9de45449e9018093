//! The frame's error messages name the real cause and a remedy the user can apply (issue 21,
//! item 4), checked on the text.

use glam::{DMat4, DVec3};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{frame, Aabb, Bound, Camera, CascadeSplits, FrameInput, FrameScheme};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::Error;

/// `warp --near 1 --far 100 --half-fov 0.5 --light-dir 0.3,-1,0.2 --warp lispsm
/// --receivers=-50,-2,-100,50,0,0 --casters=-1e13,…,1e13` said "no extent across the warp axis
/// (extent 10.77)": the casters' bound, 10¹¹ times the receivers', is the cause. Without the
/// casters, or with depth clamp (casters not needed), the same frame is built.
#[test]
fn casters_far_beyond_the_body_are_named() {
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5, 1.0).unwrap();
    let receivers =
        [Aabb::new(DVec3::new(-50.0, -2.0, -100.0), DVec3::new(50.0, 0.0, 0.0)).unwrap()];
    let casters = [Aabb::new(DVec3::splat(-1e13), DVec3::splat(1e13)).unwrap()];
    let input = FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 2048, 1080)
        .receivers(Bound::Boxes(&receivers))
        .casters(Bound::Boxes(&casters))
        .scheme(FrameScheme::Single(WarpRule::Lispsm));
    match frame(&input) {
        Err(Error::InvalidArgument {
            name: "casters",
            reason,
        }) => {
            for part in ["from the focus body", "bound the casters", "depth_clamp"] {
                assert!(reason.contains(part), "{part:?} not in {reason}");
            }
        }
        other => panic!("{other:?}"),
    }
    assert!(frame(&input.casters(Bound::Unbounded)).is_ok());
    assert!(frame(&input.depth_clamp(true)).is_ok());
}

/// A stable cascade of a camera 6·10¹¹ from the world origin was told to "reduce far/near or use
/// z-partitions"; the same camera at the origin is mapped, so the offset is the cause, and the
/// message says so.
#[test]
fn a_stable_cascade_far_from_the_origin_names_the_offset() {
    let splits = CascadeSplits::Scheme {
        scheme: SplitScheme::SelfSimilar,
        k: 4,
        overlap: 0.1,
    };
    let at = |off: f64| {
        let eye = DVec3::new(off, 0.0, off);
        let view =
            glam::dcamera::rh::view::look_at_mat4(eye, eye + DVec3::new(0.2, -0.3, -1.0), DVec3::Y);
        let cam = Camera::new(view, 1e-4, 1.0, 0.5, 1.5).unwrap();
        frame(
            &FrameInput::new(cam, DVec3::new(0.3, -1.0, -0.2), 2048, 1080)
                .scheme(FrameScheme::Stable(splits)),
        )
    };
    assert!(at(0.0).is_ok());
    match at(6e11) {
        Err(Error::Degenerate(m)) => {
            for part in [
                "from the world origin",
                "move the world origin near the camera",
            ] {
                assert!(m.contains(part), "{part:?} not in {m}");
            }
            assert!(!m.contains("far/near"), "{m}");
        }
        other => panic!("{other:?}"),
    }
}

/// Bevy's splits that miss the visible depth range: the message reads as a sentence after the
/// argument's name ("minimum_distance and maximum_distance must overlap …"), with the numbers.
#[test]
fn bevy_splits_outside_the_view_read_as_a_sentence() {
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5, 1.0).unwrap();
    let input = FrameInput::new(cam, DVec3::new(0.3, -1.0, -0.2), 2048, 1080).scheme(
        FrameScheme::Cascades {
            splits: CascadeSplits::Bevy {
                k: 3,
                minimum_distance: 200.0,
                maximum_distance: 400.0,
                first_far_bound: 250.0,
                overlap_proportion: 0.2,
            },
            rule: WarpRule::Lispsm,
        },
    );
    let e = frame(&input).unwrap_err();
    assert_eq!(
        e.to_string(),
        "minimum_distance and maximum_distance must overlap the visible depth range [1, 100] \
         (got minimum_distance=200, maximum_distance=400: every Bevy cascade would lie outside it)"
    );
}

/// A bound's polytope with too many planes, or a bad plane, says how many and which, for the
/// receivers and the casters alike (the casters' messages gave no "(got N)").
#[test]
fn polytope_errors_give_the_count_and_the_bad_plane() {
    use glam::DVec4;
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5, 1.0).unwrap();
    let input = FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 2048, 1080);
    let many = [DVec4::new(0.0, 1.0, 0.0, 0.0); 17];
    let mut bad = [DVec4::new(0.0, 1.0, 0.0, 0.0); 3];
    bad[2] = DVec4::new(0.0, 0.0, 0.0, 1.0);
    for name in ["receivers", "casters"] {
        let with = |planes| match name {
            "receivers" => input.receivers(Bound::Polytope(planes)),
            _ => input.casters(Bound::Polytope(planes)),
        };
        for (planes, part) in [(&many[..], "(got 17)"), (&bad[..], "at index 2)")] {
            match frame(&with(planes)) {
                Err(Error::InvalidArgument { name: n, reason }) => {
                    assert_eq!(n, name);
                    assert!(reason.contains(part), "{part:?} not in {reason}");
                }
                other => panic!("{name}: {other:?}"),
            }
        }
    }
}
