//! `plan`: the library's planner on `warp`'s scene flags, with each candidate spelled as `warp`'s
//! flags.

use crate::args::{PlanArgs, RoundingName};
use crate::output::sig;
use crate::scene::{frame_input, Boxes};
use glam::DVec3;
use serde_json::{json, Value};
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::candidates::{label, warp_args};
use shadow_aliasing::plan::{plan as plan_frame, Goal, Plan};
use shadow_aliasing::Error;
use std::fmt::Write as _;

/// The maps a budget's scheme may have when `--max-maps` is not given.
pub const DEFAULT_MAX_MAPS: usize = 8;

/// A whole number of the command line as a `u64` of at least `min`, naming the flag.
fn at_least(name: &'static str, v: i64, min: u64) -> Result<u64, Error> {
    u64::try_from(v)
        .ok()
        .filter(|v| *v >= min)
        .ok_or_else(|| Error::invalid(name, format!("must be at least {min} (got {v})")))
}

/// The goal from `--max-error` or `--budget-texels [--max-maps]`.
fn goal(a: &PlanArgs) -> Result<Goal, Error> {
    match (a.max_error, a.budget_texels) {
        (Some(_), None) if a.max_maps.is_some() => Err(Error::invalid(
            "--max-maps",
            "is only used with --budget-texels: drop it, or give --budget-texels instead of \
             --max-error",
        )),
        (Some(e), None) => Ok(Goal::MaxError(e)),
        (None, Some(t)) => Ok(Goal::Budget {
            texels: at_least("budget_texels", t, 1)?,
            max_maps: match a.max_maps {
                Some(m) => usize::try_from(at_least("max_maps", m, 1)?).unwrap_or(usize::MAX),
                None => DEFAULT_MAX_MAPS,
            },
        }),
        _ => Err(Error::invalid(
            "--max-error",
            "or --budget-texels is needed: give --max-error PX (the fewest texels within PX) \
             or --budget-texels N [--max-maps K] (the least error within N texels)",
        )),
    }
}

/// The text or JSON of `plan`.
pub fn plan(a: &PlanArgs) -> Result<String, Error> {
    let h = u32::try_from(at_least("image_height", a.image_height, 1)?).map_err(|_| {
        Error::invalid(
            "image_height",
            format!("must be at most {} (got {})", u32::MAX, a.image_height),
        )
    })?;
    let goal = goal(a)?;
    let boxes = Boxes::new(&a.bounds)?;
    let light = DVec3::from_array(a.light_dir);
    let input = frame_input(&a.camera, light, &a.bounds, &boxes, h)?;
    let rounding = match a.rounding {
        RoundingName::Whole => Rounding::Whole,
        RoundingName::PowerOfTwo => Rounding::PowerOfTwo,
    };
    let p = plan_frame(&input, goal, rounding).map_err(|e| match e {
        Error::InvalidArgument {
            name: "light_dir_world",
            reason,
        } => Error::invalid("light_dir", reason),
        e => e,
    })?;
    Ok(if a.json {
        json(&p, h)
    } else {
        text(&p, goal, h)
    })
}

/// `plan --json`.
fn json(p: &Plan, h: u32) -> String {
    let resolutions: Vec<Value> = p
        .resolutions
        .iter()
        .map(|r| json!([r.res_s, r.res_t]))
        .collect();
    let candidates: Vec<Value> = p
        .candidates
        .iter()
        .map(|c| {
            let mut v = json!({
                "scheme": label(&c.scheme),
                "warp_args": warp_args(&c.scheme, h),
            });
            match &c.outcome {
                Ok(m) => {
                    v["maps"] = json!(m.maps);
                    v["texels"] = json!(m.texels);
                    v["max_error_pixels"] = json!(m.max_error_pixels);
                    v["storage_factor"] = json!(m.storage_factor);
                }
                Err(e) => v["error"] = json!(e.to_string()),
            }
            v
        })
        .collect();
    let out = json!({
        "scheme": label(&p.scheme()),
        "warp_args": warp_args(&p.scheme(), h),
        "focus": p.frame.focus().name(),
        "resolutions": resolutions,
        "max_error_pixels": p.max_error_pixels,
        "texels": p.texels,
        "candidates": candidates,
    });
    let mut s = serde_json::to_string_pretty(&out).unwrap_or_default();
    s.push('\n');
    s
}

/// `plan` for people: the choice, its maps, and the table.
fn text(p: &Plan, goal: Goal, h: u32) -> String {
    let mut s = String::new();
    let asked = match goal {
        Goal::MaxError(e) => format!("the fewest texels with at most {} px per texel", sig(e)),
        Goal::Budget { texels, max_maps } => {
            format!("the least error within {texels} texels and {max_maps} maps")
        }
    };
    let _ = writeln!(s, "plan: {asked}");
    let _ = writeln!(
        s,
        "chosen: {} — {} texels, {} px per texel (focus: {})",
        label(&p.scheme()),
        p.texels,
        sig(p.max_error_pixels),
        p.frame.focus().name()
    );
    if let Some(w) = warp_args(&p.scheme(), h) {
        let _ = writeln!(s, "warp flags: {}", w.join(" "));
    }
    for (i, r) in p.resolutions.iter().enumerate() {
        let _ = writeln!(
            s,
            "  map {}: {} × {} texels, {} px",
            i + 1,
            r.res_s,
            r.res_t,
            sig(r.error_pixels)
        );
    }
    let _ = writeln!(s, "\ncandidates ({}):", p.candidates.len());
    for (i, c) in p.candidates.iter().enumerate() {
        let mark = if i == p.chosen { "*" } else { " " };
        let what = match &c.outcome {
            Ok(m) => format!(
                "{:>2} maps {:>12} texels {:>10} px",
                m.maps,
                m.texels,
                sig(m.max_error_pixels)
            ),
            Err(e) => format!("— {e}"),
        };
        let _ = writeln!(s, "{mark} {:<34} {what}", label(&c.scheme));
    }
    s
}
