//! The planner (issue 24 item 3): the cheapest shadow set-up that meets a target error, or the
//! least error within a texel budget, chosen among measured candidates.
//!
//! Each candidate ([`super::candidates`]) is built by the frame and measured over its focus
//! bodies (M_x and M_z over B's vertices, [`FrameMap::max_mx`], [`FrameMap::max_mz`]); its maps'
//! resolutions then come from the texel allocation ([`super::allocate`]):
//!
//! - [`Goal::MaxError`]: each map's cheapest resolutions whose error is at most the target
//!   ([`allocate_for_error`]); the plan is the candidate with the fewest texels (ties: the least
//!   error, then the first in the list).
//! - [`Goal::Budget`]: the least largest error within the budget ([`allocate`]), among the
//!   candidates with at most `max_maps` maps; the plan is the candidate with the least error
//!   (ties: the fewest texels, then the first).
//!
//! No closed form decides anything: every number is measured. The plan is deterministic (the
//! candidates' order is fixed and every search in the frame is). Its cost is bounded: one frame per
//! candidate (each root search of the equal-error splits bounded), plus one allocation each; the
//! measured cost is in docs/planning.md.

use super::allocate::{allocate, allocate_for_error, MapError, MapResolution, Rounding};
use super::candidates::{candidates, CLIPMAP_RESOLUTION};
use super::clipmap::{clipmap_for_error, clipmap_for_pool};
use crate::error::{fmt_num, Error, Result};
use crate::frame::{frame_into, ClipmapOptions, Frame, FrameInput, FrameMap, FrameScheme};
use crate::maps::atlas::MAX_ATLAS_ENTRIES;

/// What the plan is asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Goal {
    /// The fewest texels whose largest error is at most this, in pixels of the image per texel.
    MaxError(f64),
    /// The least largest error within a texel budget.
    Budget {
        /// The texels of all maps together.
        texels: u64,
        /// The most maps a candidate may have (1 ..= [`MAX_ATLAS_ENTRIES`]).
        max_maps: usize,
    },
}

/// One candidate's measured figures.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Measured {
    /// The maps it built (0 when no map is needed: the receivers are out of view).
    pub maps: usize,
    /// The texels of its maps at the resolutions the goal gives.
    pub texels: u64,
    /// Its largest error over its maps at those resolutions, pixels.
    pub max_error_pixels: f64,
    /// Σ S̄ over its maps (unit resolutions): the texels of the unrounded equal-error allocation
    /// are `Σ S̄ · H² / E²`.
    pub storage_factor: f64,
}

/// A candidate and what the planner found for it.
#[derive(Debug, Clone, PartialEq)]
pub struct Candidate {
    /// The scheme measured.
    pub scheme: FrameScheme<'static>,
    /// Its figures, or why it is not a plan: the frame could not build it (adaptive planes that
    /// do not exist, a root search that did not converge), it has more maps than `max_maps`, or
    /// the goal cannot be met with it (a budget below its least maps, a target that would need
    /// more than 2³⁰ texels along an axis).
    pub outcome: std::result::Result<Measured, Error>,
}

/// The planner's answer.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The index of the chosen candidate in [`Plan::candidates`].
    pub chosen: usize,
    /// Every candidate considered, in order.
    pub candidates: Vec<Candidate>,
    /// Each map's resolution and error, in the order of [`Frame::maps`] of [`Plan::frame`].
    pub resolutions: Vec<MapResolution>,
    /// The chosen candidate's largest error, pixels.
    pub max_error_pixels: f64,
    /// The chosen candidate's texels.
    pub texels: u64,
    /// The chosen candidate's frame (its maps and their matrices, at the input's
    /// `map_resolution`).
    pub frame: Box<Frame>,
}

impl Plan {
    /// The chosen scheme.
    #[must_use]
    pub fn scheme(&self) -> FrameScheme<'static> {
        self.candidates[self.chosen].scheme
    }
}

/// Validates the goal.
fn check(goal: Goal) -> Result<()> {
    match goal {
        Goal::MaxError(e) if !(e.is_finite() && e > 0.0) => Err(Error::invalid(
            "max_error",
            format!(
                "must be a finite, positive number of pixels per texel (got {})",
                fmt_num(e)
            ),
        )),
        Goal::Budget { texels: 0, .. } => Err(Error::invalid(
            "budget_texels",
            "must be at least 1 texel (got 0)",
        )),
        Goal::Budget { max_maps, .. } if !(1..=MAX_ATLAS_ENTRIES).contains(&max_maps) => {
            Err(Error::invalid(
                "max_maps",
                format!("must lie in [1, {MAX_ATLAS_ENTRIES}] (got {max_maps})"),
            ))
        }
        _ => Ok(()),
    }
}

/// The plan for `input` (its scheme is ignored: every candidate of [`candidates`] is measured)
/// and `goal`, each map's resolution along each axis rounded as `rounding` allows. The errors are
/// in pixels of an image `input.image_height` pixels high.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `max_error`, `budget_texels` or `max_maps` for a bad goal,
/// `rounding` (a multiple of 0), or any argument of the input the frame refuses (its first
/// candidate, a single uniform map, is built first and its error returned); `max_error` when no
/// candidate can meet it, `budget_texels` when no candidate fits it (the message gives the least
/// budget that would); `receivers` when no candidate builds a map (the receivers are out of
/// view or edge-on to the light: nothing to plan).
pub fn plan(input: &FrameInput<'_>, goal: Goal, rounding: Rounding) -> Result<Plan> {
    plan_among(input, goal, rounding, &candidates(input))
}

/// As [`plan`], among the schemes given (for instance the scheme chosen on the last camera cut
/// alone, to size its maps in every frame). The first scheme's error, if it fails, is returned
/// as the input's.
///
/// # Errors
/// As [`plan`]; `candidates` when the list is empty.
pub fn plan_among(
    input: &FrameInput<'_>,
    goal: Goal,
    rounding: Rounding,
    candidates: &[FrameScheme<'static>],
) -> Result<Plan> {
    check(goal)?;
    if rounding == Rounding::Multiple(0) {
        return Err(Error::invalid(
            "rounding",
            "must be a multiple of at least 1 texel (got Multiple(0))",
        ));
    }
    if candidates.is_empty() {
        return Err(Error::invalid(
            "candidates",
            "must hold at least one scheme: give plan::candidates(input) or a part of it",
        ));
    }
    let mut rows = Vec::with_capacity(candidates.len());
    let mut cur = Box::<Frame>::default();
    let mut best: Option<(usize, Box<Frame>, Vec<MapResolution>)> = None;
    let mut best_key = (f64::INFINITY, f64::INFINITY);
    for (i, scheme) in candidates.iter().enumerate() {
        let (scheme, sized) = match scheme {
            FrameScheme::Clipmap(opts) => clipmap(input, opts, goal, &mut cur),
            _ => {
                let one = input.scheme(*scheme).measure(true);
                if let Err(e) = frame_into(&one, &mut cur) {
                    if i == 0 {
                        return Err(e);
                    }
                    rows.push(Candidate {
                        scheme: *scheme,
                        outcome: Err(e),
                    });
                    continue;
                }
                (*scheme, size(&cur, goal, rounding, input.image_height))
            }
        };
        // No map: no plan (a 0-texel plan is not one).
        let sized = sized.and_then(|s| {
            if s.0.maps == 0 {
                Err(nothing_to_plan())
            } else {
                Ok(s)
            }
        });
        let outcome = sized.as_ref().map(|(m, _)| *m).map_err(Clone::clone);
        if let Ok((m, res)) = sized {
            // Fewest texels then least error for a target; least error then fewest texels for
            // a budget. Strictly better only: the first of equals stays.
            let key = match goal {
                Goal::MaxError(_) => (m.texels as f64, m.max_error_pixels),
                Goal::Budget { .. } => (m.max_error_pixels, m.texels as f64),
            };
            if key < best_key {
                best_key = key;
                let old = best.take().map(|(_, f, _)| f);
                let taken = std::mem::replace(&mut cur, old.unwrap_or_default());
                best = Some((i, taken, res));
            }
        }
        rows.push(Candidate { scheme, outcome });
    }
    let Some((chosen, frame, resolutions)) = best else {
        if rows.iter().all(|r| r.outcome == Err(nothing_to_plan())) {
            return Err(nothing_to_plan());
        }
        return Err(unmet(goal, &rows));
    };
    let m = rows[chosen].outcome.as_ref().map_or(
        Measured {
            maps: 0,
            texels: 0,
            max_error_pixels: 0.0,
            storage_factor: 0.0,
        },
        |m| *m,
    );
    Ok(Plan {
        chosen,
        candidates: rows,
        resolutions,
        max_error_pixels: m.max_error_pixels,
        texels: m.texels,
        frame,
    })
}

/// A candidate whose frame builds no map: the receivers are out of view or edge-on to the light.
fn nothing_to_plan() -> Error {
    Error::invalid(
        "receivers",
        "need no map (they are out of view or edge-on to the light): there is nothing to plan; \
         check the receivers' boxes and the camera",
    )
}

/// The error when no candidate meets the goal.
fn unmet(goal: Goal, rows: &[Candidate]) -> Error {
    match goal {
        Goal::MaxError(e) => Error::invalid(
            "max_error",
            format!(
                "cannot be met by any candidate (got {} px): each needs more than 2^30 texels \
                 along an axis of a map; allow a larger error",
                fmt_num(e)
            ),
        ),
        Goal::Budget { texels, max_maps } => {
            let fewest = rows
                .iter()
                .filter_map(|r| match &r.outcome {
                    Err(Error::InvalidArgument {
                        name: "budget_texels",
                        reason,
                    }) => least_texels(reason),
                    _ => None,
                })
                .min();
            let hint = match fewest {
                Some(t) => format!("give at least {t} texels"),
                None => "allow more maps (max_maps)".to_string(),
            };
            Error::invalid(
                "budget_texels",
                format!(
                    "is below what every candidate with at most {max_maps} maps needs (got \
                     {texels}): {hint}"
                ),
            )
        }
    }
}

/// The least texels that `allocate`'s refusal of a budget names ("is below the N texels …").
fn least_texels(reason: &str) -> Option<u64> {
    reason
        .split_whitespace()
        .find_map(|w| w.parse::<u64>().ok())
}

/// The clipmap candidate `opts` for the goal, built into `out`: the LOD bias with the fewest
/// pages that meets a target ([`clipmap_for_error`]), or the least within a budget of pages
/// ([`clipmap_for_pool`], the budget's texels over the page's), at most `max_maps` levels. Its
/// levels are [`CLIPMAP_RESOLUTION`] texels a side (their error measured at that resolution);
/// its texels are its pages × the page's texels. Returns the scheme with the bias chosen.
fn clipmap(
    input: &FrameInput<'_>,
    opts: &ClipmapOptions,
    goal: Goal,
    out: &mut Frame,
) -> (FrameScheme<'static>, Result<(Measured, Vec<MapResolution>)>) {
    let mut input = *input;
    input.map_resolution = CLIPMAP_RESOLUTION;
    let page = u64::from(opts.page_texels).pow(2);
    let planned = match goal {
        Goal::MaxError(e) => clipmap_for_error(&input, opts, e),
        Goal::Budget { texels, .. } => clipmap_for_pool(&input, opts, texels / page),
    };
    let p = match planned {
        Ok(p) => p,
        Err(e) => return (FrameScheme::Clipmap(*opts), Err(e)),
    };
    let chosen = FrameScheme::Clipmap(ClipmapOptions {
        lod_bias: p.choice.options.lod_bias,
        ..*opts
    });
    if let Err(e) = frame_into(&input.scheme(chosen).measure(true), out) {
        return (chosen, Err(e));
    }
    let h = f64::from(input.image_height);
    let r = f64::from(CLIPMAP_RESOLUTION);
    let res: Vec<MapResolution> = out
        .maps()
        .iter()
        .map(|m| MapResolution {
            res_s: u64::from(CLIPMAP_RESOLUTION),
            res_t: u64::from(CLIPMAP_RESOLUTION),
            error_pixels: (m.max_mx * h / r).max(m.max_mz * h / r),
        })
        .collect();
    if let Goal::Budget { max_maps, .. } = goal {
        if res.len() > max_maps {
            let e = Error::invalid(
                "max_maps",
                format!(
                    "is {max_maps}, and this clipmap has {} levels: allow more maps",
                    res.len()
                ),
            );
            return (chosen, Err(e));
        }
    }
    let m = Measured {
        maps: res.len(),
        texels: p.pages() * page,
        max_error_pixels: res.iter().map(|r| r.error_pixels).fold(0.0, f64::max),
        storage_factor: out.storage_factor().unwrap_or(0.0),
    };
    (chosen, Ok((m, res)))
}

/// A built frame's figures and resolutions for the goal.
fn size(
    f: &Frame,
    goal: Goal,
    rounding: Rounding,
    image_height: u32,
) -> Result<(Measured, Vec<MapResolution>)> {
    let maps: Vec<MapError> = f
        .maps()
        .iter()
        .map(|m: &FrameMap| MapError {
            max_mx: m.max_mx,
            max_mz: m.max_mz,
        })
        .collect();
    let storage_factor = f.storage_factor().unwrap_or(0.0);
    if maps.is_empty() {
        let m = Measured {
            maps: 0,
            texels: 0,
            max_error_pixels: 0.0,
            storage_factor,
        };
        return Ok((m, Vec::new()));
    }
    let a = match goal {
        Goal::MaxError(e) => allocate_for_error(&maps, image_height, e, rounding)?,
        Goal::Budget { texels, max_maps } => {
            if maps.len() > max_maps {
                return Err(Error::invalid(
                    "max_maps",
                    format!(
                        "is {max_maps}, and this scheme has {} maps: allow more maps",
                        maps.len()
                    ),
                ));
            }
            allocate(&maps, image_height, texels, rounding)?
        }
    };
    let m = Measured {
        maps: maps.len(),
        texels: a.texels,
        max_error_pixels: a.max_error_pixels,
        storage_factor,
    };
    Ok((m, a.maps().to_vec()))
}
