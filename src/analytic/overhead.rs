//! The light overhead (light ⟂ view direction): Lloyd et al. 2006 §4.1–4.2.
//!
//! A directional light travels perpendicular to the view direction; the shadow map is warped by
//! a perspective "warping frustum" along the view direction whose centre of projection lies n′
//! in front of the near plane ([`crate::analytic::eta`]). Along the view direction at depth z
//! (n ≤ z ≤ f) the image beam has width w_i = 2 z tan θ / res_i, and the light beams have widths
//! w_lx (along the map's s, the eye's x) and w_lz (along t, the view direction). The errors
//! m_x = w_lx / w_i and m_z = w_lz / w_i, their maxima M_x, M_z over the frustum, and the storage
//! factor S̄ = M_x M_z (unit resolutions) are closed forms of n, f, θ and n′.
//!
//! Notation: n = near, f = far, θ = half_fov (half the vertical field of view, square image),
//! n′ = `n_prime`, res_i, res_s, res_t = [`Resolutions`]. The numeric twin of every function
//! here is [`crate::measure::twin::overhead_map`] measured by [`crate::measure::point_error`].
//!
//! ```
//! use shadow_aliasing::analytic::overhead::{max_mx, max_mz, storage_factor};
//! use shadow_aliasing::{NPrime, Resolutions, ViewFrustum};
//! let v = ViewFrustum::new(1.0, 100.0, 45f64.to_radians())?;
//! let lispsm = NPrime::finite(v.n_prime_lispsm())?;
//! let r = Resolutions::default();
//! let s = max_mx(1.0, 100.0, lispsm, r)? * max_mz(&v, lispsm, r)?;
//! assert!((s - storage_factor(&v, lispsm)?).abs() < 1e-12 * s);
//! assert!((storage_factor(&v, lispsm)? - 49.5).abs() < 1e-12); // (f/n − 1)/(2 tan θ)
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::analytic::eta::{n_prime_at_least, near_far};
use crate::error::{finite_result, fmt_num, positive, positive_result, Error, ResRatio, Result};
use crate::frustum::{NPrime, Resolutions, ViewFrustum};
use crate::numeric::sqrt_fn;
use std::hint::select_unpredictable as select;

/// n′_LSPSM = n + √f √n (without overflow of f n).
#[inline]
fn lispsm(view: &ViewFrustum) -> f64 {
    view.near() + sqrt_fn(view.near(), view.far())
}

/// Checks n ≤ z ≤ f.
#[inline]
fn depth_in(z: f64, n: f64, f: f64) -> Result<f64> {
    if z.is_finite() && z >= n && z <= f {
        Ok(z)
    } else {
        Err(depth_outside(z, n, f))
    }
}

#[cold]
#[inline(never)]
fn depth_outside(z: f64, n: f64, f: f64) -> Error {
    if !z.is_finite() {
        return crate::error::finite("z", z).unwrap_err();
    }
    Error::invalid(
        "z",
        format!(
            "must lie in [near, far] = [{}, {}] (got {})",
            fmt_num(n),
            fmt_num(f),
            fmt_num(z)
        ),
    )
}

/// The x error at depth z (Lloyd 2006 Eq 7; Lloyd 2005 Eq 8 with n = 1, f = α).
///
/// ```text
/// m_x(z, n′) = (res_i / res_s) · f (n′ + z − n) / (z (n′ + f − n))
/// m_x(z, ∞)  = (res_i / res_s) · f / z
/// ```
///
/// n = `near`, f = `far`, z = depth (eye-space distance along the view direction, same unit);
/// n′ = `n_prime`; res_i = `res.image()` pixels across the image, res_s = `res.s()` texels along
/// the map's s (the eye's x). Dimensionless. It comes from w_lx = (1/res_s) dx/ds with
/// s = x / (2 z′ tan θ′) + ½, z′ = n′ + z − n, tan θ′ = (f / f′) tan θ, f′ = n′ + f − n.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `near`, `far` (0 < near < far), `n_prime` (n′ ≥ near),
/// `z` (near ≤ z ≤ far), or
/// `res_image` and `res_s` when they scale the value, which is positive, below f64's normal range
/// (0 or a subnormal is never returned; the message estimates the value and says how to get
/// it); [`Error::Degenerate`] when the value is not finite.
#[inline]
pub fn mx(near: f64, far: f64, n_prime: NPrime, z: f64, res: Resolutions) -> Result<f64> {
    mx_scaled(
        near,
        far,
        n_prime,
        z,
        ResRatio::new(res.image(), "res_s", res.s()),
    )
}

/// [`mx`] with the map's resolution named by the caller (Lloyd 2005's `res_x` is the crate's
/// `res_s`).
#[inline]
pub(crate) fn mx_scaled(
    near: f64,
    far: f64,
    n_prime: NPrime,
    z: f64,
    res: ResRatio,
) -> Result<f64> {
    let (n, f) = near_far(near, far)?;
    let np = n_prime_at_least(n_prime, n)?.unwrap_or(f64::INFINITY);
    let z = depth_in(z, n, f)?;
    positive_result(
        "m_x",
        mx_unchecked(n, f, np, z, res.image, res.map),
        res,
        || mx_unchecked(n, f, np, z, 1.0, 1.0),
    )
}

/// [`mx`] without validation, for callers that have checked the domain themselves (the Python
/// bindings' array path): `n_prime` is n′ as an `f64`, `f64::INFINITY` for the unwarped map.
///
/// Equal, bit for bit, to [`mx`] wherever `mx` returns `Ok` (which computes its value here);
/// outside that domain the result is meaningless (it may be NaN or infinite).
#[inline(always)]
#[must_use]
pub fn mx_unchecked(near: f64, far: f64, n_prime: f64, z: f64, res_image: f64, res_s: f64) -> f64 {
    let (n, f, np) = (near, far, n_prime);
    // Both branches, then a select without a jump (`select_unpredictable`), so that a loop
    // over arrays vectorises.
    let unwarped = f / z;
    let warped = f / z * ((np + z - n) / (np + f - n));
    let shape = select(np == f64::INFINITY, unwarped, warped);
    res_image / res_s * shape
}

/// The z error at depth z (Lloyd 2006 Eq 8; Lloyd 2005 Eq 2, 3 with n = 1, f = α).
///
/// ```text
/// m_z(z, n′) = (res_i / res_t) · (f − n) / (2 tan θ) · (n′ + z − n)² / (z n′ (n′ + f − n))
/// m_z(z, ∞)  = (res_i / res_t) · (f − n) / (2 tan θ) · 1 / z
/// ```
///
/// Symbols as in [`mx`]; θ = `view.half_fov()`, res_t = `res.t()` texels along t (the view
/// direction). Dimensionless. It comes from w_lz = (1/res_t) dz/dt with
/// t(z′) = (f′ + n′)/(2 (f′ − n′)) − f′ n′ / (z′ (f′ − n′)) + ½.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `n_prime` (n′ ≥ near), `z` (near ≤ z ≤ far), or
/// `res_image` and `res_t` when they scale the value, which is positive, below f64's normal range
/// (0 or a subnormal is never returned; the message estimates the value and says how to get
/// it); [`Error::Degenerate`] when the value is not finite.
#[inline]
pub fn mz(view: &ViewFrustum, n_prime: NPrime, z: f64, res: Resolutions) -> Result<f64> {
    let (n, f, t) = (view.near(), view.far(), view.tan_half_fov());
    let np = n_prime_at_least(n_prime, n)?.unwrap_or(f64::INFINITY);
    let z = depth_in(z, n, f)?;
    positive_result(
        "m_z",
        mz_unchecked(n, f, t, np, z, res.image(), res.t()),
        ResRatio::new(res.image(), "res_t", res.t()),
        || mz_unchecked(n, f, t, np, z, 1.0, 1.0),
    )
}

/// [`mz`] without validation: n = `near`, f = `far`, tan θ = `tan_half_fov` (as
/// [`ViewFrustum::tan_half_fov`] computes it), `n_prime` as an `f64` (`f64::INFINITY` unwarped).
///
/// Equal, bit for bit, to [`mz`] wherever `mz` returns `Ok`; meaningless outside that domain.
#[inline(always)]
#[must_use]
pub fn mz_unchecked(
    near: f64,
    far: f64,
    tan_half_fov: f64,
    n_prime: f64,
    z: f64,
    res_image: f64,
    res_t: f64,
) -> f64 {
    let (n, f, np) = (near, far, n_prime);
    let zp = np + z - n;
    // (n′ + z − n)² / (z n′ (n′ + f − n)), arranged to avoid overflow at large n′; both
    // branches, then a select (see `mx_unchecked`).
    let warped = (zp / (np + f - n)) * (zp / np) / z;
    let shape = select(np == f64::INFINITY, 1.0 / z, warped);
    res_image / res_t * (f - n) / (2.0 * tan_half_fov) * shape
}

/// The maximum x error over the view frustum, at z = n (Lloyd 2006 Eq 9; Lloyd 2005 Eq 9).
///
/// ```text
/// M_x(n′) = (res_i / res_s) · f n′ / (n (n′ + f − n)),    M_x(∞) = (res_i / res_s) · f / n
/// ```
///
/// Symbols as in [`mx`]. m_x ∝ (n′ + z − n)/z = 1 + (n′ − n)/z decreases in z for n′ ≥ n, so
/// the maximum is on the near plane.
///
/// Dimensionless.
///
/// # Errors
/// As [`mx`] without `z`.
#[inline]
pub fn max_mx(near: f64, far: f64, n_prime: NPrime, res: Resolutions) -> Result<f64> {
    mx(near, far, n_prime, near, res)
}

/// The maximum z error over the view frustum (Lloyd 2006 Eq 10).
///
/// ```text
/// M_z(n′) = (res_i/res_t) (f − n)/(2 tan θ) · (n′ + f − n) / (f n′)       n′ ≤ n′_LSPSM  (far plane)
/// M_z(n′) = (res_i/res_t) (f − n)/(2 tan θ) · n′ / (n (n′ + f − n))       n′ > n′_LSPSM  (near plane)
/// M_z(∞)  = (res_i/res_t) (f − n)/(2 tan θ) · 1 / n
/// n′_LSPSM = n + √(f n)
/// ```
///
/// Symbols as in [`mz`]. (n′ + z − n)²/z is convex in z, so the maximum is on the near or far
/// plane; they are equal exactly at n′ = n′_LSPSM.
///
/// Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `n_prime` (n′ ≥ near), or
/// `res_image` and `res_t` when they scale the value, which is positive, below f64's normal range
/// (0 or a subnormal is never returned; the message estimates the value and says how to get
/// it); [`Error::Degenerate`] when the value is not finite.
#[inline]
pub fn max_mz(view: &ViewFrustum, n_prime: NPrime, res: Resolutions) -> Result<f64> {
    let (n, f, t) = (view.near(), view.far(), view.tan_half_fov());
    let np = n_prime_at_least(n_prime, n)?.unwrap_or(f64::INFINITY);
    positive_result(
        "M_z",
        max_mz_unchecked(n, f, t, np, res.image(), res.t()),
        ResRatio::new(res.image(), "res_t", res.t()),
        || max_mz_unchecked(n, f, t, np, 1.0, 1.0),
    )
}

/// [`max_mz`] without validation; arguments as [`mz_unchecked`].
///
/// Equal, bit for bit, to [`max_mz`] wherever `max_mz` returns `Ok` and f·n is a normal `f64`
/// (n′_LSPSM = n + √(f n) is then taken as one square root, as `ViewFrustum::n_prime_lispsm`
/// does; a subnormal or overflowing product is left to the checked form); meaningless outside.
#[inline(always)]
#[must_use]
pub fn max_mz_unchecked(
    near: f64,
    far: f64,
    tan_half_fov: f64,
    n_prime: f64,
    res_image: f64,
    res_t: f64,
) -> f64 {
    let (n, f, np) = (near, far, n_prime);
    // All three branches, then selects (see `mx_unchecked`).
    let (unwarped, far_plane, near_plane) = (1.0 / n, (np + f - n) / f / np, np / (np + f - n) / n);
    let below = np <= n + (f * n).sqrt();
    let shape = select(
        np == f64::INFINITY,
        unwarped,
        select(below, far_plane, near_plane),
    );
    res_image / res_t * (f - n) / (2.0 * tan_half_fov) * shape
}

/// The storage factor S̄ = M_x M_z with unit resolutions (Lloyd 2006 Eq 12): how many times
/// more texels than image pixels a shadow map needs so that no perspective aliasing remains.
///
/// ```text
/// S̄ = (f/n − 1) / (2 tan θ)                                   n ≤ n′ ≤ n′_LSPSM
/// S̄ = (f/n − 1) / (2 tan θ) · n′² f / (n (n′ + f − n)²)       n′ > n′_LSPSM
/// S̄ = (f/n − 1) / (2 tan θ) · f / n                           n′ = ∞
/// ```
///
/// n = near, f = far, θ = half_fov, n′ = `n_prime`, n′_LSPSM = n + √(f n). Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `n_prime` (n′ ≥ near).
#[inline]
pub fn storage_factor(view: &ViewFrustum, n_prime: NPrime) -> Result<f64> {
    let (n, f) = (view.near(), view.far());
    let np = n_prime_at_least(n_prime, n)?;
    finite_result(
        "storage factor",
        storage_factor_unchecked(n, f, view.tan_half_fov(), np.unwrap_or(f64::INFINITY)),
    )
}

/// [`storage_factor`] without validation; arguments as [`mz_unchecked`].
///
/// Equal, bit for bit, to [`storage_factor`] wherever it returns `Ok` and f·n is a normal `f64`
/// (as [`max_mz_unchecked`]); meaningless outside it.
#[inline(always)]
#[must_use]
pub fn storage_factor_unchecked(near: f64, far: f64, tan_half_fov: f64, n_prime: f64) -> f64 {
    let (n, f, np) = (near, far, n_prime);
    let base = (f / n - 1.0) / (2.0 * tan_half_fov);
    // All three branches, then selects (see `mx_unchecked`).
    let r = np / (np + f - n);
    let above = r * r * f / n;
    let below = np <= n + (f * n).sqrt();
    let factor = select(np == f64::INFINITY, f / n, select(below, 1.0, above));
    base * factor
}

/// A shadow-map resolution pair, texels along s (the eye's x) and t (the view direction).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapResolution {
    /// Texels along s.
    pub res_s: f64,
    /// Texels along t.
    pub res_t: f64,
}

/// The critical resolution res*_s × res*_t: the smallest shadow map with M_x = M_z = 1
/// (Lloyd 2006 §4.2).
///
/// ```text
/// res*_s = res_i · M_x(n′)|res=1,   res*_t = res_i · M_z(n′)|res=1,   res*_s res*_t = res_i² S̄
/// ```
///
/// res_i = `res_image` pixels across the (square) image; other symbols as in [`max_mx`],
/// [`max_mz`]. Texels.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `res_image` (finite, > 0) or `n_prime` (n′ ≥ near).
pub fn critical_resolution(
    view: &ViewFrustum,
    n_prime: NPrime,
    res_image: f64,
) -> Result<MapResolution> {
    let ri = positive("res_image", res_image)?;
    let unit = Resolutions::default();
    // M_x of Eq 9 on the view's depths, which the type has validated: only n′ ≥ n is checked.
    let n = view.near();
    let np = n_prime_at_least(n_prime, n)?;
    let max_mx = finite_result(
        "m_x",
        mx_unchecked(
            n,
            view.far(),
            np.unwrap_or(f64::INFINITY),
            n,
            unit.image(),
            unit.s(),
        ),
    )?;
    Ok(MapResolution {
        res_s: finite_result("res_s", ri * max_mx)?,
        res_t: finite_result("res_t", ri * max_mz(view, n_prime, unit)?)?,
    })
}

/// The resolution for a texel budget S₀ that splits the error equally between x and z
/// (Lloyd 2006 Eq 13, 14).
///
/// ```text
/// res_s = √(S₀ · res*_s / res*_t),   res_t = √(S₀ · res*_t / res*_s)
/// ```
///
/// S₀ = `budget` texels (res_s res_t = S₀); res*_s / res*_t = M_x / M_z from
/// [`critical_resolution`], which does not depend on the image resolution, so none is needed.
/// The resulting maximum error in both directions is res_i √(S̄ / S₀) ([`budget_error`]).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `budget` (finite, > 0) or `n_prime` (n′ ≥ near).
pub fn budget_resolution(
    view: &ViewFrustum,
    n_prime: NPrime,
    budget: f64,
) -> Result<MapResolution> {
    let s0 = positive("budget", budget)?;
    let c = critical_resolution(view, n_prime, 1.0)?;
    // res*_s / res*_t = M_x / M_z of Eq 9, 10 as one fraction num/den (within a few ulps of
    // c.res_s / c.res_t), so that res_s = √(S₀ num/den) and res_t = √(S₀ den/num) are two
    // independent divisions and square roots instead of a chain of five divisions (M_x, M_z
    // above still run, beside it, and give the errors):
    //   2 tan θ f² n′² / (n (f − n) (n′ + f − n)²)   n′ ≤ n′_LSPSM,   2 tan θ f / (f − n)   else.
    let (n, f) = (view.near(), view.far());
    let t2 = 2.0 * view.tan_half_fov();
    let (num, den) = match n_prime.as_finite() {
        Some(np) if np <= lispsm(view) => {
            let (a, fp) = (np + f - n, f * np);
            (fp * fp * t2, n * (f - n) * (a * a))
        }
        _ => (t2 * f, f - n),
    };
    let (res_s, res_t) = ((s0 * num / den).sqrt(), (s0 * den / num).sqrt());
    if res_s.is_finite() && res_t.is_finite() && res_s > 0.0 && res_t > 0.0 {
        return Ok(MapResolution { res_s, res_t });
    }
    // Overflow or underflow of the one fraction: from M_x, M_z themselves.
    budget_from_critical(s0, &c)
}

/// The plain form of [`budget_resolution`]: res_s = √(S₀ r), res_t = √(S₀/r) with r = res*_s /
/// res*_t the ratio of the critical resolutions (Eq 9, 10). The fast path above is its fallback's
/// reference too (tested against it within a few ulps, `budget_fast_path_is_the_plain_form`).
fn budget_from_critical(s0: f64, c: &MapResolution) -> Result<MapResolution> {
    let ratio = c.res_s / c.res_t;
    Ok(MapResolution {
        res_s: finite_result("res_s", (s0 * ratio).sqrt())?,
        res_t: finite_result("res_t", (s0 / ratio).sqrt())?,
    })
}

/// The maximum error M_x = M_z of the budget resolution of [`budget_resolution`]:
/// res_i √(S̄ / S₀) (Lloyd 2006 §4.2, from Eq 12–14). Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `res_image`, `budget` (finite, > 0) or `n_prime`.
pub fn budget_error(
    view: &ViewFrustum,
    n_prime: NPrime,
    budget: f64,
    res_image: f64,
) -> Result<f64> {
    let s0 = positive("budget", budget)?;
    let ri = positive("res_image", res_image)?;
    finite_result(
        "budget error",
        ri * (storage_factor(view, n_prime)? / s0).sqrt(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// The one-fraction path of `budget_resolution` is its plain form from the critical
        /// resolutions, within 8 ulps, over n, f/n, θ, n′ (below and above n′_LSPSM, and ∞) and
        /// the budget.
        #[test]
        fn budget_fast_path_is_the_plain_form(
            ln_n in -20.0f64..20.0,
            ln_alpha in 1e-3f64..25.0,
            theta in 0.01f64..1.55,
            np_scale in -6.0f64..6.0,
            unwarped in any::<bool>(),
            ln_budget in 0.0f64..40.0,
        ) {
            let n = ln_n.exp();
            let view = ViewFrustum::new(n, n * ln_alpha.exp(), theta).unwrap();
            let np = if unwarped {
                NPrime::UNWARPED
            } else {
                NPrime::finite(view.n_prime_lispsm() * np_scale.exp()).unwrap()
            };
            let s0 = ln_budget.exp();
            let (Ok(fast), Ok(c)) = (
                budget_resolution(&view, np, s0),
                critical_resolution(&view, np, 1.0),
            ) else {
                return Ok(());
            };
            let plain = budget_from_critical(s0, &c).unwrap();
            for (a, b) in [(fast.res_s, plain.res_s), (fast.res_t, plain.res_t)] {
                prop_assert!((a - b).abs() <= 8.0 * f64::EPSILON * b, "{a} vs {b}");
            }
        }
    }

    /// Hand values at n = 1, f = 100, θ = 45° (tan θ = 1), n′ = 11 (LiSPSM).
    #[test]
    fn hand_values() {
        let v = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_4).unwrap();
        let r = Resolutions::default();
        let l = NPrime::finite(11.0).unwrap();
        // m_x(1) = 100·11/110 = 10; m_x(100) = 100·110/(100·110) = 1.
        assert!((mx(1.0, 100.0, l, 1.0, r).unwrap() - 10.0).abs() < 1e-13);
        assert!((mx(1.0, 100.0, l, 100.0, r).unwrap() - 1.0).abs() < 1e-13);
        // m_z(1) = 99/2 · 121/(11·110) = 4.95; m_z(100) = 99/2 · 110²/(100·11·110) = 4.95.
        let t = (std::f64::consts::FRAC_PI_4).tan();
        assert!((mz(&v, l, 1.0, r).unwrap() - 4.95 / t).abs() < 1e-12);
        assert!((mz(&v, l, 100.0, r).unwrap() - 4.95 / t).abs() < 1e-12);
        assert!((max_mz(&v, l, r).unwrap() - 4.95 / t).abs() < 1e-12);
        // Unwarped: S̄ = 99/2 · 100 = 4950.
        assert!((storage_factor(&v, NPrime::UNWARPED).unwrap() - 4950.0 / t).abs() < 1e-9);
        // Budget: S₀ = 4 S̄ halves the error.
        let s = storage_factor(&v, l).unwrap();
        let b = budget_resolution(&v, l, 4.0 * s).unwrap();
        assert!((b.res_s * b.res_t - 4.0 * s).abs() < 1e-9 * s);
        assert!((budget_error(&v, l, 4.0 * s, 1.0).unwrap() - 0.5).abs() < 1e-14);
        assert!(mx(1.0, 100.0, l, 0.5, r).is_err());
        assert!(mx(1.0, 100.0, NPrime::finite(0.5).unwrap(), 2.0, r).is_err());
    }

    /// The `*_unchecked` twins give the checked forms' values bit for bit over their domain:
    /// both warp branches (n′ below and above n′_LSPSM, n′ exactly at it), the unwarped map,
    /// z on the near and far planes and inside, and resolutions other than one.
    #[test]
    fn unchecked_twins_agree() {
        let mut cases = 0;
        for &(n, f) in &[(1.0, 100.0), (0.1, 0.3), (2.5, 4e5), (1e-3, 1e6)] {
            for &th in &[0.01, 0.5, std::f64::consts::FRAC_PI_4, 1.5] {
                let v = ViewFrustum::new(n, f, th).unwrap();
                let t = v.tan_half_fov();
                let l = v.n_prime_lispsm();
                for np in [n, 0.5 * (n + l), l, 2.0 * l, 1e3 * f, f64::INFINITY] {
                    let npv = NPrime::new(np).unwrap();
                    for &(ri, rt) in &[(1.0, 1.0), (1920.0, 700.0)] {
                        let r = Resolutions::new(ri, rt, rt / 3.0).unwrap();
                        for z in [n, 0.3 * n + 0.7 * f, f] {
                            let a = mx(n, f, npv, z, r).unwrap();
                            assert_eq!(a.to_bits(), mx_unchecked(n, f, np, z, ri, rt).to_bits());
                            let b = mz(&v, npv, z, r).unwrap();
                            let bu = mz_unchecked(n, f, t, np, z, ri, rt / 3.0);
                            assert_eq!(b.to_bits(), bu.to_bits());
                            cases += 1;
                        }
                        let c = max_mz(&v, npv, r).unwrap();
                        let cu = max_mz_unchecked(n, f, t, np, ri, rt / 3.0);
                        assert_eq!(c.to_bits(), cu.to_bits());
                    }
                    let s = storage_factor(&v, npv).unwrap();
                    assert_eq!(s.to_bits(), storage_factor_unchecked(n, f, t, np).to_bits());
                }
            }
        }
        assert_eq!(cases, 4 * 4 * 6 * 2 * 3);
        // S̄ of LiSPSM by hand: (f/n − 1)/(2 tan θ) = 99/2 at f/n = 100, θ = 45°.
        let t = std::f64::consts::FRAC_PI_4.tan();
        assert!((storage_factor_unchecked(1.0, 100.0, t, 11.0) - 49.5 / t).abs() < 1e-12);
    }
}
