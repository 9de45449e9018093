//! `out=` and `dtype=`: where a result goes and in which float type.
//!
//! As NumPy's ufuncs take it, `out` is an existing array that receives the result and is
//! returned: a `numpy.ndarray` of exactly the result's shape and dtype (float64, or float32 for a
//! matrix asked for with `dtype=numpy.float32`), writeable, of any strides. An `out` that is also
//! an argument (`sa.mx(n, f, np_, z, out=z)`) is read in full before it is written. A wrong type
//! or dtype is a `TypeError` naming `out`, a wrong shape or a read-only array a `ValueError`
//! naming it; both are raised before anything is computed.

use crate::args;
use crate::broadcast::{fmt_shape, to_python};
use crate::closed::choice;
use numpy::ndarray::{ArrayViewD, IxDyn};
use numpy::{
    PyArrayDescrMethods, PyArrayDyn, PyArrayMethods, PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyString;

type Any<'py> = Bound<'py, PyAny>;

/// `dtype`: float64 (the default, `None`) or float32, as a NumPy type, dtype or its name.
/// Returns whether float32 was asked for.
pub fn dtype(ob: Option<&Any<'_>>) -> PyResult<bool> {
    let Some(ob) = ob.filter(|o| !o.is_none()) else {
        return Ok(false);
    };
    let name = if let Ok(s) = ob.cast::<PyString>() {
        s.to_str()?.to_string()
    } else {
        let np = ob.py().import("numpy")?;
        let is_type = ob.is(&np.getattr("float32")?) || ob.is(&np.getattr("float64")?);
        let is_dtype = ob.is_instance(&np.getattr("dtype")?)?;
        if !(is_type || is_dtype) {
            return Err(PyTypeError::new_err(format!(
                "dtype must be numpy.float64 or numpy.float32 (got {})",
                args::kind(ob)
            )));
        }
        np.getattr("dtype")?
            .call1((ob,))?
            .getattr("name")?
            .extract::<String>()?
    };
    Ok(choice("dtype", &name, &["float64", "float32"])? == "float32")
}

/// A checked `out` argument (or none).
pub struct Out<'py> {
    array: Option<Bound<'py, PyUntypedArray>>,
    f32: bool,
}

impl<'py> Out<'py> {
    /// Checks `out` against the result's `shape` and float type (`f32`), before any work.
    pub fn new(out: Option<&Any<'py>>, shape: &[usize], f32: bool) -> PyResult<Self> {
        let Some(ob) = out.filter(|o| !o.is_none()) else {
            return Ok(Self { array: None, f32 });
        };
        let want = if f32 { "float32" } else { "float64" };
        let a = ob.cast::<PyUntypedArray>().map_err(|_| {
            PyTypeError::new_err(format!(
                "out must be a numpy.ndarray of dtype {want} (got {})",
                args::kind(ob)
            ))
        })?;
        let dt = a.dtype();
        let got = dt.str()?.to_string();
        let matches = if f32 {
            dt.is_equiv_to(&numpy::dtype::<f32>(ob.py()))
        } else {
            dt.is_equiv_to(&numpy::dtype::<f64>(ob.py()))
        };
        if !matches {
            return Err(PyTypeError::new_err(format!(
                "out must have dtype {want} (got an array of dtype {got}){}",
                if f32 {
                    ""
                } else {
                    "; pass dtype=numpy.float32 for a float32 matrix"
                }
            )));
        }
        if a.shape() != shape {
            return Err(PyValueError::new_err(format!(
                "out must have the result's shape {} (got shape {})",
                fmt_shape(shape),
                fmt_shape(a.shape())
            )));
        }
        if !a.getattr("flags")?.getattr("writeable")?.is_truthy()? {
            return Err(PyValueError::new_err(
                "out must be writeable (got a read-only array)",
            ));
        }
        Ok(Self {
            array: Some(a.clone()),
            f32,
        })
    }

    /// The given float64 array if it is C-contiguous, so that a computation can write into it
    /// directly.
    pub fn contiguous_f64(&self) -> Option<Bound<'py, PyArrayDyn<f64>>> {
        let a = self.array.as_ref()?;
        if self.f32 || !a.is_c_contiguous() {
            return None;
        }
        a.cast::<PyArrayDyn<f64>>().ok().cloned()
    }

    /// `values` (C order, the result's shape) as the result: written into `out` and `out`
    /// returned, or a new array (float32 rounded once from float64, as the crate's `to_mat4`).
    /// A 0-d result without `out` is a NumPy scalar.
    pub fn deliver(
        self,
        py: Python<'py>,
        shape: Vec<usize>,
        values: Vec<f64>,
    ) -> PyResult<Any<'py>> {
        let Some(a) = self.array else {
            let arr = to_python(py, shape, values)?;
            return if self.f32 {
                arr.call_method1("astype", ("float32",))
            } else {
                Ok(arr)
            };
        };
        let view = ArrayViewD::from_shape(IxDyn(&shape), &values)
            .map_err(|e| PyValueError::new_err(format!("internal error: {e}")))?;
        let busy =
            |e: numpy::BorrowError| PyValueError::new_err(format!("out cannot be written ({e})"));
        if self.f32 {
            let t = a.cast::<PyArrayDyn<f32>>()?;
            let mut w = t.try_readwrite().map_err(busy)?;
            // Rounded once from the f64 value, as the crate's `DMat4::as_mat4`.
            w.as_array_mut().zip_mut_with(&view, |o, &v| *o = v as f32);
        } else {
            let t = a.cast::<PyArrayDyn<f64>>()?;
            let mut w = t.try_readwrite().map_err(busy)?;
            w.as_array_mut().assign(&view);
        }
        Ok(a.into_any())
    }
}
