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
/// alone would print 1e300 with 301 digits). The command line's messages use it too (docs/cli.md).
pub fn fmt_num(v: f64) -> String {
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

/// The resolutions a closed form's value is proportional to: `image / map`, with `map` the
/// shadow map's resolution named as the form's argument (`res_s`, `res_t`, `res_x`).
#[derive(Debug, Clone, Copy)]
pub(crate) struct ResRatio {
    /// Pixels across the image (`res_image`).
    pub(crate) image: f64,
    /// The map resolution's argument name.
    pub(crate) map_name: &'static str,
    /// Texels along the map's axis.
    pub(crate) map: f64,
}

impl ResRatio {
    /// `res_image / <map_name>`.
    #[inline]
    pub(crate) fn new(image: f64, map_name: &'static str, map: f64) -> Self {
        Self {
            image,
            map_name,
            map,
        }
    }
}

/// Checks the computed value `v` of a closed form that is strictly positive on its domain and
/// proportional to `res.image / res.map`: a normal `f64` is returned; a non-finite one is
/// reported as by [`finite_result`]; 0 or a subnormal (the true value underflowed: 0 would be
/// wrong, a subnormal has lost digits) is [`Error::InvalidArgument`] naming `res_image` and the
/// map's resolution, with an estimate of the true value from `unit`, the form's value at unit
/// resolutions (called only on that path), and the remedy. Where even `unit` is not a normal
/// number the resolutions are not the cause: [`Error::Degenerate`].
#[inline]
pub(crate) fn positive_result(
    what: &str,
    v: f64,
    res: ResRatio,
    unit: impl FnOnce() -> f64,
) -> Result<f64> {
    if v.is_normal() {
        Ok(v)
    } else {
        Err(not_positive_result(what, v, res, unit))
    }
}

/// The smallest positive normal `f64`, as messages print it.
const MIN_NORMAL: &str = "2.2e-308";

#[cold]
#[inline(never)]
fn not_positive_result(what: &str, v: f64, res: ResRatio, unit: impl FnOnce() -> f64) -> Error {
    if !v.is_finite() {
        return not_finite_result(what, v);
    }
    let got = if v == 0.0 {
        "0".to_string()
    } else {
        format!("the subnormal {}", fmt_num(v))
    };
    let unit = unit();
    let ResRatio {
        image,
        map_name,
        map,
    } = res;
    if !unit.is_normal() || (image == 1.0 && map == 1.0) {
        return Error::Degenerate(format!(
            "{what} is positive but would be returned as {got} for these inputs: at \
             res_image={map_name}=1 it is {}, outside f64's normal range (from {MIN_NORMAL})",
            fmt_num(unit)
        ));
    }
    // The true value, unit × image / map, in logarithms (its ratio may itself underflow).
    let log = unit.log10() + image.log10() - map.log10();
    let (mut mantissa, mut exponent) = (10f64.powf(log - log.floor()), log.floor());
    if (mantissa * 1e3).round() >= 1e4 {
        // 9.9996 would print as 10.000.
        (mantissa, exponent) = (mantissa / 10.0, exponent + 1.0);
    }
    let estimate = format!("{mantissa:.3}e{exponent}");
    let head = format!(
        "and {map_name} make {what} underflow f64: {what} is proportional to res_image/{map_name} \
         (res_image={}, {map_name}={})",
        fmt_num(image),
        fmt_num(map)
    );
    let at_unit = format!(
        "evaluate it at res_image={map_name}=1 ({what} = {})",
        fmt_num(unit)
    );
    let reason = if log < f64::MIN_POSITIVE.log10() {
        format!(
            "{head} and would be returned as {got}, but its value, about {estimate}, is below \
             the smallest normal f64 ({MIN_NORMAL}); {at_unit} and scale by res_image/{map_name} \
             yourself, in logarithms"
        )
    } else {
        format!(
            "{head}, a ratio below the smallest normal f64 ({MIN_NORMAL}), and would be returned \
             as {got} though its value is about {estimate}; {at_unit} and scale by \
             res_image/{map_name} yourself, multiplying by res_image before dividing by \
             {map_name}"
        )
    };
    Error::invalid("res_image", reason)
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
    fn positive_result_refuses_what_is_not_a_normal_number() {
        let res = ResRatio::new(1e-300, "res_s", 1e300);
        assert_eq!(positive_result("m", 2.5, res, || unreachable!()), Ok(2.5));
        // Non-finite: as `finite_result`.
        assert_eq!(
            positive_result("m", f64::INFINITY, res, || 1.0),
            finite_result("m", f64::INFINITY)
        );
        // An estimate whose mantissa rounds to 10 moves to the next power: 9.99996e-600 (unit
        // value 9.99996 at a ratio of 1e-600) is "about 1.000e-599", never "10.000e-600".
        let e = positive_result("m", 0.0, res, || 9.99996).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidArgument {
                    name: "res_image",
                    ..
                }
            ),
            "{e}"
        );
        assert!(e.to_string().contains("about 1.000e-599,"), "{e}");
        // At unit resolutions, or where the unit value is itself not normal, the resolutions are
        // not the cause.
        let unit = ResRatio::new(1.0, "res_t", 1.0);
        let e = positive_result("m_z", 1e-320, unit, || 1e-320).unwrap_err();
        assert_eq!(
            e.to_string(),
            "degenerate geometry: m_z is positive but would be returned as the subnormal 1e-320 \
             for these inputs: at res_image=res_t=1 it is 1e-320, outside f64's normal range \
             (from 2.2e-308)"
        );
        let e = positive_result("m_z", 0.0, res, || 0.0).unwrap_err();
        assert!(matches!(e, Error::Degenerate(_)), "{e}");
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
