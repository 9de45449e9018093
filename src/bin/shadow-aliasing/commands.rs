//! What each subcommand does.

use crate::args::{
    Cli, ColumnName, Command, EvalArgs, FiguresArgs, Format, PartitionName, SweepArgs, SweepFormat,
    WarpArgs, WarpName,
};
use crate::output::{json_n_prime, json_num, sig, sig_n_prime};
use crate::scheme::{k, partition, partitions, rule, value_name, Lights, PartitionReport};
use crate::sweep_out::{self, Sink, WriteError};
use glam::DVec3;
use shadow_aliasing::scheme::sweep::SweepGrid;
use shadow_aliasing::{LightAngle, ViewFrustum};
use std::fmt::Write as _;
use std::io::{Read, Write};
use std::process::ExitCode;

/// Runs the parsed command line.
pub fn run(cli: Cli) -> ExitCode {
    match cli.command {
        Command::Eval(a) => eval(&a),
        Command::Warp(a) => warp(&a),
        Command::Sweep(a) => sweep(&a),
        Command::Figures(a) => figures(&a),
        Command::Plan(a) => match crate::plan::plan(&a) {
            Ok(text) => print(&text),
            Err(e) => fail(e),
        },
        Command::Replay(a) => match crate::replay::replay(&a) {
            Ok(text) => print(&text),
            Err(e) => fail(e),
        },
    }
}

/// Writes to standard error, ignoring a closed or failing stream (`eprintln!` would panic).
pub fn to_stderr(text: &str) {
    let _ = std::io::stderr().lock().write_all(text.as_bytes());
}

/// One line on standard error, exit status 1.
pub fn fail(message: impl std::fmt::Display) -> ExitCode {
    to_stderr(&format!("error: {message}\n"));
    ExitCode::from(1)
}

fn eval(a: &EvalArgs) -> ExitCode {
    let mut bytes = Vec::new();
    let read = match a.file.as_deref() {
        None => std::io::stdin().read_to_end(&mut bytes).map(|_| ()),
        Some(p) if p.as_os_str() == "-" => std::io::stdin().read_to_end(&mut bytes).map(|_| ()),
        Some(p) => std::fs::read(p).map(|b| bytes = b),
    };
    if let Err(e) = read {
        let what = a
            .file
            .as_deref()
            .map_or("standard input".to_string(), |p| p.display().to_string());
        to_stderr(&format!("error: cannot read {what}: {e}\n"));
        return ExitCode::from(2);
    }
    let Ok(text) = String::from_utf8(bytes) else {
        to_stderr("error: the input is not UTF-8 text\n");
        return ExitCode::from(2);
    };
    let out = shadow_aliasing::eval::eval_json(&text);
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(out.stdout.as_bytes())
        .and_then(|()| stdout.flush())
    {
        // A closed pipe: the reader has gone, which is not an error of the input or ours.
        Ok(()) => {}
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {}
        // Exit status 2 means malformed input; a failing output is status 1, with a message.
        Err(e) => return fail(format!("cannot write to standard output: {e}")),
    }
    to_stderr(&out.stderr);
    ExitCode::from(u8::try_from(out.exit_code).unwrap_or(2))
}

/// A grid count as the library's `usize`; a negative one answered in `SweepGrid::new`'s words.
fn count(name: &'static str, v: i64) -> Result<usize, shadow_aliasing::Error> {
    usize::try_from(v)
        .map_err(|_| shadow_aliasing::Error::invalid(name, format!("must be at least 1 (got {v})")))
}

/// Writes `text` to standard output; a closed pipe is not an error worth a message.
fn print(text: &str) -> ExitCode {
    print_bytes(text.as_bytes())
}

/// As [`print`], for bytes.
fn print_bytes(bytes: &[u8]) -> ExitCode {
    let mut out = std::io::stdout().lock();
    match out.write_all(bytes).and_then(|()| out.flush()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
        Err(e) => fail(format!("cannot write to standard output: {e}")),
    }
}

fn warp(a: &WarpArgs) -> ExitCode {
    if let Err(e) = crate::scene::clipmap_options_unused(a) {
        return fail(e);
    }
    // Equal-error splits are measured on the frame's maps: the scene path, with the frustum
    // alone when no scene is given.
    if a.scene.any()
        || a.scheme.partition == PartitionName::EqualError
        || a.scheme.partition == PartitionName::Clipmap
        || a.scheme.warp == WarpName::Trapezoid
    {
        return match crate::scene::warp_scene(a) {
            Ok(text) => print(&text),
            Err(e) => fail(e),
        };
    }
    let c = &a.camera;
    let view = match ViewFrustum::new(c.near, c.far, c.half_fov) {
        Ok(v) => v,
        Err(e) => return fail(e),
    };
    let light = DVec3::from_array(a.light_dir);
    let parts = match partitions(&view, light, &a.scheme) {
        Ok(p) => p,
        Err(e) => return fail(e),
    };
    let total: f64 = parts.iter().map(|p| p.storage_factor).sum();
    let text = if a.json {
        warp_json(a, total, &parts)
    } else {
        let gamma = LightAngle::from_light_dir(light)
            .map(LightAngle::radians)
            .unwrap_or(f64::NAN);
        warp_text(a, gamma, total, &parts)
    };
    print(&text)
}

/// The JSON of issue 3: `storage_factor` summed, and one object per partition.
fn warp_json(a: &WarpArgs, total: f64, parts: &[PartitionReport]) -> String {
    let mut s = format!(
        "{{\n  \"storage_factor\": {},\n  \"partitions\": [\n",
        json_num(total)
    );
    for (i, p) in parts.iter().enumerate() {
        let m: Vec<String> = a
            .clip_depth
            .depth()
            .convert(&p.matrix)
            .to_cols_array()
            .iter()
            .map(|v| json_num(*v))
            .collect();
        let _ = writeln!(
            s,
            "    {{{}\"near\": {}, \"far\": {}, \"n_prime\": {}, \"max_mx\": {}, \"max_mz\": {}, \"storage_factor\": {}, \"matrix\": [{}]}}{}",
            p.face
                .as_ref()
                .map_or_else(String::new, |f| format!("\"face\": \"{f}\", ")),
            json_num(p.near),
            json_num(p.far),
            json_n_prime(p.n_prime),
            json_num(p.max_mx),
            json_num(p.max_mz),
            json_num(p.storage_factor),
            m.join(", "),
            if i + 1 < parts.len() { "," } else { "" }
        );
    }
    s.push_str("  ]\n}\n");
    s
}

fn warp_text(a: &WarpArgs, gamma: f64, total: f64, parts: &[PartitionReport]) -> String {
    let c = &a.camera;
    let sch = &a.scheme;
    let [lx, ly, lz] = a.light_dir;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "camera: near {}, far {}, half_fov {} rad; light travels along ({}, {}, {}) in eye space, {}° from the view direction",
        sig(c.near),
        sig(c.far),
        sig(c.half_fov),
        sig(lx),
        sig(ly),
        sig(lz),
        sig(gamma.to_degrees())
    );
    let _ = writeln!(
        s,
        "scheme: warp {}, partition {}, k {}",
        value_name(&sch.warp),
        value_name(&sch.partition),
        sch.k
    );
    let _ = writeln!(
        s,
        "storage factor S̄ = {} (summed over {} partition{}, unit resolutions)",
        sig(total),
        parts.len(),
        if parts.len() == 1 { "" } else { "s" }
    );
    for (i, p) in parts.iter().enumerate() {
        let _ = writeln!(
            s,
            "\npartition {} of {}{}: depth [{}, {}], n′ = {}",
            i + 1,
            parts.len(),
            p.face
                .as_ref()
                .map_or_else(String::new, |f| format!(" ({f} face)")),
            sig(p.near),
            sig(p.far),
            sig_n_prime(p.n_prime)
        );
        let _ = writeln!(
            s,
            "  M_x = {}   M_z = {}   S̄ = {}",
            sig(p.max_mx),
            sig(p.max_mz),
            sig(p.storage_factor)
        );
        let _ = writeln!(
            s,
            "  matrix (eye space → light clip space, {}), by rows:",
            a.clip_depth.label()
        );
        let matrix = a.clip_depth.depth().convert(&p.matrix);
        let cells: Vec<Vec<String>> = (0..4)
            .map(|r| matrix.row(r).to_array().iter().map(|v| sig(*v)).collect())
            .collect();
        let width = cells
            .iter()
            .flatten()
            .map(|c| c.chars().count())
            .max()
            .unwrap_or(1);
        for row in cells {
            let padded: Vec<String> = row.iter().map(|c| format!("{c:>width$}")).collect();
            let _ = writeln!(s, "    [ {} ]", padded.join("  "));
        }
    }
    s
}

fn figures(a: &FiguresArgs) -> ExitCode {
    use shadow_aliasing::plot::{self, FIGURES};
    use std::io::IsTerminal;
    // An existing non-directory: say so (creating the directory would fail with "File exists").
    if std::fs::metadata(&a.out).is_ok_and(|m| !m.is_dir()) {
        return fail(format!(
            "out {} is not a directory but an existing file: give --out a directory (created \
             when missing)",
            a.out.display()
        ));
    }
    let format = match a.format {
        Format::Png => plot::Format::Png,
        Format::Svg => plot::Format::Svg,
        Format::Both => plot::Format::Both,
        Format::Pdf => plot::Format::Pdf,
    };
    // `--scale` is read signed, so that a negative one gets the range's message.
    let scale = match plot::scale(a.scale) {
        Ok(s) => s,
        Err(e) => return fail(e),
    };
    let column = match a.column {
        ColumnName::Double => plot::Column::Double,
        ColumnName::Single => plot::Column::Single,
    };
    let options = plot::Options {
        bare: a.bare,
        scale,
        dpi: a.dpi,
        column,
    };
    if let Err(e) = options.validate() {
        return fail(e.to_string());
    }
    let names: Vec<&str> = FIGURES
        .iter()
        .copied()
        .filter(|n| a.only.is_empty() || a.only.iter().any(|o| o == n))
        .collect();
    // One column: every figure asked for must have that layout, checked before anything is
    // written.
    if column == plot::Column::Single {
        let without: Vec<&str> = names
            .iter()
            .copied()
            .filter(|n| !plot::SINGLE_COLUMN.contains(n))
            .collect();
        if !without.is_empty() {
            return fail(format!(
                "--column single: {} {} no single-column layout; give --only with some of {}, \
                 or --column double",
                without.join(", "),
                if without.len() == 1 { "has" } else { "have" },
                plot::SINGLE_COLUMN.join(", ")
            ));
        }
    }
    let count = names.len();
    let bar = if std::io::stderr().is_terminal() {
        let bar = indicatif::ProgressBar::new(count as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {bar:30} {pos}/{len} {msg}",
        ) {
            bar.set_style(style);
        }
        bar.enable_steady_tick(std::time::Duration::from_millis(120));
        Some(bar)
    } else {
        None
    };
    let start = std::time::Instant::now();
    let mut result = Ok(Vec::new());
    for name in &names {
        if let Some(b) = &bar {
            b.set_message(*name);
        }
        match plot::render_with(name, &a.out, format, &options).map_err(|e| e.to_string()) {
            Ok(files) => {
                if let Ok(all) = &mut result {
                    all.extend(files);
                }
            }
            Err(e) => {
                result = Err(e);
                break;
            }
        }
        if let Some(b) = &bar {
            b.inc(1);
        }
    }
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    match result {
        Ok(files) => print(&format!(
            "wrote {} files ({} figure{}) to {} in {:.1} s\n",
            files.len(),
            count,
            if count == 1 { "" } else { "s" },
            a.out.display(),
            start.elapsed().as_secs_f64()
        )),
        Err(e) => fail(e),
    }
}

fn sweep(a: &SweepArgs) -> ExitCode {
    use shadow_aliasing::scheme::sweep::sweep;
    use std::io::IsTerminal;
    let sink = Sink::from_arg(a.output.as_deref());
    if a.format == SweepFormat::Npy
        && matches!(sink, Sink::Stdout)
        && std::io::stdout().is_terminal()
    {
        return fail(
            "--format npy writes binary data: give --output FILE, or redirect standard output",
        );
    }
    let c = &a.camera;
    let view = match ViewFrustum::new(c.near, c.far, c.half_fov) {
        Ok(v) => v,
        Err(e) => return fail(e),
    };
    let grid = match count("elevations", a.elevations)
        .and_then(|e| Ok((e, count("azimuths", a.azimuths)?)))
        .and_then(|(e, az)| SweepGrid::new(e, az))
    {
        Ok(g) => g,
        Err(e) => return fail(e),
    };
    let (r, k) =
        match rule(&view, Lights::Sweep(grid), &a.scheme).and_then(|r| Ok((r, k(&a.scheme)?))) {
            Ok(rk) => rk,
            Err(e) => return fail(e),
        };
    let part = match partition(&a.scheme) {
        Ok(p) => p,
        Err(e) => return fail(e),
    };
    let run = || sweep(&view, r, part, k, grid);
    // `--threads` is in [1, MAX_THREADS] (args::parse_threads).
    let result = match a.threads {
        None => run(),
        Some(t) => match rayon::ThreadPoolBuilder::new().num_threads(t).build() {
            Ok(pool) => pool.install(run),
            Err(e) => return fail(format!("threads: cannot start {t} threads: {e}")),
        },
    };
    let s = match result {
        Ok(s) => s,
        Err(e) => return fail(e),
    };
    write_sweep(a, &sink, grid, &s.storage_factor)
}

/// Writes a sweep's result in `--format` to `--output`; with `--output FILE --format npy`, the
/// axes beside it when FILE is (or will be) a regular file, all or nothing
/// ([`sweep_out::write_output`]).
fn write_sweep(a: &SweepArgs, sink: &Sink, grid: SweepGrid, values: &[f64]) -> ExitCode {
    let shape = [grid.elevations(), grid.azimuths()];
    let el: Vec<f64> = (0..grid.elevations()).map(|i| grid.elevation(i)).collect();
    let az: Vec<f64> = (0..grid.azimuths()).map(|j| grid.azimuth(j)).collect();
    let csv = |w: &mut dyn Write| sweep_out::write_csv(w, grid, values);
    let npy = |w: &mut dyn Write| sweep_out::write_npy(w, &shape, values);
    let el_npy = |w: &mut dyn Write| sweep_out::write_npy(w, &[el.len()], &el);
    let az_npy = |w: &mut dyn Write| sweep_out::write_npy(w, &[az.len()], &az);
    let done = match (a.format, sink) {
        (SweepFormat::Csv, _) => sweep_out::write_output(sink, &csv, &[]),
        (SweepFormat::Npy, Sink::File(path)) => {
            let (el_path, az_path) = sweep_out::axis_paths(path);
            sweep_out::write_output(sink, &npy, &[(el_path, &el_npy), (az_path, &az_npy)])
        }
        (SweepFormat::Npy, Sink::Stdout) => sweep_out::write_output(sink, &npy, &[]),
    };
    match done {
        Ok(()) => ExitCode::SUCCESS,
        Err(WriteError(message)) => fail(message),
    }
}
