//! The warp parameter n′ of a perspective shadow-map warp with the light overhead, and its
//! normalised form η ∈ [−1, 1].
//!
//! n′ is the distance from the warping frustum's centre of projection to the view frustum's
//! near plane (Lloyd 2006 Fig 3; Lloyd 2005's n with near = 1). η re-parameterises the
//! semi-infinite range n′ ∈ [n, ∞] onto [−1, 1] by the maximum z error M_z (Lloyd 2006 App. B,
//! Lloyd 2005 §3.2):
//!
//! | η | n′ | map |
//! |---|---|---|
//! | −1 | ∞ ([`NPrime::UNWARPED`]) | orthographic, M_z largest, on the near plane |
//! | 0 | n + √(f n) | LiSPSM: M_z smallest, equal on near and far planes |
//! | +1 | n | PSM: M_z largest again, on the far plane |
//!
//! ```
//! use shadow_aliasing::analytic::eta::{eta_from_n_prime, n_prime_from_eta};
//! use shadow_aliasing::NPrime;
//! let n0 = n_prime_from_eta(1.0, 100.0, 0.0)?;
//! assert_eq!(n0, NPrime::finite(11.0)?); // n + √(f n)
//! assert_eq!(n_prime_from_eta(1.0, 100.0, -1.0)?, NPrime::UNWARPED);
//! assert!((eta_from_n_prime(1.0, 100.0, n0)? - 0.0).abs() < 1e-15);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::error::{finite_result, fmt_num, in_closed, Error, Result};
use crate::frustum::{depth_range, NPrime};
use crate::numeric::{finite_select, sqrt_fn};
use std::hint::select_unpredictable as select;

/// Validates a depth range `0 < near < far`, both finite ([`depth_range`]), with f/n finite.
#[inline]
pub(crate) fn near_far(near: f64, far: f64) -> Result<(f64, f64)> {
    near_far_ratio(near, far).map(|(n, f, _)| (n, f))
}

/// [`near_far`] that also returns f/n, the quotient its check computes.
#[inline(always)]
pub(crate) fn near_far_ratio(near: f64, far: f64) -> Result<(f64, f64, f64)> {
    let (n, f) = depth_range(near, far)?;
    let alpha = f / n;
    if !alpha.is_finite() {
        return Err(ratio_not_finite(n, f));
    }
    Ok((n, f, alpha))
}

#[cold]
#[inline(never)]
fn ratio_not_finite(n: f64, f: f64) -> Error {
    Error::invalid(
        "far",
        format!(
            "must be small enough that far/near is finite (got near={}, far={})",
            fmt_num(n),
            fmt_num(f)
        ),
    )
}

/// Validates Lloyd's light-overhead domain n′ ≥ near; returns n′ or `None` for n′ = ∞.
#[inline]
pub(crate) fn n_prime_at_least(n_prime: NPrime, near: f64) -> Result<Option<f64>> {
    match n_prime.as_finite() {
        None => Ok(None),
        Some(v) if v < near => Err(n_prime_below_near(v, near)),
        Some(v) => Ok(Some(v)),
    }
}

#[cold]
#[inline(never)]
fn n_prime_below_near(v: f64, near: f64) -> Error {
    Error::invalid(
        "n_prime",
        format!(
            "must be at least near for a light overhead (got n_prime={}, near={})",
            fmt_num(v),
            fmt_num(near)
        ),
    )
}

/// LiSPSM's warp parameter for the light overhead: n′ = n + √(f n).
///
/// n = `near`, f = `far` (eye-space depths, any length unit); n′ in the same unit. It minimises
/// the maximum z error M_z, which it makes equal on the near and far planes (Wimmer et al. 2004;
/// Lloyd 2006 §4.1; Lloyd 2005 §3.1 n_opt = 1 + √α with near = 1).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `near` or `far` unless 0 < near < far, both finite.
#[inline]
pub fn n_prime_lispsm(near: f64, far: f64) -> Result<f64> {
    let (n, f) = near_far(near, far)?;
    finite_result("n_prime", n + sqrt_fn(n, f))
}

/// [`n_prime_lispsm`] without validation, n + √(f n) as one square root, for callers that have
/// checked the domain (the Python bindings' array path). Equal, bit for bit, to
/// [`n_prime_lispsm`] wherever it returns `Ok` and f·n is a normal `f64` (a subnormal or
/// overflowing product, which `n_prime_lispsm` takes as √f √n, is left to the checked form);
/// meaningless outside that domain.
#[inline(always)]
#[must_use]
pub fn n_prime_lispsm_unchecked(near: f64, far: f64) -> f64 {
    near + (far * near).sqrt()
}

/// PSM's warp parameter: n′ = n, the warping frustum's centre of projection at the eye
/// (Stamminger & Drettakis 2002; Lloyd 2006 §4.1). η = +1.
///
/// n′ in the unit of `near`.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `near` or `far` unless 0 < near < far, both finite.
#[inline]
pub fn n_prime_psm(near: f64, far: f64) -> Result<f64> {
    near_far(near, far).map(|(n, _)| n)
}

/// n′ from the normalised warp parameter η (Lloyd 2006 Eq 11; Lloyd 2005 Eq 4 times n).
///
/// ```text
/// n′(η) = n (√α + 1 − η (α − 1)) / (η + 1)   for −1 ≤ η ≤ 0
/// n′(η) = n (√α + 1) / (η √α + 1)             for  0 < η ≤ 1
/// α = f/n
/// ```
///
/// n = `near`, f = `far` (eye-space depths), η dimensionless. η = −1 gives n′ = ∞, returned as
/// [`NPrime::UNWARPED`]; so does an η so close to −1 that n′ overflows.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `near`, `far` (0 < near < far) or `eta` (∈ [−1, 1]).
pub fn n_prime_from_eta(near: f64, far: f64, eta: f64) -> Result<NPrime> {
    let (n, f) = near_far(near, far)?;
    let eta = in_closed("eta", eta, -1.0, 1.0)?;
    let v = n_prime_from_eta_unchecked(n, f, eta);
    if eta <= 0.0 {
        // n′ = ∞ for η = −1 and where it overflows: the unwarped map.
        Ok(NPrime::finite_or_unwarped(v))
    } else {
        // n′ ≥ n > 0 for η ∈ (0, 1].
        finite_result("n_prime", v).map(NPrime::finite_unchecked)
    }
}

/// [`n_prime_from_eta`] without validation, n′ as an `f64`: `f64::INFINITY` for η = −1 and
/// wherever n′ overflows for η ≤ 0 (the unwarped map). Equal, bit for bit, to
/// `n_prime_from_eta(..)?.value()` wherever that returns `Ok` (for η > 0 it requires a finite
/// result); meaningless outside the domain.
#[inline(always)]
#[must_use]
pub fn n_prime_from_eta_unchecked(near: f64, far: f64, eta: f64) -> f64 {
    let n = near;
    let alpha = far / n;
    let ra = alpha.sqrt();
    // Every branch, then selects without a jump, so that a loop over arrays vectorises.
    let below = n * ((ra + 1.0 - eta * (alpha - 1.0)) / (eta + 1.0));
    let below = select((eta == -1.0) | !finite_select(below), f64::INFINITY, below);
    let above = n * ((ra + 1.0) / (eta * ra + 1.0));
    select(eta <= 0.0, below, above)
}

/// η from n′, the inverse of [`n_prime_from_eta`] (Lloyd 2006 App. B; Lloyd 2005 §3.2 ξ with
/// n = n′/near).
///
/// App. B defines η by interpolating the maximum z error M_z (Eq 10) linearly between its
/// value at n′ = ∞ (η = −1), at n′_LSPSM = n + √(f n) (η = 0) and at n′ = n (η = 1). Solved:
///
/// ```text
/// η = (√α + 1 − ν) / (ν + α − 1)   for ν ≥ 1 + √α   (n′ ≥ n′_LSPSM)
/// η = (√α + 1 − ν) / (ν √α)        for 1 ≤ ν < 1 + √α
/// ν = n′/n, α = f/n;   η = −1 for n′ = ∞
/// ```
///
/// η is dimensionless.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `near`, `far` (0 < near < far) or `n_prime` (n′ ≥ near).
pub fn eta_from_n_prime(near: f64, far: f64, n_prime: NPrime) -> Result<f64> {
    let (n, f) = near_far(near, far)?;
    let Some(np) = n_prime_at_least(n_prime, n)? else {
        return Ok(-1.0);
    };
    Ok(eta_from_n_prime_unchecked(n, f, np))
}

/// [`eta_from_n_prime`] without validation, n′ as an `f64` (`f64::INFINITY` unwarped). Equal,
/// bit for bit, to [`eta_from_n_prime`] wherever it returns `Ok`; meaningless outside the domain.
#[inline(always)]
#[must_use]
pub fn eta_from_n_prime_unchecked(near: f64, far: f64, n_prime: f64) -> f64 {
    let (n, f, np) = (near, far, n_prime);
    let alpha = f / n;
    let ra = alpha.sqrt();
    let nu = np / n;
    // Every branch, then selects without a jump, so that a loop over arrays vectorises.
    let den = nu + alpha - 1.0;
    let far_side = select(
        finite_select(den),
        (ra + 1.0 - nu) / den,
        // Divided through by ν so that a huge ν cannot overflow.
        ((ra + 1.0) / nu - 1.0) / (1.0 + (alpha - 1.0) / nu),
    );
    let near_side = (ra + 1.0 - nu) / (nu * ra);
    let eta = select(nu >= 1.0 + ra, far_side, near_side);
    select(finite_select(nu), eta.clamp(-1.0, 1.0), -1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hand_values() {
        // α = 100: n′(0) = 11, n′(1) = 1, n′(−0.5) = (11 + 49.5)/0.5 = 121, n′(0.5) = 11/6.
        assert_eq!(
            n_prime_from_eta(1.0, 100.0, 0.0),
            Ok(NPrime::finite(11.0).unwrap())
        );
        assert_eq!(
            n_prime_from_eta(1.0, 100.0, 1.0),
            Ok(NPrime::finite(1.0).unwrap())
        );
        assert_eq!(
            n_prime_from_eta(1.0, 100.0, -0.5),
            Ok(NPrime::finite(121.0).unwrap())
        );
        let h = n_prime_from_eta(2.0, 200.0, 0.5).unwrap().value();
        assert!((h - 2.0 * 11.0 / 6.0).abs() < 1e-14);
        assert_eq!(
            eta_from_n_prime(1.0, 100.0, NPrime::finite(121.0).unwrap()),
            Ok(-0.5)
        );
        assert_eq!(eta_from_n_prime(1.0, 100.0, NPrime::UNWARPED), Ok(-1.0));
        assert!(eta_from_n_prime(1.0, 100.0, NPrime::finite(0.5).unwrap()).is_err());
        assert!(n_prime_from_eta(1.0, 100.0, 1.5).is_err());
        assert_eq!(n_prime_lispsm(1.0, 100.0), Ok(11.0));
        assert_eq!(n_prime_psm(3.0, 100.0), Ok(3.0));
    }

    /// The `*_unchecked` twins give the checked forms' values bit for bit over their domain,
    /// both branches of Eq 11 and of its inverse, the unwarped ends and n′ overflowing to ∞.
    #[test]
    fn unchecked_twins_agree() {
        for &(n, f) in &[
            (1.0, 100.0),
            (0.1, 0.3),
            (2.5, 4e5),
            (1e-3, 1e6),
            (1e300, 1e308),
        ] {
            let l = n_prime_lispsm(n, f).unwrap();
            // The twin's precondition: f·n normal (1e300 · 1e308 overflows: the checked form's).
            if (f * n).is_normal() {
                assert_eq!(l.to_bits(), n_prime_lispsm_unchecked(n, f).to_bits());
            }
            for eta in [-1.0, -1.0 + 1e-300, -0.999, -0.5, 0.0, 1e-9, 0.3, 1.0] {
                let want = n_prime_from_eta(n, f, eta).unwrap().value();
                let got = n_prime_from_eta_unchecked(n, f, eta);
                assert_eq!(want.to_bits(), got.to_bits(), "{n} {f} {eta}");
            }
            for np in [
                n,
                0.5 * (n + l),
                l,
                2.0 * l,
                1e3 * f,
                f64::MAX,
                f64::INFINITY,
            ] {
                let npv = NPrime::new(np).unwrap();
                let want = eta_from_n_prime(n, f, npv).unwrap();
                let got = eta_from_n_prime_unchecked(n, f, np);
                assert_eq!(want.to_bits(), got.to_bits(), "{n} {f} {np}");
            }
        }
        // By hand (Eq 11, α = 100): η = −0.5 gives n′ = (11 + 49.5)/0.5 = 121, and back.
        assert_eq!(n_prime_from_eta_unchecked(1.0, 100.0, -0.5), 121.0);
        assert_eq!(eta_from_n_prime_unchecked(1.0, 100.0, 121.0), -0.5);
    }
}

#[cfg(test)]
mod depth_range_tests {
    use super::*;
    use crate::frustum::ViewFrustum;

    /// The closed forms on bare depths and `ViewFrustum` refuse a bad depth range with the same
    /// error (one check); f/n overflowing is near_far's own.
    #[test]
    fn near_far_and_view_frustum_agree_on_bad_depths() {
        for (n, f) in [
            (2.0, 1.0),
            (1.0, 1.0),
            (0.0, 1.0),
            (-1.0, 2.0),
            (1.0, f64::NAN),
        ] {
            let a = near_far(n, f).unwrap_err().to_string();
            let b = ViewFrustum::new(n, f, 0.5).unwrap_err().to_string();
            assert_eq!(a, b, "near={n}, far={f}");
        }
        assert_eq!(
            near_far(2.0, 1.0).unwrap_err().to_string(),
            "far must be greater than near (got near=2, far=1)"
        );
        assert!(near_far(1e-300, 1e300).is_err());
        assert_eq!(near_far_ratio(2.0, 5.0).unwrap(), (2.0, 5.0, 2.5));
    }
}
