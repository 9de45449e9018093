//! The error-budget controller against three alternatives on every camera path of `paths/`
//! (issue 32 item 3; the table in docs/planning.md, "An error budget per frame"):
//!
//! - **controller**: `plan::Controller` with `ControllerOptions::new(TARGET)` (at most 65 maps,
//!   one power-of-two resolution shared by the maps, up to 8192², every candidate but the
//!   clipmap, a neighbour measured every 4 frames), as `shadow-aliasing replay` runs it;
//! - **without neighbours**: the same with `neighbour_every: 0`;
//! - **a resolution per map**: the same with `shared_resolution: false` (each map its own
//!   power-of-two square), and the search every frame (below) with it;
//! - **search every frame**: the same controller with a cut on every frame (`Controller::cut`):
//!   every candidate measured, the fewest texels at one shared power-of-two resolution (the
//!   planner's answer under the controller's constraint, with no memory);
//! - **Bevy**: Bevy's defaults as the crate models them (examples/engine_defaults.rs): 4 stable
//!   cascades, `CascadeSplits::Bevy` (minimum 0.1, first far bound 10, maximum 150, overlap
//!   0.2), 2048² each, measured over the part of the focus body they cover (nothing beyond 150);
//! - **plan every frame**: `plan::plan` with `Goal::MaxError(TARGET)` and power-of-two
//!   resolutions, run on every frame (each map its own `res_s × res_t`);
//! - **fixed**: the controller's first-frame set-up (scheme and resolution), kept for the whole
//!   path.
//!
//! Per path and method: the largest error, the frames over the target, the mean texels, the
//! switches (frames whose scheme or resolutions differ from the last frame's) and the median
//! wall time a frame. Run with `cargo run --release --features cli --example path_table`.

#[allow(dead_code)]
#[path = "../src/bin/shadow-aliasing/path_file.rs"]
mod path_file;

use shadow_aliasing::frame::{frame, Bound, CascadeSplits, FrameInput, FrameScheme};
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::candidates::label;
use shadow_aliasing::plan::{plan, Controller, ControllerOptions, Goal};
use std::path::Path;
use std::time::Instant;

/// The target, pixels of a 1080-pixel image per texel.
const TARGET: f64 = 2.0;
const PATHS: [&str; 5] = ["walk", "flyover", "turn", "sun_sweep", "cut"];

/// One method's numbers over a path.
#[derive(Default)]
struct Tally {
    max_error: f64,
    over: usize,
    texels: f64,
    switches: usize,
    ms: Vec<f64>,
    last: Option<String>,
}

impl Tally {
    fn add(&mut self, key: String, error: f64, texels: u64, ms: f64) {
        self.max_error = self.max_error.max(error);
        self.over += usize::from(error > TARGET);
        self.texels += texels as f64;
        if self.last.as_ref().is_some_and(|l| *l != key) {
            self.switches += 1;
        }
        self.last = Some(key);
        self.ms.push(ms);
    }

    fn row(&mut self, path: &str, method: &str, frames: usize) -> String {
        self.ms.sort_by(f64::total_cmp);
        let median = self.ms[self.ms.len() / 2];
        format!(
            "| {path} | {method} | {:.3} | {} | {:.1} | {} | {:.3} |",
            self.max_error,
            self.over,
            self.texels / frames as f64 / 1e6,
            self.switches,
            median
        )
    }
}

fn main() -> Result<(), String> {
    println!("| path | method | largest error (px) | frames over {TARGET} px | mean texels (M) | switches | median ms a frame |");
    println!("|---|---|---|---|---|---|---|");
    for name in PATHS {
        let file = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("paths")
            .join(format!("{name}.json"));
        let path = path_file::read(&file)?;
        let n = path.frames.len();
        let new = |every, shared| {
            Controller::new(ControllerOptions {
                neighbour_every: every,
                shared_resolution: shared,
                ..ControllerOptions::new(TARGET)
            })
            .map_err(|e| e.to_string())
        };
        let (mut controller, mut lone, mut eager) = (new(4, true)?, new(0, true)?, new(4, true)?);
        let (mut each, mut each_eager) = (new(4, false)?, new(4, false)?);
        let (mut ctl, mut bevy, mut full, mut fixed) = Default::default();
        let (mut ctl_lone, mut ctl_eager) = (Tally::default(), Tally::default());
        let (mut ctl_each, mut ctl_each_eager) = (Tally::default(), Tally::default());
        let mut kept: Option<(FrameScheme<'static>, u32)> = None;
        for (i, f) in path.frames.iter().enumerate() {
            let at = |e: shadow_aliasing::Error| format!("{name} frame {i}: {e}");
            let mut input = FrameInput::new(f.camera, f.light, 2048, path.image_height)
                .receivers(Bound::Boxes(&path.receivers));
            if !path.casters.is_empty() {
                input = input.casters(Bound::Boxes(&path.casters));
            }
            let t = Instant::now();
            let d = controller.frame(&input).map_err(at)?;
            let ms = t.elapsed().as_secs_f64() * 1e3;
            let key = format!("{} {}", label(&d.scheme), d.resolution);
            Tally::add(&mut ctl, key, d.max_error_pixels, d.texels, ms);
            let first = *kept.get_or_insert((d.scheme, d.resolution));
            for (c, tally, cut) in [
                (&mut lone, &mut ctl_lone, false),
                (&mut eager, &mut ctl_eager, true),
                (&mut each, &mut ctl_each, false),
                (&mut each_eager, &mut ctl_each_eager, true),
            ] {
                if cut {
                    c.cut();
                }
                let t = Instant::now();
                let d = c.frame(&input).map_err(at)?;
                let ms = t.elapsed().as_secs_f64() * 1e3;
                let key = format!("{} {:?}", label(&d.scheme), d.resolutions);
                tally.add(key, d.max_error_pixels, d.texels, ms);
            }

            let t = Instant::now();
            let b = frame(&input.scheme(FrameScheme::Stable(CascadeSplits::Bevy {
                k: 4,
                minimum_distance: 0.1,
                maximum_distance: 150.0,
                first_far_bound: 10.0,
                overlap_proportion: 0.2,
            })))
            .map_err(at)?;
            let ms = t.elapsed().as_secs_f64() * 1e3;
            let e = b
                .maps()
                .iter()
                .map(|m| m.max_error_pixels)
                .fold(0.0, f64::max);
            Tally::add(&mut bevy, String::new(), e, 4 * 2048 * 2048, ms);

            let t = Instant::now();
            let p = plan(&input, Goal::MaxError(TARGET), Rounding::PowerOfTwo).map_err(at)?;
            let ms = t.elapsed().as_secs_f64() * 1e3;
            let res: Vec<(u64, u64)> = p.resolutions.iter().map(|r| (r.res_s, r.res_t)).collect();
            let key = format!("{} {res:?}", label(&p.scheme()));
            Tally::add(&mut full, key, p.max_error_pixels, p.texels, ms);

            let t = Instant::now();
            let mut fixed_input = FrameInput::new(f.camera, f.light, first.1, path.image_height)
                .receivers(Bound::Boxes(&path.receivers))
                .scheme(first.0);
            if !path.casters.is_empty() {
                fixed_input = fixed_input.casters(Bound::Boxes(&path.casters));
            }
            let x = frame(&fixed_input).map_err(at)?;
            let ms = t.elapsed().as_secs_f64() * 1e3;
            let e = x
                .maps()
                .iter()
                .map(|m| m.max_error_pixels)
                .fold(0.0, f64::max);
            let texels = x.maps().len() as u64 * u64::from(first.1).pow(2);
            Tally::add(&mut fixed, String::new(), e, texels, ms);
        }
        let first = kept.map_or(String::new(), |(s, r)| format!("fixed: {} {r}²", label(&s)));
        println!("{}", ctl.row(name, "controller", n));
        println!("{}", ctl_lone.row(name, "controller without neighbours", n));
        println!(
            "{}",
            ctl_eager.row(name, "search every frame (shared resolution)", n)
        );
        println!(
            "{}",
            ctl_each.row(name, "controller, a resolution per map", n)
        );
        println!(
            "{}",
            ctl_each_eager.row(name, "search every frame (a resolution per map)", n)
        );
        println!("{}", bevy.row(name, "Bevy defaults (4 × 2048²)", n));
        println!("{}", full.row(name, "plan every frame", n));
        println!("{}", fixed.row(name, &first, n));
    }
    Ok(())
}
