//! Replace mode: a light's `Cascades` rewritten with the crate's frame API after Bevy built its
//! own, and its `CascadeShadowConfig` bounds set to the new cascades' far ends so that the shader
//! selects them where the crate meant them.

use crate::bias::{needed_normal_bias, pcf_radius, AppliedBias};
use crate::convert::{dmat4_to_bevy, mat4_from_cols, quat_to_crate};
use crate::measure::MAX_CASCADES;
use crate::scene::SceneBounds;
use crate::settings::{CascadeMode, Fit, Replace, Splits};
use crate::view::{light_dir, view, View};
use crate::ShadowAliasingSettings;
use bevy::camera::{Camera, Projection};
use bevy::ecs::entity::EntityHashMap;
use bevy::light::cascade::Cascade;
use bevy::light::{
    CascadeShadowConfig, Cascades, DirectionalLight, DirectionalLightShadowMap,
    ShadowFilteringMethod,
};
use bevy::prelude::*;
use bevy::render::renderer::RenderDevice;
use bevy::render::settings::WgpuFeatures;
use shadow_aliasing::frame::{
    frame, Bound, CascadeSplits, Frame, FrameInput, FrameMap, FrameScheme,
};
use shadow_aliasing::glam::{DMat4, DQuat, DVec3};
use shadow_aliasing::maps::{ClipDepth, WarpRule};

/// Replace mode's state on a light (required by [`CascadeMode`]).
#[derive(Component, Debug, Clone, Default)]
pub struct ReplacedCascades {
    /// Per camera whose cascades were replaced this frame: the view-depth range each cascade
    /// covers (its focus body's depth extent), for the measurement.
    pub covers: EntityHashMap<Vec<(f64, f64)>>,
    /// Why a camera's cascades were not replaced this frame (Bevy's are kept for it).
    pub errors: EntityHashMap<String>,
    /// The light's `CascadeShadowConfig` as it was before the plugin first replaced the cascades:
    /// restored when the light goes back to [`CascadeMode::Measure`]. While the light is in
    /// replace mode its configuration holds the replacement's far bounds, and `Splits::Bevy`
    /// reads this one.
    pub(crate) original: Option<CascadeShadowConfig>,
    /// The bias the plugin set on the light this frame ([`AppliedBias`]), or why it left the
    /// light's own (`Err`); `None` with the automatic bias off
    /// (`ShadowAliasingSettings::auto_bias`) or nothing replaced.
    pub bias: Option<Result<AppliedBias, String>>,
    /// The light's `(shadow_depth_bias, shadow_normal_bias)` before the plugin first set them:
    /// restored when the light returns to [`CascadeMode::Measure`].
    pub(crate) original_bias: Option<(f32, f32)>,
}

/// A frame map as Bevy's `Cascade` (bevy_light/src/cascade.rs): `clip_from_world` is the map's
/// world → light clip in reversed depth (1 nearest the light, Bevy's convention), from the crate's
/// column arrays; `texel_size` the map's largest texel edge over its focus body; the shadow view's
/// pose `world_from_cascade` is the light's rotation (as Bevy's `world_from_light`) placed at the
/// centre of the map's near plane, and `clip_from_cascade` the map in that frame.
#[must_use]
pub fn to_bevy_cascade(map: &FrameMap, light_rotation: DQuat) -> Cascade {
    let wc = map.world_to_clip(ClipDepth::Reversed);
    let origin = wc.inverse().project_point3(DVec3::new(0.0, 0.0, 1.0));
    let world_from_cascade = DMat4::from_rotation_translation(light_rotation, origin);
    Cascade {
        world_from_cascade: dmat4_to_bevy(&world_from_cascade),
        clip_from_cascade: dmat4_to_bevy(&(wc * world_from_cascade)),
        clip_from_world: mat4_from_cols(map.world_to_clip_cols(ClipDepth::Reversed)),
        texel_size: map.texel_world as f32,
    }
}

/// The crate's splits for the plugin's [`Splits`]; `Splits::Bevy` reads the light's original
/// configuration as `CascadeShadowConfigBuilder` builds it (far bounds a geometric series from
/// `bounds[0]` to the last bound).
fn crate_splits(
    splits: &Splits,
    original: &CascadeShadowConfig,
) -> Result<CascadeSplits<'static>, String> {
    let k = match splits {
        Splits::Bevy => original.bounds.len(),
        Splits::Scheme { k, .. } | Splits::EqualError { k } => *k,
    };
    if k == 0 || k > MAX_CASCADES {
        return Err(format!(
            "k must be in 1..={MAX_CASCADES}, the cascades Bevy renders per light (got {k})"
        ));
    }
    Ok(match *splits {
        Splits::Bevy => CascadeSplits::Bevy {
            k,
            minimum_distance: f64::from(original.minimum_distance),
            maximum_distance: f64::from(original.bounds[k - 1]),
            first_far_bound: f64::from(original.bounds[0]),
            overlap_proportion: f64::from(original.overlap_proportion),
        },
        Splits::Scheme { scheme, k } => CascadeSplits::Scheme {
            scheme,
            k,
            overlap: 0.0,
        },
        Splits::EqualError { k } => CascadeSplits::EqualError { k },
    })
}

/// Why a warped map is refused on a device without `DEPTH_CLIP_CONTROL`.
const WARPED_NEEDS_CLIP_CONTROL: &str =
    "warped maps need the device feature DEPTH_CLIP_CONTROL: without it Bevy emulates unclipped \
     depth by writing the undivided clip z as the fragment depth (UNCLIPPED_DEPTH_ORTHO_EMULATION, \
     bevy_pbr/src/prepass/prepass.wgsl), right only for orthographic maps; use \
     Fit::Focused(WarpRule::Uniform) or Fit::Stable on this device";

/// The frame for one camera; `clip_control`: the device has `DEPTH_CLIP_CONTROL`.
fn build(
    r: &Replace,
    clip_control: bool,
    v: &View,
    dir: [f64; 3],
    bounds: &SceneBounds,
    original: &CascadeShadowConfig,
    res: u32,
) -> Result<Option<Frame>, String> {
    if bounds.receivers.is_empty() {
        return Ok(None);
    }
    if let Fit::Focused(rule) = r.fit {
        if rule != WarpRule::Uniform && !clip_control {
            return Err(WARPED_NEEDS_CLIP_CONTROL.into());
        }
    }
    let splits = crate_splits(&r.splits, original)?;
    let scheme = match r.fit {
        Fit::Focused(rule) => FrameScheme::Cascades { splits, rule },
        Fit::Stable => FrameScheme::Stable(splits),
    };
    let mut input = frame_input(v, dir, bounds, res).scheme(scheme);
    if let Some((a, b)) = r.depth_range {
        input = input.depth_range(a, b);
    }
    frame(&input).map(Some).map_err(|e| e.to_string())
}

/// The frame input for one camera and light: the scene's receivers and casters, no depth clamp.
/// Casters extend each map's depth range, so that no map relies on the device clamping the
/// depth of casters nearer the light: Bevy clamps it natively with `DEPTH_CLIP_CONTROL` (right
/// for any map) and otherwise emulates it for orthographic maps only.
pub(crate) fn frame_input<'a>(
    v: &View,
    dir: [f64; 3],
    bounds: &'a SceneBounds,
    res: u32,
) -> FrameInput<'a> {
    FrameInput::new(v.camera, dir, res, v.image_height)
        .receivers(Bound::Boxes(&bounds.receivers))
        .casters(Bound::Boxes(&bounds.casters))
        .depth_clamp(false)
}

/// One light's replacement, written camera by camera ([`Installer::install`]) and then into the
/// light's configuration and bias ([`Installer::finish`]). Shared by replace and budget mode.
pub(crate) struct Installer {
    rotation: DQuat,
    /// The far bounds of the first camera installed: the light's, shared by its cameras.
    shared: Option<Vec<f32>>,
    /// The PCF radius for the automatic bias (`None`: off), and per cascade index the normal
    /// bias needed, or why it could not be derived.
    radius: Option<f64>,
    needed: Result<Vec<f32>, String>,
}

impl Installer {
    /// For a light with this transform; `auto_bias`: derive the light's bias.
    pub(crate) fn new(transform: &GlobalTransform, auto_bias: bool) -> Self {
        Self {
            rotation: quat_to_crate(transform.rotation()),
            shared: None,
            radius: auto_bias.then_some(0.0),
            needed: Ok(Vec::new()),
        }
    }

    /// Writes `maps` as the cascades of `view_entity` (filtered with `filter`, the camera's
    /// `ShadowFilteringMethod`), unless their far bounds differ from the first camera's (then
    /// Bevy's are kept and the reason recorded in `state.errors`).
    pub(crate) fn install(
        &mut self,
        view_entity: Entity,
        maps: &[&FrameMap],
        filter: Option<&ShadowFilteringMethod>,
        cascades: &mut Cascades,
        state: &mut ReplacedCascades,
    ) {
        let far: Vec<f32> = maps.iter().map(|m| m.split.1 as f32).collect();
        match &self.shared {
            Some(s) if *s != far => {
                state.errors.insert(
                    view_entity,
                    "this camera's splits differ from the first camera's, and the light's far \
                     bounds are shared: Bevy's cascades kept"
                        .into(),
                );
                return;
            }
            _ => self.shared = Some(far),
        }
        if self.radius.is_some() {
            self.need(maps, filter);
        }
        let list: Vec<Cascade> = maps
            .iter()
            .map(|m| to_bevy_cascade(m, self.rotation))
            .collect();
        state
            .covers
            .insert(view_entity, maps.iter().map(|m| body_depths(m)).collect());
        cascades.cascades.insert(view_entity, list);
    }

    /// Adds one camera's maps to the bias needed per cascade index.
    fn need(&mut self, maps: &[&FrameMap], filter: Option<&ShadowFilteringMethod>) {
        let Ok(needed) = &mut self.needed else {
            return;
        };
        let r = match pcf_radius(filter) {
            Ok(r) => r,
            Err(e) => {
                self.needed = Err(e);
                return;
            }
        };
        for (i, m) in maps.iter().enumerate() {
            match needed_normal_bias(m, r) {
                Ok(k) => {
                    if needed.len() <= i {
                        needed.resize(i + 1, 0.0);
                    }
                    needed[i] = needed[i].max(k);
                }
                Err(e) => {
                    self.needed = Err(e);
                    return;
                }
            }
        }
        self.radius = self.radius.map(|x| x.max(r));
    }

    /// Sets the light's configuration to the installed cascades (their far ends; `overlap` the
    /// cross-fade proportion) and, with the automatic bias, the light's bias (the user's kept in
    /// `state` for when the light returns to measure mode).
    pub(crate) fn finish(
        self,
        config: &mut CascadeShadowConfig,
        original: &CascadeShadowConfig,
        overlap: f32,
        light: &mut Mut<'_, DirectionalLight>,
        state: &mut ReplacedCascades,
    ) {
        let Some(far) = self.shared else {
            return;
        };
        config.bounds = far;
        config.minimum_distance = original.minimum_distance;
        config.overlap_proportion = overlap;
        let Some(radius) = self.radius else {
            // The automatic bias off: the user's own bias back, if the plugin had set it.
            if let Some((depth, normal)) = state.original_bias.take() {
                light.shadow_depth_bias = depth;
                light.shadow_normal_bias = normal;
            }
            state.bias = None;
            return;
        };
        match self.needed {
            Ok(needed) if !needed.is_empty() => {
                let normal = needed.iter().copied().fold(0.0, f32::max);
                state
                    .original_bias
                    .get_or_insert((light.shadow_depth_bias, light.shadow_normal_bias));
                if light.shadow_normal_bias != normal || light.shadow_depth_bias != 0.0 {
                    light.shadow_normal_bias = normal;
                    light.shadow_depth_bias = 0.0;
                }
                state.bias = Some(Ok(AppliedBias {
                    normal_bias: normal,
                    depth_bias: 0.0,
                    pcf_radius: radius,
                    needed,
                }));
            }
            Ok(_) => state.bias = None,
            Err(e) => {
                if let Some((depth, normal)) = state.original_bias.take() {
                    light.shadow_depth_bias = depth;
                    light.shadow_normal_bias = normal;
                }
                state.bias = Some(Err(e));
            }
        }
    }
}

/// The view-depth extent of a map's focus body (eye space looks down −Z).
fn body_depths(map: &FrameMap) -> (f64, f64) {
    map.body()
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(-p.z), b.max(-p.z))
        })
}

/// Gives a light that left replace (or budget) mode its own `CascadeShadowConfig` and bias back,
/// and clears what those modes recorded (runs in
/// `PostUpdate` before `build_directional_light_cascades`, so that Bevy's cascades of the same
/// frame are built from it).
pub fn restore_cascade_config(
    mut lights: Query<(
        &CascadeMode,
        &mut CascadeShadowConfig,
        &mut DirectionalLight,
        &mut ReplacedCascades,
    )>,
) {
    for (mode, mut config, mut light, mut state) in &mut lights {
        if matches!(mode, CascadeMode::Measure) {
            state.covers.clear();
            state.errors.clear();
            if let Some(original) = state.original.take() {
                *config = original;
            }
            if let Some((depth, normal)) = state.original_bias.take() {
                light.shadow_depth_bias = depth;
                light.shadow_normal_bias = normal;
            }
            state.bias = None;
        }
    }
}

/// A camera as the plugin reads it: its pose, projection, viewport and shadow filter.
pub(crate) type CameraItem<'a> = (
    &'a GlobalTransform,
    &'a Projection,
    &'a Camera,
    Option<&'a ShadowFilteringMethod>,
);

pub(crate) type LightItem<'a> = (
    &'a GlobalTransform,
    &'a mut DirectionalLight,
    &'a CascadeMode,
    &'a mut CascadeShadowConfig,
    &'a mut Cascades,
    &'a mut ReplacedCascades,
);

/// Replaces the cascades of every light in [`CascadeMode::Replace`] for every camera Bevy built
/// cascades for (a warped rule is refused, Bevy's cascades kept, on a device without
/// `DEPTH_CLIP_CONTROL`: see docs/bevy.md) (runs in `PostUpdate` after `build_directional_light_cascades` and before
/// `update_directional_light_frusta`, which culls the casters with the new matrices).
///
/// The light's `CascadeShadowConfig` is shared by its cameras (the shader selects a cascade by
/// its far bound, `GpuDirectionalCascade::far_bound`, from `config.bounds` in bevy_pbr's
/// `prepare_lights`), so it takes the first camera's far bounds; a further camera whose splits
/// differ (equal-error splits or a depth range are view-dependent) keeps Bevy's cascades and
/// gets an error in [`ReplacedCascades::errors`].
pub fn replace_cascades(
    settings: Res<ShadowAliasingSettings>,
    device: Option<Res<RenderDevice>>,
    shadow_map: Res<DirectionalLightShadowMap>,
    bounds: Res<SceneBounds>,
    cameras: Query<CameraItem<'_>>,
    mut lights: Query<LightItem<'_>>,
) {
    let res = u32::try_from(shadow_map.size).unwrap_or(u32::MAX);
    // No renderer (an ECS-only app): nothing is drawn, every map is allowed.
    let clip_control =
        device.is_none_or(|d| d.features().contains(WgpuFeatures::DEPTH_CLIP_CONTROL));
    for (transform, mut light, mode, mut config, mut cascades, mut state) in &mut lights {
        let state = state.as_mut();
        let CascadeMode::Replace(r) = mode else {
            continue;
        };
        state.covers.clear();
        state.errors.clear();
        if !light.shadow_maps_enabled {
            continue;
        }
        let original = state.original.get_or_insert_with(|| config.clone()).clone();
        let dir = light_dir(transform);
        let mut views: Vec<Entity> = cascades.cascades.keys().copied().collect();
        views.sort();
        let mut installer = Installer::new(transform, settings.auto_bias);
        for view_entity in views {
            let built = cameras
                .get(view_entity)
                .map_err(|e| e.to_string())
                .and_then(|(t, p, c, filter)| {
                    let v = view(t, p, c, settings.image_height)?;
                    build(r, clip_control, &v, dir, &bounds, &original, res).map(|f| (f, filter))
                });
            let (f, filter) = match built {
                Ok(f) => f,
                Err(e) => {
                    state.errors.insert(view_entity, e);
                    continue;
                }
            };
            let maps: Vec<&FrameMap> = f.as_ref().map_or(Vec::new(), |f| f.maps().iter().collect());
            installer.install(view_entity, &maps, filter, &mut cascades, state);
        }
        // Bevy's shader cross-fades cascade i into i + 1 over [(1 − o) far_i, far_i]; only
        // Bevy's own splits have that band (the crate's `CascadeSplits::Bevy` keeps it).
        let overlap = match r.splits {
            Splits::Bevy => original.overlap_proportion,
            _ => 0.0,
        };
        installer.finish(&mut config, &original, overlap, &mut light, state);
    }
}
