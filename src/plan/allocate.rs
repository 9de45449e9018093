//! Texel allocation by error (issue 24, item 2): each map's resolution chosen so that the largest
//! error over the maps is least, for a texel budget or an atlas.
//!
//! # The model
//!
//! Map i has maximum errors `M_x,i`, `M_z,i` at unit resolutions (a frame map's `max_mx`,
//! `max_mz`). At `res_s × res_t` texels its error in pixels of an image `H` pixels high is
//!
//! ```text
//! e_i = max(M_x,i · H / res_s,i,  M_z,i · H / res_t,i)
//! ```
//!
//! (the frame's `max_error_pixels` for a square map). To reach an error E, map i needs
//! `res_s ≥ M_x H / E` and `res_t ≥ M_z H / E`, so `S̄_i H² / E²` texels, `S̄_i = M_x,i M_z,i`.
//!
//! # Lloyd 2005 Eq 6, generalised
//!
//! Without rounding, the least largest error for a budget of `T` texels equalises every map's
//! error: `res_s,i = M_x,i H / E`, `res_t,i = M_z,i H / E` (each resolution proportional to the
//! map's error at unit resolution, Eq 6's `r_i ∝ e_i` along both axes), with
//! `E = H √(Σ S̄_i / T)` ([`continuous_error`]). Whole texels (or powers of two, or multiples of a
//! tile) break the equality; [`allocate`] finds the least largest error exactly: for a target E
//! each map's cheapest resolutions are the least allowed ones above `M H / E`, their total is a
//! step function falling with E, and the least E within the budget is one of its steps, found by
//! bisection and then snapped to the error the rounded resolutions give.
//!
//! # In an atlas
//!
//! [`allocate_atlas`] packs the maps side by side into a `width × height` texture in columns (the
//! [`crate::maps::atlas`] layout with one map per column): each map takes the atlas's whole height
//! (more rows cost nothing there), and the widths are the least-largest-error split of `width`
//! among the `M_x,i` (Eq 6 in whole texels, exactly rather than by largest remainder).
//! Its viewports are [`Viewport`]s, so [`Viewport::clip_matrix`] renders each map into its
//! rectangle.

use crate::error::{fmt_num, positive, Error, Result};
use crate::maps::atlas::{Viewport, MAX_ATLAS_ENTRIES};

/// One map's maximum errors at unit resolutions (a frame map's `max_mx` and `max_mz`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapError {
    /// Maximum error along x (the map's s direction).
    pub max_mx: f64,
    /// Maximum error along z (the map's t direction).
    pub max_mz: f64,
}

/// What resolutions a map may have along each axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Rounding {
    /// Any whole number of texels.
    #[default]
    Whole,
    /// Powers of two (1, 2, 4, …).
    PowerOfTwo,
    /// Multiples of a tile's side (a virtual texture's page, a GPU's alignment).
    Multiple(u32),
}

/// The largest resolution along an axis the allocation gives (2³⁰: a map of 2³⁰ × 2³⁰ texels is
/// already 10⁶ times what a GPU holds).
pub const MAX_RESOLUTION: u64 = 1 << 30;

impl Rounding {
    /// The resolutions allowed, in words, for messages: "whole texels", "powers of two",
    /// "multiples of 64 texels".
    pub(crate) fn words(self) -> String {
        match self {
            Rounding::Whole => "whole texels".into(),
            Rounding::PowerOfTwo => "powers of two".into(),
            Rounding::Multiple(m) => format!("multiples of {m} texels"),
        }
    }
    /// The least allowed resolution ≥ `need` (≥ 1), `None` above [`MAX_RESOLUTION`].
    pub(crate) fn at_least(self, need: f64) -> Option<u64> {
        // NaN (a zero error target) and anything above the cap are refused alike.
        if need.is_nan() || need > MAX_RESOLUTION as f64 {
            return None;
        }
        let n = (need.ceil() as u64).max(1);
        let r = match self {
            Rounding::Whole => n,
            Rounding::PowerOfTwo => n.next_power_of_two(),
            Rounding::Multiple(m) => n.div_ceil(u64::from(m)) * u64::from(m),
        };
        (r <= MAX_RESOLUTION).then_some(r)
    }
}

/// One map's resolution and error.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MapResolution {
    /// Texels along s.
    pub res_s: u64,
    /// Texels along t.
    pub res_t: u64,
    /// Its maximum error in pixels, `max(M_x H / res_s, M_z H / res_t)`.
    pub error_pixels: f64,
}

/// The resolutions of every map, in the order given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Allocation {
    maps: [MapResolution; MAX_ATLAS_ENTRIES],
    len: usize,
    /// The largest error over the maps, pixels.
    pub max_error_pixels: f64,
    /// The texels of all maps together.
    pub texels: u64,
}

impl Allocation {
    /// Each map's resolution and error, in the order given.
    #[must_use]
    pub fn maps(&self) -> &[MapResolution] {
        &self.maps[..self.len]
    }
}

/// Validates the maps and the image height.
fn check(maps: &[MapError], image_height: u32) -> Result<f64> {
    if maps.is_empty() || maps.len() > MAX_ATLAS_ENTRIES {
        return Err(Error::invalid(
            "maps",
            format!(
                "must hold 1 to {MAX_ATLAS_ENTRIES} maps (got {}): allocate the lights' maps in \
                 groups of at most {MAX_ATLAS_ENTRIES}",
                maps.len()
            ),
        ));
    }
    for (i, m) in maps.iter().enumerate() {
        for v in [m.max_mx, m.max_mz] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::invalid(
                    "maps",
                    format!(
                        "must have finite, positive errors (got {} at index {i}): leave out the \
                         maps that have no error (no body)",
                        fmt_num(v)
                    ),
                ));
            }
        }
    }
    if image_height == 0 {
        return Err(Error::invalid("image_height", "must be at least 1 pixel"));
    }
    Ok(f64::from(image_height))
}

/// The least largest error without rounding, `H √(Σ S̄_i / T)` (module docs), pixels.
///
/// # Errors
/// As [`allocate`].
pub fn continuous_error(maps: &[MapError], image_height: u32, budget_texels: u64) -> Result<f64> {
    let h = check(maps, image_height)?;
    let t = positive("budget_texels", budget_texels as f64)?;
    let s: f64 = maps.iter().map(|m| m.max_mx * m.max_mz).sum();
    Ok(h * (s / t).sqrt())
}

/// The cheapest resolutions of every map for the target error `e`, written to `out`, and their
/// total texels (`None` above [`MAX_RESOLUTION`] or overflowing).
fn cheapest(
    maps: &[MapError],
    h: f64,
    e: f64,
    rounding: Rounding,
    out: &mut [MapResolution],
) -> Option<u64> {
    let mut total = 0u64;
    for (m, o) in maps.iter().zip(out.iter_mut()) {
        let res_s = rounding.at_least(m.max_mx * h / e)?;
        let res_t = rounding.at_least(m.max_mz * h / e)?;
        *o = MapResolution {
            res_s,
            res_t,
            error_pixels: (m.max_mx * h / res_s as f64).max(m.max_mz * h / res_t as f64),
        };
        total = total.checked_add(res_s.checked_mul(res_t)?)?;
    }
    Some(total)
}

/// The resolutions of `maps` with at most `budget_texels` texels in all and the least largest
/// error (module docs), each axis rounded as `rounding` allows. Deterministic; no heap
/// allocation; about 120 evaluations of the maps' cheapest resolutions.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `maps` (empty, more than [`MAX_ATLAS_ENTRIES`], an error
/// that is not finite and positive), `image_height` (0), `rounding` (a multiple of 0), or
/// `budget_texels` (less than the smallest maps allowed need: one texel, or one power of two or
/// tile, per axis and map).
pub fn allocate(
    maps: &[MapError],
    image_height: u32,
    budget_texels: u64,
    rounding: Rounding,
) -> Result<Allocation> {
    let h = check(maps, image_height)?;
    if rounding == Rounding::Multiple(0) {
        return Err(Error::invalid(
            "rounding",
            "must be a multiple of at least 1 texel (got Multiple(0))",
        ));
    }
    let mut out = [MapResolution::default(); MAX_ATLAS_ENTRIES];
    let n = maps.len();
    // The largest useful error: every map at its least resolution.
    let floor = maps
        .iter()
        .map(|m| m.max_mx.max(m.max_mz) * h)
        .fold(0.0, f64::max);
    let least = cheapest(maps, h, floor, rounding, &mut out[..n]).unwrap_or(u64::MAX);
    if least > budget_texels {
        return Err(Error::invalid(
            "budget_texels",
            format!(
                "is below the {least} texels the smallest maps allowed need (got \
                 {budget_texels}): give at least that, or fewer maps"
            ),
        ));
    }
    // Bisect ln E between a feasible error (`hi`) and an infeasible one (`lo`): the continuous
    // optimum is a lower bound, since rounding only adds texels.
    let mut hi = floor;
    let mut lo = continuous_error(maps, image_height, budget_texels)?.min(hi);
    let fits = |e: f64, out: &mut [MapResolution]| {
        cheapest(maps, h, e, rounding, out).is_some_and(|t| t <= budget_texels)
    };
    if fits(lo, &mut out[..n]) {
        hi = lo;
    }
    for _ in 0..200 {
        if hi <= lo * (1.0 + 4.0 * f64::EPSILON) {
            break;
        }
        let mid = (lo * hi).sqrt();
        if fits(mid, &mut out[..n]) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    // The cheapest resolutions for `hi`: within the budget, their largest error at most `hi`,
    // and `lo` (within 4 ulps below) admits none within it, so no allocation does better.
    let texels = cheapest(maps, h, hi, rounding, &mut out[..n]).unwrap_or(u64::MAX);
    Ok(Allocation {
        maps: out,
        len: n,
        max_error_pixels: out[..n].iter().map(|m| m.error_pixels).fold(0.0, f64::max),
        texels,
    })
}

/// The cheapest resolutions of `maps` whose largest error is at most `max_error` pixels (module
/// docs): each axis the least resolution `rounding` allows at or above `M H / max_error`.
/// `texels` is their total; `max_error_pixels` the largest error they give (≤ `max_error`).
///
/// # Errors
/// As [`allocate`] for `maps`, `image_height` and `rounding`; `max_error` when it is not finite
/// and positive, or so small that a map would need more than [`MAX_RESOLUTION`] texels along an
/// axis.
pub fn allocate_for_error(
    maps: &[MapError],
    image_height: u32,
    max_error: f64,
    rounding: Rounding,
) -> Result<Allocation> {
    let h = check(maps, image_height)?;
    let e = positive("max_error", max_error)?;
    if rounding == Rounding::Multiple(0) {
        return Err(Error::invalid(
            "rounding",
            "must be a multiple of at least 1 texel (got Multiple(0))",
        ));
    }
    let mut out = [MapResolution::default(); MAX_ATLAS_ENTRIES];
    let n = maps.len();
    let texels = cheapest(maps, h, e, rounding, &mut out[..n]).ok_or_else(|| {
        Error::invalid(
            "max_error",
            format!(
                "{} px needs more than {MAX_RESOLUTION} texels along an axis of a map: allow a \
                 larger error",
                fmt_num(e)
            ),
        )
    })?;
    Ok(Allocation {
        maps: out,
        len: n,
        max_error_pixels: out[..n].iter().map(|m| m.error_pixels).fold(0.0, f64::max),
        texels,
    })
}

/// The maps side by side in a `width × height` atlas (module docs): each map a column of the
/// whole height, the widths the least-largest-error split of `width` in whole texels. Returns the
/// allocation (each map's `res_s` its column's width, `res_t` the atlas height) and the
/// viewports, left to right in the order given.
///
/// # Errors
/// As [`allocate`]; `width` when it is less than one texel per map, `height` when 0.
pub fn allocate_atlas(
    maps: &[MapError],
    image_height: u32,
    width: u32,
    height: u32,
) -> Result<(Allocation, [Viewport; MAX_ATLAS_ENTRIES])> {
    let h = check(maps, image_height)?;
    let n = maps.len();
    if (width as usize) < n {
        return Err(Error::invalid(
            "width",
            format!("must give each of the {n} maps a column of at least 1 texel (got {width})"),
        ));
    }
    if height == 0 {
        return Err(Error::invalid("height", "must be at least 1 texel (got 0)"));
    }
    // Each column at the atlas height: only the widths are to share. As one axis of `allocate`:
    // the maps' t errors made negligible, the budget the width (columns of one texel's height).
    let columns: [MapError; MAX_ATLAS_ENTRIES] = std::array::from_fn(|i| MapError {
        max_mx: maps.get(i).map_or(1.0, |m| m.max_mx),
        max_mz: f64::MIN_POSITIVE,
    });
    let widths = allocate(
        &columns[..n],
        image_height,
        u64::from(width),
        Rounding::Whole,
    )?;
    let mut out = [MapResolution::default(); MAX_ATLAS_ENTRIES];
    let mut viewports = [Viewport::default(); MAX_ATLAS_ENTRIES];
    let mut x = 0u32;
    // Texels the rounding left over go to the map with the largest error along s.
    let spare = u64::from(width) - widths.maps().iter().map(|m| m.res_s).sum::<u64>();
    let worst = (0..n)
        .max_by(|&a, &b| {
            let ea = maps[a].max_mx / widths.maps()[a].res_s as f64;
            let eb = maps[b].max_mx / widths.maps()[b].res_s as f64;
            ea.total_cmp(&eb)
        })
        .unwrap_or(0);
    for i in 0..n {
        let w = widths.maps()[i].res_s + if i == worst { spare } else { 0 };
        // `w` ≤ width, a u32.
        let w32 = u32::try_from(w).unwrap_or(width);
        let (mx, mz) = (maps[i].max_mx, maps[i].max_mz);
        out[i] = MapResolution {
            res_s: w,
            res_t: u64::from(height),
            error_pixels: (mx * h / w as f64).max(mz * h / f64::from(height)),
        };
        viewports[i] = Viewport {
            x,
            y: 0,
            width: w32,
            height,
            atlas_width: width,
            atlas_height: height,
        };
        x += w32;
    }
    let alloc = Allocation {
        maps: out,
        len: n,
        max_error_pixels: out[..n].iter().map(|m| m.error_pixels).fold(0.0, f64::max),
        texels: u64::from(width) * u64::from(height),
    };
    Ok((alloc, viewports))
}
