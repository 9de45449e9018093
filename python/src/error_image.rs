//! `error_image`: the predicted aliasing error of every pixel of a captured frame, from its depth
//! buffer and camera (the Python twin of render-check's predicted panel).
//!
//! Each pixel's surface point is recovered from the depth buffer through the inverse of
//! projection × view, its normal taken from `normals` or reconstructed from the neighbouring
//! points, and its error is the crate's exact footprint (`measure::surface_footprint`): the
//! Jacobian J of screen pixel → surface point → shadow texel, error = 1/σ_min(J) pixels per
//! texel (`Footprint::error`).

use crate::args;
use crate::broadcast::{buffer, elements, fmt_index, fmt_shape, values_of, FloatArg};
use crate::builders::from_rows;
use crate::closed::choice;
use crate::interrupt::in_blocks;
use crate::out::Out;
use glam::{DMat4, DVec3, DVec4};
use numpy::PyUntypedArrayMethods;
use pyo3::exceptions::{PyMemoryError, PyValueError};
use pyo3::prelude::*;
use rayon::prelude::*;
use shadow_aliasing::measure::{surface_footprint, Grids};
use shadow_aliasing::Error;
use std::ops::Range;

type Any<'py> = Bound<'py, PyAny>;

/// One pixel's answer: the error and J's four entries (row-major).
type Pixel = [f64; 5];

/// An array argument's shape and values (C order); a number is refused, naming the argument.
fn array(name: &str, ob: &Any<'_>) -> PyResult<(Vec<usize>, Vec<f64>)> {
    match FloatArg::extract(name, ob)? {
        FloatArg::Number(_) => Err(PyValueError::new_err(format!(
            "{name} must be an array (got a number)"
        ))),
        FloatArg::Array(a) => Ok((a.shape().to_vec(), values_of(&a)?)),
    }
}

/// A finite, invertible (4, 4) matrix argument and its inverse.
fn matrix(name: &str, ob: &Any<'_>) -> PyResult<(DMat4, DMat4)> {
    let (shape, v) = array(name, ob)?;
    if shape != [4, 4] {
        return Err(PyValueError::new_err(format!(
            "{name} must have shape (4, 4) (got {})",
            fmt_shape(&shape)
        )));
    }
    let m = from_rows(&v);
    if !m.is_finite() {
        return Err(PyValueError::new_err(format!(
            "{name} must have finite entries"
        )));
    }
    let det = m.determinant();
    let inv = m.inverse();
    if !det.is_finite() || det == 0.0 || !inv.is_finite() {
        return Err(PyValueError::new_err(format!(
            "{name} must be invertible (its determinant is {det})"
        )));
    }
    Ok((m, inv))
}

/// The predicted perspective aliasing error of every pixel of a captured frame: the Python twin
/// of render-check's predicted panel.
///
/// depth: (H, W) depth buffer as the GPU wrote it (window-space depth in [0, 1], row 0 the top
/// row as wgpu, Vulkan, Direct3D and Metal read back; flip an OpenGL read-back with
/// ``depth[::-1]``). projection: the camera's (4, 4) eye → clip matrix (row-major,
/// ``clip = P @ (x, y, z, 1)``); ``clip_depth`` says how its depth lands in the buffer:
/// "zero_to_one" (Vulkan, D3D, wgpu: depth = z/w), "neg_one_to_one" (OpenGL: depth =
/// (z/w + 1)/2) or "reversed" (a reversed-Z projection, depth = z/w, 1 nearest). view: the
/// (4, 4) world → eye matrix. shadow_matrix: (4, 4) or (m, 4, 4) world → light clip space
/// (``frame(...)["world_to_clip"]``; for the eye-space builders pass ``view=numpy.eye(4)``).
/// With several maps each pixel uses ``map_index`` ((H, W) integers, −1 for none) or, without
/// it, the first map whose square (|x/w|, |y/w| ≤ 1, w > 0) holds the point.
///
/// Each pixel's point is unprojected from its depth at the pixel's centre; its surface normal is
/// ``normals`` ((H, W, 3), world space, any length) or, by default, the cross product of the
/// steps to the neighbouring points along the row and the column, each taken on the side whose
/// depth differs less (so that an edge between two surfaces does not bend it). The error is the
/// crate's exact footprint (``measure::surface_footprint``, the Jacobian J of screen pixel →
/// surface → texel on that plane, for maps of ``map_resolution`` texels a side, or each its own
/// with ``map_resolutions``, one whole number per matrix: ``frame(...)["resolution"]``):
/// 1/σ_min(J),
/// the most pixels one texel step covers: the error lens of the crate's
/// ``FrameMap::error_lens_at`` (``Controller.error_lens``), the surface's projection factor
/// included. Returns (H, W) float64 (into ``out`` if given):
/// ``inf`` where the surface is edge-on to the light (a texel covers an unbounded strip), and
/// ``fill`` (default NaN, which matplotlib leaves blank) where there is no prediction: the
/// ``background`` depth (default 1, 0 for "reversed"), no map covering the point, a point behind
/// the camera's or the light's centre of projection, a surface edge-on to the camera, or no
/// neighbour to reconstruct a normal from. With ``return_jacobian=True`` it returns
/// ``(error, jacobian)``, the second (H, W, 2, 2) float64: J itself, row r the texel coordinate
/// (s·res, t·res), column c the pixel coordinate (column index, row index from the top); NaN
/// where the error is ``fill``.
#[pyfunction]
#[pyo3(signature = (depth, projection, view, shadow_matrix, *, map_resolution=2048,
    map_resolutions=None, clip_depth="zero_to_one", normals=None, map_index=None, background=None,
    fill=f64::NAN, return_jacobian=false, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn error_image<'py>(
    py: Python<'py>,
    depth: &Any<'py>,
    projection: &Any<'py>,
    view: &Any<'py>,
    shadow_matrix: &Any<'py>,
    #[pyo3(from_py_with = args::map_resolution)] map_resolution: u32,
    map_resolutions: Option<&Any<'py>>,
    #[pyo3(from_py_with = args::clip_depth)] clip_depth: &str,
    normals: Option<&Any<'py>>,
    map_index: Option<&Any<'py>>,
    #[pyo3(from_py_with = args::background)] background: Option<f64>,
    #[pyo3(from_py_with = args::fill)] fill: f64,
    #[pyo3(from_py_with = args::return_jacobian)] return_jacobian: bool,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let (ds, d) = array("depth", depth)?;
    let [h, w] = ds[..] else {
        return Err(PyValueError::new_err(format!(
            "depth must be a 2-D array (H, W) (got shape {})",
            fmt_shape(&ds)
        )));
    };
    if h == 0 || w == 0 || u32::try_from(h.max(w)).is_err() {
        return Err(PyValueError::new_err(format!(
            "depth must have 1 to 4294967295 rows and columns (got shape {})",
            fmt_shape(&ds)
        )));
    }
    let (proj, inv_proj) = matrix("projection", projection)?;
    let (view_m, inv_view) = matrix("view", view)?;
    let (ms, mv) = array("shadow_matrix", shadow_matrix)?;
    let maps: Vec<DMat4> = match ms[..] {
        [4, 4] => vec![from_rows(&mv)],
        [m, 4, 4] if m > 0 => {
            let mut maps = Vec::new();
            maps.try_reserve_exact(m).map_err(|_| {
                PyMemoryError::new_err(format!("shadow_matrix: {m} matrices do not fit in memory"))
            })?;
            maps.extend(mv.chunks_exact(16).map(from_rows));
            maps
        }
        _ => {
            return Err(PyValueError::new_err(format!(
                "shadow_matrix must have shape (4, 4) or (m, 4, 4) with m ≥ 1 (got {})",
                fmt_shape(&ms)
            )))
        }
    };
    if let Some(i) = maps.iter().position(|m| !m.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "shadow_matrix must have finite entries (not so at map {i})"
        )));
    }
    // A singular matrix (all zeros, a zero row) is no light's projection: it maps every point
    // behind the light or onto one line, and the image would be `fill` or ∞ throughout.
    if let Some((i, det)) = maps
        .iter()
        .map(|m| (m.determinant(), m.inverse()))
        .enumerate()
        .find_map(|(i, (det, inv))| {
            (!det.is_finite() || det == 0.0 || !inv.is_finite()).then_some((i, det))
        })
    {
        let at = if ms.len() == 3 {
            format!(" at map {i}")
        } else {
            String::new()
        };
        return Err(PyValueError::new_err(format!(
            "shadow_matrix must be invertible (its determinant is {det}{at}): pass the light's \
             world → clip matrix, e.g. frame(...)[\"world_to_clip\"]"
        )));
    }
    let reversed = match choice(
        "clip_depth",
        clip_depth,
        &["neg_one_to_one", "zero_to_one", "reversed"],
    )? {
        "neg_one_to_one" => Some(false),
        "zero_to_one" => None,
        _ => Some(true),
    };
    let background = background.unwrap_or(if reversed == Some(true) { 0.0 } else { 1.0 });
    if !background.is_finite() {
        return Err(PyValueError::new_err(format!(
            "background must be a finite depth (got {background})"
        )));
    }
    if let Some((i, v)) = d
        .iter()
        .enumerate()
        .find(|(_, v)| !(0.0..=1.0).contains(*v))
    {
        return Err(PyValueError::new_err(format!(
            "depth must hold depth-buffer values in [0, 1] (got {v} at index {}); pass the \
             window-space depth the GPU wrote, not linear eye depth",
            fmt_index(i, &ds)
        )));
    }
    let normals = match normals {
        None => None,
        Some(ob) => {
            let (ns, nv) = array("normals", ob)?;
            if ns != [h, w, 3] {
                return Err(PyValueError::new_err(format!(
                    "normals must have shape {} (depth's (H, W) and 3) (got {})",
                    fmt_shape(&[h, w, 3]),
                    fmt_shape(&ns)
                )));
            }
            Some(nv)
        }
    };
    let index = match map_index {
        None => None,
        Some(ob) => Some(map_indices(ob, h, w, maps.len())?),
    };
    let grids = match crate::frame::map_resolutions(map_resolutions)? {
        None => {
            let g =
                Grids::new(w as u32, h as u32, map_resolution, map_resolution).map_err(|_| {
                    PyValueError::new_err(format!(
                        "map_resolution must be at least 1 (got {map_resolution})"
                    ))
                })?;
            vec![g; maps.len()]
        }
        Some(each) if each.len() != maps.len() => {
            return Err(PyValueError::new_err(format!(
                "map_resolutions must hold one resolution per shadow matrix, {} (got {}): \
                 frame(...)[\"resolution\"] for frame(...)[\"world_to_clip\"]",
                maps.len(),
                each.len()
            )))
        }
        Some(each) => each
            .iter()
            .enumerate()
            .map(|(i, &r)| {
                Grids::new(w as u32, h as u32, r, r).map_err(|_| {
                    PyValueError::new_err(format!(
                        "map_resolutions must hold resolutions of at least 1 (got {r} at index \
                         {i})"
                    ))
                })
            })
            .collect::<PyResult<Vec<_>>>()?,
    };
    let target = Out::new(out, &[h, w], false)?;
    let camera = proj * view_m;
    let eye = inv_view.transform_point3(DVec3::ZERO);
    // Room for the results before any work: an image larger than memory is a `MemoryError`
    // here, never an abort halfway. The points are kept for a band of rows at a time.
    let n = h * w;
    let mut error = buffer(n, &[h, w])?;
    error.resize(n, 0.0);
    let mut jacobian = Vec::new();
    if return_jacobian {
        let shape = [h, w, 2, 2];
        jacobian = buffer(elements(&shape)?, &shape)?;
        jacobian.resize(4 * n, 0.0);
    }
    let ctx = Context {
        d: &d,
        w,
        h,
        reversed,
        background,
        fill,
        inv_proj,
        inv_view,
        camera,
        eye,
        normals: normals.as_deref(),
        index: index.as_deref(),
        maps: &maps,
        grids,
    };
    let mut points = Vec::new();
    // Bands of rows, each taking about 20 ms (the first about 16 384 pixels), Ctrl-C seen
    // between them; the first failing pixel in C order stops the image.
    let stop = in_blocks(py, h, (16 * 1024 / w).max(1), |rows| {
        ctx.band(rows, &mut points, &mut error, &mut jacobian)
    })?;
    match stop {
        None => {
            let error = target.deliver(py, vec![h, w], error)?;
            if !return_jacobian {
                return Ok(error);
            }
            let j = crate::broadcast::to_python(py, vec![h, w, 2, 2], jacobian)?;
            Ok(pyo3::types::PyTuple::new(py, [error, j])?.into_any())
        }
        Some(Stop::Memory(rows)) => Err(PyMemoryError::new_err(format!(
            "the points of {rows} rows of {w} pixels do not fit in memory"
        ))),
        Some(Stop::Pixel(i, name, why)) => Err(PyValueError::new_err(format!(
            "{name} at pixel {}: {why}",
            fmt_index(i, &[h, w])
        ))),
    }
}

/// Why a band of rows stopped the image.
enum Stop {
    /// The band's points found no room (its number of rows).
    Memory(usize),
    /// The first pixel (index, argument to blame, reason) the crate refuses.
    Pixel(usize, &'static str, String),
}

/// Everything a pixel's prediction reads.
struct Context<'a> {
    d: &'a [f64],
    w: usize,
    h: usize,
    reversed: Option<bool>,
    background: f64,
    fill: f64,
    inv_proj: DMat4,
    inv_view: DMat4,
    camera: DMat4,
    eye: DVec3,
    normals: Option<&'a [f64]>,
    index: Option<&'a [i64]>,
    maps: &'a [DMat4],
    /// Each map's texel grid (its resolution).
    grids: Vec<Grids>,
}

impl Context<'_> {
    /// The world point of pixel `i` (NaN where there is none): unprojected from its depth at
    /// the pixel's centre.
    fn point(&self, i: usize) -> DVec3 {
        let (x, y, w, h) = (i % self.w, i / self.w, self.w, self.h);
        let z = self.d[i];
        if z == self.background {
            return DVec3::NAN;
        }
        let z_ndc = if self.reversed == Some(false) {
            2.0 * z - 1.0
        } else {
            z
        };
        let ndc = DVec4::new(
            2.0 * (x as f64 + 0.5) / w as f64 - 1.0,
            1.0 - 2.0 * (y as f64 + 0.5) / h as f64,
            z_ndc,
            1.0,
        );
        let e = self.inv_proj * ndc;
        if e.w != 0.0 {
            let q = self.inv_view.transform_point3(e.truncate() / e.w);
            if q.is_finite() {
                return q;
            }
        }
        DVec3::NAN
    }

    /// Rows `rows` of the image into `error` (and `jacobian`, if it has room for the image):
    /// first the points of those rows and one row either side into `points` (pixel `i` at
    /// `points[i - base]`), then each pixel's normal, map and footprint, over all cores.
    fn band(
        &self,
        rows: Range<usize>,
        points: &mut Vec<DVec3>,
        error: &mut [f64],
        jacobian: &mut [f64],
    ) -> Option<Stop> {
        let w = self.w;
        let (p0, p1) = (rows.start.saturating_sub(1), (rows.end + 1).min(self.h));
        let len = (p1 - p0) * w;
        points.clear();
        if points.try_reserve_exact(len).is_err() {
            return Some(Stop::Memory(p1 - p0));
        }
        points.resize(len, DVec3::NAN);
        let base = p0 * w;
        points.par_chunks_mut(w).enumerate().for_each(|(r, row)| {
            for (x, p) in row.iter_mut().enumerate() {
                *p = self.point(base + r * w + x);
            }
        });
        let points = &points[..];
        let pixel = |i: usize| self.pixel(points, base, i);
        let error = &mut error[rows.start * w..rows.end * w];
        let failure = |y: usize, e: &mut [f64], j: Option<&mut [f64]>| -> Option<Stop> {
            let mut j = j;
            for (x, out) in e.iter_mut().enumerate() {
                let i = y * w + x;
                match pixel(i) {
                    Ok(px) => {
                        *out = px[0];
                        if let Some(j) = j.as_deref_mut() {
                            j[4 * x..4 * x + 4].copy_from_slice(&px[1..]);
                        }
                    }
                    Err((name, why)) => return Some(Stop::Pixel(i, name, why)),
                }
            }
            None
        };
        if jacobian.is_empty() {
            error
                .par_chunks_mut(w)
                .enumerate()
                .find_map_first(|(r, e)| failure(rows.start + r, e, None))
        } else {
            let jacobian = &mut jacobian[4 * rows.start * w..4 * rows.end * w];
            error
                .par_chunks_mut(w)
                .zip(jacobian.par_chunks_mut(4 * w))
                .enumerate()
                .find_map_first(|(r, (e, j))| failure(rows.start + r, e, Some(j)))
        }
    }

    /// Pixel `i`'s error and J's four entries (row-major), or the argument to blame and why.
    fn pixel(
        &self,
        points: &[DVec3],
        base: usize,
        i: usize,
    ) -> Result<Pixel, (&'static str, String)> {
        let none = [self.fill, f64::NAN, f64::NAN, f64::NAN, f64::NAN];
        let p = points[i - base];
        if !p.is_finite() {
            return Ok(none);
        }
        let nrm = match self.normals {
            Some(nv) => {
                let v = DVec3::new(nv[3 * i], nv[3 * i + 1], nv[3 * i + 2]);
                if !v.is_finite() || v.length_squared() == 0.0 {
                    return Err(("normals", format!("is {v}")));
                }
                v
            }
            None => match normal_from_depth(points, base, self.d, self.w, self.h, i, self.eye) {
                Some(v) => v,
                None => return Ok(none),
            },
        };
        let k = match self.index {
            Some(ix) => match ix[i] {
                k if k < 0 => return Ok(none),
                k => k as usize,
            },
            None => match self.maps.iter().position(|m| covers(m, p)) {
                Some(k) => k,
                None => return Ok(none),
            },
        };
        match surface_footprint(&self.camera, &self.maps[k], self.grids[k], p, nrm) {
            // Only a singular J (edge-on to the light) has no finite error.
            Ok(fp) => {
                let j = fp.jacobian;
                Ok([
                    fp.error().unwrap_or(f64::INFINITY),
                    j.x_axis.x,
                    j.y_axis.x,
                    j.x_axis.y,
                    j.y_axis.y,
                ])
            }
            Err(Error::Degenerate(_)) => Ok(none),
            Err(e) => {
                let name = match &e {
                    Error::InvalidArgument { name: "camera", .. } => "projection",
                    Error::InvalidArgument { name: "light", .. } => "shadow_matrix",
                    Error::InvalidArgument { name: "normal", .. } => "normals",
                    _ => "depth",
                };
                Err((name, e.to_string()))
            }
        }
    }
}

/// Whether the light clip square of `m` holds `p` (w > 0, |x/w|, |y/w| ≤ 1).
fn covers(m: &DMat4, p: DVec3) -> bool {
    let c = *m * p.extend(1.0);
    c.w > 0.0 && c.x.abs() <= c.w && c.y.abs() <= c.w
}

/// The surface normal at pixel `i` from its neighbours' points: along the row and along the
/// column the step to the neighbour whose depth differs less (either side), crossed, and turned
/// toward the camera at `eye`. Pixel `j`'s point is `points[j - base]`. `None` when a direction has no neighbour with a point.
fn normal_from_depth(
    points: &[DVec3],
    base: usize,
    depth: &[f64],
    w: usize,
    h: usize,
    i: usize,
    eye: DVec3,
) -> Option<DVec3> {
    let (x, y) = (i % w, i / w);
    let point = |j: usize| points[j - base];
    let p = point(i);
    let step = |before: Option<usize>, after: Option<usize>| -> Option<DVec3> {
        let ok = |j: Option<usize>| j.filter(|&j| point(j).is_finite());
        match (ok(before), ok(after)) {
            (Some(a), Some(b)) => Some(
                if (depth[b] - depth[i]).abs() <= (depth[i] - depth[a]).abs() {
                    point(b) - p
                } else {
                    p - point(a)
                },
            ),
            (None, Some(b)) => Some(point(b) - p),
            (Some(a), None) => Some(p - point(a)),
            (None, None) => None,
        }
    };
    let dx = step((x > 0).then(|| i - 1), (x + 1 < w).then(|| i + 1))?;
    let dy = step((y > 0).then(|| i - w), (y + 1 < h).then(|| i + w))?;
    let n = dx.cross(dy);
    if !n.is_finite() || n.length_squared() == 0.0 {
        return None;
    }
    Some(if n.dot(eye - p) < 0.0 { -n } else { n })
}

/// `map_index`: (H, W) whole numbers in −1 .. m − 1.
fn map_indices(ob: &Any<'_>, h: usize, w: usize, m: usize) -> PyResult<Vec<i64>> {
    let (s, v) = array("map_index", ob)?;
    if s != [h, w] {
        return Err(PyValueError::new_err(format!(
            "map_index must have depth's shape {} (got {})",
            fmt_shape(&[h, w]),
            fmt_shape(&s)
        )));
    }
    let mut out = Vec::new();
    out.try_reserve_exact(v.len()).map_err(|_| {
        PyMemoryError::new_err(format!(
            "map_index: an array of shape {} does not fit in memory",
            fmt_shape(&s)
        ))
    })?;
    for (i, &k) in v.iter().enumerate() {
        if k.fract() != 0.0 || k < -1.0 || k >= m as f64 {
            return Err(PyValueError::new_err(format!(
                "map_index must hold whole numbers from -1 (no map) to {} (got {k} at index {})",
                m - 1,
                fmt_index(i, &s)
            )));
        }
        // Whole, in [-1, m): exact.
        out.push(k as i64);
    }
    Ok(out)
}
