//! `shadow-aliasing-bevy`: a Bevy 0.19 plugin that measures the perspective aliasing error of
//! Bevy's directional-light cascades with the `shadow-aliasing` crate, and can replace them with
//! the crate's frame API (docs/bevy.md).
//!
//! ```no_run
//! use bevy::prelude::*;
//! use shadow_aliasing_bevy::{CascadeErrors, CascadeMode, Replace, ShadowAliasingPlugin};
//!
//! fn main() {
//!     App::new()
//!         .add_plugins((DefaultPlugins, ShadowAliasingPlugin))
//!         .add_systems(Startup, |mut commands: Commands| {
//!             // Measured by default; `CascadeMode::Replace` overwrites Bevy's cascades.
//!             commands.spawn((DirectionalLight { shadow_maps_enabled: true, ..default() },
//!                             CascadeMode::Replace(Replace::default())));
//!         })
//!         .add_systems(Update, |lights: Query<&CascadeErrors>| {
//!             for e in &lights {
//!                 for v in e.views.values() {
//!                     println!("max error {:?} px", v.max_error_pixels());
//!                 }
//!             }
//!         })
//!         .run();
//! }
//! ```
//!
//! # Modes
//!
//! - **Measure** (every shadowed `DirectionalLight`, unless its [`CascadeMode`] says otherwise):
//!   each frame, for every camera, each cascade's M_x, M_z, S̄ and maximum error in pixels over
//!   its focus body B (the cascade's slice of the view frustum ∩ the merged box of the scene's
//!   receivers), published as the light's [`CascadeErrors`] and as diagnostics
//!   ([`cascade_path`], [`MAX_ERROR_PIXELS`]).
//! - **Replace** ([`CascadeMode::Replace`]): the cascades rewritten with the crate's frame API
//!   (focused or stable, Bevy's splits, a split scheme or equal-error splits, an optional SDSM
//!   depth range), then measured like Bevy's.
//! - **Budget** ([`CascadeMode::Budget`]): one number in, the largest error in pixels; each
//!   frame the crate's error-budget controller chooses the cascades (count, splits, fit) and,
//!   where allowed, the shadow map's size among what Bevy can draw ([`bevy_candidates`]),
//!   published as [`BudgetState`] and diagnostics ([`budget_path`]).
//!
//! Replace and budget mode set the light's bias from the crate's ([`AppliedBias`]) unless
//! [`ShadowAliasingSettings::auto_bias`] is off.
//!
//! # The error lens
//!
//! [`ErrorLens`] on a camera draws the crate's per-pixel error heat map (the WGSL module's
//! `sa_error_lens`, with its legend) over the camera's image, for whatever cascades Bevy draws: a
//! full-screen pass after tone mapping that reads Bevy's depth and normal prepass
//! (docs/bevy.md, "The error lens").
//!
//! # System order (`PostUpdate`)
//!
//! Bevy computes the meshes' `Aabb`s (`VisibilitySystems::CalculateBounds`), propagates the
//! transforms (`TransformSystems::Propagate`) and builds the cascades
//! (`build_directional_light_cascades` in `SimulationLightSystems::UpdateDirectionalLightCascades`,
//! bevy_light/src/lib.rs, `LightPlugin::build`). After all three the plugin runs
//! [`ShadowAliasingSystems::Collect`] (the receivers' and casters' world boxes),
//! [`ShadowAliasingSystems::Replace`] and [`ShadowAliasingSystems::Measure`], all before
//! `SimulationLightSystems::UpdateLightFrusta`, whose `update_directional_light_frusta` culls
//! the casters of each cascade with the matrices the plugin left; then [`prepare_error_lens`].

mod bias;
mod budget;
mod convert;
mod lens;
mod lens_render;
mod measure;
mod replace;
mod scene;
mod settings;
mod view;

pub use bias::{needed_normal_bias, pcf_radius, AppliedBias};
pub use budget::{
    bevy_candidates, budget_cascades, budget_path, BudgetChoice, BudgetState, OriginalMapSize,
};
pub use lens::{prepare_error_lens, ErrorLens, ErrorLensMaps, LENS_MAPS};
pub use measure::{
    bevy_covers, cascade_path, measure_cascade, measure_cascades, CascadeError, CascadeErrors,
    CascadeSource, ViewCascadeErrors, MAX_CASCADES, MAX_ERROR_PIXELS,
};
pub use replace::{replace_cascades, restore_cascade_config, to_bevy_cascade, ReplacedCascades};
pub use scene::{collect_scene_bounds, world_box, SceneBounds};
pub use settings::{Budget, CascadeMode, Fit, Replace, Splits};
pub use shadow_aliasing;

use bevy::camera::visibility::VisibilitySystems;
use bevy::light::{DirectionalLight, SimulationLightSystems};
use bevy::prelude::*;
use bevy::transform::TransformSystems;

/// The plugin (module docs).
#[derive(Debug, Default, Clone, Copy)]
pub struct ShadowAliasingPlugin;

/// The plugin's settings.
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShadowAliasingSettings {
    /// The image height in pixels the error is counted in while a camera's viewport size is not
    /// known (no render target yet, or no renderer). Default 1080.
    pub image_height: u32,
    /// Replace and budget mode set the light's `shadow_normal_bias` and `shadow_depth_bias`
    /// from the crate's bias for the maps they drew ([`AppliedBias`], docs/bevy.md, "Automatic
    /// bias"); `false` leaves them as the user set them. Default `true`.
    pub auto_bias: bool,
}

impl Default for ShadowAliasingSettings {
    fn default() -> Self {
        Self {
            image_height: 1080,
            auto_bias: true,
        }
    }
}

/// The plugin's system sets in `PostUpdate` (module docs): `Restore` before Bevy's cascades,
/// then `Collect`, `Replace` and `Measure` after them.
#[derive(SystemSet, Debug, Clone, PartialEq, Eq, Hash)]
pub enum ShadowAliasingSystems {
    /// [`restore_cascade_config`], before Bevy builds the cascades.
    Restore,
    /// [`collect_scene_bounds`].
    Collect,
    /// [`replace_cascades`] and [`budget_cascades`].
    Replace,
    /// [`measure_cascades`].
    Measure,
}

impl Plugin for ShadowAliasingPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<ShadowAliasingSettings>()
            .init_resource::<SceneBounds>()
            .register_required_components::<DirectionalLight, CascadeErrors>()
            .configure_sets(
                PostUpdate,
                (
                    ShadowAliasingSystems::Collect,
                    ShadowAliasingSystems::Replace,
                    ShadowAliasingSystems::Measure,
                )
                    .chain()
                    .after(SimulationLightSystems::UpdateDirectionalLightCascades)
                    .after(VisibilitySystems::CalculateBounds)
                    .after(TransformSystems::Propagate)
                    .before(SimulationLightSystems::UpdateLightFrusta),
            )
            .configure_sets(
                PostUpdate,
                ShadowAliasingSystems::Restore
                    .before(SimulationLightSystems::UpdateDirectionalLightCascades),
            )
            .add_systems(
                PostUpdate,
                (
                    restore_cascade_config.in_set(ShadowAliasingSystems::Restore),
                    collect_scene_bounds.in_set(ShadowAliasingSystems::Collect),
                    (replace_cascades, budget_cascades)
                        .chain()
                        .in_set(ShadowAliasingSystems::Replace),
                    measure_cascades.in_set(ShadowAliasingSystems::Measure),
                    prepare_error_lens.after(ShadowAliasingSystems::Measure),
                ),
            );
        app.add_plugins(lens_render::ErrorLensRenderPlugin);
        app.init_resource::<OriginalMapSize>();
        measure::register_diagnostics(app);
        budget::register_budget_diagnostics(app);
    }
}
