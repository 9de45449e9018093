//! `shadow-aliasing warp`: the real binary. Expected storage factors are Lloyd 2006's closed forms
//! evaluated here by hand (Eq 12, 18, 20); the matrices are checked by what they do to the view
//! frustum's corners.
#![cfg(feature = "cli")]

use serde_json::Value;

mod common;
use common::cli::{
    assert_error, assert_infinite_view_refused, assert_lambda_refused, assert_parameter_refused,
    help, run, run_failing, set, warp_args,
};
use common::close;

#[allow(clippy::approx_constant)] // the command line's 0.5236 of issue 3, not π/6
const HALF_FOV: f64 = 0.5236;

/// Two logarithmic partitions; with the light straight down and LiSPSM, docs/cli.md's example.
const LOG_2: [&str; 4] = ["--partition", "log", "--k", "2"];

/// `warp --json` at issue 3's view (n = 1, f = 100, θ = 0.5236), the light along `dir`, the
/// warp `warp`, then `extra`: exit 0, nothing on stderr, the output parsed.
fn warp_json(dir: &str, warp: &str, extra: &[&str]) -> Value {
    common::cli::warp_json("0.5236", dir, warp, extra)
}

/// `warp` at n = 1, f = 100, θ = 0.5 with the light straight down and the warp `warp`, then
/// `extra`: the base of the refused calls.
fn overhead<'a>(warp: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    warp_args("0.5", "0,-1,0", warp, extra)
}

fn num(v: &Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is a number"))
}

/// The eight corners of the view frustum of depth range [n, f], eye space.
fn corners(n: f64, f: f64) -> Vec<[f64; 3]> {
    let t = HALF_FOV.tan();
    let mut out = Vec::new();
    for d in [n, f] {
        for (sx, sy) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            out.push([sx * d * t, sy * d * t, -d]);
        }
    }
    out
}

/// Column-major 4×4 times (p, 1), divided by w; w must be positive.
fn project(m: &[f64], p: [f64; 3]) -> [f64; 3] {
    let h: Vec<f64> = (0..4)
        .map(|r| m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r])
        .collect();
    assert!(h[3] > 0.0, "w = {} at {p:?}", h[3]);
    [h[0] / h[3], h[1] / h[3], h[2] / h[3]]
}

/// Checks the JSON shape of issue 3 and that each z-partition's matrix maps its sub-frustum's
/// corners into the clip volume [−1, 1]³ (a face partition covers only part of its depth range,
/// so its corners are not checked); returns the partitions.
fn check_shape(v: &Value) -> Vec<Value> {
    check_shape_with(v, true)
}

fn check_shape_with(v: &Value, corners_inside: bool) -> Vec<Value> {
    let parts = v["partitions"]
        .as_array()
        .expect("partitions array")
        .clone();
    assert!(!parts.is_empty());
    let mut sum = 0.0;
    for p in &parts {
        let m: Vec<f64> = p["matrix"]
            .as_array()
            .expect("matrix array")
            .iter()
            .map(num)
            .collect();
        assert_eq!(m.len(), 16);
        let (n, f) = (num(&p["near"]), num(&p["far"]));
        assert!(n > 0.0 && f >= n);
        let (mx, mz, s) = (
            num(&p["max_mx"]),
            num(&p["max_mz"]),
            num(&p["storage_factor"]),
        );
        assert!(close(mx * mz, s, 1e-12), "{p}");
        sum += s;
        for c in corners(n, f).into_iter().filter(|_| corners_inside) {
            for x in project(&m, c) {
                assert!((-1.0 - 1e-9..=1.0 + 1e-9).contains(&x), "{c:?} → {x}: {p}");
            }
        }
    }
    assert!(close(num(&v["storage_factor"]), sum, 1e-12));
    parts
}

#[test]
fn lispsm_light_overhead_is_lloyd_2006_eq_12() {
    let v = warp_json("0,-1,0", "lispsm", &[]);
    let parts = check_shape(&v);
    assert_eq!(parts.len(), 1);
    assert_eq!(
        (num(&parts[0]["near"]), num(&parts[0]["far"])),
        (1.0, 100.0)
    );
    // n′ ≤ n′_LSPSM: S̄ = (f/n − 1)/(2 tan θ).
    let want = 99.0 / (2.0 * HALF_FOV.tan());
    assert!(close(num(&v["storage_factor"]), want, 1e-9), "{v}");
    // LiSPSM makes M_z equal on the near and far planes; M_x = m_x(n) = f/(n′ + f − n) · (n′/n)
    // with n′ = 11: 100 · 11 / 110 = 10.
    assert!(close(num(&parts[0]["max_mx"]), 10.0, 1e-9), "{v}");
    assert_eq!(parts[0]["n_prime"], 11.0);
}

#[test]
fn log_partitions_with_lispsm_are_lloyd_2006_eq_18() {
    let v = warp_json("0,-1,0", "lispsm", &["--partition", "log", "--k", "4"]);
    let parts = check_shape(&v);
    assert_eq!(parts.len(), 4);
    // Planes n (f/n)^{i/k}: 1, √10, 10, 10√10, 100.
    let planes = [1.0, 10f64.sqrt(), 10.0, 1000f64.sqrt(), 100.0];
    for (i, p) in parts.iter().enumerate() {
        assert!(close(num(&p["near"]), planes[i], 1e-12), "{p}");
        assert!(close(num(&p["far"]), planes[i + 1], 1e-12), "{p}");
    }
    // S̄_ZP+W = k ((f/n)^{1/k} − 1)/(2 tan θ).
    let want = 4.0 * (10f64.sqrt() - 1.0) / (2.0 * HALF_FOV.tan());
    assert!(close(num(&v["storage_factor"]), want, 1e-9), "{v}");
}

#[test]
fn uniform_map_with_the_light_behind_is_lloyd_2006_eq_20() {
    // Light travelling along the view direction: S̄ = (f/n)² (Eq 20 with k = 1).
    let v = warp_json("0,0,-1", "uniform", &[]);
    check_shape(&v);
    assert!(close(num(&v["storage_factor"]), 1e4, 1e-9), "{v}");
    assert_eq!(v["partitions"][0]["n_prime"], "inf");
    // And with self-similar z-partitions: k (f/n)^{2/k} = 2 · 100 at k = 2.
    let v = warp_json("0,0,-1", "uniform", &LOG_2);
    check_shape(&v);
    assert!(close(num(&v["storage_factor"]), 200.0, 1e-9), "{v}");
}

#[test]
fn face_partitions_are_lloyd_2006_eq_19_and_21() {
    // Overhead the light sees one face: S̄ = k ((f/n)^{1/k} − 1)/(2 tan θ) (Eq 19) = 2·9/(2 tan θ).
    let faces_2 = ["--partition", "faces", "--k", "2"];
    let v = warp_json("0,-1,0", "lispsm", &faces_2);
    check_shape_with(&v, false);
    assert!(
        close(num(&v["storage_factor"]), 9.0 / HALF_FOV.tan(), 1e-9),
        "{v}"
    );
    // Behind: four side faces of k maps each and the near face, 4 k (a − 1)/2 + 1 = 37 (Eq 21).
    let v = warp_json("0,0,-1", "lispsm", &faces_2);
    let parts = check_shape_with(&v, false);
    assert_eq!(parts.len(), 9);
    assert!(close(num(&v["storage_factor"]), 37.0, 1e-9), "{v}");
    let faces: Vec<&str> = parts.iter().map(|p| p["face"].as_str().unwrap()).collect();
    for f in ["bottom", "right", "top", "left"] {
        assert_eq!(faces.iter().filter(|x| **x == f).count(), 2, "{faces:?}");
    }
    assert_eq!(
        faces.iter().filter(|x| **x == "near").count(),
        1,
        "{faces:?}"
    );
}

#[test]
fn every_warp_and_partition_gives_finite_matrices_for_a_tilted_light() {
    let warps = [
        "uniform",
        "psm",
        "lispsm",
        "lispsm-sin",
        "barroso",
        "barroso-zhang",
        "minimax",
        "minimax-mz",
        "tsm",
        "lispsm-reference",
        "filament",
        "ogre",
    ];
    for w in warps {
        for (part, k) in [("single", "1"), ("practical", "3"), ("faces", "2")] {
            let v = warp_json("0.3,-0.8,-0.4", w, &["--partition", part, "--k", k]);
            let parts = check_shape_with(&v, part != "faces");
            assert!(num(&v["storage_factor"]) > 0.0, "{w} {part}: {v}");
            if part == "practical" {
                assert_eq!(parts.len(), 3, "{w}");
            }
        }
    }
    let v = warp_json("0,-1,0", "eta", &["--eta", "-1"]);
    assert_eq!(v["partitions"][0]["n_prime"], "inf");
}

#[test]
fn text_output_is_readable() {
    let (code, out, err) = run(&warp_args("0.5236", "0,-1,0", "lispsm", &LOG_2));
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("storage factor"), "{out}");
    assert!(out.contains("partition 1 of 2"), "{out}");
    assert!(out.contains("partition 2 of 2"), "{out}");
    assert!(out.contains("M_x"), "{out}");
    // The four rows of each matrix.
    assert!(out.matches('[').count() >= 8, "{out}");
}

#[test]
fn bad_arguments_are_one_line_and_a_non_zero_exit() {
    for (args, needle) in [
        (set(overhead("lispsm", &[]), "--near", "-1"), "near"),
        (warp_args("0.5", "0,0,0", "lispsm", &[]), "light_dir"),
        (warp_args("0.5", "0,-1", "lispsm", &[]), "--light-dir"),
        (overhead("lsm", &[]), "--warp"),
        (overhead("lispsm", &["--k", "0"]), "k"),
        (overhead("eta", &[]), "--eta"),
        (overhead("eta", &["--eta", "2"]), "eta"),
    ] {
        let (_, err) = run_failing(&args, "");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}

#[test]
fn help_has_an_example() {
    let out = help("warp");
    assert!(out.contains("Example"), "{out}");
    assert!(out.contains("shadow-aliasing warp --near"), "{out}");
}

/// docs/cli.md shows what the binary prints: the text example exactly, the JSON example to a
/// relative 1e-12 per number.
#[test]
fn docs_show_the_binarys_output() {
    let md = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/cli.md")).unwrap();
    let block = |fence: &str| -> String {
        let start = md.find(fence).expect("fenced block") + fence.len();
        md[start..].split("```").next().unwrap().to_string()
    };
    let text = block("```text\n");
    let (first, shown) = text.split_once('\n').unwrap();
    let args: Vec<&str> = first
        .trim_start_matches("$ shadow-aliasing ")
        .split(' ')
        .collect();
    let (code, out, _) = run(&args);
    assert_eq!(code, 0);
    assert_eq!(shown, out, "docs/cli.md's text example is stale");
    let shown: Value = serde_json::from_str(&block("```json\n")).unwrap();
    let now = warp_json("0,-1,0", "lispsm", &LOG_2);
    fn same(a: &Value, b: &Value) -> bool {
        match (a, b) {
            (Value::Number(x), Value::Number(y)) => {
                let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
                (x - y).abs() <= 1e-12 * x.abs().max(y.abs())
            }
            (Value::Array(x), Value::Array(y)) => {
                x.len() == y.len() && x.iter().zip(y).all(|(p, q)| same(p, q))
            }
            (Value::Object(x), Value::Object(y)) => {
                x.len() == y.len() && x.iter().all(|(k, v)| y.get(k).is_some_and(|w| same(v, w)))
            }
            _ => a == b,
        }
    }
    assert!(
        same(&shown, &now),
        "docs/cli.md's JSON example is stale:\n{now}"
    );
}

#[test]
fn lambda_is_refused_unless_the_partition_is_practical() {
    // It used to be ignored silently: `--lambda 0.3` printed the single map's S̄.
    assert_lambda_refused(
        &overhead("lispsm", &[]),
        &[
            ("single", "1"),
            ("uniform", "2"),
            ("log", "2"),
            ("adaptive", "2"),
            ("faces", "2"),
        ],
    );
    // Practical: λ = 0 is the uniform partition, λ = 1 the logarithmic one, absent is 0.5.
    let sf = |extra: &[&str]| {
        num(&warp_json("0,-1,0", "lispsm", &[&["--k", "2"], extra].concat())["storage_factor"])
    };
    assert_eq!(
        sf(&["--partition", "practical", "--lambda", "0"]),
        sf(&["--partition", "uniform"])
    );
    assert!(close(
        sf(&["--partition", "practical", "--lambda", "1"]),
        sf(&["--partition", "log"]),
        1e-12
    ));
    assert_eq!(
        sf(&["--partition", "practical"]),
        sf(&["--partition", "practical", "--lambda", "0.5"])
    );
}

/// Issue 21 item 5: `--ratio` is Barroso & Celes' α of `adaptive` partitions (it was fixed at
/// 2). With the light along the view (γ = 0), Eq 19 is z_{i−1} = z_i/α from z_k = f: α = 4,
/// k = 3 over [1, 100] gives 1, 6.25, 25, 100 (by hand), the default α = 2 gives 1, 25, 50, 100.
#[test]
fn ratio_sets_the_adaptive_planes() {
    let ranges = |extra: &[&str]| -> Vec<(f64, f64)> {
        let args = [&["--partition", "adaptive", "--k", "3"][..], extra].concat();
        warp_json("0,0,-1", "lispsm", &args)["partitions"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| (num(&p["near"]), num(&p["far"])))
            .collect()
    };
    for (extra, planes) in [
        (&["--ratio", "4"][..], [1.0, 6.25, 25.0, 100.0]),
        (&[], [1.0, 25.0, 50.0, 100.0]),
        (&["--ratio", "2"], [1.0, 25.0, 50.0, 100.0]),
    ] {
        let got = ranges(extra);
        assert_eq!(got.len(), 3, "{extra:?}");
        for (i, (a, b)) in got.iter().enumerate() {
            assert!(
                close(*a, planes[i], 1e-12) && close(*b, planes[i + 1], 1e-12),
                "{extra:?}: {got:?}"
            );
        }
    }
    // α = 2 with k = 8 has no planes at γ = 0 (2⁷ = 128 > f/n = 100): the message's advice
    // names the flag that now exists, and following it works.
    let mut args = overhead("lispsm", &["--partition", "adaptive", "--k", "8"]);
    args = set(args, "--light-dir", "0,0,-1");
    let (code, err) = run_failing(&args, "");
    assert_eq!(code, 1);
    assert!(
        err.starts_with(
            "error: no solution: adaptive z-partitioning (Barroso & Celes Eq 19) with ratio=2"
        ) && err.ends_with(": lower the ratio or k\n"),
        "{err}"
    );
    args.extend(["--ratio", "1.5"]);
    let (code, _, err) = run(&args);
    assert_eq!(code, 0, "{err}");
    // Out of its domain, or with another partition: refused by name.
    for (value, want) in [
        ("1", "error: ratio must be greater than 1 (got 1)"),
        ("-2", "error: ratio must be greater than 0 (got -2)"),
        ("inf", "error: ratio must be a finite number (got inf)"),
    ] {
        let args = overhead(
            "lispsm",
            &["--partition", "adaptive", "--k", "2", "--ratio", value],
        );
        assert_error(&args, want);
    }
    assert_parameter_refused(
        &overhead("lispsm", &[]),
        ("ratio", "1.5", "adaptive"),
        &[
            ("single", "1"),
            ("log", "2"),
            ("practical", "2"),
            ("faces", "2"),
        ],
    );
    assert!(help("warp").contains("--ratio"));
}

#[test]
fn negative_values_reach_the_domain_checks() {
    for (args, want) in [
        (
            overhead("eta", &["--eta", "-inf"]),
            "error: eta must be a finite number (got -inf)",
        ),
        (
            overhead("eta", &["--eta", "-2"]),
            "error: eta must lie in [-1, 1] (got -2)",
        ),
        (
            overhead("lispsm", &["--partition", "log", "--k", "-1"]),
            "error: k must lie in [1, 16] (got -1)",
        ),
        (
            overhead("tsm", &["--focus", "-2"]),
            "error: focus must be greater than 0 (got -2)",
        ),
        (
            overhead("tsm", &["--focus", "-inf"]),
            "error: focus must be a finite number (got -inf)",
        ),
        (
            overhead(
                "lispsm",
                &["--partition", "practical", "--k", "2", "--lambda", "-1e-3"],
            ),
            "error: lambda must lie in [0, 1] (got -0.001)",
        ),
    ] {
        assert_error(&args, want);
    }
    assert_infinite_view_refused("warp", &["--light-dir", "0,-1,0", "--warp", "lispsm"]);
    // η = −1 is a value, the unwarped map (Lloyd 2006 Eq 11); negative hints reach Filament's
    // rule; negative light components are a direction.
    let v = warp_json("-1,-1,-0.5", "eta", &["--eta", "-1"]);
    assert_eq!(v["partitions"][0]["n_prime"], "inf");
    let (_, _, err) = run(&overhead(
        "filament",
        &["--near-hint", "-1", "--far-hint", "-0.5"],
    ));
    assert!(!err.contains("unexpected argument"), "{err}");
}

#[test]
fn huge_light_directions_are_directions_and_numbers_in_messages_are_short() {
    // (1e308, 1e308, 1e308) is the direction (1, 1, 1): its squared length overflows, and it
    // used to be refused as a zero vector with three 309-digit numbers.
    let huge = warp_json("1e308,1e308,1e308", "lispsm", &[]);
    let unit = warp_json("1,1,1", "lispsm", &[]);
    let (a, b) = (num(&huge["storage_factor"]), num(&unit["storage_factor"]));
    assert!(a.is_finite() && close(a, b, 1e-12), "{a} {b}");
    let huge_near = set(overhead("lispsm", &[]), "--near", "1e300");
    assert_error(
        &set(huge_near, "--far", "1e-300"),
        "error: far must be greater than near (got near=1e300, far=1e-300)",
    );
}

/// The LiSPSM names (issue 11): `lispsm` is the uniform map behind (n′ = ∞), `lispsm-sin` its
/// old name, `lispsm-fixed` keeps n′ = n + √(f n) = 11; `ogre-ortho` is OGRE 13.6's
/// n_opt × shadowDist: (1 + 10) · 0.1 · 300 = 330 at |cos γ| < 0.9 (default shadowDist 300 n),
/// 1.1 · 50 = 55 with `--shadow-distance 50`, which no other rule takes.
#[test]
fn lispsm_and_ogre_names() {
    for name in ["lispsm", "lispsm-sin"] {
        let v = warp_json("0,0,-1", name, &[]);
        assert_eq!(v["partitions"][0]["n_prime"], "inf", "{name}");
    }
    let v = warp_json("0,0,-1", "lispsm-fixed", &[]);
    assert_eq!(v["partitions"][0]["n_prime"], 11.0);
    let v = warp_json("0.3,-0.5,-0.8", "ogre-ortho", &[]);
    assert!(close(num(&v["partitions"][0]["n_prime"]), 330.0, 1e-12));
    let v = warp_json("0.3,-0.5,-0.8", "ogre-ortho", &["--shadow-distance", "50"]);
    assert!(close(num(&v["partitions"][0]["n_prime"]), 55.0, 1e-12));
    for (warp, distance, needle) in [
        (
            "ogre",
            "50",
            "shadow_distance is only used by --warp ogre-ortho",
        ),
        ("ogre-ortho", "-2", "shadow_distance"),
    ] {
        let (code, err) = run_failing(&overhead(warp, &["--shadow-distance", distance]), "");
        assert_eq!(code, 1, "{err}");
        assert!(err.contains(needle), "{err}");
    }
}
