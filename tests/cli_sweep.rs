//! `shadow-aliasing sweep`: the real binary. The CSV's grid is checked against the documented
//! spacing, and its values at the zenith and straight behind against Lloyd 2006's closed forms
//! evaluated here by hand (Eq 12 and Eq 20).
#![cfg(feature = "cli")]

use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::path::Path;
use std::process::Command;

mod common;
use common::cli::{
    assert_error, assert_infinite_view_refused, assert_lambda_refused, help, run, run_bytes,
    run_failing, set, view_args, warp_json,
};
use common::close;

/// `sweep --near 1 --far 100 --half-fov 0.5` followed by `extra`.
fn sweep_args<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    view_args("sweep", "0.5", extra)
}

/// Runs a sweep with n = 1, f = 100, θ = 0.5 and returns the rows.
fn sweep(extra: &[&str]) -> Vec<(f64, f64, f64)> {
    let args = sweep_args(extra);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{args:?}: {err}");
    csv_rows(&out)
}

/// The rows of a sweep's CSV, after its header line (which must be the documented one).
fn csv_rows(out: &str) -> Vec<(f64, f64, f64)> {
    let mut lines = out.lines();
    assert_eq!(lines.next(), Some("elevation,azimuth,storage_factor"));
    lines
        .map(|l| {
            let f: Vec<f64> = l
                .split(',')
                .map(|x| x.parse().unwrap_or_else(|_| panic!("{l}")))
                .collect();
            assert_eq!(f.len(), 3, "{l}");
            (f[0], f[1], f[2])
        })
        .collect()
}

#[test]
fn grid_rows_and_columns_are_as_documented() {
    let rows = sweep(&["--warp", "uniform", "--elevations", "3", "--azimuths", "4"]);
    assert_eq!(rows.len(), 12);
    // Elevation major; elevations i·(π/2)/(E − 1) with both ends; azimuths j·2π/4.
    let els = [0.0, FRAC_PI_2 / 2.0, FRAC_PI_2];
    let azs = [0.0, TAU / 4.0, PI, 3.0 * TAU / 4.0];
    for (n, (el, az, s)) in rows.iter().enumerate() {
        assert_eq!(*el, els[n / 4], "row {n}");
        assert_eq!(*az, azs[n % 4], "row {n}");
        assert!(s.is_finite() && *s > 0.0, "row {n}");
    }
}

#[test]
fn zenith_and_behind_match_lloyd_2006() {
    let (alpha, t) = (100.0f64, 0.5f64.tan());
    let rows = sweep(&["--warp", "uniform", "--elevations", "5", "--azimuths", "8"]);
    // Behind (elevation 0, azimuth 0: light travels along the view direction): S̄ = (f/n)².
    assert!(close(rows[0].2, alpha * alpha, 1e-9), "{:?}", rows[0]);
    // Overhead, unwarped (n′ = ∞): S̄ = (α − 1)/(2 tan θ) · α (Eq 12, second regime's limit),
    // the same at every azimuth.
    let want = (alpha - 1.0) / (2.0 * t) * alpha;
    for r in &rows[32..] {
        assert_eq!(r.0, FRAC_PI_2);
        assert!(close(r.2, want, 1e-9), "{r:?} want {want}");
    }
    // With LiSPSM overhead: (α − 1)/(2 tan θ).
    let rows = sweep(&["--warp", "lispsm", "--elevations", "2", "--azimuths", "3"]);
    for r in &rows[3..] {
        assert!(close(r.2, 99.0 / (2.0 * t), 1e-9), "{r:?}");
    }
    // Self-similar z-partitions, light behind: k (f/n)^{2/k} = 2 · 100 (Eq 20).
    let rows = sweep(&[
        "--warp",
        "uniform",
        "--partition",
        "log",
        "--k",
        "2",
        "--elevations",
        "2",
        "--azimuths",
        "2",
    ]);
    assert!(close(rows[0].2, 200.0, 1e-9), "{:?}", rows[0]);
}

#[test]
fn thread_count_does_not_change_a_byte() {
    let args = |t: &'static str| {
        let grid = [
            "--warp",
            "lispsm-sin",
            "--elevations",
            "9",
            "--azimuths",
            "36",
            "--threads",
            t,
        ];
        set(view_args("sweep", "0.5236", &grid), "--far", "1000")
    };
    let (c1, one, _) = run(&args("1"));
    let (c2, two, _) = run(&args("2"));
    assert_eq!((c1, c2), (0, 0));
    assert_eq!(one.lines().count(), 1 + 9 * 36);
    assert_eq!(one, two);
}

#[test]
fn bad_arguments_are_one_line_and_a_non_zero_exit() {
    for (extra, needle) in [
        (&["--warp", "lispsm", "--threads", "0"][..], "threads"),
        (&["--warp", "lispsm", "--elevations", "0"], "elevations"),
        (&["--warp", "lispsm", "--azimuths", "0"], "azimuths"),
        (&["--warp", "lispsm", "--k", "99"], "k"),
        (&["--warp", "nope"], "--warp"),
    ] {
        let args = sweep_args(extra);
        let (_, err) = run_failing(&args, "");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    let args = set(sweep_args(&["--warp", "uniform"]), "--near", "2");
    let (code, _, err) = run(&set(args, "--far", "1"));
    assert_ne!(code, 0);
    assert_eq!(
        err.trim(),
        "error: far must be greater than near (got near=2, far=1)"
    );
}

#[test]
fn help_has_an_example_and_the_grid() {
    let out = help("sweep");
    assert!(out.contains("shadow-aliasing sweep --near"), "{out}");
    assert!(out.contains("elevation,azimuth,storage_factor"), "{out}");
    assert!(out.contains("--format npy --output sweep.npy"), "{out}");
}

/// Runs the binary, killing it (and failing) if it has not finished within `secs` seconds: a
/// hang is a failure, not a stuck test run.
fn run_within(args: &[&str], secs: u64) -> (i32, String, String) {
    use std::io::Read;
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_shadow-aliasing"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        if start.elapsed().as_secs() >= secs {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{args:?} did not finish within {secs} s");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    };
    let (mut out, mut err) = (String::new(), String::new());
    child
        .stdout
        .take()
        .unwrap()
        .read_to_string(&mut out)
        .unwrap();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    (status.code().expect("exited normally"), out, err)
}

#[test]
fn thread_counts_outside_1_to_1024_are_refused_with_exit_2() {
    let base = sweep_args(&[
        "--warp",
        "lispsm",
        "--elevations",
        "2",
        "--azimuths",
        "3",
        "--threads",
    ]);
    // 20000 used to panic in a worker and hang; u64::MAX used to hang.
    for t in ["20000", "18446744073709551615", "1025", "0", "-1"] {
        let mut args = base.to_vec();
        args.push(t);
        let (code, out, err) = run_within(&args, 60);
        assert_eq!(code, 2, "{t}: {err}");
        assert!(out.is_empty(), "{t}: {out}");
        assert_eq!(
            err,
            format!(
                "error: invalid value '{t}' for '--threads <T>': must lie in [1, 1024] (got {t}) (see --help)\n"
            )
        );
    }
    let mut args = base.to_vec();
    args.push("many");
    let (code, _, err) = run_within(&args, 60);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains("--threads") && err.contains("[1, 1024]"),
        "{err}"
    );
    // The bound itself is accepted, with the same bytes as one thread.
    let mut one = base.to_vec();
    one.push("1");
    let mut most = base.to_vec();
    most.push("1024");
    let (c1, o1, e1) = run_within(&one, 60);
    let (c2, o2, e2) = run_within(&most, 60);
    assert_eq!((c1, c2), (0, 0), "{e1} {e2}");
    assert_eq!(o1.lines().count(), 1 + 2 * 3);
    assert_eq!(o1, o2);
}

#[test]
fn tsm_default_focus_fits_the_adaptive_partitions_of_every_direction() {
    // Issue 11: every k ≥ 2 failed with "focus must be at most far − near", the default focus
    // having been taken from γ = 0 although γ = π/2 has the shallower first partition.
    let tsm = |k, elevations, azimuths| {
        sweep(&[
            "--warp",
            "tsm",
            "--partition",
            "adaptive",
            "--k",
            k,
            "--elevations",
            elevations,
            "--azimuths",
            azimuths,
        ])
    };
    for k in ["2", "3", "4"] {
        let rows = tsm(k, "3", "8");
        assert_eq!(rows.len(), 24, "k {k}");
        assert!(rows.iter().all(|r| r.2.is_finite() && r.2 > 0.0), "k {k}");
    }
    // Two directions, light behind (γ = 0) and overhead (γ = π/2), k = 2, α = 2 (Barroso Eq 19
    // by hand): γ = 0 gives planes 1, 100/2 = 50, 100 (depths 49 and 50), γ = π/2 the
    // self-similar 1, √100 = 10, 100 (depths 9 and 90). The shallowest is 9, so the focus is
    // 4.5 for the whole sweep, and each row is `warp --focus 4.5` at that direction.
    let rows = tsm("2", "2", "1");
    assert_eq!(rows.len(), 2);
    // The sweep's directions: −(cos el sin az, sin el, cos el cos az) at (0, 0) and (π/2, 0).
    let zenith = format!("-0,-1,{}", -FRAC_PI_2.cos());
    for (row, dir) in rows.iter().zip(["-0,-0,-1", zenith.as_str()]) {
        let v = warp_json(
            "0.5",
            dir,
            "tsm",
            &["--focus", "4.5", "--partition", "adaptive", "--k", "2"],
        );
        let want = v["storage_factor"].as_f64().unwrap();
        assert!(close(row.2, want, 1e-12), "{row:?} want {want} ({dir})");
    }
}

#[test]
fn negative_numbers_get_the_domain_error_not_unexpected_argument() {
    for (extra, want) in [
        (
            &["--warp", "lispsm", "--elevations", "-3"][..],
            "error: elevations must be at least 1 (got -3)",
        ),
        (
            &["--warp", "lispsm", "--azimuths", "-1"],
            "error: azimuths must be at least 1 (got -1)",
        ),
        (
            &["--warp", "lispsm", "--partition", "log", "--k", "-1"],
            "error: k must lie in [1, 16] (got -1)",
        ),
        (
            &["--warp", "lispsm", "--partition", "log", "--k", "0"],
            "error: k must lie in [1, 16] (got 0)",
        ),
        (
            &["--warp", "eta", "--eta", "-inf"],
            "error: eta must be a finite number (got -inf)",
        ),
        (
            &["--warp", "eta", "--eta", "-1.5"],
            "error: eta must lie in [-1, 1] (got -1.5)",
        ),
        (
            &["--warp", "tsm", "--focus", "-2"],
            "error: focus must be greater than 0 (got -2)",
        ),
        (
            &[
                "--warp",
                "lispsm",
                "--partition",
                "practical",
                "--k",
                "2",
                "--lambda",
                "-0.5",
            ],
            "error: lambda must lie in [0, 1] (got -0.5)",
        ),
    ] {
        assert_error(&sweep_args(extra), want);
    }
    assert_infinite_view_refused("sweep", &["--warp", "lispsm"]);
}

#[test]
fn lambda_only_with_practical_partitions() {
    let base = sweep_args(&["--warp", "lispsm", "--elevations", "2", "--azimuths", "3"]);
    assert_lambda_refused(
        &base,
        &[
            ("single", "1"),
            ("log", "2"),
            ("adaptive", "2"),
            ("faces", "2"),
        ],
    );
    // With practical: given, or its default 0.5.
    let mut given = base.to_vec();
    given.extend(["--partition", "practical", "--k", "2", "--lambda", "0.5"]);
    let mut default = base.to_vec();
    default.extend(["--partition", "practical", "--k", "2"]);
    let (c1, o1, _) = run(&given);
    let (c2, o2, _) = run(&default);
    assert_eq!((c1, c2), (0, 0));
    assert_eq!(o1, o2);
}

/// A fresh directory under the system's temporary directory.
fn temp_dir(tag: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("sa-cli-sweep-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Reads a `.npy` file as NumPy's format specification (version 1.0) lays it out, written here
/// from the specification and not from the binary's writer: the magic `\x93NUMPY`, version 1.0,
/// a little-endian u16 header length, an ASCII dict literal padded with spaces and ended by a
/// newline so that the data starts at a multiple of 64, then the raw data. Returns the shape
/// and the values (little-endian float64, C order).
fn read_npy(bytes: &[u8]) -> (Vec<usize>, Vec<f64>) {
    assert_eq!(&bytes[..6], b"\x93NUMPY", "magic");
    assert_eq!((bytes[6], bytes[7]), (1, 0), "version 1.0");
    let hlen = usize::from(u16::from_le_bytes([bytes[8], bytes[9]]));
    let start = 10 + hlen;
    assert_eq!(start % 64, 0, "data aligned to 64 bytes");
    let header = std::str::from_utf8(&bytes[10..start]).expect("ASCII header");
    assert!(header.ends_with('\n'), "{header:?}");
    let dict = header.trim_end_matches('\n').trim_end_matches(' ');
    assert!(dict.starts_with('{') && dict.ends_with('}'), "{dict:?}");
    // The three keys, each exactly once, in any order.
    let value_of = |key: &str| -> &str {
        let k = format!("'{key}':");
        assert_eq!(dict.matches(&k).count(), 1, "{key} in {dict}");
        let rest = dict.split_once(&k).unwrap().1.trim_start();
        let end = if rest.starts_with('(') {
            rest.find(')').unwrap() + 1
        } else {
            rest.find([',', '}']).unwrap()
        };
        rest[..end].trim()
    };
    assert_eq!(value_of("descr"), "'<f8'");
    assert_eq!(value_of("fortran_order"), "False");
    let shape_text = value_of("shape");
    let inner = shape_text
        .strip_prefix('(')
        .and_then(|s| s.strip_suffix(')'))
        .unwrap();
    let shape: Vec<usize> = inner
        .split(',')
        .map(str::trim)
        .filter(|s| !s.is_empty())
        .map(|s| s.parse().unwrap())
        .collect();
    if shape.len() == 1 {
        // Python's one-element tuple.
        assert!(inner.trim_end().ends_with(','), "{shape_text}");
    }
    let data = &bytes[start..];
    assert_eq!(
        data.len(),
        8 * shape.iter().product::<usize>(),
        "data length"
    );
    let values = data
        .chunks_exact(8)
        .map(|b| f64::from_le_bytes(b.try_into().unwrap()))
        .collect();
    (shape, values)
}

/// `sweep --near 1 --far 100 --half-fov 0.5 --warp lispsm --partition log --k 2` followed by
/// `extra`: the base of the output-format calls.
fn log_2(extra: &[&'static str]) -> Vec<&'static str> {
    let mut args = sweep_args(&["--warp", "lispsm", "--partition", "log", "--k", "2"]);
    args.extend_from_slice(extra);
    args
}

#[test]
fn npy_holds_the_csv_values_bit_for_bit_with_its_axes() {
    let dir = temp_dir("npy");
    let file = dir.join("s.npy");
    let csv_args = log_2(&["--elevations", "7", "--azimuths", "12"]);
    let rows = {
        let (code, out, err) = run(&csv_args);
        assert_eq!(code, 0, "{err}");
        csv_rows(&out)
    };
    assert_eq!(rows.len(), 7 * 12);
    let mut npy_args = csv_args.clone();
    npy_args.extend(["--format", "npy", "--output", file.to_str().unwrap()]);
    let (code, out, err) = run(&npy_args);
    assert_eq!((code, out.as_str(), err.as_str()), (0, "", ""));

    let (shape, values) = read_npy(&std::fs::read(&file).unwrap());
    assert_eq!(shape, [7, 12]);
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    let csv_sf: Vec<f64> = rows.iter().map(|r| r.2).collect();
    assert_eq!(
        bits(&values),
        bits(&csv_sf),
        "S̄, row-major (elevation, azimuth)"
    );

    let (el_shape, el) = read_npy(&std::fs::read(dir.join("s.elevations.npy")).unwrap());
    let (az_shape, az) = read_npy(&std::fs::read(dir.join("s.azimuths.npy")).unwrap());
    assert_eq!((el_shape, az_shape), (vec![7], vec![12]));
    let csv_el: Vec<f64> = rows.iter().step_by(12).map(|r| r.0).collect();
    let csv_az: Vec<f64> = rows[..12].iter().map(|r| r.1).collect();
    assert_eq!(bits(&el), bits(&csv_el));
    assert_eq!(bits(&az), bits(&csv_az));
    // The documented spacing: i·(π/2)/(E−1) and j·2π/A.
    assert_eq!((el[0], el[6]), (0.0, FRAC_PI_2));
    assert!(close(el[2], 2.0 * FRAC_PI_2 / 6.0, 1e-15));
    assert!(close(az[3], 3.0 * TAU / 12.0, 1e-15));
    // Every row's elevation is its row's: the CSV is elevation-major.
    for (n, r) in rows.iter().enumerate() {
        assert_eq!((r.0, r.1), (el[n / 12], az[n % 12]), "row {n}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn npy_to_standard_output_is_the_file_without_axes() {
    let dir = temp_dir("npy-stdout");
    let file = dir.join("s.npy");
    let mut args = log_2(&["--elevations", "3", "--azimuths", "5", "--format", "npy"]);
    let (code, stdout, err) = run_bytes(&args);
    assert_eq!(code, 0, "{err}");
    let (shape, values) = read_npy(&stdout);
    assert_eq!(shape, [3, 5]);
    assert!(values.iter().all(|v| v.is_finite() && *v > 0.0));
    args.extend(["--output", file.to_str().unwrap()]);
    assert_eq!(run_bytes(&args).0, 0);
    assert_eq!(std::fs::read(&file).unwrap(), stdout);
    // "-" is standard output, and writes no axes.
    let n = args.len();
    args[n - 1] = "-";
    let (code, dash, _) = run_bytes(&args);
    assert_eq!((code, dash), (0, stdout));
    assert!(!Path::new("-.elevations.npy").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn output_writes_the_csv_to_a_file() {
    let dir = temp_dir("csv");
    let file = dir.join("s.csv");
    let args = log_2(&["--elevations", "4", "--azimuths", "9"]);
    let (code, stdout, _) = run_bytes(&args);
    assert_eq!(code, 0);
    assert_eq!(stdout.iter().filter(|&&b| b == b'\n').count(), 1 + 4 * 9);
    let mut explicit = args.clone();
    explicit.extend(["--format", "csv", "--output", file.to_str().unwrap()]);
    let (code, out, err) = run_bytes(&explicit);
    assert_eq!((code, out.as_slice(), err.as_str()), (0, &b""[..], ""));
    assert_eq!(std::fs::read(&file).unwrap(), stdout);
    // Only npy has axis files.
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1);
    let _ = std::fs::remove_dir_all(&dir);
}

#[cfg(target_os = "linux")]
#[test]
fn write_errors_exit_1_with_a_message() {
    use common::cli::run_to_full;
    let dir = temp_dir("errors");
    let grid = log_2(&["--elevations", "3", "--azimuths", "4"]);
    let full = "No space left on device (os error 28)";
    for format in ["csv", "npy"] {
        // A file that cannot take the data.
        let mut args = grid.clone();
        args.extend(["--format", format, "--output", "/dev/full"]);
        let (code, out, err) = run(&args);
        assert_eq!(
            (code, out.as_str(), err.as_str()),
            (
                1,
                "",
                format!("error: cannot write /dev/full: {full}\n").as_str()
            ),
            "{format}"
        );
        // A file that cannot be created.
        let missing = dir.join("no-such-dir").join("s.out");
        let mut args = grid.clone();
        args.extend(["--format", format, "--output", missing.to_str().unwrap()]);
        let (code, _, err) = run(&args);
        assert_eq!(
            (code, err),
            (
                1,
                format!(
                    "error: cannot write {}: No such file or directory (os error 2)\n",
                    missing.display()
                )
            ),
            "{format}"
        );
        // Standard output that fails.
        let mut args = grid.clone();
        args.extend(["--format", format]);
        let (code, err) = run_to_full(&args, "");
        assert_eq!(code, 1, "{format}");
        assert_eq!(
            err,
            format!("error: cannot write to standard output: {full}\n")
        );
    }
    // An axis file that cannot be written (a directory of its name) is named.
    let file = dir.join("s.npy");
    let blocked = dir.join("s.azimuths.npy");
    std::fs::create_dir_all(&blocked).unwrap();
    let mut args = grid.clone();
    args.extend(["--format", "npy", "--output", file.to_str().unwrap()]);
    let (code, _, err) = run(&args);
    assert_eq!(code, 1);
    assert!(
        err.starts_with(&format!("error: cannot write {}: ", blocked.display()))
            && err.ends_with("(os error 21)\n"),
        "{err}"
    );
    // Issue 21 item 6: nothing is left behind, neither the main file (it used to be) nor the
    // other axis nor a temporary: the directory holds the blocking directory alone.
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["s.azimuths.npy"], "{left:?}");
    // The same with the elevations blocked (renamed first) and an older main file: it is kept.
    std::fs::remove_dir(&blocked).unwrap();
    std::fs::create_dir(dir.join("s.elevations.npy")).unwrap();
    std::fs::write(&file, b"older").unwrap();
    assert_eq!(run(&args).0, 1);
    let mut left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    left.sort();
    assert_eq!(left, ["s.elevations.npy", "s.npy"], "{left:?}");
    assert_eq!(std::fs::read(&file).unwrap(), b"older");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The base of the `--output` calls of a 3 × 4 npy sweep, `--output` last, its value to add.
fn npy_3_by_4() -> Vec<&'static str> {
    log_2(&[
        "--elevations",
        "3",
        "--azimuths",
        "4",
        "--format",
        "npy",
        "--output",
    ])
}

/// Issue 21 item 6: the axes go only beside a regular file. `--output` on a device (here a
/// link to /dev/null, and /dev/null itself) writes the array into it and no `NAME.elevations.npy`
/// beside it (it used to create `/dev/null.elevations.npy`); a link to a regular file is
/// written through, with the axes beside the link.
#[cfg(target_os = "linux")]
#[test]
fn npy_axes_only_beside_a_regular_file() {
    let dir = temp_dir("devnull");
    let link = dir.join("null.npy");
    std::os::unix::fs::symlink("/dev/null", &link).unwrap();
    for out in [link.to_str().unwrap(), "/dev/null"] {
        let mut args: Vec<&str> = npy_3_by_4();
        args.push(out);
        let (code, stdout, err) = run(&args);
        assert_eq!((code, stdout.as_str(), err.as_str()), (0, "", ""), "{out}");
    }
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["null.npy"], "{left:?}");
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    // A link to a regular file: the file gets the array, the link stays a link.
    let target = dir.join("target.npy");
    std::fs::write(&target, b"").unwrap();
    let to_file = dir.join("via.npy");
    std::os::unix::fs::symlink(&target, &to_file).unwrap();
    let mut args: Vec<&str> = npy_3_by_4();
    args.push(to_file.to_str().unwrap());
    assert_eq!(run(&args).0, 0);
    assert!(std::fs::symlink_metadata(&to_file)
        .unwrap()
        .file_type()
        .is_symlink());
    assert_eq!(read_npy(&std::fs::read(&target).unwrap()).0, [3, 4]);
    assert_eq!(
        read_npy(&std::fs::read(dir.join("via.elevations.npy")).unwrap()).0,
        [3]
    );
    assert_eq!(
        read_npy(&std::fs::read(dir.join("via.azimuths.npy")).unwrap()).0,
        [4]
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 21 item 5: `--ratio` is Barroso & Celes' α (it was fixed at 2, and the advice "lower
/// the ratio or k" named no flag). A direction without planes fails the sweep, naming that
/// direction once (it was "degenerate geometry: … no solution: …"), with nothing on stdout;
/// with the advice followed every direction has a finite value.
#[test]
fn adaptive_ratio_and_a_direction_without_planes() {
    let base = ["--warp", "lispsm", "--partition", "adaptive", "--k", "8"];
    let grid = ["--elevations", "5", "--azimuths", "8"];
    let args = sweep_args(&[&base[..], &grid].concat());
    let (code, err) = run_failing(&args, "");
    assert_eq!(code, 1);
    // Elevation 0, azimuth 0: the light along the view (γ = 0), where z₁ = 100/2⁷ = 0.78125.
    assert!(
        err.starts_with(
            "error: no solution: at elevation=0, azimuth=0 (row 0, column 0 of the sweep): \
             adaptive z-partitioning (Barroso & Celes Eq 19) with ratio=2, light_angle=0, k=8 \
             puts plane 1 at 0.78125"
        ) && err.ends_with(": lower the ratio or k\n"),
        "{err}"
    );
    assert!(!err.contains("degenerate"), "{err}");
    let mut args = sweep_args(&[&base[..], &grid, &["--ratio", "1.5"]].concat());
    let rows = {
        let (code, out, err) = run(&args);
        assert_eq!(code, 0, "{err}");
        csv_rows(&out)
    };
    assert_eq!(rows.len(), 40);
    assert!(rows.iter().all(|r| r.2.is_finite() && r.2 > 0.0));
    // Each value is `warp --ratio 1.5` at its direction: behind, the planes of α = 1.5.
    let v = warp_json(
        "0.5",
        "-0,-0,-1",
        "lispsm",
        &["--partition", "adaptive", "--k", "8", "--ratio", "1.5"],
    );
    assert!(close(
        rows[0].2,
        v["storage_factor"].as_f64().unwrap(),
        1e-12
    ));
    // Out of its domain, or with another partition: refused by name before the sweep.
    args = set(args, "--ratio", "0.5");
    assert_error(&args, "error: ratio must be greater than 1 (got 0.5)");
    common::cli::assert_parameter_refused(
        &sweep_args(&["--warp", "lispsm", "--elevations", "2", "--azimuths", "3"]),
        ("ratio", "3", "adaptive"),
        &[
            ("single", "1"),
            ("log", "2"),
            ("practical", "2"),
            ("faces", "2"),
        ],
    );
    assert!(help("sweep").contains("--ratio"));
}

/// `--format npy` to a terminal is refused before the sweep runs. The terminal is a
/// pseudo-terminal made by util-linux's `script` (Debian's essential bsdutils).
#[cfg(target_os = "linux")]
#[test]
fn npy_to_a_terminal_is_refused() {
    let bin = env!("CARGO_BIN_EXE_shadow-aliasing");
    let cmd = format!(
        "{bin} {} --format npy; echo \"status $?\"",
        log_2(&[]).join(" ")
    );
    let out = Command::new("script")
        .args(["-qec", &cmd, "/dev/null"])
        .output()
        .expect("script (util-linux) runs");
    let text = String::from_utf8_lossy(&out.stdout).replace('\r', "");
    assert!(
        text.contains(
            "error: --format npy writes binary data: give --output FILE, or redirect standard output\n"
        ) && text.contains("status 1"),
        "{text:?}"
    );
    assert!(!text.contains("NUMPY"), "{text:?}");
}
