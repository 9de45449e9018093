//! Ctrl-C during long calls: work in blocks without the GIL, Python's signal handlers run
//! between them (`Python::check_signals`), so that `KeyboardInterrupt` arrives within about one
//! block's time, whatever the call's size.
//!
//! [`in_blocks`] drives a computation over `0..n` in consecutive ranges sized from the speed
//! measured on the ranges before (about [`BLOCK_SECONDS`] each, the first one small): the
//! element-wise closed forms (`crate::broadcast`), the builders and measurements over stacks
//! (`crate::stacked`) and `error_image`'s rows. [`off_thread`] runs one call of the crate that
//! cannot be cut into blocks (a frame, a plan) on its own thread and waits for it, checking
//! for signals meanwhile: on Ctrl-C the call returns at once with `KeyboardInterrupt`, and the
//! abandoned computation finishes on its thread and is dropped. The sweep has its own blocks
//! (`crate::sweep`).

use pyo3::prelude::*;
use std::ops::Range;
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// The time one block should take: the longest wait for Ctrl-C to be seen, a tenth of the
/// 0.2 s a person notices, and long enough that the pauses between blocks cost nothing
/// measurable (one GIL round trip, a few microseconds).
pub const BLOCK_SECONDS: f64 = 0.02;

/// Elements copied between two checks for Ctrl-C in [`copy_checked`] (32 MiB of float64, a few
/// milliseconds).
const COPY_STEP: usize = 1 << 22;

/// `work(range)` over `0..n` in consecutive ranges without the GIL, the first of `first`
/// elements, each next one sized to take about [`BLOCK_SECONDS`] at the speed measured on the
/// one before (at most 4× larger, so that one fast block does not make the next one long).
/// After each range Python's signal handlers run: Ctrl-C raises `KeyboardInterrupt` there.
/// The first range whose `work` returns `Some` stops the loop and its value is returned, so a
/// failure found in an earlier range is never overtaken by a later one.
pub fn in_blocks<E, F>(py: Python<'_>, n: usize, first: usize, mut work: F) -> PyResult<Option<E>>
where
    E: Send,
    F: FnMut(Range<usize>) -> Option<E> + Send,
{
    let mut start = 0;
    let mut size = first.max(1);
    while start < n {
        let end = start.saturating_add(size).min(n);
        let began = Instant::now();
        let found = py.detach(|| work(start..end));
        py.check_signals()?;
        if found.is_some() {
            return Ok(found);
        }
        let seconds = began.elapsed().as_secs_f64().max(1e-6);
        let done = (end - start) as f64;
        let next = (done / seconds * BLOCK_SECONDS).min(4.0 * size as f64);
        size = (next as usize).max(1);
        start = end;
    }
    Ok(None)
}

/// `f()` on a thread of its own, the caller waiting without the GIL and running Python's signal
/// handlers every few milliseconds: Ctrl-C raises `KeyboardInterrupt` at once, and the abandoned
/// call finishes on its thread, its result dropped. For a single call of the crate that runs as
/// long as its input is large (a plan over many caster boxes) and cannot be cut into blocks.
pub fn off_thread<T, F>(py: Python<'_>, f: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce() -> T + Send + 'static,
{
    let (send, receive) = mpsc::channel();
    std::thread::Builder::new()
        .name("shadow-aliasing".into())
        .spawn(move || {
            // The receiver is gone only after Ctrl-C: the result has nowhere to go.
            let _ = send.send(f());
        })
        .map_err(|e| {
            pyo3::exceptions::PyMemoryError::new_err(format!("cannot start a thread: {e}"))
        })?;
    let wait = Duration::from_secs_f64(BLOCK_SECONDS / 4.0);
    let mut receive = receive;
    loop {
        // The receiver is moved through the wait (it is `Send`, not `Sync`).
        let (back, got) = py.detach(move || {
            let got = receive.recv_timeout(wait);
            (receive, got)
        });
        receive = back;
        match got {
            Ok(v) => return Ok(v),
            Err(mpsc::RecvTimeoutError::Timeout) => py.check_signals()?,
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                // The thread ended without sending: its computation panicked.
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "internal error: the computation's thread ended without a result",
                ));
            }
        }
    }
}

/// `len` values from `values` into a new vector (room reserved first: `MemoryError` if it does
/// not fit, naming `shape`), Python's signal handlers run every [`COPY_STEP`] values: copying
/// a broadcast view of a billion elements takes seconds.
pub fn copy_checked(
    py: Python<'_>,
    values: impl Iterator<Item = f64>,
    len: usize,
    shape: &[usize],
) -> PyResult<Vec<f64>> {
    let mut v = crate::broadcast::buffer(len, shape)?;
    let mut values = values.take(len);
    loop {
        let before = v.len();
        v.extend(values.by_ref().take(COPY_STEP));
        if v.len() == before {
            return Ok(v);
        }
        py.check_signals()?;
    }
}
