//! The fast vertex measurement: M_x and M_z of one matrix at a handful of points, with no
//! validation and no allocation. The hemisphere sweep ([`crate::scheme::sweep`]) and the schemes'
//! own measurement ([`crate::scheme`]) call it for every partition; [`super::point_error`] is the
//! validated single-point oracle it agrees with.

use crate::numeric::fmax;
use glam::{DMat4, DVec3, DVec4};

/// M_x and M_z of one matrix over a set of points (unit resolutions), from [`vertex_max`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VertexMax {
    /// The largest m_x over the points.
    pub max_mx: f64,
    /// The largest m_z over the points.
    pub max_mz: f64,
}

impl VertexMax {
    /// The storage factor S̄ = M_x · M_z (Lloyd 2006 §4.4).
    #[inline]
    #[must_use]
    pub fn storage_factor(&self) -> f64 {
        self.max_mx * self.max_mz
    }
}

/// The largest m_x and m_z of `matrix` over `points`, the hot-path twin of
/// [`crate::measure::point_error`] with unit resolutions.
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
/// up once per matrix.
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
) -> Option<VertexMax> {
    // Rows 0, 1, 3 only: the depth row does not enter the error. With g₀, g₁, g₃ the first three
    // entries of rows 0, 1, 3, G_s = h.w g₀ − h.x g₃ and G_t = h.w g₁ − h.y g₃, so
    //   D = det[G_s, G_t, L] = h.w (h.w a − h.y b + h.x c),
    //   a = (g₀ × g₁)·L, b = (g₀ × g₃)·L, c = (g₁ × g₃)·L,
    //   G_t⊥ = h.w g₁⊥ − h.y g₃⊥  (g⊥ = g − (g·L) L),
    // with a, b, c, g₁⊥, g₃⊥ computed once per matrix.
    let r0 = matrix.row(0);
    let r1 = matrix.row(1);
    let r3 = matrix.row(3);
    let (g0, g1, g3) = (r0.truncate(), r1.truncate(), r3.truncate());
    let l = light_dir;
    let a = g0.cross(g1).dot(l);
    let b = g0.cross(g3).dot(l);
    let c = g1.cross(g3).dot(l);
    let g1p = g1 - g1.dot(l) * l;
    let g3p = g3 - g3.dot(l) * l;
    let terms = PointTerms {
        r0,
        r1,
        r3,
        a,
        b,
        c,
        g1p,
        g3p,
    };
    let (mut mx2, mut mz2) = (0.0f64, 0.0f64);
    if let Ok(p8) = <&[DVec3; 8]>::try_from(points) {
        // The eight vertices of a (sub)frustum: the same arithmetic per point, laid out as
        // arrays so the compiler evaluates two points per SSE2 instruction, then the maxima in
        // point order (max is exact, so the values are the loop's below, bit for bit).
        let mut sx = [0.0f64; 8];
        let mut sz = [0.0f64; 8];
        let mut ok = [false; 8];
        for i in 0..8 {
            (sx[i], sz[i], ok[i]) = terms.at(p8[i]);
        }
        if ok.contains(&false) {
            return None;
        }
        for i in 0..8 {
            mx2 = fmax(mx2, sx[i]);
            mz2 = fmax(mz2, sz[i]);
        }
        return finish(mx2, mz2, tan_half_fov);
    }
    for &p in points {
        let (sx, sz, ok) = terms.at(p);
        // `w > 0`, `z > 0`, NaN refused, a finite 1/(D² |G_t⊥|² z²) and G_t⊥ ≠ 0.
        if !ok {
            return None;
        }
        // `fmax`: one instruction; the values are finite here (checked above, and the result
        // below), so it is `f64::max`.
        mx2 = fmax(mx2, sx);
        mz2 = fmax(mz2, sz);
    }
    finish(mx2, mz2, tan_half_fov)
}

/// What [`vertex_max`] sets up once per matrix (rows 0, 1, 3; a, b, c; g₁⊥, g₃⊥).
struct PointTerms {
    r0: DVec4,
    r1: DVec4,
    r3: DVec4,
    a: f64,
    b: f64,
    c: f64,
    g1p: DVec3,
    g3p: DVec3,
}

impl PointTerms {
    /// m_x² tan²θ and m_z² tan²θ of one point as [`vertex_max`] compares them,
    /// `w⁴ |G_t⊥|⁴ inv` and `w⁴ D² inv` with `inv = 1/(D² |G_t⊥|² z²)`, and whether the point is
    /// measurable (`w > 0`, `z > 0`, a finite `inv`, `G_t⊥ ≠ 0`; false for NaN).
    #[inline(always)]
    fn at(&self, p: DVec3) -> (f64, f64, bool) {
        let (r0, r1, r3) = (self.r0, self.r1, self.r3);
        let (g1p, g3p) = (self.g1p, self.g3p);
        let (px, py, pz) = (p.x, p.y, p.z);
        let hx = r0.x * px + r0.y * py + r0.z * pz + r0.w;
        let hy = r1.x * px + r1.y * py + r1.z * pz + r1.w;
        let hw = r3.x * px + r3.y * py + r3.z * pz + r3.w;
        let z = -pz;
        let d = hw * (hw * self.a - hy * self.b + hx * self.c);
        let d2 = d * d;
        let tx = hw * g1p.x - hy * g3p.x;
        let ty = hw * g1p.y - hy * g3p.y;
        let tz = hw * g1p.z - hy * g3p.z;
        let gtp2 = tx * tx + ty * ty + tz * tz;
        let w2 = hw * hw;
        let w4 = w2 * w2;
        let inv = 1.0 / (d2 * gtp2 * z * z);
        let ok = hw > 0.0 && z > 0.0 && inv.is_finite() && gtp2 > 0.0;
        (w4 * gtp2 * gtp2 * inv, w4 * d2 * inv, ok)
    }
}

#[inline]
fn finish(mx2: f64, mz2: f64, tan_half_fov: f64) -> Option<VertexMax> {
    let t2 = tan_half_fov * tan_half_fov;
    let (mx, mz) = ((mx2 / t2).sqrt(), (mz2 / t2).sqrt());
    if mx.is_finite() && mz.is_finite() && mx > 0.0 && mz > 0.0 {
        Some(VertexMax {
            max_mx: mx,
            max_mz: mz,
        })
    } else {
        None
    }
}
