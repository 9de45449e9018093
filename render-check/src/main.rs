//! `render-check`: renders every set-up × scheme, writes per case `<setup>_<scheme>.png` (shaded),
//! `<setup>_<scheme>_error.png` (rendered error beside rendered/predicted) and `<setup>_<scheme>_lens.png`
//! (the error lens the GPU drew over the scene, with its legend), with `--gallery`
//! also `<setup>_<scheme>_edge.png` (a shadow edge at 512² texels), and `summary.json`.
//! `--fault NAME` injects one deliberate fault; `--self-test` runs the clean build and every fault.
//! `render-check --help` lists the options.

use render_check::faults::Fault;
use render_check::gpu::{Gpu, Lookup};
use render_check::images::{close_up, error_panels, lens_overlay, shaded, Crop};
use render_check::pool::{devices, on_devices};
use render_check::run::{case_clip_depth, run_case, run_full, CaseSummary, Render, Sizes, Summary};
use render_check::scene::Scene;
use render_check::schemes::{schemes_for, setups, Scheme, Setup};
use render_check::self_test::{self_test, MIN_SETUPS_CAUGHT};
use render_check::targets::{is_inconclusive, violations};
use shadow_aliasing::maps::ClipDepth;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

fn main() -> ExitCode {
    match real_main() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("render-check: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The map resolution of the gallery's close-ups.
const EDGE_RES: u32 = 512;

fn help() -> String {
    let mut s = String::from(
        "render-check [--out DIR] [--scene FILE.json | --setup NAME] [--width W] [--height H]\n\
         \x20            [--res N] [--frames N] [--fault NAME] [--gallery] [--reversed]\n\
         \x20            [--first-surface] [--no-cull] [--jobs N]\n\
         render-check --self-test [--jobs N]\n\n\
         --out DIR        where the images and summary.json go (default render-check-out)\n\
         --scene FILE     one scene file (docs/rendered.md has the format) instead of the built-in set\n\
         --setup NAME     only this built-in set-up (overhead, tilted_45, behind_5, front_5,\n\
         \x20                grazing_10, parallel_1, level_overhead, thin_casters, far_1e5,\n\
         \x20                far_tilted, level_side)\n\
         --width, --height  screen size (default 640 x 480)\n\
         --res N          texels per map side, overriding the scene's\n\
         --frames N       frames of the shimmer test (default 64)\n\
         --jobs N         cases rendered at once, each on a device of its own (default 2, 1 on\n\
         \x20                one core; also for --self-test)\n\
         --gallery        also write <setup>_<scheme>_edge.png: a shadow edge at 512^2 texels\n\
         --reversed       every map in reversed depth (1 nearest the light), compared\n\
         \x20                greater-equal (default: reversed where the set-up's and the\n\
         \x20                scheme's indices sum to an even number, depth [0, 1] elsewhere)\n\
         --first-surface  ordinary first-surface maps looked up at the crate's normal offset\n\
         \x20                (default: second-depth maps with a hand-set rasterizer bias)\n\
         --no-cull        draw every object into every map (default: culled by each map's\n\
         \x20                casters' volume)\n\
         --self-test      the clean build and every fault over the built-in set-ups (320 x 240):\n\
         \x20                exits 0 only when the clean build meets every target and every fault\n\
         \x20                violates one in at least two set-ups\n\
         --fault NAME     inject one deliberate fault:\n",
    );
    for f in Fault::ALL {
        s += &format!("                   {:<20} {}\n", f.name(), f.describe());
    }
    s
}

fn real_main() -> Result<(), String> {
    let mut out = PathBuf::from("render-check-out");
    let mut scene_file = None;
    let mut only = None;
    let mut gallery = false;
    let mut self_check = false;
    let mut reversed = false;
    // Two cases at once by default: a case keeps about one core busy.
    let mut threads = std::thread::available_parallelism().map_or(1, |n| n.get().min(2));
    let mut sizes = Sizes {
        width: 640,
        height: 480,
        res: None,
        frames: 64,
        shimmer_points: 4000,
        fault: None,
        render: Render::DEFAULT,
    };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut val = |name: &str| {
            args.next()
                .ok_or(format!("{name} needs a value (see --help)"))
        };
        let num = |v: String, name: &str| {
            v.parse::<u32>()
                .map_err(|e| format!("{name} {v:?}: {e} (a whole number)"))
        };
        match a.as_str() {
            "--out" => out = PathBuf::from(val("--out")?),
            "--scene" => scene_file = Some(PathBuf::from(val("--scene")?)),
            "--setup" => only = Some(val("--setup")?),
            "--width" => sizes.width = num(val("--width")?, "--width")?,
            "--height" => sizes.height = num(val("--height")?, "--height")?,
            "--res" => sizes.res = Some(num(val("--res")?, "--res")?),
            "--frames" => sizes.frames = num(val("--frames")?, "--frames")? as usize,
            "--jobs" => threads = num(val("--jobs")?, "--jobs")? as usize,
            "--fault" => sizes.fault = Some(Fault::parse(&val("--fault")?)?),
            "--gallery" => gallery = true,
            "--reversed" => reversed = true,
            "--first-surface" => sizes.render.lookup = Lookup::FirstSurface,
            "--no-cull" => sizes.render.cull = false,
            "--self-test" => self_check = true,
            "--help" | "-h" => {
                print!("{}", help());
                return Ok(());
            }
            other => return Err(format!("unknown argument {other:?} (see --help)")),
        }
    }
    if sizes.width < 16 || sizes.height < 16 {
        return Err("--width and --height must be at least 16".into());
    }
    if !(1..=64).contains(&threads) {
        return Err(format!("--jobs {threads}: must lie in [1, 64]"));
    }
    if sizes.frames < 2 {
        return Err("--frames must be at least 2".into());
    }
    if let Some(r) = sizes.res {
        if !(16..=8192).contains(&r) {
            return Err(format!("--res {r}: must lie in [16, 8192]"));
        }
    }
    if scene_file.is_some() && only.is_some() {
        return Err("--scene and --setup exclude each other: give one".into());
    }
    if self_check {
        return run_self_test(threads);
    }
    if reversed {
        sizes.render.clip_depth = ClipDepth::Reversed;
    }
    let cases: Vec<Setup> = match (&scene_file, &only) {
        (Some(f), _) => vec![Setup {
            name: f
                .file_stem()
                .map_or("scene".into(), |s| s.to_string_lossy().into_owned()),
            scene: Scene::load(f)?,
        }],
        (None, Some(name)) => {
            let all = setups();
            let names: Vec<String> = all.iter().map(|s| s.name.clone()).collect();
            let found: Vec<Setup> = all.into_iter().filter(|s| &s.name == name).collect();
            if found.is_empty() {
                return Err(format!(
                    "--setup: unknown set-up {name:?}; one of {}",
                    names.join(", ")
                ));
            }
            found
        }
        (None, None) => setups(),
    };
    let order: Vec<String> = setups().into_iter().map(|s| s.name).collect();
    // Every (set-up, scheme) pair, in the order summary.json lists them.
    let jobs: Vec<(&Setup, usize, Scheme)> = cases
        .iter()
        .flat_map(|setup| {
            // The set-up's place in the built-in list picks its schemes' clip depths (a scene
            // file counts as the first).
            let si = order.iter().position(|n| n == &setup.name).unwrap_or(0);
            schemes_for(&setup.name)
                .into_iter()
                .map(move |scheme| (setup, si, scheme))
        })
        .collect();
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    let start = Instant::now();
    // One device per thread (render_check::pool).
    let gpus = devices(threads.min(jobs.len()), &Fault::shader_source(sizes.fault)?)?;
    let gpu = &gpus[0];
    eprintln!("device: {}", gpu.name);
    if let Some(f) = sizes.fault {
        eprintln!("fault injected: {} ({})", f.name(), f.describe());
    }
    let mut summary = Summary {
        device: gpu.name.clone(),
        cases: Vec::new(),
        options: Vec::new(),
    };
    let opts = CaseOptions {
        sizes,
        reversed,
        gallery,
        out: &out,
    };
    let results = on_devices(&gpus, &jobs, |gpu, &(setup, si, scheme)| {
        one_case(gpu, setup, si, scheme, &opts)
    })?;
    let (mut violated, mut inconclusive) = (0usize, 0usize);
    for r in results {
        let case = r?;
        let v = violations(&case);
        let wrong = v.iter().any(|l| !is_inconclusive(l));
        violated += usize::from(wrong);
        inconclusive += usize::from(!wrong && !v.is_empty());
        summary.cases.push(case);
    }
    // The option cases of the set-ups run (none for a scene file): built and measured on the
    // CPU alone (render_check::options).
    let run_setups: Vec<&str> = if scene_file.is_some() {
        Vec::new()
    } else {
        cases.iter().map(|s| s.name.as_str()).collect()
    };
    for c in render_check::options::cases()
        .into_iter()
        .filter(|c| run_setups.contains(&c.setup))
    {
        let o = match render_check::options::measure(&c, sizes.width, sizes.height, sizes.fault) {
            Ok(o) => o,
            Err(e) => {
                eprintln!("  TARGET VIOLATED option {}: {e}", c.name);
                violated += 1;
                continue;
            }
        };
        let v = render_check::options::violations(&o);
        let mut msg = format!(
            "option {}: {}",
            c.name,
            serde_json::to_string(&o).map_err(|e| e.to_string())?
        );
        for line in &v {
            msg += &format!("\n  TARGET VIOLATED option {}: {line}", c.name);
        }
        eprintln!("{msg}");
        violated += usize::from(!v.is_empty());
        summary.options.push(o);
    }
    let p = out.join("summary.json");
    let json = serde_json::to_string_pretty(&summary).map_err(|e| e.to_string())?;
    std::fs::write(&p, json + "\n").map_err(|e| format!("{}: {e}", p.display()))?;
    eprintln!(
        "wrote {} cases to {} in {:.1} s",
        summary.cases.len(),
        out.display(),
        start.elapsed().as_secs_f64()
    );
    if violated + inconclusive > 0 {
        return Err(format!(
            "{violated} of {} cases and option cases violate a target (a wrong pixel or number: \
             the lines TARGET VIOLATED above) and {inconclusive} more are inconclusive (too \
             little decidable: the lines INCONCLUSIVE); docs/rendered.md lists the targets",
            summary.cases.len() + summary.options.len()
        ));
    }
    Ok(())
}

/// What every case of a run shares.
struct CaseOptions<'a> {
    sizes: Sizes,
    reversed: bool,
    gallery: bool,
    out: &'a Path,
}

/// Renders one case, writes its images and prints its summary line and violations.
fn one_case(
    gpu: &Gpu,
    setup: &Setup,
    si: usize,
    scheme: Scheme,
    o: &CaseOptions,
) -> Result<CaseSummary, String> {
    let save = |img: image::RgbImage, name: String| {
        let p = o.out.join(&name);
        img.save(&p).map_err(|e| format!("{}: {e}", p.display()))
    };
    let t = Instant::now();
    let mut sizes = o.sizes;
    if !o.reversed {
        sizes.render.clip_depth = case_clip_depth(si, scheme);
    }
    let r = run_full(gpu, &setup.name, &setup.scene, scheme, sizes)?;
    let stem = format!("{}_{}", setup.name, scheme.name());
    let res = sizes.res.unwrap_or(setup.scene.map_resolution);
    let case = format!(
        "{} / {}: {res}² texels per map, {} × {}{}",
        setup.name,
        scheme.label(),
        sizes.width,
        sizes.height,
        sizes
            .fault
            .map_or(String::new(), |f| format!(", fault {}", f.name()))
    );
    save(
        shaded(&r.color, sizes.width, sizes.height, &case),
        format!("{stem}.png"),
    )?;
    save(
        error_panels(
            &r.analysis.rendered_error,
            &r.analysis.predicted_error,
            sizes.width,
            sizes.height,
            &case,
        ),
        format!("{stem}_error.png"),
    )?;
    save(
        lens_overlay(
            &r.overlay,
            sizes.width,
            sizes.height,
            &case,
            &format!("largest: {:.4} px", r.summary.measured.max_lens),
        ),
        format!("{stem}_lens.png"),
    )?;
    if o.gallery {
        let low = Sizes {
            res: Some(EDGE_RES),
            ..sizes
        };
        let e = run_case(gpu, &setup.name, &setup.scene, scheme, low)?;
        let crop = edge_crop(&setup.name, sizes.width, sizes.height);
        let title = format!(
            "{} / {}: shadow edge, {EDGE_RES}² texels per map",
            setup.name,
            scheme.label()
        );
        save(
            close_up(
                &e.color,
                &e.analysis.predicted_error,
                sizes.width,
                crop,
                4,
                &title,
            ),
            format!("{stem}_edge.png"),
        )?;
    }
    // One eprintln per case, so that two threads' lines never interleave.
    let mut msg = format!(
        "{stem}: {} ({:.1} s)",
        serde_json::to_string(&r.summary).map_err(|e| e.to_string())?,
        t.elapsed().as_secs_f64()
    );
    for line in violations(&r.summary) {
        if is_inconclusive(&line) {
            msg += &format!("\n  INCONCLUSIVE {stem}: {line}");
        } else {
            msg += &format!("\n  TARGET VIOLATED {stem}: {line}");
        }
    }
    eprintln!("{msg}");
    Ok(r.summary)
}

/// The close-up's rectangle (a quarter of the screen's width and height): for `behind_5` the
/// tower's shadow edge nearest the camera, else the bottom centre.
fn edge_crop(setup: &str, w: u32, h: u32) -> Crop {
    let (cw, ch) = (w / 4, h / 4);
    let (fx, fy) = match setup {
        "behind_5" => (0.50, 0.66),
        _ => (0.375, 0.70),
    };
    let x = ((f64::from(w) * fx) as u32).min(w - cw);
    let y = ((f64::from(h) * fy) as u32).min(h - ch);
    (x, y, cw, ch)
}

/// `--self-test`: prints one line per fault (cases run, cases caught, the targets that caught
/// it) and fails unless the clean build passes and every fault is caught.
fn run_self_test(threads: usize) -> Result<(), String> {
    let start = Instant::now();
    let gpus = devices(threads, &Fault::shader_source(None)?)?;
    eprintln!("device: {} ({} at once)", gpus[0].name, gpus.len());
    let rows = self_test(&gpus, |line| eprintln!("{line}"))?;
    println!("| fault | cases caught / run | set-ups caught | targets violated (cases) |");
    println!("|---|---|---|---|");
    let mut ok = true;
    for r in &rows {
        let name = r.fault.map_or("none (clean)", |f| f.name());
        let targets: Vec<String> = r
            .targets
            .iter()
            // A target's own bars (|x − 0.8|) escaped: the line is a Markdown table row.
            .map(|(t, n)| format!("{} ({n})", t.replace('|', "\\|")))
            .collect();
        println!(
            "| {name} | {} / {} | {} | {} |",
            r.failing,
            r.cases,
            r.setups.len(),
            if targets.is_empty() {
                "—".to_string()
            } else {
                targets.join(", ")
            }
        );
        let pass = match r.fault {
            None => r.failing == 0 && r.errors == 0,
            Some(_) => r.setups.len() >= MIN_SETUPS_CAUGHT,
        };
        if !pass {
            ok = false;
            eprintln!(
                "self-test: {} {}",
                name,
                if r.fault.is_none() {
                    format!("violates targets: {}", r.example)
                } else {
                    format!(
                        "is caught in {} set-up(s), fewer than {MIN_SETUPS_CAUGHT} (a hole)",
                        r.setups.len()
                    )
                }
            );
        }
    }
    eprintln!("self-test took {:.1} s", start.elapsed().as_secs_f64());
    if ok {
        Ok(())
    } else {
        Err("self-test failed".into())
    }
}
