//! The ground truth: the perspective aliasing error of any shadow matrix, measured from the
//! exact derivatives of the projective maps.
//!
//! # What is measured
//!
//! A shadow matrix `M` maps an eye-space point `p` (homogeneous `(p, 1)`) to light clip space
//! `h = M (p, 1)`; the shadow-map coordinates are `s = (h.x/h.w + 1)/2`, `t = (h.y/h.w + 1)/2`,
//! both in `[0, 1]` over the map (OpenGL clip x, y; the depth row is not used). The map is for a
//! directional light travelling along `L`, so `s` and `t` are constant along light rays.
//!
//! The derivative of a projective map is closed form: `∇(h.x/h.w) = (M₀ − (h.x/h.w) M₃)/h.w`
//! with `M₀`, `M₃` the first three entries of rows 0 and 3. No finite differences are used.
//!
//! In the plane Π ⊥ L the texel footprint is a parallelogram. Following Lloyd 2006 §4.4 (Eqs 2–4)
//! generalised to any matrix:
//!
//! - image beam width `w_i = 2 z tan θ / res_i`, with `z = −p.z` the depth (Lloyd 2006 Eq 2);
//! - light beam width along s, `w_ls`: the length of the texel edge along which s advances while
//!   t stays fixed, `|∇_Π t| / (|det A| res_s)` with `A = ∂(s, t)/∂Π`;
//! - light beam width along t, `w_lt`: the distance between neighbouring t-isolines,
//!   `1 / (|∇_Π t| res_t)`;
//! - `m_x = w_ls / w_i`, `m_z = w_lt / w_i`.
//!
//! For the papers' warps (t depends only on the light-space z) these are exactly Lloyd's
//! `w_lx = (1/res_s) dx/ds` and `w_lz = (1/res_t) dz/dt`, and `w_ls · w_lt` is the texel's area.
//! Zhang et al.'s perspective aliasing uses screen coordinates in `[−1, 1]` and texture
//! coordinates in `[0, 1]`, so `E_q^pers = 2 m_x`, `E_p^pers = 2 m_z` with unit resolutions.

pub mod footprint;
pub mod tilted_twin;
pub mod twin;
pub mod vertex;

pub use footprint::{surface_footprint, Footprint, Grids};

use crate::error::{finite_result, Error, Result};
use crate::frustum::{LightDir, Resolutions, ViewFrustum};
use glam::{DMat4, DVec3, DVec4};

/// Relative tolerance for "s and t are constant along light rays".
pub const LIGHT_RAY_TOLERANCE: f64 = 1e-7;

/// The largest bound on the relative rounding error of the measured beam widths that
/// [`point_error`] and [`frustum_max`] accept (see "Domain" in [`frustum_max`]): the values
/// they return are accurate to about this, relative. Where the bound is 5 (θ = π/2 − 1 ulp) the
/// values measured were 21 % off; the crate's extreme test cameras (f/n = 10⁶, θ = 80°, PSM with
/// the light along the view axis, n′ = 10⁻⁵ n) have bounds below 2·10⁻⁷.
pub const ROUNDING_TOLERANCE: f64 = 1e-6;

/// A bound on the relative rounding error of the widths measured at `p` with `h = M (p, 1)`,
/// `G_s = h.w M₀ − h.x M₃`, `G_t = h.w M₁ − h.y M₃` (computed in `f64`), `D = (G_s × G_t)·L` and
/// `g = |G_t − (G_t·L) L|`, to first order in the unit roundoff u:
///
/// - `h` is computed with errors `|δhᵢ| ≤ 4u aᵢ`, `aᵢ = Σₖ |Mᵢₖ| |(p, 1)ₖ|`, carried into `G_t`
///   (`|δG_t| ≤ 4u (a_w |M₁| + a_y |M₃|)`) and, through the identity
///   `D = h.w (h.w (M₀×M₁)·L − h.y (M₀×M₃)·L + h.x (M₁×M₃)·L)`, which holds for any `h` (so the
///   computed `G_s × G_t` is this form of the computed `h`, whose triple products are never
///   formed), into `D`;
/// - forming `G_s`, `G_t` from `h` and the cross and dot products add `2u` relative errors of
///   their terms.
///
/// The same bound holds, to first order, for relative changes of u in the matrix entries (the
/// rounding of the matrix itself). `NaN` or `inf` when `g`, `D` or `h.w` is zero.
#[derive(Debug, Clone, Copy)]
struct Rounding {
    /// `|M|`, entrywise.
    abs: DMat4,
    /// `|M₁|`, `|M₃|` (first three entries), entrywise.
    abs1: DVec3,
    abs3: DVec3,
    /// `|M₀|`, `|M₁|`, `|M₃|`, lengths.
    n0: f64,
    n1: f64,
    n3: f64,
    /// `(M₀×M₁)·L`, `(M₀×M₃)·L`, `(M₁×M₃)·L`.
    ta: f64,
    tb: f64,
    tc: f64,
}

impl Rounding {
    /// The per-matrix terms of [`Rounding::bound`], computed once per matrix and light.
    #[inline]
    fn new(m: &DMat4, l: DVec3) -> Self {
        let abs = DMat4::from_cols(
            m.x_axis.abs(),
            m.y_axis.abs(),
            m.z_axis.abs(),
            m.w_axis.abs(),
        );
        let (r0, r1, r3) = (
            m.row(0).truncate(),
            m.row(1).truncate(),
            m.row(3).truncate(),
        );
        Self {
            abs,
            abs1: abs.row(1).truncate(),
            abs3: abs.row(3).truncate(),
            n0: r0.length(),
            n1: r1.length(),
            n3: r3.length(),
            ta: r0.cross(r1).dot(l),
            tb: r0.cross(r3).dot(l),
            tc: r1.cross(r3).dot(l),
        }
    }

    /// The bound at `p` (see above), with `h`, `G_s`, `G_t` as computed there.
    #[inline]
    fn bound(&self, p: DVec3, h: DVec4, gs: DVec3, gt: DVec3, l: DVec3) -> f64 {
        const C: f64 = 8.0 * 0.5 * f64::EPSILON;
        let a = self.abs * p.abs().extend(1.0);
        // g: the errors of h through G_t.
        let et = C * (a.w * self.abs1 + a.y * self.abs3).length();
        let g = (gt - gt.dot(l) * l).length();
        let rel_g = et / g;
        // D: the errors of h through the factorised form, then those of forming G and D from h.
        let bracket = h.w * self.ta - h.y * self.tb + h.x * self.tc;
        let e_bracket = C * (a.w * self.ta.abs() + a.y * self.tb.abs() + a.x * self.tc.abs());
        let rel_w = C * a.w / h.w.abs();
        let d = gs.cross(gt).dot(l).abs();
        let (ls, lt) = (gs.length(), gt.length());
        let gs_perp = (gs - gs.dot(l) * l).length();
        let es = C * (h.w.abs() * self.n0 + h.x.abs() * self.n3);
        let et_form = C * (h.w.abs() * self.n1 + h.y.abs() * self.n3);
        let rel_d =
            rel_w + e_bracket / bracket.abs() + (es * g + gs_perp * et_form + C * ls * lt) / d;
        // Not `max`: a NaN must survive to fail the caller's test. h.w enters squared.
        rel_g + rel_d + 2.0 * rel_w
    }
}

#[cold]
#[inline(never)]
fn ill_conditioned(p: DVec3, bound: f64) -> Error {
    Error::Degenerate(format!(
        "the shadow map is ill-conditioned at {p}: rounding in f64 can change its texel widths \
         there by a relative {} (more than {ROUNDING_TOLERANCE:e}), so no exact measurement exists \
         (the map's coordinates over the frustum are a few ulps apart; narrow the field of view \
         or the depth range)",
        crate::error::fmt_num(bound)
    ))
}

/// A shadow matrix to measure: the matrix (eye space → light clip space, OpenGL x, y) and the
/// eye-space direction the light travels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShadowMap {
    matrix: DMat4,
    /// Unit (a [`LightDir`]'s vector).
    light_dir: DVec3,
}

impl ShadowMap {
    /// Validates the light direction (normalised here) and the matrix (finite entries).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `light_dir` or `matrix`.
    pub fn new(matrix: DMat4, light_dir: DVec3) -> Result<Self> {
        if !matrix.is_finite() {
            return Err(Error::invalid("matrix", "must have finite entries"));
        }
        Ok(Self::from_parts(matrix, LightDir::new(light_dir)?))
    }

    /// A matrix with finite entries (a builder's) and a validated light direction.
    #[inline]
    pub(crate) fn from_parts(matrix: DMat4, light_dir: LightDir) -> Self {
        debug_assert!(matrix.is_finite());
        Self {
            matrix,
            light_dir: light_dir.as_dvec3(),
        }
    }

    /// Eye space → light clip space.
    #[inline]
    #[must_use]
    pub fn matrix(&self) -> DMat4 {
        self.matrix
    }

    /// Unit eye-space direction the light travels.
    #[inline]
    #[must_use]
    pub fn light_dir(&self) -> DVec3 {
        self.light_dir
    }
}

/// The perspective aliasing error at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointError {
    /// Lloyd's m_x: light beam width along s over image beam width.
    pub mx: f64,
    /// Lloyd's m_z: light beam width along t over image beam width.
    pub mz: f64,
    /// Light beam width along s, world units (resolution included).
    pub w_ls: f64,
    /// Light beam width along t, world units (resolution included).
    pub w_lt: f64,
    /// Image beam width at the point, world units.
    pub w_i: f64,
    /// Shadow-map coordinates (s, t) of the point, `[0, 1]` over the map.
    pub st: (f64, f64),
}

impl PointError {
    /// Zhang et al.'s perspective aliasing E_q^pers (screen in `[−1, 1]`, texture in `[0, 1]`):
    /// `2 m_x` when all resolutions are 1.
    #[must_use]
    pub fn zhang_eq(&self) -> f64 {
        2.0 * self.mx
    }
    /// Zhang et al.'s perspective aliasing E_p^pers: `2 m_z` when all resolutions are 1.
    #[must_use]
    pub fn zhang_ep(&self) -> f64 {
        2.0 * self.mz
    }
}

/// Exact gradients of the shadow-map coordinates at `p`: `(s, t, ∇s, ∇t, h.w)`.
///
/// # Errors
/// [`Error::Degenerate`] when `h.w ≤ 0` (the point is behind the map's centre of projection).
pub fn st_gradients(matrix: &DMat4, p: DVec3) -> Result<(f64, f64, DVec3, DVec3, f64)> {
    let h = *matrix * DVec4::new(p.x, p.y, p.z, 1.0);
    if !h.is_finite() || h.w <= 0.0 {
        return Err(Error::Degenerate(format!(
            "the point {p} maps to w = {} (behind the shadow map's centre of projection)",
            h.w
        )));
    }
    let r0 = matrix.row(0).truncate();
    let r1 = matrix.row(1).truncate();
    let r3 = matrix.row(3).truncate();
    let x = h.x / h.w;
    let y = h.y / h.w;
    let gs = (r0 - x * r3) / (2.0 * h.w);
    let gt = (r1 - y * r3) / (2.0 * h.w);
    Ok((0.5 * (x + 1.0), 0.5 * (y + 1.0), gs, gt, h.w))
}

/// The perspective aliasing error of `shadow` at the eye-space point `p` of `view`.
///
/// `p` need not lie inside the frustum, but its depth `−p.z` must be positive.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `point` for a non-finite point or depth ≤ 0, or `matrix` when
/// s or t vary along light rays (not a directional-light shadow map for `light_dir`);
/// [`Error::Degenerate`] when the point is behind the map's centre of projection, the map is
/// singular there, or so ill-conditioned there that rounding in `f64` can change the widths by
/// more than [`ROUNDING_TOLERANCE`] (relative).
pub fn point_error(
    view: &ViewFrustum,
    shadow: &ShadowMap,
    p: DVec3,
    res: Resolutions,
) -> Result<PointError> {
    if !p.is_finite() {
        return Err(Error::invalid("point", format!("must be finite (got {p})")));
    }
    let z = -p.z;
    if z <= 0.0 {
        return Err(Error::invalid(
            "point",
            format!("must be in front of the camera, depth −p.z > 0 (got {p})"),
        ));
    }
    let (s, t, gs, gt, _) = st_gradients(&shadow.matrix, p)?;
    let l = shadow.light_dir;
    let along_s = gs.dot(l);
    let along_t = gt.dot(l);
    if along_s.abs() > LIGHT_RAY_TOLERANCE * gs.length()
        || along_t.abs() > LIGHT_RAY_TOLERANCE * gt.length()
    {
        return Err(Error::invalid(
            "matrix",
            "does not map light rays to constant texels: s or t varies along light_dir",
        ));
    }
    // Project the gradients onto the plane perpendicular to the light.
    let gs_p = gs - along_s * l;
    let gt_p = gt - along_t * l;
    let grad_t = gt_p.length();
    // |det A| for an orthonormal basis of Π is |∇_Π s × ∇_Π t|.
    let det = gs_p.cross(gt_p).length();
    if !det.is_finite() || grad_t <= 0.0 || det <= 0.0 {
        return Err(Error::Degenerate(format!(
            "the shadow map is singular at {p}: texels have no finite extent there"
        )));
    }
    let m = &shadow.matrix;
    let h = *m * p.extend(1.0);
    let g_s = h.w * m.row(0).truncate() - h.x * m.row(3).truncate();
    let g_t = h.w * m.row(1).truncate() - h.y * m.row(3).truncate();
    let bound = Rounding::new(m, l).bound(p, h, g_s, g_t, l);
    if bound.is_nan() || bound > ROUNDING_TOLERANCE {
        return Err(ill_conditioned(p, bound));
    }
    let w_i = 2.0 * z * view.tan_half_fov() / res.image();
    let w_ls = grad_t / (det * res.s());
    let w_lt = 1.0 / (grad_t * res.t());
    Ok(PointError {
        mx: w_ls / w_i,
        mz: w_lt / w_i,
        w_ls,
        w_lt,
        w_i,
        st: (s, t),
    })
}

/// The maximum error of a shadow map over a view frustum.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrustumError {
    /// M_x, the maximum of m_x.
    pub max_mx: f64,
    /// M_z, the maximum of m_z.
    pub max_mz: f64,
    /// The storage factor S̄ = M_x M_z with unit resolutions (Lloyd 2006 Eq 12, §4.4).
    pub storage_factor: f64,
}

/// M_x, M_z and S̄ of `shadow` over `view`, taken at the eight vertices of the frustum
/// (Lloyd 2006 §4.4: the beam widths are monotonic over the convex frustum, so the maxima lie at
/// vertices; [`frustum_max_sampled`] checks the claim).
///
/// # Domain
///
/// The claim is exact for the papers' warps (t a function of one light-space coordinate), whose
/// `|G_t⊥|` is constant and whose `D` is affine over the frustum, and it is exact *in `f64`* only
/// where the matrix is well conditioned. With half the field of view within a few ulps of π/2
/// the frustum is ~10¹⁶ times wider than it is deep, a warp's t varies over it by a few ulps of 1,
/// and `G_t = h.w M₁ − h.y M₃` cancels to its last digits: the value at a vertex is rounding
/// noise (n = 1, f = 2, θ = π/2 − 1 ulp, light (0, −1, −1), LiSPSM 1/sin γ: M_z came out 2.2·10¹⁵ at
/// the vertices and 2.8·10¹⁵ at interior samples, 21 % apart). So each vertex's widths carry a
/// first-order rounding bound (the error of `h` carried through every cancellation), and a vertex
/// whose bound exceeds [`ROUNDING_TOLERANCE`] is an error, not a number.
///
/// # Errors
/// As [`point_error`], for any vertex (including the ill-conditioning of the Domain section);
/// [`Error::Degenerate`] when M_x, M_z or their product overflows `f64`.
pub fn frustum_max(view: &ViewFrustum, shadow: &ShadowMap) -> Result<FrustumError> {
    let corners = view.corners();
    match vertex_max_checked(view, shadow, &corners) {
        Some(e) => Ok(e),
        // Anything the fast pass is not sure of (an error, or a value near a tolerance) is
        // measured point by point, which reports the same error `point_error` does.
        None => max_over(view, shadow, corners.into_iter()),
    }
}

/// [`max_over`] at the frustum's eight corners with the one vertex kernel
/// ([`vertex::vertex_max`]'s [`vertex::Kernel`]) and, beside it, what [`point_error`] validates:
/// `None` whenever [`point_error`] could fail at a corner (or the light direction is not unit
/// length), so the caller falls back to it. With `h = M (p, 1)`, `G_s = h.w M₀ − h.x M₃`,
/// `G_t = h.w M₁ − h.y M₃` (rows of M, first three entries; `∇s = G_s/(2 h.w²)`,
/// `∇t = G_t/(2 h.w²)`), the light-ray test `|∇s·L| ≤ 10⁻⁷ |∇s|` is scale-free, so it is made
/// on `G_s`, `G_t` in squares, with a 10⁻⁹ relative margin inside which the point-by-point path
/// decides; likewise the rounding bound. `None` too when S̄ = M_x M_z overflows.
#[inline]
fn vertex_max_checked(
    view: &ViewFrustum,
    shadow: &ShadowMap,
    corners: &[DVec3; 8],
) -> Option<FrustumError> {
    let l = shadow.light_dir;
    let unit = (l.length_squared() - 1.0).abs() <= 1e-12;
    if !unit {
        return None;
    }
    let m = &shadow.matrix;
    let kernel = vertex::Kernel::new(m, l);
    let r0 = m.row(0).truncate();
    let r1 = m.row(1).truncate();
    let r2 = m.row(2);
    let r3 = m.row(3).truncate();
    let tol2 = LIGHT_RAY_TOLERANCE * LIGHT_RAY_TOLERANCE * (1.0 - 1e-9);
    let rounding = Rounding::new(m, l);
    let mut max = vertex::Maxima::new();
    let mut ok = true;
    for p in corners {
        let [hx, hy, hw] = kernel.homogeneous(*p);
        let hz = ((r2.x * p.x + r2.y * p.y) + r2.z * p.z) + r2.w;
        let h = DVec4::new(hx, hy, hz, hw);
        let w = kernel.widths([hx, hy, hw], -p.z);
        let gs = h.w * r0 - h.x * r3;
        let gt = h.w * r1 - h.y * r3;
        let (gsl, gtl) = (gs.dot(l), gt.dot(l));
        ok &= w.ok
            && h.is_finite()
            && gsl * gsl <= tol2 * gs.length_squared()
            && gtl * gtl <= tol2 * gt.length_squared()
            && rounding.bound(*p, h, gs, gt, l) <= ROUNDING_TOLERANCE * (1.0 - 1e-9);
        max.add(&w);
    }
    // An overflowing S̄ is an error `max_over` reports.
    let e = max.finish(view.tan_half_fov())?;
    (ok && e.storage_factor.is_finite()).then_some(e)
}

/// As [`frustum_max`], but over a dense `n × n × n` grid of the frustum (in depth, and in the
/// image's normalised coordinates), to check that the vertices suffice.
///
/// # Errors
/// As [`point_error`]; [`Error::InvalidArgument`] naming `n` when `n < 2`.
pub fn frustum_max_sampled(
    view: &ViewFrustum,
    shadow: &ShadowMap,
    n: usize,
) -> Result<FrustumError> {
    if n < 2 {
        return Err(Error::invalid("n", format!("must be at least 2 (got {n})")));
    }
    let t = view.tan_half_fov();
    let step = 1.0 / (n - 1) as f64;
    let points = (0..n).flat_map(move |i| {
        let z = view.near() + (view.far() - view.near()) * i as f64 * step;
        (0..n).flat_map(move |j| {
            (0..n).map(move |k| {
                let u = -1.0 + 2.0 * j as f64 * step;
                let v = -1.0 + 2.0 * k as f64 * step;
                DVec3::new(u * z * t * view.aspect(), v * z * t, -z)
            })
        })
    });
    max_over(view, shadow, points)
}

/// M_x, M_z and S̄ over `points` by [`point_error`] at each (unit resolutions).
pub(crate) fn max_over(
    view: &ViewFrustum,
    shadow: &ShadowMap,
    points: impl Iterator<Item = DVec3>,
) -> Result<FrustumError> {
    let (mut mx, mut mz) = (0.0f64, 0.0f64);
    for p in points {
        let e = point_error(view, shadow, p, Resolutions::default())?;
        mx = mx.max(e.mx);
        mz = mz.max(e.mz);
    }
    Ok(FrustumError {
        max_mx: finite_result("M_x", mx)?,
        max_mz: finite_result("M_z", mz)?,
        storage_factor: finite_result("the storage factor M_x M_z", mx * mz)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DMat4;

    /// An orthographic map, light straight down (−Y), fitted by hand to the frustum's footprint
    /// seen from above: x ∈ [−f tanθ, f tanθ], depth ∈ [n, f]. Lloyd 2006 Eq 12 with n′ = ∞ gives
    /// S̄ = (f/n − 1) f / (2 n tan θ); M_x = f/n, M_z = (f − n)/(2 n tan θ) by hand.
    #[test]
    fn orthographic_overhead_matches_hand_calculation() {
        let (n, f, th) = (1.0, 20.0, 0.4f64);
        let v = ViewFrustum::new(n, f, th).unwrap();
        let half = f * th.tan();
        // s from x; t from depth z = −p.z: t = (z − n)/(f − n).
        // clip x = x/half; clip y = 2t − 1 = 2(−p.z − n)/(f − n) − 1.
        let m = DMat4::from_cols_array(&[
            1.0 / half,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            -2.0 / (f - n),
            1.0,
            0.0,
            0.0,
            -2.0 * n / (f - n) - 1.0,
            0.0,
            1.0,
        ]);
        let sm = ShadowMap::new(m, DVec3::new(0.0, -1.0, 0.0)).unwrap();
        let e = frustum_max(&v, &sm).unwrap();
        let tan = th.tan();
        assert!((e.max_mx - f / n).abs() < 1e-12 * f);
        assert!((e.max_mz - (f - n) / (2.0 * n * tan)).abs() < 1e-12 * f);
        let sbar = (f / n - 1.0) * f / (2.0 * n * tan);
        assert!((e.storage_factor - sbar).abs() < 1e-12 * sbar);
        let dense = frustum_max_sampled(&v, &sm, 9).unwrap();
        assert!((dense.storage_factor - sbar).abs() < 1e-12 * sbar);
        // A matrix that is not constant along the light is refused.
        let bad = ShadowMap::new(DMat4::IDENTITY, DVec3::new(0.0, -1.0, 0.0)).unwrap();
        assert!(point_error(&v, &bad, DVec3::new(0.0, 0.0, -2.0), Resolutions::default()).is_err());
    }
}
