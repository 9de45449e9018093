//! Element-wise evaluation with NumPy's broadcasting rules.
//!
//! Every float argument is converted to a float64 array (Python numbers, lists, integer and float32
//! arrays alike; booleans, complex numbers, strings and objects are refused), the arguments'
//! shapes are broadcast against each other as NumPy broadcasts them, and the closed form runs once
//! per element of the broadcast shape with the GIL released, over all cores for large arrays —
//! through a vectorised fast kernel in blocks ([`map_fast`]) where the form has one, with the
//! validated form for any block holding an element the kernel's checks do not admit.
//! The first element (in C order) whose arguments the crate refuses raises `ValueError` with the
//! crate's message and, for an array, the element's index.

use crate::out::Out;
use multiversion::multiversion;
use numpy::ndarray::{ArrayD, IxDyn};
use numpy::{
    AllowTypeChange, PyArrayDescrMethods, PyArrayDyn, PyArrayLikeDyn, PyArrayMethods,
    PyUntypedArray, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyMemoryError, PyOverflowError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt};
use rayon::prelude::*;
use shadow_aliasing::Error;
use std::sync::atomic::{AtomicBool, Ordering};

/// Elements per parallel task; calls below twice this run on one thread.
const CHUNK: usize = 16 * 1024;

/// The crate's error as Python's `ValueError`.
pub fn value_error(e: &Error) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// One float argument after conversion: a float64 array, or a Python number.
pub enum FloatArg<'py> {
    Number(f64),
    Array(PyArrayLikeDyn<'py, f64, AllowTypeChange>),
}

impl<'py> FloatArg<'py> {
    /// Converts `ob` (a number or anything `numpy.asarray` takes) to float64, refusing dtypes
    /// that are not real numbers. Every error names the argument: `TypeError` for what is not
    /// a real number or an array of them (`None`, a string, a bool, a ragged nested list),
    /// `ValueError` for an integer too large for a float.
    pub fn extract(name: &str, ob: &Bound<'py, PyAny>) -> PyResult<Self> {
        Self::extract_as(name, ob, "a real number or an array of real numbers")
    }

    /// [`FloatArg::extract`], the message saying that `name` must be `expected`.
    pub fn extract_as(name: &str, ob: &Bound<'py, PyAny>, expected: &str) -> PyResult<Self> {
        let wrong = |got: &dyn std::fmt::Display| {
            PyTypeError::new_err(format!("{name} must be {expected} (got {got})"))
        };
        if ob.is_instance_of::<PyBool>() {
            return Err(wrong(&"a bool"));
        }
        if ob.is_none() {
            return Err(wrong(&"None"));
        }
        if ob.is_instance_of::<PyFloat>() || ob.is_instance_of::<PyInt>() {
            // Only an int can fail: beyond the largest float.
            return ob.extract::<f64>().map(FloatArg::Number).map_err(|_| {
                PyValueError::new_err(format!(
                    "{name} must be a finite number (got an integer too large for a float)"
                ))
            });
        }
        let py = ob.py();
        // Errors of NumPy's conversion that say what the object is (a ragged nested list, an
        // object that is not a number); others (KeyboardInterrupt, MemoryError) pass through.
        let refused = |e: PyErr| {
            if e.is_instance_of::<PyTypeError>(py)
                || e.is_instance_of::<PyValueError>(py)
                || e.is_instance_of::<PyOverflowError>(py)
            {
                let why = e.value(py).to_string();
                wrong(&format_args!(
                    "{}, which NumPy refuses: {why}",
                    crate::args::kind(ob)
                ))
            } else {
                e
            }
        };
        // numpy.asarray first, so that the dtype of lists and scalars is checked too.
        let is_array = ob.cast::<PyUntypedArray>().is_ok();
        let arr = if is_array {
            ob.clone()
        } else {
            py.import("numpy")?
                .getattr("asarray")?
                .call1((ob,))
                .map_err(refused)?
        };
        let untyped = arr
            .cast::<PyUntypedArray>()
            .map_err(|_| wrong(&crate::args::kind(ob)))?;
        let kind = untyped.dtype().kind();
        if !matches!(kind, b'f' | b'i' | b'u') {
            let dtype = untyped.dtype();
            return Err(match (is_array, untyped.ndim()) {
                (true, _) => wrong(&format_args!("an array of dtype {dtype}")),
                (false, 0) => wrong(&crate::args::kind(ob)),
                (false, _) => wrong(&format_args!("{} of dtype {dtype}", crate::args::kind(ob))),
            });
        }
        let a: PyArrayLikeDyn<'py, f64, AllowTypeChange> = arr.extract().map_err(refused)?;
        Ok(FloatArg::Array(a))
    }

    fn shape(&self) -> Vec<usize> {
        match self {
            FloatArg::Number(_) => Vec::new(),
            FloatArg::Array(a) => a.shape().to_vec(),
        }
    }
}

/// Broadcasts shapes as NumPy does: right-aligned, each pair of dimensions equal or one of them 1.
pub fn broadcast_shapes(names: &[&str], shapes: &[Vec<usize>]) -> PyResult<Vec<usize>> {
    let nd = shapes.iter().map(Vec::len).max().unwrap_or(0);
    let mut out = vec![1usize; nd];
    for (k, s) in shapes.iter().enumerate() {
        for (i, &d) in s.iter().rev().enumerate() {
            let o = &mut out[nd - 1 - i];
            if d == *o || d == 1 {
                continue;
            }
            if *o == 1 {
                *o = d;
                continue;
            }
            let described: Vec<String> = names
                .iter()
                .zip(shapes)
                .map(|(n, s)| format!("{n} {}", fmt_shape(s)))
                .collect();
            return Err(PyValueError::new_err(format!(
                "shapes cannot be broadcast together: {} ({} does not match)",
                described.join(", "),
                names[k]
            )));
        }
    }
    Ok(out)
}

/// The `MemoryError` of a shape with more elements than memory holds.
fn too_large(shape: &[usize]) -> PyErr {
    PyMemoryError::new_err(format!(
        "an array of shape {} does not fit in memory",
        fmt_shape(shape)
    ))
}

/// The number of elements of `shape`, or `MemoryError` if it overflows.
pub fn elements(shape: &[usize]) -> PyResult<usize> {
    shape
        .iter()
        .try_fold(1usize, |n, &d| n.checked_mul(d))
        .ok_or_else(|| too_large(shape))
}

/// Room for `len` float64 values (for an array of `shape`), or `MemoryError`. A NumPy broadcast
/// view (`numpy.broadcast_to`) describes any number of elements without holding them, and the
/// broadcast of several arguments multiplies their lengths: a copy or a result of that size
/// must fail as Python's `MemoryError`, as NumPy's own allocations do, not abort the process.
pub fn buffer(len: usize, shape: &[usize]) -> PyResult<Vec<f64>> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).map_err(|_| too_large(shape))?;
    Ok(v)
}

/// The values of an array argument in C order, copied into a [`buffer`].
/// Ctrl-C is seen during the copy ([`crate::interrupt::copy_checked`]).
pub fn values_of(a: &PyArrayLikeDyn<'_, f64, AllowTypeChange>) -> PyResult<Vec<f64>> {
    let view = a.as_array();
    crate::interrupt::copy_checked(a.py(), view.iter().copied(), view.len(), view.shape())
}

/// A shape as Python prints it: `()`, `(3,)`, `(2, 3)`.
pub fn fmt_shape(s: &[usize]) -> String {
    match s {
        [] => "()".into(),
        [a] => format!("({a},)"),
        _ => format!(
            "({})",
            s.iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Elements per block of the fast path: each argument is read as one slice of this length
/// (an argument with one value as a block of copies), so the kernel runs over plain slices.
const BLOCK: usize = 512;

/// The values of one argument over the broadcast shape, in C order.
enum Data<'a> {
    /// One value for every element, and a block of copies of it for the fast path.
    Scalar(f64, Vec<f64>),
    Slice(&'a [f64]),
}

impl Data<'_> {
    #[inline(always)]
    fn at(&self, i: usize) -> f64 {
        match self {
            Data::Scalar(v, _) => *v,
            Data::Slice(s) => s[i],
        }
    }

    /// Elements `start .. start + len` (`len` ≤ [`BLOCK`]).
    #[inline(always)]
    fn block(&self, start: usize, len: usize) -> &[f64] {
        match self {
            Data::Scalar(_, copies) => &copies[..len],
            Data::Slice(s) => &s[start..start + len],
        }
    }
}

fn scalar(v: f64) -> Data<'static> {
    Data::Scalar(v, vec![v; BLOCK])
}

/// Whether the fast path is used (the default); `_native._set_fast_path(False)` turns it off, so
/// that the tests can compare it with the validated element-by-element path.
static FAST_PATH: AtomicBool = AtomicBool::new(true);

/// Turns the fast path of the element-wise closed forms on or off (a test hook); returns the
/// previous setting. With it off every element goes through the crate's validated closed form,
/// as the fast path does for any block holding an element its domain check does not admit.
#[pyfunction]
pub fn _set_fast_path(enabled: bool) -> bool {
    FAST_PATH.swap(enabled, Ordering::Relaxed)
}

/// Whether the fast kernels may use the processor's wider vectors where it has them (the
/// default; [`kernel_full_wide`]); `_native._set_wide_simd(False)` keeps them on the baseline
/// target's, so that the tests can compare both.
static WIDE_SIMD: AtomicBool = AtomicBool::new(true);

/// Turns the fast kernels' wider vectors (AVX2 on x86-64) on or off (a test hook); returns the
/// previous setting. Either way the values are the same bit for bit.
#[pyfunction]
pub fn _set_wide_simd(enabled: bool) -> bool {
    WIDE_SIMD.swap(enabled, Ordering::Relaxed)
}

/// The one transcendental most forms need per element, tan θ, remembered for the last θ: a θ
/// that is one number, or repeats along a row, costs one `tan` per run (the same value, since
/// `tan` is a function of its argument's bits).
struct TanMemo {
    bits: u64,
    tan: f64,
}

impl TanMemo {
    fn new() -> Self {
        // A NaN's bits: `tan` is computed on the first call.
        Self {
            bits: f64::NAN.to_bits(),
            tan: f64::NAN,
        }
    }

    /// tan θ, as `f64::tan` computes it.
    #[inline(always)]
    fn tan(&mut self, theta: f64) -> f64 {
        if theta.to_bits() != self.bits {
            self.bits = theta.to_bits();
            self.tan = theta.tan();
        }
        self.tan
    }
}

/// What one element of the output is.
#[derive(Clone, Copy)]
pub struct OutSpec {
    /// `None`: one number per element (output shape = broadcast shape); `Some(w)`: `w` numbers
    /// per element (output shape = broadcast shape + `(w,)`).
    pub width: Option<usize>,
    /// Whether +∞ is a legitimate value (an n′ of an unwarped map).
    pub allow_inf: bool,
    /// Whether the value is strictly positive wherever the form is defined, so that only a
    /// normal `f64` is admitted by the fast path: a 0 or a subnormal is an underflow, which the
    /// validated form reports (the closed forms proportional to res_image/res_s or /res_t).
    pub positive: bool,
}

/// A scalar quantity: one finite number per element.
pub const SCALAR: OutSpec = OutSpec {
    width: None,
    allow_inf: false,
    positive: false,
};
/// A scalar quantity that is strictly positive: one normal, positive number per element.
pub const POSITIVE: OutSpec = OutSpec {
    width: None,
    allow_inf: false,
    positive: true,
};
/// An n′: one number per element, +∞ for the unwarped map.
pub const N_PRIME: OutSpec = OutSpec {
    width: None,
    allow_inf: true,
    positive: false,
};

/// The fast kernel of a scalar closed form: for the arguments of one element (and tan θ of the
/// argument `tan_of` names, or 0), the value computed without validation (the library's
/// `*_unchecked` twin) and whether the element certainly lies in the domain. Where it says so,
/// the value must be the validated form's, bit for bit.
pub type NoFast<const N: usize> = fn(&[f64; N], f64) -> (f64, bool);

/// Evaluates `f` on every element of the broadcast of `args` (each `(name, object)`).
///
/// `f` writes its `width` numbers (one for a scalar quantity) into its output slice.
pub fn map_into<'py, const N: usize, F>(
    py: Python<'py>,
    args: [(&'static str, &Bound<'py, PyAny>); N],
    spec: OutSpec,
    f: F,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>>
where
    F: Fn(&[f64; N], &mut [f64]) -> Result<(), Error> + Sync,
{
    drive(py, args, spec, f, None::<Fast<NoFast<N>>>, out)
}

/// A scalar closed form with a fast kernel `g` beside its validated form `f`.
///
/// Each block of [`BLOCK`] elements first takes tan of argument `tan_of` (if any; one call per
/// run of equal values, [`TanMemo`]), then runs `g` over plain slices (no validation, no
/// `Result`, no call: the compiler vectorises it) and collects the domain checks; a
/// block with any element outside `g`'s domain, or with a value [`OutSpec`] does not admit (not
/// finite; for a strictly positive form, 0 or subnormal), is computed again element by element
/// with `f`, which gives the values and the first error exactly as without
/// the fast path.
pub fn map_fast<'py, const N: usize, F, G>(
    py: Python<'py>,
    args: [(&'static str, &Bound<'py, PyAny>); N],
    spec: OutSpec,
    f: F,
    g: G,
    tan_of: Option<usize>,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>>
where
    F: Fn(&[f64; N]) -> Result<f64, Error> + Sync,
    G: Fn(&[f64; N], f64) -> (f64, bool) + Sync,
{
    let fast = FAST_PATH
        .load(Ordering::Relaxed)
        .then_some(Fast { g, tan_of });
    drive(
        py,
        args,
        spec,
        |x, o| {
            o[0] = f(x)?;
            Ok(())
        },
        fast,
        out,
    )
}

/// A fast kernel and the argument whose tangent it needs.
pub struct Fast<G> {
    g: G,
    tan_of: Option<usize>,
}

fn drive<'py, const N: usize, F, G>(
    py: Python<'py>,
    args: [(&'static str, &Bound<'py, PyAny>); N],
    spec: OutSpec,
    f: F,
    g: Option<Fast<G>>,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>>
where
    F: Fn(&[f64; N], &mut [f64]) -> Result<(), Error> + Sync,
    G: Fn(&[f64; N], f64) -> (f64, bool) + Sync,
{
    let names: [&'static str; N] = std::array::from_fn(|k| args[k].0);
    let mut conv = Vec::with_capacity(N);
    for (name, ob) in args {
        conv.push(FloatArg::extract(name, ob)?);
    }
    let shapes: Vec<Vec<usize>> = conv.iter().map(FloatArg::shape).collect();
    let shape = broadcast_shapes(&names, &shapes)?;
    let width = spec.width.unwrap_or(1);
    let mut out_shape = shape.clone();
    out_shape.extend(spec.width);
    let n = elements(&shape)?;
    let len = elements(&out_shape)?;
    let target = Out::new(out, &out_shape, false)?;
    // A C-contiguous `out` that is none of the arguments is written directly; otherwise the
    // result's room first: a broadcast can describe more elements than memory holds.
    let direct = target.contiguous_f64();
    let mut writer = direct.as_ref().and_then(|d| d.try_readwrite().ok());
    let mut room = Vec::new();
    let into: &mut [f64] = match writer.as_mut().and_then(|w| w.as_slice_mut().ok()) {
        Some(s) => s,
        None => {
            room = buffer(len, &out_shape)?;
            room.resize(len, 0.0);
            &mut room
        }
    };
    // Arguments that are neither one value nor already C-contiguous in the broadcast shape are
    // copied out in C order (NumPy's broadcast views, transposes, slices with steps).
    let mut owned: Vec<Option<Vec<f64>>> = Vec::with_capacity(N);
    for a in &conv {
        owned.push(match a {
            FloatArg::Number(_) => None,
            FloatArg::Array(arr) => {
                let view = arr.as_array();
                if view.len() == 1
                    || (view.shape() == shape.as_slice() && view.is_standard_layout())
                {
                    None
                } else {
                    let b = view.broadcast(IxDyn(&shape)).ok_or_else(|| {
                        PyValueError::new_err("internal error: broadcast of a checked shape")
                    })?;
                    Some(crate::interrupt::copy_checked(
                        py,
                        b.iter().copied(),
                        n,
                        &shape,
                    )?)
                }
            }
        });
    }
    let mut data: Vec<Data<'_>> = Vec::with_capacity(N);
    for (a, o) in conv.iter().zip(&owned) {
        data.push(match (a, o) {
            (_, Some(v)) => Data::Slice(v.as_slice()),
            (FloatArg::Number(v), None) => scalar(*v),
            (FloatArg::Array(arr), None) => {
                let view = arr.as_array();
                if view.len() == 1 {
                    scalar(view.iter().next().copied().unwrap_or(f64::NAN))
                } else {
                    Data::Slice(
                        arr.as_slice()
                            .map_err(|e| PyValueError::new_err(e.to_string()))?,
                    )
                }
            }
        });
    }
    // The fast kernel writes one number per element.
    let g = g.filter(|_| width == 1);
    let failure = run(py, &data, into, width, spec, &f, g.as_ref())?;
    if let Some((i, e)) = failure {
        let msg = e.to_string();
        return Err(PyValueError::new_err(if shape.is_empty() {
            msg
        } else {
            format!("{msg} (at index {})", fmt_index(i, &shape))
        }));
    }
    // The arguments' borrows end here, so that an `out` that is one of them can be written.
    drop(data);
    drop(conv);
    match (writer, direct) {
        (Some(_), Some(d)) => Ok(d.into_any()),
        _ => target.deliver(py, out_shape, room),
    }
}

/// A scalar quantity of `N` broadcast arguments.
pub fn map<'py, const N: usize, F>(
    py: Python<'py>,
    args: [(&'static str, &Bound<'py, PyAny>); N],
    spec: OutSpec,
    f: F,
    out: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyAny>>
where
    F: Fn(&[f64; N]) -> Result<f64, Error> + Sync,
{
    map_into(
        py,
        args,
        spec,
        |x, o| {
            o[0] = f(x)?;
            Ok(())
        },
        out,
    )
}

/// Elements of the first block of [`run`] (a millisecond or two for most forms); the next
/// blocks are sized by [`crate::interrupt::in_blocks`] to take about 20 ms.
const FIRST_BLOCK: usize = 16 * CHUNK;

/// The computation proper, in blocks without the GIL with a check for Ctrl-C between them
/// (`KeyboardInterrupt`): the first failing element (lowest index), if any.
fn run<const N: usize, F, G>(
    py: Python<'_>,
    data: &[Data<'_>],
    out: &mut [f64],
    width: usize,
    spec: OutSpec,
    f: &F,
    g: Option<&Fast<G>>,
) -> PyResult<Option<(usize, Error)>>
where
    F: Fn(&[f64; N], &mut [f64]) -> Result<(), Error> + Sync,
    G: Fn(&[f64; N], f64) -> (f64, bool) + Sync,
{
    let w = width.max(1);
    let elements = out.len() / w;
    crate::interrupt::in_blocks(py, elements, FIRST_BLOCK, |r| {
        run_range(
            data,
            &mut out[r.start * w..r.end * w],
            r.start,
            width,
            spec,
            f,
            g,
        )
    })
}

/// Elements `start ..` (as many as `out` holds) over all cores: the first failing element
/// (lowest index), if any.
fn run_range<const N: usize, F, G>(
    data: &[Data<'_>],
    out: &mut [f64],
    start: usize,
    width: usize,
    spec: OutSpec,
    f: &F,
    g: Option<&Fast<G>>,
) -> Option<(usize, Error)>
where
    F: Fn(&[f64; N], &mut [f64]) -> Result<(), Error> + Sync,
    G: Fn(&[f64; N], f64) -> (f64, bool) + Sync,
{
    let checked = |start: usize, out: &mut [f64]| -> Option<(usize, Error)> {
        for (j, o) in out.chunks_exact_mut(width).enumerate() {
            let i = start + j;
            let x: [f64; N] = std::array::from_fn(|k| data[k].at(i));
            if let Err(e) = f(&x, o) {
                return Some((i, e));
            }
            if let Some(bad) = o
                .iter()
                .find(|v| !(v.is_finite() || (spec.allow_inf && **v == f64::INFINITY)))
            {
                return Some((
                    i,
                    Error::Degenerate(format!(
                        "the value is not finite ({bad}) for these arguments"
                    )),
                ));
            }
        }
        None
    };
    let chunk = |start: usize, out: &mut [f64]| -> Option<(usize, Error)> {
        let Some(Fast { g, tan_of }) = g else {
            return checked(start, out);
        };
        let wide = WIDE_SIMD.load(Ordering::Relaxed);
        let mut memo = TanMemo::new();
        let mut tans = [0.0f64; BLOCK];
        for (b, ob) in out.chunks_mut(BLOCK).enumerate() {
            let s0 = start + b * BLOCK;
            let len = ob.len();
            let cols: [&[f64]; N] = std::array::from_fn(|k| data[k].block(s0, len));
            if let Some(k) = *tan_of {
                for (t, &th) in tans.iter_mut().zip(cols[k]) {
                    *t = memo.tan(th);
                }
            }
            // A full block as fixed-length arrays, so that the loop has no bounds checks and
            // vectorises where the kernel allows; the last, shorter block as slices.
            let mut full = [&UNUSED; N];
            let mut is_full = true;
            for (f, c) in full.iter_mut().zip(&cols) {
                match c.first_chunk::<BLOCK>() {
                    Some(c) => *f = c,
                    None => is_full = false,
                }
            }
            let ok = match ob.first_chunk_mut::<BLOCK>() {
                Some(o) if is_full && wide => kernel_full_wide(&full, &tans, o, spec, g),
                Some(o) if is_full => kernel_full(&full, &tans, o, spec, g),
                _ => kernel_tail(&cols, &tans[..len], ob, spec, g),
            };
            if !ok {
                if let Some(failure) = checked(s0, ob) {
                    return Some(failure);
                }
            }
        }
        None
    };
    let elements = out.len() / width.max(1);
    if elements < 2 * CHUNK {
        return chunk(start, out);
    }
    out.par_chunks_mut(CHUNK * width)
        .enumerate()
        .filter_map(|(c, o)| chunk(start + c * CHUNK, o))
        .min_by_key(|(i, _)| *i)
}

/// The placeholder of a column before it is set (never read).
static UNUSED: [f64; BLOCK] = [0.0; BLOCK];

/// Whether an element's value is admitted: finite, or +∞ where allowed; for a strictly positive
/// form also normal (≥ `f64::MIN_POSITIVE`: 0 and subnormals are underflows, NaN fails both).
#[inline(always)]
fn admitted(v: f64, good: bool, spec: OutSpec) -> bool {
    good & (finite(v) | (spec.allow_inf & (v == f64::INFINITY)))
        & (!spec.positive | (v >= f64::MIN_POSITIVE))
}

/// `v.is_finite()` as two float operations: v − v is +0 exactly for a finite v and NaN for ±∞
/// and NaN. (`is_finite` compiles to integer compares of the bits, which without SSE4.2's 64-bit
/// compare cost several instructions per lane.)
#[inline(always)]
#[allow(clippy::eq_op)] // v − v is the test, not a mistake.
pub fn finite(v: f64) -> bool {
    v - v == 0.0
}

/// `g` over one full block: writes the values, returns whether every element was admitted.
#[inline(always)]
fn kernel_full<const N: usize, G>(
    cols: &[&[f64; BLOCK]; N],
    tans: &[f64; BLOCK],
    out: &mut [f64; BLOCK],
    spec: OutSpec,
    g: &G,
) -> bool
where
    G: Fn(&[f64; N], f64) -> (f64, bool),
{
    let mut ok = true;
    for j in 0..BLOCK {
        let x: [f64; N] = std::array::from_fn(|k| cols[k][j]);
        let (v, good) = g(&x, tans[j]);
        out[j] = v;
        ok &= admitted(v, good, spec);
    }
    ok
}

/// [`kernel_full`], compiled once more for AVX2 (four f64 lanes where the baseline x86-64 target
/// has SSE2's two) and chosen at run time where the processor has it (`multiversion`); elsewhere
/// it is [`kernel_full`]. Only the vector width differs: IEEE 754 +, −, ×, ÷, √ and comparisons
/// give the same bits at any width, Rust never fuses a multiply and an add, and libm calls
/// (`tan`, `atan`, …) are the same functions, so both versions write the same values
/// (python/tests/test_fast_path.py compares them, `_set_wide_simd`). The arithmetic forms run
/// about twice as fast with it (docs/python.md).
#[multiversion(targets("x86_64+avx2"))]
fn kernel_full_wide<const N: usize, G>(
    cols: &[&[f64; BLOCK]; N],
    tans: &[f64; BLOCK],
    out: &mut [f64; BLOCK],
    spec: OutSpec,
    g: &G,
) -> bool
where
    G: Fn(&[f64; N], f64) -> (f64, bool),
{
    kernel_full(cols, tans, out, spec, g)
}

/// [`kernel_full`] over a shorter block (`out.len()` elements of each column).
#[inline(always)]
fn kernel_tail<const N: usize, G>(
    cols: &[&[f64]; N],
    tans: &[f64],
    out: &mut [f64],
    spec: OutSpec,
    g: &G,
) -> bool
where
    G: Fn(&[f64; N], f64) -> (f64, bool),
{
    let mut ok = true;
    for (j, o) in out.iter_mut().enumerate() {
        let x: [f64; N] = std::array::from_fn(|k| cols[k][j]);
        let (v, good) = g(&x, tans[j]);
        *o = v;
        ok &= admitted(v, good, spec);
    }
    ok
}

/// A flat C-order index as NumPy's multi-index `(i, j, …)`.
pub fn fmt_index(mut flat: usize, shape: &[usize]) -> String {
    let mut idx = vec![0usize; shape.len()];
    for (k, &d) in shape.iter().enumerate().rev() {
        if d > 0 {
            idx[k] = flat % d;
            flat /= d;
        }
    }
    fmt_shape(&idx)
}

/// A float64 array of `shape` holding `values` (C order); a 0-d result is a `numpy.float64`,
/// as NumPy's ufuncs return for scalar arguments.
pub fn to_python(
    py: Python<'_>,
    shape: Vec<usize>,
    values: Vec<f64>,
) -> PyResult<Bound<'_, PyAny>> {
    let zero_d = shape.is_empty();
    let arr = ArrayD::from_shape_vec(IxDyn(&shape), values)
        .map_err(|e| PyValueError::new_err(format!("internal error: {e}")))?;
    let arr = PyArrayDyn::from_owned_array(py, arr);
    if zero_d {
        arr.into_any().get_item(())
    } else {
        Ok(arr.into_any())
    }
}

/// A whole number ≥ 1 passed as a float element (`k`), in the eval contract's words.
pub fn count(name: &'static str, v: f64) -> Result<usize, Error> {
    if !v.is_finite() {
        return Err(Error::invalid(
            name,
            format!("must be a finite number (got {v})"),
        ));
    }
    if v.fract() != 0.0 || v < 1.0 {
        return Err(Error::invalid(
            name,
            format!("must be a whole number of at least 1 (got {v})"),
        ));
    }
    if v > 1e6 {
        return Err(Error::invalid(
            name,
            format!("must be at most 1000000 (got {v})"),
        ));
    }
    // Whole, in [1, 1e6]: exact.
    Ok(v as usize)
}
