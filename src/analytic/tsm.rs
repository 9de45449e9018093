//! Martin & Tan 2004, *Trapezoidal Shadow Maps* §6.2: the distance η of the trapezoid's
//! centre of projection q from its top line, from the 1D homogeneous projection that maps the
//! focus point to a chosen line of the map (the "80 % rule").
//!
//! # The 1D projection
//!
//! Along the trapezoid's centre line, measure the distance x from q (on the far side of the top
//! line from the base). The top line is at x = η, the base line at x = η + λ (λ the distance
//! between them), the focus point p_L at x = η + δ′. The projective map
//!
//! `y(x) = (A x + B) / x`, `A = −(λ + 2η)/λ`, `B = 2 (λ + η) η / λ`
//!
//! (Martin & Tan's 2×2 matrix `[[A, B], [1, 0]]` acting on `(x, 1)`) is the one that sends the top
//! line to y = +1 and the base line to y = −1; the 80 % rule asks it to send p_L to y = ξ
//! (ξ = −0.6 is the line 80 % of the way from the top, 1 − 0.8 · 2). Solving `y(η + δ′) = ξ`
//! for η gives the printed
//!
//! `η = λ δ′ (1 + ξ) / (λ (1 − ξ) − 2 δ′)`,
//!
//! which the crate checks against the map itself (tests/tsm_eta.rs).
//!
//! Martin & Tan's ξ and η are not Lloyd's ξ and η (DESIGN.md): here η is a distance (the
//! analogue of Lloyd's n′, which is why it is returned as an [`NPrime`]) and ξ a map line.
//!
//! ```
//! use shadow_aliasing::analytic::tsm::{tsm_eta, tsm_focus_line, EIGHTY_PERCENT_LINE};
//! use shadow_aliasing::NPrime;
//! // A trapezoid of height 10 with the focus point 3 below the top line.
//! let eta = tsm_eta(10.0, 3.0, EIGHTY_PERCENT_LINE)?;
//! assert!((eta.value() - 10.0 * 3.0 * 0.4 / (16.0 - 6.0)).abs() < 1e-12);
//! // The map with that centre sends the focus point to the 80 % line.
//! assert!((tsm_focus_line(10.0, eta, 3.0)? - EIGHTY_PERCENT_LINE).abs() < 1e-12);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::error::{finite_result, fmt_num, in_open, positive, Error, Result};
use crate::frustum::NPrime;

/// ξ = −0.6, the map line 80 % of the way from the top line (+1) to the base line (−1)
/// (Martin & Tan §6.2, the "80 % line").
pub const EIGHTY_PERCENT_LINE: f64 = -0.6;

fn check_inputs(lambda: f64, delta_prime: f64) -> Result<(f64, f64)> {
    let lambda = positive("lambda", lambda)?;
    let d = in_open("delta_prime", delta_prime, 0.0, lambda)?;
    Ok((lambda, d))
}

/// Martin & Tan's η (§6.2): the distance from the top line of the centre of projection q that
/// maps the focus point p_L (at distance δ′ below the top line of a trapezoid of height λ) to the
/// map line y = ξ, with the top line at +1 and the base line at −1:
///
/// `η = λ δ′ (1 + ξ) / (λ (1 − ξ) − 2 δ′)`.
///
/// λ and δ′ are distances in the light's post-perspective space (any consistent unit); η is in
/// the same unit. ξ is dimensionless, [`EIGHTY_PERCENT_LINE`] for the 80 % rule.
///
/// The warp can only move p_L towards the base (a centre above the top line magnifies the top):
/// a finite η > 0 exists exactly when ξ is below the unwarped line `1 − 2δ′/λ`; at that line the
/// answer is [`NPrime::UNWARPED`] (η = ∞, the orthographic map).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda` (not finite and positive), `delta_prime` (outside
/// `(0, λ)`: the focus point must lie strictly between the top and base lines) or `xi` (outside
/// `(−1, 1)`); [`Error::NoSolution`] when ξ lies above the unwarped line `1 − 2δ′/λ`: the printed
/// formula then gives η < −λ, a centre beyond the base line, which inverts the trapezoid (its
/// top edge would be the longer one) and which TSM's construction cannot use.
#[inline]
pub fn tsm_eta(lambda: f64, delta_prime: f64, xi: f64) -> Result<NPrime> {
    let (lambda, d) = check_inputs(lambda, delta_prime)?;
    let xi = in_open("xi", xi, -1.0, 1.0)?;
    let den = eta_denominator(lambda, d, xi);
    if den == 0.0 {
        // tsm_eta_unchecked gives ∞ here, the value of NPrime::UNWARPED.
        return Ok(NPrime::UNWARPED);
    }
    if den < 0.0 {
        return Err(eta_no_solution(lambda, d, xi));
    }
    let eta = finite_result("tsm_eta", tsm_eta_unchecked(lambda, d, xi))?;
    NPrime::new(eta)
}

/// [`tsm_eta`] without validation, η as an `f64` (Martin & Tan §6.2):
///
/// `η = λ δ′ (1 + ξ) / (λ (1 − ξ) − 2 δ′)`, `f64::INFINITY` on the unwarped line (denominator 0),
///
/// for callers that have checked the domain themselves (the Python bindings' array path).
/// Equal, bit for bit, to `tsm_eta(..)?.value()` wherever that returns `Ok` (which computes its
/// finite value here); outside that domain the result is meaningless (negative, NaN or ∞ where
/// `tsm_eta` refuses).
#[inline(always)]
#[must_use]
pub fn tsm_eta_unchecked(lambda: f64, delta_prime: f64, xi: f64) -> f64 {
    let den = eta_denominator(lambda, delta_prime, xi);
    // Both branches, then a select without a jump, so that a loop over arrays vectorises.
    std::hint::select_unpredictable(
        den == 0.0,
        f64::INFINITY,
        eta_over(lambda, delta_prime, xi, den),
    )
}

/// λ (1 − ξ) − 2 δ′, the denominator of η: positive exactly when ξ lies below the unwarped line.
#[inline(always)]
fn eta_denominator(lambda: f64, d: f64, xi: f64) -> f64 {
    lambda * (1.0 - xi) - 2.0 * d
}

/// λ δ′ (1 + ξ) / `den`.
#[inline(always)]
fn eta_over(lambda: f64, d: f64, xi: f64, den: f64) -> f64 {
    lambda * d * (1.0 + xi) / den
}

/// [`tsm_eta`]'s finite value without building its `Result`, for the trapezoidal builders (the
/// line search calls it ≈ 45 times per map): `Some(η)` exactly where [`tsm_eta`] returns
/// a finite `Ok(η)`, bit for bit, and `None` where it returns [`NPrime::UNWARPED`] or an error
/// (outside its domain, no solution, a focus point on the top or base line). The builders then
/// use the bounding rectangle, the limit η → ∞.
#[inline]
pub(crate) fn tsm_eta_finite(lambda: f64, delta_prime: f64, xi: f64) -> Option<f64> {
    let d = delta_prime;
    if !(lambda.is_finite() && d > 0.0 && d < lambda && xi > -1.0 && xi < 1.0) {
        return None;
    }
    let den = eta_denominator(lambda, d, xi);
    if den <= 0.0 {
        return None;
    }
    let eta = eta_over(lambda, d, xi, den);
    (eta.is_finite() && eta > 0.0).then_some(eta)
}

#[cold]
#[inline(never)]
fn eta_no_solution(lambda: f64, d: f64, xi: f64) -> Error {
    Error::NoSolution(format!(
        "no centre of projection above the top line maps the focus point (delta_prime={}) of a trapezoid of height lambda={} to the line xi={}: without warping it already lies at {}, and a centre above the top line only moves it towards the base (-1)",
        fmt_num(d),
        fmt_num(lambda),
        fmt_num(xi),
        fmt_num(1.0 - 2.0 * d / lambda)
    ))
}

/// The forward map of Martin & Tan's 1D homogeneous projection (§6.2): the map line y ∈ (−1, 1)
/// to which the centre of projection at distance η above the top line sends the point at
/// distance δ′ below it, for a trapezoid of height λ:
///
/// `y = (A (η + δ′) + B) / (η + δ′)`, `A = −(λ + 2η)/λ`, `B = 2 (λ + η) η / λ`,
///
/// and `y = 1 − 2δ′/λ` unwarped (η = ∞). The inverse of [`tsm_eta`] in ξ.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda` or `delta_prime` (outside `(0, λ)`); `tsm_eta` is
/// valid by construction ([`NPrime`]).
#[inline]
pub fn tsm_focus_line(lambda: f64, tsm_eta: NPrime, delta_prime: f64) -> Result<f64> {
    let (lambda, d) = check_inputs(lambda, delta_prime)?;
    match tsm_eta.as_finite() {
        Some(e) => {
            let [[a, b], _] = tsm_projection(lambda, e)?;
            finite_result("the focus line", a + b / (e + d))
        }
        None => finite_result("the focus line", 1.0 - 2.0 * d / lambda),
    }
}

/// Martin & Tan's 1D homogeneous projection matrix (§6.2), row-major,
///
/// `[[−(λ + 2η)/λ, 2 (λ + η) η / λ], [1, 0]]`,
///
/// acting on `(x, 1)` with x the distance from the centre of projection; the projected
/// coordinate is the first component over the second. It sends the top line (x = η) to +1 and the
/// base line (x = η + λ) to −1. λ = `lambda` (trapezoid height) and η = `tsm_eta` (distance of the
/// centre of projection above the top line) are distances in the same unit; the entries are
/// dimensionless (first row, first column) and in that unit (first row, second column).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda` or `tsm_eta` unless finite and positive;
/// [`Error::Degenerate`] when an entry overflows (η/λ beyond about 1e154).
#[inline]
pub fn tsm_projection(lambda: f64, tsm_eta: f64) -> Result<[[f64; 2]; 2]> {
    let lambda = positive("lambda", lambda)?;
    let eta = positive("tsm_eta", tsm_eta)?;
    Ok([
        [
            finite_result("the projection", -(1.0 + 2.0 * (eta / lambda)))?,
            finite_result("the projection", 2.0 * (1.0 + eta / lambda) * eta)?,
        ],
        [1.0, 0.0],
    ])
}

#[cfg(test)]
mod finite_tests {
    use super::*;

    /// The builders' `tsm_eta_finite` is `tsm_eta`'s `Ok(Finite(η))` bit for bit and `None`
    /// wherever `tsm_eta` gives `Unwarped` or an error, over a grid through every branch
    /// (δ′ outside (0, λ), ξ at and beyond ±1, the unwarped line, non-finite inputs).
    #[test]
    fn finite_value_is_the_closed_form() {
        let lambdas = [1e-300, 0.5, 1.0, 37.0, 1e300, f64::INFINITY, f64::NAN, -1.0];
        let fractions = [-0.1, 0.0, 1e-12, 0.2, 0.5, 0.7, 1.0, 1.5];
        let xis = [-1.0, -0.999, -0.6, 0.0, 0.4, 0.6, 0.999, 1.0, f64::NAN];
        let mut finite = 0;
        for &l in &lambdas {
            for &fr in &fractions {
                for &xi in &xis {
                    let d = fr * if l.is_finite() { l } else { 1.0 };
                    let fast = tsm_eta_finite(l, d, xi);
                    match tsm_eta(l, d, xi).map(NPrime::as_finite) {
                        Ok(Some(e)) => {
                            assert_eq!(fast.map(f64::to_bits), Some(e.to_bits()));
                            finite += 1;
                        }
                        other => assert_eq!(fast, None, "{l} {d} {xi}: {other:?}"),
                    }
                }
            }
        }
        assert!(finite > 20, "{finite}");
    }

    /// [`tsm_eta_unchecked`] is `tsm_eta(..)?.value()` bit for bit wherever `tsm_eta` returns
    /// `Ok`: finite η over a grid of heights, focus depths and lines (ξ at both ends of (−1, 1)),
    /// and ∞ exactly on the unwarped line; by hand at the 80 % line.
    #[test]
    fn unchecked_twin_agrees() {
        let mut finite = 0;
        for l in [1e-300, 1e-3, 0.5, 1.0, 37.0, 1e6, 1e300] {
            for fr in [1e-12, 0.01, 0.2, 0.5, 0.7, 0.999_999] {
                let d = fr * l;
                for xi in [
                    -0.999_999_999,
                    -0.6,
                    -0.3,
                    0.0,
                    0.3,
                    0.6,
                    0.999,
                    1.0 - 2.0 * fr,
                ] {
                    if let Ok(e) = tsm_eta(l, d, xi) {
                        let got = tsm_eta_unchecked(l, d, xi);
                        assert_eq!(got.to_bits(), e.value().to_bits(), "{l} {d} {xi}");
                        finite += usize::from(e.as_finite().is_some());
                    }
                }
            }
        }
        assert!(finite > 100, "{finite}");
        // The unwarped line ξ = 1 − 2δ′/λ (exact at δ′/λ = 1/4): ∞ on both.
        assert_eq!(tsm_eta(8.0, 2.0, 0.5), Ok(NPrime::UNWARPED));
        assert_eq!(tsm_eta_unchecked(8.0, 2.0, 0.5), f64::INFINITY);
        // λ = 10, δ′ = 3, ξ = −0.6: 10 · 3 · 0.4 / (16 − 6) = 1.2.
        assert!((tsm_eta_unchecked(10.0, 3.0, EIGHTY_PERCENT_LINE) - 1.2).abs() < 1e-15);
    }
}
