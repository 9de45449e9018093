//! The planner (`plan/NAME`, issue 24 item 3): a full plan over every candidate, and its parts.
//! The scene of `builders/frame_*_scene`: n = 1, f = 1000, half field of view 30°, square image
//! 1080 pixels high, light `(0.3, −0.8, −0.4)`; receivers a ground box [−50, 50] × [−5, 0] ×
//! [−100, 0], casters that box and a tower [−10, 10] × [0, 20] × [−60, −40].
//!
//! ```text
//! cargo bench --bench plan -- --warm-up-time 1 --measurement-time 3
//! ```

use criterion::{criterion_group, criterion_main, Criterion};
use glam::DVec3;
use shadow_aliasing::frame::{frame_into, Aabb, Bound, Camera, Frame, FrameInput, FrameScheme};
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::candidates::{candidates, is_searched, label};
use shadow_aliasing::plan::{plan, plan_among, Goal};
use std::hint::black_box as bb;

fn planner(c: &mut Criterion) {
    let light = DVec3::new(0.3, -0.8, -0.4);
    let cam = Camera::new(glam::DMat4::IDENTITY, 1.0, 1000.0, 30f64.to_radians(), 1.0).unwrap();
    let ground = Aabb::new(DVec3::new(-50.0, -5.0, -100.0), DVec3::new(50.0, 0.0, 0.0)).unwrap();
    let tower = Aabb::new(DVec3::new(-10.0, 0.0, -60.0), DVec3::new(10.0, 20.0, -40.0)).unwrap();
    let receivers = [ground];
    let casters = [ground, tower];
    let scene = FrameInput::new(cam, light, 2048, 1080)
        .receivers(Bound::Boxes(&receivers))
        .casters(Bound::Boxes(&casters));
    let all = candidates(&scene);
    let fast: Vec<FrameScheme<'static>> = all.iter().copied().filter(|s| !is_searched(s)).collect();
    let mut g = c.benchmark_group("plan");
    g.sample_size(10);
    g.bench_function("full_max_error_1px", |b| {
        b.iter(|| plan(bb(&scene), bb(Goal::MaxError(1.0)), Rounding::Whole))
    });
    g.bench_function("full_budget_16M", |b| {
        let goal = Goal::Budget {
            texels: 16 << 20,
            max_maps: 8,
        };
        b.iter(|| plan(bb(&scene), bb(goal), Rounding::Whole))
    });
    g.bench_function("without_equal_error_max_error_1px", |b| {
        b.iter(|| plan_among(bb(&scene), bb(Goal::MaxError(1.0)), Rounding::Whole, &fast))
    });
    let chosen = plan(&scene, Goal::MaxError(1.0), Rounding::Whole)
        .unwrap()
        .scheme();
    g.bench_function("chosen_only_max_error_1px", |b| {
        b.iter(|| {
            plan_among(
                bb(&scene),
                bb(Goal::MaxError(1.0)),
                Rounding::Whole,
                &[chosen],
            )
        })
    });
    g.finish();
    // Where the time goes: each candidate's frame, by kind (printed, not a criterion figure).
    let mut out = Frame::default();
    let mut kinds: Vec<(String, usize, f64)> = Vec::new();
    for s in &all {
        let t = std::time::Instant::now();
        for _ in 0..3 {
            let _ = frame_into(bb(&scene.scheme(*s)), &mut out);
        }
        let dt = t.elapsed().as_secs_f64() / 3.0;
        let l = label(s);
        if std::env::var_os("PLAN_BENCH_EACH").is_some() {
            println!("  {l:<36} {:>9.3} ms", dt * 1e3);
        }
        let words: Vec<&str> = l.split(' ').collect();
        let kind = match words[0] {
            "cascades" => format!("cascades {} {}", words[1], words[3]),
            "stable" => format!("stable {}", words[1]),
            w => w.to_string(),
        };
        match kinds.iter_mut().find(|k| k.0 == kind) {
            Some(k) => {
                k.1 += 1;
                k.2 += dt;
            }
            None => kinds.push((kind, 1, dt)),
        }
    }
    println!("plan: {} candidates; frame time by kind:", all.len());
    for (kind, n, t) in &kinds {
        println!("  {kind:<32} {n:>3} candidates {:>9.3} ms", t * 1e3);
    }
}

criterion_group!(benches, planner);
criterion_main!(benches);
