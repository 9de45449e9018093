//! The error-budget controller (issue 32 item 1): each frame, the cheapest set-up (a scheme and
//! one square resolution shared by all its maps) whose measured largest error is at most a
//! target, kept from frame to frame so that it does not flicker.
//!
//! - **On a cut** (the first frame, or the camera or the light jumped past the thresholds of
//!   [`ControllerOptions`]): every allowed candidate is built once and measured; the set-up is
//!   the one with the fewest texels (`maps × resolution²`) whose resolution, the least allowed by
//!   [`Rounding`] that meets the target, is at most `max_resolution` (ties: the least error, then
//!   the first in the list). Where none can, the least error at `max_resolution`.
//! - **Each other frame**: the kept set-up is built at its kept resolution and its error read
//!   from the frame's own measurement
//!   ([`FrameMap::max_error_pixels`](crate::frame::FrameMap::max_error_pixels)). Above the
//!   target, it is resized at once (to meet `margin × target`, so that the next frames have
//!   room), or, where `max_resolution` does not allow that, searched again as on a cut. At or
//!   below it, a smaller resolution that would have met `margin × target` in this frame and in
//!   each of the last `patience` frames is switched to. Equal-error cascades that follow the
//!   camera keep the planes of their last search, as fractions of the visible depth range: one
//!   frame, no search.
//!
//! The scheme changes only on a cut or when the kept scheme cannot meet the target: the
//! controller does not look at other schemes between cuts (docs/planning.md, "An error budget per
//! frame", says what is not done).

use super::allocate::Rounding;
use super::candidates::candidates;
use crate::error::{fmt_num, Error, Result};
use crate::frame::{frame_into, CascadeSplits, Frame, FrameInput, FrameScheme};
use crate::maps::atlas::MAX_ATLAS_ENTRIES;

/// What the controller is asked for and what it may choose from.
#[derive(Debug, Clone, PartialEq)]
pub struct ControllerOptions {
    /// The target: the largest error, pixels of the image per texel.
    pub max_error: f64,
    /// The most maps a set-up may have (1 ..= [`MAX_ATLAS_ENTRIES`]).
    pub max_maps: usize,
    /// The resolutions allowed (every map of a set-up shares one square resolution).
    pub rounding: Rounding,
    /// The largest resolution allowed, texels a side (an engine's texture limit); allowed by
    /// `rounding` itself.
    pub max_resolution: u32,
    /// The schemes allowed; `None`: [`candidates`] of each cut's input without the clipmap.
    pub candidates: Option<Vec<FrameScheme<'static>>>,
    /// A smaller resolution is switched to only after it would have met `margin × max_error`
    /// in this frame and each of the `patience` frames before it.
    pub patience: u32,
    /// See `patience`; in (0, 1]. Also the headroom of a resize upward.
    pub margin: f64,
    /// A cut when the camera's eye moved more than this fraction of its far distance since the
    /// last frame.
    pub cut_move: f64,
    /// A cut when the view direction turned more than this, radians, since the last frame.
    pub cut_turn: f64,
    /// A cut when the light's direction turned more than this, radians, since the last frame.
    pub cut_light: f64,
}

impl ControllerOptions {
    /// The target `max_error` with the defaults: at most [`MAX_ATLAS_ENTRIES`] maps, powers of
    /// two up to 8192, every candidate but the clipmap, patience 30 frames, margin 0.9, a cut
    /// past 10 % of the far distance, 15° of the view or 5° of the light.
    #[must_use]
    pub fn new(max_error: f64) -> Self {
        Self {
            max_error,
            max_maps: MAX_ATLAS_ENTRIES,
            rounding: Rounding::PowerOfTwo,
            max_resolution: 8192,
            candidates: None,
            patience: 30,
            margin: 0.9,
            cut_move: 0.1,
            cut_turn: 15f64.to_radians(),
            cut_light: 5f64.to_radians(),
        }
    }

    fn check(&self) -> Result<()> {
        let e = self.max_error;
        if !(e.is_finite() && e > 0.0) {
            return Err(Error::invalid(
                "max_error",
                format!(
                    "must be a finite, positive number of pixels (got {})",
                    fmt_num(e)
                ),
            ));
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
        if r == 0 || self.rounding.at_least(f64::from(r)) != Some(u64::from(r)) {
            return Err(Error::invalid(
                "max_resolution",
                format!(
                    "must be a resolution that rounding {:?} allows (got {r})",
                    self.rounding
                ),
            ));
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

/// The set-up kept between frames.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Setup {
    scheme: FrameScheme<'static>,
    resolution: u32,
}

/// One frame's choice ([`Controller::frame`]).
#[derive(Debug, Clone, Copy)]
pub struct Decision<'c> {
    /// The scheme chosen.
    pub scheme: FrameScheme<'static>,
    /// Every map's resolution, texels a side.
    pub resolution: u32,
    /// Its maps, built at `resolution` (their matrices for the GPU, their measured error).
    pub frame: &'c Frame,
    /// The largest [`FrameMap::max_error_pixels`](crate::frame::FrameMap::max_error_pixels)
    /// over the maps: the frame's own measurement, pixels.
    pub max_error_pixels: f64,
    /// `maps × resolution²`.
    pub texels: u64,
    /// `max_error_pixels ≤ max_error`. `false` only where no allowed candidate meets the target
    /// within `max_resolution` (the set-up then has the least error found).
    pub meets_target: bool,
    /// The set-up (scheme or resolution) differs from the last frame's.
    pub switched: bool,
    /// This frame was a cut: every candidate was searched.
    pub cut: bool,
}

/// The controller: one per light and camera; call [`Controller::frame`] every frame.
#[derive(Debug, Clone)]
pub struct Controller {
    options: ControllerOptions,
    frame: Frame,
    setup: Option<Setup>,
    /// The eye, the view direction and the light direction of the last frame.
    last: Option<(glam::DVec3, glam::DVec3, glam::DVec3)>,
    /// Frames in a row in which a resolution below the kept one met `margin × max_error`, and
    /// the largest such resolution over them.
    streak: u32,
    down: u32,
    /// The interior planes of kept equal-error cascades (that follow the camera), as fractions
    /// of the visible depth range, from the last search of their planes.
    fractions: Vec<f64>,
}

impl Controller {
    /// A controller for `options`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming the option: `max_error` (not finite and positive),
    /// `max_maps` (outside 1 ..= [`MAX_ATLAS_ENTRIES`]), `rounding` (`Multiple(0)`),
    /// `max_resolution` (0, or not allowed by `rounding`), `candidates` (empty, or holding a
    /// clipmap), `margin` (outside (0, 1]), `cut_move` (not positive), `cut_turn` or `cut_light`
    /// (outside (0, π]).
    pub fn new(options: ControllerOptions) -> Result<Self> {
        options.check()?;
        Ok(Self {
            options,
            frame: Frame::default(),
            setup: None,
            last: None,
            streak: 0,
            down: 0,
            fractions: Vec::new(),
        })
    }

    /// The options.
    #[must_use]
    pub fn options(&self) -> &ControllerOptions {
        &self.options
    }

    /// Makes the next frame a cut (every candidate searched): for what the controller does not
    /// watch, such as a change of the receivers' or casters' bounds.
    pub fn cut(&mut self) {
        self.last = None;
    }

    /// This frame's set-up and maps for `input` (its scheme, map resolution and `measure` are
    /// ignored).
    ///
    /// # Errors
    /// Any error of the frame for the input (its first candidate's, on a cut where none builds);
    /// `receivers` where no candidate builds a map (they are out of view or edge-on to the
    /// light); `max_maps` where every candidate that builds has more maps.
    pub fn frame(&mut self, input: &FrameInput<'_>) -> Result<Decision<'_>> {
        let eye_to_world = input.camera.world_to_eye().inverse();
        let now = (
            eye_to_world.transform_point3(glam::DVec3::ZERO),
            eye_to_world
                .transform_vector3(glam::DVec3::NEG_Z)
                .normalize(),
            input.light_dir_world.normalize(),
        );
        let cut = match (self.setup, self.last) {
            (Some(_), Some((eye, view, light))) => {
                let o = &self.options;
                let far = input.camera.view().far();
                eye.distance(now.0) > o.cut_move * far
                    || view.angle_between(now.1) > o.cut_turn
                    || light.angle_between(now.2) > o.cut_light
                    || !(now.2.is_finite())
            }
            _ => true,
        };
        self.last = Some(now);
        let before = self.setup;
        let (setup, err) = match (cut, before) {
            (false, Some(kept)) => self.steady(input, kept)?,
            _ => self.search(input)?,
        };
        if Some(setup) != before {
            self.streak = 0;
            self.down = 0;
        }
        self.setup = Some(setup);
        let target = self.options.max_error;
        Ok(Decision {
            scheme: setup.scheme,
            resolution: setup.resolution,
            frame: &self.frame,
            max_error_pixels: err,
            texels: self.frame.maps().len() as u64 * u64::from(setup.resolution).pow(2),
            meets_target: err <= target,
            switched: before.is_some_and(|b| b != setup),
            cut,
        })
    }

    /// A frame that is not a cut: the kept set-up, resized as the module docs say.
    fn steady(&mut self, input: &FrameInput<'_>, kept: Setup) -> Result<(Setup, f64)> {
        let o = &self.options;
        let (target, margin, patience) = (o.max_error, o.margin, o.patience);
        let Ok(err) = self.build_kept(input, kept) else {
            return self.search(input);
        };
        let r = f64::from(kept.resolution);
        if err > target {
            // Up at once, with the margin's headroom; where the cap forbids it, search.
            let up = self.resolution_for(err * r, margin * target);
            if let Some(res) = up.filter(|&u| u > kept.resolution) {
                if let Ok(Some(f)) = self.fit(input, kept.scheme, res) {
                    return Ok(f);
                }
            }
            return self.search(input);
        }
        match self.resolution_for(err * r, margin * target) {
            Some(d) if d < kept.resolution => {
                self.streak = self.streak.saturating_add(1);
                self.down = self.down.max(d);
            }
            _ => {
                self.streak = 0;
                self.down = 0;
            }
        }
        if self.streak > patience {
            let down = Setup {
                resolution: self.down,
                ..kept
            };
            if let Ok(e) = self.build_kept(input, down) {
                if e <= target {
                    return Ok((down, e));
                }
            }
            // The smaller maps missed after all (a stable map's snap): keep the set-up.
            self.streak = 0;
            self.down = 0;
            let e = self.build_kept(input, kept)?;
            return Ok((kept, e));
        }
        Ok((kept, err))
    }

    /// `setup` built into the controller's frame; its largest measured error. Equal-error
    /// cascades that follow the camera are built with the planes their last search placed, as
    /// fractions of the visible depth range (one frame, no search); their planes are searched
    /// again (and kept) where there are none or the frame refuses them.
    fn build_kept(&mut self, input: &FrameInput<'_>, setup: Setup) -> Result<f64> {
        let max_maps = self.options.max_maps;
        let res = setup.resolution;
        let FrameScheme::Cascades {
            splits: CascadeSplits::EqualError { k },
            rule,
        } = setup.scheme
        else {
            return build(input, setup.scheme, res, max_maps, &mut self.frame);
        };
        if self.fractions.len() + 1 == k {
            let kept = FrameScheme::Cascades {
                splits: CascadeSplits::Fractions {
                    fractions: &self.fractions,
                    overlap: 0.0,
                },
                rule,
            };
            if let Ok(e) = build(input, kept, res, max_maps, &mut self.frame) {
                return Ok(e);
            }
        }
        let e = build(input, setup.scheme, res, max_maps, &mut self.frame)?;
        self.fractions.clear();
        let slots = self.frame.slots();
        let planes: Option<Vec<(f64, f64)>> = slots.iter().map(|m| m.map(|m| m.split)).collect();
        if let Some(p) = planes.filter(|p| p.len() == k) {
            let (z0, zk) = (p[0].0, p[k - 1].1);
            self.fractions
                .extend(p[..k - 1].iter().map(|s| (s.1 - z0) / (zk - z0)));
        }
        Ok(e)
    }

    /// The least allowed resolution whose error is at most `e` for maps whose largest error
    /// times resolution is `err_res` (pixels × texels), `None` above `max_resolution`.
    fn resolution_for(&self, err_res: f64, e: f64) -> Option<u32> {
        let r = self.options.rounding.at_least(err_res / e)?;
        u32::try_from(r)
            .ok()
            .filter(|&r| r <= self.options.max_resolution)
    }

    /// `scheme` built into the controller's frame from resolution `res` up until its measured
    /// error meets the target (a stable map's snap changes its error a little with the
    /// resolution): `None` where `max_resolution` is reached first.
    fn fit(
        &mut self,
        input: &FrameInput<'_>,
        scheme: FrameScheme<'static>,
        mut res: u32,
    ) -> Result<Option<(Setup, f64)>> {
        let target = self.options.max_error;
        for _ in 0..4 {
            let s = Setup {
                scheme,
                resolution: res,
            };
            let err = self.build_kept(input, s)?;
            if err <= target {
                return Ok(Some((s, err)));
            }
            let next = self.resolution_for(err * f64::from(res), target);
            let next = next
                .filter(|&n| n > res)
                .or_else(|| self.resolution_for(f64::from(res) + 1.0, 1.0));
            match next {
                Some(n) => res = n,
                None => return Ok(None),
            }
        }
        Ok(None)
    }

    /// A cut: every candidate built once at `max_resolution` and measured; the fewest texels
    /// that meet the target, else the least error at `max_resolution`.
    fn search(&mut self, input: &FrameInput<'_>) -> Result<(Setup, f64)> {
        let list = match &self.options.candidates {
            Some(l) => l.clone(),
            None => candidates(input)
                .into_iter()
                .filter(|s| !matches!(s, FrameScheme::Clipmap(_)))
                .collect(),
        };
        let cap = self.options.max_resolution;
        let target = self.options.max_error;
        self.fractions.clear();
        let mut scratch = Frame::default();
        // (texels, error at that resolution, index, resolution) of those that meet the target;
        // (error at the cap, index) of every one built.
        let mut meet: Vec<(u64, f64, usize, u32)> = Vec::new();
        let mut least: Option<(f64, usize)> = None;
        let mut first_err = None;
        for (i, s) in list.iter().enumerate() {
            let at_cap = Setup {
                scheme: *s,
                resolution: cap,
            };
            let err = match build(
                input,
                at_cap.scheme,
                cap,
                self.options.max_maps,
                &mut scratch,
            ) {
                Ok(e) => e,
                Err(e) => {
                    first_err.get_or_insert(e);
                    continue;
                }
            };
            if least.is_none_or(|(l, _)| err < l) {
                least = Some((err, i));
            }
            if let Some(r) = self.resolution_for(err * f64::from(cap), target) {
                let n = scratch.maps().len() as u64;
                let e = err * f64::from(cap) / f64::from(r);
                meet.push((n * u64::from(r).pow(2), e, i, r));
            }
        }
        meet.sort_by(|a, b| {
            (a.0, a.1, a.2)
                .partial_cmp(&(b.0, b.1, b.2))
                .expect("finite")
        });
        for &(_, _, i, r) in &meet {
            if let Some(f) = self.fit(input, list[i], r)? {
                return Ok(f);
            }
        }
        let Some((_, i)) = least else {
            return Err(first_err.unwrap_or_else(nothing_to_plan));
        };
        let s = Setup {
            scheme: list[i],
            resolution: cap,
        };
        let err = self.build_kept(input, s)?;
        Ok((s, err))
    }
}

/// `setup` built into `out` for `input`; its largest measured error.
fn build<'a>(
    input: &FrameInput<'a>,
    scheme: FrameScheme<'a>,
    resolution: u32,
    max_maps: usize,
    out: &mut Frame,
) -> Result<f64> {
    let mut one = input.scheme(scheme).measure(true);
    one.map_resolution = resolution;
    frame_into(&one, out)?;
    let n = out.maps().len();
    if n == 0 {
        return Err(nothing_to_plan());
    }
    if n > max_maps {
        return Err(Error::invalid(
            "max_maps",
            format!("is {max_maps}, and this scheme has {n} maps: allow more maps"),
        ));
    }
    Ok(out
        .maps()
        .iter()
        .map(|m| m.max_error_pixels)
        .fold(0.0, f64::max))
}

/// A frame that builds no map.
fn nothing_to_plan() -> Error {
    Error::invalid(
        "receivers",
        "need no map (they are out of view or edge-on to the light): there is nothing to \
         control; check the receivers' boxes and the camera",
    )
}
