//! The per-frame builders (`builders/NAME`): what a renderer calls every frame for every shadowed
//! light. TSM's focus region is the first 30 % of the depth range, its iterative search over a
//! 1024-line map. Configuration: n = 1, f = 1000, half field of view 30°, square image, a light tilted
//! 53° from the view direction and off the view's vertical plane, `(0.3, −0.8, −0.4)`.
//!
//! ```text
//! cargo bench --bench builders -- --warm-up-time 1 --measurement-time 3
//! ```

use criterion::{criterion_group, criterion_main, Criterion};
use glam::DVec3;
use shadow_aliasing::build::{tsm, warp, TsmOptions, TsmSearch, WarpRule};
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
    g.bench_function("lispsm_sin", |b| {
        b.iter(|| warp(bb(&view), bb(light), bb(WarpRule::LispsmSin)))
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
    g.finish();
}

criterion_group!(benches, builders);
criterion_main!(benches);
