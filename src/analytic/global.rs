//! Zhang, Zhao & Sun 2009, *An Aliasing Theory of Shadow Mapping*: the aliasing functions E_q,
//! E_p in the local representation (Eq 8, 9), their factorisation into perspective × projection
//! aliasing for a surface slope (Eq 10, 11 and the Appendix), and the global representation for a
//! light tilted in the view's vertical plane (Eq 12–14 with μ, z_w, tan φ_w, F_q, F_p, G).
//!
//! # Notation and conventions
//!
//! Zhang's n, f, φ are the crate's `near`, `far`, `half_fov` (square image: both fields of view
//! 2φ); his θ ∈ [0, π/2] (the angle between light and view) is the crate's [`LightAngle`]
//! (argument `light_angle`; Barroso's γ); his λ (near plane of the warping frustum W) is Lloyd's n′, passed as an
//! [`NPrime`] (any λ > 0, or unwarped, λ = ∞). A point is `(x, y, z)` with z its depth in front
//! of the eye: Zhang's left-handed DirectX eye space (z forward) is the crate's right-handed one
//! with `z = −p.z`; x and y are the same. His light is above and in front of the viewer
//! ([`crate::measure::tilted_twin::TiltSide::InFront`]), so the near-top edge of the frustum is
//! nearest W's centre of projection; for the light above and behind, replace y by −y.
//!
//! E_q and E_p compare the screen's normalised device coordinates (q, p) ∈ [−1, 1]² with the
//! texture coordinates (t, s) ∈ [0, 1]² (Zhang's t runs across the light, the crate's s; his s
//! along the warp, the crate's t). Their perspective parts are exactly twice Lloyd's m_x, m_z
//! with unit resolutions: `E_q^pers = 2 m_x`, `E_p^pers = 2 m_z` (m_z measured perpendicular
//! to the light, [`crate::measure::point_error`]).
//!
//! # Corrections (docs/errata.md)
//!
//! The crate computes every function from the coordinate maps of Eq 12 with the warping frustum
//! fitted to contain the view frustum, and checks each against the measured matrix
//! ([`crate::measure::tilted_twin`]). Where the printed Appendix disagrees, the crate's form
//! is documented on the function: tan φ_w for θ ∈ [φ, π/2] (printed with the far-bottom corner;
//! the far-top corner bounds it), F_p (printed too large by 1/sin θ, and by 1/(tan φ cos θ) for
//! θ < φ), F_q and Eq 8 (valid only while the far corners bound W), and E_q^pers in §2.4
//! (printed without its 1/z).
//!
//! ```
//! use shadow_aliasing::analytic::global::{zhang_ep, zhang_ep_local, zhang_eq, zhang_eq_local};
//! use shadow_aliasing::{LightAngle, NPrime, ViewFrustum};
//! let view = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_6)?;
//! let lambda = NPrime::finite(11.0)?;
//! let up = LightAngle::new(std::f64::consts::FRAC_PI_2)?;
//! // At θ = π/2 and y = 0 the global representation is the local one.
//! let (g, l) = (zhang_ep(&view, lambda, up, 0.0, 10.0)?, zhang_ep_local(&view, lambda, 10.0)?);
//! assert!((g - l).abs() < 1e-12 * l);
//! let (g, l) = (zhang_eq(&view, lambda, up, 0.0, 10.0)?, zhang_eq_local(&view, lambda, 10.0)?);
//! assert!((g - l).abs() < 1e-12 * l);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::analytic::tilted::{depth_in_view, mu_unchecked, warp_depth_range};
use crate::error::{finite, finite_result, fmt_num, positive, Error, Result};
use crate::frustum::{LightAngle, NPrime, ViewFrustum};
use std::hint::select_unpredictable as select;

/// μ, the depth range of the warping frustum W (Zhang Appendix; the same as Barroso's f′ − n′):
///
/// `μ = (n tan φ / tan θ + f − n + f tan φ / tan θ) sin θ` for θ ∈ [φ, π/2],
/// `μ = 2 f tan φ cos θ` for θ ∈ [0, φ).
///
/// The printed μ agrees with the fitted warping frustum (checked against the twin). This is
/// [`crate::analytic::tilted::warp_depth_range`]. Unit: eye-space distance.
///
/// # Errors
/// [`Error::Degenerate`] when μ overflows an `f64` (f tan φ beyond about 1e308).
#[inline]
pub fn zhang_mu(view: &ViewFrustum, light_angle: LightAngle) -> Result<f64> {
    warp_depth_range(view, light_angle)
}

/// z_w − λ, the point's warp depth from the frustum's nearest extent.
#[inline]
fn z_w_offset(view: &ViewFrustum, light_angle: LightAngle, y: f64, z: f64) -> f64 {
    let (s, c) = light_angle.radians().sin_cos();
    z_w_offset_sc(view, light_angle, s, c, y, z)
}

/// [`z_w_offset`] with `(s, c) = light_angle.radians().sin_cos()` already taken.
#[inline]
fn z_w_offset_sc(
    view: &ViewFrustum,
    light_angle: LightAngle,
    s: f64,
    c: f64,
    y: f64,
    z: f64,
) -> f64 {
    let upper = light_angle.radians() >= view.half_fov();
    let (n, f, t) = (view.near(), view.far(), view.tan_half_fov());
    z_w_offset_unchecked(n, f, t, upper, s, c, y, z)
}

/// Validates a point (y, z) of the view frustum's vertical section: `near ≤ z ≤ far` and
/// `|y| ≤ z tan φ` (with a relative slack of 1e-12 for points on the side planes).
fn point_in_view(view: &ViewFrustum, y: f64, z: f64) -> Result<(f64, f64)> {
    let z = depth_in_view(view, z)?;
    let y = finite("y", y)?;
    let h = z * view.tan_half_fov();
    if y.abs() > h * (1.0 + 1e-12) {
        return Err(y_outside(h, y));
    }
    Ok((y, z))
}

#[cold]
#[inline(never)]
fn y_outside(h: f64, y: f64) -> Error {
    Error::invalid(
        "y",
        format!(
            "must lie in the view frustum, |y| ≤ z tan(half_fov) = {} (got {})",
            fmt_num(h),
            fmt_num(y)
        ),
    )
}

/// z_w, the warp depth of the point (x, y, z) in W's frame (Zhang Appendix):
///
/// `z_w = (z − n + n tan φ / tan θ − y / tan θ) sin θ + λ` for θ ∈ [φ, π/2],
/// `z_w = (f tan φ − (f − z) tan θ − y) cos θ + λ` for θ ∈ [0, φ),
///
/// (both written without tan θ in the crate, so θ = 0 and θ = π/2 are exact). The printed z_w
/// agrees with the twin. Unit: eye-space distance.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda` (not finite and positive), `z` (outside
/// `[near, far]`) or `y` (outside the frustum, `|y| > z tan φ`).
#[inline]
pub fn zhang_z_w(
    view: &ViewFrustum,
    lambda: f64,
    light_angle: LightAngle,
    y: f64,
    z: f64,
) -> Result<f64> {
    let lambda = positive("lambda", lambda)?;
    let (y, z) = point_in_view(view, y, z)?;
    finite_result("z_w", lambda + z_w_offset(view, light_angle, y, z))
}

/// tan φ_w, the half-angle in x of the warping frustum W fitted to contain the view frustum
/// (Zhang's "light view", Appendix), square image:
///
/// `tan φ_w = max( n tan φ / (λ + max(0, −D)), f tan φ / (λ + max(0, D)) )`,
/// `D = (f − n)(sin θ − tan φ cos θ)`,
///
/// the larger of the near-top and far-top corners' ratios |x| / z_w (the bottom corners, further
/// from W's centre of projection, never bound it). For θ ∈ [φ, π/2] and λ ≥ n sin(θ − φ)/cos φ
/// this is `f tan φ / (λ + (f − n)(1 − tan φ / tan θ) sin θ)`; for θ < φ it is `f tan φ / λ` as
/// printed.
///
/// **Erratum**: Zhang prints `f tan φ / (μ + λ)` for θ ∈ [φ, π/2], the far-*bottom* corner's
/// ratio, which leaves the far-top corners outside W for every θ < π/2 (their t exceeds 1);
/// his own F_q uses the far-top corner. Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda` (not finite and positive).
#[inline]
pub fn zhang_tan_phi_w(view: &ViewFrustum, lambda: f64, light_angle: LightAngle) -> Result<f64> {
    let lambda = positive("lambda", lambda)?;
    finite_result("tan_phi_w", tan_phi_w_unchecked(view, lambda, light_angle))
}

#[inline]
fn tan_phi_w_unchecked(view: &ViewFrustum, lambda: f64, light_angle: LightAngle) -> f64 {
    let (s, c) = light_angle.radians().sin_cos();
    tan_phi_w_parts(view.near(), view.far(), view.tan_half_fov(), lambda, s, c)
}

/// tan φ_w of [`tan_phi_w_unchecked`] from its parts: n, f, t = tan φ, λ and the sine and cosine
/// of θ. `D = (f − n)(sin θ − tan φ cos θ)` is the offset of the far-top corner's warp depth from
/// the near-top corner's: the near-top corner is nearest W's centre of projection when D ≥ 0
/// (θ ≥ φ), the far-top corner otherwise.
#[inline(always)]
fn tan_phi_w_parts(n: f64, f: f64, t: f64, lambda: f64, s: f64, c: f64) -> f64 {
    let d = (f - n) * (s - t * c);
    let near = n * t / (lambda + (-d).max(0.0));
    let far = f * t / (lambda + d.max(0.0));
    near.max(far)
}

/// F_q(λ, θ) of Zhang's global representation (Eq 13, Appendix), `E_q^pers = F_q (z + G)/z`:
///
/// `F_q = 2 tan φ_w sin θ / tan φ`, tan φ_w from [`zhang_tan_phi_w`]; that is
/// `2 f sin θ / (λ + (f − n)(1 − tan φ/tan θ) sin θ)` for θ ∈ [φ, π/2] and
/// `2 f sin θ / λ` for θ ∈ [0, φ) as printed, while the far corners bound W
/// (λ ≥ n sin(θ − φ)/cos φ); below that, the near corners bound W and `F_q = 2 n sin θ / λ`
/// (the printed F_q then describes a W that cuts off the near corners). Unit: 1.
/// F_q = 0 at θ = 0, where G is infinite: use [`zhang_eq`] there.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda` (not finite and positive).
#[inline]
pub fn zhang_f_q(view: &ViewFrustum, lambda: f64, light_angle: LightAngle) -> Result<f64> {
    let lambda = positive("lambda", lambda)?;
    finite_result(
        "F_q",
        2.0 * tan_phi_w_unchecked(view, lambda, light_angle) * light_angle.radians().sin()
            / view.tan_half_fov(),
    )
}

/// F_p(λ, θ) of Zhang's global representation (Eq 14, Appendix), `E_p^pers = F_p (z + G)²/z`:
///
/// `F_p = μ sin²θ / (tan φ · λ (λ + μ))`, μ from [`zhang_mu`], for both ranges of θ.
///
/// **Erratum**: the printed F_p is `μ sin θ / (tan φ λ (λ + μ))` for θ ∈ [φ, π/2] (too large by
/// 1/sin θ) and `2 f sin²θ / (tan φ λ (λ + μ))` for θ ∈ [0, φ) (too large by 1/(tan φ cos θ));
/// both disagree with Zhang's own E_p^pers = μ z_w² / (tan φ (λ + μ) λ z) and z_w = (z + G) sin θ,
/// and with the measured map. Unit: 1 / eye-space distance.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda` (not finite and positive).
#[inline]
pub fn zhang_f_p(view: &ViewFrustum, lambda: f64, light_angle: LightAngle) -> Result<f64> {
    let lambda = positive("lambda", lambda)?;
    let mu = zhang_mu(view, light_angle)?;
    let s = light_angle.radians().sin();
    finite_result(
        "F_p",
        mu * s * s / (view.tan_half_fov() * lambda * (lambda + mu)),
    )
}

/// G(y, λ, θ) of Zhang's global representation (Appendix), `z_w = (z + G) sin θ`:
///
/// `G = λ / sin θ − n + (n tan φ − y) / tan θ` for θ ∈ [φ, π/2],
/// `G = λ / sin θ − f + (f tan φ − y) / tan θ` for θ ∈ (0, φ),
///
/// as printed (checked against the twin). Unit: eye-space distance.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda` (not finite and positive), `y` (not finite) or
/// `light_angle` (θ = 0, where G is infinite and the global representation F·(z + G)/z is
/// 0 · ∞; [`zhang_eq`] and [`zhang_ep`] are finite there).
#[inline]
pub fn zhang_g(view: &ViewFrustum, lambda: f64, light_angle: LightAngle, y: f64) -> Result<f64> {
    let lambda = positive("lambda", lambda)?;
    let y = finite("y", y)?;
    let (s, c) = light_angle.radians().sin_cos();
    if s <= 0.0 {
        return Err(Error::invalid(
            "light_angle",
            "must be greater than 0 for Zhang's G, which is infinite when light and view are parallel (got 0)",
        ));
    }
    let t = view.tan_half_fov();
    let r = if light_angle.radians() >= view.half_fov() {
        view.near()
    } else {
        view.far()
    };
    finite_result("G", lambda / s - r + (r * t - y) * c / s)
}

/// Zhang's E_q^pers, the perspective aliasing across the light at the point (x, y, z) of the view
/// frustum (Eq 13, global representation), computed from the coordinate map of Eq 12:
///
/// `E_q^pers = 2 tan φ_w z_w / (tan φ z)` `= F_q (z + G)/z`,
///
/// with z_w from [`zhang_z_w`], tan φ_w from [`zhang_tan_phi_w`] (fitted W), φ the half field of
/// view, z the depth; unwarped (λ = ∞), `2 f / z`. It does not depend on x. It equals
/// `2 m_x` of [`crate::measure::point_error`] with unit resolutions. Dimensionless.
///
/// Domain: any λ > 0 or unwarped, θ ∈ [0, π/2], `near ≤ z ≤ far`, `|y| ≤ z tan φ`.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `y` or `z` outside that domain.
#[inline]
pub fn zhang_eq(
    view: &ViewFrustum,
    lambda: NPrime,
    light_angle: LightAngle,
    y: f64,
    z: f64,
) -> Result<f64> {
    let (y, z) = point_in_view(view, y, z)?;
    finite_result(
        "E_q",
        zhang_eq_unchecked(
            view.near(),
            view.far(),
            view.half_fov(),
            view.tan_half_fov(),
            lambda.value(),
            light_angle.radians(),
            y,
            z,
        ),
    )
}

/// [`zhang_eq`] without validation (Zhang Eq 13 and Appendix, `E_q^pers = 2 tan φ_w z_w /
/// (tan φ z)`, `2 f / z` for λ = ∞), for callers that have checked the domain themselves (the
/// Python bindings' array path): n = `near`, f = `far`, φ = `half_fov` with tan φ =
/// `tan_half_fov` (as [`ViewFrustum::tan_half_fov`] computes it), λ = `lambda` as an `f64`
/// (`f64::INFINITY` unwarped), θ = `light_angle` in radians.
///
/// Equal, bit for bit, to [`zhang_eq`] wherever `zhang_eq` returns `Ok` (which computes its
/// value here); meaningless outside that domain.
#[inline(always)]
#[must_use]
#[allow(clippy::too_many_arguments)]
pub fn zhang_eq_unchecked(
    near: f64,
    far: f64,
    half_fov: f64,
    tan_half_fov: f64,
    lambda: f64,
    light_angle: f64,
    y: f64,
    z: f64,
) -> f64 {
    let (n, f, t, l) = (near, far, tan_half_fov, lambda);
    let (s, c) = light_angle.sin_cos();
    // Every branch, then selects without a jump (`select_unpredictable`), so that a loop over
    // arrays vectorises. z_w − λ (`z_w_offset`) and tan φ_w (`tan_phi_w_parts`).
    let upper = light_angle >= half_fov;
    let zw = l + z_w_offset_unchecked(n, f, t, upper, s, c, y, z);
    let tan_phi_w = tan_phi_w_parts(n, f, t, l, s, c);
    select(
        l == f64::INFINITY,
        2.0 * f / z,
        2.0 * tan_phi_w * zw / (t * z),
    )
}

/// z_w − λ of the point (y, z) ([`z_w_offset_sc`]) without validation, both branches computed and
/// one selected without a jump: `upper` is θ ≥ φ, `s`, `c` the sine and cosine of θ.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn z_w_offset_unchecked(
    n: f64,
    f: f64,
    t: f64,
    upper: bool,
    s: f64,
    c: f64,
    y: f64,
    z: f64,
) -> f64 {
    select(
        upper,
        (z - n) * s + (n * t - y) * c,
        (z - f) * s + (f * t - y) * c,
    )
}

/// Zhang's E_p^pers, the perspective aliasing along the warp at the point (x, y, z) of the view
/// frustum (Eq 14, global representation), from the coordinate map of Eq 12:
///
/// `E_p^pers = μ z_w² / (tan φ (λ + μ) λ z)` `= F_p (z + G)²/z`,
///
/// with μ from [`zhang_mu`], z_w from [`zhang_z_w`]; unwarped, `μ / (tan φ z)`. It equals
/// `2 m_z` of [`crate::measure::point_error`] (perpendicular to the light, unit resolutions) and,
/// on the view axis, `2 sin θ` times Barroso's m_z ([`crate::analytic::tilted::tilted_mz`]).
/// Dimensionless.
///
/// Domain: any λ > 0 or unwarped, θ ∈ [0, π/2], `near ≤ z ≤ far`, `|y| ≤ z tan φ`.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `y` or `z` outside that domain.
#[inline]
pub fn zhang_ep(
    view: &ViewFrustum,
    lambda: NPrime,
    light_angle: LightAngle,
    y: f64,
    z: f64,
) -> Result<f64> {
    let (y, z) = point_in_view(view, y, z)?;
    // μ's own error first (an overflow), then the value from the twin, which takes μ again.
    warp_depth_range(view, light_angle)?;
    finite_result(
        "E_p",
        zhang_ep_unchecked(
            view.near(),
            view.far(),
            view.half_fov(),
            view.tan_half_fov(),
            lambda.value(),
            light_angle.radians(),
            y,
            z,
        ),
    )
}

/// [`zhang_ep`] without validation (Zhang Eq 14 and Appendix, `E_p^pers = μ z_w² / (tan φ
/// (λ + μ) λ z)`, `μ / (tan φ z)` for λ = ∞); arguments as [`zhang_eq_unchecked`].
///
/// Equal, bit for bit, to [`zhang_ep`] wherever `zhang_ep` returns `Ok` (which computes its
/// value here); meaningless outside that domain (where μ overflows the value is not finite).
#[inline(always)]
#[must_use]
#[allow(clippy::too_many_arguments)]
pub fn zhang_ep_unchecked(
    near: f64,
    far: f64,
    half_fov: f64,
    tan_half_fov: f64,
    lambda: f64,
    light_angle: f64,
    y: f64,
    z: f64,
) -> f64 {
    let (n, f, t, l) = (near, far, tan_half_fov, lambda);
    let (s, c) = light_angle.sin_cos();
    // Every branch, then selects (see `zhang_eq_unchecked`): μ (`warp_depth_range_sc`) and
    // z_w − λ (`z_w_offset_sc`).
    let upper = light_angle >= half_fov;
    let mu = mu_unchecked(n, f, t, upper, s, c);
    let zw = l + z_w_offset_unchecked(n, f, t, upper, s, c, y, z);
    let unwarped = mu / (t * z);
    select(
        l == f64::INFINITY,
        unwarped,
        unwarped * (zw / l) * (zw / (l + mu)),
    )
}

/// Zhang's local representation of E_q (Eq 8): the light overhead (θ = π/2), the point on the
/// view axis at depth z:
///
/// `E_q = 2 f (z − n + λ) / ((f − n + λ) z)` for λ ≥ n (as printed), and
/// `E_q = 2 n (z − n + λ) / (λ z)` for λ < n, where the near corners bound the warping frustum
/// (Eq 8's `tan φ_w / tan φ = f/(μ + λ)` assumes λ ≥ n).
///
/// Equal to `2 m_x` of Lloyd 2006 Eq 7 with unit resolutions (for λ = n′ ≥ n). Unwarped: `2f/z`.
/// Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `z` (outside `[near, far]`).
#[inline]
pub fn zhang_eq_local(view: &ViewFrustum, lambda: NPrime, z: f64) -> Result<f64> {
    let z = depth_in_view(view, z)?;
    finite_result(
        "E_q",
        zhang_eq_local_unchecked(view.near(), view.far(), lambda.value(), z),
    )
}

/// [`zhang_eq_local`] without validation (Zhang Eq 8: `2 f (z − n + λ) / ((f − n + λ) z)` for
/// λ ≥ n, `2 n (z − n + λ) / (λ z)` for λ < n, `2 f / z` for λ = ∞), for callers that have
/// checked the domain themselves (the Python bindings' array path): n = `near`, f = `far`,
/// λ = `lambda` as an `f64` (`f64::INFINITY` unwarped). It does not depend on the field of view.
///
/// Equal, bit for bit, to [`zhang_eq_local`] wherever it returns `Ok` (which computes its value
/// here); meaningless outside that domain.
#[inline(always)]
#[must_use]
pub fn zhang_eq_local_unchecked(near: f64, far: f64, lambda: f64, z: f64) -> f64 {
    let (n, f, l) = (near, far, lambda);
    // Every branch, then selects without a jump (`select_unpredictable`), so that a loop over
    // arrays vectorises.
    let far_bound = 2.0 * f * (z - n + l) / ((f - n + l) * z);
    let near_bound = 2.0 * n * (z - n + l) / (l * z);
    select(
        l == f64::INFINITY,
        2.0 * f / z,
        select(l >= n, far_bound, near_bound),
    )
}

/// Zhang's local representation of E_p (Eq 9): the light overhead, the point on the view axis:
///
/// `E_p = (f − n)(z − n + λ)² / ((f − n + λ) λ tan φ z)`,
///
/// twice Lloyd 2006 Eq 8's m_z with unit resolutions. Unwarped: `(f − n)/(tan φ z)`.
/// Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `z` (outside `[near, far]`).
#[inline]
pub fn zhang_ep_local(view: &ViewFrustum, lambda: NPrime, z: f64) -> Result<f64> {
    let z = depth_in_view(view, z)?;
    finite_result(
        "E_p",
        zhang_ep_local_unchecked(
            view.near(),
            view.far(),
            view.tan_half_fov(),
            lambda.value(),
            z,
        ),
    )
}

/// [`zhang_ep_local`] without validation (Zhang Eq 9: `(f − n)(z − n + λ)² / ((f − n + λ) λ
/// tan φ z)`, `(f − n)/(tan φ z)` for λ = ∞): n = `near`, f = `far`, tan φ = `tan_half_fov` (as
/// [`ViewFrustum::tan_half_fov`] computes it), λ = `lambda` as an `f64` (`f64::INFINITY`
/// unwarped).
///
/// Equal, bit for bit, to [`zhang_ep_local`] wherever it returns `Ok` (which computes its value
/// here); meaningless outside that domain.
#[inline(always)]
#[must_use]
pub fn zhang_ep_local_unchecked(
    near: f64,
    far: f64,
    tan_half_fov: f64,
    lambda: f64,
    z: f64,
) -> f64 {
    let (n, f, t, l) = (near, far, tan_half_fov, lambda);
    // Both branches, then a select (see `zhang_eq_local_unchecked`).
    let unwarped = (f - n) / (t * z);
    let warped = unwarped * ((z - n + l) / l) * ((z - n + l) / (f - n + l));
    select(l == f64::INFINITY, unwarped, warped)
}

/// The slopes of Zhang's small shaft through a point: `x = k_x z − b_x`, `y = k_y z − b_y`
/// (Eq 10), so its tangent is `(k_x, k_y, 1)` in Zhang's (x, y, depth) and `(k_x, k_y, −1)` in
/// the crate's eye space.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceSlope {
    /// dx/dz, the slope in the XZ plane.
    pub k_x: f64,
    /// dy/dz, the slope in the YZ plane.
    pub k_y: f64,
}

/// Zhang's factorisation E = E^pers × E^proj (Eq 10, 11, §2.4 and the Appendix).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Factorisation {
    /// E_q^pers ([`zhang_eq`]).
    pub eq_pers: f64,
    /// |E_q^proj| = |(k_x − x/z) / (k_x − (x/z_w)(∂z_w/∂y k_y + ∂z_w/∂z))|.
    pub eq_proj: f64,
    /// E_p^pers ([`zhang_ep`]).
    pub ep_pers: f64,
    /// |E_p^proj| = |(k_y − y/z) / (∂z_w/∂y k_y + ∂z_w/∂z)|.
    pub ep_proj: f64,
}

impl Factorisation {
    /// E_q = E_q^pers · |E_q^proj| (Eq 11).
    #[inline]
    #[must_use]
    pub fn e_q(&self) -> f64 {
        self.eq_pers * self.eq_proj
    }
    /// E_p = E_p^pers · |E_p^proj| (Eq 11).
    #[inline]
    #[must_use]
    pub fn e_p(&self) -> f64 {
        self.ep_pers * self.ep_proj
    }
}

/// Zhang's factorisation of the aliasing functions at the point (x, y, z) of the view frustum
/// for a surface with slopes (k_x, k_y) (Eq 10, 11; §2.4; Appendix), with the warping frustum of
/// Eq 12 (finite λ):
///
/// `E_q = E_q^pers · |(k_x − x/z) / (k_x − (x/z_w)(∂z_w/∂y k_y + ∂z_w/∂z))|`,
/// `E_p = E_p^pers · |(k_y − y/z) / (∂z_w/∂y k_y + ∂z_w/∂z)|`,
///
/// with `∂z_w/∂y = −cos θ`, `∂z_w/∂z = sin θ` in both ranges of θ, E^pers from [`zhang_eq`],
/// [`zhang_ep`]. The product equals the total differentials |dq/dt|, |dp/ds| of Eq 1 along the
/// shaft ([`crate::measure::tilted_twin::aliasing_functions`]). x is the point's horizontal
/// eye coordinate, `|x| ≤ z tan φ`.
///
/// All four factors are dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda`, `x`, `y`, `z` or `slope` (non-finite slopes) outside
/// the domain; [`Error::Degenerate`] when a denominator vanishes (the surface contains the light
/// direction: projection aliasing is infinite), or when a factor or the products E_q, E_p
/// overflow an `f64`.
pub fn zhang_factorisation(
    view: &ViewFrustum,
    lambda: f64,
    light_angle: LightAngle,
    x: f64,
    y: f64,
    z: f64,
    slope: SurfaceSlope,
) -> Result<Factorisation> {
    let l = positive("lambda", lambda)?;
    let (y, z) = point_in_view(view, y, z)?;
    let x = finite("x", x)?;
    if x.abs() > z * view.tan_half_fov() * (1.0 + 1e-12) {
        return Err(Error::invalid(
            "x",
            format!(
                "must lie in the view frustum, |x| ≤ z tan(half_fov) (got {})",
                fmt_num(x)
            ),
        ));
    }
    let kx = finite("slope", slope.k_x)?;
    let ky = finite("slope", slope.k_y)?;
    let (s, c) = light_angle.radians().sin_cos();
    let zw = l + z_w_offset(view, light_angle, y, z);
    let dzw = -c * ky + s;
    let den_q = kx - x / zw * dzw;
    if dzw == 0.0 || den_q == 0.0 {
        return Err(Error::Degenerate(
            "the surface contains the light direction: projection aliasing is infinite".into(),
        ));
    }
    let lambda = NPrime::finite_unchecked(l);
    let eq_pers = zhang_eq(view, lambda, light_angle, y, z)?;
    let ep_pers = zhang_ep(view, lambda, light_angle, y, z)?;
    let f = Factorisation {
        eq_pers,
        eq_proj: finite_result("E_q^proj", ((kx - x / z) / den_q).abs())?,
        ep_pers,
        ep_proj: finite_result("E_p^proj", ((ky - y / z) / dzw).abs())?,
    };
    finite_result("E_q", f.e_q())?;
    finite_result("E_p", f.e_p())?;
    Ok(f)
}

#[cfg(test)]
mod unchecked_tests {
    use super::*;

    /// The `*_unchecked` twins give the checked forms' values bit for bit wherever those return
    /// `Ok`: λ below near, at it, above it and unwarped; θ = 0, below φ, at φ, above it and π/2;
    /// y on both side planes (with the relative slack) and inside; z on both planes and inside.
    #[test]
    fn unchecked_twins_agree() {
        let mut cases = 0;
        for &(n, f) in &[(1.0, 100.0), (0.1, 0.3), (2.5, 4e5), (1e-3, 1e6)] {
            for &phi in &[0.01, 0.5, std::f64::consts::FRAC_PI_4, 1.5] {
                let v = ViewFrustum::new(n, f, phi).unwrap();
                let t = v.tan_half_fov();
                for l in [0.25 * n, n, v.n_prime_lispsm(), 1e3 * f, f64::INFINITY] {
                    let lv = NPrime::named("lambda", l).unwrap();
                    for z in [n, 0.3 * n + 0.7 * f, f] {
                        let a = zhang_eq_local(&v, lv, z).unwrap();
                        assert_eq!(a.to_bits(), zhang_eq_local_unchecked(n, f, l, z).to_bits());
                        let b = zhang_ep_local(&v, lv, z).unwrap();
                        let bu = zhang_ep_local_unchecked(n, f, t, l, z);
                        assert_eq!(b.to_bits(), bu.to_bits());
                        for g in [
                            0.0,
                            0.5 * phi,
                            phi,
                            0.5 * (phi + 1.5),
                            1.5,
                            std::f64::consts::FRAC_PI_2,
                        ] {
                            let la = LightAngle::new(g).unwrap();
                            let h = z * t * (1.0 + 1e-12);
                            for y in [-h, -0.5 * z * t, 0.0, 0.9 * z * t, h] {
                                let c = zhang_eq(&v, lv, la, y, z).unwrap();
                                let cu = zhang_eq_unchecked(n, f, phi, t, l, g, y, z);
                                assert_eq!(
                                    c.to_bits(),
                                    cu.to_bits(),
                                    "{n} {f} {phi} {l} {g} {y} {z}"
                                );
                                let d = zhang_ep(&v, lv, la, y, z).unwrap();
                                let du = zhang_ep_unchecked(n, f, phi, t, l, g, y, z);
                                assert_eq!(
                                    d.to_bits(),
                                    du.to_bits(),
                                    "{n} {f} {phi} {l} {g} {y} {z}"
                                );
                                cases += 1;
                            }
                        }
                    }
                }
            }
        }
        assert_eq!(cases, 4 * 4 * 5 * 3 * 6 * 5);
        // By hand (Eq 8, 9): n = 1, f = 100, λ = 11, z = 10, tan φ = 1 (φ = π/4):
        // E_q = 2 · 100 · 20 / (110 · 10), E_p = 99 · 400 / (110 · 11 · 10).
        let t = std::f64::consts::FRAC_PI_4.tan();
        assert!((zhang_eq_local_unchecked(1.0, 100.0, 11.0, 10.0) - 4000.0 / 1100.0).abs() < 1e-14);
        let ep = zhang_ep_local_unchecked(1.0, 100.0, t, 11.0, 10.0);
        assert!((ep - 39600.0 / 12100.0 / t).abs() < 1e-13);
        // λ < n: 2 n (z − n + λ)/(λ z) = 2 · 9.5 / 5 at n = 1, λ = 0.5, z = 10.
        assert!((zhang_eq_local_unchecked(1.0, 100.0, 0.5, 10.0) - 3.8).abs() < 1e-14);
    }
}
