//! `shadow_aliasing._native`: the Python bindings of the shadow-aliasing crate.
//!
//! The closed forms of the eval contract element-wise on NumPy arrays with broadcasting
//! (`closed`, over `broadcast`), the shadow-matrix builders, the measurement of any 4×4 matrix
//! (`builders`) and the hemisphere sweep (`sweep`). Every argument that is one number or string
//! is converted by `args`, naming it in any error: `TypeError` for a wrong type, `ValueError` for
//! a value outside the domain (the crate's message). No function returns NaN or panics.

mod args;
mod broadcast;
mod builders;
mod closed;
mod controller;
mod error_image;
mod frame;
mod interrupt;
mod measure;
mod out;
mod plan;
mod stacked;
mod sweep;

use pyo3::prelude::*;

/// Acquires NumPy's C API at import, where a failure (a `KeyboardInterrupt` while NumPy's
/// modules load) is an ordinary exception. rust-numpy otherwise acquires it at the first array
/// a function makes, runs Python code to do so (NumPy's version check), and panics if that code
/// raises: a Ctrl-C pending then became a `PanicException`. Once NumPy's modules are imported
/// (by `get_array_module`, which returns the error), the API capsule and the borrow-checking
/// capsule are found in `sys.modules` without running Python code, so they cannot fail.
fn acquire_numpy(py: Python<'_>) -> PyResult<()> {
    numpy::get_array_module(py)?;
    let probe = numpy::PyArray1::<f64>::zeros(py, 0, false);
    // The shared borrow-checking API, acquired at the first borrow.
    drop(numpy::PyArrayMethods::try_readonly(&probe));
    Ok(())
}

/// The native module; `shadow_aliasing/__init__.py` re-exports it.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    acquire_numpy(m.py())?;
    use closed::*;
    m.add_function(wrap_pyfunction!(broadcast::_set_fast_path, m)?)?;
    m.add_function(wrap_pyfunction!(broadcast::_set_wide_simd, m)?)?;
    m.add_function(wrap_pyfunction!(mx, m)?)?;
    m.add_function(wrap_pyfunction!(mz, m)?)?;
    m.add_function(wrap_pyfunction!(max_mx, m)?)?;
    m.add_function(wrap_pyfunction!(max_mz, m)?)?;
    m.add_function(wrap_pyfunction!(storage_factor, m)?)?;
    m.add_function(wrap_pyfunction!(critical_resolution, m)?)?;
    m.add_function(wrap_pyfunction!(n_prime_lispsm, m)?)?;
    m.add_function(wrap_pyfunction!(n_prime_from_eta, m)?)?;
    m.add_function(wrap_pyfunction!(eta_from_n_prime, m)?)?;
    m.add_function(wrap_pyfunction!(distribution_g, m)?)?;
    m.add_function(wrap_pyfunction!(subdivided_max_error, m)?)?;
    m.add_function(wrap_pyfunction!(allocate_texels, m)?)?;
    m.add_function(wrap_pyfunction!(z_partition, m)?)?;
    m.add_function(wrap_pyfunction!(scheme_storage_factor, m)?)?;
    m.add_function(wrap_pyfunction!(tilted_mz, m)?)?;
    m.add_function(wrap_pyfunction!(generalized_n_prime, m)?)?;
    m.add_function(wrap_pyfunction!(gamma_lim, m)?)?;
    m.add_function(wrap_pyfunction!(tsm_eta, m)?)?;
    m.add_function(wrap_pyfunction!(zhang_eq, m)?)?;
    m.add_function(wrap_pyfunction!(zhang_ep, m)?)?;
    m.add_function(wrap_pyfunction!(zhang_eq_local, m)?)?;
    m.add_function(wrap_pyfunction!(zhang_ep_local, m)?)?;
    use builders::*;
    m.add_function(wrap_pyfunction!(warp, m)?)?;
    m.add_function(wrap_pyfunction!(n_prime_for, m)?)?;
    m.add_function(wrap_pyfunction!(cascades, m)?)?;
    m.add_function(wrap_pyfunction!(faces, m)?)?;
    m.add_function(wrap_pyfunction!(tsm, m)?)?;
    m.add_function(wrap_pyfunction!(measure::frustum_max, m)?)?;
    m.add_function(wrap_pyfunction!(measure::point_error, m)?)?;
    m.add_function(wrap_pyfunction!(error_image::error_image, m)?)?;
    m.add_function(wrap_pyfunction!(frame::frame, m)?)?;
    m.add_function(wrap_pyfunction!(plan::plan, m)?)?;
    m.add_function(wrap_pyfunction!(plan::plan_clipmap, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_angles, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep, m)?)?;
    m.add_class::<controller::Controller>()?;
    m.add("WARP_RULES", builders::WARP_RULES.to_vec())?;
    Ok(())
}
