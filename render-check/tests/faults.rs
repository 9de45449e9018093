//! The fault suite has teeth at the tests' size: a few cheap faults (`render-check --fault`),
//! each on a case whose clean build meets every target, violate the target that should catch
//! them. `render-check --self-test` runs every fault over every set-up; docs/rendered.md lists
//! what catches each.

use render_check::faults::Fault;
use render_check::gpu::Gpu;
use render_check::run::{case_clip_depth, run_full, Render, Sizes};
use render_check::schemes::{setups, Scheme};
use render_check::self_test::target_name;
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
    let all = setups();
    let si = all.iter().position(|s| s.name == setup).unwrap();
    let s = &all[si];
    let mut sizes = Sizes { fault, ..SIZES };
    // Each case in the clip depth the binary draws it in.
    sizes.render.clip_depth = case_clip_depth(si, scheme);
    let r = run_full(gpu, &s.name, &s.scene, scheme, sizes).unwrap();
    violations(&r.summary)
}

/// The clean case meets every target; with `fault` it violates `target`. Returns the faulted
/// case's violations.
fn caught(setup: &str, scheme: Scheme, fault: Fault, target: &str) -> Vec<String> {
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("{e}"));
    let clean = violated(&gpu, setup, scheme, None);
    // A fault in the shaders' source runs on its own device.
    let gpu = match Fault::shader_source(Some(fault)) {
        Ok(src) if fault.changes_shader() => {
            Gpu::with_source(&src).unwrap_or_else(|e| panic!("{e}"))
        }
        Ok(_) => gpu,
        Err(e) => panic!("{e}"),
    };
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
    v
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
        "blend_mismatches (the cross-fade against the band the requested overlap makes)",
    );
}

/// LiSPSM's n′ without its 1/sin γ (γ = 5°: n′ 11.5 × too small): the warp fitted from the
/// GPU's texel coordinates parts from the paper's `1 + Δ/n′`.
#[test]
fn lispsm_without_sin_gamma_is_caught() {
    caught(
        "behind_5",
        Scheme::Lispsm,
        Fault::LispsmNoSin,
        "warp_rel_diff (w's ratio fitted from the texels against 1 + Δ/n′ of the paper)",
    );
}

/// TSM's focus line at ξ = −0.8: the focus line fitted from the texels lies 90 % down the map,
/// not Martin & Tan's 80 %.
#[test]
fn tsm_focus_at_minus_0_8_is_caught() {
    caught(
        "tilted_45",
        Scheme::Tsm,
        Fault::TsmFocus,
        "|tsm_focus_fraction − 0.8| (the focus line fitted from the texels, Martin & Tan)",
    );
}

/// Blend bands 1.5 × as wide as the overlap makes them: the shader's weights part from the
/// band computed from the request.
#[test]
fn blend_band_too_wide_is_caught() {
    caught(
        "overhead",
        Scheme::BlendedCascades,
        Fault::BlendWide,
        "blend_mismatches (the cross-fade against the band the requested overlap makes)",
    );
}

/// The overlap dropped: no pixel is cross-faded where the request puts a band.
#[test]
fn overlap_dropped_is_caught() {
    caught(
        "overhead",
        Scheme::BlendedCascades,
        Fault::OverlapDropped,
        "blend_mismatches (the cross-fade against the band the requested overlap makes)",
    );
}

/// The upload origin rounded through `f32` (the camera 10⁵ from the origin, off an `f32`): every
/// texel position moves by the rounding.
#[test]
fn upload_origin_through_f32_is_caught() {
    caught(
        "far_1e5",
        Scheme::Uniform,
        Fault::OriginF32,
        "texel_position_p99 (the GPU's texel position against the exact point's, texels)",
    );
}

/// Every split 3 % past its map: pixels beyond a split plane are looked up in the map before it.
#[test]
fn splits_past_their_maps_are_caught() {
    caught(
        "tilted_45",
        Scheme::Cascades,
        Fault::SplitsPast,
        "split_mismatches (the map picked against the paper's split planes)",
    );
}

/// The reversed-depth comparison strict: under the overhead light the ground's depth equals the
/// stored one, and it is shadowed by itself.
#[test]
fn strict_reversed_comparison_is_caught() {
    caught(
        "overhead",
        Scheme::Uniform,
        Fault::ReversedStrict,
        "false_shadows",
    );
}

/// The records' depth bias and normal offset halved: on the paths that apply them alone, lit
/// ground under the 45° light shadows itself at its texels' far corners (acne), which the texels
/// read prove to hold the ground, lit.
#[test]
fn bias_halved_is_caught() {
    caught(
        "tilted_45",
        Scheme::Uniform,
        Fault::BiasHalved,
        "acne in path depth_bias (lit pixels shaded below 1 on their own lit face)",
    );
}

/// The PCF kernel reaching 2r texels: the GPU's shaded fraction is no longer the (2r + 1)² taps'
/// that render-check reads back from the depth maps.
#[test]
fn pcf_radius_doubled_is_caught() {
    caught(
        "tilted_45",
        Scheme::Uniform,
        Fault::PcfRadiusDoubled,
        "tap_mismatches in path pcf1_local_normal_offset (the GPU's shaded fraction against the \
         taps re-evaluated from the read-back maps)",
    );
}

/// The normal offset twice too large (record and per point, in the Rust the lookup is modelled
/// with and in the WGSL alike): shadowed pixels near the boxes' feet are lit by a lookup lifted
/// beyond the need (peter-panning).
#[test]
fn normal_offset_doubled_detaches_shadows() {
    caught(
        "tilted_45",
        Scheme::Uniform,
        Fault::NormalOffsetDoubled,
        "detached in path pcf1_local_normal_offset (shadowed pixels lit by a lookup lifted beyond \
         the need)",
    );
}

/// The uniform map 1.2 × as wide as its body, its error reported 1.2 × larger with it: the
/// frame's own ratios cannot see it (rendered over reported stays 1), the paper's map can (the
/// rendered m_x, m_z are 1.2 × the paper's at every pixel).
#[test]
fn a_uniform_map_too_wide_and_honestly_reported_is_caught() {
    let v = caught(
        "behind_5",
        Scheme::Uniform,
        Fault::UniformWide,
        "paper_error_p99 (rendered m_x, m_z against the paper's map, Lloyd 2006 §4.4)",
    );
    assert!(
        !v.iter()
            .any(|x| x.starts_with("frame_error_ratio") || x.starts_with("lens_frame_ratio")),
        "{v:?}"
    );
}

/// n′ × 2 in the minimax map (whose n′ the warp fit of LiSPSM does not check): the rendered
/// m_x, m_z part from the paper's map for the n′ the frame reports.
#[test]
fn minimax_n_prime_doubled_is_caught_by_the_paper() {
    caught(
        "tilted_45",
        Scheme::Minimax,
        Fault::NPrimeDouble,
        "paper_error_p99 (rendered m_x, m_z against the paper's map, Lloyd 2006 §4.4)",
    );
}

/// PSM's n′ doubled in the crate's rule, everything the frame reports following it: the frame's
/// own ratios cannot see it (rendered over reported stays within 1 %), the warp fitted from the
/// texels against PSM's n′ = n_B from the paper (9) and the paper's map (12) can.
#[test]
fn psm_n_prime_doubled_in_the_rule_is_caught_by_the_paper() {
    let v = caught(
        "tilted_45",
        Scheme::Psm,
        Fault::PsmNPrimeDouble,
        "paper_error_p99 (rendered m_x, m_z against the paper's map, Lloyd 2006 §4.4)",
    );
    assert!(v.iter().any(|x| x.starts_with("warp_rel_diff")), "{v:?}");
    assert!(
        !v.iter()
            .any(|x| x.starts_with("frame_error_ratio") || x.starts_with("lens_frame_ratio")),
        "{v:?}"
    );
}

/// Cascade selection off by one under the overhead light: every shadow-edge point lies in a
/// split whose faulted map does not hold it, so the shimmer test follows none; the case still
/// reports what it measured (the pixels outside their map), where it used to end in an error
/// that the self-test counted as neither caught nor clean.
#[test]
fn cascade_off_by_one_under_the_overhead_light_is_caught() {
    let v = caught(
        "overhead",
        Scheme::Cascades,
        Fault::CascadeOffByOne,
        "uncovered_pixels",
    );
    assert!(
        v.iter().any(|x| x.starts_with("shimmer_points = 0")),
        "{v:?}"
    );
}

/// The receivers left out of the frame: every focus body grows to its whole view slice, and the
/// frame's reported numbers follow it, so the rendered error still agrees with the report; the
/// level set-up, built so that every scheme's worst body point is on screen, finds that point
/// off the visible ground, and a two-sided check that did not run is a violation, not a pass.
#[test]
fn receivers_left_out_lose_the_worst_point_of_the_level_set_up() {
    caught(
        "level_side",
        Scheme::Lispsm,
        Fault::ReceiversUnbounded,
        "frame_error_ratio_worst_visible (null, not measured where the set-up puts every \
         scheme's worst body point on screen)",
    );
}
