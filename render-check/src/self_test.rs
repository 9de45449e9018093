//! The fault suite (`render-check --self-test`, docs/rendered.md, "Fault suite"): the clean
//! build and every fault of [`crate::faults::Fault`] over every built-in set-up and every scheme
//! the fault can change, each case held to the targets ([`crate::targets`]); a fault counts as
//! caught in a case only by a target the clean build of that case meets.

use crate::faults::Fault;
use crate::gpu::Gpu;
use crate::pool::{devices, on_devices};
use crate::run::{run_full, Render, Sizes};
use crate::schemes::{schemes_for, setups};
use crate::targets::violations;
use std::collections::BTreeMap;

/// The sizes of `render-check --self-test`: 320 × 240, the scenes' own map resolution, 16
/// shimmer frames.
pub const SELF_TEST_SIZES: Sizes = Sizes {
    width: 320,
    height: 240,
    res: None,
    frames: 16,
    shimmer_points: 1500,
    fault: None,
    render: Render::DEFAULT,
};

/// One run of the self-test: the clean build (`fault` `None`) or one fault, over every built-in
/// set-up (the thin-caster scene included) and every scheme the fault can change.
#[derive(Debug, Clone, Default)]
pub struct SelfTestRow {
    /// The fault, or `None` for the clean build.
    pub fault: Option<Fault>,
    /// Cases run.
    pub cases: usize,
    /// Cases that violate a target: for the clean build any; for a fault, one the clean build
    /// of the same case meets (a fault is caught only by what it changes).
    pub failing: usize,
    /// Cases that could not be run (their error), not counted as caught.
    pub errors: usize,
    /// Each target counted in `failing` (its name, as [`violations`] words it) with the number of
    /// cases.
    pub targets: BTreeMap<String, usize>,
    /// The first counted violation or error, with its case.
    pub example: String,
    /// The set-ups with a case counted in `failing`.
    pub setups: std::collections::BTreeSet<String>,
}

/// A fault counts as caught by the self-test only in at least this many set-ups.
pub const MIN_SETUPS_CAUGHT: usize = 2;

/// The target a line of [`violations`] names (the text before its value).
pub fn target_name(violation: &str) -> String {
    let head = violation.split(" = ").next().unwrap_or(violation);
    head.split(": ").next().unwrap_or(head).to_string()
}

/// Runs the clean build and every fault at [`SELF_TEST_SIZES`] on every device in `gpus` at once
/// (a fault in the shaders' source on as many devices of its own), calling `log` with one line
/// per run.
///
/// # Errors
/// When no built-in set-up exists, `gpus` is empty, or a faulted shader's devices cannot be
/// created; a case that fails to run is counted in
/// [`SelfTestRow::errors`].
pub fn self_test(gpus: &[Gpu], log: impl Fn(&str)) -> Result<Vec<SelfTestRow>, String> {
    let all = setups();
    if all.is_empty() {
        return Err("no built-in set-up".into());
    }
    let mut rows = Vec::new();
    // The targets each clean case violates (none when the clean build passes).
    let mut clean: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for fault in std::iter::once(None).chain(Fault::ALL.map(Some)) {
        let sizes = Sizes {
            fault,
            ..SELF_TEST_SIZES
        };
        let mut row = SelfTestRow {
            fault,
            ..SelfTestRow::default()
        };
        let t = std::time::Instant::now();
        // A fault in the shaders' source runs on devices of its own.
        let own;
        let gpus = if fault.is_some_and(Fault::changes_shader) {
            own = devices(gpus.len(), &Fault::shader_source(fault)?)?;
            &own[..]
        } else {
            gpus
        };
        let mut jobs = Vec::new();
        for (si, setup) in all.iter().enumerate() {
            for scheme in schemes_for(&setup.name) {
                let clip_depth = crate::run::case_clip_depth(si, scheme);
                if fault.is_some_and(|f| {
                    !f.applies_to(scheme)
                        || !f.applies_to_scene(&setup.scene)
                        || !f.applies_to_depth(clip_depth)
                        || (f.paths_only() && !crate::paths::applies(&setup.name, scheme))
                }) {
                    continue;
                }
                let mut sizes = sizes;
                sizes.render.clip_depth = clip_depth;
                jobs.push((setup, scheme, sizes));
            }
        }
        // The cases run on every device at once; their results are read in the jobs' order.
        let results = on_devices(gpus, &jobs, |gpu, &(setup, scheme, sizes)| {
            run_full(gpu, &setup.name, &setup.scene, scheme, sizes).map(|r| r.summary)
        })?;
        for (&(setup, scheme, _), result) in jobs.iter().zip(results) {
            row.cases += 1;
            let case = format!("{}/{}", setup.name, scheme.name());
            match result {
                Ok(summary) => {
                    let before = clean.get(&case).cloned().unwrap_or_default();
                    let v: Vec<String> = violations(&summary)
                        .into_iter()
                        .filter(|x| !before.contains(&target_name(x)))
                        .collect();
                    if fault.is_none() {
                        clean.insert(case.clone(), v.iter().map(|x| target_name(x)).collect());
                    }
                    if !v.is_empty() {
                        row.failing += 1;
                        row.setups.insert(setup.name.clone());
                        for x in &v {
                            *row.targets.entry(target_name(x)).or_default() += 1;
                        }
                        if row.example.is_empty() {
                            row.example = format!("{case}: {}", v.join("; "));
                        }
                    }
                }
                Err(e) => {
                    row.errors += 1;
                    if row.example.is_empty() {
                        row.example = format!("{case}: error {e}");
                    }
                }
            }
        }
        log(&format!(
            "{}: {} of {} cases violate a target{}, {} errors ({:.1} s){}",
            fault.map_or("clean build", |f| f.name()),
            row.failing,
            row.cases,
            if fault.is_some() {
                " the clean case meets"
            } else {
                ""
            },
            row.errors,
            t.elapsed().as_secs_f64(),
            if row.example.is_empty() {
                String::new()
            } else {
                format!("; first: {}", row.example)
            }
        ));
        rows.push(row);
    }
    Ok(rows)
}
