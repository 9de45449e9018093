//! What the controller is asked for ([`ControllerOptions`]) and the checks of it.

use crate::error::{fmt_num, Error, Result};
use crate::frame::FrameScheme;
use crate::maps::atlas::MAX_ATLAS_ENTRIES;
use crate::plan::allocate::{Rounding, MAX_RESOLUTION};

/// What the controller is asked for and what it may choose from.
///
/// The goal is `max_error`, `max_texels` or both: the fewest texels whose largest error is at
/// most `max_error` (within `max_texels` where given), else the least error that fits
/// `max_texels` and `max_resolution`.
#[derive(Debug, Clone, PartialEq)]
pub struct ControllerOptions {
    /// The target: the largest error, pixels of the image per texel; `None`: the least error
    /// within `max_texels`.
    pub max_error: Option<f64>,
    /// The texel budget: every map of a set-up together (the sum of their `resolution²`) at
    /// most this; `None`: no budget but `max_maps × max_resolution²`.
    pub max_texels: Option<u64>,
    /// The most maps a set-up may have (1 ..= [`MAX_ATLAS_ENTRIES`]).
    pub max_maps: usize,
    /// The resolutions allowed (each map square).
    pub rounding: Rounding,
    /// Every map of a set-up shares one resolution (`true`, the default: Bevy's and three.js's
    /// one shadow-map size), or each map has its own ([`FrameInput::map_resolutions`](crate::frame::FrameInput::map_resolutions):
    /// separate textures or an atlas), chosen by its own error as
    /// [`allocate`](crate::plan::allocate) does (equal-error planes are placed at one
    /// resolution, then each map sized).
    pub shared_resolution: bool,
    /// The largest resolution allowed, texels a side (an engine's texture limit); allowed by
    /// `rounding` itself.
    pub max_resolution: u32,
    /// The schemes allowed; `None`: [`candidates`](crate::plan::candidates::candidates) of each
    /// cut's input without the clipmap.
    pub candidates: Option<Vec<FrameScheme<'static>>>,
    /// A cheaper set-up (a smaller resolution, or a neighbour) is switched to only after it
    /// would have been enough, by `margin`, in this frame and each of the `patience` frames
    /// before it (a neighbour: in each of its checks over them).
    pub patience: u32,
    /// See `patience`; in (0, 1]: a cheaper set-up must meet `margin × max_error` (without a
    /// target: have at most `margin` times the kept set-up's error). Also the headroom of a
    /// resize upward.
    pub margin: f64,
    /// Between cuts, one neighbour of the kept scheme (one cascade more or fewer among the
    /// allowed schemes, then the cheapest candidates of the last search: at most 4) is measured
    /// every `neighbour_every` frames, in turn, and all of them in a frame whose kept set-up
    /// misses the target; 0: never.
    pub neighbour_every: u32,
    /// While the last search found no allowed set-up that meets `max_error` (the kept one is
    /// the least error found), every allowed candidate is searched again every `retry_every`
    /// frames; 1: every frame that misses the target (the target met in every frame where any
    /// allowed set-up can meet it, at a cut's cost per such frame). Without a target, a search
    /// runs again where the kept set-up's error has grown past twice the last search's, at
    /// least `retry_every` frames after it.
    pub retry_every: u32,
    /// A cut when the camera's eye moved more than this fraction of its far distance since the
    /// last frame.
    pub cut_move: f64,
    /// A cut when the view direction turned more than this, radians, since the last frame.
    pub cut_turn: f64,
    /// A cut when the light's direction turned more than this, radians, since the last frame.
    pub cut_light: f64,
}

impl ControllerOptions {
    /// The target `max_error` (pixels) with the defaults: no texel budget, at most
    /// [`MAX_ATLAS_ENTRIES`] maps, powers of two up to 8192, every candidate but the clipmap,
    /// patience 30 frames, margin 0.9, a neighbour every 4 frames, a search again every 30
    /// frames while the target cannot be met, a cut past 10 % of the far
    /// distance, 15° of the view or 5° of the light.
    #[must_use]
    pub fn new(max_error: f64) -> Self {
        Self {
            max_error: Some(max_error),
            max_texels: None,
            max_maps: MAX_ATLAS_ENTRIES,
            rounding: Rounding::PowerOfTwo,
            shared_resolution: true,
            max_resolution: 8192,
            candidates: None,
            patience: 30,
            margin: 0.9,
            neighbour_every: 4,
            retry_every: 30,
            cut_move: 0.1,
            cut_turn: 15f64.to_radians(),
            cut_light: 5f64.to_radians(),
        }
    }

    /// The least error within `max_texels` (all maps together), with [`Self::new`]'s other
    /// defaults. Give both goals with `ControllerOptions { max_texels: Some(t), ..new(e) }`.
    #[must_use]
    pub fn budget(max_texels: u64) -> Self {
        Self {
            max_error: None,
            max_texels: Some(max_texels),
            ..Self::new(1.0)
        }
    }

    /// The largest resolution allowed for a set-up of `maps` maps: at most `max_resolution`,
    /// allowed by `rounding`, and within `max_texels`; `None` where even the least allowed
    /// resolution exceeds the budget.
    pub(crate) fn cap_for(&self, maps: usize) -> Option<u32> {
        let mut most = u64::from(self.max_resolution);
        if let Some(b) = self.max_texels {
            most = most.min((b / maps.max(1) as u64).isqrt());
        }
        let r = match self.rounding {
            Rounding::Whole => most,
            Rounding::PowerOfTwo if most == 0 => 0,
            Rounding::PowerOfTwo => 1 << most.ilog2(),
            Rounding::Multiple(m) => most / u64::from(m) * u64::from(m),
        };
        u32::try_from(r).ok().filter(|&r| r >= 3)
    }

    pub(crate) fn check(&self) -> Result<()> {
        if self.max_error.is_none() && self.max_texels.is_none() {
            return Err(Error::invalid(
                "max_error",
                "and max_texels are both None: give a target error in pixels, a texel budget, \
                 or both",
            ));
        }
        if let Some(e) = self.max_error {
            if !(e.is_finite() && e > 0.0) {
                return Err(Error::invalid(
                    "max_error",
                    format!(
                        "must be a finite, positive number of pixels (got {})",
                        fmt_num(e)
                    ),
                ));
            }
        }
        if !(1..=MAX_ATLAS_ENTRIES).contains(&self.max_maps) {
            return Err(Error::invalid(
                "max_maps",
                format!(
                    "must lie in [1, {MAX_ATLAS_ENTRIES}] (got {})",
                    self.max_maps
                ),
            ));
        }
        if self.rounding == Rounding::Multiple(0) {
            return Err(Error::invalid(
                "rounding",
                "must be a multiple of at least 1 texel (got Multiple(0))",
            ));
        }
        let r = self.max_resolution;
        if r < 3 || self.rounding.at_least(f64::from(r)) != Some(u64::from(r)) {
            return Err(Error::invalid(
                "max_resolution",
                format!(
                    "must be a resolution from 3 texels (a map's least) to {MAX_RESOLUTION} that \
                     the rounding allows ({}) (got {r})",
                    self.rounding.words()
                ),
            ));
        }
        if let Some(b) = self.max_texels {
            if self.cap_for(1).is_none() {
                let least = self.rounding.at_least(3.0).unwrap_or(3).pow(2);
                return Err(Error::invalid(
                    "max_texels",
                    format!(
                        "is {b}, less than one map of the least resolution the rounding allows \
                         ({}, at least 3 texels a side: {least} texels): raise it",
                        self.rounding.words()
                    ),
                ));
            }
        }
        if let Some(list) = &self.candidates {
            if list.is_empty() {
                return Err(Error::invalid(
                    "candidates",
                    "must hold at least one scheme: give None for every candidate, or a part \
                     of plan::candidates(input)",
                ));
            }
            if list.iter().any(|s| matches!(s, FrameScheme::Clipmap(_))) {
                return Err(Error::invalid(
                    "candidates",
                    "must not hold a clipmap: its levels' resolution is fixed and its knob is \
                     the LOD bias (plan::clipmap); remove it",
                ));
            }
        }
        if self.retry_every == 0 {
            return Err(Error::invalid(
                "retry_every",
                "must be at least 1 frame (1: search again in every frame that misses the target)",
            ));
        }
        if !(self.margin > 0.0 && self.margin <= 1.0) {
            return Err(Error::invalid(
                "margin",
                format!("must lie in (0, 1] (got {})", fmt_num(self.margin)),
            ));
        }
        let positive = |name, v: f64, most: f64| {
            if v > 0.0 && v <= most {
                Ok(())
            } else {
                Err(Error::invalid(
                    name,
                    format!("must lie in (0, {}] (got {})", fmt_num(most), fmt_num(v)),
                ))
            }
        };
        positive("cut_move", self.cut_move, f64::MAX)?;
        positive("cut_turn", self.cut_turn, std::f64::consts::PI)?;
        positive("cut_light", self.cut_light, std::f64::consts::PI)
    }
}
