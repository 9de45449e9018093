//! The clipmap planner (issue 24 item 4): for a frame's camera, scene and light, the levels a
//! clipmap ([`FrameScheme::Clipmap`]) needs, the error each guarantees, the pages each needs,
//! and the LOD bias that fits a page pool.
//!
//! - **Levels**: the first and last level that the visible depth range needs
//!   ([`LevelChoice::levels_needed`]).
//! - **Error**: over the depths `[a, b]` where a level is chosen, its error lies in
//!   `[t H / (2 b tan θ), t H / (2 a tan θ)]` pixels, t the level's texel
//!   ([`LevelChoice::error_at`]). For a level that no clamp reaches, that is
//!   `(2^{bias−1}, 2^bias]`. Each level also carries the error measured over its focus body.
//! - **Pages**: the pages of the level's page grid that its focus body's footprint touches (the
//!   convex hull of its vertices in the map, each row of pages cut by the hull). A renderer
//!   that marks pages from its depth buffer asks for at most these.
//! - **Pool**: the least LOD bias (the finest levels) whose pages fit a pool, by bisection on the
//!   bias ([`clipmap_for_pool`]).
//! - **Target**: the fewest pages whose measured error meets a target ([`clipmap_for_error`]),
//!   the planner's clipmap candidate.
//!
//! docs/planning.md gives the measured figures.

use crate::analytic::partition::MAX_PARTITIONS;
use crate::error::{fmt_num, Error, Result};
use crate::frame::{
    frame, ClipmapOptions, FrameInput, FrameMap, FrameScheme, LevelChoice, MAX_BODY_VERTICES,
};
use crate::geom::hull::convex_hull;
use glam::DVec2;

/// The bisection on the LOD bias stops once its bracket is this narrow.
const BIAS_TOLERANCE: f64 = 1e-6;

/// The grid of LOD biases scanned below the bisection's answer ([`clipmap_for_pool`]).
const GRID: f64 = 1.0 / 64.0;

/// One level of a [`ClipmapPlan`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelPlan {
    /// The level.
    pub level: i32,
    /// The eye depths where the shader picks it, within the visible depth range.
    pub depths: (f64, f64),
    /// The error it guarantees over those depths, pixels: `(at the far end, at the near end)`,
    /// the least and the largest (the error is `t H / (2 z tan θ)`).
    pub error_bound: (f64, f64),
    /// Its texel edge, world units.
    pub texel: f64,
    /// Its error measured over its focus body, pixels; `None` where the body is empty (no map).
    pub max_error_pixels: Option<f64>,
    /// The pages its focus body's footprint touches (0 where the body is empty).
    pub pages: u32,
}

/// What the clipmap needs for one frame ([`plan_clipmap`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClipmapPlan {
    /// The level choice (its `bias` is the one in effect).
    pub choice: LevelChoice,
    levels: [Option<LevelPlan>; MAX_PARTITIONS],
    len: usize,
}

impl ClipmapPlan {
    /// The levels needed, finest first.
    pub fn levels(&self) -> impl Iterator<Item = &LevelPlan> {
        self.levels[..self.len].iter().flatten()
    }

    /// The first and last level the visible depth range needs.
    #[must_use]
    pub fn level_range(&self) -> (i32, i32) {
        let first = self.levels[0].map_or(0, |l| l.level);
        let last = self.levels[self.len - 1].map_or(first, |l| l.level);
        (first, last)
    }

    /// The pages of every level.
    #[must_use]
    pub fn pages(&self) -> u64 {
        self.levels().map(|l| u64::from(l.pages)).sum()
    }

    /// The largest measured error over every level's focus body, pixels (0 when no level has a
    /// body).
    #[must_use]
    pub fn max_error_pixels(&self) -> f64 {
        self.levels()
            .filter_map(|l| l.max_error_pixels)
            .fold(0.0, f64::max)
    }
}

/// The clipmap `options` for the camera, scene and light of `input` (whose own scheme is not
/// used; its `map_resolution` is the levels' resolution): its levels, each level's error bound,
/// measured error and pages.
///
/// # Errors
/// As [`frame`] with [`FrameScheme::Clipmap`]: [`Error::InvalidArgument`] naming a field of
/// [`ClipmapOptions`], `last_level` when the visible depths need a coarser level, `depth_range`
/// when they need more levels than a frame holds.
pub fn plan_clipmap(input: &FrameInput<'_>, options: &ClipmapOptions) -> Result<ClipmapPlan> {
    let input = input.scheme(FrameScheme::Clipmap(*options)).measure(true);
    let f = frame(&input)?;
    let choice = LevelChoice::new(
        input.camera.view(),
        input.image_height,
        input.map_resolution,
        options,
    )?;
    let mut plan = ClipmapPlan {
        choice,
        levels: [None; MAX_PARTITIONS],
        len: 0,
    };
    // The frame's slots are the levels needed, finest first, `None` where B is empty.
    let (zn, zf) = visible(&input);
    let (first, _) = choice.levels_needed(zn, zf)?;
    let per_side = input.map_resolution / options.page_texels;
    for (level, slot) in (first..).zip(f.slots()) {
        let (depths, max_error_pixels, pages) = match slot {
            Some(m) => (
                m.split,
                Some(m.max_error_pixels),
                pages_touched(m, per_side),
            ),
            None => (choice.level_depths(level, zn, zf), None, 0),
        };
        plan.levels[plan.len] = Some(LevelPlan {
            level,
            depths,
            error_bound: (
                choice.error_at(level, depths.1),
                choice.error_at(level, depths.0),
            ),
            texel: choice.texel(level),
            max_error_pixels,
            pages,
        });
        plan.len += 1;
    }
    if plan.len == 0 {
        // No slot at all cannot happen (one level at least is needed); kept typed.
        return Err(Error::Degenerate("the clipmap has no level".into()));
    }
    Ok(plan)
}

/// The visible depth range of a valid input: the camera's, cut to `depth_range`.
fn visible(input: &FrameInput<'_>) -> (f64, f64) {
    let view = input.camera.view();
    match input.depth_range {
        Some((a, b)) => (a.max(view.near()), b.min(view.far())),
        None => (view.near(), view.far()),
    }
}

/// The pages of a level's grid (`per_side` pages a side) that the footprint of the map's focus
/// body touches: the convex hull of its vertices in page units, each row of pages cut by it.
#[must_use]
pub fn pages_touched(map: &FrameMap, per_side: u32) -> u32 {
    let m = map.shadow.matrix();
    let scale = 0.5 * f64::from(per_side);
    let mut pts = [DVec2::ZERO; MAX_BODY_VERTICES];
    let n = map.body().len();
    for (q, p) in pts.iter_mut().zip(map.body()) {
        let h = m * p.extend(1.0);
        *q = DVec2::new((h.x / h.w + 1.0) * scale, (h.y / h.w + 1.0) * scale);
    }
    let mut hull = [DVec2::ZERO; 2 * MAX_BODY_VERTICES];
    let k = convex_hull(&mut pts[..n], &mut hull);
    pages_of_polygon(&hull[..k], per_side)
}

/// The cells of the unit grid `[0, per_side)²` that the convex polygon `poly` (in order) meets:
/// rows `⌊v_min⌋ ..= ⌈v_max⌉ − 1`, and in each row the cells under the polygon's cut by the row.
fn pages_of_polygon(poly: &[DVec2], per_side: u32) -> u32 {
    if poly.is_empty() {
        return 0;
    }
    let top = f64::from(per_side);
    let (vmin, vmax) = poly
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
            (a.min(p.y), b.max(p.y))
        });
    let cells = |lo: f64, hi: f64| -> (f64, f64) {
        let a = lo.floor().clamp(0.0, top - 1.0);
        let b = (hi.ceil() - 1.0).clamp(a, top - 1.0);
        (a, b)
    };
    let (r0, r1) = cells(vmin, vmax);
    let mut total = 0u32;
    let mut row = r0;
    while row <= r1 {
        if let Some((u0, u1)) = band_extent(poly, row, row + 1.0) {
            let (c0, c1) = cells(u0, u1);
            total += (c1 - c0) as u32 + 1;
        }
        row += 1.0;
    }
    total
}

/// The u-extent of the convex polygon `poly` cut to the band `lo ≤ v ≤ hi`: its vertices in the
/// band and its edges' crossings of the band's lines.
fn band_extent(poly: &[DVec2], lo: f64, hi: f64) -> Option<(f64, f64)> {
    let (mut a, mut b) = (f64::INFINITY, f64::NEG_INFINITY);
    let n = poly.len();
    for i in 0..n {
        let (p, q) = (poly[i], poly[(i + 1) % n]);
        if p.y >= lo && p.y <= hi {
            a = a.min(p.x);
            b = b.max(p.x);
        }
        for v in [lo, hi] {
            if (p.y - v) * (q.y - v) < 0.0 {
                let x = p.x + (q.x - p.x) * (v - p.y) / (q.y - p.y);
                a = a.min(x);
                b = b.max(x);
            }
        }
    }
    (a <= b).then_some((a, b))
}

/// The clipmap with the least LOD bias (the finest levels) whose pages ([`ClipmapPlan::pages`])
/// fit `pool` pages, `options.lod_bias` ignored. The bias lies between the least in effect
/// (where the levels' coverage sets it, [`LevelChoice::bias`]) and the largest that `last_level`
/// allows. The pages fall as the bias grows, but not monotonically: they rise by up to a few
/// percent where a level's boundary crosses rows of pages (docs/planning.md). So the search
/// bisects, then scans a grid of 1/64 below the answer from the least bias up and bisects again
/// from the first grid point that fits, to 10⁻⁶: the bias found fits, a bias 10⁻⁶ below it does
/// not, and no grid point below it does.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `pool` when it is 0 or no bias fits it (the message gives
/// the pages at the coarsest bias that `last_level` allows), or as [`plan_clipmap`].
pub fn clipmap_for_pool(
    input: &FrameInput<'_>,
    options: &ClipmapOptions,
    pool: u64,
) -> Result<ClipmapPlan> {
    if pool == 0 {
        return Err(Error::invalid("pool", "must be at least 1 page"));
    }
    let with = |b: f64| ClipmapOptions {
        lod_bias: b,
        ..*options
    };
    // The least bias in effect (below it the levels' coverage fixes them) and the largest whose
    // levels reach the visible far depth: log₂ z_f + L ≤ last + 1.
    let (mut lo, hi) = bias_range(input, options)?;
    let plan_at = |b: f64| plan_clipmap(input, &with(b));
    let at_hi = plan_at(hi)?;
    if at_hi.pages() > pool {
        return Err(Error::invalid(
            "pool",
            format!(
                "of {pool} pages is too small: at LOD bias {}, the coarsest that last_level={} \
                 allows, the clipmap needs {} pages; raise the pool or last_level",
                fmt_num(hi),
                options.last_level,
                at_hi.pages()
            ),
        ));
    }
    let at_lo = plan_at(lo)?;
    if at_lo.pages() <= pool {
        return Ok(at_lo);
    }
    // The pages fall with the bias, but not monotonically (docs/planning.md): a bisection first,
    // then the grid of `GRID` steps below its answer, from the least bias up, for the first that
    // fits, and a bisection between it and the grid point before.
    let least = lo;
    let (mut ok, mut best) = (hi, at_hi);
    bisect(&mut lo, &mut ok, &mut best, pool, &plan_at)?;
    let mut prev = least;
    let mut b = least + GRID;
    while b < ok {
        let p = plan_at(b)?;
        if p.pages() <= pool {
            let (mut lo, mut ok, mut best) = (prev, b, p);
            bisect(&mut lo, &mut ok, &mut best, pool, &plan_at)?;
            return Ok(best);
        }
        prev = b;
        b += GRID;
    }
    Ok(best)
}

/// The bracket on the LOD bias of [`clipmap_for_error`] stops once this narrow (the pages
/// change in steps of whole pages; 1/1024 of a bias step moves a level's boundary by 0.07 %).
const ERROR_BIAS_TOLERANCE: f64 = 1.0 / 1024.0;

/// The least and largest LOD bias in effect for `options` and `input`: below the least the
/// levels' coverage fixes them ([`LevelChoice::bias`]); above the largest `last_level` no longer
/// reaches the visible far depth.
fn bias_range(input: &FrameInput<'_>, options: &ClipmapOptions) -> Result<(f64, f64)> {
    let finest = ClipmapOptions {
        lod_bias: -32.0,
        ..*options
    };
    let c = LevelChoice::new(
        input.camera.view(),
        input.image_height,
        input.map_resolution,
        &finest,
    )?;
    let (_, zf) = visible(input);
    let matched = c.offset - c.bias;
    let hi = (f64::from(options.last_level) + 1.0 - zf.log2() - matched).min(32.0);
    Ok((c.bias, hi.max(c.bias)))
}

/// The clipmap with the fewest pages whose error measured over its levels' focus bodies
/// ([`ClipmapPlan::max_error_pixels`]) is at most `max_error` pixels, `options.lod_bias` ignored:
/// the LOD bias is the knob. The search starts from the closed form (resolution-matched levels
/// bound the error by 2^b, so b = log₂ max_error), then narrows the bracket between a bias that
/// meets the target and one that does not by bisection to 1/1024; every bias tried is measured,
/// and the answer is the one of those meeting the target with the fewest pages (ties: the least
/// error). The error grows with the bias but not strictly (clamped levels, B's extent), so a
/// bias above the answer may meet it too; none tried does with fewer pages.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `max_error` when it is not a positive number or the finest
/// bias in effect does not meet it (the message gives that bias's error), or as
/// [`plan_clipmap`].
pub fn clipmap_for_error(
    input: &FrameInput<'_>,
    options: &ClipmapOptions,
    max_error: f64,
) -> Result<ClipmapPlan> {
    if !(max_error.is_finite() && max_error > 0.0) {
        return Err(Error::invalid(
            "max_error",
            format!(
                "must be a finite, positive number of pixels (got {})",
                fmt_num(max_error)
            ),
        ));
    }
    let (lo, hi) = bias_range(input, options)?;
    let plan_at = |b: f64| {
        plan_clipmap(
            input,
            &ClipmapOptions {
                lod_bias: b,
                ..*options
            },
        )
    };
    let mut best: Option<ClipmapPlan> = None;
    let mut keep = |p: ClipmapPlan| {
        let fits = p.max_error_pixels() <= max_error;
        if fits
            && best.is_none_or(|b| {
                (p.pages(), p.max_error_pixels()) < (b.pages(), b.max_error_pixels())
            })
        {
            best = Some(p);
        }
        fits
    };
    let finest = plan_at(lo)?;
    if !keep(finest) {
        return Err(Error::invalid(
            "max_error",
            format!(
                "of {} px cannot be met by the clipmap: at its finest LOD bias in effect, {}, \
                 its measured error is {} px; allow a larger error or a larger resolution",
                fmt_num(max_error),
                fmt_num(lo),
                fmt_num(finest.max_error_pixels())
            ),
        ));
    }
    // ok: a bias that meets the target; bad: one that does not (or the largest, untried).
    let (mut ok, mut bad) = (lo, hi);
    let guess = max_error.log2().clamp(lo, hi);
    if keep(plan_at(hi)?) {
        ok = hi;
    } else if guess > lo && guess < hi {
        if keep(plan_at(guess)?) {
            ok = guess;
        } else {
            bad = guess;
        }
    }
    while bad - ok > ERROR_BIAS_TOLERANCE {
        let mid = 0.5 * (ok + bad);
        if keep(plan_at(mid)?) {
            ok = mid;
        } else {
            bad = mid;
        }
    }
    best.ok_or_else(|| Error::Degenerate("the clipmap search kept no plan".into()))
}

/// Narrows `[lo, ok]` (`lo` too fine for `pool`, `ok` fitting with the plan `best`) to
/// [`BIAS_TOLERANCE`] by bisection.
fn bisect(
    lo: &mut f64,
    ok: &mut f64,
    best: &mut ClipmapPlan,
    pool: u64,
    plan_at: &impl Fn(f64) -> Result<ClipmapPlan>,
) -> Result<()> {
    while *ok - *lo > BIAS_TOLERANCE * (1.0 + ok.abs()) {
        let mid = 0.5 * (*lo + *ok);
        let p = plan_at(mid)?;
        if p.pages() <= pool {
            *ok = mid;
            *best = p;
        } else {
            *lo = mid;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square of side 2 placed on the grid: the cells it meets, half-open at the far sides.
    #[test]
    fn pages_of_a_square() {
        let sq = |x: f64, y: f64, s: f64| {
            [
                DVec2::new(x, y),
                DVec2::new(x + s, y),
                DVec2::new(x + s, y + s),
                DVec2::new(x, y + s),
            ]
        };
        assert_eq!(pages_of_polygon(&sq(1.0, 1.0, 2.0), 8), 4);
        assert_eq!(pages_of_polygon(&sq(1.5, 1.5, 2.0), 8), 9);
        assert_eq!(pages_of_polygon(&sq(0.25, 0.25, 0.5), 8), 1);
        // A triangle over 3 × 3 cells misses the cells beyond its hypotenuse.
        let tri = [
            DVec2::new(0.0, 0.0),
            DVec2::new(3.0, 0.0),
            DVec2::new(0.0, 3.0),
        ];
        assert_eq!(pages_of_polygon(&tri, 8), 6);
    }
}
