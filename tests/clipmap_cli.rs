//! `warp --partition clipmap` (issue 24 item 4): the command line builds the frame's clipmap, one
//! map per level with its level, and names bad options.

use glam::{DMat4, DVec3};
use shadow_aliasing::frame::{Camera, ClipmapOptions, FrameInput};
use shadow_aliasing::plan::clipmap::plan_clipmap;
use std::process::Command;

fn warp(extra: &[&str]) -> (bool, String) {
    warp_rule("uniform", extra)
}

/// `warp --partition clipmap` with the warp rule `rule`, near 0.1 and far 1000, and `extra`
/// flags: success and output.
fn warp_rule(rule: &str, extra: &[&str]) -> (bool, String) {
    let mut args = vec!["--near", "0.1", "--far", "1000"];
    args.extend_from_slice(extra);
    clipmap_with(rule, &args)
}

/// `warp --partition clipmap` with the warp rule `rule` at half field of view 0.5 with the
/// light (0.3, −0.8, −0.4), then `args`: success and output.
fn clipmap_with<S: AsRef<str>>(rule: &str, args: &[S]) -> (bool, String) {
    let mut all: Vec<String> = ["warp", "--warp", rule, "--half-fov", "0.5"]
        .into_iter()
        .chain(["--light-dir", "0.3,-0.8,-0.4", "--partition", "clipmap"])
        .map(String::from)
        .collect();
    all.extend(args.iter().map(|a| a.as_ref().to_string()));
    run(&all)
}

/// The command line with `args`: success, and standard output then standard error.
fn run<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> (bool, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_shadow-aliasing"))
        .args(args)
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

/// `warp --partition clipmap` with the uniform rule (the only one a clipmap takes), then `args`.
fn clipmap(args: &[String]) -> (bool, String) {
    clipmap_with("uniform", args)
}

/// The word after `marker` in `text`, without a trailing comma.
fn after<'a>(text: &'a str, marker: &str) -> Option<&'a str> {
    let rest = &text[text.find(marker)? + marker.len()..];
    Some(rest.split_whitespace().next()?.trim_end_matches(','))
}

/// `flags` with `flag`'s value replaced (or `flag` added).
fn with(flags: &[String], flag: &str, value: &str) -> Vec<String> {
    let mut out = flags.to_vec();
    match out.iter().position(|f| f == flag) {
        Some(i) => out[i + 1] = value.to_string(),
        None => out.extend([flag.to_string(), value.to_string()]),
    }
    out
}

/// Issue 31: every remedy the `--levels` refusal advises works when followed, programmatically:
/// the `--levels` it gives, and the far depth it gives as `--far` and as `--depth-range`'s ZMAX.
/// A far depth is never advised at or before the near one; where neither remedy exists the
/// advice is a larger `--level-unit`. The configurations include the issue's: a LAST whose
/// depth rounded to six digits rounds up (`--levels 6,8`: 3.494745…, once advised as 3.49475,
/// which was refused again), and a near plane beyond the last level (near 2 with `--levels 6,6`,
/// once advised a far of 0.873686).
#[test]
fn following_the_levels_advice_works() {
    let cases: [&[&str]; 12] = [
        &["--near", "0.1", "--far", "1000", "--levels", "6,9"],
        &["--near", "0.1", "--far", "1000", "--levels", "6,8"],
        &["--near", "0.1", "--far", "1000", "--levels", "6,7"],
        &["--near", "0.1", "--far", "1000", "--levels", "6,6"],
        &["--near", "2", "--far", "1000", "--levels", "6,6"],
        &["--near", "2", "--far", "1000", "--levels", "6,7"],
        &["--near", "0.1", "--far", "1000", "--levels", "0,0"],
        &["--near", "0.001", "--far", "1e6", "--levels", "0,5"],
        &[
            "--near",
            "0.1",
            "--far",
            "1000",
            "--levels",
            "6,8",
            "--depth-range",
            "0.5,900",
        ],
        &[
            "--near",
            "0.1",
            "--far",
            "1000",
            "--levels",
            "3,9",
            "--lod-bias",
            "1.3",
        ],
        &["--near", "1e-20", "--far", "1e30", "--levels", "-64,-60"],
        &[
            "--near",
            "2",
            "--far",
            "1000",
            "--levels",
            "62,62",
            "--level-unit",
            "1e-300",
        ],
    ];
    let mut followed = (0, 0);
    for case in cases {
        let flags: Vec<String> = case.iter().map(|s| s.to_string()).collect();
        let (ok, text) = clipmap(&flags);
        assert!(
            !ok && text.contains("--levels has LAST"),
            "{case:?}: {text}"
        );
        let near: f64 = flags[1].parse().unwrap();
        let mut advised = false;
        if let Some(levels) = after(&text, "give --levels ") {
            let (ok, out) = clipmap(&with(&flags, "--levels", levels));
            assert!(
                ok,
                "{case:?}: --levels {levels} advised, then refused: {out}"
            );
            advised = true;
            followed.0 += 1;
        }
        if let Some(far) = after(&text, "cut the visible depths to ") {
            let z: f64 = far
                .parse()
                .unwrap_or_else(|_| panic!("{case:?}: {far} is a number"));
            assert!(
                z > near,
                "{case:?}: far {far} advised before the near {near}: {text}"
            );
            assert!(far.len() <= 12, "{case:?}: {far} is more than six digits");
            let (ok, out) = clipmap(&with(&flags, "--far", far));
            assert!(ok, "{case:?}: --far {far} advised, then refused: {out}");
            let range = format!("{near},{far}");
            let (ok, out) = clipmap(&with(&flags, "--depth-range", &range));
            assert!(
                ok,
                "{case:?}: --depth-range {range} advised, then refused: {out}"
            );
            advised = true;
            followed.1 += 1;
        }
        if !advised {
            assert!(
                text.contains("raise --level-unit"),
                "{case:?}: no advice: {text}"
            );
            let (ok, out) = clipmap(&with(&flags, "--level-unit", "1"));
            assert!(ok, "{case:?}: --level-unit 1 refused: {out}");
        }
    }
    // Both kinds of advice were followed, most cases giving both.
    assert!(followed.0 >= 9 && followed.1 >= 6, "{followed:?}");
}

/// The library's own advice (`LevelChoice::levels_needed`'s error naming `last_level`), followed
/// over a grid of cameras, layouts and biases: the far depth it advises is beyond the near depth
/// and is accepted; where the near depth is already beyond the last level no far depth is
/// advised.
#[test]
fn the_librarys_last_level_advice_works_when_followed() {
    use shadow_aliasing::frame::LevelChoice;
    use shadow_aliasing::ViewFrustum;
    let mut followed = 0;
    let mut near_beyond = 0;
    for half_fov in [0.2, 0.5, 0.75, 1.2] {
        for unit in [0.01, 0.3, 1.0, 7.0] {
            for lod_bias in [-2.0, -0.5, 0.0, 1.7] {
                for last in [-3, 0, 6, 9, 13] {
                    let view = ViewFrustum::new(0.05, 1e12, half_fov).unwrap();
                    let options = ClipmapOptions {
                        first_level: last - 2,
                        last_level: last,
                        lod_bias,
                        unit,
                        page_texels: 128,
                    };
                    let c = LevelChoice::new(&view, 1080, 16384, &options).unwrap();
                    for near in [0.05, 3.0, 40.0] {
                        let Err(e) = c.levels_needed(near, 1e12) else {
                            continue;
                        };
                        let text = e.to_string();
                        match after(&text, "cut the visible depths to ") {
                            Some(far) => {
                                let z: f64 = far.parse().unwrap();
                                assert!(z > near, "{text}");
                                assert!(c.levels_needed(near, z).is_ok(), "{text}");
                                followed += 1;
                            }
                            None => {
                                // Then the last level's depths end before the near one.
                                assert!(c.levels_needed(near, near).is_err(), "{text}");
                                near_beyond += 1;
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(
        followed > 100 && near_beyond > 10,
        "{followed} {near_beyond}"
    );
}

/// `LevelChoice::deepest_covered` is the boundary itself: accepted as the far depth, the next
/// float beyond it refused, and within 10⁻¹⁴ of 2^(last + 1 − offset) (docs/planning.md's level
/// choice, computed here from `offset`).
#[test]
fn the_deepest_covered_depth_is_the_boundary() {
    use shadow_aliasing::frame::LevelChoice;
    use shadow_aliasing::ViewFrustum;
    for half_fov in [0.2, 0.5, 1.2] {
        for last in [-5, 0, 9, 22] {
            let view = ViewFrustum::new(1e-3, 1e12, half_fov).unwrap();
            let options = ClipmapOptions {
                first_level: last - 3,
                last_level: last,
                ..ClipmapOptions::UNREAL
            };
            let c = LevelChoice::new(&view, 1080, 16384, &options).unwrap();
            let z = c.deepest_covered();
            let expected = (f64::from(last) + 1.0 - c.offset).exp2();
            assert!((z - expected).abs() <= 1e-14 * expected, "{z} {expected}");
            assert!(c.levels_needed(z * 1e-3, z).is_ok(), "{z}");
            assert!(c.levels_needed(z * 1e-3, z.next_up()).is_err(), "{z}");
        }
    }
}
