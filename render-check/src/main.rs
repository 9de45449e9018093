//! `render-check [--out DIR] [--scene FILE.json] [--width W] [--height H] [--res N] [--frames N]`:
//! renders every set-up × scheme, writes per case `<setup>_<scheme>.png` (shaded) and
//! `<setup>_<scheme>_error.png` (rendered and predicted error), and `summary.json`.

use render_check::gpu::Gpu;
use render_check::images::{heat_map, shaded};
use render_check::run::{run_case, shimmer, Sizes, Summary};
use render_check::scene::Scene;
use render_check::schemes::{setups, Scheme, Setup};
use std::path::PathBuf;
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

fn real_main() -> Result<(), String> {
    let mut out = PathBuf::from("render-check-out");
    let mut scene_file = None;
    let mut sizes = Sizes {
        width: 640,
        height: 480,
        res: None,
        frames: 64,
        shimmer_points: 4000,
        fault: None,
    };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut val = |name: &str| args.next().ok_or(format!("{name} needs a value"));
        let num = |v: String, name: &str| v.parse::<u32>().map_err(|e| format!("{name}: {e}"));
        match a.as_str() {
            "--out" => out = PathBuf::from(val("--out")?),
            "--scene" => scene_file = Some(PathBuf::from(val("--scene")?)),
            "--width" => sizes.width = num(val("--width")?, "--width")?,
            "--height" => sizes.height = num(val("--height")?, "--height")?,
            "--res" => sizes.res = Some(num(val("--res")?, "--res")?),
            "--frames" => sizes.frames = num(val("--frames")?, "--frames")? as usize,
            "--help" | "-h" => {
                println!("render-check [--out DIR] [--scene FILE.json] [--width W] [--height H] [--res N] [--frames N]");
                return Ok(());
            }
            other => return Err(format!("unknown argument {other} (see --help)")),
        }
    }
    if sizes.width < 16 || sizes.height < 16 {
        return Err("--width and --height must be at least 16".into());
    }
    if sizes.frames < 2 {
        return Err("--frames must be at least 2".into());
    }
    let cases: Vec<Setup> = match &scene_file {
        Some(f) => vec![Setup {
            name: f
                .file_stem()
                .map_or("scene".into(), |s| s.to_string_lossy().into_owned()),
            scene: Scene::load(f)?,
        }],
        None => setups(),
    };
    std::fs::create_dir_all(&out).map_err(|e| format!("{}: {e}", out.display()))?;
    let start = Instant::now();
    let gpu = Gpu::new()?;
    eprintln!("device: {}", gpu.name);
    let mut summary = Summary {
        device: gpu.name.clone(),
        cases: Vec::new(),
    };
    for setup in &cases {
        for scheme in Scheme::ALL {
            let t = Instant::now();
            let mut r = run_case(&gpu, &setup.name, &setup.scene, scheme, sizes)?;
            if matches!(scheme, Scheme::Cascades | Scheme::StableCascades) {
                r.summary.shimmer_changed_fraction =
                    Some(shimmer(&gpu, &setup.scene, scheme, sizes)?);
            }
            let stem = format!("{}_{}", setup.name, scheme.name());
            let save = |img: image::RgbImage, name: String| {
                let p = out.join(&name);
                img.save(&p).map_err(|e| format!("{}: {e}", p.display()))
            };
            save(
                shaded(&r.color, sizes.width, sizes.height),
                format!("{stem}.png"),
            )?;
            save(
                heat_map(
                    &r.analysis.rendered_error,
                    &r.analysis.predicted_error,
                    sizes.width,
                    sizes.height,
                ),
                format!("{stem}_error.png"),
            )?;
            let s = &r.summary;
            eprintln!(
                "{stem}: compared {} median {:.2e} p99 {:.2e} misses {} false {} band {:.3} max err {:.3}/{:.3} shimmer {:?} ({}; {:.1} s)",
                s.pixels_compared, s.median_rel_diff, s.p99_rel_diff, s.interior_misses,
                s.interior_false_shadows, s.edge_band_mismatch_fraction, s.max_rendered_error,
                s.max_predicted_error, s.shimmer_changed_fraction, r.diagnostics, t.elapsed().as_secs_f64()
            );
            summary.cases.push(r.summary);
        }
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
    Ok(())
}
