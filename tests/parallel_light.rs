//! The light parallel to the view direction, from behind and from in front (γ = 0).
//!
//! Lloyd 2006 §4.4: there "LiSPSM reverts to" the orthographic map, and §5.3's closed forms
//! for the light behind follow: Eq 20 for ZP and ZP+W (k (f/n)^{2/k}), Eq 21 for FP+ZP+W
//! (4 · k((f/n)^{1/k} − 1)/2 + 1, square image). Every builder, through the scheme layer the
//! command line uses, must give those values, measured from its matrices, at every k, from
//! behind and from in front; and LiSPSM must reach the uniform map continuously as γ → 0.

mod common;

use common::close;
use glam::DVec3;
use shadow_aliasing::analytic::partition::{
    scheme_storage_factor, Scheme, SchemeLight, MAX_PARTITIONS,
};
use shadow_aliasing::maps::{warp, WarpRule};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::scheme::{scheme, Partition};
use shadow_aliasing::ViewFrustum;

const BEHIND: DVec3 = DVec3::NEG_Z;
const IN_FRONT: DVec3 = DVec3::Z;

fn measured(view: &ViewFrustum, light: DVec3, rule: WarpRule) -> f64 {
    let s = warp(view, light, rule).unwrap();
    frustum_max(view, &s.shadow_map()).unwrap().storage_factor
}

/// A single map with the light behind or in front, f/n = 10, θ = 30°: the uniform map has
/// S̄ = (f/n)² = 100 (Eq 20 with k = 1: the square far plane seen face-on holds the near plane's
/// pixels at f/n times their size in both directions). LiSPSM is that map exactly. The fixed
/// overhead n′ = n + √(f n) keeps a warp that only stretches the map along the view: 4.27×.
#[test]
fn lispsm_is_the_uniform_map_behind_and_in_front() {
    let view = ViewFrustum::new(1.0, 10.0, 30f64.to_radians()).unwrap();
    for light in [BEHIND, IN_FRONT] {
        let uniform = measured(&view, light, WarpRule::Uniform);
        assert!(close(uniform, 100.0, 1e-12), "uniform {uniform}");
        let lispsm = measured(&view, light, WarpRule::Lispsm);
        assert!(close(lispsm, 100.0, 1e-12), "LiSPSM {lispsm}");
        let fixed = measured(&view, light, WarpRule::LispsmFixed);
        assert!(fixed > 4.0 * uniform, "fixed n′ {fixed}");
    }
    // f/n = 1000: the fixed n′ is two orders of magnitude worse than the uniform map (10⁶).
    let deep = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap();
    let uniform = measured(&deep, BEHIND, WarpRule::Uniform);
    assert!(close(uniform, 1e6, 1e-12), "{uniform}");
    assert!(close(measured(&deep, BEHIND, WarpRule::Lispsm), 1e6, 1e-12));
    assert!(measured(&deep, BEHIND, WarpRule::LispsmFixed) > 100.0 * uniform);
}

/// Eq 20 for ZP (uniform maps) and ZP+W (LiSPSM maps) and Eq 21 for FP+ZP+W, at every k the
/// crate allows, from behind and from in front, f/n = 10 and 1000, θ = 30° (Eq 21's value for a
/// square image does not depend on θ: each side face is an overhead frustum of half angle 45°).
#[test]
fn partitions_match_eq20_and_eq21_behind_and_in_front_at_every_k() {
    for alpha in [10.0, 1000.0] {
        let view = ViewFrustum::new(1.0, alpha, 30f64.to_radians()).unwrap();
        for k in 1..=MAX_PARTITIONS {
            let eq20 = scheme_storage_factor(Scheme::Zp, SchemeLight::Behind, &view, k).unwrap();
            let eq21 = scheme_storage_factor(Scheme::FpZpW, SchemeLight::Behind, &view, k).unwrap();
            // The closed forms by hand: k (f/n)^{2/k} and 2 k ((f/n)^{1/k} − 1) + 1.
            let r = alpha.powf(1.0 / k as f64);
            assert!(close(eq20, k as f64 * r * r, 1e-12));
            assert!(close(eq21, 2.0 * k as f64 * (r - 1.0) + 1.0, 1e-12));
            for light in [BEHIND, IN_FRONT] {
                for (rule, name) in [(WarpRule::Uniform, "ZP"), (WarpRule::Lispsm, "ZP+W")] {
                    let got = scheme(&view, light, rule, Partition::Log, k)
                        .unwrap()
                        .storage_factor();
                    assert!(
                        close(got, eq20, 1e-9),
                        "{name} f/n={alpha} k={k} {light}: {got} vs Eq 20 {eq20}"
                    );
                }
                let got = scheme(&view, light, WarpRule::Lispsm, Partition::Faces, k)
                    .unwrap()
                    .storage_factor();
                assert!(
                    close(got, eq21, 1e-9),
                    "FP+ZP+W f/n={alpha} k={k} {light}: {got} vs Eq 21 {eq21}"
                );
            }
        }
    }
}

/// The review's case: ZP+W behind, f/n = 10, k = 2 is Eq 20's 2 · 10 = 20 with LiSPSM; the
/// fixed overhead n′ gave 56.06 under the name LiSPSM.
#[test]
fn zp_w_behind_k2_is_twenty() {
    let view = ViewFrustum::new(1.0, 10.0, 30f64.to_radians()).unwrap();
    let s = scheme(&view, BEHIND, WarpRule::Lispsm, Partition::Log, 2).unwrap();
    assert!(
        close(s.storage_factor(), 20.0, 1e-12),
        "{}",
        s.storage_factor()
    );
    let fixed = scheme(&view, BEHIND, WarpRule::LispsmFixed, Partition::Log, 2).unwrap();
    assert!(
        fixed.storage_factor() > 2.5 * 20.0,
        "{}",
        fixed.storage_factor()
    );
}

/// Continuity in γ: as the light turns toward the view direction (from above, behind), LiSPSM's
/// S̄ tends to the uniform map's 100 (f/n = 10, θ = 30°); n′ ∝ 1/sin γ, so the warp's effect,
/// and the gap to the uniform map, shrink in proportion to γ: within 10 γ relative.
#[test]
fn lispsm_tends_continuously_to_the_uniform_map() {
    let view = ViewFrustum::new(1.0, 10.0, 30f64.to_radians()).unwrap();
    for j in 2..=9 {
        let g = 10f64.powi(-j);
        for light in [
            DVec3::new(0.0, -g.sin(), -g.cos()),
            DVec3::new(0.0, -g.sin(), g.cos()),
        ] {
            let s = measured(&view, light, WarpRule::Lispsm);
            assert!(
                (s - 100.0).abs() <= 10.0 * g * 100.0,
                "γ = {g}: S̄ = {s} (uniform 100)"
            );
        }
    }
}
