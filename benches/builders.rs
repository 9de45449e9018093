//! The per-frame builders (`builders/NAME`): what a renderer calls every frame for every shadowed
//! light. TSM's focus region is the first 30 % of the depth range, its iterative search over a
//! 1024-line map; the cascades are four self-similar z-partitions; the face partitions are
//! unsubdivided (k = 1), and the atlas packs them. Configuration: n = 1, f = 1000, half field of view 30°, square image, a light tilted
//! 53° from the view direction and off the view's vertical plane, `(0.3, −0.8, −0.4)`.
//!
//! ```text
//! cargo bench --bench builders -- --warm-up-time 1 --measurement-time 3
//! ```

use criterion::{criterion_group, criterion_main, Criterion};
use glam::DVec3;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::frame::{
    frame_into, Aabb, Bound, Camera, CascadeSplits, Frame, FrameInput, FrameScheme,
};
use shadow_aliasing::maps::atlas::{layout, AtlasEntry};
use shadow_aliasing::maps::cascades::{cascades, stable_cascades};
use shadow_aliasing::maps::faces::{face_partitions, FaceWarp};
use shadow_aliasing::maps::{tsm, warp, TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::ViewFrustum;
use std::hint::black_box as bb;

fn builders(c: &mut Criterion) {
    let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap();
    let light = DVec3::new(0.3, -0.8, -0.4);
    let mut g = c.benchmark_group("builders");
    g.bench_function("uniform", |b| {
        b.iter(|| warp(bb(&view), bb(light), bb(WarpRule::Uniform)))
    });
    g.bench_function("lispsm", |b| {
        b.iter(|| warp(bb(&view), bb(light), bb(WarpRule::Lispsm)))
    });
    g.bench_function("lispsm_fixed", |b| {
        b.iter(|| warp(bb(&view), bb(light), bb(WarpRule::LispsmFixed)))
    });
    g.bench_function("minimax", |b| {
        b.iter(|| warp(bb(&view), bb(light), bb(WarpRule::Minimax)))
    });
    // Martin & Tan: the focus region is the first 30 % of the frustum's depth range.
    let focus = 0.3 * (view.far() - view.near());
    g.bench_function("tsm", |b| {
        let opts = TsmOptions {
            focus,
            search: TsmSearch::EightyPercent,
        };
        b.iter(|| tsm(bb(&view), bb(light), bb(opts)))
    });
    g.bench_function("tsm_iterative", |b| {
        let opts = TsmOptions {
            focus,
            search: TsmSearch::Iterative { map_lines: 1024 },
        };
        b.iter(|| tsm(bb(&view), bb(light), bb(opts)))
    });
    // Four self-similar z-partitions (Lloyd 2006 Eq 15, 16), each with its own LiSPSM map and its
    // measured M_x, M_z: the splits are computed in the timed call, as a renderer whose near and
    // far change each frame does.
    g.bench_function("cascades4_lispsm", |b| {
        b.iter(|| {
            let splits = z_splits(bb(1.0), bb(1000.0), bb(4), SplitScheme::SelfSimilar)?;
            cascades(bb(&view), bb(light), &splits, bb(WarpRule::Lispsm), bb(0.0))
        })
    });
    // Face partitions (Lloyd 2006 §5.1), one map per visible face, warped (n′ = d_n + √(d_n d_f)).
    g.bench_function("faces", |b| {
        b.iter(|| face_partitions(bb(&view), bb(light), bb(FaceWarp::Lispsm), bb(1)))
    });
    // The atlas layout of those face partitions in a 4096² texture (Lloyd 2005 Eq 6, x then z),
    // two partitions per column.
    let faces = face_partitions(&view, light, FaceWarp::Lispsm, 1).unwrap();
    let mut entries = [AtlasEntry {
        group: 0,
        max_mx: 1.0,
        max_mz: 1.0,
    }; 8];
    let mut n = 0;
    for p in faces.iter() {
        entries[n] = AtlasEntry {
            group: n / 2,
            max_mx: p.error.max_mx,
            max_mz: p.error.max_mz,
        };
        n += 1;
    }
    let entries = &entries[..n];
    g.bench_function("atlas", |b| {
        b.iter(|| layout(bb(4096), bb(4096), bb(entries)))
    });
    // The frame API on a scene 100 units across inside the 1000-deep frustum (issue 9): camera
    // at the world origin (world = eye, the configuration above), receivers a ground box
    // [−50, 50] × [−5, 0] × [−100, 0], casters that box and a tower [−10, 10] × [0, 20] × [−60, −40].
    let cam = Camera::new(glam::DMat4::IDENTITY, 1.0, 1000.0, 30f64.to_radians(), 1.0).unwrap();
    let ground = Aabb::new(DVec3::new(-50.0, -5.0, -100.0), DVec3::new(50.0, 0.0, 0.0)).unwrap();
    let tower = Aabb::new(DVec3::new(-10.0, 0.0, -60.0), DVec3::new(10.0, 20.0, -40.0)).unwrap();
    let receivers = [ground];
    let casters = [ground, tower];
    let scene = FrameInput::new(cam, light, 2048, 1080)
        .receivers(Bound::Boxes(&receivers))
        .casters(Bound::Boxes(&casters));
    // The renderer's loop: one `Frame` reused by `frame_into` every frame (`frame` returns a new
    // one by value, a 20 KB copy).
    let mut out = Frame::default();
    // One LiSPSM map focused on the ground, casters in its depth range, measured over B.
    let single = scene.scheme(FrameScheme::Single(WarpRule::Lispsm));
    g.bench_function("frame_lispsm_scene", |b| {
        b.iter(|| frame_into(bb(&single), &mut out))
    });
    // The same map without measuring its error (`FrameInput::measure(false)`, issue 23 item 7).
    let unmeasured = single.measure(false);
    g.bench_function("frame_lispsm_scene_unmeasured", |b| {
        b.iter(|| frame_into(bb(&unmeasured), &mut out))
    });
    // Four stable cascades (practical λ = 0.8) with the same scene bounds; the counterpart is
    // `stable_cascades4`, the frustum-only stable cascades.
    let stable = scene.scheme(FrameScheme::Stable(CascadeSplits::Scheme {
        scheme: SplitScheme::Practical { lambda: 0.8 },
        k: 4,
        overlap: 0.0,
    }));
    g.bench_function("frame_cascades4_scene", |b| {
        b.iter(|| frame_into(bb(&stable), &mut out))
    });
    // Four LiSPSM cascades of the same scene, practical λ = 0.8 against equal-error splits
    // (issue 24: the root search measures a few hundred slices' maps per frame).
    let practical = scene.scheme(FrameScheme::Cascades {
        splits: CascadeSplits::Scheme {
            scheme: SplitScheme::Practical { lambda: 0.8 },
            k: 4,
            overlap: 0.0,
        },
        rule: WarpRule::Lispsm,
    });
    g.bench_function("frame_practical4_scene", |b| {
        b.iter(|| frame_into(bb(&practical), &mut out))
    });
    let equal = scene.scheme(FrameScheme::Cascades {
        splits: CascadeSplits::EqualError { k: 4 },
        rule: WarpRule::Lispsm,
    });
    g.bench_function("frame_equal_error4_scene", |b| {
        b.iter(|| frame_into(bb(&equal), &mut out))
    });
    // Face partitions (LiSPSM per face, k = 1) of the same scene; the counterpart is `faces`.
    let faces = scene.scheme(FrameScheme::Faces {
        rule: FaceWarp::Lispsm,
        k: 1,
    });
    g.bench_function("frame_faces_scene", |b| {
        b.iter(|| frame_into(bb(&faces), &mut out))
    });
    g.bench_function("stable_cascades4", |b| {
        b.iter(|| {
            let splits = z_splits(
                bb(1.0),
                bb(1000.0),
                bb(4),
                SplitScheme::Practical { lambda: 0.8 },
            )?;
            stable_cascades(
                bb(&view),
                bb(glam::DMat4::IDENTITY),
                bb(light),
                &splits,
                bb(2048),
            )
        })
    });
    g.finish();
}

criterion_group!(benches, builders);
criterion_main!(benches);
