//! The crate's WGSL shadow lookup (issue 23, item 6): [`SHADOW_WGSL`], the text of
//! `src/frame/shadow.wgsl` after the [`GpuShadowMap`](super::GpuShadowMap) record's declaration
//! [`GPU_SHADOW_MAP_WGSL`], to concatenate before a renderer's own shader. It covers the lookup
//! (the w-divide and each clip-depth convention), cascade selection by `split` and cross-fade over
//! `blend`, the face choice of face partitions, and the normal offset, depth bias and PCF in
//! texel units from the record's bias values. docs/renderer.md ("The WGSL module") shows its use
//! with wgpu and what differs in Bevy; render-check's shaders include it.

use super::upload::GPU_SHADOW_MAP_WGSL;

/// The functions of the module (`src/frame/shadow.wgsl`) alone, without the record's
/// declaration.
const FUNCTIONS: &str = include_str!("shadow.wgsl");

const LEN: usize = GPU_SHADOW_MAP_WGSL.len() + FUNCTIONS.len();

/// `GPU_SHADOW_MAP_WGSL` followed by `FUNCTIONS`, at compile time (a static: a constant array
/// over 16 KiB would be copied wherever it is used).
static BYTES: [u8; LEN] = {
    let mut out = [0u8; LEN];
    let (a, b) = (GPU_SHADOW_MAP_WGSL.as_bytes(), FUNCTIONS.as_bytes());
    let mut i = 0;
    while i < a.len() {
        out[i] = a[i];
        i += 1;
    }
    while i < LEN {
        out[i] = b[i - a.len()];
        i += 1;
    }
    out
};

/// The WGSL shadow-lookup module: [`GPU_SHADOW_MAP_WGSL`] (the record and its `clip_depth` codes)
/// followed by `src/frame/shadow.wgsl`. Concatenate it before your shader, which declares the
/// three functions the module reads the maps through:
///
/// ```wgsl
/// fn sa_map(i: u32) -> GpuShadowMap         // map i's record (FrameMap::gpu, gpu_relative)
/// fn sa_map_count() -> u32                  // how many maps (at least 1)
/// fn sa_stored_depth(i: u32, texel: vec2<i32>) -> f32 // map i's stored depth at a texel
/// ```
///
/// (each map's resolution comes from its record, `resolution`; a map smaller than its
/// texture layer sits at the layer's texel (0, 0), its texel (x, y) the layer's), and calls `sa_visibility` (one map: w-divide, clip-depth convention, normal offset and/or
/// depth bias, PCF of radius r texels), `sa_pick_cascade` / `sa_cascaded_visibility` (selection
/// by `split`, cross-fade over `blend`) or `sa_pick_face` (face partitions), and for a heat
/// overlay `sa_error_lens` / `sa_lens_colour` (the error lens, [`super::lens`]). Every function is
/// prefixed `sa_` (the record's names excepted); the file's comments document each.
pub const SHADOW_WGSL: &str = match core::str::from_utf8(&BYTES) {
    Ok(s) => s,
    Err(_) => panic!("the WGSL module is UTF-8"),
};

#[cfg(test)]
mod tests {
    use super::*;

    /// The constant is the record's declaration and then the file, whole.
    #[test]
    fn the_module_is_the_record_then_the_file() {
        assert!(SHADOW_WGSL.starts_with(GPU_SHADOW_MAP_WGSL));
        assert!(SHADOW_WGSL.ends_with(FUNCTIONS));
        assert_eq!(
            SHADOW_WGSL.len(),
            GPU_SHADOW_MAP_WGSL.len() + FUNCTIONS.len()
        );
        assert!(FUNCTIONS.contains("fn sa_visibility("));
    }
}
