//! Automatic bias: the light's `shadow_normal_bias` and `shadow_depth_bias` from the crate's
//! bias for the maps the plugin drew (`FrameMap::bias`, docs/renderer.md, "Texel size and
//! normal bias").
//!
//! Bevy's directional lookup (`sample_directional_cascade`, bevy_pbr/src/render/shadows.wgsl)
//! moves the fragment by `shadow_normal_bias · texel_size` along the surface normal and by
//! `shadow_depth_bias` (world units) toward the light, with `texel_size` the cascade's and
//! `shadow_normal_bias` the light's value times √2 (`prepare_lights`,
//! bevy_pbr/src/render/light.rs: "The factor of SQRT_2 is for the worst-case diagonal offset").
//! The crate's normal offset alone keeps every lit surface from shadowing itself, so the depth
//! bias is 0 and the normal bias is the largest over the cascades of what each needs,
//! `normal_offset / (√2 · texel_size)`: one value per light, so every cascade but the one that
//! sets it gets more offset than it needs ([`AppliedBias::needed`]).

use bevy::light::ShadowFilteringMethod;
use shadow_aliasing::frame::FrameMap;
use shadow_aliasing::maps::ClipDepth;

/// Bevy's factor on the light's normal bias (`prepare_lights`, bevy_pbr/src/render/light.rs).
const BEVY_NORMAL_BIAS_FACTOR: f64 = std::f64::consts::SQRT_2;

/// The bias the plugin set on a light, and what each cascade needed.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct AppliedBias {
    /// The light's `shadow_normal_bias` as set (Bevy's units: cascade texels before its √2).
    pub normal_bias: f32,
    /// The light's `shadow_depth_bias` as set (world units toward the light): 0.
    pub depth_bias: f32,
    /// The PCF radius the bias is for, texels (the crate's `r` of `FrameMap::bias`).
    pub pcf_radius: f64,
    /// Per cascade index, the largest over the cameras of the normal bias that cascade alone
    /// needs; `normal_bias` is their maximum, so cascade i's offset is `normal_bias /
    /// needed[i]` times its need.
    pub needed: Vec<f32>,
}

/// The PCF radius, in texels as `FrameMap::bias` takes it, of Bevy's directional lookup with a
/// camera's `ShadowFilteringMethod` (bevy_pbr/src/render/shadow_sampling.wgsl; Bevy's default
/// where the camera has none):
///
/// - `Hardware2x2`: one comparison sample, bilinear over the 2 × 2 texels around the point:
///   radius ½ (texel centres within 1 texel of the point).
/// - `Gaussian` (`sample_shadow_map_castano_thirteen`): 9 bilinear comparison samples at
///   offsets up to 2 texels from the point (`u0 − s` and `u2 − s` over s in [0, 1)), each
///   reaching texel centres within 1 texel more: radius 2½.
///
/// # Errors
/// For `Temporal`, whose taps are `f(texel_size) / (texel_size · map size)` apart (a fudge
/// factor of the cascade's world texel, `calculate_uv_offset_scale_jimenez_fourteen`) and
/// rotated by noise: not derived here, the light's bias is left as the user set it.
pub fn pcf_radius(method: Option<&ShadowFilteringMethod>) -> Result<f64, String> {
    match method.copied().unwrap_or_default() {
        ShadowFilteringMethod::Hardware2x2 => Ok(0.5),
        ShadowFilteringMethod::Gaussian => Ok(2.5),
        ShadowFilteringMethod::Temporal => Err(
            "automatic bias is not derived for ShadowFilteringMethod::Temporal (its tap spacing \
             is a fudge factor of the texel size): the light's bias is left as set; use \
             Hardware2x2 or Gaussian, or set ShadowAliasingSettings::auto_bias to false"
                .into(),
        ),
    }
}

/// The normal bias one map needs in Bevy's units: the crate's normal offset for a PCF kernel of
/// radius `r` texels (the maximum over the map's focus body) over Bevy's offset per unit of
/// bias, `√2 · texel_size`, with `texel_size` = the map's `texel_world` as the plugin gives it to
/// Bevy (rounded to `f32`); the result rounded up to the next `f32`.
///
/// # Errors
/// The crate's refusal of `r` (negative or not finite), or a map without a positive texel size.
pub fn needed_normal_bias(map: &FrameMap, r: f64) -> Result<f32, String> {
    let b = map
        .bias(r, ClipDepth::Reversed)
        .map_err(|e| format!("bias: {e}"))?;
    let texel = f64::from(map.texel_world as f32);
    if !(texel > 0.0 && b.normal_offset.is_finite()) {
        return Err(format!(
            "the map's texel size ({texel}) or normal offset ({}) cannot give a normal bias",
            b.normal_offset
        ));
    }
    let k = b.normal_offset / (BEVY_NORMAL_BIAS_FACTOR * texel);
    let f = k as f32;
    Ok(if f64::from(f) >= k { f } else { f.next_up() })
}
