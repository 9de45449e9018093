//! The arguments that are one number, one whole number or one string, each converted by a
//! function named after it (`#[pyo3(from_py_with = args::near)]`).
//!
//! pyo3's own conversion of a typed argument (`f64`, `usize`, `&str`) raises a message that does
//! not name the argument (`OverflowError: can't convert negative int to unsigned`; the name only
//! in `__notes__`). These conversions raise `TypeError` for a wrong type and `ValueError` for a
//! value that no conversion can hold (a negative count, an integer too large), each naming the
//! argument in its message; the crate then checks the domain, naming the argument too.

use crate::broadcast::{fmt_shape, FloatArg};
use numpy::PyUntypedArrayMethods;
use pyo3::exceptions::{PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyString};

type Any<'py> = Bound<'py, PyAny>;

/// What `ob` is, for a message: `None`, or its type's name (`str`, `list`, …).
pub fn kind(ob: &Any<'_>) -> String {
    if ob.is_none() {
        return "None".into();
    }
    ob.get_type()
        .name()
        .map(|n| n.to_string())
        .unwrap_or_else(|_| "an object".into())
}

/// One real number: a Python or NumPy number or a 0-d array of one (converted to float64 as the
/// closed forms' arguments are). An array of another shape is a `TypeError`.
pub fn real(name: &str, ob: &Any<'_>) -> PyResult<f64> {
    match FloatArg::extract_as(name, ob, "one real number")? {
        FloatArg::Number(v) => Ok(v),
        FloatArg::Array(a) => match (a.ndim(), a.as_array().iter().next()) {
            (0, Some(&v)) => Ok(v),
            _ => Err(PyTypeError::new_err(format!(
                "{name} must be one real number (got an array of shape {})",
                fmt_shape(a.shape())
            ))),
        },
    }
}

/// [`real`], or `None` for Python's `None` (an argument whose default is `None`).
pub fn real_or_none(name: &str, ob: &Any<'_>) -> PyResult<Option<f64>> {
    if ob.is_none() {
        Ok(None)
    } else {
        real(name, ob).map(Some)
    }
}

/// A whole number in `0..=max`: a Python or NumPy integer (anything with `__index__`; not a bool
/// or a float). A negative or too large one is a `ValueError`.
pub fn whole(name: &str, ob: &Any<'_>, max: u64) -> PyResult<u64> {
    let py = ob.py();
    if ob.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "{name} must be a whole number (got a bool)"
        )));
    }
    let v = match ob.extract::<i128>() {
        Ok(v) => v,
        Err(e) if e.is_instance_of::<PyOverflowError>(py) => {
            // Beyond i128 either way: the sign says which bound it misses.
            return Err(PyValueError::new_err(if ob.lt(0)? {
                format!("{name} must not be negative (got an integer below -2**127)")
            } else {
                format!("{name} must be at most {max} (got an integer above 2**127)")
            }));
        }
        Err(e) if e.is_instance_of::<PyTypeError>(py) => {
            return Err(PyTypeError::new_err(format!(
                "{name} must be a whole number (got {})",
                kind(ob)
            )));
        }
        Err(e) => return Err(e),
    };
    if v < 0 {
        return Err(PyValueError::new_err(format!(
            "{name} must not be negative (got {v})"
        )));
    }
    u64::try_from(v)
        .ok()
        .filter(|&u| u <= max)
        .ok_or_else(|| PyValueError::new_err(format!("{name} must be at most {max} (got {v})")))
}

/// A string (`str`); anything else is a `TypeError`.
pub fn text<'a>(name: &str, ob: &'a Any<'_>) -> PyResult<&'a str> {
    let s = ob
        .cast::<PyString>()
        .map_err(|_| PyTypeError::new_err(format!("{name} must be a string (got {})", kind(ob))))?;
    s.to_str()
        .map_err(|e| PyValueError::new_err(format!("{name} must be valid text ({e})")))
}

/// One converter per argument name, for `#[pyo3(from_py_with = args::NAME)]`.
macro_rules! named {
    ($(fn $name:ident = $conv:ident($($extra:expr)?) -> $t:ty;)+) => {$(
        #[doc = concat!("`", stringify!($name), "`, by [`", stringify!($conv), "`].")]
        pub fn $name(ob: &Any<'_>) -> PyResult<$t> {
            $conv(stringify!($name), ob $(, $extra)?)
        }
    )+};
}

/// A `usize` count (`k`, `elevations`, `azimuths`).
fn count(name: &str, ob: &Any<'_>) -> PyResult<usize> {
    // At most usize::MAX: the casts are exact.
    whole(name, ob, usize::MAX as u64).map(|v| v as usize)
}

/// A `u32` count, or `None` (`iterative`).
fn count_u32_or_none(name: &str, ob: &Any<'_>) -> PyResult<Option<u32>> {
    if ob.is_none() {
        return Ok(None);
    }
    // At most u32::MAX: the cast is exact.
    whole(name, ob, u64::from(u32::MAX)).map(|v| Some(v as u32))
}

/// A `u32` count (`map_resolution`, `image_height`).
fn count_u32(name: &str, ob: &Any<'_>) -> PyResult<u32> {
    // At most u32::MAX: the cast is exact.
    whole(name, ob, u64::from(u32::MAX)).map(|v| v as u32)
}

named! {
    fn map_resolution = count_u32() -> u32;
    fn pcf_radius = real() -> f64;
    fn image_height = count_u32() -> u32;
    fn near = real() -> f64;
    fn far = real() -> f64;
    fn half_fov = real() -> f64;
    fn aspect = real() -> f64;
    fn overlap = real() -> f64;
    fn total = real() -> f64;
    fn res_image = real() -> f64;
    fn res_s = real() -> f64;
    fn res_t = real() -> f64;
    fn eta = real_or_none() -> Option<f64>;
    fn focus = real_or_none() -> Option<f64>;
    fn near_hint = real_or_none() -> Option<f64>;
    fn far_hint = real_or_none() -> Option<f64>;
    fn shadow_distance = real_or_none() -> Option<f64>;
    fn lambda_ = real_or_none() -> Option<f64>;
    fn xi = real_or_none() -> Option<f64>;
    fn background = real_or_none() -> Option<f64>;
    fn fill = real() -> f64;
    fn k = count() -> usize;
    fn elevations = count() -> usize;
    fn azimuths = count() -> usize;
    fn iterative = count_u32_or_none() -> Option<u32>;
}

/// `return_jacobian` of `error_image`: `True` or `False` only.
pub fn return_jacobian(ob: &Any<'_>) -> PyResult<bool> {
    if ob.is_instance_of::<PyBool>() {
        ob.is_truthy()
    } else {
        Err(PyTypeError::new_err(format!(
            "return_jacobian must be True or False (got {})",
            kind(ob)
        )))
    }
}

/// `overlap` where its default is `None` (`frame`).
pub fn overlap_or_none(ob: &Any<'_>) -> PyResult<Option<f64>> {
    real_or_none("overlap", ob)
}

/// `k` of `z_partition`: one real number (a whole one, which the closed form's `count` checks).
pub fn k_real(ob: &Any<'_>) -> PyResult<f64> {
    real("k", ob)
}

/// The string arguments (a fixed set of choices each, which `closed::choice` checks).
macro_rules! named_text {
    ($($name:ident),+) => {$(
        #[doc = concat!("`", stringify!($name), "`, by [`text`].")]
        pub fn $name<'a>(ob: &'a Any<'_>) -> PyResult<&'a str> {
            text(stringify!($name), ob)
        }
    )+};
}

named_text!(rule, partition, warp, clip_depth, scheme, light, falloff, centre);
