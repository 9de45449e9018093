//! Subdivided shadow maps: Lloyd, Yoon, Tuft & Manocha 2005 (UNC TR05-024), §3–4.
//!
//! The 2005 report works in a canonical 2D frustum with the near plane at 1 and the far plane at
//! α = f/n, the light perpendicular to the view direction, and a perspective warp whose near
//! plane sits a distance n from its centre of projection (n is Lloyd 2006's n′ / near; PSM n = 1,
//! LiSPSM n_opt = 1 + √α, unwarped n = ∞). The shadow map's s runs along the warp (the view
//! direction) and t along x, the other way round from Lloyd 2006 and the crate:
//!
//! | Lloyd 2005 | meaning | crate |
//! |---|---|---|
//! | α | f/n | `alpha` (= `far/near`) |
//! | n | warp near distance, near = 1 | `n_warp` (n′/near) |
//! | ξ | normalised warp parameter | `eta` (= Lloyd 2006's η) |
//! | r_p | image resolution | `res_image` |
//! | r_s | texels along the warp (z) direction | `res_s`, as the eval contract names Lloyd 2005's r_s (the crate's res_t elsewhere) |
//! | r_t | texels along x | `res_x` (the crate's res_s elsewhere) |
//!
//! Every quantity here is scale-free, so a frustum [n, f] behaves as [1, α]; the tests check
//! each function against Lloyd 2006's general-n forms ([`crate::analytic::overhead`]) and
//! against the measured warp ([`crate::measure::twin`]).
//!
//! ```
//! use shadow_aliasing::analytic::subdivided::{distribution_g, n_from_xi, xi_from_n};
//! use shadow_aliasing::NPrime;
//! let alpha = 100.0;
//! let n = n_from_xi(alpha, 0.0)?; // LiSPSM: 1 + √α
//! assert_eq!(n, NPrime::finite(11.0)?);
//! // g is 1/√α on both planes there.
//! assert!((distribution_g(alpha, n, 1.0)? - 0.1).abs() < 1e-15);
//! assert!((distribution_g(alpha, n, alpha)? - 0.1).abs() < 1e-15);
//! assert_eq!(xi_from_n(alpha, n)?, 0.0);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::analytic::eta::{eta_from_n_prime, n_prime_from_eta};
use crate::analytic::partition::{z_splits, SplitScheme, Splits};
use crate::error::{
    finite_result, fmt_num, in_closed, in_open, positive, positive_result, Error, ResRatio, Result,
};
use crate::frustum::NPrime;

/// Validates α > 1, finite.
#[inline]
fn alpha_ok(alpha: f64) -> Result<f64> {
    let a = positive("alpha", alpha)?;
    if a <= 1.0 {
        return Err(alpha_not_above_one(a));
    }
    Ok(a)
}

#[cold]
#[inline(never)]
fn alpha_not_above_one(a: f64) -> Error {
    Error::invalid(
        "alpha",
        format!("must be greater than 1 (got {})", fmt_num(a)),
    )
}

/// Validates the warp distance n ≥ 1 (the warp frustum must contain the view frustum).
#[inline]
fn n_warp_ok(n_warp: NPrime) -> Result<Option<f64>> {
    match n_warp.as_finite() {
        None => Ok(None),
        Some(v) => {
            if v < 1.0 {
                Err(Error::invalid(
                    "n_warp",
                    format!(
                        "must be at least 1, the normalised near plane (got {})",
                        fmt_num(v)
                    ),
                ))
            } else {
                Ok(Some(v))
            }
        }
    }
}

/// Validates 1 ≤ z ≤ α.
#[inline]
fn z_ok(z: f64, alpha: f64) -> Result<f64> {
    let z = crate::error::finite("z", z)?;
    if !(1.0..=alpha).contains(&z) {
        return Err(z_outside(z, alpha));
    }
    Ok(z)
}

#[cold]
#[inline(never)]
fn z_outside(z: f64, alpha: f64) -> Error {
    Error::invalid(
        "z",
        format!(
            "must lie in [1, alpha] = [1, {}] (got {})",
            fmt_num(alpha),
            fmt_num(z)
        ),
    )
}

#[inline]
fn tan_ok(half_fov: f64) -> Result<f64> {
    Ok(in_open("half_fov", half_fov, 0.0, std::f64::consts::FRAC_PI_2)?.tan())
}

/// LiSPSM's optimal warp distance with near = 1: n_opt = 1 + √α (Lloyd 2005 §3.1).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha` unless α > 1, finite.
#[inline]
pub fn n_opt(alpha: f64) -> Result<f64> {
    Ok(1.0 + alpha_ok(alpha)?.sqrt())
}

/// The least maximum of g over the frustum, g₀ = min_n max_z g = 1/√α, reached at n = n_opt
/// (Lloyd 2005 §3.1).
///
/// Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha` unless α > 1, finite.
#[inline]
pub fn g_min(alpha: f64) -> Result<f64> {
    Ok(1.0 / alpha_ok(alpha)?.sqrt())
}

/// The error distribution function g (Lloyd 2005 Eq 3).
///
/// ```text
/// g(z) = (z − 1 + n)² / (z n (n + α − 1)),     g(z) = 1/z for n = ∞
/// ```
///
/// α = `alpha` = f/n of the view frustum (> 1); n = `n_warp` ≥ 1, the warp near distance with
/// the view near plane at 1; z ∈ [1, α] the normalised depth. Dimensionless. g is 1 at z = α for
/// n = 1 (PSM) and at z = 1 for n = ∞; its least maximum 1/√α is at n = 1 + √α.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha`, `n_warp` (≥ 1) or `z` (∈ [1, α]).
#[inline]
pub fn distribution_g(alpha: f64, n_warp: NPrime, z: f64) -> Result<f64> {
    let a = alpha_ok(alpha)?;
    let n = n_warp_ok(n_warp)?;
    let z = z_ok(z, a)?;
    finite_result(
        "g",
        distribution_g_unchecked(a, n.unwrap_or(f64::INFINITY), z),
    )
}

/// [`distribution_g`] without validation, for callers that have checked the domain (the Python
/// bindings' array path): `n_warp` as an `f64`, `f64::INFINITY` for the unwarped map. Equal, bit
/// for bit, to [`distribution_g`] wherever it returns `Ok`; meaningless outside that domain.
#[inline(always)]
#[must_use]
pub fn distribution_g_unchecked(alpha: f64, n_warp: f64, z: f64) -> f64 {
    let (a, n) = (alpha, n_warp);
    // Both branches, then a select without a jump (`select_unpredictable`), so that a loop
    // over arrays vectorises.
    let zp = z - 1.0 + n;
    let warped = (zp / (n + a - 1.0)) * (zp / n) / z;
    std::hint::select_unpredictable(n == f64::INFINITY, 1.0 / z, warped)
}

/// The perspective aliasing error m along the warp direction (Lloyd 2005 Eq 2).
///
/// ```text
/// m = (r_p / r_s) · (α − 1) / (2 tan θ) · g(z)
/// ```
///
/// r_p = `res_image` (pixels across the image), r_s = `res_s` (texels along the warp, the
/// crate's res_t), θ = `half_fov` (radians), g from [`distribution_g`]. Dimensionless. Equal to
/// Lloyd 2006's m_z (Eq 8) at depth z·near for n′ = n·near.
///
/// # Errors
/// As [`distribution_g`], and `half_fov` (∈ (0, π/2)), `res_image`, `res_s` (> 0), and
/// `res_image` and `res_s` when they
/// scale the value, which is positive, below f64's normal range (0 or a subnormal is never
/// returned; the message estimates the value and says how to get it).
pub fn error_m(
    alpha: f64,
    half_fov: f64,
    n_warp: NPrime,
    z: f64,
    res_image: f64,
    res_s: f64,
) -> Result<f64> {
    let t = tan_ok(half_fov)?;
    let rp = positive("res_image", res_image)?;
    let rs = positive("res_s", res_s)?;
    let g = distribution_g(alpha, n_warp, z)?;
    let m = |ratio: f64| ratio * (alpha - 1.0) / (2.0 * t) * g;
    positive_result("m", m(rp / rs), warp_res(rp, rs), || m(1.0))
}

/// The resolutions of Lloyd 2005's error along the warp: `res_image / res_s`.
#[inline]
fn warp_res(res_image: f64, res_s: f64) -> ResRatio {
    ResRatio::new(res_image, "res_s", res_s)
}

/// ξ from the warp distance n (Lloyd 2005 §3.2).
///
/// ```text
/// ξ = (g₀ − g(n, 1)) / (1 − g₀) = (√α − n + 1) / (n + α − 1)   n ≥ n_opt
/// ξ = (g(n, α) − g₀) / (1 − g₀) = (√α − n + 1) / (n √α)        n < n_opt
/// ξ = −1 for n = ∞;   g₀ = 1/√α, n_opt = 1 + √α
/// ```
///
/// α = `alpha` (> 1), n = `n_warp` (≥ 1). ξ ∈ [−1, 1] interpolates the maximum of g linearly:
/// from 1 on the near plane (ξ = −1) to g₀ (ξ = 0) and back to 1 on the far plane (ξ = 1).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha` or `n_warp` (≥ 1).
pub fn xi_from_n(alpha: f64, n_warp: NPrime) -> Result<f64> {
    let a = alpha_ok(alpha)?;
    n_warp_ok(n_warp)?;
    // The same map as Lloyd 2006's η(n′) with near = 1 (one implementation, in `warp`).
    eta_from_n_prime(1.0, a, n_warp)
}

/// The warp distance n from ξ (Lloyd 2005 Eq 4).
///
/// ```text
/// n = (√α + 1 − ξ (α − 1)) / (ξ + 1)   −1 ≤ ξ ≤ 0   (ξ = −1: n = ∞, [`NPrime::UNWARPED`])
/// n = (√α + 1) / (ξ √α + 1)           0 < ξ ≤ 1
/// ```
///
/// α = `alpha` (> 1), ξ = `eta`. n with the view near plane at 1.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha` or `eta` (∈ [−1, 1]).
pub fn n_from_xi(alpha: f64, eta: f64) -> Result<NPrime> {
    let a = alpha_ok(alpha)?;
    let eta = in_closed("eta", eta, -1.0, 1.0)?;
    // The same map as Lloyd 2006's n′(η) with near = 1 (one implementation, in `warp`).
    n_prime_from_eta(1.0, a, eta)
}

/// The normalised depth at which g (and m) is largest for a given ξ: the near plane z = 1 for
/// ξ ≤ 0 (n ≥ n_opt), the far plane z = α for ξ > 0 (both at ξ = 0).
///
/// Lloyd 2005 §3.2 prints the two the other way round (see docs/errata.md); Eq 5 is right.
///
/// The depth is normalised (a multiple of the near distance, in [1, α]).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha` or `eta`.
pub fn max_error_depth(alpha: f64, eta: f64) -> Result<f64> {
    let a = alpha_ok(alpha)?;
    let eta = in_closed("eta", eta, -1.0, 1.0)?;
    Ok(if eta <= 0.0 { 1.0 } else { a })
}

/// The maximum error over the frustum in terms of ξ (Lloyd 2005 Eq 5).
///
/// ```text
/// m_max = (r_p / r_s) · (α − 1) / (2 tan θ) · (1 + |ξ| (√α − 1)) / √α
/// ```
///
/// Symbols as in [`error_m`]; ξ = `eta` ∈ [−1, 1]. Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha`, `half_fov`, `eta`, `res_image` or `res_s`, and
/// `res_image` and `res_s` when they
/// scale the value, which is positive, below f64's normal range (0 or a subnormal is never
/// returned; the message estimates the value and says how to get it).
pub fn max_error(alpha: f64, half_fov: f64, eta: f64, res_image: f64, res_s: f64) -> Result<f64> {
    let a = alpha_ok(alpha)?;
    let t = tan_ok(half_fov)?;
    let eta = in_closed("eta", eta, -1.0, 1.0)?;
    let rp = positive("res_image", res_image)?;
    let rs = positive("res_s", res_s)?;
    let ra = a.sqrt();
    let m = |ratio: f64| ratio * (a - 1.0) / (2.0 * t) * (1.0 + eta.abs() * (ra - 1.0)) / ra;
    positive_result("m_max", m(rp / rs), warp_res(rp, rs), || m(1.0))
}

fn check_errors(errors: &[f64]) -> Result<f64> {
    if errors.is_empty() {
        return Err(Error::invalid(
            "errors",
            "must hold at least one value (got none)",
        ));
    }
    let mut sum = 0.0;
    for (i, &e) in errors.iter().enumerate() {
        if !(e.is_finite() && e > 0.0) {
            return Err(Error::invalid(
                "errors",
                format!(
                    "must be finite and greater than 0 (got {} at index {i})",
                    fmt_num(e)
                ),
            ));
        }
        sum += e;
    }
    if !sum.is_finite() {
        return Err(Error::invalid("errors", "sum overflows"));
    }
    Ok(sum)
}

/// Texels per subdivision in proportion to each subdivision's maximum error (Lloyd 2005 Eq 6).
///
/// ```text
/// r_si = r_s · e_i / Σ_j e_j
/// ```
///
/// e_i = `errors[i]` (each subdivision's maximum error with the whole map's resolution, > 0),
/// r_s = `total` texels (> 0, along the split direction). Written into `out` (same length as
/// `errors`; no heap allocation). Since error scales as 1/texels, every subdivision then has the
/// same maximum error, Σ_j e_j (in units of the whole map's error), and the r_si sum to r_s.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `errors` (empty, or a value not finite and positive),
/// `total` (finite, > 0) or `out` (length differs from `errors`).
///
/// ```
/// # use shadow_aliasing::analytic::subdivided::allocate_texels;
/// let mut out = [0.0; 3];
/// allocate_texels(&[1.0, 2.0, 1.0], 1024.0, &mut out)?;
/// assert_eq!(out, [256.0, 512.0, 256.0]);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn allocate_texels(errors: &[f64], total: f64, out: &mut [f64]) -> Result<()> {
    let sum = check_errors(errors)?;
    let total = positive("total", total)?;
    same_length(errors.len(), out.len())?;
    for (o, &e) in out.iter_mut().zip(errors) {
        *o = total * (e / sum);
    }
    Ok(())
}

/// `out` must have the length of `errors`.
fn same_length(errors: usize, out: usize) -> Result<()> {
    if out == errors {
        return Ok(());
    }
    Err(Error::invalid(
        "out",
        format!("must have the length of errors ({errors}), got {out}"),
    ))
}

/// Eq 6 in whole texels: the largest-remainder rounding of [`allocate_texels`], so the counts
/// sum to `total` exactly (ties go to the earlier subdivision). No heap allocation.
///
/// # Errors
/// As [`allocate_texels`]; `total` must be at least 1.
pub fn allocate_texels_whole(errors: &[f64], total: u32, out: &mut [u32]) -> Result<()> {
    let sum = check_errors(errors)?;
    if total == 0 {
        return Err(Error::invalid("total", "must be at least 1 (got 0)"));
    }
    same_length(errors.len(), out.len())?;
    let t = f64::from(total);
    let mut given: u64 = 0;
    for (o, &e) in out.iter_mut().zip(errors) {
        // floor of a value in [0, total]: fits in u32.
        let share = (t * (e / sum)).floor().clamp(0.0, t);
        *o = share as u32;
        given += u64::from(*o);
    }
    let mut left = u64::from(total).saturating_sub(given);
    while left > 0 {
        // Give one texel to the largest remaining fractional part.
        let mut best = 0usize;
        let mut best_frac = f64::NEG_INFINITY;
        for (i, (&o, &e)) in out.iter().zip(errors).enumerate() {
            let frac = t * (e / sum) - f64::from(o);
            if frac > best_frac {
                best_frac = frac;
                best = i;
            }
        }
        out[best] += 1;
        left -= 1;
    }
    Ok(())
}

/// The k face-subdivision planes z_i = α^{i/k}, i = 0..k, over the normalised frustum [1, α]
/// (Lloyd 2005 §4, "Face subdivision"; the same self-similar planes as Lloyd 2006 Eq 15, 16).
///
/// Depths normalised to near = 1 (multiply by the near distance for eye-space units).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha` (> 1) or `k` (1 ≤ k ≤ 16).
pub fn face_subdivision_planes(alpha: f64, k: usize) -> Result<Splits> {
    let a = alpha_ok(alpha)?;
    z_splits(1.0, a, k, SplitScheme::SelfSimilar)
}

/// The maximum error with k self-similar face subdivisions, each with ratio α^{1/k}, the same
/// ξ, and 1/k of the texels (Lloyd 2005 Eq 7).
///
/// ```text
/// m_max(k) = k (r_p / r_s) (α^{1/k} − 1) / (2 tan θ) · (1 + |ξ| (√(α^{1/k}) − 1)) / √(α^{1/k})
/// ```
///
/// Symbols as in [`max_error`]; k = `k` ≥ 1. All subdivisions have the same maximum error, so
/// Eq 6 gives each r_s/k texels, and Eq 5 with α → α^{1/k}, r_s → r_s/k is Eq 7. As k → ∞ it
/// tends to (r_p/r_s) ln α / (2 tan θ) for every ξ (the |ξ| factor tends to 1).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha`, `k` (≥ 1), `half_fov`, `eta`, `res_image` or
/// `res_s`, and `res_image` and `res_s` when they
/// scale the value, which is positive, below f64's normal range (0 or a subnormal is never
/// returned; the message estimates the value and says how to get it).
pub fn subdivided_max_error(
    alpha: f64,
    k: usize,
    eta: f64,
    half_fov: f64,
    res_image: f64,
    res_s: f64,
) -> Result<f64> {
    let a = alpha_ok(alpha)?;
    if k == 0 {
        return Err(Error::invalid("k", "must be at least 1 (got 0)"));
    }
    let t = tan_ok(half_fov)?;
    let eta = in_closed("eta", eta, -1.0, 1.0)?;
    let rp = positive("res_image", res_image)?;
    let rs = positive("res_s", res_s)?;
    positive_result(
        "m_max",
        subdivided_max_error_unchecked(a, k, eta, t, rp, rs),
        warp_res(rp, rs),
        || subdivided_max_error_unchecked(a, k, eta, t, 1.0, 1.0),
    )
}

/// [`subdivided_max_error`] without validation (Lloyd 2005 Eq 7,
/// `m_max = k (r_p/r_s) (α^{1/k} − 1)/(2 tan θ) · (1 + |ξ| (α^{1/2k} − 1))/α^{1/2k}`), for callers
/// that have checked the domain themselves (the Python bindings' array path): tan θ =
/// `tan_half_fov` (as `half_fov.tan()`), the other arguments as [`subdivided_max_error`].
///
/// Equal, bit for bit, to [`subdivided_max_error`] wherever it returns `Ok` (which computes its
/// value here); meaningless outside that domain (k = 0 included; it does not panic).
#[inline]
#[must_use]
pub fn subdivided_max_error_unchecked(
    alpha: f64,
    k: usize,
    eta: f64,
    tan_half_fov: f64,
    res_image: f64,
    res_s: f64,
) -> f64 {
    let a = alpha;
    let kf = k as f64;
    // e = (α^{1/k} − 1)/s with s = √(α^{1/k}) = α^{1/2k}, each within a few ulps, without
    // cancellation near α = 1 (α − 1 is exact there) and for large k, and without an
    // intermediate overflow for huge α (e ≤ √α).
    let (e, rak) = if k.is_power_of_two() && k <= 16 {
        // k = 2^m: r_j = α^{1/2^j} by m square roots, and the exact identity
        // α^{1/k} − 1 = (α − 1) / ∏_{j=1..m} (r_j + 1); then s = √r_m. No logarithm or
        // exponential: square roots only, independent of `tan θ`'s chain.
        let mut r = a;
        let mut prod = 1.0;
        let mut j = k;
        while j > 1 {
            r = r.sqrt();
            prod *= r + 1.0;
            j >>= 1;
        }
        let s = r.sqrt();
        ((a - 1.0) / (prod * s), s)
    } else {
        // s − 1 = exp_m1(ln α / 2k) (1/2k beside the logarithm, off its dependency chain);
        // α^{1/k} − 1 = (s − 1)(s + 1), with one exponential.
        let rak_m1 = (a.ln() * (0.5 / kf)).exp_m1();
        let rak = 1.0 + rak_m1;
        (rak_m1 * (rak_m1 + 2.0) / rak, rak)
    };
    // k (r_p/r_s)/(2 tan θ) is ready before e; 1 + |ξ|(s − 1) is 1 or more, so s − 1 needs no
    // care there.
    let q = kf * res_image / (res_s * (2.0 * tan_half_fov));
    q * e * (1.0 + eta.abs() * (rak - 1.0))
}

/// The x error (Lloyd 2005 Eq 8; Lloyd 2006 Eq 7 with n = 1, f = α).
///
/// ```text
/// m_x = (r_p / r_t) · α (n + z − 1) / (z (n + α − 1)),    m_x = (r_p / r_t) α / z for n = ∞
/// ```
///
/// r_p = `res_image`, r_t = `res_x` (texels along x: the crate's res_s); α, n, z as in
/// [`distribution_g`]. Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha`, `n_warp`, `z`, `res_image` or `res_x`, and
/// `res_image` and `res_x` when they
/// scale the value, which is positive, below f64's normal range (0 or a subnormal is never
/// returned; the message estimates the value and says how to get it).
pub fn mx_normalised(
    alpha: f64,
    n_warp: NPrime,
    z: f64,
    res_image: f64,
    res_x: f64,
) -> Result<f64> {
    let a = alpha_ok(alpha)?;
    n_warp_ok(n_warp)?;
    let z = z_ok(z, a)?;
    let rp = positive("res_image", res_image)?;
    let rt = positive("res_x", res_x)?;
    // Lloyd 2006 Eq 7 with near = 1, far = α (one implementation, in `overhead`).
    crate::analytic::overhead::mx_scaled(1.0, a, n_warp, z, ResRatio::new(rp, "res_x", rt))
}

/// The maximum x error, on the near plane z = 1, in terms of ξ (Lloyd 2005 Eq 9).
///
/// ```text
/// m_x,max = (r_p / r_t) · α (1 − ξ (√α − 1)) / √α          ξ ≤ 0
/// m_x,max = (r_p / r_t) · α / (√α (1 + ξ (√α − 1)))        ξ > 0
/// ```
///
/// Symbols as in [`mx_normalised`] and [`max_error`]. It is smallest, r_p/r_t, at ξ = +1 (PSM, n = 1), and
/// largest, (r_p/r_t) α, at ξ = −1 (unwarped).
///
/// Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `alpha`, `eta`, `res_image` or `res_x`, and
/// `res_image` and `res_x` when they
/// scale the value, which is positive, below f64's normal range (0 or a subnormal is never
/// returned; the message estimates the value and says how to get it).
pub fn max_mx_normalised(alpha: f64, eta: f64, res_image: f64, res_x: f64) -> Result<f64> {
    let a = alpha_ok(alpha)?;
    let eta = in_closed("eta", eta, -1.0, 1.0)?;
    let rp = positive("res_image", res_image)?;
    let rt = positive("res_x", res_x)?;
    let ra = a.sqrt();
    let shape = if eta <= 0.0 {
        a * (1.0 - eta * (ra - 1.0)) / ra
    } else {
        a / (ra * (1.0 + eta * (ra - 1.0)))
    };
    positive_result(
        "m_x,max",
        rp / rt * shape,
        ResRatio::new(rp, "res_x", rt),
        || shape,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`distribution_g_unchecked`] gives [`distribution_g`]'s values bit for bit over its
    /// domain (warped, n = 1, unwarped; z at both ends and inside), and Eq 3 by hand.
    #[test]
    fn distribution_g_unchecked_agrees() {
        for a in [1.5f64, 100.0, 1e6] {
            for n in [1.0, 3.0, 1.0 + a.sqrt(), 1e9, f64::INFINITY] {
                let nv = NPrime::new(n).unwrap();
                for z in [1.0, 0.5 * (1.0 + a), a] {
                    let want = distribution_g(a, nv, z).unwrap();
                    assert_eq!(want.to_bits(), distribution_g_unchecked(a, n, z).to_bits());
                }
            }
        }
        // Eq 3, α = 100, n = 11, z = 10: (10 − 1 + 11)² / (10 · 11 · 110) = 400/12100.
        assert!((distribution_g_unchecked(100.0, 11.0, 10.0) - 400.0 / 12100.0).abs() < 1e-16);
    }

    /// [`subdivided_max_error_unchecked`] gives [`subdivided_max_error`]'s values bit for bit:
    /// k a power of two up to 16 (square roots), 3, 17 and large k (logarithm); α near 1, large
    /// and huge; ξ at both ends and 0; θ at both ends; resolutions other than one.
    #[test]
    fn subdivided_max_error_unchecked_agrees() {
        let mut cases = 0;
        for a in [1.0 + 1e-12, 1.5, 100.0, 1e6, 1e300] {
            for k in [1, 2, 3, 4, 8, 16, 17, 32, 1000, 1_000_000] {
                for eta in [-1.0, -0.3, 0.0, 0.7, 1.0] {
                    // The largest f64 below π/2 too.
                    let below = f64::from_bits(std::f64::consts::FRAC_PI_2.to_bits() - 1);
                    for th in [1e-300, 0.01, 0.5, 1.5, below] {
                        for &(ri, rs) in &[(1.0, 1.0), (1920.0, 700.0)] {
                            let Ok(want) = subdivided_max_error(a, k, eta, th, ri, rs) else {
                                // Only an overflow of 1/tan θ at θ = 1e-300 with a large α.
                                assert!(th < 1e-200, "{a} {k} {eta} {th}");
                                continue;
                            };
                            let got = subdivided_max_error_unchecked(a, k, eta, th.tan(), ri, rs);
                            assert_eq!(want.to_bits(), got.to_bits(), "{a} {k} {eta} {th}");
                            cases += 1;
                        }
                    }
                }
            }
        }
        assert!(cases > 2000, "{cases}");
        // Eq 7 with k = 2, ξ = 0, α = 100, θ = 45°: 2 · 9/2 / √10 / tan θ.
        let t = std::f64::consts::FRAC_PI_4.tan();
        let e = subdivided_max_error_unchecked(100.0, 2, 0.0, t, 1.0, 1.0);
        assert!((e - 9.0 / 10f64.sqrt() / t).abs() < 1e-12);
    }

    #[test]
    fn hand_values() {
        // α = 100: n(ξ = 0) = 11, g₀ = 0.1; Eq 5 at θ = 45°, ξ = 0: 99/2 · 0.1 = 4.95.
        let q = std::f64::consts::FRAC_PI_4;
        let t = q.tan();
        assert!((max_error(100.0, q, 0.0, 1.0, 1.0).unwrap() - 4.95 / t).abs() < 1e-12);
        // ξ = ±1: 99/2 · 1.
        assert!((max_error(100.0, q, 1.0, 1.0, 1.0).unwrap() - 49.5 / t).abs() < 1e-12);
        // Eq 7 with k = 2, ξ = 0: 2 · 9/2 / √10.
        let e = subdivided_max_error(100.0, 2, 0.0, q, 1.0, 1.0).unwrap();
        assert!((e - 9.0 / 10f64.sqrt() / t).abs() < 1e-12);
        // Eq 9: ξ = 1 gives r_p/r_t; ξ = −1 gives α.
        assert!((max_mx_normalised(100.0, 1.0, 1.0, 1.0).unwrap() - 1.0).abs() < 1e-14);
        assert!((max_mx_normalised(100.0, -1.0, 1.0, 1.0).unwrap() - 100.0).abs() < 1e-12);
        assert_eq!(n_from_xi(100.0, -1.0), Ok(NPrime::UNWARPED));
        assert_eq!(xi_from_n(100.0, NPrime::finite(1.0).unwrap()), Ok(1.0));
        let mut w = [0u32; 3];
        allocate_texels_whole(&[1.0, 1.0, 1.0], 100, &mut w).unwrap();
        assert_eq!(w, [34, 33, 33]);
        assert!(distribution_g(1.0, NPrime::UNWARPED, 1.0).is_err());
        assert!(distribution_g(10.0, NPrime::finite(0.5).unwrap(), 1.0).is_err());
        assert!(allocate_texels(&[1.0, 0.0], 10.0, &mut [0.0; 2]).is_err());
    }
}
