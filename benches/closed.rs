//! One benchmark per closed form (`closed/NAME`), at least one per quantity of the eval contract
//! (/work/shared/eval-contract.md), named after the contract's quantity where there is one.
//! Inputs pass through `black_box` so nothing is constant-folded; the configuration is the
//! papers' usual n = 1, f = 100, θ = 30°, n′ = n + √(f n) = 11, γ = 60°.
//!
//! ```text
//! cargo bench --bench closed -- --warm-up-time 1 --measurement-time 3
//! ```

use criterion::{criterion_group, criterion_main, Criterion};
use shadow_aliasing::analytic::eta;
use shadow_aliasing::analytic::{global, overhead, partition, subdivided, tilted, tsm};
use shadow_aliasing::{LightAngle, NPrime, Resolutions, ViewFrustum};
use std::hint::black_box as bb;

fn closed(c: &mut Criterion) {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians()).unwrap();
    let np = NPrime::finite(11.0).unwrap();
    let res = Resolutions::default();
    let gamma = LightAngle::new(60f64.to_radians()).unwrap();
    let (n, f, z) = (1.0, 100.0, 7.5);
    let mut g = c.benchmark_group("closed");

    // Lloyd 2006 overhead (Eq 7–14).
    g.bench_function("mx", |b| {
        b.iter(|| overhead::mx(bb(n), bb(f), bb(np), bb(z), bb(res)))
    });
    g.bench_function("mz", |b| {
        b.iter(|| overhead::mz(bb(&view), bb(np), bb(z), bb(res)))
    });
    g.bench_function("max_mx", |b| {
        b.iter(|| overhead::max_mx(bb(n), bb(f), bb(np), bb(res)))
    });
    g.bench_function("max_mz", |b| {
        b.iter(|| overhead::max_mz(bb(&view), bb(np), bb(res)))
    });
    g.bench_function("storage_factor", |b| {
        b.iter(|| overhead::storage_factor(bb(&view), bb(np)))
    });
    g.bench_function("critical_resolution", |b| {
        b.iter(|| overhead::budget_resolution(bb(&view), bb(np), bb(1024.0 * 1024.0)))
    });
    // η ↔ n′ (Lloyd 2006 §4.1, Eq 11, App. B).
    g.bench_function("n_prime_lispsm", |b| {
        b.iter(|| eta::n_prime_lispsm(bb(n), bb(f)))
    });
    g.bench_function("n_prime_from_eta", |b| {
        b.iter(|| eta::n_prime_from_eta(bb(n), bb(f), bb(-0.3)))
    });
    g.bench_function("eta_from_n_prime", |b| {
        b.iter(|| eta::eta_from_n_prime(bb(n), bb(f), bb(np)))
    });
    // Lloyd 2005 (Eq 3–9).
    g.bench_function("distribution_g", |b| {
        b.iter(|| subdivided::distribution_g(bb(100.0), bb(NPrime::finite(11.0).unwrap()), bb(z)))
    });
    g.bench_function("xi_from_n", |b| {
        b.iter(|| subdivided::xi_from_n(bb(100.0), bb(NPrime::finite(11.0).unwrap())))
    });
    g.bench_function("subdivided_max_error", |b| {
        b.iter(|| {
            subdivided::subdivided_max_error(bb(100.0), bb(4), bb(0.0), bb(0.5), bb(1.0), bb(1.0))
        })
    });
    g.bench_function("allocate_texels", |b| {
        let errors = [1.0, 2.5, 4.0, 0.5];
        let mut out = [0.0; 4];
        b.iter(|| {
            subdivided::allocate_texels(bb(&errors), bb(4096.0 * 4096.0), &mut out)
                .map(|()| bb(out[0]))
        })
    });
    // z-partitions and scheme storage factors (Lloyd 2006 Eq 15–23, App. C; Barroso Eq 19).
    g.bench_function("z_partition", |b| {
        b.iter(|| partition::z_splits(bb(n), bb(f), bb(4), bb(partition::SplitScheme::SelfSimilar)))
    });
    g.bench_function("z_partition_adaptive", |b| {
        let s = partition::SplitScheme::Adaptive {
            light_angle: 0.7,
            ratio: 4.0,
        };
        b.iter(|| partition::z_splits(bb(n), bb(f), bb(4), bb(s)))
    });
    g.bench_function("scheme_storage_factor", |b| {
        b.iter(|| {
            partition::scheme_storage_factor(
                bb(partition::Scheme::FpZpW),
                bb(partition::SchemeLight::Overhead),
                bb(&view),
                bb(4),
            )
        })
    });
    // Barroso & Celes (Eq 10–18).
    g.bench_function("tilted_mz", |b| {
        b.iter(|| tilted::tilted_mz(bb(&view), bb(np), bb(gamma), bb(z), bb(res)))
    });
    g.bench_function("generalized_n_prime", |b| {
        b.iter(|| tilted::generalized_n_prime(bb(&view), bb(gamma), bb(tilted::Falloff::Barroso)))
    });
    g.bench_function("gamma_lim", |b| b.iter(|| tilted::gamma_lim(bb(&view))));
    // Martin & Tan §6.2.
    g.bench_function("tsm_eta", |b| {
        b.iter(|| tsm::tsm_eta(bb(10.0), bb(3.0), bb(-0.6)))
    });
    // Zhang et al. (Eq 8–14).
    g.bench_function("zhang_eq", |b| {
        b.iter(|| global::zhang_eq(bb(&view), bb(np), bb(gamma), bb(0.5), bb(z)))
    });
    g.bench_function("zhang_ep", |b| {
        b.iter(|| global::zhang_ep(bb(&view), bb(np), bb(gamma), bb(0.5), bb(z)))
    });
    g.bench_function("zhang_eq_local", |b| {
        b.iter(|| global::zhang_eq_local(bb(&view), bb(np), bb(z)))
    });
    g.bench_function("zhang_ep_local", |b| {
        b.iter(|| global::zhang_ep_local(bb(&view), bb(np), bb(z)))
    });
    g.finish();
}

criterion_group!(benches, closed);
criterion_main!(benches);
