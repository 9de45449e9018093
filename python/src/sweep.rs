//! The hemisphere sweep, in blocks of the grid with a check for Ctrl-C between them.
//!
//! The library sweeps a block of the grid without the GIL (`sweep_block_into`, over all cores);
//! between blocks the GIL is taken back and Python's signal handlers run
//! (`Python::check_signals`), so that Ctrl-C raises `KeyboardInterrupt` within about one
//! block's time. The blocks are sized to take about [`BLOCK_SECONDS`] from the speed measured on
//! the blocks before (the first ones small), whatever the scheme's cost per direction.

use crate::args;
use crate::broadcast::to_python;
use crate::builders::{err, view_of, RuleParams};
use crate::closed::choice;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::scheme::sweep::{sweep_block_into, SweepGrid};
use shadow_aliasing::scheme::Partition;
use shadow_aliasing::ViewFrustum;
use std::ops::Range;
use std::time::Instant;

type Any<'py> = Bound<'py, PyAny>;

/// The time one block of a sweep should take: the longest wait for Ctrl-C to be seen, less than
/// a tenth of the 0.2 s a person notices, and long enough that the pauses between blocks cost
/// nothing measurable.
const BLOCK_SECONDS: f64 = 0.02;

/// Directions per thread in the first block, before any speed is measured (a few milliseconds
/// for the costliest schemes: face partitions with k = 16).
const FIRST_BLOCK_PER_THREAD: usize = 32;

/// One scheme's sweep over a grid, driven block by block.
struct Blocks<'a> {
    view: &'a ViewFrustum,
    rule: WarpRule,
    partition: Partition,
    k: usize,
    grid: SweepGrid,
}

impl Blocks<'_> {
    /// Sweeps rows × cols without the GIL into `out`, which holds those rows whole (`stride`
    /// values each; the block's columns are written, the others kept), then runs Python's
    /// signal handlers (`KeyboardInterrupt` from Ctrl-C, before the sweep's own error if any).
    fn run(
        &self,
        py: Python<'_>,
        rows: Range<usize>,
        cols: Range<usize>,
        out: &mut [f64],
        stride: usize,
        tile: &mut Vec<f64>,
    ) -> PyResult<()> {
        let Blocks {
            view,
            rule,
            partition,
            k,
            grid,
        } = *self;
        let swept = if cols.len() == stride {
            // Whole rows: the block is one run of `out`.
            py.detach(|| sweep_block_into(view, rule, partition, k, grid, rows, cols, out))
        } else {
            tile.clear();
            tile.resize(rows.len() * cols.len(), 0.0);
            let (c0, w) = (cols.start, cols.len());
            py.detach(|| sweep_block_into(view, rule, partition, k, grid, rows, cols, tile))
                .map(|()| {
                    for (row, values) in out.chunks_exact_mut(stride).zip(tile.chunks_exact(w)) {
                        row[c0..c0 + w].copy_from_slice(values);
                    }
                })
        };
        py.check_signals()?;
        swept.map_err(err)
    }
}

/// The sweep of the whole grid, block by block, Ctrl-C seen between blocks. The blocks are bands
/// of whole rows (at least one row per thread) while a band takes about [`BLOCK_SECONDS`], and
/// otherwise bands of one row per thread cut into pieces of columns. A failing direction raises
/// the crate's error for the first failing direction in grid order, as the whole-grid sweep does.
fn sweep_in_blocks(py: Python<'_>, b: &Blocks<'_>) -> PyResult<Vec<f64>> {
    let (e, a) = (b.grid.elevations(), b.grid.azimuths());
    let threads = rayon::current_num_threads().max(1);
    let mut out = crate::broadcast::buffer(b.grid.len(), &[e, a])?;
    out.resize(b.grid.len(), 0.0);
    let mut tile = Vec::new();
    let mut budget = FIRST_BLOCK_PER_THREAD * threads;
    let mut r0 = 0;
    while r0 < e {
        let whole_rows = budget >= threads * a;
        let band = if whole_rows {
            (budget / a).clamp(1, e - r0)
        } else {
            threads.min(e - r0)
        };
        let rows = r0..r0 + band;
        let dst = &mut out[r0 * a..(r0 + band) * a];
        let mut c0 = 0;
        while c0 < a {
            let width = if whole_rows {
                a
            } else {
                (budget / band).clamp(1, a - c0)
            };
            let cols = c0..c0 + width;
            let started = Instant::now();
            if let Err(failure) = b.run(py, rows.clone(), cols.clone(), dst, a, &mut tile) {
                if band == 1 || width == a || !failure.is_instance_of::<PyValueError>(py) {
                    return Err(failure);
                }
                // A piece of a band failed: the columns from c0 on of the band's rows above the
                // failing one are not swept yet, and one of them may fail first in grid order.
                // Sweep the rest of the band row by row; its first failure is that one.
                for i in rows.clone() {
                    let row = &mut dst[(i - r0) * a..(i - r0 + 1) * a];
                    for c in (c0..a).step_by(width) {
                        b.run(py, i..i + 1, c..(c + width).min(a), row, a, &mut tile)?;
                    }
                }
                return Err(failure);
            }
            // The next block's size from this one's speed: at most 4× larger, so that one
            // block that happened to be fast does not make the next one long.
            let seconds = started.elapsed().as_secs_f64().max(1e-6);
            let done = (rows.len() * cols.len()) as f64;
            let next = (done / seconds * BLOCK_SECONDS).min(4.0 * budget as f64);
            budget = (next as usize).clamp(1, b.grid.len());
            c0 += width;
        }
        r0 += band;
    }
    Ok(out)
}

/// The elevations and azimuths of a sweep's grid: el_i = i (π/2)/(E − 1), both ends included
/// (π/2 alone for E = 1), and az_j = j 2π/A, 2π excluded. Returns ``(el, az)``, 1-D float64.
#[pyfunction]
pub fn sweep_angles<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::elevations)] elevations: usize,
    #[pyo3(from_py_with = args::azimuths)] azimuths: usize,
) -> PyResult<(Any<'py>, Any<'py>)> {
    let g = SweepGrid::new(elevations, azimuths).map_err(err)?;
    let el: Vec<f64> = (0..elevations).map(|i| g.elevation(i)).collect();
    let az: Vec<f64> = (0..azimuths).map(|j| g.azimuth(j)).collect();
    Ok((
        to_python(py, vec![elevations], el)?,
        to_python(py, vec![azimuths], az)?,
    ))
}

/// The storage factor S̄ (summed over the scheme's maps) for every light direction of the
/// hemisphere (Lloyd 2006 Fig 7's layout): light travels −D with
/// D = (cos el sin az, sin el, cos el cos az); az = 0 is the light behind the viewer, el = π/2
/// overhead. The scheme is ``rule`` (as in :func:`warp`) with ``partition`` "single", "uniform",
/// "log", "practical" (``lambda_``), "adaptive" or "faces" and ``k`` partitions, each map measured
/// at its partition's vertices. Runs without the GIL, over all cores (rayon; set
/// ``RAYON_NUM_THREADS`` to limit), in blocks of about 20 ms: Ctrl-C raises
/// ``KeyboardInterrupt`` between two blocks. Returns an (elevations, azimuths) float64 array.
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, rule="minimax", partition="single", k=1, *,
    elevations=90, azimuths=360, lambda_=None, eta=None, focus=None, near_hint=None,
    far_hint=None, shadow_distance=None, aspect=1.0))]
#[allow(clippy::too_many_arguments)]
pub fn sweep<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    #[pyo3(from_py_with = args::rule)] rule: &str,
    #[pyo3(from_py_with = args::partition)] partition: &str,
    #[pyo3(from_py_with = args::k)] k: usize,
    #[pyo3(from_py_with = args::elevations)] elevations: usize,
    #[pyo3(from_py_with = args::azimuths)] azimuths: usize,
    #[pyo3(from_py_with = args::lambda_)] lambda_: Option<f64>,
    #[pyo3(from_py_with = args::eta)] eta: Option<f64>,
    #[pyo3(from_py_with = args::focus)] focus: Option<f64>,
    #[pyo3(from_py_with = args::near_hint)] near_hint: Option<f64>,
    #[pyo3(from_py_with = args::far_hint)] far_hint: Option<f64>,
    #[pyo3(from_py_with = args::shadow_distance)] shadow_distance: Option<f64>,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
) -> PyResult<Any<'py>> {
    let view = view_of(near, far, half_fov, aspect)?;
    let part = choice(
        "partition",
        partition,
        &["single", "uniform", "log", "practical", "adaptive", "faces"],
    )?;
    if lambda_.is_some() && part != "practical" {
        return Err(PyValueError::new_err(format!(
            "lambda_ is not an argument of partition \"{part}\" (only of partition \"practical\")"
        )));
    }
    if part == "single" && k != 1 {
        return Err(PyValueError::new_err(format!(
            "k must be 1 with partition \"single\" (got {k})"
        )));
    }
    if part != "single" && focus.is_none() && rule.replace('_', "-") == "tsm" {
        return Err(PyValueError::new_err(
            "focus is missing: rule \"tsm\" with partitions needs focus (world units beyond each partition's near plane)",
        ));
    }
    let p = match part {
        "single" => Partition::Single,
        "uniform" => Partition::Uniform,
        "log" => Partition::Log,
        "practical" => Partition::Practical(lambda_.ok_or_else(|| {
            PyValueError::new_err("lambda_ is missing (partition \"practical\" needs it)")
        })?),
        "adaptive" => Partition::Adaptive,
        _ => Partition::Faces,
    };
    let r = crate::builders::rule(
        &view,
        rule,
        RuleParams {
            eta,
            focus,
            near_hint,
            far_hint,
            shadow_distance,
        },
    )?;
    let grid = SweepGrid::new(elevations, azimuths).map_err(err)?;
    let blocks = Blocks {
        view: &view,
        rule: r,
        partition: p,
        k,
        grid,
    };
    let out = sweep_in_blocks(py, &blocks)?;
    to_python(py, vec![elevations, azimuths], out)
}
