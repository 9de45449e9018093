//! The crate's WGSL module (`shadow_aliasing::frame::SHADOW_WGSL`, issue 23 item 6) is valid WGSL
//! to naga, the compiler wgpu uses: alone with the four functions it asks its includer for, and
//! as render-check's shaders include it (the module's text, not a copy, before render-check's
//! own). The GPU runs of tests/render.rs then exercise it on every case.

use render_check::gpu::shader_source;
use shadow_aliasing::frame::{GpuShadowMap, GPU_SHADOW_MAP_WGSL, SHADOW_WGSL};

/// Parses and validates `source` with naga's WGSL front end and full validation; the module.
fn validate(source: &str) -> naga::Module {
    let module = naga::front::wgsl::parse_str(source)
        .unwrap_or_else(|e| panic!("{}", e.emit_to_string(source)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{}", e.emit_to_string(source)));
    module
}

/// The smallest includer: the four functions over a storage buffer of records and a depth array.
const HOOKS: &str = "
@group(0) @binding(0) var<storage, read> records: array<GpuShadowMap>;
@group(0) @binding(1) var maps: texture_depth_2d_array;
fn sa_map(i: u32) -> GpuShadowMap { return records[i]; }
fn sa_map_count() -> u32 { return arrayLength(&records); }
fn sa_map_resolution() -> f32 { return f32(textureDimensions(maps).x); }
fn sa_stored_depth(i: u32, texel: vec2<i32>) -> f32 { return textureLoad(maps, texel, i32(i), 0); }
@fragment
fn main(@location(0) p: vec3<f32>, @location(1) n: vec3<f32>, @location(2) e: vec3<f32>) -> @location(0) vec4<f32> {
    let l = vec3<f32>(0.0, -1.0, 0.0);
    let a = sa_cascaded_visibility(-e.z, p, n, l, 1, SA_NORMAL_OFFSET | SA_DEPTH_BIAS);
    let f = sa_pick_face(p, e, l, vec4<f32>(0.1, 100.0, 0.5, 0.7));
    let b = sa_visibility(min(f, sa_map_count() - 1u), p, n, l, 0, 0u);
    let c = sa_clipmap_level(-e.z, 3.2, 6, 22);
    return vec4<f32>(a, b, f32(c), 1.0);
}
";

/// The module with a minimal includer validates, and declares every function the docs name
/// (each reachable from the entry point).
#[test]
fn the_module_validates_with_naga() {
    let source = format!("{SHADOW_WGSL}{HOOKS}");
    let module = validate(&source);
    for name in [
        "sa_project",
        "sa_on_map",
        "sa_texel",
        "sa_depth_lit",
        "sa_kernel_scale",
        "sa_offset_point",
        "sa_depth_bias",
        "sa_visibility",
        "sa_pick_cascade",
        "sa_cascaded_visibility",
        "sa_face_crossing",
        "sa_pick_face",
        "sa_clipmap_level",
        "sa_error_lens",
        "sa_lens_colour",
    ] {
        assert!(
            module
                .functions
                .iter()
                .any(|(_, f)| f.name.as_deref() == Some(name)),
            "{name}"
        );
    }
    // The record as naga lays it out: 144 bytes, the Rust record's size.
    let record = module
        .types
        .iter()
        .find(|(_, t)| t.name.as_deref() == Some("GpuShadowMap"))
        .expect("the record's struct")
        .1;
    match &record.inner {
        naga::TypeInner::Struct { span, .. } => {
            assert_eq!(*span as usize, GpuShadowMap::SIZE)
        }
        other => panic!("{other:?}"),
    }
}

/// Without the includer's four functions the module does not validate: it reads the maps only
/// through them (nothing of the includer is copied into it).
#[test]
fn the_module_needs_the_includers_functions() {
    assert!(naga::front::wgsl::parse_str(SHADOW_WGSL).is_err());
}

/// render-check's shader source is the crate's module, byte for byte, followed by render-check's
/// own text, and validates.
#[test]
fn render_checks_shaders_include_the_module() {
    let source = shader_source();
    assert!(source.starts_with(SHADOW_WGSL), "the module comes first");
    assert!(SHADOW_WGSL.starts_with(GPU_SHADOW_MAP_WGSL));
    let own = &source[SHADOW_WGSL.len()..];
    assert!(!own.contains("fn sa_visibility") && !own.contains("struct GpuShadowMap"));
    validate(&source);
}
