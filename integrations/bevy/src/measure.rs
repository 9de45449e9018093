//! Measure mode: the crate's measurement of whatever cascades a light holds (Bevy's own, or the
//! ones replace mode wrote), published as [`CascadeErrors`] on the light and as Bevy diagnostics.

use crate::convert::mat4_to_crate;
use crate::replace::ReplacedCascades;
use crate::scene::SceneBounds;
use crate::view::{light_dir, view};
use crate::ShadowAliasingSettings;
use bevy::camera::{Camera, Projection};
use bevy::diagnostic::{Diagnostic, DiagnosticPath, Diagnostics, RegisterDiagnostic};
use bevy::ecs::entity::EntityHashMap;
use bevy::light::{CascadeShadowConfig, Cascades, DirectionalLight, DirectionalLightShadowMap};
use bevy::math::Mat4;
use bevy::prelude::*;
use shadow_aliasing::frame::{frame, Aabb, Bound, Camera as FrameCamera, FrameInput, FrameScheme};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::measure::vertex::vertex_max;

/// The most cascades Bevy renders per light (`MAX_CASCADES_PER_LIGHT` in
/// bevy_pbr/src/render/light.rs, off WebGL); the diagnostics have one set per cascade index.
pub const MAX_CASCADES: usize = 4;

/// One cascade's error, measured by the crate over its focus body B (the cascade's covered
/// slice of the view frustum ∩ the receivers' merged box), at B's vertices
/// (`shadow_aliasing::measure::vertex::vertex_max`, the measurement the frame API uses for its
/// own maps).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CascadeError {
    /// The largest texel-to-pixel ratio over B: how many screen pixels the longest texel edge
    /// spans, `max(M_x, M_z) · image_height / map_resolution` (≤ 1: no visible aliasing).
    pub max_error_pixels: f64,
    /// M_x over B (unit resolutions): texel width along s per pixel width.
    pub max_mx: f64,
    /// M_z over B (unit resolutions): texel width along t per pixel width.
    pub max_mz: f64,
    /// S̄ = M_x M_z: texels needed per image pixel² for a maximum error of 1 (Lloyd 2006 §4.2).
    pub storage_factor: f64,
    /// The view-depth range the cascade covers, whose slice ∩ the receivers is B.
    pub cover: (f64, f64),
    /// The cascade's `texel_size` as Bevy holds it (world units, the normal bias's scale).
    pub texel_size: f32,
}

/// Who built the cascades that were measured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum CascadeSource {
    /// Bevy's `build_directional_light_cascades`.
    #[default]
    Bevy,
    /// The plugin's replace mode (the crate's frame API).
    ShadowAliasing,
}

/// The measured cascades of one light for one camera.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ViewCascadeErrors {
    /// Who built the cascades.
    pub source: CascadeSource,
    /// The shadow map's texels per side (`DirectionalLightShadowMap::size`).
    pub map_resolution: u32,
    /// The image height in pixels the error is counted in.
    pub image_height: u32,
    /// Per cascade, near to far: `None` where B is empty (no receiver in the cascade's slice) or
    /// has no area seen from the light.
    pub cascades: Vec<Option<CascadeError>>,
    /// Why this view could not be measured (an orthographic camera, a scaled camera transform, a
    /// map singular at a vertex of B); the cascades are then empty.
    pub error: Option<String>,
}

impl ViewCascadeErrors {
    /// The largest `max_error_pixels` over the cascades, `None` when none was measured.
    #[must_use]
    pub fn max_error_pixels(&self) -> Option<f64> {
        self.cascades
            .iter()
            .flatten()
            .map(|c| c.max_error_pixels)
            .reduce(f64::max)
    }
}

/// The measured cascades of a shadowed `DirectionalLight`, per camera entity. Every directional
/// light gets this component (a required component registered by the plugin); it is rewritten
/// each frame in `PostUpdate`.
#[derive(Component, Debug, Clone, Default)]
pub struct CascadeErrors {
    /// Per camera entity.
    pub views: EntityHashMap<ViewCascadeErrors>,
}

/// The diagnostic path of a cascade's figure: `shadow_aliasing/cascade{index}/{figure}` with
/// `figure` one of `max_error_pixels`, `max_mx`, `max_mz`, `storage_factor`. Each holds the
/// largest value over every measured light and camera.
#[must_use]
pub fn cascade_path(index: usize, figure: &str) -> DiagnosticPath {
    DiagnosticPath::new(format!("shadow_aliasing/cascade{index}/{figure}"))
}

/// The diagnostic of the largest `max_error_pixels` over every cascade, light and camera.
pub const MAX_ERROR_PIXELS: DiagnosticPath =
    DiagnosticPath::const_new("shadow_aliasing/max_error_pixels");

const FIGURES: [&str; 4] = ["max_error_pixels", "max_mx", "max_mz", "storage_factor"];

pub(crate) fn register_diagnostics(app: &mut App) {
    app.register_diagnostic(Diagnostic::new(MAX_ERROR_PIXELS));
    for i in 0..MAX_CASCADES {
        for f in FIGURES {
            app.register_diagnostic(Diagnostic::new(cascade_path(i, f)));
        }
    }
}

/// The view-depth ranges Bevy's cascades cover, as `build_directional_light_cascades`
/// (bevy_light/src/cascade.rs) slices the frustum: cascade 0 from `minimum_distance`, cascade
/// i > 0 from `(1 − overlap_proportion)` times the previous far bound, each to its far bound.
#[must_use]
pub fn bevy_covers(config: &CascadeShadowConfig) -> Vec<(f64, f64)> {
    let o = f64::from(config.overlap_proportion);
    let far = config.bounds.iter().map(|b| f64::from(*b));
    let near = std::iter::once(f64::from(config.minimum_distance))
        .chain(config.bounds.iter().map(|b| (1.0 - o) * f64::from(*b)));
    near.zip(far).collect()
}

/// The crate's measurement of one cascade: B = the slice `cover` of `camera`'s frustum ∩ the
/// receivers' merged box (the frame API's exact clipping, read from a uniform map's body), and
/// M_x, M_z, S̄ of `clip_from_world` (Bevy's world → light clip matrix, any depth convention: the
/// depth row does not enter the error) at B's vertices. `Ok(None)` where B is empty or edge-on
/// to the light, or the slice lies outside the camera's [near, far].
///
/// # Errors
/// The crate's error for a bad input (a bad box), or a message when the matrix is singular or
/// behind its centre of projection at a vertex of B.
pub fn measure_cascade(
    camera: &FrameCamera,
    light_dir_world: [f64; 3],
    receivers: &[Aabb],
    cover: (f64, f64),
    clip_from_world: &Mat4,
    map_resolution: u32,
    image_height: u32,
) -> Result<Option<CascadeError>, String> {
    let v = camera.view();
    if receivers.is_empty() || cover.0 >= v.far() || cover.1 <= v.near() {
        return Ok(None);
    }
    let input = FrameInput::new(*camera, light_dir_world, map_resolution, image_height)
        .receivers(Bound::Boxes(receivers))
        .depth_range(cover.0, cover.1)
        .scheme(FrameScheme::Single(WarpRule::Uniform))
        .measure(false);
    let f = frame(&input).map_err(|e| e.to_string())?;
    let Some(map) = f.maps().iter().next() else {
        return Ok(None);
    };
    let eye_to_clip = mat4_to_crate(clip_from_world) * camera.world_to_eye().inverse();
    let e = vertex_max(
        &eye_to_clip,
        f.light_dir_eye(),
        v.tan_half_fov(),
        map.body(),
    )
    .ok_or(
        "the cascade's matrix is singular or behind its centre of projection at a vertex of B",
    )?;
    Ok(Some(CascadeError {
        max_error_pixels: e.max_mx.max(e.max_mz) * f64::from(image_height)
            / f64::from(map_resolution),
        max_mx: e.max_mx,
        max_mz: e.max_mz,
        storage_factor: e.storage_factor,
        cover,
        texel_size: 0.0,
    }))
}

type LightItem<'a> = (
    &'a GlobalTransform,
    &'a DirectionalLight,
    &'a CascadeShadowConfig,
    &'a Cascades,
    Option<&'a ReplacedCascades>,
    &'a mut CascadeErrors,
);

/// Measures every shadowed directional light's cascades for every camera they were built for,
/// writes [`CascadeErrors`] and the diagnostics (runs after Bevy's cascades and the plugin's
/// replacement in `PostUpdate`).
pub fn measure_cascades(
    settings: Res<ShadowAliasingSettings>,
    shadow_map: Res<DirectionalLightShadowMap>,
    bounds: Res<SceneBounds>,
    cameras: Query<(&GlobalTransform, &Projection, &Camera)>,
    mut lights: Query<LightItem<'_>>,
    mut diagnostics: Diagnostics,
) {
    let res = u32::try_from(shadow_map.size).unwrap_or(u32::MAX);
    let mut max = [[f64::NEG_INFINITY; 4]; MAX_CASCADES];
    for (transform, light, config, cascades, replaced, mut errors) in &mut lights {
        errors.views.clear();
        if !light.shadow_maps_enabled {
            continue;
        }
        let dir = light_dir(transform);
        for (&view_entity, list) in &cascades.cascades {
            let mut out = ViewCascadeErrors {
                map_resolution: res,
                ..default()
            };
            let covers = match replaced.and_then(|r| r.covers.get(&view_entity)) {
                Some(c) => {
                    out.source = CascadeSource::ShadowAliasing;
                    c.clone()
                }
                None => bevy_covers(config),
            };
            let measured = cameras
                .get(view_entity)
                .map_err(|e| e.to_string())
                .and_then(|(t, p, c)| view(t, p, c, settings.image_height))
                .and_then(|v| {
                    out.image_height = v.image_height;
                    list.iter()
                        .zip(&covers)
                        .map(|(c, &cover)| {
                            measure_cascade(
                                &v.camera,
                                dir,
                                &bounds.receivers,
                                cover,
                                &c.clip_from_world,
                                res,
                                v.image_height,
                            )
                            .map(|m| {
                                m.map(|m| CascadeError {
                                    texel_size: c.texel_size,
                                    ..m
                                })
                            })
                        })
                        .collect::<Result<Vec<_>, String>>()
                });
            match measured {
                Ok(list) => out.cascades = list,
                Err(e) => out.error = Some(e),
            }
            for (i, c) in out.cascades.iter().enumerate().take(MAX_CASCADES) {
                if let Some(c) = c {
                    let figures = [c.max_error_pixels, c.max_mx, c.max_mz, c.storage_factor];
                    for (m, v) in max[i].iter_mut().zip(figures) {
                        *m = m.max(v);
                    }
                }
            }
            errors.views.insert(view_entity, out);
        }
    }
    let mut overall = f64::NEG_INFINITY;
    for (i, figures) in max.iter().enumerate() {
        for (f, &v) in FIGURES.iter().zip(figures) {
            if v.is_finite() {
                diagnostics.add_measurement(&cascade_path(i, f), || v);
            }
        }
        overall = overall.max(figures[0]);
    }
    if overall.is_finite() {
        diagnostics.add_measurement(&MAX_ERROR_PIXELS, || overall);
    }
}
