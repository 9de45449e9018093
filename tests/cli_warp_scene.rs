//! `shadow-aliasing warp` with a scene (issue 9): `--receivers`, `--casters`, `--depth-range`,
//! `--splits`, `--fractions`, `--bevy`. Expected values are hand computations (the uniform map
//! over a box by hand, Bevy's bounds) or the frustum-only command's own output.
#![cfg(feature = "cli")]

use serde_json::Value;

mod common;
use common::cli::{run_failing, warp_args};

/// `warp --json` at n = 1, f = 100, θ = π/4 (tan θ = 1), the light along `dir`, the warp `warp`,
/// then `extra`: exit 0, nothing on stderr, the output parsed.
fn warp(dir: &str, warp: &str, extra: &[&str]) -> Value {
    common::cli::warp_json("0.7853981633974483", dir, warp, extra)
}

/// The receivers' box of the hand computations: the lower half of the view (y ≤ 0) between
/// depths 2 and 5.
const LOWER_HALF: [&str; 2] = ["--receivers", "-100,-100,-5,100,0,-2"];

/// `a` is a number within 1e-9 · max(b, 1) of `b`.
fn close(a: &Value, b: f64) -> bool {
    (a.as_f64().unwrap() - b).abs() < 1e-9 * b.max(1.0)
}

#[test]
fn receivers_focus_the_map_and_report_over_b() {
    // The lower half of the view between depths 2 and 5, light straight down, uniform: s spans
    // x ∈ [−5, 5], t depth [2, 5]; M_x = 10/(2·2) = 2.5, M_z = 3/(2·2) = 0.75, S̄ = 1.875.
    // The value after a space begins with '-'.
    let v = warp("0,-1,0", "uniform", &LOWER_HALF);
    assert_eq!(v["focus"], "body");
    assert!(close(&v["storage_factor"], 1.875), "{v}");
    assert!(close(&v["max_mx"], 2.5));
    assert!(close(&v["max_mz"], 0.75));
    assert_eq!(v["n_prime"], "inf");
    let p = &v["partitions"][0];
    assert!(close(&p["storage_factor"], 1.875));
    assert!(close(&p["near"], 2.0) && close(&p["far"], 5.0));
    assert_eq!(p["body_vertices"], 8);
}

#[test]
fn out_of_view_is_exit_0_with_focus_empty_and_no_storage_factor() {
    let v = warp(
        "0.3,-1,0.2",
        "lispsm",
        &["--receivers", "-10,-10,1,10,10,5"],
    );
    assert_eq!(v["focus"], "empty");
    assert!(v.get("storage_factor").is_none());
    assert_eq!(v["partitions"].as_array().unwrap().len(), 0);
}

#[test]
fn a_receiver_box_containing_the_frustum_gives_the_frustum_only_matrix() {
    let plain = warp("0.3,-1,0.2", "lispsm", &[]);
    let scene = warp(
        "0.3,-1,0.2",
        "lispsm",
        &["--receivers", "-1000,-1000,-1000,1000,1000,1000"],
    );
    assert_eq!(
        plain["partitions"][0]["matrix"],
        scene["partitions"][0]["matrix"]
    );
    assert_eq!(plain["storage_factor"], scene["storage_factor"]);
}

#[test]
fn face_partitions_on_a_scene() {
    // The light straight down sees only the bottom face; every light ray through B leaves through
    // it, so its part's body is all of B (the lower half between depths 2 and 5) and the
    // orthographic face map along the bisector (the view axis here) is the uniform map over B by
    // hand: M_x = 2.5, M_z = 0.75, S̄ = 1.875.
    let faces_1 = [&["--partition", "faces", "--k", "1"][..], &LOWER_HALF].concat();
    let v = warp("0,-1,0", "uniform", &faces_1);
    let parts = v["partitions"].as_array().unwrap();
    assert_eq!(parts.len(), 1, "{v}");
    assert_eq!(parts[0]["face"], "bottom");
    assert!(close(&v["storage_factor"], 1.875), "{v}");
    assert!(close(&v["max_mx"], 2.5) && close(&v["max_mz"], 0.75), "{v}");
    // A receivers' box containing the frustum: the frustum-only face partitions' S̄.
    let faces = |extra: &[&str]| {
        let args = [&["--partition", "faces", "--k", "2"], extra].concat();
        warp("0.2,-0.5,-1", "lispsm", &args)
    };
    let plain = faces(&[]);
    let scene = faces(&["--receivers", "-1e4,-1e4,-1e4,1e4,1e4,1e4"]);
    let want = plain["storage_factor"].as_f64().unwrap();
    assert!(close(&scene["storage_factor"], want), "{scene} vs {want}");
    assert_eq!(
        scene["partitions"].as_array().unwrap().len(),
        plain["partitions"].as_array().unwrap().len()
    );
    // A ground slab: the maps focus on it and cost less.
    let ground = faces(&["--receivers", "-20,-2,-60,20,0,0"]);
    assert!(
        ground["storage_factor"].as_f64().unwrap() < 0.5 * want,
        "{ground}"
    );
}

#[test]
fn casters_and_depth_range_and_new_splits() {
    // Casters change only the depth row (rows 0, 1, 3 of the column-major matrix unchanged).
    let receivers = ["--receivers", "-20,-1,-9,20,0,-1"];
    let a = warp("0.05,-1,0.05", "lispsm", &receivers);
    let casters = [
        "--casters",
        "-1,0,-6,1,30,-4",
        "--casters",
        "-20,-1,-9,20,0,-1",
    ];
    let b = warp(
        "0.05,-1,0.05",
        "lispsm",
        &[&receivers[..], &casters].concat(),
    );
    assert_eq!(a["storage_factor"], b["storage_factor"]);
    let (ma, mb) = (&a["partitions"][0]["matrix"], &b["partitions"][0]["matrix"]);
    for col in 0..4 {
        for row in [0, 1, 3] {
            let i = 4 * col + row;
            let d = (ma[i].as_f64().unwrap() - mb[i].as_f64().unwrap()).abs();
            assert!(d < 1e-12, "entry {i}");
        }
    }
    assert_ne!(ma, mb);
    // The visible depth range cuts the map to [2, 40].
    let d = warp("0.3,-1,0.2", "lispsm", &["--depth-range", "2,40"]);
    assert_eq!(d["partitions"][0]["split"][0], 2.0);
    assert_eq!(d["partitions"][0]["split"][1], 40.0);
    // Absolute splits, fractions and Bevy's cascades.
    let s = warp("0.3,-1,0.2", "lispsm", &["--splits", "1,4,20,100"]);
    assert_eq!(s["partitions"].as_array().unwrap().len(), 3);
    assert_eq!(s["partitions"][1]["split"][0], 4.0);
    let f = warp("0.3,-1,0.2", "lispsm", &["--fractions", "0.25,0.5"]);
    assert_eq!(f["partitions"][1]["split"][0], 1.0 + 0.25 * 99.0);
    let bv = warp("0.3,-1,0.2", "uniform", &["--bevy", "4,0.1,10,150,0.2"]);
    let parts = bv["partitions"].as_array().unwrap();
    assert_eq!(parts.len(), 4);
    // Bevy's far bounds 10 · 15^{i/3} (the last one cut at the camera's far plane, 100).
    let far1 = 10.0 * 15f64.cbrt();
    assert!((parts[1]["split"][1].as_f64().unwrap() - far1).abs() < 1e-9 * far1);
    assert!((parts[1]["blend"][0].as_f64().unwrap() - 0.8 * far1).abs() < 1e-9 * far1);
    assert_eq!(parts[3]["split"][1], 100.0);
}

#[test]
fn bad_scene_arguments_are_errors() {
    for extra in [
        &["--receivers", "1,2,3"][..],
        &["--receivers", "1,0,0,0,1,1"],
        &["--depth-range", "5,4"],
        &[
            "--partition",
            "faces",
            "--k",
            "4",
            "--receivers",
            "-1,-1,-5,1,1,-2",
        ],
        &["--splits", "1,50,40,100"],
        // --bevy carries its own overlap proportion; a second one was ignored silently.
        &["--bevy", "4,0.1,10,150,0.2", "--overlap", "0.7"],
    ] {
        let (_, err) = run_failing(&warp_args("0.5", "0.3,-1,0.2", "lispsm", extra), "");
        assert!(err.starts_with("error:"), "{err}");
    }
}

/// Issue 21 item 4: errors of the cascades the user gives speak of the user's flags: `--splits`
/// (not the library's "planes"), which flags cannot be combined and which to drop, Bevy's K.
/// Issue 21 item 5: `--ratio` reaches the scene's adaptive cascades.
#[test]
fn cascade_flags_are_named_in_their_errors() {
    for (extra, want) in [
        (
            &["--splits", "5"][..],
            "error: splits must hold 2 to 17 depths (got 1)",
        ),
        (
            &["--splits", "1,5,3,100"],
            "error: splits must be strictly increasing (got 3 after 5 at index 2)",
        ),
        (
            &["--splits", "0,5,100"],
            "error: splits must be finite and positive (got 0 at index 0)",
        ),
        (
            &["--splits", "1,5,100", "--partition", "log", "--k", "2"],
            "error: partition log cannot be combined with --splits, which gives the cascades \
             itself: drop --partition (and --k), or drop --splits",
        ),
        (
            &["--fractions", "0.5", "--k", "3"],
            "error: k 3 cannot be combined with --fractions, which gives the number of cascades \
             itself: drop --k, or drop --fractions",
        ),
        (
            &["--bevy", "20,0.1,5,100,0.2"],
            "error: bevy needs a whole number of cascades K in [1, 16] first (got 20)",
        ),
    ] {
        let (code, err) = run_failing(&warp_args("0.5", "0,-1,0", "lispsm", extra), "");
        assert_eq!(
            (code, err.as_str()),
            (1, format!("{want}\n").as_str()),
            "{extra:?}"
        );
        assert!(!err.contains("planes"), "{err}");
    }
    // The adaptive cascades of the scene take --ratio: light along the view (γ = 0), α = 4,
    // k = 3 over the receivers' depths [1, 100] gives splits at 6.25 and 25 (Eq 19 by hand).
    let v = warp(
        "0,0,-1",
        "lispsm",
        &[
            "--partition",
            "adaptive",
            "--k",
            "3",
            "--ratio",
            "4",
            "--receivers",
            "-1000,-1000,-100,1000,1000,-1",
        ],
    );
    let parts = v["partitions"].as_array().unwrap();
    assert_eq!(parts.len(), 3);
    for (p, (a, b)) in parts.iter().zip([(1.0, 6.25), (6.25, 25.0), (25.0, 100.0)]) {
        assert!(close(&p["split"][0], a) && close(&p["split"][1], b), "{p}");
    }
}

/// Issue 31 defect 2: the command printed 7 maps, the slice [0.1, 1.778] in front of the
/// camera without one, and 5 of 8 at far/near = 10¹⁵. Every slice is mapped: the splits are the
/// hand values n (f/n)^(i/8), 0.1 · 10^(10 i/8), ground box or not.
#[test]
fn log_cascades_at_far_near_1e10_map_every_slice() {
    for extra in [
        &["--aspect", "1"][..],
        &["--receivers=-1e9,-1,-1e9,1e9,0,0"][..],
    ] {
        let mut args = vec![
            "warp",
            "--near",
            "0.1",
            "--far",
            "1e9",
            "--half-fov",
            "0.5236",
            "--light-dir",
            "0.3,-0.8,-0.4",
            "--warp",
            "lispsm",
            "--partition",
            "log",
            "--k",
            "8",
            "--json",
        ];
        args.extend_from_slice(extra);
        let v = common::cli::run_json(&args);
        let parts = v["partitions"].as_array().unwrap();
        assert_eq!(parts.len(), 8, "{extra:?}");
        for (i, p) in parts.iter().enumerate() {
            let a = 0.1 * 10f64.powf(10.0 * i as f64 / 8.0);
            assert!(close(&p["split"][0], a), "{extra:?} {i}: {}", p["split"]);
        }
    }
}

/// Issue 31 defects 4 and 5: a frustum too thin for the frame was "no map needed" (and `plan`
/// offered a 0-texel plan); an aspect out of f64's range was blamed on the far or near plane.
/// Each names `aspect` or `half_fov`, in `warp` and `plan` alike.
#[test]
fn degenerate_frusta_are_refused_naming_the_argument() {
    for (flags, name) in [
        (["--half-fov", "0.5236", "--aspect", "1e10"], "aspect"),
        (["--half-fov", "0.5236", "--aspect", "1e-10"], "aspect"),
        (["--half-fov", "1e-10", "--aspect", "1"], "half_fov"),
        (["--half-fov", "0.5236", "--aspect", "1e308"], "aspect"),
        (["--half-fov", "0.5236", "--aspect", "5e-324"], "aspect"),
    ] {
        let base = ["--near", "1", "--far", "100", "--light-dir", "0,-1,0"];
        let mut warp = vec!["warp", "--warp", "uniform"];
        warp.extend_from_slice(&base);
        warp.extend_from_slice(&flags);
        let (_, err) = run_failing(&warp, "");
        assert!(
            err.starts_with(&format!("error: {name} is too ")),
            "{flags:?}: {err}"
        );
        let mut plan = vec!["plan", "--image-height", "1080", "--max-error", "1"];
        plan.extend_from_slice(&base);
        plan.extend_from_slice(&flags);
        let (_, err) = run_failing(&plan, "");
        assert!(
            err.starts_with(&format!("error: {name} is too ")),
            "{flags:?}: {err}"
        );
    }
}
