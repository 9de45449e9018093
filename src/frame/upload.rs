//! What a renderer uploads, in forms that do not depend on the glam version: every matrix as
//! plain column-major `f32` arrays, one `#[repr(C)]` plain-data record per map
//! ([`GpuShadowMap`]) whose WGSL/std140 layout is [`GPU_SHADOW_MAP_WGSL`], and, with the `mint`
//! feature, the matrices as mint types. docs/renderer.md ("Uploading") tabulates every value.
//
// The only unsafe code of the crate: bytemuck's derive of `Pod` and `Zeroable` (feature
// `bytemuck`) writes `unsafe impl`s for the record, whose fields are all 4-byte scalars with no
// padding between them (tests/upload.rs checks every offset).
#![cfg_attr(feature = "bytemuck", allow(unsafe_code))]

use super::output::FrameMap;
use crate::maps::matrix::in_clip_depth;
use crate::maps::ClipDepth;
use glam::{DMat4, DVec3, Mat4};

/// One map as a GPU uniform or storage-buffer element: `#[repr(C)]`, 144 bytes, every field a
/// 4-byte scalar or an array of them, laid out exactly as the WGSL struct
/// [`GPU_SHADOW_MAP_WGSL`] in the `uniform` and `storage` address spaces and as the same block in
/// GLSL's std140 and std430 (tests/upload.rs computes each offset by those rules), so an array of
/// them has a 144-byte stride in every one of these layouts. Write it with
/// [`GpuShadowMap::to_bytes`] or, with the `bytemuck` feature, `bytemuck::bytes_of`.
///
/// | field | byte offset | WGSL type |
/// |---|---|---|
/// | `world_to_clip` | 0 | `mat4x4<f32>` |
/// | `split` | 64 | `vec2<f32>` |
/// | `blend` | 72 | `vec2<f32>` |
/// | `texel_world` | 80 | `f32` |
/// | `max_error_pixels` | 84 | `f32` |
/// | `max_mx` | 88 | `f32` |
/// | `max_mz` | 92 | `f32` |
/// | `face` | 96 | `u32` |
/// | `clip_depth` | 100 | `u32` |
/// | `normal_offset` | 104 | `f32` |
/// | `slope_scaled_depth` | 108 | `f32` |
/// | `texel_extent` | 112 | `vec2<f32>` |
/// | `constant_depth` | 120 | `f32` |
/// | `bias_radius` | 124 | `f32` |
/// | `resolution` | 128 | `u32` |
/// | `normal_offset_growth` | 132 | `f32` |
/// | `reserved1`, `reserved2` | 136, 140 | `u32` |
///
/// The bias values are [`FrameMap::bias`]'s for a PCF kernel of radius `bias_radius` texels:
/// 0 (a single lookup) from [`FrameMap::gpu`] and [`FrameMap::gpu_relative`], r from
/// [`FrameMap::gpu_with_pcf`]. The depth bias is proportional to r + ½ (but for the constant's 8
/// `f32` ulps, which enlarging only enlarges), so a shader filtering with radius r scales it by
/// s = (2r + 1)/(2 `bias_radius` + 1), and by 1 where that is below 1 (a record built for a larger
/// kernel is kept, never shrunk): the WGSL module's `sa_kernel_scale(m, r)`. The normal offset
/// grows faster where the map is perspective (the offset point's own footprint: `frame::bias`):
/// by s (1 − τ)/(1 − s τ), τ = `normal_offset_growth` (0 for an orthographic map, where this is
/// s), the WGSL module's `sa_offset_scale(m, r)`. Uploading `gpu_with_pcf(depth, r)` and
/// filtering with the same r therefore counts the kernel once, and either upload covers a
/// larger kernel.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
#[cfg_attr(feature = "bytemuck", derive(bytemuck::Pod, bytemuck::Zeroable))]
pub struct GpuShadowMap {
    /// World → light clip, column-major (`world_to_clip[c][r]` is row r of column c, glam's
    /// `to_cols_array_2d`, WGSL's `m[c][r]`), in the convention `clip_depth` names.
    pub world_to_clip: [[f32; 4]; 4],
    /// [`FrameMap::split`]: the view-depth range (positive eye depth, world units) where the
    /// shader selects this map.
    pub split: [f32; 2],
    /// [`FrameMap::blend`]: the band, in view depth, to cross-fade over with the next map.
    pub blend: [f32; 2],
    /// [`FrameMap::texel_world`]: the largest world-space texel edge over the map's body.
    pub texel_world: f32,
    /// [`FrameMap::max_error_pixels`]: the predicted largest texel-to-pixel ratio; +∞ (no bound
    /// known) where the error was not measured ([`FrameMap::error`] `None`).
    pub max_error_pixels: f32,
    /// [`FrameMap::max_mx`]: M_x over the body (unit resolutions); +∞ where not measured.
    pub max_mx: f32,
    /// [`FrameMap::max_mz`]: M_z over the body (unit resolutions); +∞ where not measured.
    pub max_mz: f32,
    /// [`FrameMap::face`]: the index of the face in [`crate::maps::faces::Face::ALL`] (bottom 0,
    /// right 1, top 2, left 3, near 4, far 5), or [`GpuShadowMap::NO_FACE`].
    pub face: u32,
    /// The clip-depth convention of `world_to_clip`: [`GpuShadowMap::clip_depth_code`].
    pub clip_depth: u32,
    /// [`Bias::normal_offset`](super::Bias::normal_offset): world units along the surface's
    /// normal to move the lookup point.
    pub normal_offset: f32,
    /// [`Bias::slope_scaled_depth`](super::Bias::slope_scaled_depth): depth units per unit of
    /// tan α, to add to the receiver's depth in `clip_depth`'s convention (negative for codes 0
    /// and 1, positive for 2).
    pub slope_scaled_depth: f32,
    /// [`Bias::texel_extent`](super::Bias::texel_extent): the texel's largest world-space edges
    /// along s and t over B.
    pub texel_extent: [f32; 2],
    /// [`Bias::constant_depth`](super::Bias::constant_depth): depth units to add to the
    /// receiver's depth at any slope.
    pub constant_depth: f32,
    /// The PCF radius r (texels) the bias values were computed for: 0 from [`FrameMap::gpu`],
    /// r from [`FrameMap::gpu_with_pcf`].
    pub bias_radius: f32,
    /// The map's texels per side, at least 3 (maps of one frame may differ:
    /// [`FrameInput::map_resolutions`](super::FrameInput::map_resolutions)); the WGSL module's
    /// texel lookups read it, so a record built by hand must set it (`Default` leaves 0).
    pub resolution: u32,
    /// [`Bias::normal_offset_growth`](super::Bias::normal_offset_growth) τ for `bias_radius`,
    /// rounded up to `f32`: a kernel s times the record's reach needs s (1 − τ)/(1 − s τ) times
    /// `normal_offset` (0 for an orthographic map; a record built by hand with 0 claims one).
    pub normal_offset_growth: f32,
    /// Zero, as `reserved2`: they bring the record to 144 bytes, a multiple of 16, the
    /// alignment of `mat4x4<f32>` (as a uniform buffer's arrays need a stride of 16).
    /// Zero.
    pub reserved1: u32,
    /// Zero.
    pub reserved2: u32,
}

impl GpuShadowMap {
    /// The record's size in bytes.
    pub const SIZE: usize = 144;

    /// `face` of a map that is not a face partition's.
    pub const NO_FACE: u32 = u32::MAX;

    /// The number `clip_depth` holds for a convention: 0 for [`ClipDepth::NegOneToOne`], 1 for
    /// [`ClipDepth::ZeroToOne`], 2 for [`ClipDepth::Reversed`] (the WGSL constants
    /// `CLIP_DEPTH_NEG_ONE_TO_ONE`, `CLIP_DEPTH_ZERO_TO_ONE`, `CLIP_DEPTH_REVERSED` of
    /// [`GPU_SHADOW_MAP_WGSL`]).
    #[must_use]
    pub const fn clip_depth_code(depth: ClipDepth) -> u32 {
        match depth {
            ClipDepth::NegOneToOne => 0,
            ClipDepth::ZeroToOne => 1,
            ClipDepth::Reversed => 2,
        }
    }

    /// The record's bytes, little-endian (the byte order of every GPU wgpu and Vulkan run on;
    /// on a little-endian host the same bytes as `bytemuck::bytes_of`).
    #[must_use]
    pub fn to_bytes(&self) -> [u8; Self::SIZE] {
        let scalars = [
            self.texel_world,
            self.max_error_pixels,
            self.max_mx,
            self.max_mz,
        ];
        let bias = [
            self.normal_offset,
            self.slope_scaled_depth,
            self.texel_extent[0],
            self.texel_extent[1],
            self.constant_depth,
        ];
        let words = self
            .world_to_clip
            .iter()
            .flatten()
            .chain(&self.split)
            .chain(&self.blend)
            .chain(&scalars)
            .map(|v| v.to_bits())
            .chain([self.face, self.clip_depth])
            .chain(bias.map(f32::to_bits))
            .chain([self.bias_radius.to_bits(), self.resolution])
            .chain([self.normal_offset_growth.to_bits()])
            .chain([self.reserved1, self.reserved2]);
        let mut out = [0u8; Self::SIZE];
        for (chunk, w) in out.chunks_exact_mut(4).zip(words) {
            chunk.copy_from_slice(&w.to_le_bytes());
        }
        out
    }
}

/// The WGSL declaration of [`GpuShadowMap`] and of its `clip_depth` codes, to paste or
/// concatenate into a shader: bind it as `var<uniform> maps: array<GpuShadowMap, N>` or in a
/// storage buffer.
pub const GPU_SHADOW_MAP_WGSL: &str = "\
// shadow-aliasing's GpuShadowMap (144 bytes; the same offsets in std140 and std430).
const CLIP_DEPTH_NEG_ONE_TO_ONE: u32 = 0u;
const CLIP_DEPTH_ZERO_TO_ONE: u32 = 1u;
const CLIP_DEPTH_REVERSED: u32 = 2u;
const NO_FACE: u32 = 0xffffffffu;
struct GpuShadowMap {
    world_to_clip: mat4x4<f32>,
    split: vec2<f32>,
    blend: vec2<f32>,
    texel_world: f32,
    max_error_pixels: f32,
    max_mx: f32,
    max_mz: f32,
    face: u32,
    clip_depth: u32,
    normal_offset: f32,
    slope_scaled_depth: f32,
    texel_extent: vec2<f32>,
    constant_depth: f32,
    bias_radius: f32,
    resolution: u32,
    normal_offset_growth: f32,
    reserved1: u32,
    reserved2: u32,
}
";

impl FrameMap {
    /// [`FrameMap::to_mat4`] as plain column-major arrays (`[column][row]`), for a renderer on
    /// any math library.
    #[must_use]
    pub fn world_to_clip_cols(&self, depth: ClipDepth) -> [[f32; 4]; 4] {
        self.to_mat4(depth).to_cols_array_2d()
    }

    /// The map's [`GpuShadowMap`] with the world → clip matrix in `depth`'s convention. Every
    /// `f64` is rounded once to `f32`.
    #[must_use]
    pub fn gpu(&self, depth: ClipDepth) -> GpuShadowMap {
        self.record(self.world_to_clip_cols(depth), depth, 0.0)
    }

    /// [`FrameMap::gpu`] with the bias values for a PCF kernel of radius `r` texels
    /// ([`FrameMap::bias`]).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`](crate::Error::InvalidArgument) naming `r` when it is negative
    /// or not finite.
    pub fn gpu_with_pcf(&self, depth: ClipDepth, r: f64) -> crate::Result<GpuShadowMap> {
        self.bias(r, depth)?;
        Ok(self.record(self.world_to_clip_cols(depth), depth, r))
    }

    /// World → light clip for points given relative to `origin` (the camera's position, or the
    /// engine's floating origin), `clip = M_rel · (p − origin, 1)`, in `f64`: the map's eye → clip
    /// matrix times the camera's world → eye composed with the translation by `origin`, whose
    /// translation column is the eye-space position of `origin` (small when `origin` is near the
    /// camera, however far both are from the world origin).
    #[must_use]
    pub fn world_to_clip_relative_f64(&self, origin: impl Into<DVec3>, depth: ClipDepth) -> DMat4 {
        let mut to_eye = self.world_to_eye;
        to_eye.w_axis = self
            .world_to_eye
            .transform_point3(origin.into())
            .extend(1.0);
        in_clip_depth(&self.shadow.matrix(), depth) * to_eye
    }

    /// [`FrameMap::world_to_clip_relative_f64`] rounded once to `f32`: the matrix to upload with
    /// vertices relative to `origin`. Far from the world origin it keeps the map to within 0.01
    /// texel at B's vertices (tests/upload_precision.rs: cameras up to 10⁶ from it), where the
    /// plain [`FrameMap::to_mat4`] loses texels (docs/renderer.md, "Uploading").
    #[must_use]
    pub fn world_to_clip_relative(&self, origin: impl Into<DVec3>, depth: ClipDepth) -> Mat4 {
        self.world_to_clip_relative_f64(origin, depth).as_mat4()
    }

    /// What rounding to `f32` costs this map, in texels: the largest difference in s or t, over
    /// the focus body's vertices, between the `f64` map and the GPU's `f32` path, the matrix
    /// [`FrameMap::world_to_clip_relative`]`(origin, depth)` times the vertex's position
    /// `p − origin` rounded to `f32` as a vertex buffer holds it, in `f32` arithmetic.
    /// `origin = DVec3::ZERO` measures the plain [`FrameMap::to_mat4`]. The truth is the map's
    /// eye → clip matrix at B's eye-space vertices, in which no large number enters.
    ///
    /// Near the world origin the loss is the map's own conditioning: strongly warped parts (a
    /// texel far smaller than a pixel, M_x or M_z near 0) lose most (docs/renderer.md, "Far from
    /// the origin", tabulates it by scheme). Far from it, the plain matrix loses texels and the
    /// relative one does not. It costs one 4×4 product per vertex of B: call it when choosing an
    /// upload path or in a debug overlay, not every frame.
    #[must_use]
    pub fn upload_error_texels(&self, origin: impl Into<DVec3>, depth: ClipDepth) -> f64 {
        let origin = origin.into();
        let half = f64::from(self.resolution) / 2.0;
        let truth = self.shadow.matrix();
        let eye_to_world = self.world_to_eye.inverse();
        let m32 = self.world_to_clip_relative(origin, depth);
        self.body()
            .iter()
            .map(|p| {
                let h = truth * p.extend(1.0);
                let rel = (eye_to_world.transform_point3(*p) - origin).as_vec3();
                let g = m32 * rel.extend(1.0);
                let (gx, gy, gw) = (f64::from(g.x), f64::from(g.y), f64::from(g.w));
                let ds = (gx / gw - h.x / h.w).abs() * half;
                let dt = (gy / gw - h.y / h.w).abs() * half;
                // A vertex the f32 path sends to w = 0 or to a NaN has lost the map: infinite.
                if ds.is_nan() || dt.is_nan() {
                    f64::INFINITY
                } else {
                    ds.max(dt)
                }
            })
            .fold(0.0, f64::max)
    }

    /// [`FrameMap::world_to_clip_relative`] as plain column-major arrays.
    #[must_use]
    pub fn world_to_clip_relative_cols(
        &self,
        origin: impl Into<DVec3>,
        depth: ClipDepth,
    ) -> [[f32; 4]; 4] {
        self.world_to_clip_relative(origin, depth)
            .to_cols_array_2d()
    }

    /// [`FrameMap::gpu`] with [`FrameMap::world_to_clip_relative`] as its matrix.
    #[must_use]
    pub fn gpu_relative(&self, origin: impl Into<DVec3>, depth: ClipDepth) -> GpuShadowMap {
        self.record(self.world_to_clip_relative_cols(origin, depth), depth, 0.0)
    }

    /// [`FrameMap::gpu_relative`] with the bias values for a PCF kernel of radius `r` texels:
    /// the record a renderer with camera-relative positions and PCF uploads.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`](crate::Error::InvalidArgument) naming `r` when it is negative
    /// or not finite.
    pub fn gpu_relative_with_pcf(
        &self,
        origin: impl Into<DVec3>,
        depth: ClipDepth,
        r: f64,
    ) -> crate::Result<GpuShadowMap> {
        self.bias(r, depth)?;
        Ok(self.record(self.world_to_clip_relative_cols(origin, depth), depth, r))
    }

    fn record(&self, world_to_clip: [[f32; 4]; 4], depth: ClipDepth, r: f64) -> GpuShadowMap {
        let pair = |p: (f64, f64)| [p.0 as f32, p.1 as f32];
        let bias = self.bias_unchecked(r, depth);
        GpuShadowMap {
            world_to_clip,
            split: pair(self.split),
            blend: pair(self.blend),
            texel_world: self.texel_world as f32,
            max_error_pixels: self.max_error_pixels as f32,
            max_mx: self.max_mx as f32,
            max_mz: self.max_mz as f32,
            // `Face`'s declaration order is `Face::ALL`'s (tests/upload.rs).
            face: self.face.map_or(GpuShadowMap::NO_FACE, |f| f as u32),
            clip_depth: GpuShadowMap::clip_depth_code(depth),
            normal_offset: bias.normal_offset as f32,
            slope_scaled_depth: bias.slope_scaled_depth as f32,
            texel_extent: pair(bias.texel_extent),
            constant_depth: bias.constant_depth as f32,
            bias_radius: r as f32,
            resolution: self.resolution,
            normal_offset_growth: f32_up(bias.normal_offset_growth),
            reserved1: 0,
            reserved2: 0,
        }
    }

    /// [`FrameMap::to_mat4`] as a mint matrix (feature `mint`), which any glam version with its
    /// own mint feature (and cgmath, nalgebra, …) converts from.
    #[cfg(feature = "mint")]
    #[must_use]
    pub fn to_mint(&self, depth: ClipDepth) -> mint::ColumnMatrix4<f32> {
        self.to_mat4(depth).into()
    }

    /// [`FrameMap::world_to_clip`] (`f64`) as a mint matrix (feature `mint`).
    #[cfg(feature = "mint")]
    #[must_use]
    pub fn world_to_clip_mint(&self, depth: ClipDepth) -> mint::ColumnMatrix4<f64> {
        self.world_to_clip(depth).into()
    }
}

/// `x` rounded up to `f32` (x ≥ 0 finite, or +∞): the growth τ must not shrink on upload, since
/// the factor `s (1 − τ)/(1 − s τ)` grows with it.
fn f32_up(x: f64) -> f32 {
    let v = x as f32;
    if f64::from(v) < x {
        f32::from_bits(v.to_bits() + 1)
    } else {
        v
    }
}
