//! The error-budget controller over the recorded camera paths of `paths/` (issue 32 item 1's
//! cost targets; docs/performance.md, "The controller over the camera paths"), at a target of
//! 2 px with `ControllerOptions::new`'s defaults (as `shadow-aliasing replay` runs it):
//!
//! - `controller/PATH/replay`: the whole path, a fresh controller (its first frame a cut);
//!   every frame is timed on its own, and the median and the 99th percentile over the frames
//!   that are not cuts, and the median of the cuts, are printed after the group;
//! - `controller/PATH/chosen`: every frame's chosen set-up built alone at its resolution, its
//!   cascades' planes given as `CascadeSplits::Distances` (no search): the yardstick of the
//!   target "median ≤ 1.5 × the chosen maps with fixed splits";
//! - `controller/PATH/plan`: `plan::plan` (every candidate, `Goal::MaxError(2)`, powers of two)
//!   on every 30th frame: the yardstick of "a cut ≤ the full plan";
//! - `controller_per_map/PATH/…`: the same with `shared_resolution: false` (each map its own
//!   resolution; the chosen maps built at their own resolutions).
//!
//! ```text
//! cargo bench --features cli --bench controller -- --warm-up-time 1 --measurement-time 3
//! ```

#[allow(dead_code)]
#[path = "../src/bin/shadow-aliasing/path_file.rs"]
mod path_file;

use criterion::{criterion_group, criterion_main, Criterion};
use shadow_aliasing::frame::{frame_into, Bound, CascadeSplits, Frame, FrameInput, FrameScheme};
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::{plan, Controller, ControllerOptions, Goal};
use std::hint::black_box as bb;
use std::path::Path;
use std::time::{Duration, Instant};

const TARGET: f64 = 2.0;
const PATHS: [&str; 5] = ["walk", "flyover", "turn", "sun_sweep", "cut"];

/// The `q` quantile (nearest rank) of `v`, milliseconds.
fn quantile(v: &mut [Duration], q: f64) -> f64 {
    v.sort();
    let i = ((q * v.len() as f64).ceil() as usize).clamp(1, v.len()) - 1;
    v[i].as_secs_f64() * 1e3
}

/// A frame's chosen set-up with its planes fixed: (scheme, each slot's resolution, planes).
type Chosen = (FrameScheme<'static>, Vec<u32>, Option<Vec<f64>>);

fn controller(c: &mut Criterion) {
    let mut summary = Vec::new();
    for (shared, name) in [true, false]
        .into_iter()
        .flat_map(|s| PATHS.iter().map(move |n| (s, *n)))
    {
        let options = ControllerOptions {
            shared_resolution: shared,
            ..ControllerOptions::new(TARGET)
        };
        let file = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("paths")
            .join(format!("{name}.json"));
        let path = path_file::read(&file).unwrap();
        let inputs: Vec<FrameInput<'_>> = path
            .frames
            .iter()
            .map(|f| {
                let i = FrameInput::new(f.camera, f.light, 2048, path.image_height)
                    .receivers(Bound::Boxes(&path.receivers));
                if path.casters.is_empty() {
                    i
                } else {
                    i.casters(Bound::Boxes(&path.casters))
                }
            })
            .collect();
        // One replay for the chosen set-ups and their planes.
        let mut ctl = Controller::new(options.clone()).unwrap();
        let chosen: Vec<Chosen> = inputs
            .iter()
            .map(|inp| {
                let d = ctl.frame(inp).unwrap();
                let planes = match d.scheme {
                    FrameScheme::Cascades { .. } | FrameScheme::Stable(_) => {
                        let s: Option<Vec<(f64, f64)>> =
                            d.frame.slots().iter().map(|m| m.map(|m| m.split)).collect();
                        s.map(|s| {
                            let mut p: Vec<f64> = s.iter().map(|x| x.0).collect();
                            p.push(s[s.len() - 1].1);
                            p
                        })
                    }
                    _ => None,
                };
                (d.scheme, d.resolutions.to_vec(), planes)
            })
            .collect();

        let group = if shared {
            "controller"
        } else {
            "controller_per_map"
        };
        let mut g = c.benchmark_group(format!("{group}/{name}"));
        g.sample_size(10);
        let (mut steady, mut cuts) = (Vec::new(), Vec::new());
        g.bench_function("replay", |b| {
            b.iter_custom(|iters| {
                let mut total = Duration::ZERO;
                for _ in 0..iters {
                    let mut ctl = Controller::new(options.clone()).unwrap();
                    for inp in &inputs {
                        let t = Instant::now();
                        let d = ctl.frame(bb(inp)).unwrap();
                        let dt = t.elapsed();
                        total += dt;
                        if d.cut { &mut cuts } else { &mut steady }.push(dt);
                    }
                }
                total
            });
        });
        let mut out = Frame::default();
        let mut fixed = Vec::new();
        g.bench_function("chosen", |b| {
            b.iter_custom(|iters| {
                let mut total = Duration::ZERO;
                for _ in 0..iters {
                    for (inp, (scheme, res, planes)) in inputs.iter().zip(&chosen) {
                        let scheme = match (scheme, planes) {
                            (FrameScheme::Cascades { rule, .. }, Some(p)) => {
                                FrameScheme::Cascades {
                                    splits: CascadeSplits::Distances {
                                        planes: p,
                                        overlap: 0.0,
                                    },
                                    rule: *rule,
                                }
                            }
                            (FrameScheme::Stable(_), Some(p)) => {
                                FrameScheme::Stable(CascadeSplits::Distances {
                                    planes: p,
                                    overlap: 0.0,
                                })
                            }
                            _ => *scheme,
                        };
                        let mut one = inp.scheme(scheme).measure(true);
                        one.map_resolution = res.iter().copied().max().unwrap_or(3);
                        if !shared {
                            one = one.map_resolutions(res);
                        }
                        let t = Instant::now();
                        frame_into(bb(&one), &mut out).unwrap();
                        let dt = t.elapsed();
                        total += dt;
                        fixed.push(dt);
                    }
                }
                total
            });
        });
        let mut plans = Vec::new();
        g.bench_function("plan", |b| {
            b.iter_custom(|iters| {
                let mut total = Duration::ZERO;
                for _ in 0..iters {
                    for inp in inputs.iter().step_by(30) {
                        let t = Instant::now();
                        bb(plan(bb(inp), Goal::MaxError(TARGET), Rounding::PowerOfTwo).unwrap());
                        let dt = t.elapsed();
                        total += dt;
                        plans.push(dt);
                    }
                }
                total
            });
        });
        g.finish();
        let (m, p99) = (quantile(&mut steady, 0.5), quantile(&mut steady, 0.99));
        let f = quantile(&mut fixed, 0.5);
        let label = if shared { "" } else { ", a resolution per map" };
        summary.push(format!(
            "| {name}{label} | {m:.4} | {p99:.4} | {f:.4} | {:.2} | {:.1} | {:.1} |",
            m / f,
            quantile(&mut cuts, 0.5),
            quantile(&mut plans, 0.5)
        ));
    }
    println!(
        "\n| path | frame median (ms) | frame p99 (ms) | chosen maps, fixed planes, median (ms) \
         | ratio | cut median (ms) | full plan median (ms) |"
    );
    println!("|---|---|---|---|---|---|---|");
    for row in summary {
        println!("{row}");
    }
}

criterion_group!(benches, controller);
criterion_main!(benches);
