//! The storage factor over the hemisphere of light directions, for any scheme, and the fast
//! vertex measurement behind it.
//!
//! # Directions
//!
//! A light direction is given by its elevation `el` above the viewer's horizon and its azimuth
//! `az` around the eye-space Y axis. The direction *towards* the light source is
//!
//! ```text
//! D = (cos el · sin az, sin el, cos el · cos az)        (eye space)
//! ```
//!
//! and light travels along `−D`. So `el = π/2` is the light overhead, `az = 0` puts the light
//! source behind the viewer (light travels along the view direction −Z) and `az = π` in front of
//! the viewer (light travels towards the camera). This is the layout of Lloyd 2006 Fig 7: overhead
//! at the centre, behind and in front at the sides.
//!
//! # Grid
//!
//! A [`SweepGrid`] of `E` elevation rows and `A` azimuth columns samples
//! `el_i = i · (π/2)/(E − 1)`, `i = 0..E` — both ends included, the horizon `el = 0` and the zenith
//! `el = π/2` (with `E = 1` the single row is the zenith) — and `az_j = j · 2π/A`, `j = 0..A`:
//! `0` included, `2π` excluded (it is `az = 0` again). Values are stored row by row (elevation
//! major): the value of `(i, j)` is at `i · A + j`.
//!
//! # Speed
//!
//! [`sweep`] measures the scheme's own matrices at the vertices of each partition only, with
//! [`vertex_max`](crate::measure::vertex::vertex_max) (no validation, no allocation); each elevation row reuses one stack-allocated
//! [`SchemeResult`]. A single map ([`Partition::Single`]) of the uniform, PSM, LiSPSM, η, 1/sin γ
//! LiSPSM or reference LiSPSM rule is evaluated four directions at a time: the scalar builder's
//! and [`vertex_max`](crate::measure::vertex::vertex_max)'s own functions, generic over
//! `numeric::lane`, run on four directions laid out side by side, so every value is the scalar
//! scheme's bit for bit; a direction the lane code does not take (the light parallel to the view
//! axis, a degenerate fit, any doubt) goes through the scalar code. With the `parallel` feature
//! the rows are spread over all cores with rayon; without it the same code runs serially.
//!
//! ```
//! use shadow_aliasing::scheme::sweep::{light_dir_from_angles, SweepGrid};
//! let g = SweepGrid::new(3, 4)?;
//! assert_eq!(g.elevation(2), std::f64::consts::FRAC_PI_2);
//! assert_eq!(g.azimuth(1), std::f64::consts::FRAC_PI_2);
//! // az = 0 at the horizon: the source is behind the viewer, light travels down −Z.
//! let l = light_dir_from_angles(0.0, 0.0);
//! assert!((l.z + 1.0).abs() < 1e-15);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::scheme::{scheme_into, scheme_into_prepared, Partition, Prepared, SchemeResult};
use lanes::{LaneSweep, LANES};

mod lanes;
use crate::error::{fmt_num, Error, Result};
use crate::frustum::{LightDir, ViewFrustum};
use crate::maps::WarpRule;
/// The jump of error across each seam between neighbouring partitions of a scheme (defined with
/// the scheme, re-exported here beside the other measurements of partitions).
pub use crate::scheme::{seams, Seam, Seams};
use glam::DVec3;

/// The eye-space direction light *travels* for elevation `el` and azimuth `az` (radians):
/// `−D` with `D = (cos el · sin az, sin el, cos el · cos az)` towards the source. `az = 0` is the
/// source behind the viewer, `az = π` in front, `el = π/2` overhead.
#[inline]
#[must_use]
pub fn light_dir_from_angles(el: f64, az: f64) -> DVec3 {
    let (se, ce) = el.sin_cos();
    let (sa, ca) = az.sin_cos();
    -DVec3::new(ce * sa, se, ce * ca)
}

/// The grid of light directions of a hemisphere sweep (see the module docs for both ends).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SweepGrid {
    elevations: usize,
    azimuths: usize,
}

/// The largest number of directions a sweep accepts (16 million), so the value buffer stays
/// within memory.
pub const MAX_SWEEP_DIRECTIONS: usize = 1 << 24;

impl SweepGrid {
    /// `elevations` rows over `[0, π/2]` (both ends) and `azimuths` columns over `[0, 2π)`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `elevations` or `azimuths` when zero, or when their
    /// product exceeds [`MAX_SWEEP_DIRECTIONS`].
    pub fn new(elevations: usize, azimuths: usize) -> Result<Self> {
        if elevations == 0 {
            return Err(Error::invalid("elevations", "must be at least 1 (got 0)"));
        }
        if azimuths == 0 {
            return Err(Error::invalid("azimuths", "must be at least 1 (got 0)"));
        }
        if elevations.saturating_mul(azimuths) > MAX_SWEEP_DIRECTIONS {
            return Err(Error::invalid(
                "azimuths",
                format!(
                    "times elevations must not exceed {MAX_SWEEP_DIRECTIONS} (got {elevations} × {azimuths})"
                ),
            ));
        }
        Ok(Self {
            elevations,
            azimuths,
        })
    }
    /// Number of elevation rows.
    #[must_use]
    pub fn elevations(&self) -> usize {
        self.elevations
    }
    /// Number of azimuth columns.
    #[must_use]
    pub fn azimuths(&self) -> usize {
        self.azimuths
    }
    /// Number of directions, rows × columns.
    #[must_use]
    pub fn len(&self) -> usize {
        self.elevations * self.azimuths
    }
    /// Always false: a grid has at least one direction.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        false
    }
    /// Elevation of row `i`: `i · (π/2)/(E − 1)`, or π/2 when `E = 1`.
    #[must_use]
    pub fn elevation(&self, i: usize) -> f64 {
        if self.elevations == 1 {
            std::f64::consts::FRAC_PI_2
        } else if i + 1 >= self.elevations {
            // Exactly π/2 on the last row, whatever the rounding of the product.
            std::f64::consts::FRAC_PI_2
        } else {
            i as f64 * std::f64::consts::FRAC_PI_2 / (self.elevations - 1) as f64
        }
    }
    /// Azimuth of column `j`: `j · 2π/A`.
    #[must_use]
    pub fn azimuth(&self, j: usize) -> f64 {
        j as f64 * std::f64::consts::TAU / self.azimuths as f64
    }
}

/// The storage factor over a [`SweepGrid`], row by row (elevation major).
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// The grid the values belong to.
    pub grid: SweepGrid,
    /// S̄ summed over the scheme's partitions, at `i · azimuths + j`.
    pub storage_factor: Vec<f64>,
}

impl Sweep {
    /// `(elevation, azimuth, storage_factor)` of every direction, row by row.
    pub fn rows(&self) -> impl Iterator<Item = (f64, f64, f64)> + '_ {
        self.storage_factor.iter().enumerate().map(|(n, &v)| {
            let (i, j) = (n / self.grid.azimuths, n % self.grid.azimuths);
            (self.grid.elevation(i), self.grid.azimuth(j), v)
        })
    }
    /// The largest storage factor over the hemisphere.
    #[must_use]
    pub fn max(&self) -> f64 {
        self.storage_factor.iter().fold(0.0, |a, &b| a.max(b))
    }
}

/// The storage factor S̄ (summed over partitions) of the scheme `(rule, partition, k)` for every
/// light direction of `grid`, from the crate's measurement of the scheme's own matrices at the
/// partitions' vertices. Parallel over cores with the `parallel` feature (rayon's global pool:
/// set its size with `RAYON_NUM_THREADS` or a `rayon::ThreadPool::install`), serial without.
///
/// # Errors
/// An error of [`crate::scheme::scheme`] at some direction, of the same kind and with that
/// direction named once (`no solution: at elevation=0, azimuth=0 (row 0, column 0 of the
/// sweep): …`): the first in grid order, whether serial or parallel. Validation errors of the
/// rule, `partition` or `k` are found first, at the zenith, and reported as the scheme reports
/// them. A direction without a solution (for instance [`Partition::AdaptiveRatio`]'s planes at a
/// light near the view axis) fails the whole sweep, naming it: no value is left unset or NaN.
///
/// ```
/// use shadow_aliasing::scheme::Partition;
/// use shadow_aliasing::scheme::sweep::{sweep, SweepGrid};
/// use shadow_aliasing::maps::WarpRule;
/// use shadow_aliasing::ViewFrustum;
/// let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
/// let s = sweep(&view, WarpRule::Uniform, Partition::Single, 1, SweepGrid::new(4, 8)?)?;
/// assert_eq!(s.storage_factor.len(), 32);
/// assert!(s.storage_factor.iter().all(|v| v.is_finite() && *v > 0.0));
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn sweep(
    view: &ViewFrustum,
    rule: WarpRule,
    partition: Partition,
    k: usize,
    grid: SweepGrid,
) -> Result<Sweep> {
    let mut values = vec![0.0; grid.len()];
    sweep_into(view, rule, partition, k, grid, &mut values)?;
    Ok(Sweep {
        grid,
        storage_factor: values,
    })
}

/// As [`sweep`], writing into a caller's buffer of `grid.len()` values (no allocation at all).
///
/// # Errors
/// As [`sweep`]; [`Error::InvalidArgument`] naming `out` when its length is not `grid.len()`.
pub fn sweep_into(
    view: &ViewFrustum,
    rule: WarpRule,
    partition: Partition,
    k: usize,
    grid: SweepGrid,
    out: &mut [f64],
) -> Result<()> {
    let (rows, cols) = (0..grid.elevations, 0..grid.azimuths);
    sweep_block_into(view, rule, partition, k, grid, rows, cols, out)
}

/// As [`sweep_into`], for one block of the grid only: the rows `rows` (elevations) and columns
/// `cols` (azimuths), written row by row into `out` of `rows.len() × cols.len()` values (the
/// value of grid cell `(i, j)` at `(i − rows.start) · cols.len() + (j − cols.start)`). Each value
/// is bit for bit the one [`sweep_into`] writes for that cell, so a caller can cover the grid
/// in blocks, e.g. to stay responsive between them (the Python bindings check for Ctrl-C between
/// blocks); tests/sweep_rows.rs compares both.
///
/// # Errors
/// As [`sweep`], the failing direction being the first of the block in grid order;
/// [`Error::InvalidArgument`] naming `rows` or `cols` when the range is not within the grid, or
/// `out` when its length is not `rows.len() × cols.len()`.
#[allow(clippy::too_many_arguments)]
pub fn sweep_block_into(
    view: &ViewFrustum,
    rule: WarpRule,
    partition: Partition,
    k: usize,
    grid: SweepGrid,
    rows: std::ops::Range<usize>,
    cols: std::ops::Range<usize>,
    out: &mut [f64],
) -> Result<()> {
    for (name, r, end) in [
        ("rows", &rows, grid.elevations),
        ("cols", &cols, grid.azimuths),
    ] {
        if r.start > r.end || r.end > end {
            return Err(Error::invalid(
                name,
                format!(
                    "must be a range within 0..{end} (got {}..{})",
                    r.start, r.end
                ),
            ));
        }
    }
    let len = rows.len() * cols.len();
    if out.len() != len {
        return Err(Error::invalid(
            "out",
            format!("must hold {len} values (got {})", out.len()),
        ));
    }
    // Validate the scheme once, at the zenith, so argument errors are reported as such.
    let mut probe = SchemeResult::default();
    scheme_into(view, DVec3::NEG_Y, rule, partition, k, &mut probe)?;
    let prep = Prepared::new(view);
    // A single map of a rule whose n′ the lane code computes: LANES directions at a time, bit for
    // bit the scalar values (`lanes`).
    let lanes = if partition == Partition::Single {
        let fixed = crate::maps::n_prime_for(view, DVec3::NEG_Y, rule).ok();
        LaneSweep::new(view, rule, fixed)
    } else {
        None
    };
    // S̄ of one direction: light_dir_from_angles(el, az) from the angles' sines and cosines,
    // normalised as `scheme` normalises it (so the value is bit for bit `scheme`'s).
    let one = |(se, ce): (f64, f64), (sa, ca): (f64, f64), buf: &mut SchemeResult| {
        let l = LightDir::new(-DVec3::new(ce * sa, se, ce * ca))?;
        scheme_into_prepared(&prep, l, rule, partition, k, buf).map(|()| buf.storage_factor())
    };
    // The azimuths' sines and cosines are taken once per block of columns for all rows, not once
    // per direction (the same values: the same `sin_cos` of the same azimuth), in a stack table.
    const BLOCK: usize = 512;
    let mut table = [(0.0, 0.0); BLOCK];
    // The block's width; `first` below counts its columns from `cols.start`.
    let a = cols.len();
    let mut ok = true;
    for first in (0..a).step_by(BLOCK) {
        let n = BLOCK.min(a - first);
        for (j, t) in table[..n].iter_mut().enumerate() {
            *t = grid.azimuth(cols.start + first + j).sin_cos();
        }
        let table = &table[..n];
        let row = |i: usize, values: &mut [f64]| -> bool {
            let el = grid.elevation(rows.start + i).sin_cos();
            let values = &mut values[first..first + n];
            if let Some(lanes) = &lanes {
                // The scalar code's result buffer (several KB) only for a row that needs it.
                let mut buf: Option<SchemeResult> = None;
                // LANES directions at a time; a lane the lane code cannot take (or the padding
                // of the last group, which repeats its last direction) goes through `one`.
                for (vs, azs) in values.chunks_mut(LANES).zip(table.chunks(LANES)) {
                    let az: [(f64, f64); LANES] =
                        std::array::from_fn(|j| azs[j.min(azs.len() - 1)]);
                    let (s, ok) = lanes.run(el, &az);
                    for (j, v) in vs.iter_mut().enumerate() {
                        if ok[j] {
                            *v = s[j];
                        } else {
                            match one(el, az[j], buf.get_or_insert_with(SchemeResult::default)) {
                                Ok(s) => *v = s,
                                Err(_) => return false,
                            }
                        }
                    }
                }
                return true;
            }
            let mut buf = SchemeResult::default();
            for (v, &az) in values.iter_mut().zip(table) {
                match one(el, az, &mut buf) {
                    Ok(s) => *v = s,
                    Err(_) => return false,
                }
            }
            true
        };
        #[cfg(feature = "parallel")]
        {
            use rayon::prelude::*;
            ok = out
                .par_chunks_mut(a)
                .enumerate()
                .all(|(i, values)| row(i, values));
        }
        #[cfg(not(feature = "parallel"))]
        {
            ok = out
                .chunks_mut(a)
                .enumerate()
                .all(|(i, values)| row(i, values));
        }
        if !ok {
            break;
        }
    }
    if ok {
        return Ok(());
    }
    // Some direction failed: find the first in grid order, serially, and report it.
    let mut buf = SchemeResult::default();
    for i in rows.clone() {
        let el = grid.elevation(i);
        for j in cols.clone() {
            let az = grid.azimuth(j);
            one(el.sin_cos(), az.sin_cos(), &mut buf).map_err(|e| at_cell(e, &grid, i, j))?;
        }
    }
    Ok(())
}

/// The scheme's error `e` at grid cell `(i, j)`, its kind kept and the cell named once:
/// `no solution: at elevation=0, azimuth=0 (row 0, column 0 of the sweep): adaptive …`.
#[cold]
fn at_cell(e: Error, grid: &SweepGrid, i: usize, j: usize) -> Error {
    let at = format!(
        "at elevation={}, azimuth={} (row {i}, column {j} of the sweep)",
        fmt_num(grid.elevation(i)),
        fmt_num(grid.azimuth(j))
    );
    match e {
        Error::InvalidArgument { name, reason } => Error::InvalidArgument {
            name,
            reason: format!("{reason}, {at}"),
        },
        Error::NoSolution(m) => Error::NoSolution(format!("{at}: {m}")),
        Error::NoClosedForm(m) => Error::NoClosedForm(format!("{at}: {m}")),
        Error::Degenerate(m) => Error::Degenerate(format!("{at}: {m}")),
    }
}
