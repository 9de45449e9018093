//! Cases spread over several devices, one thread each: a case keeps about one core busy (its
//! exact ray casts and the analysis), so two at once fill a two-core machine. Each thread has a
//! device of its own, because a device's queue and error scopes are shared by everything that
//! uses it: two threads on one device wait for each other's GPU work, and wgpu rejects error
//! scopes popped out of order.

use crate::gpu::Gpu;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};

/// `n` devices (at least one) compiling the shaders' `source`.
///
/// # Errors
/// When a device cannot be created or the source does not compile.
pub fn devices(n: usize, source: &str) -> Result<Vec<Gpu>, String> {
    (0..n.max(1)).map(|_| Gpu::with_source(source)).collect()
}

/// `f` applied to every job, the jobs shared out among `gpus` (one thread each); the results in
/// the jobs' order, whichever thread finished first.
///
/// # Errors
/// When `gpus` is empty and there are jobs to run.
pub fn on_devices<J: Sync, T: Send>(
    gpus: &[Gpu],
    jobs: &[J],
    f: impl Fn(&Gpu, &J) -> T + Sync,
) -> Result<Vec<T>, String> {
    if gpus.is_empty() && !jobs.is_empty() {
        return Err("no device to run the cases on".into());
    }
    let next = AtomicUsize::new(0);
    let out: Mutex<Vec<Option<T>>> = Mutex::new(jobs.iter().map(|_| None).collect());
    std::thread::scope(|sc| {
        for gpu in gpus.iter().take(jobs.len()) {
            sc.spawn(|| loop {
                let i = next.fetch_add(1, Ordering::Relaxed);
                let Some(job) = jobs.get(i) else { break };
                let r = f(gpu, job);
                out.lock().unwrap_or_else(PoisonError::into_inner)[i] = Some(r);
            });
        }
    });
    // A thread that panicked re-raised its panic when the scope ended, so every slot is filled.
    Ok(out
        .into_inner()
        .unwrap_or_else(PoisonError::into_inner)
        .into_iter()
        .flatten()
        .collect())
}
