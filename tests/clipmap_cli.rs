//! `warp --partition clipmap` (issue 24 item 4): the command line builds the frame's clipmap, one
//! map per level with its level, and names bad options.

use glam::{DMat4, DVec3};
use shadow_aliasing::frame::{Camera, ClipmapOptions, FrameInput};
use shadow_aliasing::plan::clipmap::plan_clipmap;
use std::process::Command;

fn warp(extra: &[&str]) -> (bool, String) {
    warp_rule("uniform", extra)
}

/// `warp --partition clipmap` with the warp rule `rule` and `extra` flags: success and output.
fn warp_rule(rule: &str, extra: &[&str]) -> (bool, String) {
    let mut args = vec![
        "warp",
        "--warp",
        rule,
        "--near",
        "0.1",
        "--far",
        "1000",
        "--half-fov",
        "0.5",
        "--light-dir",
        "0.3,-0.8,-0.4",
        "--partition",
        "clipmap",
    ];
    args.extend_from_slice(extra);
    let out = Command::new(env!("CARGO_BIN_EXE_shadow-aliasing"))
        .args(&args)
        .output()
        .unwrap();
    let text =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    (out.status.success(), text)
}

/// Unreal's defaults: the levels the library plans for the same camera, 16 384 texels and 1080
/// pixels, each named in the JSON.
#[test]
fn warp_builds_the_clipmap_levels() {
    let (ok, json) = warp(&["--json"]);
    assert!(ok, "{json}");
    let cam = Camera::new(DMat4::IDENTITY, 0.1, 1000.0, 0.5, 1.0).unwrap();
    let input = FrameInput::new(cam, DVec3::new(0.3, -0.8, -0.4), 16384, 1080);
    let p = plan_clipmap(&input, &ClipmapOptions::UNREAL).unwrap();
    let (first, last) = p.level_range();
    for level in first..=last {
        assert!(
            json.contains(&format!("\"clipmap_level\": {level},")),
            "level {level} missing"
        );
    }
    assert!(!json.contains(&format!("\"clipmap_level\": {},", last + 1)));
}

#[test]
fn bad_clipmap_options_are_named() {
    for (extra, name) in [
        (&["--levels", "6"][..], "levels"),
        (&["--levels", "9,6"][..], "--levels needs FIRST,LAST"),
        (&["--page-texels", "100"][..], "page_texels"),
        (&["--page-texels", "-1"][..], "page_texels"),
        (&["--image-height", "0"][..], "image_height"),
        (&["--lod-bias", "nan"][..], "lod_bias"),
        (&["--level-unit", "0"][..], "unit"),
        (&["--overlap", "0.1"][..], "overlap"),
    ] {
        let (ok, text) = warp(extra);
        assert!(!ok && text.contains(name), "{extra:?}: {text}");
    }
}

/// `--levels` whose LAST is too fine for the visible depths names `--levels` (not the library's
/// `last_level`) and the LAST that covers them: the depth 1000 at Unreal's layout, 16 384 texels
/// and 1080 pixels is level 17's (the library's plan of the same camera, computed separately), and
/// `--levels 6,17` then works.
#[test]
fn too_few_levels_name_the_flag_and_the_last_level_needed() {
    let cam = Camera::new(DMat4::IDENTITY, 0.1, 1000.0, 0.5, 1.0).unwrap();
    let input = FrameInput::new(cam, DVec3::new(0.3, -0.8, -0.4), 16384, 1080);
    let (_, last) = plan_clipmap(&input, &ClipmapOptions::UNREAL)
        .unwrap()
        .level_range();
    let (ok, text) = warp(&["--levels", "6,9"]);
    assert!(!ok, "{text}");
    assert!(
        text.contains("--levels") && !text.contains("last_level"),
        "{text}"
    );
    assert!(
        text.contains(&format!("give --levels 6,{last}")) && text.contains("--far"),
        "{text}"
    );
    let (ok, text) = warp(&["--levels", &format!("6,{last}"), "--json"]);
    assert!(ok, "{text}");
    let (ok, text) = warp(&["--levels", &format!("6,{}", last - 1)]);
    assert!(
        !ok && text.contains(&format!("give --levels 6,{last}")),
        "{text}"
    );
}

/// Clipmap levels are orthographic: a warp rule other than uniform is refused by name, not
/// silently dropped.
#[test]
fn a_warped_clipmap_is_refused() {
    let (ok, text) = warp_rule("lispsm", &[]);
    assert!(!ok, "{text}");
    assert!(
        text.contains("partition") && text.contains("--warp uniform") && text.contains("lispsm"),
        "{text}"
    );
}
