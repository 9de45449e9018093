//! The reduced set, rendered for real (wgpu on Vulkan; lavapipe without a GPU): every scheme on
//! two set-ups at a small resolution, asserting the issue's targets, and the shimmer test. With no
//! Vulkan adapter these tests fail, naming `mesa-vulkan-drivers`; they never skip.

use render_check::faults::Fault;
use render_check::gpu::Gpu;
use render_check::run::{run_case, shimmer, Sizes};
use render_check::schemes::{setups, Scheme};
use std::process::Command;

const SIZES: Sizes = Sizes {
    width: 240,
    height: 180,
    res: Some(1024),
    frames: 64,
    shimmer_points: 1500,
    fault: None,
};

fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|e| panic!("{e}"))
}

fn check_setup(name: &str) {
    let gpu = gpu();
    let setup = setups().into_iter().find(|s| s.name == name).unwrap();
    for scheme in Scheme::ALL {
        let r = run_case(&gpu, &setup.name, &setup.scene, scheme, SIZES).unwrap();
        let s = &r.summary;
        let what = format!("{name}/{}: {s:?} ({})", scheme.name(), r.diagnostics);
        // At least a third of the screen compared (the rest: sky, and pixels next to discontinuities).
        assert!(s.pixels_compared > 240 * 180 / 3, "{what}");
        assert!(s.median_rel_diff <= 0.01, "{what}");
        assert!(s.p99_rel_diff <= 0.05, "{what}");
        assert_eq!(s.interior_misses, 0, "{what}");
        assert_eq!(s.interior_false_shadows, 0, "{what}");
        // Some pixels are interior (a check over none would pass vacuously).
        assert!(r.analysis.interior_pixels > 240 * 180 / 100, "{what}");
        assert!(
            s.max_predicted_error > 0.0 && s.max_rendered_error > 0.0,
            "{what}"
        );
        assert!(
            (s.max_rendered_error - s.max_predicted_error).abs() <= 0.05 * s.max_predicted_error,
            "{what}"
        );
    }
}

#[test]
fn tilted_45_every_scheme_meets_the_targets() {
    check_setup("tilted_45");
}

/// The light 5° from behind: the tower behind the camera, outside the view frustum, shadows the
/// view; a depth range cut at the frustum would lose that shadow (interior misses).
#[test]
fn behind_5_every_scheme_meets_the_targets() {
    check_setup("behind_5");
}

/// The same set-up with the casters left out of the frame (the depth range fitted to the focus
/// body alone): the tower behind the camera is clipped out of the map and its shadow is lost,
/// which the interior-miss count catches.
#[test]
fn depth_range_without_the_casters_is_caught() {
    let gpu = gpu();
    let setup = setups().into_iter().find(|s| s.name == "behind_5").unwrap();
    let sizes = Sizes {
        fault: Some(Fault::NoCasters),
        ..SIZES
    };
    let r = run_case(&gpu, &setup.name, &setup.scene, Scheme::Uniform, sizes).unwrap();
    assert!(r.summary.interior_misses > 100, "{:?}", r.summary);
}

/// Stable cascades keep every edge point's state over 64 frames of sub-texel moves and 0.05°
/// turns; the plain LiSPSM cascades do not (the test can fail).
#[test]
fn stable_cascades_do_not_shimmer_and_plain_ones_do() {
    let gpu = gpu();
    let setup = setups()
        .into_iter()
        .find(|s| s.name == "tilted_45")
        .unwrap();
    let stable = shimmer(&gpu, &setup.scene, Scheme::StableCascades, SIZES).unwrap();
    let plain = shimmer(&gpu, &setup.scene, Scheme::Cascades, SIZES).unwrap();
    assert!(stable <= 0.001, "stable {stable}, plain {plain}");
    assert!(plain > 0.001, "stable {stable}, plain {plain}");
}

/// The binary with a scene file: summary.json has exactly the issue's fields, and the images
/// are written.
#[test]
fn scene_file_run_writes_the_summary_with_exactly_the_fields() {
    let dir = std::env::temp_dir().join(format!("render-check-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("small.json");
    std::fs::write(
        &scene,
        r#"{"ground_y": 0.0, "ground_half_extent": 100.0,
            "boxes": [{"min": [-2, 0, -12], "max": [2, 3, -8]}, {"min": [3, 0, -20], "max": [4, 6, -19]}],
            "camera": {"eye": [0, 4, 0], "target": [0, 0, -20], "up": [0, 1, 0],
                       "near": 0.5, "far": 60, "fov_y_deg": 55},
            "light_dir": [0.4, -1.0, -0.3], "map_resolution": 256}"#,
    )
    .unwrap();
    let out = dir.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_render-check"))
        .args([
            "--out",
            out.to_str().unwrap(),
            "--scene",
            scene.to_str().unwrap(),
        ])
        .args(["--width", "160", "--height", "120", "--frames", "4"])
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let top: Vec<&String> = summary.as_object().unwrap().keys().collect();
    assert_eq!(top, ["cases", "device"]);
    let cases = summary["cases"].as_array().unwrap();
    assert_eq!(cases.len(), Scheme::ALL.len());
    let mut keys: Vec<&str> = cases[0]
        .as_object()
        .unwrap()
        .keys()
        .map(String::as_str)
        .collect();
    keys.sort_unstable();
    let mut expect = [
        "setup",
        "scheme",
        "map_texels",
        "pixels_compared",
        "median_rel_diff",
        "p99_rel_diff",
        "interior_misses",
        "interior_false_shadows",
        "edge_band_mismatch_fraction",
        "max_rendered_error",
        "max_predicted_error",
        "shimmer_changed_fraction",
    ];
    expect.sort_unstable();
    assert_eq!(keys, expect);
    for c in cases {
        assert_eq!(c["setup"], "small");
        assert_eq!(c["interior_misses"], 0, "{c}");
        assert_eq!(c["interior_false_shadows"], 0, "{c}");
        let shimmer = &c["shimmer_changed_fraction"];
        let cascaded = c["scheme"].as_str().unwrap().contains("cascades");
        assert_eq!(shimmer.is_null(), !cascaded, "{c}");
        let stem = format!("small_{}", c["scheme"].as_str().unwrap());
        assert!(out.join(format!("{stem}.png")).is_file());
        assert!(out.join(format!("{stem}_error.png")).is_file());
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Without a Vulkan driver the binary fails and names the package.
#[test]
fn no_adapter_fails_naming_the_package() {
    let o = Command::new(env!("CARGO_BIN_EXE_render-check"))
        .args([
            "--out",
            std::env::temp_dir()
                .join("render-check-none")
                .to_str()
                .unwrap(),
        ])
        .env("VK_ICD_FILENAMES", "/nonexistent/icd.json")
        .env("VK_DRIVER_FILES", "/nonexistent/icd.json")
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("mesa-vulkan-drivers"), "{err}");
}

/// A bad scene file is an error naming the file, not a panic.
#[test]
fn bad_scene_file_is_an_error() {
    let dir = std::env::temp_dir().join(format!("render-check-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("bad.json");
    std::fs::write(&scene, r#"{"ground_y": 0.0}"#).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_render-check"))
        .args([
            "--out",
            dir.join("o").to_str().unwrap(),
            "--scene",
            scene.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bad.json"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}
