//! The fault suite has teeth at the tests' size: a few cheap faults (`render-check --fault`),
//! each on a case whose clean build meets every target, violate the target that should catch
//! them. `render-check --self-test` runs every fault over every set-up; docs/rendered.md lists
//! what catches each.

use render_check::faults::{target_name, Fault};
use render_check::gpu::Gpu;
use render_check::run::{run_full, Render, Sizes};
use render_check::schemes::{setups, Scheme};
use render_check::targets::violations;

const SIZES: Sizes = Sizes {
    width: 240,
    height: 180,
    res: None,
    frames: 16,
    shimmer_points: 1500,
    fault: None,
    render: Render::DEFAULT,
};

fn violated(gpu: &Gpu, setup: &str, scheme: Scheme, fault: Option<Fault>) -> Vec<String> {
    let s = setups().into_iter().find(|s| s.name == setup).unwrap();
    let sizes = Sizes { fault, ..SIZES };
    let r = run_full(gpu, &s.name, &s.scene, scheme, sizes).unwrap();
    violations(&r.summary)
}

/// The clean case meets every target; with `fault` it violates `target`.
fn caught(setup: &str, scheme: Scheme, fault: Fault, target: &str) {
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("{e}"));
    let clean = violated(&gpu, setup, scheme, None);
    assert!(
        clean.is_empty(),
        "{setup}/{}: clean {clean:?}",
        scheme.name()
    );
    let v = violated(&gpu, setup, scheme, Some(fault));
    assert!(
        v.iter().any(|x| target_name(x) == target),
        "{setup}/{} with {}: {v:?}",
        scheme.name(),
        fault.name()
    );
}

/// The matrix scaled by 1.01 about the map centre: visible ground near the screen's edges falls
/// outside the map.
#[test]
fn matrix_scaled_is_uncovered() {
    caught(
        "tilted_45",
        Scheme::Lispsm,
        Fault::MatrixScale,
        "uncovered_pixels",
    );
}

/// Cascade selection off by one: pixels of a split looked up in the next cascade, which does not
/// hold them.
#[test]
fn cascade_off_by_one_is_uncovered() {
    caught(
        "tilted_45",
        Scheme::Cascades,
        Fault::CascadeOffByOne,
        "uncovered_pixels",
    );
}

/// The frame built for a light 0.5° off: shadows drawn where the ray cast finds light.
#[test]
fn light_rotated_draws_false_shadows() {
    caught(
        "tilted_45",
        Scheme::Uniform,
        Fault::LightRotated,
        "false_shadows",
    );
}

/// n′ × 2: the rendered error exceeds what the frame reported for the map (by 20 % at
/// 320 × 240 in the self-test).
#[test]
fn n_prime_doubled_exceeds_the_reported_error() {
    caught(
        "overhead",
        Scheme::Cascades,
        Fault::NPrimeDouble,
        "frame_error_ratio − 1 (rendered M_x, M_z over the frame's reported)",
    );
}

/// The plain `f32` world matrix (`FrameMap::gpu`, world positions in `f32`) 10⁵ from the
/// origin, in place of the relative path: the rendered texel positions jitter, and their
/// derivatives part from the predicted footprint (p99 3 % at 240 × 180). The same set-up through
/// the relative path meets every target (tests/render.rs).
#[test]
fn plain_world_matrix_far_from_the_origin_is_caught() {
    caught(
        "far_1e5",
        Scheme::Uniform,
        Fault::PlainWorld,
        "p99_rel_diff",
    );
}

/// Culling too tight (the casters' volume cut to the view slice): the tower behind the camera,
/// outside the view, is no longer drawn into the maps and its long shadow is lost.
#[test]
fn culling_too_tight_drops_a_caster() {
    caught(
        "behind_5",
        Scheme::Uniform,
        Fault::CullTight,
        "shadow_misses",
    );
}

/// The blend band ignored (the band shaded by its first map alone, not cross-faded): where the
/// band's two maps' lookups differ, the shaded visibility is not their weighted pair (15 pixels
/// of the thin-caster scene's blended cascades at 240 × 180; the clean build: 0).
#[test]
fn blend_band_ignored_is_caught() {
    caught(
        "thin_casters",
        Scheme::BlendedCascades,
        Fault::BlendIgnored,
        "blend_mismatches (the cross-fade against the frame's blend)",
    );
}
