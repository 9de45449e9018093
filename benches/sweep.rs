//! The hemisphere sweep of S̄ (Lloyd 2006 Fig 7's data): f/n = 1000, half field of view 30°,
//! the 1/sin γ LiSPSM rule (`--warp lispsm-sin`), one map, 90 elevations × 360 azimuths, in
//! process. `sweep/hemisphere_1thread` runs it in a one-thread rayon pool,
//! `sweep/hemisphere_all` in a pool of all cores (`std::thread::available_parallelism`).
//! benches/reference/sweep_numpy.py is the NumPy reference of the same computation.
//!
//! ```text
//! cargo bench --features parallel --bench sweep -- --warm-up-time 1 --measurement-time 3
//! ```

use criterion::{criterion_group, criterion_main, Criterion};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::scheme::sweep::{sweep_into, SweepGrid};
use shadow_aliasing::scheme::Partition;
use shadow_aliasing::ViewFrustum;
use std::hint::black_box as bb;

fn sweeps(c: &mut Criterion) {
    let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap();
    let grid = SweepGrid::new(90, 360).unwrap();
    let mut out = vec![0.0; grid.len()];
    let all = std::thread::available_parallelism().map_or(1, |n| n.get());
    let mut g = c.benchmark_group("sweep");
    g.sample_size(20);
    for (name, threads) in [("hemisphere_1thread", 1), ("hemisphere_all", all)] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        g.bench_function(name, |b| {
            b.iter(|| {
                pool.install(|| {
                    sweep_into(
                        bb(&view),
                        bb(WarpRule::Lispsm),
                        Partition::Single,
                        1,
                        grid,
                        &mut out,
                    )
                })
            })
        });
    }
    g.finish();
}

criterion_group!(benches, sweeps);
criterion_main!(benches);
