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
//! The same centre of projection and side lines are what [`crate::build::fit_warp`] builds with
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

use crate::build::lightspace::{light_space, LightSpace};
use crate::build::matrix::ShadowMatrix;
use crate::build::warp::{fmax, fmin, tsm_eta};
use crate::error::{fmt_num, in_open, positive, Error, Result};
use crate::frustum::{NPrime, ViewFrustum};
use glam::{DMat3, DMat4, DVec2, DVec3, DVec4};
use nalgebra::{Matrix2, Vector2};

pub use crate::build::warp::TSM_80_PERCENT_LINE;

/// The centre line is treated as a point (the frustum looks square from the light) when its
/// length is below this fraction of the trapezoid's height λ. 10⁻³: one texel in a 1024-line map.
pub const SQUARE_TOLERANCE: f64 = 1e-3;

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
        /// Number of texel lines of the shadow map along t (1024 or 2048 in the paper).
        map_lines: u32,
    },
    /// The iterative variant exactly as printed: every line from the 80 % line up to the top.
    /// About 0.8 × `map_lines` evaluations.
    IterativeExhaustive {
        /// Number of texel lines of the shadow map along t.
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

/// Which corners the homography maps where: top-left, top-right, base-right, base-left.
const SQUARE: [DVec2; 4] = [
    DVec2::new(-1.0, 1.0),
    DVec2::new(1.0, 1.0),
    DVec2::new(1.0, -1.0),
    DVec2::new(-1.0, -1.0),
];

/// The four-point homography H with `H (pᵢ, 1) ∝ (sᵢ, 1)` for the unit square's corners sᵢ
/// (top-left (−1, 1), top-right (1, 1), base-right (1, −1), base-left (−1, −1)).
///
/// On coordinates translated to the quad's centroid and scaled to unit size (Hartley's
/// normalisation), Heckbert's square-to-quad map P (Heckbert 1989, "Fundamentals of Texture
/// Mapping and Image Warping") sends the unit square's (α, β) = (0, 0), (1, 0), (1, 1), (0, 1) to
/// the corners p₀ … p₃:
///
/// ```text
/// P = [[a, b, c], [d, e, f], [g, h, 1]],   [p₁ − p₂ | p₃ − p₂] (g, h)ᵀ = p₀ − p₁ + p₂ − p₃,
/// (a, d) = p₁ − p₀ + g p₁,   (b, e) = p₃ − p₀ + h p₃,   (c, f) = p₀
/// ```
///
/// (the 2 × 2 system solved by nalgebra's LU; g = h = 0 for a parallelogram). H is P's adjugate
/// (∝ P⁻¹) followed by (u, v) = (2α − 1, 1 − 2β), scaled so that the centroid maps to w = 1, and
/// the normalisation composed back. The same map as the 8 × 8 system
/// `[x, y, 1, 0, 0, 0, −X x, −X y] h = X`, `[0, 0, 0, x, y, 1, −Y x, −Y y] h = Y`
/// (`homography_is_the_eight_point_solve` in tests/tsm.rs checks the two agree).
///
/// # Errors
/// [`Error::Degenerate`] when the quadrilateral is near-degenerate: not strictly convex with
/// corners in this order, any three corners within a relative 10⁻⁹ of collinear, or a mapped-back
/// residual above 10⁻⁹.
///
/// ```
/// # use shadow_aliasing::build::tsm::quad_to_square;
/// # use glam::{DVec2, DVec3};
/// let quad = [DVec2::new(-1.0, 0.0), DVec2::new(1.0, 0.0), DVec2::new(3.0, 4.0), DVec2::new(-3.0, 4.0)];
/// let h = quad_to_square(quad)?;
/// let p = h * DVec3::new(3.0, 4.0, 1.0);
/// assert!((p.x / p.z - 1.0).abs() < 1e-12 && (p.y / p.z + 1.0).abs() < 1e-12);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn quad_to_square(quad: [DVec2; 4]) -> Result<DMat3> {
    if quad.iter().any(|p| !p.is_finite()) {
        return Err(Error::invalid("quad", "must have finite corners"));
    }
    let c = (quad[0] + quad[1] + quad[2] + quad[3]) * 0.25;
    let size = quad
        .iter()
        .map(|p| (*p - c).length())
        .fold(0.0f64, f64::max);
    if size.is_nan() || size <= 0.0 {
        return Err(Error::Degenerate("the quadrilateral has no extent".into()));
    }
    let norm: [DVec2; 4] = quad.map(|p| (p - c) / size);
    // Strict convexity with a consistent orientation, and no three corners nearly collinear.
    let mut sign = 0.0f64;
    for i in 0..4 {
        let a = norm[i];
        let b = norm[(i + 1) % 4];
        let d = norm[(i + 2) % 4];
        let cr = (b - a).perp_dot(d - b);
        if cr.abs() < 1e-9 {
            return Err(Error::Degenerate(format!(
                "the quadrilateral is nearly degenerate (corners {i}..{} almost collinear)",
                i + 2
            )));
        }
        if sign == 0.0 {
            sign = cr.signum();
        } else if cr.signum() != sign {
            return Err(Error::Degenerate(
                "the quadrilateral is not convex in the given corner order".into(),
            ));
        }
    }
    // Heckbert's square-to-quad map P: the unit square's (α, β) = (0, 0), (1, 0), (1, 1), (0, 1)
    // onto the corners in order, P = [[a, b, c], [d, e, f], [g, h, 1]] on (α, β, 1). Its two
    // perspective terms solve [p₁ − p₂, p₃ − p₂] (g, h)ᵀ = p₀ − p₁ + p₂ − p₃ (nalgebra LU;
    // (g, h) = 0 for a parallelogram).
    let hn = {
        let p = norm;
        let sigma = p[0] - p[1] + p[2] - p[3];
        let (d1, d2) = (p[1] - p[2], p[3] - p[2]);
        let gh = Matrix2::new(d1.x, d2.x, d1.y, d2.y)
            .lu()
            .solve(&Vector2::new(sigma.x, sigma.y))
            .ok_or_else(|| Error::Degenerate("the homography system is singular".into()))?;
        let (g, h) = (gh[0], gh[1]);
        let (a, b, c) = (
            p[1].x - p[0].x + g * p[1].x,
            p[3].x - p[0].x + h * p[3].x,
            p[0].x,
        );
        let (d, e, f) = (
            p[1].y - p[0].y + g * p[1].y,
            p[3].y - p[0].y + h * p[3].y,
            p[0].y,
        );
        // P⁻¹ ∝ adj(P) (rows below), then (u, v) = (2α − 1, 1 − 2β) onto the corners' order
        // top-left (−1, 1) …, scaled so that h₃₃ = 1 (the centroid, the origin here, maps to w = 1).
        let row_a = DVec3::new(e - f * h, c * h - b, b * f - c * e);
        let row_b = DVec3::new(f * g - d, a - c * g, c * d - a * f);
        let row_w = DVec3::new(d * h - e * g, b * g - a * h, a * e - b * d);
        let k = 1.0 / row_w.z;
        let (row_u, row_v) = ((2.0 * row_a - row_w) * k, (row_w - 2.0 * row_b) * k);
        let row_w = row_w * k;
        DMat3::from_cols(
            DVec3::new(row_u.x, row_v.x, row_w.x),
            DVec3::new(row_u.y, row_v.y, row_w.y),
            DVec3::new(row_u.z, row_v.z, 1.0),
        )
    };
    // Undo the normalisation: p_norm = (p − c)/size.
    let t = DMat3::from_cols(
        DVec3::new(1.0 / size, 0.0, 0.0),
        DVec3::new(0.0, 1.0 / size, 0.0),
        DVec3::new(-c.x / size, -c.y / size, 1.0),
    );
    let m = hn * t;
    for i in 0..4 {
        let p = m * quad[i].extend(1.0);
        let r = DVec2::new(p.x / p.z, p.y / p.z) - SQUARE[i];
        if p.z == 0.0 || !r.is_finite() || r.length() > 1e-9 {
            return Err(Error::Degenerate(format!(
                "the homography maps corner {i} with residual {}",
                fmt_num(r.length())
            )));
        }
    }
    Ok(m)
}

/// The trapezoidal shadow map of the whole view frustum for a light travelling along
/// `light_dir` (eye space). No heap allocation.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir`, `focus` (not in (0, f − n]), `xi` (not in
/// (−1, 1)) or `map_lines` (< 2); [`Error::Degenerate`] when the trapezoid is near-degenerate.
///
/// ```
/// # use shadow_aliasing::build::tsm::{tsm, TsmOptions, TsmSearch};
/// # use shadow_aliasing::ViewFrustum;
/// # use glam::{DVec3, DVec4};
/// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
/// let opts = TsmOptions { focus: 20.0, search: TsmSearch::EightyPercent };
/// let t = tsm(&view, DVec3::new(0.0, -1.0, 0.3), opts)?;
/// // The focus point on the view axis lands on the 80 % line.
/// let h = t.shadow.matrix * DVec4::new(0.0, 0.0, -21.0, 1.0);
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
    let fr = ViewFrustum::with_aspect(n, focus_depth, view.half_fov(), view.aspect())
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

fn validate(view: &ViewFrustum, opts: &TsmOptions) -> Result<()> {
    let focus = positive("focus", opts.focus)?;
    if focus > view.far() - view.near() {
        return Err(Error::invalid(
            "focus",
            format!(
                "must be at most far − near = {} (got {})",
                fmt_num(view.far() - view.near()),
                fmt_num(focus)
            ),
        ));
    }
    match opts.search {
        TsmSearch::EightyPercent => {}
        TsmSearch::Line(xi) => {
            in_open("xi", xi, -1.0, 1.0)?;
        }
        TsmSearch::Iterative { map_lines } | TsmSearch::IterativeExhaustive { map_lines } => {
            if map_lines < 2 {
                return Err(Error::invalid(
                    "map_lines",
                    format!("must be at least 2 (got {map_lines})"),
                ));
            }
        }
    }
    Ok(())
}

/// Everything the construction needs, independent of how E was obtained.
struct Core<'a> {
    ls: LightSpace,
    /// E's vertices (eye space).
    points: &'a [DVec3],
    /// The focus region's vertices (eye space).
    focus_region: &'a [DVec3],
    /// The focus point on the centre line (eye space).
    focus_point: DVec3,
    /// Length of the projected centre line.
    centre_line: f64,
}

/// The analytic trapezoid map for a given η (q = (0, z₀ − η)): (X, Y) of a light-space (x, z).
#[derive(Clone, Copy)]
struct Analytic {
    z0: f64,
    lambda: f64,
    /// None: the bounding rectangle.
    eta: Option<f64>,
    s_min: f64,
    s_max: f64,
}

impl Analytic {
    /// From E's vertices projected to light-space (x, z).
    fn new(xz: &[DVec2], z0: f64, lambda: f64, eta: Option<f64>) -> Self {
        let (mut s_min, mut s_max) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in xz {
            let s = match eta {
                Some(e) => p.x / (p.y - z0 + e),
                None => p.x,
            };
            s_min = s_min.min(s);
            s_max = s_max.max(s);
        }
        Self {
            z0,
            lambda,
            eta,
            s_min,
            s_max,
        }
    }

    fn map(&self, x: f64, z: f64) -> DVec2 {
        let d = z - self.z0;
        let (s, y) = match self.eta {
            Some(e) => (
                x / (d + e),
                1.0 - 2.0 * (d / self.lambda) * (e + self.lambda) / (e + d),
            ),
            None => (x, 1.0 - 2.0 * d / self.lambda),
        };
        let sm = 0.5 * (self.s_min + self.s_max);
        let sh = 0.5 * (self.s_max - self.s_min);
        DVec2::new((s - sm) / sh, y)
    }

    fn corners(&self) -> [DVec2; 4] {
        let (z0, z1) = (self.z0, self.z0 + self.lambda);
        match self.eta {
            Some(e) => [
                DVec2::new(self.s_min * e, z0),
                DVec2::new(self.s_max * e, z0),
                DVec2::new(self.s_max * (e + self.lambda), z1),
                DVec2::new(self.s_min * (e + self.lambda), z1),
            ],
            None => [
                DVec2::new(self.s_min, z0),
                DVec2::new(self.s_max, z0),
                DVec2::new(self.s_max, z1),
                DVec2::new(self.s_min, z1),
            ],
        }
    }
}

impl Core<'_> {
    /// The map, with scratch for up to `N` points of E and of the focus region (more are
    /// ignored; callers pass at most `N`) and `H` ≥ 2`N` hull slots (the monotone chain's stack
    /// holds at most 2n − 1 points): sized per caller, so [`tsm`] zeroes no unused kilobytes.
    fn build<const N: usize, const H: usize>(
        &self,
        search: TsmSearch,
        near: f64,
        far: f64,
    ) -> Result<TsmMap> {
        const { assert!(H >= 2 * N) };
        let ls = &self.ls;
        // E and the focus region projected to light-space (x, z), once.
        let mut xz = [DVec2::ZERO; N];
        let m = self.points.len().min(N);
        let (mut z0, mut z1) = (f64::INFINITY, f64::NEG_INFINITY);
        for (q, p) in xz.iter_mut().zip(self.points) {
            *q = DVec2::new(ls.x.dot(*p), ls.z.dot(*p));
            z0 = z0.min(q.y);
            z1 = z1.max(q.y);
        }
        let xz = &xz[..m];
        let mut hull = [DVec2::ZERO; H];
        let mut fxz = [DVec2::ZERO; N];
        let fm = self.focus_region.len().min(N);
        for (q, p) in fxz.iter_mut().zip(self.focus_region) {
            *q = DVec2::new(ls.x.dot(*p), ls.z.dot(*p));
        }
        let hn = convex_hull(&mut fxz[..fm], &mut hull);
        let hull = &hull[..hn];
        let lambda = z1 - z0;
        if lambda.is_nan() || lambda <= 0.0 {
            return Err(Error::Degenerate(
                "the region has no extent along the centre line".into(),
            ));
        }
        let square = self.centre_line < SQUARE_TOLERANCE * lambda;
        let delta_p = ls.z.dot(self.focus_point) - z0;
        let eta_for = |xi: f64| {
            if square {
                None
            } else {
                tsm_eta(lambda, delta_p, xi)
            }
        };

        let (eta, xi) = match search {
            TsmSearch::EightyPercent => (eta_for(TSM_80_PERCENT_LINE), TSM_80_PERCENT_LINE),
            TsmSearch::Line(xi) => (eta_for(xi), xi),
            TsmSearch::Iterative { map_lines } | TsmSearch::IterativeExhaustive { map_lines } => {
                // Built only for the line searches (tables the fixed-line rules skip).
                let fast = FastArea::<N, H>::new(xz, hull, z0, lambda);
                // The bounding rectangle's area (every line without a centre of projection, all
                // those above the focus point's unwarped line) is computed once, when first needed.
                let rect = std::cell::OnceCell::new();
                let area_at = |xi: f64| match eta_for(xi) {
                    Some(e) => fast.area(e),
                    None => {
                        *rect.get_or_init(|| focus_area(&Analytic::new(xz, z0, lambda, None), hull))
                    }
                };
                let x = f64::from(map_lines);
                let line = |k: u32| 1.0 - 2.0 * f64::from(k) / x;
                let k0 = ((0.8 * x).round() as u32).max(1);
                // The first (largest k) line of largest area in [lo, hi], exhaustively.
                let scan = |lo: u32, hi: u32| {
                    let mut best = (f64::NEG_INFINITY, hi);
                    for k in (lo..=hi).rev() {
                        let a = area_at(line(k));
                        if a > best.0 {
                            best = (a, k);
                        }
                    }
                    best
                };
                let k = if matches!(search, TsmSearch::IterativeExhaustive { .. }) || k0 <= 64 {
                    scan(1, k0).1
                } else {
                    // 33 evenly spread lines (both ends included), then a golden-section
                    // search in the bracket of the best one's neighbours, then the last few
                    // lines exhaustively, every line evaluated at most once.
                    const COARSE: u32 = 32;
                    let at = |i: u32| 1 + ((k0 - 1) as u64 * i as u64 / COARSE as u64) as u32;
                    let mut best = (f64::NEG_INFINITY, 0u32);
                    for i in (0..=COARSE).rev() {
                        let a = area_at(line(at(i)));
                        if a > best.0 {
                            best = (a, i);
                        }
                    }
                    // The refinement's lines with their areas, the best coarse line first (the
                    // first 16 kept: enough for the bracket of up to ≈ 10⁴ map lines; beyond,
                    // lines are only evaluated again).
                    let mut seen = [(at(best.1), best.0); 16];
                    let mut n_seen = 1usize;
                    let mut eval = |k: u32| {
                        if let Some(&(_, a)) = seen[..n_seen].iter().find(|s| s.0 == k) {
                            return a;
                        }
                        let a = area_at(line(k));
                        if n_seen < seen.len() {
                            seen[n_seen] = (k, a);
                            n_seen += 1;
                        }
                        a
                    };
                    let (mut lo, mut hi) =
                        (at(best.1.saturating_sub(1)), at((best.1 + 1).min(COARSE)));
                    // Bracket lo ≤ c ≤ hi with c the largest area seen: probe the wider side at
                    // the golden ratio, keep the larger of the probe and c.
                    let (mut c, mut fc) = (at(best.1), best.0);
                    while hi - lo > 6 {
                        let probe = |w: u32| {
                            ((f64::from(w) * 0.381_966_011_250_105).round() as u32).clamp(1, w - 1)
                        };
                        if c - lo >= hi - c {
                            let x = c - probe(c - lo);
                            let fx = eval(x);
                            if fx > fc {
                                (hi, c, fc) = (c, x, fx);
                            } else {
                                lo = x;
                            }
                        } else {
                            let x = c + probe(hi - c);
                            let fx = eval(x);
                            if fx > fc {
                                (lo, c, fc) = (c, x, fx);
                            } else {
                                hi = x;
                            }
                        }
                    }
                    // The first (largest k) line of largest area in [lo, hi].
                    let mut refined = (f64::NEG_INFINITY, hi);
                    for k in (lo..=hi).rev() {
                        let a = eval(k);
                        if a > refined.0 {
                            refined = (a, k);
                        }
                    }
                    // Never worse than any coarse line, the 80 % line among them.
                    if best.0 > refined.0 {
                        at(best.1)
                    } else {
                        refined.1
                    }
                };
                (eta_for(line(k)), line(k))
            }
        };
        let analytic = Analytic::new(xz, z0, lambda, eta);
        let corners = analytic.corners();
        let n_t = quad_to_square(corners)?;
        // The 4 × 4 in light space: rows from N_T on (x, z, 1), depth fitted below.
        let w_of = |p: DVec3| {
            let h = n_t * DVec3::new(ls.x.dot(p), ls.z.dot(p), 1.0);
            h.z
        };
        // Orient and scale N_T so that w > 0 over E with minimum 1 (the homogeneous scale does
        // not change the map; it gives the same w ≥ 1 convention as the warps).
        let sign = if w_of(self.points[0]) < 0.0 {
            -1.0
        } else {
            1.0
        };
        let mut w_min = f64::INFINITY;
        for p in self.points {
            let w = sign * w_of(*p);
            if w.is_nan() || w <= 0.0 {
                return Err(Error::Degenerate(format!(
                    "a region vertex maps to w = {} under the trapezoid map",
                    fmt_num(w)
                )));
            }
            w_min = w_min.min(w);
        }
        let scale = sign / w_min;
        let h = n_t * scale;
        let (mut vmin, mut vmax) = (f64::INFINITY, f64::NEG_INFINITY);
        let (mut ymin, mut ymax) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in self.points {
            let w = scale * w_of(*p);
            let y = ls.y.dot(*p);
            vmin = vmin.min(y / w);
            vmax = vmax.max(y / w);
            ymin = ymin.min(y);
            ymax = ymax.max(y);
        }
        let extent = self
            .points
            .iter()
            .fold(0.0f64, |m, p| m.max(p.abs().max_element()));
        let v_h = (0.5 * (vmax - vmin)).max(1e-9 * extent);
        let v_m = 0.5 * (vmax + vmin);
        let y_h = (0.5 * (ymax - ymin)).max(1e-9 * extent);
        let y_m = 0.5 * (ymax + ymin);
        // Light-space (x, y, z, 1) rows: N_T acts on (x, z, 1).
        let row = |r: usize| DVec4::new(h.col(0)[r], 0.0, h.col(1)[r], h.col(2)[r]);
        let (r0, r1, r3) = (row(0), row(1), row(2));
        let r2 = DVec4::new(0.0, -1.0 / v_h, 0.0, 0.0) + r3 * (v_m / v_h);
        let w_ls = DMat4::from_cols(r0, r1, r2, r3).transpose();
        let matrix = w_ls * ls.rotation();
        if !matrix.is_finite() {
            return Err(Error::Degenerate(
                "the trapezoidal map is not finite".into(),
            ));
        }
        crate::build::warp::verify_clip(&matrix, self.points.iter())?;
        let light_depth = DVec4::new(-ls.y.x / y_h, -ls.y.y / y_h, -ls.y.z / y_h, y_m / y_h);
        let focus_area = focus_area(&analytic, hull);
        Ok(TsmMap {
            shadow: ShadowMatrix {
                matrix,
                light_dir: ls.light_dir(),
                n_prime: match eta {
                    Some(e) => NPrime::Finite(e),
                    None => NPrime::Unwarped,
                },
                near,
                far,
            },
            light_space: *ls,
            trapezoid: Trapezoid {
                corners,
                q: eta.map(|e| DVec2::new(0.0, z0 - e)),
            },
            n_t: h,
            light_depth,
            focus_point: self.focus_point,
            xi: if eta.is_some() {
                xi
            } else {
                analytic
                    .map(ls.x.dot(self.focus_point), ls.z.dot(self.focus_point))
                    .y
            },
            focus_area,
        })
    }
}

/// [`focus_area`] of the trapezoid map with centre of projection at distance η from the top
/// line, for the line searches, with a division per vertex instead of three. With
/// `d = z − z₀`, `r = 1/(d + η)`, the map is `s = x r` (then `(s − s_m)/s_h`) and
/// `y = 1 − 2 (η + λ)/λ · d r`; the shoelace sum is invariant under the translations and scales
/// by the scales, so
///
/// ```text
/// area = (η + λ) |Σᵢ cᵢ rᵢ₋₁ rᵢ| / (4 λ s_h),   cᵢ = xᵢ₋₁ dᵢ − xᵢ dᵢ₋₁
/// ```
///
/// over the hull's vertices (cyclic), with `cᵢ` independent of η and computed once. Equal to
/// [`focus_area`] up to rounding (`fast_area_is_focus_area` checks it).
struct FastArea<const N: usize, const H: usize> {
    /// E's x and d = z − z₀.
    ex: [f64; N],
    ed: [f64; N],
    m: usize,
    /// The hull's d and cᵢ.
    hd: [f64; H],
    hc: [f64; H],
    hn: usize,
    lambda: f64,
}

impl<const N: usize, const H: usize> FastArea<N, H> {
    fn new(xz: &[DVec2], hull: &[DVec2], z0: f64, lambda: f64) -> Self {
        let mut f = Self {
            ex: [0.0; N],
            ed: [0.0; N],
            m: xz.len().min(N),
            hd: [0.0; H],
            hc: [0.0; H],
            hn: hull.len().min(H),
            lambda,
        };
        for (j, p) in xz.iter().take(f.m).enumerate() {
            f.ex[j] = p.x;
            f.ed[j] = p.y - z0;
        }
        let hn = f.hn;
        for i in 0..hn {
            let (p, q) = (hull[(i + hn - 1) % hn], hull[i]);
            let (dp, dq) = (p.y - z0, q.y - z0);
            f.hd[i] = dq;
            f.hc[i] = p.x * dq - q.x * dp;
        }
        f
    }

    fn area(&self, eta: f64) -> f64 {
        let hn = self.hn;
        if hn < 3 {
            return 0.0;
        }
        // The divisions two at a time (independent, so the compiler can pair them in one SSE2
        // `divpd`), the min/max and the sum in the same order as one at a time: bit for bit.
        // η > 0 and d ≥ 0, so no value is NaN and the one-instruction min/max are exact.
        let (mut s_min, mut s_max) = (f64::INFINITY, f64::NEG_INFINITY);
        let m = self.m;
        let mut j = 0;
        while j + 2 <= m {
            let s0 = self.ex[j] / (self.ed[j] + eta);
            let s1 = self.ex[j + 1] / (self.ed[j + 1] + eta);
            s_min = fmin(fmin(s_min, s0), s1);
            s_max = fmax(fmax(s_max, s0), s1);
            j += 2;
        }
        if j < m {
            let s0 = self.ex[j] / (self.ed[j] + eta);
            s_min = fmin(s_min, s0);
            s_max = fmax(s_max, s0);
        }
        let s_h = 0.5 * (s_max - s_min);
        let mut r_prev = 1.0 / (self.hd[hn - 1] + eta);
        let mut sum = 0.0;
        let mut i = 0;
        while i + 2 <= hn {
            let r0 = 1.0 / (self.hd[i] + eta);
            let r1 = 1.0 / (self.hd[i + 1] + eta);
            sum += self.hc[i] * r_prev * r0;
            sum += self.hc[i + 1] * r0 * r1;
            r_prev = r1;
            i += 2;
        }
        if i < hn {
            let r = 1.0 / (self.hd[i] + eta);
            sum += self.hc[i] * r_prev * r;
        }
        (eta + self.lambda) * sum.abs() / (4.0 * self.lambda * s_h)
    }
}

/// Fraction of the unit square covered by the image of the focus region. The map is projective
/// with w > 0 over the region (or affine), so it maps the hull's vertices, in order, onto the
/// image's hull: shoelace on the mapped vertices.
fn focus_area(a: &Analytic, hull: &[DVec2]) -> f64 {
    let n = hull.len();
    if n < 3 {
        return 0.0;
    }
    let mut area = 0.0;
    let mut prev = a.map(hull[n - 1].x, hull[n - 1].y);
    for h in hull {
        let p = a.map(h.x, h.y);
        area += prev.perp_dot(p);
        prev = p;
    }
    0.125 * area.abs()
}

/// Convex hull (monotone chain, counter-clockwise, no repeated end point) of `pts` into `out`;
/// returns the number of hull vertices. Sorts `pts` in place; no allocation. The chain's stack
/// holds at most 2n − 1 points (the lower hull, then at most n − 1 more), so `out` needs 2n slots.
fn convex_hull(pts: &mut [DVec2], out: &mut [DVec2]) -> usize {
    let n = pts.len();
    if n < 3 {
        out[..n].copy_from_slice(pts);
        return n;
    }
    pts.sort_unstable_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let mut k = 0usize;
    for &p in pts.iter() {
        while k >= 2 && (out[k - 1] - out[k - 2]).perp_dot(p - out[k - 2]) <= 0.0 {
            k -= 1;
        }
        out[k] = p;
        k += 1;
    }
    let lower = k + 1;
    for i in (0..n - 1).rev() {
        while k >= lower && (out[k - 1] - out[k - 2]).perp_dot(pts[i] - out[k - 2]) <= 0.0 {
            k -= 1;
        }
        out[k] = pts[i];
        k += 1;
    }
    k - 1
}

/// A convex region of eye space bounded by up to six planes `a x + b y + c z + d ≤ 0`, stored as
/// `(a, b, c, d)`: the light's volume or a scene box for [`tsm_general`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ConvexBound {
    planes: [DVec4; 6],
}

impl ConvexBound {
    /// From six eye-space planes `(a, b, c, d)`, inside where `a x + b y + c z + d ≤ 0`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `planes` for a non-finite plane or a zero normal.
    pub fn from_planes(planes: [DVec4; 6]) -> Result<Self> {
        for p in &planes {
            if !p.is_finite() || p.truncate().length() <= 0.0 {
                return Err(Error::invalid(
                    "planes",
                    format!("must be finite with a non-zero normal (got {p})"),
                ));
            }
        }
        Ok(Self { planes })
    }

    /// A world-space axis-aligned box seen through the camera's view matrix (world → eye).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `min`/`max` (not finite, or min > max on an axis) or
    /// `view_matrix` (not invertible).
    pub fn from_aabb(min: DVec3, max: DVec3, view_matrix: DMat4) -> Result<Self> {
        if !min.is_finite() || !max.is_finite() || min.cmpgt(max).any() {
            return Err(Error::invalid(
                "min",
                format!("must be finite and not above max (got min={min}, max={max})"),
            ));
        }
        let det = view_matrix.determinant();
        if !det.is_finite() || det.abs() < 1e-300 {
            return Err(Error::invalid("view_matrix", "must be invertible"));
        }
        // A world plane π (π·(x, 1) ≤ 0) is V⁻ᵀ π in eye space.
        let it = view_matrix.inverse().transpose();
        let world = [
            DVec4::new(1.0, 0.0, 0.0, -max.x),
            DVec4::new(-1.0, 0.0, 0.0, min.x),
            DVec4::new(0.0, 1.0, 0.0, -max.y),
            DVec4::new(0.0, -1.0, 0.0, min.y),
            DVec4::new(0.0, 0.0, 1.0, -max.z),
            DVec4::new(0.0, 0.0, -1.0, min.z),
        ];
        Self::from_planes(world.map(|p| it * p))
    }
}

/// The planes of the view frustum in the same convention (a x + b y + c z + d ≤ 0).
fn frustum_planes(view: &ViewFrustum, far: f64) -> [DVec4; 6] {
    let t = view.tan_half_fov();
    let ta = t * view.aspect();
    [
        DVec4::new(0.0, 0.0, 1.0, view.near()), // depth ≥ near
        DVec4::new(0.0, 0.0, -1.0, -far),       // depth ≤ far
        DVec4::new(1.0, 0.0, ta, 0.0),          // x ≤ depth · t · a
        DVec4::new(-1.0, 0.0, ta, 0.0),         // −x ≤ depth · t · a
        DVec4::new(0.0, 1.0, t, 0.0),           // y ≤ depth · t
        DVec4::new(0.0, -1.0, t, 0.0),          // −y ≤ depth · t
    ]
}

/// Vertices of the convex polyhedron `{p : πᵢ·(p, 1) ≤ 0}`: every triple of planes whose
/// intersection point satisfies all the constraints (relative tolerance 10⁻⁹ of `scale`),
/// deduplicated. Returns the count written into `out`.
fn polytope_vertices(planes: &[DVec4], scale: f64, out: &mut [DVec3; 64]) -> usize {
    let mut count = 0;
    let tol = 1e-9 * scale;
    let m = planes.len();
    for i in 0..m {
        for j in (i + 1)..m {
            for k in (j + 1)..m {
                let a = DMat3::from_cols(
                    planes[i].truncate(),
                    planes[j].truncate(),
                    planes[k].truncate(),
                )
                .transpose();
                let det = a.determinant();
                let norms = planes[i].truncate().length()
                    * planes[j].truncate().length()
                    * planes[k].truncate().length();
                if det.abs() <= 1e-12 * norms {
                    continue;
                }
                let p = a.inverse() * DVec3::new(-planes[i].w, -planes[j].w, -planes[k].w);
                if !p.is_finite() {
                    continue;
                }
                let inside = planes
                    .iter()
                    .all(|pl| pl.truncate().dot(p) + pl.w <= tol * pl.truncate().length());
                if inside && !out[..count].iter().any(|q| (*q - p).length() <= tol) && count < 64 {
                    out[count] = p;
                    count += 1;
                }
            }
        }
    }
    count
}

/// The trapezoidal map of the part of the view frustum inside `bound` (Martin & Tan §6.4; module
/// docs). No heap allocation.
///
/// # Errors
/// As [`tsm`]; [`Error::NoSolution`] when the bound does not meet the view frustum in a solid.
///
/// ```
/// # use shadow_aliasing::build::tsm::{tsm_general, ConvexBound, TsmOptions, TsmSearch};
/// # use shadow_aliasing::ViewFrustum;
/// # use glam::{DMat4, DVec3, DVec4};
/// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
/// // The scene is a box 40 units deep in front of the camera (world = eye here).
/// let bound = ConvexBound::from_aabb(DVec3::new(-50.0, -5.0, -40.0), DVec3::new(50.0, 5.0, 0.0), DMat4::IDENTITY)?;
/// let opts = TsmOptions { focus: 20.0, search: TsmSearch::EightyPercent };
/// let t = tsm_general(&view, DVec3::new(0.3, -1.0, 0.2), &bound, opts)?;
/// let h = t.shadow.matrix * DVec4::new(0.0, 0.0, -40.0, 1.0);
/// assert!((h.truncate() / h.w).abs().max_element() <= 1.0 + 1e-9);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn tsm_general(
    view: &ViewFrustum,
    light_dir: DVec3,
    bound: &ConvexBound,
    opts: TsmOptions,
) -> Result<TsmMap> {
    validate(view, &opts)?;
    let (n, f) = (view.near(), view.far());
    let scale = f * (1.0 + view.tan_half_fov() * (1.0 + view.aspect()));
    let mut planes = [DVec4::ZERO; 13];
    planes[..6].copy_from_slice(&frustum_planes(view, f));
    planes[6..12].copy_from_slice(&bound.planes);
    let mut verts = [DVec3::ZERO; 64];
    let count = polytope_vertices(&planes[..12], scale, &mut verts);
    if count < 4 {
        return Err(Error::NoSolution(
            "the bound does not meet the view frustum in a solid region".into(),
        ));
    }
    let pts = &verts[..count];
    let e = pts.iter().fold(DVec3::ZERO, |a, p| a + *p) / count as f64;
    let (mut n_i, mut f_i) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in pts {
        n_i = n_i.min(-p.z);
        f_i = f_i.max(-p.z);
    }
    if f_i - n_i <= 1e-12 * scale {
        return Err(Error::NoSolution(
            "the bound meets the view frustum in a region without depth".into(),
        ));
    }
    let ls = light_space(light_dir, e)?;
    let focus = opts.focus * (f_i - n_i) / (f - n);
    // The focus point on the centre line (eye → e) at depth n_I + focus.
    let focus_point = e * ((n_i + focus) / -e.z);
    // The focus region: I cut at that depth.
    planes[12] = DVec4::new(0.0, 0.0, -1.0, -(n_i + focus));
    let mut fverts = [DVec3::ZERO; 64];
    let fcount = polytope_vertices(&planes[..13], scale, &mut fverts);
    // The centre line's projected length: from the eye's depth-n_I point to the f_I point on l.
    let dir = e / -e.z;
    let centre_line = (ls.z.dot(dir) * (f_i - n_i)).abs();
    let core = Core {
        ls,
        points: pts,
        focus_region: &fverts[..fcount],
        focus_point,
        centre_line,
    };
    core.build::<64, 128>(opts.search, n_i, f_i)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The line search's area (one division per vertex, translation- and scale-free shoelace)
    /// equals the map-then-shoelace area of `focus_area` on the same trapezoids, for lights all
    /// around the view and every line from the base to the top.
    #[test]
    fn fast_area_is_focus_area() {
        let view = ViewFrustum::with_aspect(0.3, 70.0, 0.6, 1.4).unwrap();
        let corners = view.corners();
        let focus = ViewFrustum::with_aspect(0.3, 12.0, 0.6, 1.4)
            .unwrap()
            .corners();
        let mut checked = 0;
        for l in [
            DVec3::new(0.2, -1.0, 0.3),
            DVec3::new(-0.7, -0.2, -0.5),
            DVec3::new(0.1, 0.4, 0.9),
        ] {
            let ls = light_space(l, DVec3::NEG_Z).unwrap();
            let xz: Vec<DVec2> = corners
                .iter()
                .map(|p| DVec2::new(ls.x.dot(*p), ls.z.dot(*p)))
                .collect();
            let mut fxz: Vec<DVec2> = focus
                .iter()
                .map(|p| DVec2::new(ls.x.dot(*p), ls.z.dot(*p)))
                .collect();
            let mut hull = [DVec2::ZERO; 130];
            let hn = convex_hull(&mut fxz, &mut hull);
            let hull = &hull[..hn];
            let z0 = xz.iter().map(|p| p.y).fold(f64::INFINITY, f64::min);
            let z1 = xz.iter().map(|p| p.y).fold(f64::NEG_INFINITY, f64::max);
            let lambda = z1 - z0;
            let fast = FastArea::<64, 130>::new(&xz, hull, z0, lambda);
            for eta in [1e-3, 0.1, 1.0, 7.5, 40.0, 1e3, 1e6] {
                let slow = focus_area(&Analytic::new(&xz, z0, lambda, Some(eta)), hull);
                let f = fast.area(eta);
                assert!(slow > 0.0 && slow <= 1.0 + 1e-12, "{slow}");
                // Relative agreement ≈ 1e−15 except where the area is a tiny fraction of the map
                // (the focus region seen nearly edge-on, η → 0), where both sums cancel; the
                // absolute difference stays below 1e−16 of the map there (3e−17 at area 2e−10).
                assert!(
                    (f - slow).abs() <= 1e-15 + 1e-12 * slow,
                    "η = {eta}: {f} vs {slow}"
                );
                checked += 1;
            }
        }
        assert_eq!(checked, 21);
    }
}
