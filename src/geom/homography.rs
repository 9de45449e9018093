//! The four-point homography from a convex quadrilateral onto the unit square (Heckbert 1989),
//! as the trapezoidal map's N_T uses it (Martin & Tan §6).

use crate::error::{fmt_num, Error, Result};
use glam::{DMat3, DVec2, DVec3};
use nalgebra::{Matrix2, Vector2};

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
/// # use shadow_aliasing::geom::homography::quad_to_square;
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
