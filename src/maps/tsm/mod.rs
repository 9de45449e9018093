//! Trapezoidal shadow maps (Martin & Tan 2004), for a directional light.
//!
//! # Construction (Martin & Tan §6, in the crate's light space)
//!
//! For a directional light the light's post-perspective space L is light space itself
//! (orthographic), and E, the eye's frustum seen from the light, is the projection of its corners
//! onto the light-space (x, z) plane.
//!
//! 1. The centre line l passes through the projected centres of the near and far planes (§6.1
//!    step 2). Both lie on the view axis, whose projection is the light-space z axis through the
//!    eye, so l is the line x = 0 and the top and base lines, orthogonal to l and touching the hull
//!    of E (steps 4, 5), are z = z₀ (nearest the near plane) and z = z₀ + λ.
//! 2. The focus point p, `focus` beyond the near plane on the view axis, lies δ′ below the top
//!    line. The centre of projection q on l, η above the top line, maps p to the line y = ξ of the
//!    unit square (top → +1, base → −1) for η = λδ′(1 + ξ)/(λ − 2δ′ − λξ) (§6.2; ξ = −0.6 is the
//!    80 % line).
//! 3. The side lines pass through q and touch the hull of E (§6.2); with the top and base lines
//!    they bound the trapezoid T.
//! 4. N_T is the projective map sending T's corners to the unit square's: top-left → (−1, 1),
//!    top-right → (1, 1), base-right → (1, −1), base-left → (−1, −1), solved as the four-point
//!    homography (Heckbert's square-to-quad map, whose two perspective terms are a 2 × 2 linear
//!    system solved by nalgebra's LU, inverted by its adjugate, on coordinates normalised to the
//!    trapezoid's size), and checked by mapping the corners back.
//! 5. N_T is applied to x, y and w; depth stays in light space (§4): [`TsmMap::light_depth`] is
//!    the affine light-space depth for the fragment stage (`gl_FragDepth = z_L` plus the usual
//!    polygon offset, as §4 describes). The 4 × 4 [`ShadowMatrix`] also carries a depth row (the
//!    light-space depth over w, fitted to [−1, 1], monotonic along each light ray) so that it can
//!    be used as an ordinary shadow matrix.
//!
//! The same centre of projection and side lines are what [`crate::maps::fit_warp`] builds with
//! n′ = η (the trapezoid's homography equals the warp with t reversed): a test checks it.
//!
//! # When the frustum looks square from the light
//!
//! When the centres of the near and far planes (almost) coincide in the light's view (§6.1:
//! "the algorithm handles that separately to result in the smallest box bounding the far plane as
//! the desired trapezoid") — here when the centre line is shorter than [`SQUARE_TOLERANCE`] times
//! λ — the map is the bounding rectangle of E: the orthographic fit, with the focus point wherever
//! it lands. The same rectangle is used when no centre of projection beyond the top line can map
//! the focus point to the requested line (the denominator of η is not positive): warping can only
//! move the focus point further down, so the rectangle is the closest map. TSM is discontinuous at
//! the first switch (an 80 % trapezoid just off the axis, the rectangle on it), as Martin & Tan's
//! rule is; docs/builders.md gives the size of the jump.
//!
//! # The iterative variant
//!
//! §6.2: "In the first iteration, p_L is mapped to the 80 % line (or 0.8x), and in each subsequent
//! iteration, p_L is mapped to an entry one line before that of the last iteration … we adopt the
//! trapezoid … that transforms the focus region to cover the largest area." With `map_lines` = x
//! lines numbered from the top, line k is ξ_k = 1 − 2k/x; the search runs k from round(0.8 x) down
//! to 1 ("one line before": towards the top) and keeps the first trapezoid of largest focus area,
//! the area of the image of the focus region (the frustum truncated δ beyond the near plane) in the
//! unit square. Lines above the focus point's unwarped line have no centre of projection beyond
//! the top line (see `analytic::tsm::tsm_eta`) and give the bounding rectangle. The area is not
//! unimodal in k (it can fall and rise again), so [`TsmSearch::IterativeExhaustive`] tries every
//! line as printed, and [`TsmSearch::Iterative`] samples 33 lines, then refines between the best
//! one's neighbours: a fast approximation, never worse than the 80 % line, that can miss a peak
//! narrower than its sampling step.
//!
//! # The general case (§6.4)
//!
//! [`tsm_general`] restricts the eye's frustum to a convex bound (the light's volume, a scene
//! box): I = frustum ∩ bound. The centre line runs from the eye through the centroid e of I's
//! vertices (the warp axis is the direction of e), the near and far planes are pushed to I's depth
//! range [n_I, f_I], and the focus distance becomes δ (f_I − n_I)/(f − n).

use crate::error::{in_open, Error, Result};
use crate::frustum::ViewFrustum;
use crate::maps::lightspace::{light_space, LightSpace};
use crate::maps::matrix::ShadowMatrix;
use glam::{DMat3, DVec2, DVec3, DVec4};

mod bound;
mod search;

pub use crate::geom::homography::quad_to_square;
pub use crate::geom::polytope::ConvexBound;
pub use bound::tsm_general;
use search::Core;

/// The centre line is treated as a point (the frustum looks square from the light) when its
/// length is below this fraction of the trapezoid's height λ. 10⁻³: one texel in a 1024-line map.
pub const SQUARE_TOLERANCE: f64 = 1e-3;

/// The largest `map_lines` of [`TsmSearch::Iterative`] and [`TsmSearch::IterativeExhaustive`]:
/// 65 536, four times the largest texture side of current GPUs (16 384 in Direct3D 12; Vulkan
/// and OpenGL devices report at most 32 768). The exhaustive search evaluates about
/// 0.8 × `map_lines` trapezoids, about 20 ns each: about 1 ms at this bound, where
/// `u32::MAX` lines took 72 s for one frame.
pub const MAX_MAP_LINES: u32 = 1 << 16;

/// Which line the focus point is mapped to (Martin & Tan §6.2).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum TsmSearch {
    /// The 80 % rule: ξ = −0.6.
    #[default]
    EightyPercent,
    /// A chosen line ξ ∈ (−1, 1) of the unit square (top +1, base −1).
    Line(f64),
    /// The iterative variant over the map's lines (module docs), searched fast: 33 lines spread
    /// from the 80 % line to the top, a golden-section search between the neighbours of the best, and
    /// the last few lines exhaustively (all lines when there are at most 64). The focus area can
    /// fall and rise again along the lines, so this is a fast approximation of
    /// [`TsmSearch::IterativeExhaustive`]: its focus area is never below the best of the 33
    /// sampled lines (the 80 % line among them) nor above the exhaustive maximum, and it usually
    /// equals the latter; a peak narrower than the sampling step (about `map_lines`/40 lines) can
    /// be missed (seen: ξ = −0.598 against the exhaustive 0.145 at 433 lines). tests/tsm.rs
    /// checks the bounds on random configurations.
    Iterative {
        /// Number of texel lines of the shadow map along t (1024 or 2048 in the paper), in
        /// [2, [`MAX_MAP_LINES`]].
        map_lines: u32,
    },
    /// The iterative variant exactly as printed: every line from the 80 % line up to the top.
    /// About 0.8 × `map_lines` evaluations, so `map_lines` is bounded by [`MAX_MAP_LINES`]
    /// (about 1 ms of search there; `u32::MAX` lines would take over a minute per map).
    IterativeExhaustive {
        /// Number of texel lines of the shadow map along t, in [2, [`MAX_MAP_LINES`]].
        map_lines: u32,
    },
}

/// Options of the trapezoidal map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TsmOptions {
    /// Focus distance δ beyond the near plane, world units, `0 < focus ≤ f − n`.
    pub focus: f64,
    /// The line rule.
    pub search: TsmSearch,
}

/// The trapezoid in light-space (x, z) coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Trapezoid {
    /// Corners: top-left, top-right, base-right, base-left (top nearest the near plane).
    pub corners: [DVec2; 4],
    /// The centre of projection q, or `None` for the bounding-rectangle fallback.
    pub q: Option<DVec2>,
}

/// A trapezoidal shadow map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TsmMap {
    /// The 4 × 4 map (eye space → clip), N_T on x, y, w and a fitted depth row.
    pub shadow: ShadowMatrix,
    /// The light space the trapezoid lives in.
    pub light_space: LightSpace,
    /// The trapezoid.
    pub trapezoid: Trapezoid,
    /// N_T: light-space `(x, z, 1)` → homogeneous unit-square coordinates, scaled so that
    /// w ≥ 1 over the region with equality at its nearest point to q.
    pub n_t: DMat3,
    /// Light-space depth kept out of N_T (§4): `dot(light_depth, (p, 1))` ∈ [−1, 1] over the
    /// frustum, −1 nearest the light, for an eye-space point p.
    pub light_depth: DVec4,
    /// The focus point p (eye space): `focus` beyond the near plane on the centre line (for
    /// [`tsm_general`], beyond the pushed near plane on the line from the eye through I's centroid).
    pub focus_point: DVec3,
    /// The line y = ξ the focus point maps to.
    pub xi: f64,
    /// Fraction of the map's area covered by the focus region.
    pub focus_area: f64,
}

/// The trapezoidal shadow map of the whole view frustum for a light travelling along
/// `light_dir` (eye space). No heap allocation.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir`, `focus` (not in (0, f − n]), `xi` (not in
/// (−1, 1)) or `map_lines` (not in [2, [`MAX_MAP_LINES`]]); [`Error::Degenerate`] when the
/// trapezoid is near-degenerate.
///
/// ```
/// # use shadow_aliasing::maps::tsm::{tsm, TsmOptions, TsmSearch};
/// # use shadow_aliasing::ViewFrustum;
/// # use glam::{DVec3, DVec4};
/// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
/// let opts = TsmOptions { focus: 20.0, search: TsmSearch::EightyPercent };
/// let t = tsm(&view, DVec3::new(0.0, -1.0, 0.3), opts)?;
/// // The focus point on the view axis lands on the 80 % line.
/// let h = t.shadow.matrix() * DVec4::new(0.0, 0.0, -21.0, 1.0);
/// assert!((h.y / h.w + 0.6).abs() < 1e-9);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn tsm(view: &ViewFrustum, light_dir: DVec3, opts: TsmOptions) -> Result<TsmMap> {
    validate(view, &opts)?;
    let ls = light_space(light_dir, DVec3::NEG_Z)?;
    let corners = view.corners();
    let (n, f) = (view.near(), view.far());
    let focus_depth = n + opts.focus;
    let focus_point = DVec3::new(0.0, 0.0, -focus_depth);
    // The view's own field of view and aspect, already valid: only the depths are checked.
    let fr = view
        .with_depth_range(n, focus_depth)
        .map(|v| v.corners())
        .unwrap_or(corners);
    let centre_line =
        (ls.z.dot(DVec3::new(0.0, 0.0, -f)) - ls.z.dot(DVec3::new(0.0, 0.0, -n))).abs();
    let core = Core {
        ls,
        points: &corners,
        focus_region: &fr,
        focus_point,
        centre_line,
    };
    // E and the focus region are 8 corners each: scratch for 8 points, 16 hull slots.
    core.build::<8, 16>(opts.search, n, f)
}

/// The trapezoidal map of a body's vertices `points` (eye space, at most 32) in the view-axis
/// light space `ls`, with its focus region's vertices, the focus point on the view axis and the
/// projected length of the view axis over the body's depth range `[near, far]` (the frame API's
/// TSM on its focus body B; [`tsm`] is the frustum's case). `search` is validated by the caller.
#[allow(clippy::too_many_arguments)] // Core's fields and build's arguments, one call site
pub(crate) fn tsm_on_points(
    ls: LightSpace,
    points: &[DVec3],
    focus_region: &[DVec3],
    focus_point: DVec3,
    centre_line: f64,
    search: TsmSearch,
    near: f64,
    far: f64,
) -> Result<TsmMap> {
    let core = Core {
        ls,
        points,
        focus_region,
        focus_point,
        centre_line,
    };
    core.build::<32, 64>(search, near, far)
}

pub(crate) fn validate(view: &ViewFrustum, opts: &TsmOptions) -> Result<()> {
    crate::maps::warp::focus_in_range(view, opts.focus)?;
    match opts.search {
        TsmSearch::EightyPercent => {}
        TsmSearch::Line(xi) => {
            in_open("xi", xi, -1.0, 1.0)?;
        }
        TsmSearch::Iterative { map_lines } | TsmSearch::IterativeExhaustive { map_lines } => {
            if !(2..=MAX_MAP_LINES).contains(&map_lines) {
                return Err(Error::invalid(
                    "map_lines",
                    format!(
                        "must lie in [2, {MAX_MAP_LINES}] (got {map_lines}): the number of the \
                         shadow map's texel lines, searched one by one (beyond {MAX_MAP_LINES}, \
                         four times the largest texture GPUs allow, the search costs more than a \
                         millisecond per map and grows without bound)"
                    ),
                ));
            }
        }
    }
    Ok(())
}
