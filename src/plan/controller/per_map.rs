//! The controller with a resolution per map ([`ControllerOptions::shared_resolution`] false):
//! each map's resolution is chosen by its own error, as [`allocate`] does for the planner.
//!
//! A map's error times its resolution (pixels × texels) does not depend on the resolution for
//! maps that are not snapped to their texels, and changes by a fraction of a texel for stable
//! cascades: each frame's measurement at the kept resolutions says what every map needs.
//!
//! - **On a cut**: every allowed candidate is built once with every map at `max_resolution`
//!   (equal-error planes placed there, and kept between cuts as with a shared resolution); for a target `t` each map gets the least allowed resolution that
//!   meets it, and the set-up is the one with the fewest texels (ties: the least error, then the
//!   first in the list) whose resolutions are within `max_resolution` and `max_texels`. Where
//!   none is (or without a target), the least largest error that fits ([`allocate`] within the
//!   budget, at most `max_resolution` a map), at the fewest texels that give it.
//! - **Each other frame**: the kept scheme is built at its kept resolutions. A map over the
//!   target is raised at once (to meet `margin × t`); a map that would have met `margin × t` at
//!   a smaller resolution in this frame and each of the last `patience` frames is lowered (each
//!   map counted on its own); a set-up over the budget (a map has appeared where the cut found
//!   none) is searched again. Without a target, the budget's allocation is switched to when it
//!   has had `margin` times less error for `patience` frames, and at once where the kept
//!   set-up is over the budget or has more than twice the allocation's error.
//! - **Neighbours** as with a shared resolution (one cascade more or fewer, the last search's
//!   cheapest): built with every map at one resolution, compared by the texels their own
//!   resolutions would take.

use super::options::ControllerOptions;
use super::{build, nothing_to_plan, over_budget, Controller, Setup, MAX_NEIGHBOURS};
use crate::analytic::partition::MAX_PARTITIONS;
use crate::error::Result;
use crate::frame::{Frame, FrameInput, FrameScheme};
use crate::plan::allocate::{allocate, MapError};

/// Each slot's error × resolution (pixels × texels) in `f`; `None` for a slot without a map.
fn products(f: &Frame, out: &mut Vec<Option<f64>>) {
    out.clear();
    out.extend(f.slots().iter().map(|m| {
        m.as_ref()
            .map(|m| m.max_error_pixels * f64::from(m.resolution()))
    }));
}

/// The least resolution the options allow that is at least `need` and at least 3 (the frame's
/// least), `None` above `max_resolution`.
fn at_least(o: &ControllerOptions, need: f64) -> Option<u32> {
    let r = o.rounding.at_least(need.max(3.0))?;
    u32::try_from(r).ok().filter(|&r| r <= o.max_resolution)
}

/// The texel budget: `max_texels`, else `max_maps × max_resolution²`.
fn budget(o: &ControllerOptions) -> u64 {
    o.max_texels
        .unwrap_or(o.max_maps as u64 * u64::from(o.max_resolution).pow(2))
}

/// Resolutions into `out` (one per slot; a slot without a map the least allowed) for the maps
/// of products `p` to meet error `e` each: `(texels, largest error)`, `None` where a map would
/// need more than `max_resolution` or the maps more than the budget.
fn sized(
    o: &ControllerOptions,
    p: &[Option<f64>],
    e: f64,
    out: &mut [u32; MAX_PARTITIONS],
) -> Option<(u64, f64)> {
    let (mut texels, mut worst) = (0u64, 0.0f64);
    for (i, pi) in p.iter().enumerate() {
        out[i] = match pi {
            Some(pi) => {
                let r = at_least(o, pi / e)?;
                texels += u64::from(r).pow(2);
                worst = worst.max(pi / f64::from(r));
                r
            }
            None => at_least(o, 3.0)?,
        };
    }
    out[p.len()..].fill(0);
    (texels <= budget(o)).then_some((texels, worst))
}

/// The least largest error for products `p` within the budget and `max_resolution`, at the
/// fewest texels that give it: the resolutions into `out`, `(texels, largest error)`; `None`
/// where even the least allowed resolutions are over the budget.
fn least(
    o: &ControllerOptions,
    p: &[Option<f64>],
    out: &mut [u32; MAX_PARTITIONS],
) -> Option<(u64, f64)> {
    let maps: Vec<MapError> = p
        .iter()
        .flatten()
        .map(|&x| MapError {
            max_mx: x,
            max_mz: x,
        })
        .collect();
    // An image 1 pixel high: each map's error at `res` texels is its product over `res`.
    let a = allocate(&maps, 1, budget(o), o.rounding).ok()?;
    let top = f64::from(o.max_resolution);
    // A map the allocation gives more than `max_resolution` has its least error there, which
    // bounds the largest error of any allocation from below.
    let e = a
        .maps()
        .iter()
        .zip(&maps)
        .map(|(r, m)| m.max_mx / (r.res_s as f64).min(top))
        .fold(0.0, f64::max);
    sized(o, p, e * (1.0 + 1e-12), out)
}

fn setup(scheme: FrameScheme<'static>, each: [u32; MAX_PARTITIONS]) -> Setup {
    Setup {
        scheme,
        resolution: each.iter().copied().max().unwrap_or(0),
        each,
    }
}

impl Controller {
    /// A cut with a resolution per map (module docs), over the allowed `list`.
    pub(super) fn search_each_in(
        &mut self,
        input: &FrameInput<'_>,
        list: &[FrameScheme<'static>],
    ) -> Result<(Setup, f64)> {
        let top = self.options.max_resolution;
        let target = self.options.max_error;
        self.fractions.clear();
        // (texels, error, index, resolutions) of those that meet the target; (least error,
        // index, resolutions) of every one built.
        let mut meet = Vec::new();
        let mut errors = Vec::new();
        let mut first_err = None;
        let mut each = [0; MAX_PARTITIONS];
        for (i, s) in list.iter().enumerate() {
            if let Err(e) = build(input, *s, top, self.options.max_maps, &mut self.scratch) {
                first_err.get_or_insert(e);
                continue;
            }
            products(&self.scratch, &mut self.products);
            if let Some(t) = target {
                if let Some((texels, e)) = sized(&self.options, &self.products, t, &mut each) {
                    meet.push((texels, e, i, each));
                }
            }
            match least(&self.options, &self.products, &mut each) {
                Some((_, e)) => errors.push((e, i, each)),
                None => {
                    first_err.get_or_insert_with(|| over_budget(self.scratch.maps().len()));
                }
            }
        }
        meet.sort_by(|a, b| {
            (a.0, a.1, a.2)
                .partial_cmp(&(b.0, b.1, b.2))
                .expect("finite")
        });
        errors.sort_by(|a, b| (a.0, a.1).partial_cmp(&(b.0, b.1)).expect("finite"));
        self.ranked.clear();
        if meet.is_empty() {
            self.ranked
                .extend(errors.iter().take(MAX_NEIGHBOURS).map(|e| list[e.1]));
        } else {
            self.ranked
                .extend(meet.iter().take(MAX_NEIGHBOURS).map(|m| list[m.2]));
        }
        for &(_, _, i, each) in &meet {
            if let Some(f) = self.fit_each(input, list[i], each)? {
                self.least = false;
                return Ok(f);
            }
        }
        let Some(&(_, i, each)) = errors.first() else {
            return Err(first_err.unwrap_or_else(nothing_to_plan));
        };
        let err = self.build_kept(input, setup(list[i], each))?;
        self.least = true;
        Ok((setup(list[i], each), err))
    }

    /// `scheme` built into the controller's frame at `each` and, where a map misses the
    /// target (a stable map's snap moves its error a little with the resolution), at the next
    /// resolutions up: `None` where the build fails, a map would pass `max_resolution` or the
    /// maps the budget. Only with a target.
    fn fit_each(
        &mut self,
        input: &FrameInput<'_>,
        scheme: FrameScheme<'static>,
        mut each: [u32; MAX_PARTITIONS],
    ) -> Result<Option<(Setup, f64)>> {
        let Some(t) = self.options.max_error else {
            return Ok(None);
        };
        for _ in 0..4 {
            let Ok(err) = self.build_kept(input, setup(scheme, each)) else {
                return Ok(None);
            };
            if err <= t {
                return Ok(Some((setup(scheme, each), err)));
            }
            for (i, m) in self.frame.slots().iter().enumerate() {
                if let Some(m) = m.as_ref().filter(|m| m.max_error_pixels > t) {
                    let need = m.max_error_pixels * f64::from(each[i]) / t;
                    let Some(up) = at_least(&self.options, need.max(f64::from(each[i]) + 1.0))
                    else {
                        return Ok(None);
                    };
                    each[i] = up;
                }
            }
            let texels: u64 = self
                .frame
                .slots()
                .iter()
                .zip(&each)
                .filter(|(m, _)| m.is_some())
                .map(|(_, &r)| u64::from(r).pow(2))
                .sum();
            if texels > budget(&self.options) {
                return Ok(None);
            }
        }
        Ok(None)
    }

    /// A frame that is not a cut, with a resolution per map (module docs).
    pub(super) fn steady_each(
        &mut self,
        input: &FrameInput<'_>,
        kept: Setup,
    ) -> Result<(Setup, f64)> {
        let Ok(err) = self.build_kept(input, setup(kept.scheme, kept.each)) else {
            return self.search(input);
        };
        products(&self.frame, &mut self.products);
        let margin = self.options.margin;
        let mut each = kept.each;
        match self.options.max_error {
            Some(t) if err > t => {
                // Every map over the target up at once, with the margin's headroom.
                let mut fits = true;
                for (i, p) in self.products.iter().enumerate() {
                    if let Some(p) = p.filter(|p| p / f64::from(kept.each[i]) > t) {
                        match at_least(&self.options, p / (margin * t)) {
                            Some(r) => each[i] = r.max(kept.each[i]),
                            None => fits = false,
                        }
                    }
                }
                let up = fits.then(|| texels_of(&self.products, &each));
                let up = up.filter(|&u| u <= budget(&self.options));
                if let Some(f) = self.on_miss_each(input, kept, t, up)? {
                    self.least = false;
                    return Ok(f);
                }
                if up.is_some() {
                    if let Some(f) = self.fit_each(input, kept.scheme, each)? {
                        self.least = false;
                        return Ok(f);
                    }
                }
                self.missed += 1;
                if !self.least || self.missed >= self.options.retry_every {
                    return self.search(input);
                }
                let e = self.build_kept(input, setup(kept.scheme, kept.each))?;
                return self.neighbour_each(input, kept, e);
            }
            Some(_) if texels_of(&self.products, &kept.each) > budget(&self.options) => {
                // A map has appeared since at the least resolution and taken the set-up over
                // the budget: search again.
                return self.search(input);
            }
            Some(t) => {
                self.least = false;
                let mut lower = false;
                for (i, p) in self.products.iter().enumerate() {
                    let want = p.and_then(|p| at_least(&self.options, p / (margin * t)));
                    match want.filter(|&w| w < kept.each[i]) {
                        Some(w) => {
                            self.down[i] = self.down[i].saturating_add(1);
                            if self.down[i] > self.options.patience {
                                each[i] = w;
                                lower = true;
                            }
                        }
                        None => self.down[i] = 0,
                    }
                }
                if lower {
                    if let Some(f) = self.fit_each(input, kept.scheme, each)? {
                        if f.0.each != kept.each {
                            for (i, d) in self.down.iter_mut().enumerate() {
                                if each[i] != kept.each[i] {
                                    *d = 0;
                                }
                            }
                            return Ok(f);
                        }
                    }
                    // The smaller resolutions missed after all: keep the set-up.
                    self.down = [0; MAX_PARTITIONS];
                    let e = self.build_kept(input, setup(kept.scheme, kept.each))?;
                    return self.neighbour_each(input, kept, e);
                }
            }
            None => {
                // The budget's allocation for this frame's errors, switched to when it has had
                // `margin` times less error for `patience` frames, or at once where the kept
                // set-up is over the budget or has more than twice its error (a map that has
                // appeared since at the least resolution).
                if self.drifted(err) {
                    return self.search(input);
                }
                let over = texels_of(&self.products, &kept.each) > budget(&self.options);
                match least(&self.options, &self.products, &mut each) {
                    Some((_, e)) if each != kept.each && e < margin * err => {
                        self.down[0] = self.down[0].saturating_add(1);
                        if over || 2.0 * e < err || self.down[0] > self.options.patience {
                            self.down[0] = 0;
                            if let Ok(e) = self.build_kept(input, setup(kept.scheme, each)) {
                                return Ok((setup(kept.scheme, each), e));
                            }
                            let e = self.build_kept(input, setup(kept.scheme, kept.each))?;
                            return Ok((kept, e));
                        }
                    }
                    _ => self.down[0] = 0,
                }
            }
        }
        self.neighbour_each(input, kept, err)
    }

    /// `scheme` built into the scratch frame with every map at one resolution (an equal-error
    /// one with the kept planes resampled, as with a shared resolution); the resolutions its
    /// maps need into `out` and `(texels, error)`: for `margin × max_error` (`None` where they
    /// do not fit), or without a target the least error within the budget.
    fn probe_each(
        &mut self,
        input: &FrameInput<'_>,
        scheme: FrameScheme<'static>,
        kept: Setup,
        e: Option<f64>,
        out: &mut [u32; MAX_PARTITIONS],
    ) -> Option<(u64, f64)> {
        self.probe(input, scheme, kept)?;
        products(&self.scratch, &mut self.products);
        match e {
            Some(e) => sized(&self.options, &self.products, e, out),
            None => least(&self.options, &self.products, out),
        }
    }

    /// Every neighbour probed in a frame whose kept set-up misses the target `t`: the one with
    /// the fewest texels for `margin × t`, where fewer than the kept set-up raised (`up`; any
    /// where it cannot be), built and returned if it meets the target.
    fn on_miss_each(
        &mut self,
        input: &FrameInput<'_>,
        kept: Setup,
        t: f64,
        up: Option<u64>,
    ) -> Result<Option<(Setup, f64)>> {
        if self.options.neighbour_every == 0 {
            return Ok(None);
        }
        let margin = self.options.margin;
        let mut best: Option<(u64, FrameScheme<'static>, [u32; MAX_PARTITIONS])> = None;
        let mut each = [0; MAX_PARTITIONS];
        for i in 0..self.near.len() {
            let scheme = self.near[i].0;
            if let Some((texels, _)) =
                self.probe_each(input, scheme, kept, Some(margin * t), &mut each)
            {
                if up.is_none_or(|u| texels < u) && best.is_none_or(|b| texels < b.0) {
                    best = Some((texels, scheme, each));
                }
            }
        }
        let Some((_, scheme, each)) = best else {
            return Ok(None);
        };
        self.without_kept_planes(|c| c.fit_each(input, scheme, each))
    }

    /// Every `neighbour_every` frames, one neighbour measured and switched to as the module
    /// docs of the controller say, by the texels of its own resolutions; otherwise the kept
    /// set-up (in the controller's frame, with error `err`).
    fn neighbour_each(
        &mut self,
        input: &FrameInput<'_>,
        kept: Setup,
        err: f64,
    ) -> Result<(Setup, f64)> {
        let Some(i) = self.next_neighbour() else {
            return Ok((kept, err));
        };
        let every = self.options.neighbour_every;
        let scheme = self.near[i].0;
        products(&self.frame, &mut self.products);
        let kept_texels = texels_of(&self.products, &kept.each);
        let margin = self.options.margin;
        let target = self.options.max_error;
        let mut each = [0; MAX_PARTITIONS];
        let probe = self.probe_each(input, scheme, kept, target.map(|t| margin * t), &mut each);
        let (better, now) = match (probe, target) {
            (Some((texels, _)), Some(t)) if !(self.least && err > t) => {
                (texels < kept_texels, false)
            }
            (Some(_), Some(_)) => (true, true),
            (Some((_, e)), None) => (e < margin * err, false),
            (None, _) => (false, false),
        };
        self.near[i].1 = if better { self.near[i].1 + 1 } else { 0 };
        let span =
            u64::from(self.near[i].1.saturating_sub(1)) * u64::from(every) * self.near.len() as u64;
        if !(now || (better && span >= u64::from(self.options.patience))) {
            return Ok((kept, err));
        }
        self.near[i].1 = 0;
        let kept_fractions = std::mem::take(&mut self.fractions);
        let switched = match target {
            Some(_) => self.fit_each(input, scheme, each)?,
            None => self
                .build_kept(input, setup(scheme, each))
                .ok()
                .map(|e| (setup(scheme, each), e)),
        };
        if let Some((s, e)) = switched {
            products(&self.frame, &mut self.products);
            let texels = texels_of(&self.products, &s.each);
            let good = match target {
                Some(t) if e <= t => self.least || texels < kept_texels,
                Some(_) => false,
                None => e < err,
            };
            if good && texels <= budget(&self.options) {
                self.least = target.is_none();
                return Ok((s, e));
            }
        }
        self.fractions = kept_fractions;
        let e = self.build_kept(input, setup(kept.scheme, kept.each))?;
        Ok((kept, e))
    }
}

/// The texels of the maps of products `p` (slots with a map) at resolutions `each`.
fn texels_of(p: &[Option<f64>], each: &[u32; MAX_PARTITIONS]) -> u64 {
    p.iter()
        .zip(each)
        .filter(|(p, _)| p.is_some())
        .map(|(_, &r)| u64::from(r).pow(2))
        .sum()
}
