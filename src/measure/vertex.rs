//! The one vertex kernel: M_x and M_z of one matrix at a handful of points, with no allocation.
//! [`crate::measure::frustum_max`] (with its validation beside it), the schemes' own measurement
//! ([`crate::scheme`], [`crate::maps::cascades`], [`crate::maps::faces`]) and the hemisphere
//! sweep ([`crate::scheme::sweep`], four directions at a time) all compute the widths with
//! `Kernel`; [`super::point_error`] is the validated single-point oracle it agrees with.

use super::FrustumError;
use crate::numeric::lane::{Lane, V3};
use glam::{DMat4, DVec3};

/// The largest m_x and m_z of `matrix` over `points` (unit resolutions), the hot-path twin of
/// [`crate::measure::point_error`]; `storage_factor` is their product.
///
/// At a point p with `h = M (p, 1)`, the gradients of s and t are `G_s/(2 h.w²)` and
/// `G_t/(2 h.w²)` with `G_s = h.w M₀ − h.x M₃`, `G_t = h.w M₁ − h.y M₃` (rows 0, 1, 3 of M, first
/// three entries). With `G_t⊥ = G_t − (G_t·L) L` the part of G_t in the plane perpendicular to the
/// light L, and `D = det[G_s, G_t, L]` the area factor of the (s, t) map restricted to that plane
/// (projecting both gradients onto the plane does not change this determinant), the widths of
/// [`crate::measure`] become
///
/// ```text
/// m_x = h.w² |G_t⊥| / (|D| z tan θ),   m_z = h.w² / (|G_t⊥| z tan θ),   z = −p.z (depth)
/// ```
///
/// The loop compares squares, `m_x² = h.w⁴ |G_t⊥|⁴ / (D² |G_t⊥|² z²) / tan²θ` and
/// `m_z² = h.w⁴ D² / (D² |G_t⊥|² z²) / tan²θ`, with one division per point and one square root per
/// maximum; since G_s, G_t are linear in (h.x, h.y, h.w), `D = h.w (h.w a − h.y b + h.x c)` with
/// `a = (g₀ × g₁)·L`, `b = (g₀ × g₃)·L`, `c = (g₁ × g₃)·L` and `G_t⊥ = h.w g₁⊥ − h.y g₃⊥` are set
/// up once per matrix (`Kernel::new`).
///
/// `light_dir` must be a unit vector (the direction light travels) and `tan_half_fov` = tan θ of
/// the camera. No validation is done beyond what keeps the answer honest: the function returns
/// `None` (never NaN) when a point is behind the map's centre of projection (`h.w ≤ 0`), has
/// depth ≤ 0, or the map is singular there.
#[inline]
#[must_use]
pub fn vertex_max(
    matrix: &DMat4,
    light_dir: DVec3,
    tan_half_fov: f64,
    points: &[DVec3],
) -> Option<FrustumError> {
    let kernel = Kernel::new(matrix, light_dir);
    let mut max = Maxima::new();
    for &p in points {
        let h = kernel.homogeneous(p);
        let w = kernel.widths(h, -p.z);
        // `w > 0`, `z > 0`, NaN refused, a finite 1/(D² |G_t⊥|² z²) and G_t⊥ ≠ 0.
        if !w.ok {
            return None;
        }
        max.add(&w);
    }
    max.finish(tan_half_fov)
}

/// What the kernel sets up once per matrix: rows 0, 1, 3 (the depth row does not enter the
/// error), `a`, `b`, `c` and `g₁⊥`, `g₃⊥` of [`vertex_max`]'s derivation. Generic over the lane
/// type: `f64` for one matrix, `[f64; 4]` for four (the sweep's lanes), the same IEEE operations
/// in the same order either way.
#[derive(Clone, Copy)]
pub(crate) struct Kernel<T: Lane> {
    /// Rows 0, 1, 3: eye-space part and constant.
    pub(crate) rows: [(V3<T>, T); 3],
    a: T,
    b: T,
    c: T,
    g1p: V3<T>,
    g3p: V3<T>,
}

/// m_x² tan²θ and m_z² tan²θ of one point as the kernel compares them, `w⁴ |G_t⊥|⁴ inv` and
/// `w⁴ D² inv` with `inv = 1/(D² |G_t⊥|² z²)`, and whether the point is measurable (`w > 0`,
/// `z > 0`, a finite `inv`, `G_t⊥ ≠ 0`; false for NaN).
#[derive(Clone, Copy)]
pub(crate) struct Widths<T: Lane> {
    pub(crate) mx2: T,
    pub(crate) mz2: T,
    pub(crate) ok: T::Mask,
}

impl Kernel<f64> {
    /// The kernel of one matrix and unit light direction.
    #[inline(always)]
    pub(crate) fn new(matrix: &DMat4, light_dir: DVec3) -> Self {
        let row = |i: usize| {
            let r = matrix.row(i);
            (V3::from(r.truncate()), r.w)
        };
        Self::from_rows([row(0), row(1), row(3)], V3::from(light_dir))
    }

    /// `(h.x, h.y, h.w)` of `M (p, 1)`, `((r.x p.x + r.y p.y) + r.z p.z) + r.w` (glam's order).
    #[inline(always)]
    pub(crate) fn homogeneous(&self, p: DVec3) -> [f64; 3] {
        let at = |(v, w): (V3<f64>, f64)| ((v.x * p.x + v.y * p.y) + v.z * p.z) + w;
        [at(self.rows[0]), at(self.rows[1]), at(self.rows[2])]
    }
}

impl<T: Lane> Kernel<T> {
    /// The kernel from rows 0, 1, 3 of the matrix and the unit light direction `l`.
    #[inline(always)]
    pub(crate) fn from_rows(rows: [(V3<T>, T); 3], l: V3<T>) -> Self {
        let (g0, g1, g3) = (rows[0].0, rows[1].0, rows[2].0);
        Self {
            rows,
            a: g0.cross(g1).dot(l),
            b: g0.cross(g3).dot(l),
            c: g1.cross(g3).dot(l),
            g1p: g1.perp(l),
            g3p: g3.perp(l),
        }
    }

    /// The widths at a point with `[h.x, h.y, h.w]` and depth `z = −p.z`.
    #[inline(always)]
    pub(crate) fn widths(&self, [hx, hy, hw]: [T; 3], z: T) -> Widths<T> {
        let d = hw * (hw * self.a - hy * self.b + hx * self.c);
        let d2 = d * d;
        let tx = hw * self.g1p.x - hy * self.g3p.x;
        let ty = hw * self.g1p.y - hy * self.g3p.y;
        let tz = hw * self.g1p.z - hy * self.g3p.z;
        let gtp2 = tx * tx + ty * ty + tz * tz;
        let w2 = hw * hw;
        let w4 = w2 * w2;
        let inv = T::splat(1.0) / (d2 * gtp2 * z * z);
        let zero = T::splat(0.0);
        let ok = T::and(
            T::and(hw.gt(zero), z.gt(zero)),
            T::and(inv.finite(), gtp2.gt(zero)),
        );
        Widths {
            mx2: w4 * gtp2 * gtp2 * inv,
            mz2: w4 * d2 * inv,
            ok,
        }
    }
}

/// The running maxima of m_x² tan²θ and m_z² tan²θ over the points, in point order.
#[derive(Clone, Copy)]
pub(crate) struct Maxima<T: Lane> {
    mx2: T,
    mz2: T,
}

impl<T: Lane> Maxima<T> {
    #[inline(always)]
    pub(crate) fn new() -> Self {
        Self {
            mx2: T::splat(0.0),
            mz2: T::splat(0.0),
        }
    }
    /// `fmax`: the values are finite wherever they count (a point that is not `ok` makes the
    /// result unusable), so `fmax` is `f64::max` there.
    #[inline(always)]
    pub(crate) fn add(&mut self, w: &Widths<T>) {
        self.mx2 = self.mx2.max(w.mx2);
        self.mz2 = self.mz2.max(w.mz2);
    }
    /// M_x and M_z: `√(max / tan²θ)`.
    #[inline(always)]
    pub(crate) fn values(&self, tan_half_fov: T) -> (T, T) {
        let t2 = tan_half_fov * tan_half_fov;
        ((self.mx2 / t2).sqrt(), (self.mz2 / t2).sqrt())
    }
}

impl Maxima<f64> {
    /// The result, or `None` unless M_x and M_z are finite and positive.
    #[inline]
    pub(crate) fn finish(&self, tan_half_fov: f64) -> Option<FrustumError> {
        let (mx, mz) = self.values(tan_half_fov);
        if mx.is_finite() && mz.is_finite() && mx > 0.0 && mz > 0.0 {
            Some(FrustumError {
                max_mx: mx,
                max_mz: mz,
                storage_factor: mx * mz,
            })
        } else {
            None
        }
    }
}
