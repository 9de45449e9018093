//! The WGSL module's PCF scaling executed on the GPU (wgpu compute on Vulkan; lavapipe without a
//! GPU): a record's bias values are for the kernel radius it carries (`bias_radius`), and
//! `sa_kernel_scale(m, r)` rescales them to the shader's r, so a record from `gpu_with_pcf(r)`
//! filtered with the same r counts the kernel once. The expected depth bias is the library's `f64`
//! bias for the shader's r (`FrameMap::bias`), computed directly, not by scaling; the normal
//! offset covers that radius's record and is the record's scaled by s (1 − τ)/(1 − s τ)
//! (`sa_offset_scale`: a perspective map's offset outgrows the kernel's reach).

mod common;

use glam::DVec3;
use render_check::compute;
use shadow_aliasing::frame::{frame, GpuShadowMap};
use shadow_aliasing::maps::ClipDepth;

/// The entry point after `compute::harness_prelude("i32")` (the cases are the shader's radii): it
/// writes, per case, the kernel scale, the depth bias of a surface facing the light
/// (tan α = 0: `constant_depth` times the scale) and the normal offset `sa_offset_point` moves by.
const MAIN: &str = "
@compute @workgroup_size(1)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    let m = records[i];
    let r = cases[i];
    let up = vec3<f32>(0.0, 1.0, 0.0);
    results[3u * i] = sa_kernel_scale(m, r);
    results[3u * i + 1u] = sa_depth_bias(m, up, -up, r);
    results[3u * i + 2u] = length(sa_offset_point(m, vec3<f32>(0.0), up, r));
}
";

/// Runs the harness over `records` with the shader radii `radii`: (scale, depth bias, offset).
fn run(records: &[GpuShadowMap], radii: &[i32]) -> Vec<[f32; 3]> {
    let harness = format!("{}{MAIN}", compute::harness_prelude("i32"));
    let bytes: Vec<u8> = radii.iter().flat_map(|r| r.to_le_bytes()).collect();
    compute::run(
        "wgsl_kernel",
        &harness,
        records,
        &bytes,
        radii.len() as u32,
        radii.len() * 3,
    )
    .unwrap_or_else(|e| panic!("{e}"))
    .chunks_exact(3)
    .map(|c| [c[0], c[1], c[2]])
    .collect()
}

#[test]
fn a_pcf_record_filtered_with_its_own_radius_counts_the_kernel_once() {
    let ground = common::ground();
    let input = common::input(&ground, DVec3::new(0.3, -0.8, -0.4), 1024);
    let f = frame(&input).unwrap();
    let m = &f.maps()[0];
    let depth = ClipDepth::ZeroToOne;
    // The default scheme's warped map: its normal offset outgrows the kernel (τ > 0), so the
    // scaling below is not the depth bias's.
    assert!(m.bias(0.0, depth).unwrap().normal_offset_growth > 0.0);
    // (record's radius, shader's radius, the radius whose f64 bias the GPU must give).
    let cases = [
        (0.0, 0, 0.0),
        (0.0, 2, 2.0),
        (2.0, 2, 2.0),
        (2.0, 0, 2.0),
        (1.0, 3, 3.0),
    ];
    let records: Vec<GpuShadowMap> = cases
        .iter()
        .map(|&(rec, _, _)| m.gpu_with_pcf(depth, rec).unwrap())
        .collect();
    let radii: Vec<i32> = cases.iter().map(|c| c.1).collect();
    let got = run(&records, &radii);
    for (&(rec, r, want_r), [scale, depth_bias, offset]) in cases.iter().zip(got) {
        let want = m.bias(want_r, depth).unwrap();
        let close = |a: f32, b: f64| (f64::from(a) - b).abs() <= 1e-5 * b.abs();
        // The normal offset: the record's, scaled by s (1 − τ)/(1 − s τ), s the kernel's factor
        // on the reach, and never under the f64 record for the shader's own radius.
        let record = m.bias(rec, depth).unwrap();
        let s = ((2.0 * f64::from(r) + 1.0) / (2.0 * rec + 1.0)).max(1.0);
        let tau = record.normal_offset_growth;
        let scaled = record.normal_offset * s * (1.0 - tau) / (1.0 - s * tau);
        assert!(
            close(offset, scaled),
            "record r = {rec}, shader r = {r}: offset {offset} against s (1 − τ)/(1 − s τ) × {} = {scaled}",
            record.normal_offset
        );
        assert!(
            f64::from(offset) >= want.normal_offset * (1.0 - 1e-5),
            "record r = {rec}, shader r = {r}: offset {offset} under bias({want_r}) = {}",
            want.normal_offset
        );
        // The constant depth ∝ r + ½ but its 8 f32 ulps, which scaling only enlarges: at least
        // the f64 value.
        let (d, w) = (f64::from(depth_bias).abs(), want.constant_depth.abs());
        // The scaled 8 ulps: at most (2r + 1) · 8 · 2⁻²³ over the f64 value (depth in [0, 1]).
        let ulps = (2.0 * want_r + 1.0) * 8.0 * 2f64.powi(-23);
        assert!(
            d >= w * (1.0 - 1e-6) && d <= w + ulps,
            "record r = {rec}, shader r = {r}: depth bias {depth_bias} against bias({want_r}) = {}",
            want.constant_depth
        );
        let ratio = (2.0 * want_r + 1.0) / (2.0 * rec + 1.0);
        assert!(
            (f64::from(scale) - ratio).abs() <= 1e-6,
            "{scale} against {ratio}"
        );
    }
}
