//! What the plugin does with a light: [`CascadeMode`] and the replacement's options.

use crate::replace::ReplacedCascades;
use bevy::prelude::*;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::maps::WarpRule;

/// Put on a `DirectionalLight` to choose what the plugin does with its cascades. A light without
/// it is measured ([`CascadeMode::Measure`]).
#[derive(Component, Debug, Clone, PartialEq, Default)]
#[require(ReplacedCascades)]
pub enum CascadeMode {
    /// Bevy builds the cascades; the plugin only measures them.
    #[default]
    Measure,
    /// The plugin overwrites Bevy's cascades with the crate's (and measures those).
    Replace(Replace),
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
