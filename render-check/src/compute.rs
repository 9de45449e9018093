//! The crate's WGSL module run in a compute pass, for tests that execute its functions one by
//! one (render-check/tests/wgsl_kernel.rs, lens_kernel.rs): a shader of `SHADOW_WGSL` and an
//! entry point `main` of the caller's, three storage bindings (0: the records, 1: the cases, 2:
//! the results, `f32`s), one invocation per case.

use shadow_aliasing::frame::{GpuShadowMap, SHADOW_WGSL};

/// The four functions the module asks its includer for, over the records at binding 0 (no
/// texture: a harness calls no lookup), and bindings 1 (the cases, `array<T>` of the caller's
/// `T`) and 2 (`results: array<f32>`). The caller's text follows: `@compute @workgroup_size(1) fn
/// main(@builtin(global_invocation_id) id: vec3<u32>)`.
pub fn harness_prelude(case_type: &str) -> String {
    format!(
        "
@group(0) @binding(0) var<storage, read> records: array<GpuShadowMap>;
@group(0) @binding(1) var<storage, read> cases: array<{case_type}>;
@group(0) @binding(2) var<storage, read_write> results: array<f32>;
fn sa_map(i: u32) -> GpuShadowMap {{ return records[i]; }}
fn sa_map_count() -> u32 {{ return arrayLength(&records); }}
fn sa_map_resolution() -> f32 {{ return 1024.0; }}
fn sa_stored_depth(i: u32, texel: vec2<i32>) -> f32 {{ return 1.0; }}
"
    )
}

/// Runs `SHADOW_WGSL` + `harness` (its [`harness_prelude`] and `main`) over `records` and the
/// little-endian `cases` bytes in `invocations` invocations; the `results` binding, `outputs`
/// `f32`s long, read back.
///
/// # Errors
/// No adapter ([`crate::gpu::NO_ADAPTER`]), the device's or the shader's error, the read-back's.
pub fn run(
    label: &str,
    harness: &str,
    records: &[GpuShadowMap],
    cases: &[u8],
    invocations: u32,
    outputs: usize,
) -> Result<Vec<f32>, String> {
    let (device, queue, _) = crate::gpu::device(label)?;
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let source = format!("{SHADOW_WGSL}{harness}");
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(label),
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    let storage = |name: &str, bytes: &[u8], usage| {
        let b = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(name),
            size: bytes.len() as u64,
            usage: usage | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        queue.write_buffer(&b, 0, bytes);
        b
    };
    let record_bytes: Vec<u8> = records.iter().flat_map(|r| r.to_bytes()).collect();
    let out_size = (outputs * 4) as u64;
    let recs = storage("records", &record_bytes, wgpu::BufferUsages::STORAGE);
    let input = storage("cases", cases, wgpu::BufferUsages::STORAGE);
    let out = storage(
        "results",
        &vec![0u8; outputs * 4],
        wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
    );
    let back = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: out_size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let entries: Vec<wgpu::BindGroupEntry<'_>> = [&recs, &input, &out]
        .into_iter()
        .zip(0..)
        .map(|(b, binding)| wgpu::BindGroupEntry {
            binding,
            resource: b.as_entire_binding(),
        })
        .collect();
    let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(label),
        layout: &pipeline.get_bind_group_layout(0),
        entries: &entries,
    });
    let mut enc = device.create_command_encoder(&Default::default());
    {
        let mut pass = enc.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind, &[]);
        pass.dispatch_workgroups(invocations, 1, 1);
    }
    enc.copy_buffer_to_buffer(&out, 0, &back, 0, out_size);
    queue.submit([enc.finish()]);
    if let Some(e) = pollster::block_on(scope.pop()) {
        return Err(format!("{label}: {e}"));
    }
    let slice = back.slice(..);
    slice.map_async(wgpu::MapMode::Read, |_| {});
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| format!("{label}: waiting for the GPU: {e}"))?;
    let data = slice
        .get_mapped_range()
        .map_err(|e| format!("{label}: reading back: {e}"))?;
    Ok(data
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect())
}
