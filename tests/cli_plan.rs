//! `shadow-aliasing plan` (issue 24 item 3): `warp` run with the plan's `warp_args` (and the
//! same camera and scene flags) reproduces the planned error from its own measured M_x and M_z,
//! every candidate's flags build its maps, and bad flag combinations are refused by name.
#![cfg(feature = "cli")]

mod common;
use common::cli::{assert_error, run, run_json};
use serde_json::Value;

const CAMERA: [&str; 8] = [
    "--near",
    "1",
    "--far",
    "400",
    "--half-fov",
    "0.5236",
    "--light-dir",
    "0.3,-0.8,-0.4",
];

/// The scenes: none (the frustum alone), a ground and a tower, and a wide image of the ground
/// through an SDSM depth range.
const SCENES: [&[&str]; 3] = [
    &[],
    &[
        "--receivers=-50,-5,-100,50,0,0",
        "--casters=-50,-5,-100,50,0,0",
        "--casters=-10,0,-60,10,20,-40",
    ],
    &[
        "--aspect",
        "1.7778",
        "--receivers=-50,-5,-100,50,0,0",
        "--depth-range",
        "3,150",
    ],
];

fn plan_json(scene: &[&str], goal: &[&str]) -> Value {
    let mut args = vec!["plan"];
    args.extend_from_slice(&CAMERA);
    args.extend_from_slice(scene);
    args.extend_from_slice(&["--image-height", "1080", "--json"]);
    args.extend_from_slice(goal);
    run_json(&args)
}

/// `warp` with the camera, the scene and `flags`: each map's (M_x, M_z).
fn warp_maps(scene: &[&str], flags: &[String]) -> Vec<(f64, f64)> {
    let mut args = vec!["warp"];
    args.extend_from_slice(&CAMERA);
    args.extend_from_slice(scene);
    args.extend(flags.iter().map(String::as_str));
    args.push("--json");
    let v = run_json(&args);
    v["partitions"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p["max_mx"].as_f64().unwrap(), p["max_mz"].as_f64().unwrap()))
        .collect()
}

fn strings(v: &Value) -> Vec<String> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|s| s.as_str().unwrap().to_string())
        .collect()
}

#[test]
fn warp_with_warp_args_reproduces_the_planned_error() {
    let goals: [&[&str]; 4] = [
        &["--max-error", "1"],
        &["--max-error", "0.3", "--rounding", "power-of-two"],
        &["--budget-texels", "4194304", "--max-maps", "1"],
        &["--budget-texels", "33554432", "--max-maps", "4"],
    ];
    for scene in SCENES {
        for goal in goals {
            let p = plan_json(scene, goal);
            let maps = warp_maps(scene, &strings(&p["warp_args"]));
            let res = p["resolutions"].as_array().unwrap();
            assert_eq!(maps.len(), res.len(), "{scene:?} {goal:?}");
            let (mut worst, mut texels) = (0.0f64, 0u64);
            for ((mx, mz), r) in maps.iter().zip(res) {
                let (rs, rt) = (r[0].as_u64().unwrap(), r[1].as_u64().unwrap());
                worst = worst.max((mx * 1080.0 / rs as f64).max(mz * 1080.0 / rt as f64));
                texels += rs * rt;
            }
            let want = p["max_error_pixels"].as_f64().unwrap();
            assert!(
                (worst - want).abs() <= 1e-12 * want,
                "{scene:?} {goal:?}: warp gives {worst}, plan {want}"
            );
            assert_eq!(texels, p["texels"].as_u64().unwrap());
        }
    }
}

/// The clipmap candidate (its LOD bias chosen for the goal): `warp` with its `warp_args` builds
/// as many levels, each of 16 384² texels (the plan's resolutions), and the error from warp's
/// own M_x and M_z, max(M H / 16 384), is the plan's; its texels are whole pages of 128², no more
/// than its levels hold; at a target it meets the target, within a budget it fits it.
#[test]
fn clipmap_candidate_reproduces_its_error() {
    let goals: [&[&str]; 3] = [
        &["--max-error", "1"],
        &["--max-error", "2"],
        &["--budget-texels", "33554432", "--max-maps", "16"],
    ];
    for scene in SCENES {
        for goal in goals {
            let p = plan_json(scene, goal);
            let row = p["candidates"]
                .as_array()
                .unwrap()
                .iter()
                .find(|r| r["scheme"].as_str().unwrap().starts_with("clipmap"))
                .unwrap_or_else(|| panic!("{scene:?} {goal:?}: no clipmap row"));
            let want = row["max_error_pixels"]
                .as_f64()
                .unwrap_or_else(|| panic!("{scene:?} {goal:?}: {row}"));
            let args = strings(&row["warp_args"]);
            assert!(
                args.join(" ").contains("--partition clipmap --lod-bias"),
                "{args:?}"
            );
            let maps = warp_maps(scene, &args);
            assert_eq!(maps.len() as u64, row["maps"].as_u64().unwrap(), "{row}");
            let worst = maps
                .iter()
                .map(|(mx, mz)| mx.max(*mz) * 1080.0 / 16384.0)
                .fold(0.0, f64::max);
            assert!(
                (worst - want).abs() <= 1e-12 * want,
                "{scene:?} {goal:?}: warp gives {worst}, plan {want}"
            );
            let texels = row["texels"].as_u64().unwrap();
            assert!(texels.is_multiple_of(128 * 128), "{row}");
            assert!(texels <= maps.len() as u64 * 16384 * 16384, "{row}");
            match goal[0] {
                "--max-error" => assert!(want <= goal[1].parse::<f64>().unwrap(), "{row}"),
                _ => assert!(texels <= goal[1].parse::<u64>().unwrap(), "{row}"),
            }
        }
    }
}

/// Every candidate's `warp_args` build its maps: as many, and at the target their whole-texel
/// cost ⌈M H/E⌉ per axis, by hand from warp's M_x and M_z, is the candidate's texels.
#[test]
fn every_candidates_warp_args_build_its_maps() {
    let scene = SCENES[1];
    let p = plan_json(scene, &["--max-error", "1"]);
    let rows = p["candidates"].as_array().unwrap();
    assert_eq!(rows.len(), 129);
    for row in rows {
        let Some(texels) = row["texels"].as_u64() else {
            continue;
        };
        if row["scheme"].as_str().unwrap().starts_with("clipmap") {
            // Its texels are pages (clipmap_candidate_reproduces_its_error).
            continue;
        }
        let maps = warp_maps(scene, &strings(&row["warp_args"]));
        assert_eq!(maps.len() as u64, row["maps"].as_u64().unwrap(), "{row}");
        let hand: u64 = maps
            .iter()
            .map(|(mx, mz)| ((mx * 1080.0).ceil() * (mz * 1080.0).ceil()) as u64)
            .sum();
        assert_eq!(hand, texels, "{row}");
    }
}

fn plan_args<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec!["plan"];
    args.extend_from_slice(&CAMERA);
    args.extend_from_slice(extra);
    args
}

#[test]
fn bad_flag_combinations_name_the_flag() {
    assert_error(
        &plan_args(&["--image-height", "1080"]),
        "error: --max-error or --budget-texels is needed: give --max-error PX (the fewest texels \
         within PX) or --budget-texels N [--max-maps K] (the least error within N texels)",
    );
    assert_error(
        &plan_args(&["--image-height", "0", "--max-error", "1"]),
        "error: image_height must be at least 1 (got 0)",
    );
    assert_error(
        &plan_args(&["--image-height", "1080", "--budget-texels", "0"]),
        "error: budget_texels must be at least 1 (got 0)",
    );
    assert_error(
        &plan_args(&[
            "--image-height",
            "1080",
            "--budget-texels",
            "8",
            "--max-maps",
            "0",
        ]),
        "error: max_maps must be at least 1 (got 0)",
    );
    let (code, _, err) = run(&plan_args(&["--image-height", "1080", "--max-error", "0"]));
    assert_eq!(code, 1);
    assert!(err.starts_with("error: max_error must be"), "{err}");
    let (code, out, err) = run(&plan_args(&[
        "--image-height",
        "1080",
        "--max-error",
        "1",
        "--budget-texels",
        "9",
    ]));
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(
        err.contains("--max-error") && err.contains("--budget-texels"),
        "{err}"
    );
    assert_error(
        &plan_args(&[
            "--image-height",
            "1080",
            "--max-error",
            "1",
            "--max-maps",
            "2",
        ]),
        "error: --max-maps is only used with --budget-texels: drop it, or give --budget-texels \
         instead of --max-error",
    );
}

#[test]
fn warp_stable_and_trapezoid_refuse_what_they_do_not_use() {
    let warp = |extra: &[&'static str]| {
        let mut a = vec!["warp"];
        a.extend_from_slice(&CAMERA);
        a.extend_from_slice(extra);
        a
    };
    assert_error(
        &warp(&[
            "--warp",
            "lispsm",
            "--stable",
            "--partition",
            "log",
            "--k",
            "3",
        ]),
        "error: stable cascades are unwarped (world-fixed squares): give --warp uniform (got \
         --warp lispsm)",
    );
    assert_error(
        &warp(&["--warp", "uniform", "--stable", "--partition", "faces"]),
        "error: stable needs cascades (--partition other than faces, --splits, --fractions or \
         --bevy) or none: drop --stable or --partition faces",
    );
    assert_error(
        &warp(&["--warp", "trapezoid", "--partition", "log", "--k", "2"]),
        "error: partition is not used by --warp trapezoid, one trapezoidal map (its only \
         parameter is --focus): drop it",
    );
    let mut sweep = vec!["sweep", "--near", "1", "--far", "100", "--half-fov", "0.5"];
    sweep.extend_from_slice(&[
        "--warp",
        "trapezoid",
        "--elevations",
        "2",
        "--azimuths",
        "2",
    ]);
    let (code, _, err) = run(&sweep);
    assert_eq!(code, 1);
    assert!(
        err.starts_with("error: warp trapezoid is one trapezoidal map"),
        "{err}"
    );
    // --aspect is the frame's: a wide image gives a wider frustum and a larger M_x.
    let square = warp_maps(
        &[],
        &[
            "--warp".into(),
            "uniform".into(),
            "--aspect".into(),
            "1".into(),
        ],
    );
    let wide = warp_maps(
        &[],
        &[
            "--warp".into(),
            "uniform".into(),
            "--aspect".into(),
            "2".into(),
        ],
    );
    assert!(wide[0].0 > square[0].0 || wide[0].1 > square[0].1);
}
