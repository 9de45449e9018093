//! `replay`: the error-budget controller (`plan::Controller`) over a camera path file
//! (docs/paths.md): per frame the choice, its measured error, its texels and whether it
//! switched; in summary the switches, the largest error, the mean texels and the cost.

use crate::args::ReplayArgs;
use crate::output::sig;
use crate::path_file;
use crate::replay_figure::{svg, Point};
use serde_json::{json, Value};
use shadow_aliasing::frame::{Bound, FrameInput};
use shadow_aliasing::plan::candidates::label;
use shadow_aliasing::plan::{Controller, ControllerOptions};
use std::fmt::Write as _;
use std::time::Instant;

/// One frame's outcome.
struct Row {
    scheme: String,
    maps: usize,
    resolution: u32,
    /// Each slot's resolution.
    resolutions: Vec<u32>,
    /// Each built map's resolution.
    built: Vec<u32>,
    max_error_pixels: f64,
    texels: u64,
    meets_target: bool,
    within_budget: bool,
    switched: bool,
    cut: bool,
    ms: f64,
}

/// The `q` quantile (nearest rank) of sorted values.
fn quantile(sorted: &[f64], q: f64) -> f64 {
    let rank = (q * sorted.len() as f64).ceil() as usize;
    sorted[rank.clamp(1, sorted.len()) - 1]
}

/// The text or JSON of `replay`.
pub fn replay(a: &ReplayArgs) -> Result<String, String> {
    let budget = match a.budget_texels {
        Some(b) if b < 1 => {
            return Err(format!(
                "--budget-texels must be at least 1 texel (got {b}): give the texels all maps \
                 may take together"
            ))
        }
        b => b.map(i64::unsigned_abs),
    };
    let mut options = match (a.max_error, budget) {
        (Some(e), b) => ControllerOptions {
            max_texels: b,
            ..ControllerOptions::new(e)
        },
        (None, Some(b)) => ControllerOptions::budget(b),
        (None, None) => {
            return Err(
                "--max-error or --budget-texels is needed (or both): --max-error PX for \
                 the fewest texels within PX, --budget-texels N for the least error within N \
                 texels"
                    .into(),
            )
        }
    };
    options.shared_resolution = !a.per_map;
    let path = path_file::read(&a.path)?;
    let mut c = Controller::new(options).map_err(|e| match e {
        shadow_aliasing::Error::InvalidArgument { name, reason } => {
            let flag = match name {
                "max_texels" => "budget-texels".to_string(),
                n => n.replace('_', "-"),
            };
            format!("--{flag} {reason}")
        }
        e => e.to_string(),
    })?;
    let mut rows = Vec::with_capacity(path.frames.len());
    for (i, f) in path.frames.iter().enumerate() {
        let mut input = FrameInput::new(f.camera, f.light, 2048, path.image_height)
            .receivers(Bound::Boxes(&path.receivers));
        if !path.casters.is_empty() {
            input = input.casters(Bound::Boxes(&path.casters));
        }
        let t0 = Instant::now();
        let d = c
            .frame(&input)
            .map_err(|e| format!("path file {}, frame {i}: {e}", a.path.display()))?;
        let ms = t0.elapsed().as_secs_f64() * 1e3;
        rows.push(Row {
            scheme: label(&d.scheme),
            maps: d.frame.maps().len(),
            resolution: d.resolution,
            resolutions: d.resolutions.to_vec(),
            built: d.frame.maps().iter().map(|m| m.resolution()).collect(),
            max_error_pixels: d.max_error_pixels,
            texels: d.texels,
            meets_target: d.meets_target,
            within_budget: d.within_budget,
            switched: d.switched,
            cut: d.cut,
            ms,
        });
    }
    if let Some(file) = &a.figure {
        let points: Vec<Point> = rows
            .iter()
            .map(|r| Point {
                error: r.max_error_pixels,
                texels: r.texels,
                cut: r.cut,
            })
            .collect();
        let title = format!("replay {}: {}", a.path.display(), goal(a));
        std::fs::write(file, svg(&points, a.max_error, budget, &title))
            .map_err(|e| format!("cannot write {}: {e}", file.display()))?;
    }
    Ok(if a.json {
        json_out(a, &rows)
    } else {
        text(a, &rows)
    })
}

/// The summary's numbers.
struct Summary {
    switches: usize,
    cuts: usize,
    missed: usize,
    over_budget: usize,
    max_error: f64,
    mean_texels: f64,
    median_ms: f64,
    p99_ms: f64,
}

fn summary(rows: &[Row]) -> Summary {
    let mut ms: Vec<f64> = rows.iter().map(|r| r.ms).collect();
    ms.sort_by(f64::total_cmp);
    Summary {
        switches: rows.iter().filter(|r| r.switched).count(),
        cuts: rows.iter().filter(|r| r.cut).count(),
        missed: rows.iter().filter(|r| !r.meets_target).count(),
        over_budget: rows.iter().filter(|r| !r.within_budget).count(),
        max_error: rows.iter().map(|r| r.max_error_pixels).fold(0.0, f64::max),
        mean_texels: rows.iter().map(|r| r.texels as f64).sum::<f64>() / rows.len() as f64,
        median_ms: quantile(&ms, 0.5),
        p99_ms: quantile(&ms, 0.99),
    }
}

/// `replay --json`.
fn json_out(a: &ReplayArgs, rows: &[Row]) -> String {
    let frames: Vec<Value> = rows
        .iter()
        .enumerate()
        .map(|(i, r)| {
            json!({
                "frame": i,
                "scheme": r.scheme,
                "maps": r.maps,
                "resolution": r.resolution,
                "resolutions": r.resolutions,
                "max_error_pixels": r.max_error_pixels,
                "texels": r.texels,
                "meets_target": r.meets_target,
                "within_budget": r.within_budget,
                "switched": r.switched,
                "cut": r.cut,
                "ms": r.ms,
            })
        })
        .collect();
    let s = summary(rows);
    let out = json!({
        "path": a.path.display().to_string(),
        "max_error": a.max_error,
        "budget_texels": a.budget_texels,
        "per_map": a.per_map,
        "frames": frames,
        "summary": {
            "frames": rows.len(),
            "switches": s.switches,
            "cuts": s.cuts,
            "missed": s.missed,
            "over_budget": s.over_budget,
            "max_error_pixels": s.max_error,
            "mean_texels": s.mean_texels,
            "median_ms": s.median_ms,
            "p99_ms": s.p99_ms,
        },
    });
    let mut t = serde_json::to_string_pretty(&out).unwrap_or_default();
    t.push('\n');
    t
}

/// `replay` for people: a line a frame, then the summary.
fn text(a: &ReplayArgs, rows: &[Row]) -> String {
    let mut t = String::new();
    let _ = writeln!(
        t,
        "replay {}: {}, {} frames",
        a.path.display(),
        goal(a),
        rows.len()
    );
    for (i, r) in rows.iter().enumerate() {
        let mark = match (r.cut, r.switched) {
            (true, true) => "cut, switched",
            (true, false) => "cut",
            (false, true) => "switched",
            (false, false) => "",
        };
        let missed = match (r.meets_target, r.within_budget) {
            (true, true) => "",
            (false, true) => " (misses)",
            (true, false) => " (over the budget)",
            (false, false) => " (misses, over the budget)",
        };
        let size = if a.per_map {
            let each: Vec<String> = r.built.iter().map(u32::to_string).collect();
            format!("{:>2} maps {}²", r.maps, each.join("/"))
        } else {
            format!("{:>2} × {:>5}²", r.maps, r.resolution)
        };
        let line = format!(
            "frame {i:>4}: {:<34} {size} {:>10} texels {:>9} px{missed} {:.3} ms {mark}",
            r.scheme,
            r.texels,
            sig(r.max_error_pixels),
            r.ms,
        );
        let _ = writeln!(t, "{}", line.trim_end());
    }
    let s = summary(rows);
    let _ = writeln!(
        t,
        "summary: {} switches, {} cuts, {} frames missing the target, {} over the budget, largest \
         error {} px, mean {:.0} texels, cost {:.3} ms median, {:.3} ms p99 a frame",
        s.switches,
        s.cuts,
        s.missed,
        s.over_budget,
        sig(s.max_error),
        s.mean_texels,
        s.median_ms,
        s.p99_ms
    );
    t
}

/// The goal in words: the target, the budget, and whether each map has its own resolution.
fn goal(a: &ReplayArgs) -> String {
    let mut g = match (a.max_error, a.budget_texels) {
        (Some(e), Some(b)) => format!("at most {} px per texel within {b} texels", sig(e)),
        (Some(e), None) => format!("at most {} px per texel", sig(e)),
        (None, b) => format!("the least error within {} texels", b.unwrap_or(0)),
    };
    if a.per_map {
        g.push_str(", a resolution per map");
    }
    g
}
