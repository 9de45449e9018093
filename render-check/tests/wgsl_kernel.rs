//! The WGSL module's PCF scaling executed on the GPU (wgpu compute on Vulkan; lavapipe without a
//! GPU): a record's bias values are for the kernel radius it carries (`bias_radius`), and
//! `sa_kernel_scale(m, r)` rescales them to the shader's r, so a record from `gpu_with_pcf(r)`
//! filtered with the same r counts the kernel once. The expected values are the library's `f64`
//! bias for the shader's r (`FrameMap::bias`), computed directly, not by scaling.

use glam::DVec3;
use shadow_aliasing::frame::{frame, Aabb, Bound, Camera, FrameInput, GpuShadowMap, SHADOW_WGSL};
use shadow_aliasing::maps::ClipDepth;

/// The includer's four functions (no texture: the lookups are not called) and an entry point
/// that writes, per case, the kernel scale, the depth bias of a surface facing the light
/// (tan α = 0: `constant_depth` times the scale) and the normal offset `sa_offset_point` moves by.
const HARNESS: &str = "
@group(0) @binding(0) var<storage, read> records: array<GpuShadowMap>;
@group(0) @binding(1) var<storage, read> radii: array<i32>;
@group(0) @binding(2) var<storage, read_write> results: array<f32>;
fn sa_map(i: u32) -> GpuShadowMap { return records[i]; }
fn sa_map_count() -> u32 { return arrayLength(&records); }
fn sa_map_resolution() -> f32 { return 1024.0; }
fn sa_stored_depth(i: u32, texel: vec2<i32>) -> f32 { return 1.0; }
@compute @workgroup_size(1)
fn main(@builtin(global_invocation_id) id: vec3<u32>) {
    let i = id.x;
    let m = records[i];
    let r = radii[i];
    let up = vec3<f32>(0.0, 1.0, 0.0);
    results[3u * i] = sa_kernel_scale(m, r);
    results[3u * i + 1u] = sa_depth_bias(m, up, -up, r);
    results[3u * i + 2u] = length(sa_offset_point(m, vec3<f32>(0.0), up, r));
}
";

/// Runs the harness over `records` with the shader radii `radii`: (scale, depth bias, offset).
fn run(records: &[GpuShadowMap], radii: &[i32]) -> Vec<[f32; 3]> {
    let (device, queue, _) =
        render_check::gpu::device("wgsl_kernel").unwrap_or_else(|e| panic!("{e}"));
    let source = format!("{SHADOW_WGSL}{HARNESS}");
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("harness"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some("harness"),
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    let storage = |label, bytes: &[u8], usage| {
        let b = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: bytes.len() as u64,
            usage: usage | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        queue.write_buffer(&b, 0, bytes);
        b
    };
    let record_bytes: Vec<u8> = records.iter().flat_map(|r| r.to_bytes()).collect();
    let radius_bytes: Vec<u8> = radii.iter().flat_map(|r| r.to_le_bytes()).collect();
    let out_size = (records.len() * 3 * 4) as u64;
    let recs = storage("records", &record_bytes, wgpu::BufferUsages::STORAGE);
    let rads = storage("radii", &radius_bytes, wgpu::BufferUsages::STORAGE);
    let out = storage(
        "results",
        &vec![0u8; out_size as usize],
        wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
    );
    let back = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: out_size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some("harness"),
        layout: &pipeline.get_bind_group_layout(0),
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: recs.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: rads.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: out.as_entire_binding(),
            },
        ],
    });
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(records.len() as u32, 1, 1);
    }
    enc.copy_buffer_to_buffer(&out, 0, &back, 0, out_size);
    queue.submit([enc.finish()]);
    let slice = back.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("the GPU finishes");
    let data = slice.get_mapped_range().expect("mapped results");
    data.chunks_exact(12)
        .map(|c| {
            let f = |k: usize| f32::from_le_bytes(c[4 * k..4 * k + 4].try_into().unwrap());
            [f(0), f(1), f(2)]
        })
        .collect()
}

#[test]
fn a_pcf_record_filtered_with_its_own_radius_counts_the_kernel_once() {
    let ground = [Aabb::new([-60.0, -1.0, -60.0], [60.0, 0.0, 60.0]).unwrap()];
    let view = glam::dcamera::rh::view::look_at_mat4(
        DVec3::new(0.0, 6.0, 20.0),
        DVec3::new(2.0, 0.0, -10.0),
        DVec3::Y,
    );
    let camera = Camera::new(view, 0.5, 120.0, 0.6, 1.5).unwrap();
    let input = FrameInput::new(camera, DVec3::new(0.3, -0.8, -0.4), 1024, 720)
        .receivers(Bound::Boxes(&ground))
        .casters(Bound::Boxes(&ground));
    let f = frame(&input).unwrap();
    let m = &f.maps()[0];
    let depth = ClipDepth::ZeroToOne;
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
        // Each value ∝ r + ½ but the constant's 8 f32 ulps, which scaling only enlarges: the
        // normal offset is exact to f32; the constant depth is at least the f64 value.
        assert!(
            close(offset, want.normal_offset),
            "record r = {rec}, shader r = {r}: offset {offset} against bias({want_r}) = {}",
            want.normal_offset
        );
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
