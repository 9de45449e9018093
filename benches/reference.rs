//! The machine-independent unit: one glam `DMat4 * DMat4` product (`reference/dmat4_mul`).
//!
//! Every other benchmark is reported in docs/performance.md as a multiple of this median.
//!
//! ```text
//! cargo bench --bench reference -- --warm-up-time 1 --measurement-time 3
//! ```

use criterion::{criterion_group, criterion_main, Criterion};
use glam::DMat4;
use std::hint::black_box;

fn reference(c: &mut Criterion) {
    let a = DMat4::from_cols_array(&[
        1.1, 0.2, -0.3, 0.4, 0.5, 1.6, 0.7, -0.8, 0.9, -1.0, 1.1, 1.2, 1.3, 1.4, -1.5, 1.6,
    ]);
    let b = DMat4::from_cols_array(&[
        0.6, -0.5, 0.4, 0.3, 0.2, 0.1, -0.9, 0.8, 0.7, 0.6, 0.5, -0.4, 0.3, 0.2, 0.1, 1.0,
    ]);
    let mut g = c.benchmark_group("reference");
    g.bench_function("dmat4_mul", |bch| bch.iter(|| black_box(a) * black_box(b)));
    g.finish();
}

criterion_group!(benches, reference);
criterion_main!(benches);
