//! `shadow-aliasing sweep`: the real binary. The CSV's grid is checked against the documented
//! spacing, and its values at the zenith and straight behind against Lloyd 2006's closed forms
//! evaluated here by hand (Eq 12 and Eq 20).
#![cfg(feature = "cli")]

use std::f64::consts::{FRAC_PI_2, PI, TAU};
use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_shadow-aliasing"))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code().expect("exited normally"),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// Runs a sweep with n = 1, f = 100, θ = 0.5 and returns the rows.
fn sweep(extra: &[&str]) -> Vec<(f64, f64, f64)> {
    let mut args = vec!["sweep", "--near", "1", "--far", "100", "--half-fov", "0.5"];
    args.extend_from_slice(extra);
    let (code, out, err) = run(&args);
    assert_eq!(code, 0, "{args:?}: {err}");
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

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
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
        [
            "sweep",
            "--near",
            "1",
            "--far",
            "1000",
            "--half-fov",
            "0.5236",
            "--warp",
            "lispsm-sin",
            "--elevations",
            "9",
            "--azimuths",
            "36",
            "--threads",
            t,
        ]
    };
    let (c1, one, _) = run(&args("1"));
    let (c2, two, _) = run(&args("2"));
    assert_eq!((c1, c2), (0, 0));
    assert_eq!(one.lines().count(), 1 + 9 * 36);
    assert_eq!(one, two);
}

#[test]
fn bad_arguments_are_one_line_and_a_non_zero_exit() {
    let base = ["sweep", "--near", "1", "--far", "100", "--half-fov", "0.5"];
    for (extra, needle) in [
        (vec!["--warp", "lispsm", "--threads", "0"], "threads"),
        (vec!["--warp", "lispsm", "--elevations", "0"], "elevations"),
        (vec!["--warp", "lispsm", "--azimuths", "0"], "azimuths"),
        (vec!["--warp", "lispsm", "--k", "99"], "k"),
        (vec!["--warp", "nope"], "--warp"),
    ] {
        let mut args: Vec<&str> = base.to_vec();
        args.extend(extra.iter());
        let (code, out, err) = run(&args);
        assert_ne!(code, 0, "{args:?}");
        assert!(out.is_empty(), "{args:?}: {out}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
    let (code, _, err) = run(&[
        "sweep",
        "--near",
        "2",
        "--far",
        "1",
        "--half-fov",
        "0.5",
        "--warp",
        "uniform",
    ]);
    assert_ne!(code, 0);
    assert_eq!(
        err.trim(),
        "error: far must be greater than near (got near=2, far=1)"
    );
}

#[test]
fn help_has_an_example_and_the_grid() {
    let (code, out, _) = run(&["sweep", "--help"]);
    assert_eq!(code, 0);
    assert!(out.contains("shadow-aliasing sweep --near"), "{out}");
    assert!(out.contains("elevation,azimuth,storage_factor"), "{out}");
}
