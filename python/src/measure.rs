//! The measurement of any shadow matrix: over the view frustum (`frustum_max`), at points
//! (`point_error`), both over stacks (`crate::stacked`). A captured frame's per-pixel error:
//! `crate::error_image`.

use crate::args;
use crate::builders::from_rows;
use crate::out::Out;
use crate::stacked::{each, lead_shape, message, Operand};
use glam::DVec3;
use pyo3::prelude::*;
use shadow_aliasing::measure::{
    frustum_max as measure_frustum_max, point_error as measure_point_error, ShadowMap,
};
use shadow_aliasing::{Resolutions, ViewFrustum};

type Any<'py> = Bound<'py, PyAny>;

/// M_x, M_z and S̄ = M_x M_z of any shadow matrix over the view frustum, measured from the
/// exact derivatives of the projective map at the frustum's eight vertices (Lloyd 2006 §4.4):
///
///     m_x = w_ls / w_i,  m_z = w_lt / w_i,  w_i = 2 z tan θ / res_image  (unit resolutions)
///
/// matrix: (4, 4) or (..., 4, 4) (row-major, clip = M @ (x, y, z, 1)); light_dir: (3,) or
/// (..., 3), the direction light travels; near, far, half_fov: numbers or arrays. The stacks
/// broadcast as NumPy broadcasts (the last axes (4, 4) and (3,) aside), without the GIL on all
/// cores. Returns (..., 3) float64: ``[M_x, M_z, S̄]`` for each matrix (into ``out`` if given).
#[pyfunction]
#[pyo3(signature = (matrix, light_dir, near, far, half_fov, *, aspect=1.0, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn frustum_max<'py>(
    py: Python<'py>,
    matrix: &Any<'py>,
    light_dir: &Any<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let ops = [
        Operand::new("matrix", matrix, &[4, 4])?,
        Operand::new("light_dir", light_dir, &[3])?,
        Operand::new("near", near, &[])?,
        Operand::new("far", far, &[])?,
        Operand::new("half_fov", half_fov, &[])?,
    ];
    let [m, l, n, f, h] = &ops;
    let lead = lead_shape(&[m, l, n, f, h])?;
    let shape = [&lead[..], &[3]].concat();
    let target = Out::new(out, &shape, false)?;
    let v = each(
        py,
        [m, l, n, f, h],
        &lead,
        3,
        |[m, l, n, f, h], o| {
            let view = ViewFrustum::with_aspect(n[0], f[0], h[0], aspect)?;
            let s = ShadowMap::new(from_rows(m), DVec3::new(l[0], l[1], l[2]))?;
            let r = measure_frustum_max(&view, &s)?;
            o.copy_from_slice(&[r.max_mx, r.max_mz, r.storage_factor]);
            Ok(())
        },
        message,
    )?;
    target.deliver(py, shape, v)
}

/// The perspective aliasing error ``[m_x, m_z]`` of a shadow matrix at eye-space points
/// (depth −z > 0), from the exact derivatives of s and t: the light beam widths across and
/// along the map over the image beam width 2 z tan θ / res_image (Lloyd 2006 Eq 7, 8 for any
/// matrix). matrix (4, 4) or (..., 4, 4), light_dir (3,) or (..., 3), point (3,) or (..., 3),
/// near, far, half_fov numbers or arrays, broadcast as in :func:`frustum_max`; returns (..., 2)
/// float64 (into ``out`` if given).
#[pyfunction]
#[pyo3(signature = (matrix, light_dir, point, near, far, half_fov, *, res_image=1.0, res_s=1.0,
    res_t=1.0, aspect=1.0, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn point_error<'py>(
    py: Python<'py>,
    matrix: &Any<'py>,
    light_dir: &Any<'py>,
    point: &Any<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    #[pyo3(from_py_with = args::res_image)] res_image: f64,
    #[pyo3(from_py_with = args::res_s)] res_s: f64,
    #[pyo3(from_py_with = args::res_t)] res_t: f64,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let res = Resolutions::new(res_image, res_s, res_t).map_err(crate::builders::err)?;
    let ops = [
        Operand::new("matrix", matrix, &[4, 4])?,
        Operand::new("light_dir", light_dir, &[3])?,
        Operand::new("point", point, &[3])?,
        Operand::new("near", near, &[])?,
        Operand::new("far", far, &[])?,
        Operand::new("half_fov", half_fov, &[])?,
    ];
    let [m, l, p, n, f, h] = &ops;
    let lead = lead_shape(&[m, l, p, n, f, h])?;
    let shape = [&lead[..], &[2]].concat();
    let target = Out::new(out, &shape, false)?;
    let v = each(
        py,
        [m, l, p, n, f, h],
        &lead,
        2,
        |[m, l, p, n, f, h], o| {
            let view = ViewFrustum::with_aspect(n[0], f[0], h[0], aspect)?;
            let s = ShadowMap::new(from_rows(m), DVec3::new(l[0], l[1], l[2]))?;
            let e = measure_point_error(&view, &s, DVec3::new(p[0], p[1], p[2]), res)?;
            o.copy_from_slice(&[e.mx, e.mz]);
            Ok(())
        },
        message,
    )?;
    target.deliver(py, shape, v)
}
