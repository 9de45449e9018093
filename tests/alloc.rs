//! No heap allocation in the per-frame builders (issue 5): a counting global allocator wraps the
//! system allocator and counts, per thread, every `alloc`, `alloc_zeroed` and `realloc`. Each
//! builder is called once to warm up (so lazily initialised state, if any, is not counted), then
//! on many cameras and lights, including the light parallel, antiparallel and perpendicular to the
//! view and the near-parallel fallback, and the count over those calls must be zero.
//!
//! The count is per thread (a `const`-initialised thread-local `Cell`, which itself never
//! allocates), so the test harness running other tests on other threads does not disturb it.
//! `allocations_are_counted` checks that the counter sees a real allocation, so a zero count
//! cannot come from a counter that never counts.
use glam::DVec3;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::maps::atlas::{layout, AtlasEntry};
use shadow_aliasing::maps::cascades::cascades;
use shadow_aliasing::maps::faces::{face_partitions, FaceWarp};
use shadow_aliasing::maps::minimax::minimax_n_prime;
use shadow_aliasing::maps::{tsm, warp, ShadowMatrix, TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::ViewFrustum;
use std::hint::black_box;

#[path = "common/counting_alloc.rs"]
mod no_alloc;
use no_alloc::allocations;

/// Cameras from f/n = 1.01 to 10⁶ and half fields of view from 1° to 80°, with an aspect ≠ 1.
fn views() -> Vec<ViewFrustum> {
    vec![
        ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap(),
        ViewFrustum::new(0.1, 0.101, 1f64.to_radians()).unwrap(),
        ViewFrustum::new(0.01, 1e4, 80f64.to_radians()).unwrap(),
        ViewFrustum::with_aspect(0.5, 200.0, 35f64.to_radians(), 16.0 / 9.0).unwrap(),
    ]
}

/// Tilted, overhead, behind, in front, exactly parallel to the view, and 1e−13 off parallel (below
/// the light-space fallback threshold).
fn lights() -> Vec<DVec3> {
    vec![
        DVec3::new(0.3, -0.8, -0.4),
        DVec3::new(0.0, -1.0, 0.0),
        DVec3::new(0.0, 0.0, -1.0),
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(1e-13, 0.0, -1.0),
        DVec3::new(-0.7, -0.1, 0.7),
        DVec3::new(0.2, 0.9, 0.1),
    ]
}

/// Asserts that `build` never allocates, over every camera and light above, after one warm-up call.
fn assert_no_allocation(name: &str, build: impl Fn(&ViewFrustum, DVec3)) {
    let views = views();
    let lights = lights();
    build(&views[0], lights[0]);
    for v in &views {
        for &l in &lights {
            let ((), n) = allocations(|| build(black_box(v), black_box(l)));
            assert_eq!(
                n,
                0,
                "{name} allocated {n} times for near={}, far={}, half_fov={}, light={l}",
                v.near(),
                v.far(),
                v.half_fov()
            );
        }
    }
}

fn single(rule: WarpRule) -> impl Fn(&ViewFrustum, DVec3) {
    move |v, l| {
        let s: ShadowMatrix = warp(v, l, rule).unwrap();
        black_box(s);
    }
}

#[test]
fn allocations_are_counted() {
    let (v, n) = allocations(|| black_box(vec![1u8; 64]));
    assert!(n >= 1, "the counter saw {n} allocations for a Vec");
    drop(v);
}

#[test]
fn uniform_builder_does_not_allocate() {
    assert_no_allocation("warp(Uniform)", single(WarpRule::Uniform));
}

#[test]
fn lispsm_builder_does_not_allocate() {
    assert_no_allocation("warp(Lispsm)", single(WarpRule::Lispsm));
    assert_no_allocation("warp(LispsmFixed)", single(WarpRule::LispsmFixed));
}

#[test]
fn minimax_builder_does_not_allocate() {
    assert_no_allocation("warp(Minimax)", single(WarpRule::Minimax));
    assert_no_allocation("minimax_n_prime", |v, l| {
        black_box(minimax_n_prime(v, l).unwrap());
    });
}

#[test]
fn frustum_max_does_not_allocate() {
    assert_no_allocation("frustum_max", |v, l| {
        let s = warp(v, l, WarpRule::Lispsm).unwrap();
        black_box(frustum_max(v, &s.shadow_map()).unwrap());
    });
}

#[test]
fn tsm_builder_does_not_allocate() {
    for search in [
        TsmSearch::EightyPercent,
        TsmSearch::Iterative { map_lines: 1024 },
    ] {
        assert_no_allocation("tsm", |v, l| {
            let opts = TsmOptions {
                focus: 0.3 * (v.far() - v.near()),
                search,
            };
            black_box(tsm(v, l, opts).unwrap());
        });
    }
}

#[test]
fn cascades_do_not_allocate() {
    for rule in [WarpRule::Lispsm, WarpRule::Uniform, WarpRule::Minimax] {
        assert_no_allocation("cascades", |v, l| {
            let splits = z_splits(v.near(), v.far(), 4, SplitScheme::SelfSimilar).unwrap();
            black_box(cascades(v, l, &splits, rule, 0.1).unwrap());
        });
    }
}

#[test]
fn face_partitions_do_not_allocate() {
    for (warp, k) in [
        (FaceWarp::Lispsm, 1),
        (FaceWarp::Lispsm, 3),
        (FaceWarp::Uniform, 2),
    ] {
        assert_no_allocation("face_partitions", |v, l| {
            black_box(face_partitions(v, l, warp, k).unwrap());
        });
    }
}

#[test]
fn atlas_layout_does_not_allocate() {
    assert_no_allocation("face partitions + atlas layout", |v, l| {
        let faces = face_partitions(v, l, FaceWarp::Lispsm, 2).unwrap();
        let mut entries = [AtlasEntry {
            group: 0,
            max_mx: 1.0,
            max_mz: 1.0,
        }; 16];
        let mut n = 0;
        for p in faces.iter() {
            entries[n] = AtlasEntry {
                group: n / 2,
                max_mx: p.error.max_mx,
                max_mz: p.error.max_mz,
            };
            n += 1;
        }
        let atlas = layout(4096, 4096, &entries[..n]).unwrap();
        black_box(atlas.compose(0, &faces.iter().next().unwrap().shadow.matrix()));
    });
}

#[test]
fn frame_api_does_not_allocate() {
    use shadow_aliasing::frame::{
        frame, Aabb, Bound, Camera, CascadeSplits, FrameInput, FrameScheme,
    };
    for scheme in [
        FrameScheme::Single(WarpRule::Lispsm),
        FrameScheme::Single(WarpRule::Minimax),
        FrameScheme::Single(WarpRule::Ogre),
        FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.8 },
                k: 4,
                overlap: 0.1,
            },
            rule: WarpRule::Lispsm,
        },
        FrameScheme::Stable(CascadeSplits::Bevy {
            k: 4,
            minimum_distance: 0.0,
            maximum_distance: 1e9,
            first_far_bound: 1e-3,
            overlap_proportion: 0.2,
        }),
        FrameScheme::Faces {
            rule: shadow_aliasing::maps::faces::FaceWarp::Lispsm,
            k: 3,
        },
        FrameScheme::Tsm(TsmOptions {
            focus: 0.3,
            search: TsmSearch::EightyPercent,
        }),
    ] {
        assert_no_allocation("frame", |v, l| {
            let cam = Camera::new(
                glam::DMat4::IDENTITY,
                v.near(),
                v.far(),
                v.half_fov(),
                v.aspect(),
            )
            .unwrap();
            let f = v.far();
            // Receivers: the lower half of the view to 60 % of its depth; casters above it.
            let r = [Aabb::new(DVec3::new(-f, -f, -0.6 * f), DVec3::new(f, 0.0, 0.0)).unwrap()];
            let c = [
                Aabb::new(
                    DVec3::new(-0.1 * f, 0.0, -0.3 * f),
                    DVec3::new(0.1 * f, 0.5 * f, -0.2 * f),
                )
                .unwrap(),
                r[0],
            ];
            // TSM's focus distance: the given fraction of the view's depth range.
            let scheme = match scheme {
                FrameScheme::Tsm(o) => FrameScheme::Tsm(TsmOptions {
                    focus: o.focus * (v.far() - v.near()),
                    ..o
                }),
                s => s,
            };
            let input = FrameInput::new(cam, l, 2048, 1080)
                .receivers(Bound::Boxes(&r))
                .casters(Bound::Boxes(&c))
                .scheme(scheme);
            // With and without measuring the error (issue 23 item 7).
            for input in [input, input.measure(false)] {
                match frame(&input) {
                    Ok(fr) => {
                        black_box(fr);
                    }
                    Err(e) => panic!("{e} at near={}, far={}, light={l}", v.near(), v.far()),
                }
            }
        });
    }
}

/// Face partitions at f/n up to 10⁷ (issue 21, item 2): a candidate warp axis that fails and is
/// discarded for the other must not allocate its error message. Every `FaceWarp` × k, through the
/// frame (`frame_into`, reused) and the frustum-only builder, for f/n from 10 to 10⁷ and lights
/// tilted, overhead, grazing and the one the issue found (PSM, k = 1, f/n = 10⁷: 218 bytes on the
/// second call). Only `Ok` results are counted (an error's message is allowed to allocate), and
/// most must be `Ok`.
#[test]
fn face_partitions_at_deep_frusta_do_not_allocate() {
    use shadow_aliasing::frame::{frame_into, Camera, Frame, FrameInput, FrameScheme, MAX_FACE_K};
    let lights = [
        DVec3::new(
            -0.785_215_254_286_591_6,
            -0.443_948_106_965_519_73,
            -0.431_679_374_956_176_3,
        ),
        DVec3::new(0.3, -0.8, -0.4),
        DVec3::new(0.0, -1.0, -0.3),
        DVec3::new(0.0, -1.0, 0.0),
        DVec3::new(-0.7, -0.1, 0.7),
        DVec3::new(0.05, -0.02, -1.0),
    ];
    let (mut ok, mut calls) = (0, 0);
    let mut failures = Vec::new();
    let mut out = Frame::default();
    for far in [10.0, 1e3, 1e5, 1e6, 1e7] {
        for half_fov in [0.3, 0.8, 1.2] {
            let cam = Camera::new(glam::DMat4::IDENTITY, 1.0, far, half_fov, 1.0).unwrap();
            let view = *cam.view();
            for &l in &lights {
                for rule in [FaceWarp::Uniform, FaceWarp::Psm, FaceWarp::Lispsm] {
                    for k in 1..=MAX_FACE_K {
                        let input = FrameInput::new(cam, l, 2048, 1080)
                            .scheme(FrameScheme::Faces { rule, k });
                        // Warm-up, then the counted call.
                        let _ = frame_into(&input, &mut out);
                        let (r, n) = allocations(|| frame_into(black_box(&input), &mut out));
                        calls += 2;
                        if r.is_ok() {
                            ok += 1;
                            if n > 0 {
                                failures.push(format!("frame_into {rule:?} k={k} f/n={far} θ={half_fov} light={l}: {n} allocations"));
                            }
                        }
                        let (r, n) = allocations(|| face_partitions(black_box(&view), l, rule, k));
                        if r.is_ok() {
                            ok += 1;
                            if n > 0 {
                                failures.push(format!("face_partitions {rule:?} k={k} f/n={far} θ={half_fov} light={l}: {n} allocations"));
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(ok * 10 >= calls * 9, "only {ok} of {calls} calls succeeded");
}

/// The frame's per-map outputs of issue 23 (culling volumes, `unchanged`) through `frame_into` on
/// a reused `Frame`, and every query on them, allocate nothing: the counted call compares each map
/// with the previous frame's and tests boxes and points against both volumes.
#[test]
fn frame_into_culling_and_unchanged_do_not_allocate() {
    use shadow_aliasing::frame::{
        frame_into, Aabb, Bound, Camera, CascadeSplits, Frame, FrameInput, FrameScheme,
    };
    let out = std::cell::RefCell::new(Frame::default());
    for scheme in [
        FrameScheme::Single(WarpRule::Lispsm),
        FrameScheme::Stable(CascadeSplits::Scheme {
            scheme: SplitScheme::Practical { lambda: 0.8 },
            k: 4,
            overlap: 0.0,
        }),
        FrameScheme::Faces {
            rule: FaceWarp::Lispsm,
            k: 2,
        },
        FrameScheme::Tsm(TsmOptions {
            focus: 0.5,
            search: TsmSearch::EightyPercent,
        }),
    ] {
        assert_no_allocation("frame_into + culling + unchanged", |v, l| {
            let cam = Camera::new(
                glam::DMat4::IDENTITY,
                v.near(),
                v.far(),
                v.half_fov(),
                v.aspect(),
            )
            .unwrap();
            let f = v.far();
            let r = [Aabb::new(DVec3::new(-f, -f, -0.6 * f), DVec3::new(f, 0.0, 0.0)).unwrap()];
            let c = [
                Aabb::new(
                    DVec3::new(-0.1 * f, 0.0, -0.3 * f),
                    DVec3::new(0.1 * f, 0.5 * f, -0.2 * f),
                )
                .unwrap(),
                r[0],
            ];
            let scheme = match scheme {
                FrameScheme::Tsm(o) => FrameScheme::Tsm(TsmOptions {
                    focus: o.focus * (v.far() - v.near()),
                    ..o
                }),
                s => s,
            };
            let input = FrameInput::new(cam, l, 2048, 1080)
                .receivers(Bound::Boxes(&r))
                .casters(Bound::Boxes(&c))
                .scheme(scheme);
            // Twice: the second call compares every map with the first's.
            let mut o = out.borrow_mut();
            for _ in 0..2 {
                if let Err(e) = frame_into(&input, &mut o) {
                    panic!("{e} at near={}, far={}, light={l}", v.near(), v.far());
                }
            }
            let mut kept = 0;
            for m in o.maps().iter() {
                kept += usize::from(m.unchanged());
                kept += usize::from(m.casters_volume().intersects_aabb(&c[0]));
                kept += usize::from(m.receivers_volume().contains(DVec3::new(0.0, -1.0, -f)));
                kept += m.casters_volume().grown(1.0).unwrap().planes().len();
            }
            assert!(o.maps().iter().all(|m| m.unchanged()));
            black_box(kept);
        });
    }
}
