//! Builders and measurements over stacks: NumPy broadcasting of arguments that have core axes.
//!
//! Each argument is a stack of items: one number (`near`, `far`, `half_fov`: no core axis), a
//! vector (`light_dir`, `point`: core `(3,)`) or a matrix (`matrix`: core `(4, 4)`). The leading
//! axes (the shape before the core) broadcast as NumPy broadcasts, and the call runs once per
//! element of the broadcast leading shape, without the GIL and over all cores, writing `width`
//! numbers per element. The result's shape is the broadcast leading shape followed by the
//! result's own core (`(4, 4)` for a matrix, `(3,)` for `[M_x, M_z, S̄]`, none for n′). Each
//! element's value is the one-item call's bit for bit. The first element (C order) the crate
//! refuses raises `ValueError` with its message and, for a stack, `(at index (i, …))`.

use crate::broadcast::{
    broadcast_shapes, buffer, elements, fmt_index, fmt_shape, values_of, FloatArg,
};
use numpy::PyUntypedArrayMethods;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use shadow_aliasing::Error;

type Any<'py> = Bound<'py, PyAny>;

/// One stacked argument: its name, leading shape, core length and values (C order).
pub struct Operand {
    name: &'static str,
    lead: Vec<usize>,
    core: usize,
    values: Vec<f64>,
}

impl Operand {
    /// `ob` as a stack of items of shape `core` (empty: numbers): a shape ending in `core`.
    pub fn new(name: &'static str, ob: &Any<'_>, core: &[usize]) -> PyResult<Self> {
        let (shape, values) = match FloatArg::extract(name, ob)? {
            FloatArg::Number(v) => (Vec::new(), vec![v]),
            FloatArg::Array(a) => (a.shape().to_vec(), values_of(&a)?),
        };
        let split = shape.len().checked_sub(core.len());
        let Some(split) = split.filter(|&s| shape[s..] == *core) else {
            return Err(PyValueError::new_err(format!(
                "{name} must have shape {} or (..., {}) (got {})",
                fmt_shape(core),
                fmt_shape(core).trim_matches(|c| c == '(' || c == ')' || c == ','),
                if shape.is_empty() {
                    "a number".to_string()
                } else {
                    format!("shape {}", fmt_shape(&shape))
                }
            )));
        };
        Ok(Self {
            name,
            lead: shape[..split].to_vec(),
            core: core.iter().product(),
            values,
        })
    }

    /// Strides (in items) of each axis of `lead` (right-aligned with it), 0 where broadcast.
    fn strides(&self, lead: &[usize]) -> Vec<usize> {
        let pad = lead.len() - self.lead.len();
        let mut strides = vec![0usize; lead.len()];
        let mut step = 1usize;
        for (k, &d) in self.lead.iter().enumerate().rev() {
            if d != 1 {
                strides[pad + k] = step;
            }
            step *= d;
        }
        strides
    }
}

/// The broadcast leading shape of `ops` (NumPy's rules on the shapes before each core).
pub fn lead_shape(ops: &[&Operand]) -> PyResult<Vec<usize>> {
    let names: Vec<&str> = ops.iter().map(|o| o.name).collect();
    let leads: Vec<Vec<usize>> = ops.iter().map(|o| o.lead.clone()).collect();
    broadcast_shapes(&names, &leads).map_err(|e| {
        PyValueError::new_err(format!(
            "{} (the shapes before each argument's last axes: (3,) of a vector, (4, 4) of a \
             matrix)",
            Python::attach(|py| e.value(py).to_string())
        ))
    })
}

/// `f` once per element of the broadcast leading shape `lead` of `ops` (each gets its items as
/// slices, in the order of `ops`), `width` numbers per element, without the GIL and over all
/// cores. The first failing element (C order) raises `ValueError` with `msg` of its error and,
/// for a stack (`lead` not empty), its index.
pub fn each<const N: usize, F>(
    py: Python<'_>,
    ops: [&Operand; N],
    lead: &[usize],
    width: usize,
    f: F,
    msg: fn(Error) -> String,
) -> PyResult<Vec<f64>>
where
    F: Fn([&[f64]; N], &mut [f64]) -> Result<(), Error> + Sync,
{
    use rayon::prelude::*;
    let n = elements(lead)?;
    let shape = [lead, &[width]].concat();
    let len = n.checked_mul(width).ok_or_else(|| {
        pyo3::exceptions::PyMemoryError::new_err(format!(
            "an array of shape {} does not fit in memory",
            fmt_shape(&shape)
        ))
    })?;
    let mut out = buffer(len, &shape)?;
    out.resize(len, 0.0);
    let strides: [Vec<usize>; N] = std::array::from_fn(|k| ops[k].strides(lead));
    let item = |i: usize, k: usize| -> &[f64] {
        let (mut flat, mut at) = (i, 0usize);
        for (d, &s) in lead.iter().zip(&strides[k]).rev() {
            at += (flat % d) * s;
            flat /= d;
        }
        let c = ops[k].core.max(1);
        &ops[k].values[at * c..at * c + c]
    };
    // Items per parallel task: at most PART, fewer in a small block so that every core gets
    // some. The first block is a few items per thread (one item can take milliseconds: an
    // iterative TSM search, 16 cascades), the next ones sized to take about 20 ms.
    const PART: usize = 256;
    let threads = rayon::current_num_threads().max(1);
    let w = width.max(1);
    let failed: Option<(usize, Error)> =
        crate::interrupt::in_blocks(py, n, 4 * threads, |r: std::ops::Range<usize>| {
            let part = r.len().div_ceil(threads).clamp(1, PART);
            out[r.start * w..r.end * w]
                .par_chunks_mut(w * part)
                .enumerate()
                .find_map_first(|(c, o)| {
                    for (j, oo) in o.chunks_exact_mut(w).enumerate() {
                        let i = r.start + c * part + j;
                        let x: [&[f64]; N] = std::array::from_fn(|k| item(i, k));
                        if let Err(e) = f(x, oo) {
                            return Some((i, e));
                        }
                    }
                    None
                })
        })?;
    match failed {
        Some((i, e)) if lead.is_empty() => {
            let _ = i;
            Err(PyValueError::new_err(msg(e)))
        }
        Some((i, e)) => Err(PyValueError::new_err(format!(
            "{} (at index {})",
            msg(e),
            fmt_index(i, lead)
        ))),
        None => Ok(out),
    }
}

/// The crate's message, as [`each`] reports an error by default.
pub fn message(e: Error) -> String {
    e.to_string()
}
