//! `shadow-aliasing warp --partition equal-error` (issue 24 item 1): the frame's equal-error
//! cascades from the command line, with or without a scene; refused by `sweep` and with
//! `--overlap`.
#![cfg(feature = "cli")]

mod common;
use common::cli::{assert_error, view_args, warp_json};

/// The frustum alone, light overhead: the planes z_i = n (f/n)^{i/k} of Lloyd 2006 Eq 15–16 by
/// hand (n = 1, f = 100), every partition's M_x and M_z the same.
#[test]
fn frustum_alone_gives_logarithmic_planes() {
    let v = warp_json(
        "0.5",
        "0,-1,0",
        "lispsm",
        &["--partition", "equal-error", "--k", "3"],
    );
    let parts = v["partitions"].as_array().unwrap();
    assert_eq!(parts.len(), 3);
    for (i, p) in parts.iter().enumerate() {
        for (j, z) in p["split"].as_array().unwrap().iter().enumerate() {
            let want = 100f64.powf((i + j) as f64 / 3.0);
            let got = z.as_f64().unwrap();
            assert!((got - want).abs() <= 1e-9 * want, "{i}: {got} vs {want}");
        }
        let mx = p["max_mx"].as_f64().unwrap();
        let mx0 = parts[0]["max_mx"].as_f64().unwrap();
        assert!((mx - mx0).abs() <= 1e-9 * mx0);
    }
}

/// With a scene: every partition's largest error the same, and no higher than the logarithmic
/// partitions' (the same scene through `--partition log`).
#[test]
fn scene_errors_equal_and_no_worse_than_log() {
    let scene = ["--receivers", "-50,-5,-90,50,0,-3", "--k", "4"];
    let largest = |v: &serde_json::Value| -> Vec<f64> {
        v["partitions"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| {
                p["max_mx"]
                    .as_f64()
                    .unwrap()
                    .max(p["max_mz"].as_f64().unwrap())
            })
            .collect()
    };
    let mut args = vec!["--partition", "equal-error"];
    args.extend_from_slice(&scene);
    let ours = largest(&warp_json("0.5", "0.3,-0.8,-0.4", "uniform", &args));
    let mut args = vec!["--partition", "log"];
    args.extend_from_slice(&scene);
    let log = largest(&warp_json("0.5", "0.3,-0.8,-0.4", "uniform", &args));
    let top = ours.iter().copied().fold(0.0, f64::max);
    assert_eq!(ours.len(), 4);
    for e in &ours {
        assert!((e - top).abs() <= 1e-9 * top, "{ours:?}");
    }
    assert!(
        top <= log.iter().copied().fold(0.0, f64::max),
        "{ours:?} vs {log:?}"
    );
}

#[test]
fn sweep_and_overlap_are_refused() {
    assert_error(
        &view_args(
            "sweep",
            "0.5",
            &["--warp", "lispsm", "--partition", "equal-error", "--k", "3"],
        ),
        "error: partition equal-error places its splits by measuring one light's maps: use it \
         with warp, or sweep --partition log (the frustum's own equal-error splits for the rules \
         whose map scales with its slice)",
    );
    assert_error(
        &view_args(
            "warp",
            "0.5",
            &[
                "--light-dir",
                "0,-1,0",
                "--warp",
                "uniform",
                "--partition",
                "equal-error",
                "--k",
                "2",
                "--overlap",
                "0.1",
            ],
        ),
        "error: overlap is not used by --partition equal-error, whose maps cover exactly their \
         splits: drop --overlap",
    );
}
