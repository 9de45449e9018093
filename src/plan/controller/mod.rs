//! The error-budget controller (issue 32 item 1): each frame, the cheapest set-up (a scheme and
//! one square resolution shared by all its maps) for the goal of [`ControllerOptions`] (a target
//! error, a texel budget, or both), kept from frame to frame so that it does not flicker.
//!
//! - **On a cut** (the first frame, or the camera or the light jumped past the thresholds of
//!   [`ControllerOptions`]): every allowed candidate is built once and measured; the set-up is
//!   the one with the fewest texels (`maps × resolution²`) whose resolution, the least allowed by
//!   [`Rounding`](super::allocate::Rounding) that meets the target, is at most the set-up's cap
//!   (`max_resolution`, and the budget's share `√(max_texels / maps)`; ties: the least error,
//!   then the first in the list). Where none can (or without a target), the least error at the
//!   cap.
//! - **Each other frame**: the kept set-up is built at its kept resolution and its error read
//!   from the frame's own measurement
//!   ([`FrameMap::max_error_pixels`](crate::frame::FrameMap::max_error_pixels)). Above the
//!   target, it is resized at once (to meet `margin × target`, so that the next frames have
//!   room), or, where the cap does not allow that, searched again as on a cut (unless the last
//!   search found no candidate that meets the target: then it stays at its cap). At or below
//!   it, a smaller resolution that would have met `margin × target` in this frame and in each
//!   of the last `patience` frames is switched to (without a target: the cap, where the map
//!   count changed it).
//! - **Neighbours**: the kept scheme's neighbours are the allowed schemes with one cascade more
//!   or fewer, then the cheapest candidates of the last search (at most 4).
//!   Every `neighbour_every` frames one of them, in turn, is built and measured; one that would
//!   have been cheaper (fewer texels for `margin × target`; without a target or where the
//!   target is missed, `margin` times less error at its cap) in each of its checks over the
//!   last `patience` frames is switched to, and one that meets a target the kept set-up misses
//!   is switched to at once. In a frame whose kept set-up misses the target, all of them are
//!   measured, and the cheapest that meets it, where cheaper than the kept set-up resized, is
//!   switched to. Equal-error cascades that follow the camera keep the planes of their last
//!   search, as fractions of the visible depth range (one frame, no search); their equal-error
//!   neighbours are measured with those planes resampled and
//!   searched only when switched to.

mod neighbours;
mod options;
mod per_map;
mod search;

/// The most neighbours measured between cuts: one cascade more and fewer, then the cheapest
/// candidates of the last search.
const MAX_NEIGHBOURS: usize = 4;

pub use options::ControllerOptions;

use crate::analytic::partition::MAX_PARTITIONS;
use crate::error::{Error, Result};
use crate::frame::{frame_into, CascadeSplits, Frame, FrameInput, FrameScheme};
use neighbours::{count, neighbours, resampled};

/// The set-up kept between frames.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Setup {
    scheme: FrameScheme<'static>,
    /// The largest map's resolution (every map's, with a shared resolution).
    resolution: u32,
    /// With a resolution per map, each slot's (`Frame::slots` order, the rest 0); all 0 with a
    /// shared resolution.
    each: [u32; MAX_PARTITIONS],
}

impl Setup {
    /// `scheme` with every map at `resolution`.
    fn shared(scheme: FrameScheme<'static>, resolution: u32) -> Self {
        Self {
            scheme,
            resolution,
            each: [0; MAX_PARTITIONS],
        }
    }
}

/// One frame's choice ([`Controller::frame`]).
#[derive(Debug, Clone, Copy)]
pub struct Decision<'c> {
    /// The scheme chosen.
    pub scheme: FrameScheme<'static>,
    /// The largest map's resolution, texels a side (every map's, with
    /// [`ControllerOptions::shared_resolution`]).
    pub resolution: u32,
    /// Each slot's resolution, in [`Frame::slots`](crate::frame::Frame::slots) order: what
    /// [`FrameInput::map_resolutions`](crate::frame::FrameInput::map_resolutions) takes to build
    /// these maps again with `scheme` (all `resolution` with a shared resolution). Equal-error
    /// cascades between cuts are the exception: they keep the planes of their cut's search (the
    /// maps' [`FrameMap::split`](crate::frame::FrameMap::split)s), which the scheme alone would
    /// search again; give those planes as `CascadeSplits::Distances` to rebuild them.
    pub resolutions: &'c [u32],
    /// Its maps, built at `resolution` (their matrices for the GPU, their measured error).
    /// Each map's [`FrameMap::unchanged`](crate::frame::FrameMap::unchanged) compares it with
    /// the map in the same slot of the last decision (the controller may build several set-ups
    /// in one frame before it chooses).
    pub frame: &'c Frame,
    /// The largest [`FrameMap::max_error_pixels`](crate::frame::FrameMap::max_error_pixels)
    /// over the maps: the frame's own measurement, pixels.
    pub max_error_pixels: f64,
    /// The maps' texels together (the sum of each map's resolution²).
    pub texels: u64,
    /// `max_error_pixels ≤ max_error` (`true` without a target). `false` only where no allowed
    /// candidate meets the target within the caps (the set-up then has the least error found).
    pub meets_target: bool,
    /// `texels ≤ max_texels` (`true` without a budget). `false` only where the least allowed
    /// resolution of every allowed candidate is over the budget (the set-up then has the least
    /// error found at the least resolution).
    pub within_budget: bool,
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
    /// The neighbours' maps.
    scratch: Frame,
    setup: Option<Setup>,
    /// The kept set-up is the least error found at its cap: the last search found no
    /// candidate that meets the target, or there is none.
    least: bool,
    /// Frames since the last search while `least`.
    missed: u32,
    /// The error of the set-up the last search chose (pixels).
    found: f64,
    /// The eye, the view direction and the light direction of the last frame.
    last: Option<(glam::DVec3, glam::DVec3, glam::DVec3)>,
    /// Frames in a row in which another resolution (`pending`: smaller, for a target; the cap,
    /// without one) was enough by the margin.
    streak: u32,
    pending: u32,
    /// The interior planes of kept equal-error cascades (that follow the camera), as fractions
    /// of the visible depth range, from the last search of their planes.
    fractions: Vec<f64>,
    /// The schemes allowed at the last search.
    allowed: Vec<FrameScheme<'static>>,
    /// The cheapest candidates of the last search, in order (the chosen one among them).
    ranked: Vec<FrameScheme<'static>>,
    /// The kept scheme's neighbours and, for each, its checks in a row that found it cheaper.
    near: Vec<(FrameScheme<'static>, u32)>,
    /// The last decision's maps (world → clip by slot) and resolution, for
    /// [`FrameMap::unchanged`](crate::frame::FrameMap::unchanged): a frame may build several
    /// set-ups into `frame` before it chooses.
    shown: Vec<Option<(glam::DMat4, u32)>>,
    /// The last decision's resolution per slot ([`Decision::resolutions`]).
    shown_each: Vec<u32>,
    /// With a resolution per map: each slot's frames in a row in which a smaller resolution was
    /// enough by the margin (a target), or frames in a row in which the budget's allocation had
    /// `margin` times less error (no target; slot 0).
    down: [u32; MAX_PARTITIONS],
    /// Each slot's error × resolution of the last build (pixels × texels), scratch.
    products: Vec<Option<f64>>,
    /// The neighbour checked next, and the frames since the last check.
    turn: usize,
    since: u32,
}

impl Controller {
    /// A controller for `options`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming the option: `max_error` (not finite and positive, or
    /// `None` with `max_texels`), `max_texels` (less than one map of the least allowed
    /// resolution), `max_maps` (outside 1 ..= [`MAX_ATLAS_ENTRIES`](crate::maps::atlas::MAX_ATLAS_ENTRIES)),
    /// `rounding` (`Multiple(0)`), `max_resolution` (0, or not allowed by `rounding`),
    /// `candidates` (empty, or holding a clipmap), `retry_every` (0), `margin` (outside (0, 1]), `cut_move` (not
    /// positive), `cut_turn` or `cut_light` (outside (0, π]).
    pub fn new(options: ControllerOptions) -> Result<Self> {
        options.check()?;
        Ok(Self {
            options,
            frame: Frame::default(),
            scratch: Frame::default(),
            setup: None,
            least: false,
            missed: 0,
            found: f64::INFINITY,
            last: None,
            streak: 0,
            pending: 0,
            fractions: Vec::new(),
            allowed: Vec::new(),
            ranked: Vec::new(),
            near: Vec::new(),
            shown: Vec::new(),
            shown_each: Vec::new(),
            down: [0; MAX_PARTITIONS],
            products: Vec::new(),
            turn: 0,
            since: 0,
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

    /// This frame's set-up and maps for `input` (its scheme, `map_resolution`,
    /// `map_resolutions` and `measure` are ignored).
    ///
    /// # Errors
    /// Any error of the frame for the input (its first candidate's, on a cut where none builds);
    /// `receivers` where no candidate builds a map (they are out of view or edge-on to the
    /// light); `max_maps` where every candidate that builds has more maps.
    pub fn frame(&mut self, input: &FrameInput<'_>) -> Result<Decision<'_>> {
        // The resolutions are the controller's to choose.
        let input = &FrameInput {
            map_resolutions: None,
            ..*input
        };
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
        let shared = self.options.shared_resolution;
        let (setup, err) = match (cut, before) {
            (false, Some(kept)) if shared => self.steady(input, kept)?,
            (false, Some(kept)) => self.steady_each(input, kept)?,
            _ => self.search(input)?,
        };
        if cut || before.is_none_or(|b| b.scheme != setup.scheme) {
            self.down = [0; MAX_PARTITIONS];
        }
        if cut || Some(setup) != before {
            self.streak = 0;
            self.pending = 0;
            self.near.clear();
            let mut near = neighbours(setup.scheme, &self.allowed);
            for s in &self.ranked {
                if near.len() < MAX_NEIGHBOURS && *s != setup.scheme && !near.contains(s) {
                    near.push(*s);
                }
            }
            self.near.extend(near.into_iter().map(|s| (s, 0)));
            self.turn = 0;
            self.since = 0;
        }
        self.setup = Some(setup);
        self.frame.mark_unchanged(&self.shown);
        self.frame.fingerprint(&mut self.shown);
        let slots = self.frame.slots().len();
        self.shown_each.clear();
        if shared {
            self.shown_each.resize(slots, setup.resolution);
        } else {
            self.shown_each.extend_from_slice(&setup.each[..slots]);
        }
        let texels = self
            .frame
            .maps()
            .iter()
            .map(|m| u64::from(m.resolution()).pow(2))
            .sum();
        let o = &self.options;
        Ok(Decision {
            scheme: setup.scheme,
            resolution: setup.resolution,
            resolutions: &self.shown_each,
            frame: &self.frame,
            max_error_pixels: err,
            texels,
            meets_target: o.max_error.is_none_or(|t| err <= t),
            within_budget: o.max_texels.is_none_or(|b| texels <= b),
            switched: before.is_some_and(|b| b != setup),
            cut,
        })
    }

    /// A frame that is not a cut: the kept set-up, resized, or a neighbour switched to, as the
    /// module docs say.
    fn steady(&mut self, input: &FrameInput<'_>, kept: Setup) -> Result<(Setup, f64)> {
        let Ok(err) = self.build_kept(input, kept) else {
            return self.search(input);
        };
        let Some(cap) = self.options.cap_for(self.frame.maps().len()) else {
            return self.search(input);
        };
        if kept.resolution > cap {
            // More maps than when it was chosen: down to the budget's share at once.
            let s = Setup {
                resolution: cap,
                ..kept
            };
            return match self.build_kept(input, s) {
                Ok(e) if self.options.cap_for(self.frame.maps().len()) >= Some(cap) => Ok((s, e)),
                _ => self.search(input),
            };
        }
        let margin = self.options.margin;
        let r = f64::from(kept.resolution);
        if self.options.max_error.is_none() && self.drifted(err) {
            return self.search(input);
        }
        let pending = match self.options.max_error {
            Some(t) if err > t => {
                // Up at once, with the margin's headroom, within the cap; where the cap forbids
                // it, search (unless the last search found nothing that meets the target).
                let up = self.resolution_for(err * r, margin * t, cap).unwrap_or(cap);
                let n = self.frame.maps().len() as u64;
                let up_texels = (up > kept.resolution).then(|| n * u64::from(up).pow(2));
                if let Some(f) = self.on_miss(input, kept, t, up_texels)? {
                    self.least = false;
                    return Ok(f);
                }
                if up > kept.resolution {
                    if let Some(f) = self.fit(input, kept.scheme, up, cap)? {
                        self.least = false;
                        return Ok(f);
                    }
                }
                self.missed += 1;
                if !self.least || self.missed >= self.options.retry_every {
                    return self.search(input);
                }
                let s = Setup {
                    resolution: cap,
                    ..kept
                };
                let e = self.build_kept(input, s)?;
                return self.neighbour(input, s, e);
            }
            Some(t) => {
                self.least = false;
                self.resolution_for(err * r, margin * t, cap)
                    .filter(|&d| d < kept.resolution)
            }
            None => Some(cap).filter(|&c| c != kept.resolution),
        };
        match pending {
            Some(p)
                if self.pending == 0 || self.pending == p || self.options.max_error.is_some() =>
            {
                self.streak = self.streak.saturating_add(1);
                self.pending = self.pending.max(p);
            }
            _ => {
                self.streak = 0;
                self.pending = 0;
            }
        }
        if self.streak > self.options.patience {
            let other = Setup {
                resolution: self.pending,
                ..kept
            };
            if let Ok(e) = self.build_kept(input, other) {
                let n = self.frame.maps().len();
                let fits = self.options.cap_for(n) >= Some(other.resolution);
                if fits && self.options.max_error.is_none_or(|t| e <= t) {
                    return Ok((other, e));
                }
            }
            // The other resolution missed after all (a stable map's snap): keep the set-up.
            self.streak = 0;
            self.pending = 0;
            let e = self.build_kept(input, kept)?;
            return self.neighbour(input, kept, e);
        }
        self.neighbour(input, kept, err)
    }

    /// The neighbour to measure in this frame (one every `neighbour_every` frames, in turn), if
    /// any.
    fn next_neighbour(&mut self) -> Option<usize> {
        let every = self.options.neighbour_every;
        if every == 0 || self.near.is_empty() {
            return None;
        }
        self.since += 1;
        if self.since < every {
            return None;
        }
        self.since = 0;
        let i = self.turn % self.near.len();
        self.turn = i + 1;
        Some(i)
    }

    /// Every `neighbour_every` frames, one neighbour of the kept set-up (in `self.frame`, with
    /// error `err`) measured, and switched to as the module docs say; otherwise the kept one.
    fn neighbour(&mut self, input: &FrameInput<'_>, kept: Setup, err: f64) -> Result<(Setup, f64)> {
        let Some(i) = self.next_neighbour() else {
            return Ok((kept, err));
        };
        let every = self.options.neighbour_every;
        let scheme = self.near[i].0;
        let kept_texels = self.frame.maps().len() as u64 * u64::from(kept.resolution).pow(2);
        let Some((n, e_n)) = self.probe(input, scheme, kept) else {
            self.near[i].1 = 0;
            return Ok((kept, err));
        };
        let Some(cap) = self.options.cap_for(n) else {
            self.near[i].1 = 0;
            return Ok((kept, err));
        };
        let r = f64::from(kept.resolution);
        let margin = self.options.margin;
        // (better, at once, the resolution to switch to)
        let (better, now, res) = match self.options.max_error {
            Some(t) if !(self.least && err > t) => {
                match self.resolution_for(e_n * r, margin * t, cap) {
                    Some(rn) => (n as u64 * u64::from(rn).pow(2) < kept_texels, false, rn),
                    None => (false, false, 0),
                }
            }
            Some(t) => match self.resolution_for(e_n * r, t, cap) {
                Some(rn) => (true, true, rn),
                None => (e_n * r / f64::from(cap) < margin * err, false, cap),
            },
            None => (e_n * r / f64::from(cap) < margin * err, false, cap),
        };
        self.near[i].1 = if better { self.near[i].1 + 1 } else { 0 };
        // Its first check in a row was `(streak − 1) × every × neighbours` frames ago.
        let span =
            u64::from(self.near[i].1.saturating_sub(1)) * u64::from(every) * self.near.len() as u64;
        let ready = span >= u64::from(self.options.patience);
        if !(now || (better && ready)) {
            return Ok((kept, err));
        }
        // Switch: the neighbour built for real (an equal-error one searched); kept where it
        // turns out not to be better.
        self.near[i].1 = 0;
        let kept_fractions = std::mem::take(&mut self.fractions);
        let switched = match self.options.max_error {
            Some(_) => self.fit(input, scheme, res, cap)?,
            None => None,
        };
        let switched = match (switched, self.options.max_error) {
            (Some(f), _) => Some(f),
            (None, None) => {
                let s = Setup::shared(scheme, res);
                self.build_kept(input, s).ok().map(|e| (s, e))
            }
            (None, Some(_)) => None,
        };
        if let Some((s, e)) = switched {
            let texels = self.frame.maps().len() as u64 * u64::from(s.resolution).pow(2);
            let fits = self.options.cap_for(self.frame.maps().len()) >= Some(s.resolution);
            let good = match self.options.max_error {
                Some(t) if e <= t => self.least || texels < kept_texels,
                Some(_) => false,
                None => e < err,
            };
            if fits && good {
                self.least = self.options.max_error.is_none();
                return Ok((s, e));
            }
        }
        self.fractions = kept_fractions;
        let e = self.build_kept(input, kept)?;
        Ok((kept, e))
    }

    /// `scheme` built into the scratch frame at the kept resolution (an equal-error one that
    /// follows the camera with the kept cascades' planes resampled, [`resampled`]): its maps and
    /// largest error; `None` where it does not build (or is equal-error and the kept set-up has
    /// no planes to resample).
    fn probe(
        &mut self,
        input: &FrameInput<'_>,
        scheme: FrameScheme<'static>,
        kept: Setup,
    ) -> Option<(usize, f64)> {
        let max_maps = self.options.max_maps;
        let e = match scheme {
            FrameScheme::Cascades {
                splits: CascadeSplits::EqualError { k },
                rule,
            } => {
                if count(&kept.scheme) != Some(self.fractions.len() + 1) {
                    return None;
                }
                let f = resampled(&self.fractions, k);
                let s = FrameScheme::Cascades {
                    splits: CascadeSplits::Fractions {
                        fractions: &f,
                        overlap: 0.0,
                    },
                    rule,
                };
                build(input, s, kept.resolution, max_maps, &mut self.scratch)
            }
            _ => build(input, scheme, kept.resolution, max_maps, &mut self.scratch),
        };
        e.ok().map(|e| (self.scratch.maps().len(), e))
    }

    /// A frame whose kept set-up misses the target `t` (unless `neighbour_every` is 0): every
    /// neighbour probed, and the one with the fewest texels for `margin × t`, where fewer than
    /// the kept set-up resized (`up_texels`), built and returned if it meets the target.
    fn on_miss(
        &mut self,
        input: &FrameInput<'_>,
        kept: Setup,
        t: f64,
        up_texels: Option<u64>,
    ) -> Result<Option<(Setup, f64)>> {
        if self.options.neighbour_every == 0 {
            return Ok(None);
        }
        let r = f64::from(kept.resolution);
        let margin = self.options.margin;
        let mut best: Option<(u64, FrameScheme<'static>, u32, u32)> = None;
        for i in 0..self.near.len() {
            let scheme = self.near[i].0;
            let Some((n, e_n)) = self.probe(input, scheme, kept) else {
                continue;
            };
            let Some(cap) = self.options.cap_for(n) else {
                continue;
            };
            if let Some(rn) = self.resolution_for(e_n * r, margin * t, cap) {
                let texels = n as u64 * u64::from(rn).pow(2);
                if up_texels.is_none_or(|u| texels < u) && best.is_none_or(|b| texels < b.0) {
                    best = Some((texels, scheme, rn, cap));
                }
            }
        }
        let Some((_, scheme, res, cap)) = best else {
            return Ok(None);
        };
        self.without_kept_planes(|c| c.fit(input, scheme, res, cap))
    }

    /// `fit` (a neighbour built for real) without the kept equal-error planes, which are not
    /// the neighbour's (its own are searched); they are given back where it returns `None`.
    fn without_kept_planes<R>(
        &mut self,
        fit: impl FnOnce(&mut Self) -> Result<Option<R>>,
    ) -> Result<Option<R>> {
        let kept = std::mem::take(&mut self.fractions);
        let f = fit(self)?;
        if f.is_none() {
            self.fractions = kept;
        }
        Ok(f)
    }

    /// `setup` built into the controller's frame; its largest measured error. Equal-error
    /// cascades that follow the camera are built with the planes their last search placed, as
    /// fractions of the visible depth range (one frame, no search); their planes are searched
    /// again (and kept) where there are none or the frame refuses them.
    fn build_kept(&mut self, input: &FrameInput<'_>, setup: Setup) -> Result<f64> {
        let max_maps = self.options.max_maps;
        let res = setup.resolution;
        // With a resolution per map, each slot's (the rest of `each` is 0).
        let n = setup.each.iter().take_while(|&&r| r > 0).count();
        let each = FrameInput {
            map_resolutions: (n > 0).then(|| &setup.each[..n]),
            ..*input
        };
        let input = &each;
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

    /// Without a target: whether the kept set-up's error `err` has grown past twice the error
    /// the last search found, at least `retry_every` frames after it (a scheme that the camera
    /// has moved away from since, whose neighbours may not reach the better ones).
    fn drifted(&mut self, err: f64) -> bool {
        self.missed = self.missed.saturating_add(1);
        err > 2.0 * self.found && self.missed >= self.options.retry_every
    }

    /// The least allowed resolution whose error is at most `e` for maps whose largest error
    /// times resolution is `err_res` (pixels × texels), `None` above `cap`.
    fn resolution_for(&self, err_res: f64, e: f64, cap: u32) -> Option<u32> {
        let r = self.options.rounding.at_least(err_res / e)?;
        u32::try_from(r).ok().filter(|&r| r <= cap)
    }

    /// `scheme` built into the controller's frame from resolution `res` up until its measured
    /// error meets the target (a stable map's snap changes its error a little with the
    /// resolution): `None` where the cap (`cap`, and the budget's share for the maps built) is
    /// reached first. Only with a target.
    fn fit(
        &mut self,
        input: &FrameInput<'_>,
        scheme: FrameScheme<'static>,
        mut res: u32,
        cap: u32,
    ) -> Result<Option<(Setup, f64)>> {
        let Some(target) = self.options.max_error else {
            return Ok(None);
        };
        for _ in 0..4 {
            let s = Setup::shared(scheme, res);
            let err = self.build_kept(input, s)?;
            let cap = self
                .options
                .cap_for(self.frame.maps().len())
                .map_or(0, |c| c.min(cap));
            if res > cap {
                return Ok(None);
            }
            if err <= target {
                return Ok(Some((s, err)));
            }
            let next = self.resolution_for(err * f64::from(res), target, cap);
            let next = next
                .filter(|&n| n > res)
                .or_else(|| self.resolution_for(f64::from(res) + 1.0, 1.0, cap));
            match next {
                Some(n) => res = n,
                None => return Ok(None),
            }
        }
        Ok(None)
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

/// A set-up of `n` maps whose least resolution is over the texel budget.
fn over_budget(n: usize) -> Error {
    Error::invalid(
        "max_texels",
        format!(
            "is less than {n} maps of the least resolution allowed, and every allowed \
             candidate that builds has at least {n} maps: raise it or allow fewer maps"
        ),
    )
}

/// A frame that builds no map.
fn nothing_to_plan() -> Error {
    Error::invalid(
        "receivers",
        "need no map (they are out of view or edge-on to the light): there is nothing to \
         control; check the receivers' boxes and the camera",
    )
}
