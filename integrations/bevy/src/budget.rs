//! Budget mode: each frame the crate's error-budget controller (`shadow_aliasing::plan::Controller`,
//! docs/planning.md, "An error budget per frame") chooses a light's cascades (count, splits, fit)
//! and, where allowed, the shadow map's size for a target error, among what Bevy can draw.
//!
//! **Bevy's constraints.** One `DirectionalLightShadowMap::size` for every light (so every map of
//! a set-up shares one square resolution, as the controller assumes), at most
//! `MAX_CASCADES_PER_LIGHT` = 4 cascades (`max_maps`), far bounds shared by the light's cameras
//! (the controller runs for the light's first camera; another camera gets the chosen scheme
//! where its far bounds come out the same, as in replace mode), and Bevy's cascade structure:
//! the shader picks one map by view depth (`get_cascade_index`) and emulates unclipped depth
//! for orthographic maps only without `DEPTH_CLIP_CONTROL`. So the candidates
//! ([`bevy_candidates`]) are the orthographic cascades of `plan::candidates`: one uniform map,
//! focused uniform cascades and stable cascades, each with k ≤ 4 and every split scheme of the
//! list (uniform, logarithmic, practical, adaptive, equal-error), no overlap band. Warped maps
//! (LiSPSM, PSM, TSM, …) are left out (Bevy draws them correctly only with
//! `DEPTH_CLIP_CONTROL`), and so are face partitions (several maps per depth slice, which
//! Bevy's selection by view depth cannot pick between) and the clipmap.

use crate::measure::MAX_CASCADES;
use crate::replace::{frame_input, CameraItem, Installer, LightItem};
use crate::scene::SceneBounds;
use crate::settings::{Budget, CascadeMode};
use crate::view::{light_dir, view};
use crate::ShadowAliasingSettings;
use bevy::diagnostic::{Diagnostic, DiagnosticPath, Diagnostics, RegisterDiagnostic};
use bevy::light::DirectionalLightShadowMap;
use bevy::prelude::*;
use shadow_aliasing::frame::{frame, CascadeSplits, Frame, FrameInput, FrameMap, FrameScheme};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::candidates::candidates;
use shadow_aliasing::plan::{Controller, ControllerOptions};

/// The number of cascades a split setting asks for.
fn split_count(s: &CascadeSplits<'_>) -> usize {
    match *s {
        CascadeSplits::Scheme { k, .. }
        | CascadeSplits::Bevy { k, .. }
        | CascadeSplits::EqualError { k } => k,
        CascadeSplits::Distances { planes, .. } => planes.len().saturating_sub(1),
        CascadeSplits::Fractions { fractions, .. } => fractions.len() + 1,
    }
}

/// The schemes Bevy can draw, among the crate's candidates for `input` (module docs): one
/// orthographic map, orthographic focused cascades and stable cascades of at most
/// [`MAX_CASCADES`] cascades.
#[must_use]
pub fn bevy_candidates(input: &FrameInput<'_>) -> Vec<FrameScheme<'static>> {
    candidates(input)
        .into_iter()
        .filter(|s| match s {
            FrameScheme::Single(WarpRule::Uniform) => true,
            FrameScheme::Cascades {
                splits,
                rule: WarpRule::Uniform,
            }
            | FrameScheme::Stable(splits) => split_count(splits) <= MAX_CASCADES,
            _ => false,
        })
        .collect()
}

/// One frame's choice for a light in budget mode.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BudgetChoice {
    /// The camera the controller chose for (the light's first).
    pub camera: Entity,
    /// The scheme chosen.
    pub scheme: FrameScheme<'static>,
    /// The cascades drawn.
    pub cascades: usize,
    /// The maps' resolution, texels a side (the shared `DirectionalLightShadowMap::size`).
    pub resolution: u32,
    /// The largest measured error over the cascades, pixels (the frame's own measurement at
    /// `resolution`).
    pub max_error_pixels: f64,
    /// `cascades × resolution²`.
    pub texels: u64,
    /// `max_error_pixels ≤ max_error_pixels` of the [`Budget`]: `false` only where no allowed
    /// set-up meets it within the constraints (then the least error found).
    pub meets_target: bool,
    /// The set-up (scheme or resolution) differs from the last frame's.
    pub switched: bool,
    /// The controller searched every candidate this frame.
    pub cut: bool,
}

/// A light's controller and what it was made for: the budget, the fixed map size (`None`: the
/// size is chosen), the camera.
type Kept = (Budget, Option<u32>, Entity, Controller);

/// Budget mode's state on a light (required by [`CascadeMode`]).
#[derive(Component, Debug, Clone, Default)]
pub struct BudgetState {
    /// The controller, with what it was made for (the options, the fixed map size, the camera);
    /// boxed: a controller holds two frames inline (about 150 kB).
    controller: Option<Box<Kept>>,
    /// This frame's choice; `None` outside budget mode or where nothing was chosen (see
    /// `error`).
    pub choice: Option<BudgetChoice>,
    /// Set-up switches (scheme or resolution) since the light entered budget mode.
    pub switches: u64,
    /// Why nothing was chosen this frame (Bevy's cascades kept): no camera, no receivers, the
    /// controller's refusal.
    pub error: Option<String>,
}

/// The diagnostic path of a budget figure: `shadow_aliasing/budget/{figure}` with `figure` one
/// of `max_error_pixels`, `cascades`, `resolution`, `texels`, `meets_target` (1 or 0) and
/// `switches` (the total since entering budget mode); over every light in budget mode, the
/// largest value (`meets_target`: the least, 1 only where every light meets its target).
#[must_use]
pub fn budget_path(figure: &str) -> DiagnosticPath {
    DiagnosticPath::new(format!("shadow_aliasing/budget/{figure}"))
}

/// The index of `meets_target` in [`BUDGET_FIGURES`].
const MEETS_TARGET: usize = 4;

const BUDGET_FIGURES: [&str; 6] = [
    "max_error_pixels",
    "cascades",
    "resolution",
    "texels",
    "meets_target",
    "switches",
];

pub(crate) fn register_budget_diagnostics(app: &mut App) {
    for f in BUDGET_FIGURES {
        app.register_diagnostic(Diagnostic::new(budget_path(f)));
    }
}

/// The app's `DirectionalLightShadowMap::size` before budget mode first set it, restored when
/// no light in budget mode may set it any more.
#[derive(Resource, Debug, Default, Clone, Copy)]
pub struct OriginalMapSize(pub Option<usize>);

/// The controller's options for a budget: map sizes among powers of two up to the budget's
/// `max_map_size`, or `fixed` alone; the candidates from `input`.
fn options(b: &Budget, fixed: u32, input: &FrameInput<'_>) -> Result<ControllerOptions, String> {
    let (rounding, max_resolution) = match b.max_map_size {
        Some(n) if !n.is_power_of_two() => {
            return Err(format!(
                "Budget::max_map_size must be a power of two (got {n}): Bevy's map size is \
                 chosen among powers of two up to it"
            ))
        }
        Some(n) => (Rounding::PowerOfTwo, n),
        None => (Rounding::Multiple(fixed), fixed),
    };
    Ok(ControllerOptions {
        max_maps: MAX_CASCADES,
        rounding,
        max_resolution,
        candidates: Some(bevy_candidates(input)),
        patience: b.patience,
        margin: b.margin,
        ..ControllerOptions::new(b.max_error_pixels)
    })
}

/// A light's decision, before the shared map size is settled.
struct Pending {
    light: Entity,
    choice: BudgetChoice,
    /// The controller's maps (a copy: the decision borrows the controller; `Frame` holds
    /// its maps inline).
    frame: Box<Frame>,
}

/// Runs budget mode for every light in [`CascadeMode::Budget`] (`PostUpdate`, in
/// `ShadowAliasingSystems::Replace`): the controller for the light's first camera, the shared
/// map size (the largest chosen over the lights that may set it; a light whose choice was
/// smaller gets its scheme built again at that size), the cascades and the light's
/// configuration and bias as in replace mode, [`BudgetState`] and the diagnostics
/// ([`budget_path`]).
pub fn budget_cascades(
    settings: Res<ShadowAliasingSettings>,
    mut shadow_map: ResMut<DirectionalLightShadowMap>,
    mut original_size: ResMut<OriginalMapSize>,
    bounds: Res<SceneBounds>,
    cameras: Query<CameraItem<'_>>,
    mut lights: Query<(Entity, LightItem<'_>, &mut BudgetState)>,
    mut diagnostics: Diagnostics,
) {
    let app_size = u32::try_from(shadow_map.size).unwrap_or(u32::MAX);
    let fixed = original_size
        .0
        .map_or(app_size, |s| u32::try_from(s).unwrap_or(u32::MAX));
    let mut pending: Vec<Pending> = Vec::new();
    let mut resizing = false;
    for (entity, item, mut budget) in &mut lights {
        let (transform, light, mode, _, cascades, mut state) = item;
        let CascadeMode::Budget(b) = mode else {
            if budget.controller.is_some() || budget.choice.is_some() {
                *budget = BudgetState::default();
            }
            continue;
        };
        state.covers.clear();
        state.errors.clear();
        budget.choice = None;
        budget.error = None;
        if !light.shadow_maps_enabled {
            continue;
        }
        resizing |= b.max_map_size.is_some();
        let mut views: Vec<Entity> = cascades.cascades.keys().copied().collect();
        views.sort();
        let Some(&first) = views.first() else {
            budget.error = Some("Bevy built cascades for no camera".into());
            continue;
        };
        if bounds.receivers.is_empty() {
            budget.error = Some("no shadow receivers in the scene".into());
            continue;
        }
        let v = match cameras
            .get(first)
            .map_err(|e| e.to_string())
            .and_then(|(t, p, c, _)| view(t, p, c, settings.image_height))
        {
            Ok(v) => v,
            Err(e) => {
                budget.error = Some(e);
                continue;
            }
        };
        let input = frame_input(&v, light_dir(transform), &bounds, fixed);
        let size = b.max_map_size.is_none().then_some(fixed);
        let stale =
            !matches!(&budget.controller, Some(k) if k.0 == *b && k.1 == size && k.2 == first);
        if stale {
            match options(b, fixed, &input)
                .and_then(|o| Controller::new(o).map_err(|e| e.to_string()))
            {
                Ok(c) => {
                    budget.controller = Some(Box::new((*b, size, first, c)));
                    budget.switches = 0;
                }
                Err(e) => {
                    budget.controller = None;
                    budget.error = Some(e);
                    continue;
                }
            }
        }
        let Some(kept) = budget.controller.as_mut() else {
            continue;
        };
        let controller = &mut kept.3;
        let decided = controller.frame(&input).map(|d| {
            let choice = BudgetChoice {
                camera: first,
                scheme: d.scheme,
                cascades: d.frame.maps().len(),
                resolution: d.resolution,
                max_error_pixels: d.max_error_pixels,
                texels: d.texels,
                meets_target: d.meets_target,
                switched: d.switched,
                cut: d.cut,
            };
            (choice, Box::new(*d.frame))
        });
        match decided {
            Ok((choice, frame)) => {
                budget.switches += u64::from(choice.switched && !stale);
                pending.push(Pending {
                    light: entity,
                    choice,
                    frame,
                });
            }
            Err(e) => budget.error = Some(e.to_string()),
        }
    }
    // The shared map size: the largest chosen where a light may set it.
    let size = if resizing {
        original_size.0.get_or_insert(shadow_map.size);
        pending
            .iter()
            .map(|p| p.choice.resolution)
            .max()
            .unwrap_or(fixed)
    } else {
        if let Some(s) = original_size.0.take() {
            shadow_map.size = s;
        }
        app_size
    };
    if resizing && shadow_map.size != size as usize {
        shadow_map.size = size as usize;
    }
    let mut figures = [f64::NEG_INFINITY; 6];
    figures[MEETS_TARGET] = f64::INFINITY;
    for p in pending {
        let Ok((_, item, mut budget)) = lights.get_mut(p.light) else {
            continue;
        };
        let (transform, mut light, _, mut config, mut cascades, mut state) = item;
        let state = state.as_mut();
        let original = state.original.get_or_insert_with(|| config.clone()).clone();
        let dir = light_dir(transform);
        let mut views: Vec<Entity> = cascades.cascades.keys().copied().collect();
        views.sort();
        let mut installer = Installer::new(transform, settings.auto_bias);
        let mut choice = p.choice;
        for view_entity in views {
            // The controller's own maps where they are at the shared size; otherwise (another
            // camera, or a smaller choice than another light's) the scheme built again.
            let reuse = view_entity == choice.camera && choice.resolution == size;
            let built = cameras
                .get(view_entity)
                .map_err(|e| e.to_string())
                .and_then(|(t, pr, c, filter)| {
                    let v = view(t, pr, c, settings.image_height)?;
                    if reuse {
                        let maps: Vec<&FrameMap> = p.frame.maps().iter().collect();
                        installer.install(view_entity, &maps, filter, &mut cascades, state);
                        return Ok(None);
                    }
                    frame(&frame_input(&v, dir, &bounds, size).scheme(choice.scheme))
                        .map(|f| Some((f, filter)))
                        .map_err(|e| e.to_string())
                });
            match built {
                Ok(None) => {}
                Ok(Some((f, filter))) => {
                    let maps: Vec<&FrameMap> = f.maps().iter().collect();
                    if view_entity == choice.camera {
                        choice.max_error_pixels =
                            maps.iter().map(|m| m.max_error_pixels).fold(0.0, f64::max);
                        choice.resolution = size;
                        choice.cascades = maps.len();
                        choice.texels = maps.len() as u64 * u64::from(size) * u64::from(size);
                        choice.meets_target = choice.max_error_pixels <= choice_target(&budget);
                    }
                    installer.install(view_entity, &maps, filter, &mut cascades, state);
                }
                Err(e) => {
                    state.errors.insert(view_entity, e);
                }
            }
        }
        installer.finish(&mut config, &original, 0.0, &mut light, state);
        let values = [
            choice.max_error_pixels,
            choice.cascades as f64,
            f64::from(choice.resolution),
            choice.texels as f64,
            f64::from(u8::from(choice.meets_target)),
            budget.switches as f64,
        ];
        for (i, (m, v)) in figures.iter_mut().zip(values).enumerate() {
            // meets_target: 1 only where every budget light meets its target.
            *m = if i == MEETS_TARGET {
                m.min(v)
            } else {
                m.max(v)
            };
        }
        budget.choice = Some(choice);
    }
    for (f, v) in BUDGET_FIGURES.iter().zip(figures) {
        if v.is_finite() {
            diagnostics.add_measurement(&budget_path(f), || v);
        }
    }
}

/// The target of the budget a state's controller was made for.
fn choice_target(b: &BudgetState) -> f64 {
    b.controller
        .as_ref()
        .map_or(f64::INFINITY, |k| k.0.max_error_pixels)
}
