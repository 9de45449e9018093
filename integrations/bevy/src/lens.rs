//! The error lens (docs/bevy.md, "The error lens"): the crate's per-pixel error heat map
//! (`sa_error_lens` and `sa_lens_colour` of the WGSL module `shadow_aliasing::frame::SHADOW_WGSL`,
//! `FrameMap::error_lens_at` in Rust) drawn over a camera's image, with its legend, for the
//! cascades Bevy draws: its own (measure mode) or the plugin's (replace and budget mode).
//!
//! Put [`ErrorLens`] on a 3D camera. Each frame, after the cascades are built, replaced and
//! measured, [`prepare_error_lens`] writes the camera's [`ErrorLensMaps`]: one `GpuShadowMap`
//! record per cascade of the chosen light for that camera, from the matrix Bevy holds
//! (`Cascade::clip_from_world`, reversed depth), which the render world's pass
//! (`lens_render.rs`) uploads and draws with.

use crate::measure::{bevy_covers, CascadeErrors};
use crate::replace::ReplacedCascades;
use crate::view::light_dir;
use bevy::core_pipeline::prepass::{DepthPrepass, NormalPrepass};
use bevy::light::{CascadeShadowConfig, Cascades, DirectionalLight, DirectionalLightShadowMap};
use bevy::prelude::*;
use bevy::render::extract_component::ExtractComponent;
use shadow_aliasing::frame::GpuShadowMap;
use shadow_aliasing::maps::ClipDepth;

/// The most cascades the lens shows: Bevy's `MAX_CASCADES_PER_LIGHT`
/// ([`crate::MAX_CASCADES`]).
pub const LENS_MAPS: usize = crate::measure::MAX_CASCADES;

/// The error lens of a camera: put it on a `Camera3d` with a perspective projection to draw,
/// over the camera's image, the size in screen pixels of the shadow map's texel on each visible
/// surface (the crate's error lens, projection factor included), in viridis on a log₂ scale
/// from 1/16 to 32 pixels (1 pixel teal, `#26828e`), with the ramp's legend in the image's
/// lower-left corner. Remove it to switch the lens off.
///
/// It requires Bevy's depth and normal prepasses on the camera (`DepthPrepass`,
/// `NormalPrepass`; added with it, and left when it is removed): the lens pass reads each
/// pixel's surface point from the depth and its normal from the normal prepass. Pixels without
/// a value show the scene: the sky, a surface beyond the last cascade's far bound or off its
/// cascade's map (Bevy draws them unshadowed), an orthographic camera.
#[derive(Component, Debug, Clone, Copy, PartialEq)]
#[require(DepthPrepass, NormalPrepass)]
pub struct ErrorLens {
    /// How much the heat map covers the scene: 0 the scene alone, 1 the heat map alone (in the
    /// view's linear colour, after tone mapping); a value outside [0, 1] is taken as the nearer
    /// end, NaN as 0. Default 0.7.
    pub opacity: f32,
    /// Whether to draw the legend (the ramp with its values in pixels). Default `true`.
    pub legend: bool,
    /// The directional light whose cascades the lens shows; `None`: the shadowed light with
    /// cascades for this camera that has the lowest entity. Default `None`.
    pub light: Option<Entity>,
}

impl Default for ErrorLens {
    fn default() -> Self {
        Self {
            opacity: 0.7,
            legend: true,
            light: None,
        }
    }
}

/// What the lens pass draws with for one camera, written each frame by [`prepare_error_lens`]
/// and copied to the render world.
#[derive(Component, Debug, Clone, PartialEq, Default, ExtractComponent)]
pub struct ErrorLensMaps {
    /// The light shown, `None` when no light has cascades for this camera (then nothing is
    /// drawn but the legend).
    pub light: Option<Entity>,
    /// One record per cascade, near to far (at most [`LENS_MAPS`]): `world_to_clip` the matrix
    /// Bevy holds (`Cascade::clip_from_world`, `ClipDepth::Reversed`); `split` the view depths
    /// the cascade covers, its far end Bevy's `far_bound` (`CascadeShadowConfig::bounds`, by
    /// which Bevy's shader picks a cascade); `blend` Bevy's cross-fade band into the next
    /// cascade; `texel_world` Bevy's `texel_size`; the error figures measure mode's
    /// ([`CascadeErrors`]), +∞ where none was measured; `resolution` the map size. The bias
    /// fields are 0 and `bias_radius` 0: the lens pass looks nothing up in the maps.
    pub maps: Vec<GpuShadowMap>,
    /// The direction the light travels (world space, unit).
    pub light_dir: [f32; 3],
    /// The shadow maps' texels per side (`DirectionalLightShadowMap::size`).
    pub resolution: u32,
    /// [`ErrorLens::opacity`].
    pub opacity: f32,
    /// [`ErrorLens::legend`].
    pub legend: bool,
}

/// The uniform block the lens pass reads: the [`LENS_MAPS`] records (unused ones zero), then the
/// light's direction, the cascade count, the opacity and the legend flag (and two words of
/// padding to a multiple of 16 bytes), in
/// the WGSL struct `ErrorLensUniform`'s layout (src/lens.wgsl; uniform address space: the
/// records' stride is their size, a multiple of 16, and the vector after them starts on 16).
impl ErrorLensMaps {
    /// The uniform block's size in bytes.
    pub const UNIFORM_SIZE: usize = LENS_MAPS * GpuShadowMap::SIZE + 32;

    /// The uniform block's bytes (little-endian).
    #[must_use]
    pub fn uniform_bytes(&self) -> Vec<u8> {
        let mut out = Vec::with_capacity(Self::UNIFORM_SIZE);
        for i in 0..LENS_MAPS {
            match self.maps.get(i) {
                Some(m) => out.extend_from_slice(&m.to_bytes()),
                None => out.extend(std::iter::repeat_n(0u8, GpuShadowMap::SIZE)),
            }
        }
        let count = self.maps.len().min(LENS_MAPS) as u32;
        let opacity = if self.opacity.is_nan() {
            0.0f32
        } else {
            self.opacity.clamp(0.0, 1.0)
        };
        let words = [
            self.light_dir[0].to_bits(),
            self.light_dir[1].to_bits(),
            self.light_dir[2].to_bits(),
            count,
            opacity.to_bits(),
            u32::from(self.legend),
            0,
            0,
        ];
        for w in words {
            out.extend_from_slice(&w.to_le_bytes());
        }
        out
    }
}

type LensLight<'a> = (
    Entity,
    &'a GlobalTransform,
    &'a DirectionalLight,
    &'a Cascades,
    &'a CascadeShadowConfig,
    &'a CascadeErrors,
    Option<&'a ReplacedCascades>,
);

/// The records of one light's cascades for one camera (the fields of [`ErrorLensMaps::maps`]).
fn records(camera: Entity, light: &LensLight<'_>, resolution: u32) -> Vec<GpuShadowMap> {
    let (_, _, _, cascades, config, errors, replaced) = light;
    let Some(list) = cascades.cascades.get(&camera) else {
        return Vec::new();
    };
    let covers = replaced
        .and_then(|r| r.covers.get(&camera).cloned())
        .unwrap_or_else(|| bevy_covers(config));
    let measured = errors.views.get(&camera);
    let o = config.overlap_proportion;
    let n = list.len().min(LENS_MAPS).min(config.bounds.len());
    (0..n)
        .map(|i| {
            let c = &list[i];
            let far = config.bounds[i];
            let near = covers.get(i).map_or(0.0, |c| c.0 as f32);
            // Bevy's shader fades cascade i into i + 1 over [(1 − o) far_i, far_i]
            // (`fetch_directional_shadow`, bevy_pbr/src/render/shadows.wgsl).
            let blend = if i + 1 < n && o > 0.0 {
                [(1.0 - o) * far, far]
            } else {
                [far, far]
            };
            let e = measured.and_then(|v| v.cascades.get(i).copied().flatten());
            let figure =
                |f: fn(&crate::CascadeError) -> f64| e.map_or(f32::INFINITY, |e| f(&e) as f32);
            GpuShadowMap {
                world_to_clip: c.clip_from_world.to_cols_array_2d(),
                split: [near, far],
                blend,
                texel_world: c.texel_size,
                max_error_pixels: figure(|e| e.max_error_pixels),
                max_mx: figure(|e| e.max_mx),
                max_mz: figure(|e| e.max_mz),
                face: GpuShadowMap::NO_FACE,
                clip_depth: GpuShadowMap::clip_depth_code(ClipDepth::Reversed),
                resolution,
                ..GpuShadowMap::default()
            }
        })
        .collect()
}

/// Writes each [`ErrorLens`] camera's [`ErrorLensMaps`] (in `PostUpdate`, after
/// [`crate::ShadowAliasingSystems::Measure`]): the cascades Bevy will draw this frame, whoever
/// built them.
pub fn prepare_error_lens(
    mut commands: Commands,
    shadow_map: Res<DirectionalLightShadowMap>,
    cameras: Query<(Entity, &ErrorLens)>,
    lights: Query<LensLight<'_>>,
    stale: Query<Entity, (With<ErrorLensMaps>, Without<ErrorLens>)>,
) {
    for e in &stale {
        commands.entity(e).remove::<ErrorLensMaps>();
    }
    let resolution = u32::try_from(shadow_map.size).unwrap_or(u32::MAX);
    for (camera, lens) in &cameras {
        let chosen = lights
            .iter()
            .filter(|l| {
                l.2.shadow_maps_enabled
                    && l.3.cascades.contains_key(&camera)
                    && lens.light.is_none_or(|e| e == l.0)
            })
            .min_by_key(|l| l.0);
        let mut out = ErrorLensMaps {
            resolution,
            opacity: lens.opacity,
            legend: lens.legend,
            ..default()
        };
        if let Some(l) = chosen {
            out.light = Some(l.0);
            let d = light_dir(l.1);
            out.light_dir = [d[0] as f32, d[1] as f32, d[2] as f32];
            out.maps = records(camera, &l, resolution);
        }
        commands.entity(camera).insert(out);
    }
}
