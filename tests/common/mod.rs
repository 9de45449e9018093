//! Shared test helpers for every test binary: the tolerance policy (`REL`, `close`, `rel`), the
//! one proptest configuration `config(cases)`, and the strategies over the view frustum
//! (n, ln α, θ, aspect) and the light direction. Each test binary uses a subset, hence
//! `dead_code` is allowed here.
#![allow(dead_code)]

pub mod audit;
#[cfg(feature = "cli")]
pub mod cli;
pub mod faces;
pub mod scene;
pub mod walk;
pub mod zhang_printed;

use glam::DVec3;
use proptest::prelude::*;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme, Splits};
use shadow_aliasing::maps::{tsm, TsmOptions, TsmSearch};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::ViewFrustum;
use std::ops::Range;

/// A small deterministic generator (Knuth's MMIX LCG; no dependency on the code under test), for
/// tests that sample many random cases with a fixed seed.
pub struct Lcg(pub u64);

impl Lcg {
    /// A number in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A unit vector (normalised from a cube, not uniform on the sphere).
    pub fn unit(&mut self) -> DVec3 {
        DVec3::new(self.next() - 0.5, self.next() - 0.5, self.next() - 0.5).normalize()
    }
}

/// Closed form against its numeric twin: relative 1e-9 (docs/architecture.md, tolerance policy).
pub const REL: f64 = 1e-9;

/// `cases` cases, no failure persistence (CI stays short; CI pins the seed). Every test binary's
/// proptests use this one configuration (docs/architecture.md: bounded case counts).
pub fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// `a` and `b` agree to the relative tolerance `rel` of the larger magnitude.
pub fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * a.abs().max(b.abs())
}

/// The relative difference of `a` and `b`, over the larger magnitude (at least 1e-300, so that
/// two zeros differ by 0).
pub fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
}

/// A random valid frustum over (n, ln α, θ, aspect): n = 10^`log10_near`, f = n e^`ln_alpha`.
pub fn view(
    log10_near: Range<f64>,
    ln_alpha: Range<f64>,
    half_fov: impl Strategy<Value = f64>,
    aspect: impl Strategy<Value = f64>,
) -> impl Strategy<Value = ViewFrustum> {
    (log10_near, ln_alpha, half_fov, aspect).prop_map(|(ln, lr, th, a)| {
        let n = 10f64.powf(ln);
        ViewFrustum::with_aspect(n, n * lr.exp(), th, a).unwrap()
    })
}

/// The builders' cameras: near in [1e−3, 10], f/n log-uniform in [1.01, 10⁶], half field of
/// view from `half_fov`, aspect in [0.5, 2].
pub fn camera(half_fov: impl Strategy<Value = f64>) -> impl Strategy<Value = ViewFrustum> {
    view(
        -3.0..1.0,
        (1.01f64).ln()..(1e6f64).ln(),
        half_fov,
        0.5f64..2.0,
    )
}

/// The tilted-light closed forms' frusta (Barroso, Zhang): near uniform in [0.05, 10], log10(f/n)
/// in [0.004, 6], half field of view in [1°, 80°], square image.
pub fn tilted_view() -> impl Strategy<Value = ViewFrustum> {
    (
        0.05f64..10.0,
        0.004f64..6.0,    // log10(f/n)
        0.0175f64..1.396, // half fov, 1° to 80°
    )
        .prop_map(|(n, la, phi)| ViewFrustum::new(n, n * 10f64.powf(la), phi).unwrap())
}

/// The partitions' parameters (n, ln α, θ, k): near in [0.01, 10], α = f/n log-uniform in
/// [1.5, 10⁵], half field of view in [5°, 75°], k ∈ 1..=8 partitions.
pub fn n_ln_alpha_theta_k() -> impl Strategy<Value = (f64, f64, f64, usize)> {
    (
        0.01f64..10.0,
        (1.5f64).ln()..(1e5f64).ln(),
        5f64.to_radians()..75f64.to_radians(),
        1usize..=8,
    )
}

/// The adaptive partition's limit at γ = 0 with ratio α = 2 (Barroso & Celes Eq 19) of
/// n = 1, f = 1000 into `k` parts.
pub fn adaptive_limit(k: usize) -> Splits {
    z_splits(
        1.0,
        1000.0,
        k,
        SplitScheme::Adaptive {
            light_angle: 0.0,
            ratio: 2.0,
        },
    )
    .unwrap()
}

/// S̄ (measured) of Martin & Tan's trapezoid with the 80 % rule and focus 20, the light
/// travelling along (0, −sin ε, −cos ε) for ε = `deg` degrees (straight behind at ε = 0).
pub fn tsm_80_percent_sbar(view: &ViewFrustum, deg: f64) -> f64 {
    let opts = TsmOptions {
        focus: 20.0,
        search: TsmSearch::EightyPercent,
    };
    let e = deg.to_radians();
    let t = tsm(view, DVec3::new(0.0, -e.sin(), -e.cos()), opts).unwrap();
    frustum_max(view, &t.shadow.shadow_map())
        .unwrap()
        .storage_factor
}

/// The eye-space points a scheme's partition covers: its sub-frustum's corners, or its face's
/// vertices over its depth range.
pub fn region_points(
    view: &ViewFrustum,
    p: &shadow_aliasing::scheme::PartitionResult,
) -> Vec<DVec3> {
    match p.region {
        shadow_aliasing::scheme::Region::Frustum => view
            .with_depth_range(p.near, p.far)
            .unwrap()
            .corners()
            .to_vec(),
        shadow_aliasing::scheme::Region::Face(f) => f.vertices(view, p.near, p.far).to_vec(),
    }
}

/// A light direction: random on the sphere, or one of the special directions (parallel,
/// antiparallel, perpendicular to the view, a hair away from parallel), and `extra`.
pub fn light(extra: DVec3) -> impl Strategy<Value = DVec3> {
    prop_oneof![
        (0.0..std::f64::consts::TAU, -1.0f64..1.0).prop_map(|(a, z)| {
            let r = (1.0 - z * z).sqrt();
            DVec3::new(r * a.cos(), r * a.sin(), z)
        }),
        Just(DVec3::new(0.0, 0.0, -1.0)),
        Just(DVec3::new(0.0, 0.0, 1.0)),
        Just(DVec3::new(0.0, -1.0, 0.0)),
        Just(DVec3::new(1.0, 0.0, 0.0)),
        Just(DVec3::new(1e-9, -1e-9, -1.0)),
        Just(extra),
    ]
}

/// A random valid frustum: near log-uniform in [0.01, 10], f/n log-uniform in [1.01, 10⁴],
/// half field of view in [1°, 80°].
pub fn frustum() -> impl Strategy<Value = ViewFrustum> {
    (-2.0f64..1.0, 0.0043f64..4.0, 1.0f64..80.0).prop_map(|(ln, la, th)| {
        let n = 10f64.powf(ln);
        ViewFrustum::new(n, n * 10f64.powf(la), th.to_radians()).unwrap()
    })
}

/// Where §6.1's top line crosses the centre line, as an eye-space x coordinate, for a directional
/// light travelling along d = (sin ε, 0, −cos ε) (ε from the view direction, in the XZ plane):
/// Steps 1–4 by hand with the light's view an orthographic projection along d (a directional
/// light), E = the frustum's corners projected, l through the projected near and far centres,
/// the top line ⟂ l touching E on the near centre's side.
pub fn top_line_crossing_x(view: &ViewFrustum, eps: f64) -> f64 {
    let d = DVec3::new(eps.sin(), 0.0, -eps.cos());
    let proj = |p: DVec3| p - p.dot(d) * d;
    let cn = proj(DVec3::new(0.0, 0.0, -view.near()));
    let cf = proj(DVec3::new(0.0, 0.0, -view.far()));
    let l = (cf - cn).normalize();
    let m = view
        .corners()
        .iter()
        .map(|&p| proj(p).dot(l))
        .fold(f64::INFINITY, f64::min);
    (cn + (m - cn.dot(l)) * l).x
}

/// Any `f64` (NaN and infinities included) with the values where formulas break weighted in:
/// powers of ten over the whole range, ∞, 0, 1 and −1. The robustness tests' inputs.
pub fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        prop::num::f64::ANY,
        (-300.0f64..300.0).prop_map(|e| 10f64.powf(e)),
        Just(f64::INFINITY),
        Just(0.0),
        Just(1.0),
        Just(-1.0),
    ]
}
