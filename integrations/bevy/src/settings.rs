//! What the plugin does with a light: [`CascadeMode`] and the replacement's options.

use crate::budget::BudgetState;
use crate::replace::ReplacedCascades;
use bevy::prelude::*;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::maps::WarpRule;

/// Put on a `DirectionalLight` to choose what the plugin does with its cascades. A light without
/// it is measured ([`CascadeMode::Measure`]).
#[derive(Component, Debug, Clone, PartialEq, Default)]
#[require(ReplacedCascades, BudgetState)]
pub enum CascadeMode {
    /// Bevy builds the cascades; the plugin only measures them.
    #[default]
    Measure,
    /// The plugin overwrites Bevy's cascades with the crate's (and measures those).
    Replace(Replace),
    /// The plugin chooses the cascades each frame for a target error with the crate's
    /// error-budget controller (`shadow_aliasing::plan::Controller`), among the orthographic
    /// schemes Bevy draws, and, where allowed, the shadow map's size (docs/bevy.md, "Budget").
    Budget(Budget),
}

/// Budget mode's options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Budget {
    /// The target: the largest error, pixels of the camera's image per shadow texel (finite,
    /// > 0).
    pub max_error_pixels: f64,
    /// `Some(n)`: the plugin sets `DirectionalLightShadowMap::size` (one size for every light)
    /// to the least power of two up to n (itself a power of two) that meets the target;
    /// `None`: the size stays the app's and only the cascades are chosen.
    pub max_map_size: Option<u32>,
    /// Against flicker: a cheaper set-up is switched to only after it would have met
    /// `margin × max_error_pixels` in this frame and each of the `patience` frames before it
    /// (the controller's `ControllerOptions::patience`, default 30).
    pub patience: u32,
    /// See `patience`, in (0, 1] (default 0.9); also the headroom of a resize upward.
    pub margin: f64,
}

impl Budget {
    /// The target `max_error_pixels` at the app's map size, patience 30 frames, margin 0.9.
    #[must_use]
    pub fn new(max_error_pixels: f64) -> Self {
        Self {
            max_error_pixels,
            max_map_size: None,
            patience: 30,
            margin: 0.9,
        }
    }
}

impl Default for Budget {
    /// One pixel at the app's map size.
    fn default() -> Self {
        Self::new(1.0)
    }
}

/// Replace mode's options.
#[derive(Debug, Clone, PartialEq)]
pub struct Replace {
    /// How each cascade is fitted.
    pub fit: Fit,
    /// Where the cascades are split.
    pub splits: Splits,
    /// The visible depth range of the receivers `(z_min, z_max)` (view depth, world units), from
    /// the previous frame's depth-buffer min/max reduction (sample-distribution shadow maps):
    /// the cascades are then spread over what is seen. `None`: the camera's near to far.
    pub depth_range: Option<(f64, f64)>,
}

impl Default for Replace {
    /// Focused orthographic cascades on Bevy's own splits.
    fn default() -> Self {
        Self {
            fit: Fit::Focused(WarpRule::Uniform),
            splits: Splits::Bevy,
            depth_range: None,
        }
    }
}

/// How each cascade is fitted.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Fit {
    /// Fitted to its focus body (the slice ∩ the receivers' box) with a warp rule:
    /// `WarpRule::Uniform` gives orthographic maps; any other rule a warped (perspective) map,
    /// which Bevy's shader samples correctly since it divides by w.
    Focused(WarpRule),
    /// Stable cascades: world-fixed light space, the slice's bounding sphere, snapped to whole
    /// texels (no shimmering under camera moves), depth from the body and casters.
    Stable,
}

/// Where the cascades are split.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Splits {
    /// Bevy's splits from the light's `CascadeShadowConfig` (as `CascadeShadowConfigBuilder`
    /// makes them: far bounds a geometric series, `overlap_proportion` cross-faded).
    Bevy,
    /// k cascades (1..=4) of one of the crate's split schemes over the visible depth range, no
    /// cross-fade band.
    Scheme {
        /// The split scheme.
        scheme: SplitScheme,
        /// Number of cascades, 1..=4.
        k: usize,
    },
    /// k cascades (1..=4) whose measured maximum errors are equal (the crate's planner:
    /// `CascadeSplits::EqualError`), no cross-fade band.
    EqualError {
        /// Number of cascades, 1..=4.
        k: usize,
    },
}
