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

/// Formats a number for an error message: shortest round-trip form.
pub(crate) fn fmt_num(v: f64) -> String {
    if v.is_nan() {
        "NaN".into()
    } else if v == f64::INFINITY {
        "inf".into()
    } else if v == f64::NEG_INFINITY {
        "-inf".into()
    } else {
        format!("{v}")
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
    }
}
