//! The rendered Jacobian from the read-back texel coordinates (exact derivatives, not finite
//! differences), the perspective error of a Jacobian (the surface's projection factor divided
//! out), and Lloyd 2006's overhead closed forms (Eq 7–10) that the level set-up is held to.
//!
//! # Exact derivatives from three samples
//!
//! On one planar surface the texel coordinates are a 2D projective map (a homography) of the
//! pixel coordinates: the surface point seen through a pixel is a projective function of the
//! pixel, and the shadow map is projective in the point. Along a pixel row (or column) both
//! texel coordinates are therefore Möbius functions `f(u) = (A u + B)/(c u + 1)` with a common
//! denominator, and three samples determine the derivative exactly. With `a = f(1) − f(0)` and
//! `b = f(0) − f(−1)`, `a = f′(0)/(1 + c)` and `b = f′(0)/(1 − c)`, so
//!
//! ```text
//! f′(0) = (a + b) · 2|a||b| / (|a| + |b|)²       (centred: the harmonic mean of a and b)
//! f′(0) = a (|a| + |b|) / (2|b|)                  (one-sided, a = f(1) − f(0), b = f(2) − f(1))
//! ```
//!
//! (for the one-sided form `a = f′(0)/(1 + c)`, `b = f′(0)/((1 + c)(1 + 2c))`). Both are exact for
//! any pixel size, so the rendered Jacobian does not depend on the screen resolution: where the
//! ground approaches the horizon a central difference is off by `(Δ/u)²` at `u` pixels from the
//! horizon (8.9 % at 320 × 240 in a thin-caster scene before), these are off by the GPU's `f32`
//! rounding only. A pixel is compared only when both neighbours along each axis, or two on one
//! side, lie on its surface and in its map; the others are counted as not compared.

use crate::schemes::View;
use glam::{DMat2, DMat4, DVec2, DVec3};

/// The derivative at the middle of three equally spaced samples of a Möbius function
/// (`fm = f(−1)`, `f0 = f(0)`, `fp = f(1)`), exact (module docs). Where the two differences are
/// not parallel and alike in direction (rounding, a derivative near zero) the central
/// difference.
pub fn centred(fm: DVec2, f0: DVec2, fp: DVec2) -> DVec2 {
    let (a, b) = (fp - f0, f0 - fm);
    let (la, lb) = (a.length(), b.length());
    if a.dot(b) <= 0.0 || la + lb == 0.0 {
        return (a + b) * 0.5;
    }
    (a + b) * (2.0 * la * lb / ((la + lb) * (la + lb)))
}

/// The derivative at `f0` from `f1 = f(±1)`, `f2 = f(±2)` on one side, exact for a Möbius
/// function (module docs), signed for the step `+1`: for samples on the negative side pass
/// `f(−1)`, `f(−2)` and the result is still the derivative along `+u`.
pub fn one_sided(f0: DVec2, f1: DVec2, f2: DVec2, forward: bool) -> DVec2 {
    let (a, b) = if forward {
        (f1 - f0, f2 - f1)
    } else {
        (f0 - f1, f1 - f2)
    };
    let (la, lb) = (a.length(), b.length());
    if a.dot(b) <= 0.0 || lb == 0.0 {
        return a;
    }
    a * ((la + lb) / (2.0 * lb))
}

/// The perspective error at the eye-space point `p` of a surface with unit eye-space normal `n`,
/// from `j`, the Jacobian texel ← pixel there (texels per pixel; column 0 along the pixel
/// column index, column 1 along the row index from the top): `(m_x, m_z, shear)`, m_x and m_z in
/// pixels per texel, the definitions of `shadow_aliasing::measure` (Lloyd 2006 §4.4): the light
/// beam widths `w_ls = |∇_Π t| / |det A|`, `w_lt = 1/|∇_Π t|` in the plane Π ⊥ L (A: the texel
/// coordinates' Jacobian on Π) over the image beam width `w_i = 2 z tan θ / H` at depth
/// `z = −p.z`; `shear` the texel's largest extent on Π, σ_max(A⁻¹) = 1/σ_min(A), over the larger
/// of the two widths (≥ 1; 1 for a texel whose edges are perpendicular: w_ls is the s step's
/// length and w_lt the t lines' spacing, so a t step off perpendicular is longer than w_lt).
///
/// The surface's projection factor is divided out exactly: with `F` the exact Jacobian pixel ←
/// surface (the camera's, in `f64`), `G = J F` is texel ← surface, and `A = G P⁻¹` with `P` the
/// projection of the surface onto Π along the light (texels are constant along light rays).
/// `None` where the surface is edge-on to the camera or the light (F or P singular) or J is.
pub fn perspective_error(
    view: &View,
    width: u32,
    height: u32,
    j: DMat2,
    p: DVec3,
    n: DVec3,
) -> Option<(f64, f64, f64)> {
    let f = pixel_jacobian(&view.proj, width, height, p, n)?;
    let (e1, e2) = n.any_orthonormal_pair();
    let l = view.light_eye;
    let (b1, b2) = l.any_orthonormal_pair();
    let proj = DMat2::from_cols(
        DVec2::new(b1.dot(e1), b2.dot(e1)),
        DVec2::new(b1.dot(e2), b2.dot(e2)),
    );
    if proj.determinant().abs() < 1e-12 {
        return None;
    }
    let a = j * f * proj.inverse();
    let grad_t = a.row(1);
    let det = a.determinant().abs();
    let (gt, z) = (grad_t.length(), -p.z);
    if !(det > 0.0 && gt > 0.0 && z > 0.0) {
        return None;
    }
    let wi = 2.0 * z * view.frustum.tan_half_fov() / f64::from(height);
    let (mx, mz) = (gt / det / wi, 1.0 / gt / wi);
    (mx.is_finite() && mz.is_finite()).then_some((mx, mz, texel_shear(a)))
}

/// A texel's shear on Π from `a`, the texel coordinates' Jacobian there (row 0 ∇s, row 1 ∇t):
/// its largest extent σ_max(A⁻¹) = 1/σ_min(A) over the larger of Lloyd's widths,
/// `w_ls = |∇t|/|det A|` (the s step's length) and `w_lt = 1/|∇t|` (the t lines' spacing); at
/// least 1, +∞ for a singular `a`.
pub fn texel_shear(a: DMat2) -> f64 {
    let det = a.determinant().abs();
    let gt = a.row(1).length();
    // 1/σ_min(A) = σ_max(A)/|det A|, σ_max² from ‖A‖_F² = σ₁² + σ₂² and |det A| = σ₁ σ₂.
    let f2 = a.x_axis.length_squared() + a.y_axis.length_squared();
    let s_max = (0.5 * (f2 + (f2 * f2 - 4.0 * det * det).max(0.0).sqrt())).sqrt();
    let shear = (s_max / det) / (gt / det).max(1.0 / gt);
    if shear.is_finite() {
        shear.max(1.0)
    } else {
        f64::INFINITY
    }
}

/// `F = ∂(u, v)/∂(e₁, e₂)`: pixels per unit length on the plane through `p` with normal `n`, in
/// the basis `n.any_orthonormal_pair()` (exact gradients of the projective camera).
fn pixel_jacobian(proj: &DMat4, width: u32, height: u32, p: DVec3, n: DVec3) -> Option<DMat2> {
    let h = *proj * p.extend(1.0);
    if h.w <= 0.0 {
        return None;
    }
    let r3 = proj.row(3).truncate();
    let gx = (proj.row(0).truncate() - r3 * (h.x / h.w)) / h.w * (0.5 * f64::from(width));
    let gy = (proj.row(1).truncate() - r3 * (h.y / h.w)) / h.w * (-0.5 * f64::from(height));
    let (e1, e2) = n.any_orthonormal_pair();
    let f = DMat2::from_cols(
        DVec2::new(gx.dot(e1), gy.dot(e1)),
        DVec2::new(gx.dot(e2), gy.dot(e2)),
    );
    (f.determinant().abs() > 1e-300).then_some(f)
}

/// Lloyd, Tuft, Yoon, Manocha 2006, *Warping and Partitioning for Low Error Shadow Maps*, the
/// overhead light (light ⊥ view direction, light-space z along the view), written from the paper
/// (/work/shared/papers/lloyd2006-warping-and-partitioning.txt), not from the crate's closed
/// forms. The frustum (or slice) spans eye depths `n..f`, `n′` is the warp parameter (∞:
/// orthographic), θ the vertical half field of view, `res_i` the pixels across the image in the
/// direction measured (`W` for x, whose half-angle θ_x has `W/(2 tan θ_x) = H/(2 tan θ)`: square
/// pixels; `H` for z), `res_s`, `res_t` the map's texels.
pub mod lloyd2006 {
    /// Eq 7: `m_x(z, n′) = (res_i/res_s) · f (n′ + z − n) / (z (n′ + f − n))`; its limit `f/z`
    /// for n′ = ∞.
    pub fn m_x(z: f64, n: f64, f: f64, n_prime: f64, res_i: f64, res_s: f64) -> f64 {
        let shape = if n_prime.is_infinite() {
            f / z
        } else {
            f * (n_prime + z - n) / (z * (n_prime + f - n))
        };
        res_i / res_s * shape
    }

    /// Eq 8: `m_z(z, n′) = (res_i/res_t) · (f − n)/(2 tan θ) · (n′ + z − n)² / (z n′ (n′ + f − n))`;
    /// its limit `1/z` for the last factor when n′ = ∞.
    pub fn m_z(
        z: f64,
        n: f64,
        f: f64,
        n_prime: f64,
        tan_theta: f64,
        res_i: f64,
        res_t: f64,
    ) -> f64 {
        let shape = if n_prime.is_infinite() {
            1.0 / z
        } else {
            (n_prime + z - n).powi(2) / (z * n_prime * (n_prime + f - n))
        };
        res_i / res_t * (f - n) / (2.0 * tan_theta) * shape
    }

    /// n′_LSPSM = n + √(f n) (the paper's §4.2): where Eq 10 switches.
    pub fn n_prime_lspsm(n: f64, f: f64) -> f64 {
        n + (f * n).sqrt()
    }

    /// Eq 9 and 10 as the paper states them: "the maximum error for x always occurs at z = n;
    /// for z, the maximum error is at z = n for n′ > n′_LSPSM and at z = f for n′ ≤ n′_LSPSM":
    /// `(M_x, M_z) = (m_x(n), m_z(f or n))`. (The transcription's printed Eq 10 carries a factor
    /// n that is 1 in the paper's normalisation; Eq 8 at those depths has none.)
    pub fn maxima(
        n: f64,
        f: f64,
        n_prime: f64,
        tan_theta: f64,
        (res_x, res_z): (f64, f64),
        res: f64,
    ) -> (f64, f64) {
        let mx = m_x(n, n, f, n_prime, res_x, res);
        let zz = if n_prime > n_prime_lspsm(n, f) { n } else { f };
        (mx, m_z(zz, n, f, n_prime, tan_theta, res_z, res))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The three-sample formulas give the exact derivative of a Möbius function whatever the
    /// step, where the central difference is off by (Δ c)² relatively.
    #[test]
    fn three_samples_of_a_moebius_function_give_its_derivative() {
        // f(u) = (A u + B)/(c u + 1): f'(u) = (A − B c)/(c u + 1)².
        let (a, b, c) = (DVec2::new(3.0, -2.0), DVec2::new(0.5, 7.0), 0.21);
        let f = |u: f64| (a * u + b) / (c * u + 1.0);
        let exact = |u: f64| (a - b * c) / (c * u + 1.0).powi(2);
        for (u, step) in [(0.0, 1.0), (0.7, 0.5), (-1.3, 0.9)] {
            let d = centred(f(u - step), f(u), f(u + step)) / step;
            assert!(
                (d - exact(u)).length() < 1e-12 * exact(u).length(),
                "{d} {}",
                exact(u)
            );
            let fw = one_sided(f(u), f(u + step), f(u + 2.0 * step), true) / step;
            assert!((fw - exact(u)).length() < 1e-12 * exact(u).length(), "{fw}");
            let bw = one_sided(f(u), f(u - step), f(u - 2.0 * step), false) / step;
            assert!((bw - exact(u)).length() < 1e-12 * exact(u).length(), "{bw}");
            let central = (f(u + step) - f(u - step)) / (2.0 * step);
            assert!((central - exact(u)).length() > 1e-3 * exact(u).length());
        }
    }

    /// A texel with edges a = (2, 0) (the s step) and b = (3, 1) (the t step) on Π: Lloyd's widths
    /// |a| = 2 and the t lines' spacing det/|a| = 1, its largest extent the larger singular
    /// value of [a b] (by hand: ‖·‖_F² = 14, det = 2, σ² = 7 ± √45); a square texel has no shear.
    #[test]
    fn texel_shear_by_hand() {
        let edges = DMat2::from_cols(DVec2::new(2.0, 0.0), DVec2::new(3.0, 1.0));
        let sigma = (7.0 + 45f64.sqrt()).sqrt();
        let got = texel_shear(edges.inverse());
        assert!((got - sigma / 2.0).abs() < 1e-12, "{got} {}", sigma / 2.0);
        assert_eq!(
            texel_shear(DMat2::from_diagonal(DVec2::new(0.5, 0.25))),
            1.0
        );
    }

    /// Eq 9–10 are Eq 7–8 at their maximising depths: m_x(z) decreases for n′ > n, and m_z is
    /// largest at f for LiSPSM's n′ (where m_z(n) = m_z(f)) and at n for a larger n′.
    #[test]
    fn lloyd_maxima_are_the_largest_values_over_the_frustum() {
        let (n, f, t) = (0.5, 120.0, 30f64.to_radians().tan());
        for np in [lloyd2006::n_prime_lspsm(n, f), 3.0 * n, 40.0, f64::INFINITY] {
            let (mx, mz) = lloyd2006::maxima(n, f, np, t, (640.0, 480.0), 1024.0);
            let mut big = (0.0f64, 0.0f64);
            for i in 0..=1000 {
                let z = n * (f / n).powf(f64::from(i) / 1000.0);
                big.0 = big.0.max(lloyd2006::m_x(z, n, f, np, 640.0, 1024.0));
                big.1 = big.1.max(lloyd2006::m_z(z, n, f, np, t, 480.0, 1024.0));
            }
            assert!((big.0 / mx - 1.0).abs() < 1e-12, "{np}: {big:?} {mx}");
            assert!((big.1 / mz - 1.0).abs() < 1e-12, "{np}: {big:?} {mz}");
        }
        // LiSPSM equalises m_z at both ends.
        let np = lloyd2006::n_prime_lspsm(n, f);
        let (a, b) = (
            lloyd2006::m_z(n, n, f, np, t, 1.0, 1.0),
            lloyd2006::m_z(f, n, f, np, t, 1.0, 1.0),
        );
        assert!((a / b - 1.0).abs() < 1e-12);
    }
}
