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
/// answer is [`NPrime::Unwarped`] (η = ∞, the orthographic map).
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
    let den = lambda * (1.0 - xi) - 2.0 * d;
    if den == 0.0 {
        return Ok(NPrime::Unwarped);
    }
    if den < 0.0 {
        return Err(eta_no_solution(lambda, d, xi));
    }
    let eta = finite_result("eta", lambda * d * (1.0 + xi) / den)?;
    NPrime::new(eta)
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
/// [`Error::InvalidArgument`] naming `lambda`, `delta_prime` (outside `(0, λ)`) or `eta` (a
/// finite η that is not positive).
#[inline]
pub fn tsm_focus_line(lambda: f64, eta: NPrime, delta_prime: f64) -> Result<f64> {
    let (lambda, d) = check_inputs(lambda, delta_prime)?;
    match eta {
        NPrime::Finite(e) => {
            let e = positive("eta", e)?;
            let [[a, b], _] = tsm_projection(lambda, e)?;
            finite_result("the focus line", a + b / (e + d))
        }
        NPrime::Unwarped => finite_result("the focus line", 1.0 - 2.0 * d / lambda),
    }
}

/// Martin & Tan's 1D homogeneous projection matrix (§6.2), row-major,
///
/// `[[−(λ + 2η)/λ, 2 (λ + η) η / λ], [1, 0]]`,
///
/// acting on `(x, 1)` with x the distance from the centre of projection; the projected
/// coordinate is the first component over the second. It sends the top line (x = η) to +1 and the
/// base line (x = η + λ) to −1. λ = `lambda` (trapezoid height) and η = `eta` (distance of the
/// centre of projection above the top line) are distances in the same unit; the entries are
/// dimensionless (first row, first column) and in that unit (first row, second column).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `lambda` or `eta` unless finite and positive;
/// [`Error::Degenerate`] when an entry overflows (η/λ beyond about 1e154).
#[inline]
pub fn tsm_projection(lambda: f64, eta: f64) -> Result<[[f64; 2]; 2]> {
    let lambda = positive("lambda", lambda)?;
    let eta = positive("eta", eta)?;
    Ok([
        [
            finite_result("the projection", -(1.0 + 2.0 * (eta / lambda)))?,
            finite_result("the projection", 2.0 * (1.0 + eta / lambda) * eta)?,
        ],
        [1.0, 0.0],
    ])
}
