//! The measurement of one matrix's maximum error over the frustum's eight vertices
//! (`measure/frustum_max`), for the LiSPSM map of `benches/builders.rs`' configuration.
//!
//! ```text
//! cargo bench --bench measure -- --warm-up-time 1 --measurement-time 3
//! ```

use criterion::{criterion_group, criterion_main, Criterion};
use glam::DVec3;
use shadow_aliasing::maps::{warp, WarpRule};
use shadow_aliasing::measure::{frustum_max, point_error};
use shadow_aliasing::{Resolutions, ViewFrustum};
use std::hint::black_box as bb;

fn measure(c: &mut Criterion) {
    let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap();
    let light = DVec3::new(0.3, -0.8, -0.4);
    let map = warp(&view, light, WarpRule::Lispsm).unwrap().shadow_map();
    let mut g = c.benchmark_group("measure");
    g.bench_function("frustum_max", |b| {
        b.iter(|| frustum_max(bb(&view), bb(&map)))
    });
    g.bench_function("point_error", |b| {
        let p = DVec3::new(3.0, -2.0, -40.0);
        b.iter(|| point_error(bb(&view), bb(&map), bb(p), bb(Resolutions::default())))
    });
    g.finish();
}

criterion_group!(benches, measure);
criterion_main!(benches);
