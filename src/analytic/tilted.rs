//! A light tilted in the view's vertical plane: Barroso & Celes 2007 §3.1, the generalised
//! LiSPSM error m_z(z, n′, γ) (Eq 10–12), the warp parameters that equalise it on the near and
//! far planes (Eq 13), the limit angle γ_lim (Eq 15) and the generalised n′ (Eq 16–18).
//!
//! # Geometry and notation
//!
//! The view frustum has near and far depths n, f and half field of view φ_y (the crate's
//! `half_fov`; square image); `a = n tan φ_y`, `b = f tan φ_y` are the half heights of its near
//! and far planes. The light lies in the view's vertical plane at the angle γ ∈ [0, π/2] from the
//! view axis (`light_angle`; π/2 overhead). The warping frustum looks along the view direction
//! projected perpendicular to the light, z′ is the warp depth of a point measured from the
//! warp's centre of projection c, and n′ the distance from c to the frustum's nearest extent
//! (Barroso Fig 6; [`crate::measure::tilted_twin`] builds it as a matrix).
//!
//! # Which m_z
//!
//! Barroso measures the texel width **along the view axis** (his Eq 6, `(dt/dz)⁻¹` with z the
//! position on the view axis); the crate's measurement [`crate::measure::point_error`] and Lloyd
//! 2006 §4.4 measure it **perpendicular to the light** (the distance between t-isolines). Along
//! the view axis, `dz′/dz = sin γ`, so
//!
//! `m_z(Barroso) = m_z(perpendicular) / sin γ`.
//!
//! [`tilted_mz`] is Barroso's (the eval contract's `tilted_mz`), [`tilted_mz_perpendicular`] the
//! perpendicular one; they agree overhead. The factor does not change where the error is largest
//! nor the n′ that equalises it (Eq 13), but it is a projection factor (Barroso's own Eq 3 calls
//! `cos θ_c / cos θ_L` projection aliasing and excludes it), and it makes Barroso's m_z infinite as
//! γ → 0 where the perpendicular error stays finite. See docs/errata.md.
//!
//! ```
//! use shadow_aliasing::analytic::tilted::{generalized_n_prime, tilted_mz, Falloff, gamma_lim};
//! use shadow_aliasing::{LightAngle, NPrime, Resolutions, ViewFrustum};
//! let view = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_6)?;
//! // Overhead, the generalised n′ is LiSPSM's n + √(f n) = 11.
//! let overhead = LightAngle::new(std::f64::consts::FRAC_PI_2)?;
//! assert!((generalized_n_prime(&view, overhead, Falloff::Barroso).value() - 11.0).abs() < 1e-12);
//! // Below γ_lim it grows, and it is unwarped when light and view are parallel.
//! assert_eq!(generalized_n_prime(&view, LightAngle::new(0.0)?, Falloff::Zhang), NPrime::UNWARPED);
//! assert!(gamma_lim(&view) > view.half_fov());
//! let m = tilted_mz(&view, NPrime::finite(11.0)?, overhead, 1.0, Resolutions::default())?;
//! assert!(m > 0.0);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::error::{
    finite_result, fmt_num, in_closed, positive, positive_result, Error, ResRatio, Result,
};
use crate::frustum::{LightAngle, NPrime, Resolutions, ViewFrustum};
use crate::numeric::sqrt_fn;
use std::hint::select_unpredictable as select;

/// Validates a depth on the view axis, `near ≤ z ≤ far`.
#[inline]
pub(crate) fn depth_in_view(view: &ViewFrustum, z: f64) -> Result<f64> {
    in_closed("z", z, view.near(), view.far())
}

/// μ = f′ − n′, the extent of the view frustum along the warp axis for a light at γ from the
/// view axis (Barroso Eq 11 minus n′; Zhang et al. 2009 Appendix, μ):
///
/// `μ = (a + b) cos γ + (f − n) sin γ` for φ_y ≤ γ ≤ π/2, `μ = 2 b cos γ` for 0 ≤ γ < φ_y,
///
/// with n, f the near and far depths, φ_y the half field of view, `a = n tan φ_y`,
/// `b = f tan φ_y` (all in eye-space units). μ > 0 for every valid input; the two branches agree
/// at γ = φ_y (both are 2 f sin φ_y), so μ is continuous. Unit: eye-space distance.
///
/// Evaluated as `f · ((1 + n/f) · tan φ_y cos γ) + (f − n) sin γ`, so that a large `b` with a
/// small `cos γ` does not overflow on the way.
///
/// # Errors
/// [`Error::Degenerate`] when μ itself overflows an `f64` (f tan φ_y beyond about 1e308).
///
/// ```
/// # use shadow_aliasing::{analytic::tilted::warp_depth_range, LightAngle, ViewFrustum};
/// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
/// // Overhead the extent is the frustum's depth range f − n.
/// let mu = warp_depth_range(&view, LightAngle::new(std::f64::consts::FRAC_PI_2)?)?;
/// assert!((mu - 99.0).abs() < 1e-12);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
#[inline]
pub fn warp_depth_range(view: &ViewFrustum, light_angle: LightAngle) -> Result<f64> {
    let (s, c) = light_angle.radians().sin_cos();
    warp_depth_range_sc(view, light_angle, s, c)
}

/// [`warp_depth_range`] with `(s, c) = light_angle.radians().sin_cos()` already taken.
#[inline]
pub(crate) fn warp_depth_range_sc(
    view: &ViewFrustum,
    light_angle: LightAngle,
    s: f64,
    c: f64,
) -> Result<f64> {
    let upper = light_angle.radians() >= view.half_fov();
    finite_result(
        "mu",
        mu_unchecked(view.near(), view.far(), view.tan_half_fov(), upper, s, c),
    )
}

/// μ of [`warp_depth_range_sc`] without validation, both branches computed and one selected
/// without a jump (so that the twins' array loops vectorise): `upper` is γ ≥ φ_y.
#[inline(always)]
pub(crate) fn mu_unchecked(
    near: f64,
    far: f64,
    tan_half_fov: f64,
    upper: bool,
    s: f64,
    c: f64,
) -> f64 {
    let (n, f) = (near, far);
    let tc = tan_half_fov * c;
    select(
        upper,
        f * ((1.0 + n / f) * tc) + (f - n) * s,
        f * (2.0 * tc),
    )
}

/// ψ(z, n′, γ) = z′, the warp depth of the point at depth z on the view axis (Barroso Eq 10 and
/// the ψ of Eq 12):
///
/// `ψ = n′ + a cos γ + (z − n) sin γ` for φ_y ≤ γ ≤ π/2,
/// `ψ = n′ + b cos γ + (z − f) sin γ` for 0 ≤ γ < φ_y,
///
/// with `a = n tan φ_y`, `b = f tan φ_y`, n′ the warp parameter (eye-space units, any n′ > 0).
/// Unit: eye-space distance.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `n_prime` (not finite and positive) or `z` (outside
/// `[near, far]`).
#[inline]
pub fn tilted_psi(
    view: &ViewFrustum,
    n_prime: f64,
    light_angle: LightAngle,
    z: f64,
) -> Result<f64> {
    let np = positive("n_prime", n_prime)?;
    let z = depth_in_view(view, z)?;
    finite_result("psi", np + psi_offset(view, light_angle, z))
}

/// ψ − n′: the point's warp depth from the frustum's nearest extent.
#[inline]
fn psi_offset(view: &ViewFrustum, light_angle: LightAngle, z: f64) -> f64 {
    let (s, c) = light_angle.radians().sin_cos();
    let upper = light_angle.radians() >= view.half_fov();
    psi_offset_parts(
        view.near(),
        view.far(),
        view.tan_half_fov() * c,
        upper,
        s,
        z,
    )
}

/// ψ − n′ of [`psi_offset`] from its parts (`upper`: γ ≥ φ_y, `tc` = tan φ_y cos γ, `s` = sin γ),
/// both branches computed and one selected without a jump.
#[inline(always)]
fn psi_offset_parts(n: f64, f: f64, tc: f64, upper: bool, s: f64, z: f64) -> f64 {
    select(upper, n * tc + (z - n) * s, f * tc + (z - f) * s)
}

/// ξ(n′, γ), the factor of Barroso's m_z (Eq 12):
///
/// `ξ = (res_i / res_t) · 1/(2 tan φ_y) · (f′ − n′)/(n′ f′) · 1/sin γ`, with `f′ − n′ = μ`
/// ([`warp_depth_range`], Eq 11) and `f′ = n′ + μ`.
///
/// Domain: n′ > 0, 0 < γ ≤ π/2. Unit: 1 / eye-space distance.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `n_prime` (not finite and positive), `light_angle`
/// (γ = 0, where ξ is infinite: t does not change along the view axis), or
/// `res_image` and `res_t` when they scale the value, which is positive, below f64's normal
/// range (0 or a subnormal is never returned; the message estimates the value and says how to
/// get it); [`Error::Degenerate`] when μ or ξ overflows.
#[inline]
pub fn tilted_xi(
    view: &ViewFrustum,
    n_prime: f64,
    light_angle: LightAngle,
    res: Resolutions,
) -> Result<f64> {
    let np = positive("n_prime", n_prime)?;
    let s = positive_sin(light_angle)?;
    let mu = warp_depth_range(view, light_angle)?;
    let xi = |ratio: f64| ratio / (2.0 * view.tan_half_fov()) * mu / (np * (np + mu)) / s;
    positive_result("xi", xi(res.image() / res.t()), res_t(res), || xi(1.0))
}

/// The resolutions of an m_z: `res_image / res_t`.
#[inline]
fn res_t(res: Resolutions) -> ResRatio {
    ResRatio::new(res.image(), "res_t", res.t())
}

#[inline]
fn positive_sin(light_angle: LightAngle) -> Result<f64> {
    let s = light_angle.radians().sin();
    if s > 0.0 {
        Ok(s)
    } else {
        Err(parallel_light(light_angle))
    }
}

#[cold]
#[inline(never)]
fn parallel_light(light_angle: LightAngle) -> Error {
    Error::invalid(
        "light_angle",
        format!(
            "must be greater than 0 for Barroso's m_z, which measures texels along the view axis and is infinite when light and view are parallel (got {})",
            fmt_num(light_angle.radians())
        ),
    )
}

/// The perpendicular m_z of [`tilted_mz_perpendicular`] from its parts, every branch computed and
/// selected without a jump: `upper` is γ ≥ φ_y, `(s, c)` the sine and cosine of γ, n′ = ∞
/// unwarped, `res` = res_i/res_t.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn mz_perp_parts(
    n: f64,
    f: f64,
    t: f64,
    upper: bool,
    (s, c): (f64, f64),
    np: f64,
    z: f64,
    res: f64,
) -> f64 {
    let mu = mu_unchecked(n, f, t, upper, s, c);
    let k = res / (2.0 * t) * mu / z;
    let psi = np + psi_offset_parts(n, f, t * c, upper, s, z);
    // ψ²/(n′(n′ + μ)), written so that it stays accurate for large n′.
    select(np == f64::INFINITY, k, k * (psi / np) * (psi / (np + mu)))
}

/// Barroso & Celes's generalised error in the z direction for a tilted light (Eq 12), the texel
/// width measured along the view axis (Eq 6) over the pixel width, at depth z on the view axis:
///
/// `m_z(z, n′, γ) = ξ(n′, γ) ψ(z, n′, γ)² / z`
/// `= (res_i/res_t) · (f′ − n′) ψ² / (2 tan φ_y · n′ f′ · z · sin γ)`,
///
/// with ψ the warp depth ([`tilted_psi`], Eq 10), `f′ − n′ = μ` ([`warp_depth_range`], Eq 11),
/// φ_y the half field of view, res_i the image and res_t the shadow map's t resolution. For the
/// unwarped map (n′ = ∞) the limit `(res_i/res_t) μ / (2 tan φ_y z sin γ)`.
/// At γ = π/2 this is Lloyd 2006 Eq 8. It equals [`tilted_mz_perpendicular`] / sin γ (module docs).
///
/// Domain: `0 < γ ≤ π/2`, `near ≤ z ≤ far`, any n′ > 0 or unwarped. Dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_angle` (γ = 0, where this along-axis width is
/// infinite), `z` (outside `[near, far]`), or
/// `res_image` and `res_t` when they scale the value, which is positive, below f64's normal
/// range (0 or a subnormal is never returned; the message estimates the value and says how to
/// get it);
/// [`Error::Degenerate`] when the value (or μ) overflows.
///
/// ```
/// # use shadow_aliasing::{analytic::tilted::tilted_mz, LightAngle, NPrime, Resolutions, ViewFrustum};
/// let view = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_4)?;
/// let up = LightAngle::new(std::f64::consts::FRAC_PI_2)?;
/// // Overhead with n′ = n (PSM): m_z = (f − n) z / (2 tan θ · f n) = 99·50/200 at z = 50.
/// let m = tilted_mz(&view, NPrime::finite(1.0)?, up, 50.0, Resolutions::default())?;
/// assert!((m - 99.0 * 50.0 / 200.0).abs() < 1e-12);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
#[inline]
pub fn tilted_mz(
    view: &ViewFrustum,
    n_prime: NPrime,
    light_angle: LightAngle,
    z: f64,
    res: Resolutions,
) -> Result<f64> {
    positive_sin(light_angle)?;
    let z = depth_in_view(view, z)?;
    // μ's own error first (an overflow), then the value from the twin, which takes μ again.
    warp_depth_range(view, light_angle)?;
    let m = |ri: f64, rt: f64| {
        tilted_mz_unchecked(
            view.near(),
            view.far(),
            view.half_fov(),
            view.tan_half_fov(),
            n_prime.value(),
            light_angle.radians(),
            z,
            ri,
            rt,
        )
    };
    positive_result("m_z", m(res.image(), res.t()), res_t(res), || m(1.0, 1.0))
}

/// [`tilted_mz`] without validation (Barroso Eq 10–12, `m_z = (res_i/res_t) · μ ψ² / (2 tan φ_y
/// · n′ (n′ + μ) · z · sin γ)`, `(res_i/res_t) μ / (2 tan φ_y z sin γ)` for n′ = ∞), for callers
/// that have checked the domain themselves (the Python bindings' array path): n = `near`,
/// f = `far`, φ_y = `half_fov` with tan φ_y = `tan_half_fov` (as
/// [`ViewFrustum::tan_half_fov`] computes it), n′ = `n_prime` as an `f64` (`f64::INFINITY`
/// unwarped), γ = `light_angle` in radians.
///
/// Equal, bit for bit, to [`tilted_mz`] wherever `tilted_mz` returns `Ok` (which computes its
/// value here); meaningless outside that domain (where μ overflows the value is not finite).
#[inline(always)]
#[must_use]
#[allow(clippy::too_many_arguments)]
pub fn tilted_mz_unchecked(
    near: f64,
    far: f64,
    half_fov: f64,
    tan_half_fov: f64,
    n_prime: f64,
    light_angle: f64,
    z: f64,
    res_image: f64,
    res_t: f64,
) -> f64 {
    // Every branch, then selects without a jump (`select_unpredictable`), so that a loop over
    // arrays vectorises: the perpendicular m_z (`mz_perp_parts`) over sin γ.
    let sc = light_angle.sin_cos();
    let upper = light_angle >= half_fov;
    mz_perp_parts(
        near,
        far,
        tan_half_fov,
        upper,
        sc,
        n_prime,
        z,
        res_image / res_t,
    ) / sc.0
}

/// The tilted-light m_z measured perpendicular to the light, as the crate measures every map
/// ([`crate::measure::point_error`], Lloyd 2006 §4.4): Barroso's Eq 12 times sin γ,
///
/// `m_z⊥(z, n′, γ) = (res_i/res_t) · μ ψ² / (2 tan φ_y · n′ (n′ + μ) · z)`,
///
/// on the view axis at depth z (symbols as in [`tilted_mz`]); unwarped,
/// `(res_i/res_t) μ / (2 tan φ_y z)`. Zhang et al.'s E_p^pers at y = 0 is twice this with unit
/// resolutions. Defined for every γ ∈ [0, π/2].
///
/// # Errors
/// [`Error::InvalidArgument`] naming `z` (outside `[near, far]`), or
/// `res_image` and `res_t` when they scale the value, which is positive, below f64's normal
/// range (0 or a subnormal is never returned; the message estimates the value and says how to
/// get it); [`Error::Degenerate`] when the value (or μ) overflows.
#[inline]
pub fn tilted_mz_perpendicular(
    view: &ViewFrustum,
    n_prime: NPrime,
    light_angle: LightAngle,
    z: f64,
    res: Resolutions,
) -> Result<f64> {
    let z = depth_in_view(view, z)?;
    // μ's own error (an overflow) first; the parts take μ again.
    warp_depth_range(view, light_angle)?;
    let sc = light_angle.radians().sin_cos();
    let upper = light_angle.radians() >= view.half_fov();
    let (n, f, t) = (view.near(), view.far(), view.tan_half_fov());
    let m = |ratio: f64| mz_perp_parts(n, f, t, upper, sc, n_prime.value(), z, ratio);
    positive_result("m_z", m(res.image() / res.t()), res_t(res), || m(1.0))
}

/// Barroso's n′₁(γ) (Eq 13, first branch): the n′ that makes m_z equal on the near and far
/// planes when the near-bottom corner is the frustum's nearest point to the warp's centre of
/// projection (φ_y ≤ γ ≤ π/2):
///
/// `n′₁(γ) = (n + √(f n)) sin γ − a cos γ`, `a = n tan φ_y`.
///
/// At γ = π/2 this is LiSPSM's n + √(f n). The formula is evaluated for any γ ∈ [0, π/2]; it is
/// negative for small γ, where no warp satisfies the constraint. Unit: eye-space distance.
///
/// Always finite: a [`ViewFrustum`] keeps n + √(f n) and n tan φ_y ≤ f tan φ_y finite, and
/// `A sin γ − B cos γ` with finite A, B ≥ 0 lies in [−B, A]. So there is no error to return.
#[inline]
#[must_use]
pub fn n_prime_1(view: &ViewFrustum, light_angle: LightAngle) -> f64 {
    let (s, c) = light_angle.radians().sin_cos();
    (view.n_prime_lispsm() * s) - view.near() * (view.tan_half_fov() * c)
}

/// n′₁(γ_lim) in closed form, without the rounding of γ_lim and cos γ_lim near π/2:
/// with ρ = n/f, t = tan φ_y, tan γ_lim = (1 + ρ) t / (1 − ρ),
/// `n′₁(γ_lim) = f t (2ρ² + √ρ (1 + ρ)) / hypot(1 − ρ, (1 + ρ) t)`, always > 0.
#[inline]
fn n_prime_1_at_lim(view: &ViewFrustum) -> f64 {
    let (n, f, t) = (view.near(), view.far(), view.tan_half_fov());
    let rho = n / f;
    let d = (f - n) / f;
    f * (t * (2.0 * rho * rho + rho.sqrt() * (1.0 + rho)) / d.hypot((1.0 + rho) * t))
}

/// Barroso's n′₂(γ) (Eq 13, second branch), for 0 < γ < φ_y, where the far-bottom corner is
/// nearest the centre of projection:
///
/// `n′₂(γ) = (f + √(f n)) sin γ − b cos γ`, `b = f tan φ_y`.
///
/// Negative for light near parallel to the view (Barroso's remark after Eq 13), and for every
/// γ below `atan(b / (f + √(fn)))`. Unit: eye-space distance.
///
/// # Errors
/// [`Error::Degenerate`] when the value overflows an `f64` (f tan φ_y or f + √(f n) beyond
/// about 1e308).
#[inline]
pub fn n_prime_2(view: &ViewFrustum, light_angle: LightAngle) -> Result<f64> {
    let (n, f) = (view.near(), view.far());
    let (s, c) = light_angle.radians().sin_cos();
    finite_result(
        "n_prime",
        (f + sqrt_fn(n, f)) * s - f * (view.tan_half_fov() * c),
    )
}

/// The n′ of Barroso Eq 13: n′₁ for φ_y ≤ γ ≤ π/2, n′₂ for γ < φ_y; the warp parameter for which
/// the tilted m_z on the view axis is equal on the near and far planes, which minimises its
/// maximum over `[near, far]` (m_z ∝ ψ²/z has a single minimum).
///
/// Unit: eye-space distance.
///
/// # Errors
/// [`Error::NoSolution`] where that n′ is not positive (light near parallel to the view): no
/// warp equalises the errors there; [`Error::Degenerate`] when it overflows.
pub fn n_prime_equal_error(view: &ViewFrustum, light_angle: LightAngle) -> Result<NPrime> {
    let v = if light_angle.radians() >= view.half_fov() {
        n_prime_1(view, light_angle)
    } else {
        n_prime_2(view, light_angle)?
    };
    if v > 0.0 {
        NPrime::new(v)
    } else {
        Err(Error::NoSolution(format!(
            "no warp makes m_z equal on the near and far planes at light_angle={}: Barroso's Eq 13 gives n_prime={} ≤ 0",
            fmt_num(light_angle.radians()),
            fmt_num(v)
        )))
    }
}

/// The n′ that minimises the maximum of the tilted m_z over the view axis, `max(m_z(n), m_z(f))`
/// (the quantity Barroso's Eq 13 sets out to minimise), for every γ ∈ [0, π/2]:
///
/// `n′_opt = max(n′_eq, n′*)`, `n′* = d μ / (μ − 2 d)`,
///
/// with n′_eq Barroso's equal-error n′ (n′₁ or n′₂ of Eq 13, [`n_prime_equal_error`]; ignored
/// where it is not positive), μ the frustum's extent along the warp axis ([`warp_depth_range`])
/// and `d = ψ(n) − n′` the near point's warp depth from the nearest extent (`a cos γ` for
/// γ ≥ φ_y, `b cos γ − (f − n) sin γ` below). Reason: m_z(f) decreases in n′ everywhere, while
/// m_z(n) ∝ (n′ + d)²/(n′(n′ + μ)) decreases up to its stationary point n′* and increases after
/// it; m_z(n) > m_z(f) exactly for n′ > n′_eq. So the equal-error n′ is the optimum only when
/// n′* ≤ n′_eq; otherwise the optimum is n′*, with m_z(n) > m_z(f) there. At γ = 0, n′* = ∞
/// ([`NPrime::UNWARPED`]). Overhead, n′_opt = n + √(f n) (LiSPSM).
///
/// Unit: eye-space distance. Inputs are validated types, so this cannot fail; where μ or the
/// optimum overflows an `f64` (frusta beyond about 1e308 across) the answer is
/// [`NPrime::UNWARPED`], the limit n′ → ∞.
///
/// ```
/// # use shadow_aliasing::{analytic::tilted::{n_prime_axis_minimax, n_prime_2}, LightAngle, ViewFrustum};
/// let view = ViewFrustum::new(1.0, 100.0, std::f64::consts::FRAC_PI_6)?;
/// let g = LightAngle::new(28f64.to_radians())?;
/// // Barroso's n′₂ = 0.665 equalises the errors, but n′ = 4.935 has a lower maximum.
/// assert!((n_prime_2(&view, g)? - 0.66487).abs() < 1e-4);
/// assert!((n_prime_axis_minimax(&view, g).value() - 4.9349).abs() < 1e-4);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
#[must_use]
pub fn n_prime_axis_minimax(view: &ViewFrustum, light_angle: LightAngle) -> NPrime {
    let Ok(mu) = warp_depth_range(view, light_angle) else {
        return NPrime::UNWARPED;
    };
    let d = psi_offset(view, light_angle, view.near()).max(0.0);
    let den = mu - 2.0 * d;
    let star = if den > 0.0 {
        d * (mu / den)
    } else {
        f64::INFINITY
    };
    let eq = if light_angle.radians() >= view.half_fov() {
        Ok(n_prime_1(view, light_angle))
    } else {
        n_prime_2(view, light_angle)
    };
    // An overflowing n′_eq is larger than any finite n′*.
    let v = star.max(eq.unwrap_or(f64::INFINITY));
    NPrime::finite_or_unwarped(v)
}

/// Barroso's limit angle (Eq 15), where the near and far faces of the view frustum begin to
/// overlap in the light's view:
///
/// `γ_lim = atan((a + b)/(f − n)) = atan((f + n) tan φ_y / (f − n))`, radians.
///
/// Always in (φ_y, π/2]: the limit lies above the half field of view, as Barroso requires
/// (it rounds to π/2 only when tan φ_y (f + n)/(f − n) exceeds about 1e16). Evaluated as
/// `atan((1 + n/f) tan φ_y / ((f − n)/f))`, which cannot overflow on the way.
#[inline]
#[must_use]
pub fn gamma_lim(view: &ViewFrustum) -> f64 {
    gamma_lim_unchecked(view.near(), view.far(), view.tan_half_fov())
}

/// [`gamma_lim`] on bare numbers (Barroso Eq 15, `γ_lim = atan((f + n) tan φ_y / (f − n))`,
/// evaluated as `atan((1 + n/f) tan φ_y / ((f − n)/f))`), for callers that have checked the
/// view frustum's domain themselves (the Python bindings' array path): n = `near`, f = `far`,
/// tan φ_y = `tan_half_fov` (as [`ViewFrustum::tan_half_fov`] computes it).
///
/// Equal, bit for bit, to [`gamma_lim`] of `ViewFrustum::new(near, far, φ_y)` wherever that
/// frustum is valid (which computes its value here); meaningless otherwise. Radians.
#[inline(always)]
#[must_use]
pub fn gamma_lim_unchecked(near: f64, far: f64, tan_half_fov: f64) -> f64 {
    let (n, f) = (near, far);
    ((1.0 + n / f) * tan_half_fov / ((f - n) / f)).atan()
}

/// The fall-off r(γ) of Barroso's generalised n′ below γ_lim (Eq 16–18).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Falloff {
    /// Zhang et al.'s `r(γ) = sin((γ/γ_lim) · π/2)` (Barroso Eq 17).
    Zhang,
    /// Barroso's faster `r(γ) = [1 + sin((γ/γ_lim − 1) · π/2)]²` (Eq 18).
    Barroso,
}

impl std::str::FromStr for Falloff {
    type Err = Error;

    /// Parses the eval contract's names, `"zhang"` (Eq 17) and `"barroso"` (Eq 18).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `falloff` for any other string.
    fn from_str(s: &str) -> Result<Self> {
        match s {
            "zhang" => Ok(Falloff::Zhang),
            "barroso" => Ok(Falloff::Barroso),
            other => Err(Error::invalid(
                "falloff",
                format!("must be \"barroso\" or \"zhang\" (got \"{other}\")"),
            )),
        }
    }
}

/// r(γ) for γ ∈ [0, γ_lim] (Barroso Eq 17, 18): 1 at γ_lim, 0 at γ = 0, increasing between.
///
/// Eq 18 is evaluated as `4 sin⁴(γ π / (4 γ_lim))`, the same function
/// (`1 + sin(x − π/2) = 1 − cos x = 2 sin²(x/2)`) without cancellation near γ = 0.
/// γ = `light_angle` and γ_lim = `gamma_lim` in radians. Arguments outside `[0, γ_lim]` are
/// clamped into it (NaN counts as 0); a γ_lim that is not positive gives r = 1. Total: the result
/// lies in [0, 1] for every input.
#[inline]
#[must_use]
pub fn falloff_r(falloff: Falloff, light_angle: f64, gamma_lim: f64) -> f64 {
    let u = if gamma_lim > 0.0 {
        (light_angle / gamma_lim).clamp(0.0, 1.0)
    } else {
        1.0
    };
    let u = if u.is_nan() { 0.0 } else { u };
    match falloff {
        Falloff::Zhang => (u * std::f64::consts::FRAC_PI_2).sin(),
        Falloff::Barroso => {
            let h = (u * std::f64::consts::FRAC_PI_4).sin();
            4.0 * h * h * h * h
        }
    }
}

/// Barroso & Celes's generalised LiSPSM parameter (Eq 16):
///
/// `n′ = n′₁(γ) = (n + √(f n)) sin γ − a cos γ` for γ_lim ≤ γ ≤ π/2,
/// `n′ = n′₁(γ_lim) / r(γ)` for 0 ≤ γ < γ_lim,
///
/// with γ_lim from [`gamma_lim`] (Eq 15), r from [`falloff_r`] (Eq 17 or 18), `a = n tan φ_y`.
/// Continuous at γ_lim (r = 1); at γ = 0 (r = 0) it is [`NPrime::UNWARPED`], and wherever the
/// quotient overflows. Unit: eye-space distance. n′₁(γ_lim) > 0 always, so n′ > 0; it is
/// evaluated in closed form (`f t (2ρ² + √ρ (1 + ρ)) / hypot(1 − ρ, (1 + ρ) t)`, ρ = n/f,
/// t = tan φ_y) so that the rounding of γ_lim near π/2 cannot cancel it to 0.
///
/// All inputs are validated types, so this cannot fail; where n′ overflows an `f64` (frusta
/// beyond about 1e308) the answer is [`NPrime::UNWARPED`], the limit n′ → ∞.
#[must_use]
pub fn generalized_n_prime(
    view: &ViewFrustum,
    light_angle: LightAngle,
    falloff: Falloff,
) -> NPrime {
    let gl = gamma_lim(view);
    let g = light_angle.radians();
    if g >= gl {
        return NPrime::finite_or_unwarped(n_prime_1(view, light_angle));
    }
    let at_lim = n_prime_1_at_lim(view);
    let r = falloff_r(falloff, g, gl);
    NPrime::finite_or_unwarped(at_lim / r)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`tilted_mz_unchecked`] and [`gamma_lim_unchecked`] give [`tilted_mz`]'s and
    /// [`gamma_lim`]'s values bit for bit wherever those return `Ok`: n′ below near, above it and
    /// unwarped; γ just above 0, below φ_y, at it, above it and π/2; z on both planes and inside;
    /// resolutions other than one.
    #[test]
    fn unchecked_twins_agree() {
        let mut cases = 0;
        for &(n, f) in &[(1.0, 100.0), (0.1, 0.3), (2.5, 4e5), (1e-3, 1e6)] {
            for &phi in &[0.01, 0.5, std::f64::consts::FRAC_PI_4, 1.5] {
                let v = ViewFrustum::new(n, f, phi).unwrap();
                let t = v.tan_half_fov();
                assert_eq!(
                    gamma_lim(&v).to_bits(),
                    gamma_lim_unchecked(n, f, t).to_bits()
                );
                for np in [0.25 * n, n, v.n_prime_lispsm(), 1e3 * f, f64::INFINITY] {
                    let npv = NPrime::new(np).unwrap();
                    for g in [
                        1e-300,
                        0.5 * phi,
                        phi,
                        0.5 * (phi + 1.5),
                        std::f64::consts::FRAC_PI_2,
                    ] {
                        let la = LightAngle::new(g).unwrap();
                        for &(ri, rt) in &[(1.0, 1.0), (1920.0, 700.0)] {
                            let r = Resolutions::new(ri, 1.0, rt).unwrap();
                            for z in [n, 0.3 * n + 0.7 * f, f] {
                                let Ok(a) = tilted_mz(&v, npv, la, z, r) else {
                                    // Only an overflow at γ → 0 (1/sin γ) is refused here.
                                    assert!(g < 1e-200);
                                    continue;
                                };
                                let au = tilted_mz_unchecked(n, f, phi, t, np, g, z, ri, rt);
                                assert_eq!(a.to_bits(), au.to_bits(), "{n} {f} {phi} {np} {g} {z}");
                                cases += 1;
                            }
                        }
                    }
                }
            }
        }
        assert!(cases >= 4 * 4 * 5 * 4 * 2 * 3, "{cases}");
        // Overhead with n′ = n (PSM): (f − n) z / (2 tan θ f n) = 99 · 50/200 at z = 50, θ = π/4.
        let t = std::f64::consts::FRAC_PI_4.tan();
        let m = tilted_mz_unchecked(
            1.0,
            100.0,
            std::f64::consts::FRAC_PI_4,
            t,
            1.0,
            std::f64::consts::FRAC_PI_2,
            50.0,
            1.0,
            1.0,
        );
        assert!((m - 99.0 * 50.0 / 200.0 / t).abs() < 1e-12);
        // γ_lim = atan(101/99) at n = 1, f = 100, θ = π/4.
        assert!((gamma_lim_unchecked(1.0, 100.0, t) - (101.0f64 / 99.0 * t).atan()).abs() < 1e-15);
    }

    #[test]
    fn branches_meet_at_half_fov() {
        let view = ViewFrustum::new(2.0, 30.0, 0.4).unwrap();
        let at = LightAngle::new(0.4).unwrap();
        let below = LightAngle::new(0.4 - 1e-13).unwrap();
        let (m1, m2) = (
            warp_depth_range(&view, at).unwrap(),
            warp_depth_range(&view, below).unwrap(),
        );
        assert!((m1 - 2.0 * 30.0 * 0.4f64.sin()).abs() < 1e-9);
        assert!((m1 - m2).abs() < 1e-9);
        let (p1, p2) = (
            tilted_psi(&view, 3.0, at, 7.0).unwrap(),
            tilted_psi(&view, 3.0, below, 7.0).unwrap(),
        );
        assert!((p1 - p2).abs() < 1e-9);
    }

    #[test]
    fn falloff_names() {
        assert_eq!("zhang".parse::<Falloff>(), Ok(Falloff::Zhang));
        assert_eq!("barroso".parse::<Falloff>(), Ok(Falloff::Barroso));
        assert_eq!(
            "lloyd".parse::<Falloff>().unwrap_err().to_string(),
            "falloff must be \"barroso\" or \"zhang\" (got \"lloyd\")"
        );
    }

    #[test]
    fn falloffs_end_points() {
        for f in [Falloff::Zhang, Falloff::Barroso] {
            assert!((falloff_r(f, 0.7, 0.7) - 1.0).abs() < 1e-15);
            assert_eq!(falloff_r(f, 0.0, 0.7), 0.0);
        }
        // Eq 18 as printed, at a middle angle.
        let (g, gl) = (0.3f64, 0.7f64);
        let printed = (1.0 + ((g / gl - 1.0) * std::f64::consts::FRAC_PI_2).sin()).powi(2);
        assert!((falloff_r(Falloff::Barroso, g, gl) - printed).abs() < 1e-15);
    }

    #[test]
    fn domain_errors() {
        let view = ViewFrustum::new(1.0, 10.0, 0.5).unwrap();
        let g0 = LightAngle::new(0.0).unwrap();
        let e = tilted_mz(
            &view,
            NPrime::finite(2.0).unwrap(),
            g0,
            2.0,
            Resolutions::default(),
        );
        assert!(matches!(
            e,
            Err(Error::InvalidArgument {
                name: "light_angle",
                ..
            })
        ));
        let g = LightAngle::new(1.0).unwrap();
        assert!(NPrime::finite(-1.0).is_err());
        assert!(tilted_mz(
            &view,
            NPrime::finite(1.0).unwrap(),
            g,
            11.0,
            Resolutions::default()
        )
        .is_err());
        assert!(
            tilted_mz_perpendicular(&view, NPrime::UNWARPED, g0, 2.0, Resolutions::default())
                .is_ok()
        );
        assert!(matches!(
            n_prime_equal_error(&view, LightAngle::new(0.01).unwrap()),
            Err(Error::NoSolution(_))
        ));
    }
}
