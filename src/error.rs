//! The crate's one error type.
//!
//! Every public function with a domain validates its input and answers [`Error`] rather
//! than panicking or returning NaN. The message names the argument and what was wrong,
//! in the form the `eval` command line prints (`far must be greater than near (got near=2, far=1)`).

use std::fmt::Display;

/// Result alias used throughout the crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// What went wrong, with enough words to fix the input.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An argument is NaN, infinite where it may not be, or outside its domain.
    /// Fix: pass a value inside the domain the reason states.
    #[error("{name} {reason}")]
    InvalidArgument {
        /// The argument's name, as in the eval contract (`near`, `half_fov`, …).
        name: &'static str,
        /// What is wrong with it, including the value received.
        reason: String,
    },
    /// The configuration is valid but the requested quantity has no solution there
    /// (for instance a focus point no projection centre can map to the requested line).
    #[error("no solution: {0}")]
    NoSolution(String),
    /// The papers give no closed form for this combination (for instance a partition
    /// scheme for a light direction the paper does not analyse).
    #[error("no closed form: {0}")]
    NoClosedForm(String),
    /// The geometry is degenerate in a way that has no documented fallback
    /// (for instance a shadow matrix that maps a frustum point behind its projection centre).
    #[error("degenerate geometry: {0}")]
    Degenerate(String),
}

impl Error {
    /// Builds [`Error::InvalidArgument`].
    pub fn invalid(name: &'static str, reason: impl Display) -> Self {
        Error::InvalidArgument {
            name,
            reason: reason.to_string(),
        }
    }
}

/// Formats a number for an error message: the shortest decimal that parses back to the same
/// `f64`, positional for 10⁻⁵ ≤ |v| < 10¹⁶ (`2`, `0.1`, `-0.00012`) and in exponent form outside
/// it (`1e300`, `-2.5e-7`), so that no number takes more than 24 characters (positional `{}`
/// alone would print 1e300 with 301 digits).
pub(crate) fn fmt_num(v: f64) -> String {
    if v.is_nan() {
        "NaN".into()
    } else if v == f64::INFINITY {
        "inf".into()
    } else if v == f64::NEG_INFINITY {
        "-inf".into()
    } else if v == 0.0 || (1e-5..1e16).contains(&v.abs()) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// `v` must be finite.
///
/// The validators are `#[inline]` with their error paths in `#[cold]`, never-inlined functions, so
/// that a closed form's hot path is a few compares and its caller can inline it (the `format!`
/// of a message costs nothing until a value is actually refused).
#[inline]
pub(crate) fn finite(name: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(not_finite(name, v))
    }
}

#[cold]
#[inline(never)]
fn not_finite(name: &'static str, v: f64) -> Error {
    Error::invalid(
        name,
        format!("must be a finite number (got {})", fmt_num(v)),
    )
}

/// `v` must be finite and strictly positive.
#[inline]
pub(crate) fn positive(name: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(not_positive(name, v))
    }
}

#[cold]
#[inline(never)]
fn not_positive(name: &'static str, v: f64) -> Error {
    if !v.is_finite() {
        return not_finite(name, v);
    }
    Error::invalid(name, format!("must be greater than 0 (got {})", fmt_num(v)))
}

/// `v` must be finite and lie in the closed interval `[lo, hi]`.
#[inline]
pub(crate) fn in_closed(name: &'static str, v: f64, lo: f64, hi: f64) -> Result<f64> {
    if v.is_finite() && (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(not_in_closed(name, v, lo, hi))
    }
}

#[cold]
#[inline(never)]
fn not_in_closed(name: &'static str, v: f64, lo: f64, hi: f64) -> Error {
    if !v.is_finite() {
        return not_finite(name, v);
    }
    Error::invalid(
        name,
        format!(
            "must lie in [{}, {}] (got {})",
            fmt_num(lo),
            fmt_num(hi),
            fmt_num(v)
        ),
    )
}

/// `v` must be finite and lie in the open interval `(lo, hi)`.
#[inline]
pub(crate) fn in_open(name: &'static str, v: f64, lo: f64, hi: f64) -> Result<f64> {
    if v.is_finite() && v > lo && v < hi {
        Ok(v)
    } else {
        Err(not_in_open(name, v, lo, hi))
    }
}

#[cold]
#[inline(never)]
fn not_in_open(name: &'static str, v: f64, lo: f64, hi: f64) -> Error {
    if !v.is_finite() {
        return not_finite(name, v);
    }
    Error::invalid(
        name,
        format!(
            "must lie in ({}, {}) (got {})",
            fmt_num(lo),
            fmt_num(hi),
            fmt_num(v)
        ),
    )
}

/// Checks that a computed value is finite; a non-finite result is reported, never returned.
#[inline]
pub(crate) fn finite_result(what: &str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(not_finite_result(what, v))
    }
}

#[cold]
#[inline(never)]
fn not_finite_result(what: &str, v: f64) -> Error {
    Error::Degenerate(format!(
        "{what} is not finite ({}) for these inputs",
        fmt_num(v)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_argument_and_value() {
        assert_eq!(
            positive("near", -2.0).unwrap_err().to_string(),
            "near must be greater than 0 (got -2)"
        );
        assert_eq!(
            finite("z", f64::NAN).unwrap_err().to_string(),
            "z must be a finite number (got NaN)"
        );
        assert_eq!(
            in_closed("eta", 1.5, -1.0, 1.0).unwrap_err().to_string(),
            "eta must lie in [-1, 1] (got 1.5)"
        );
        assert!(in_open("half_fov", 0.0, 0.0, 1.0).is_err());
        assert_eq!(in_open("half_fov", 0.5, 0.0, 1.0), Ok(0.5));
        assert_eq!(
            positive("near", -1e300).unwrap_err().to_string(),
            "near must be greater than 0 (got -1e300)"
        );
    }

    #[test]
    fn message_numbers_are_short_and_round_trip() {
        // Expected strings written by hand: positional in [1e-5, 1e16), exponent form outside.
        for (v, want) in [
            (2.0, "2"),
            (-2.0, "-2"),
            (0.0, "0"),
            (-0.0, "-0"),
            (0.1, "0.1"),
            (0.5237, "0.5237"),
            (1e-5, "0.00001"),
            (-0.00012345678901234567, "-0.00012345678901234567"),
            (9.999999999999998e15, "9999999999999998"),
            (1e16, "1e16"),
            (1e300, "1e300"),
            (-1e300, "-1e300"),
            (1e308, "1e308"),
            (f64::MAX, "1.7976931348623157e308"),
            (-f64::MIN_POSITIVE, "-2.2250738585072014e-308"),
            (5e-324, "5e-324"),
            (9.99e-6, "9.99e-6"),
            (2.5e-7, "2.5e-7"),
            (f64::NAN, "NaN"),
            (f64::NEG_INFINITY, "-inf"),
        ] {
            assert_eq!(fmt_num(v), want, "{v:e}");
        }
        // Every finite value, sampled across all exponents: at most 24 characters, and it parses
        // back to the same bits.
        let mut bits: u64 = 0x9e37_79b9_7f4a_7c15;
        for _ in 0..200_000 {
            // xorshift64*: a fixed, seedless sequence covering the whole bit range.
            bits ^= bits >> 12;
            bits ^= bits << 25;
            bits ^= bits >> 27;
            let v = f64::from_bits(bits.wrapping_mul(0x2545_f491_4f6c_dd1d));
            if !v.is_finite() {
                continue;
            }
            let s = fmt_num(v);
            assert!(s.len() <= 24, "{s} ({} chars)", s.len());
            assert_eq!(s.parse::<f64>().map(f64::to_bits), Ok(v.to_bits()), "{s}");
        }
    }
}
