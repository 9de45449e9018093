//! Shared test helpers for the closed-form tests (tests/lloyd2005.rs, tests/lloyd2006.rs,
//! tests/partition.rs): the tolerance policy, the proptest configuration and the bounded random
//! frustum. Each test binary uses a subset, hence `dead_code` is allowed here.
#![allow(dead_code)]

#[cfg(feature = "cli")]
pub mod cli;
pub mod faces;

use proptest::prelude::*;
use shadow_aliasing::ViewFrustum;

/// Closed form against its numeric twin: relative 1e-9 (docs/architecture.md, tolerance policy).
pub const REL: f64 = 1e-9;

/// 128 cases, no failure persistence (CI stays short; CI pins the seed).
pub fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 128,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// `a` and `b` agree to the relative tolerance `rel` of the larger magnitude.
pub fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

/// A random valid frustum: near log-uniform in [0.01, 10], f/n log-uniform in [1.01, 10⁴],
/// half field of view in [1°, 80°].
pub fn frustum() -> impl Strategy<Value = ViewFrustum> {
    (-2.0f64..1.0, 0.0043f64..4.0, 1.0f64..80.0).prop_map(|(ln, la, th)| {
        let n = 10f64.powf(ln);
        ViewFrustum::new(n, n * 10f64.powf(la), th.to_radians()).unwrap()
    })
}
