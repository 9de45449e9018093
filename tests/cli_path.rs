//! `shadow-aliasing replay` (issue 32 item 3) over a camera path file (docs/paths.md): a line a
//! frame, the summary's switches equal to the frames marked switched, the JSON keys docs/cli.md
//! lists, the cut the file holds found, and bad path files refused by name.
#![cfg(feature = "cli")]

mod common;
use common::cli::run;
use serde_json::Value;
use std::path::PathBuf;

/// `paths/cut.json`'s frames `from .. to`, written to a file of its own (named by `tag`).
fn excerpt(tag: &str, from: usize, to: usize, edit: impl Fn(&mut Value)) -> PathBuf {
    let text = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/paths/cut.json"))
        .expect("paths/cut.json reads");
    let mut v: Value = serde_json::from_str(&text).expect("paths/cut.json is JSON");
    let frames = v["frames"].as_array().expect("frames")[from..to].to_vec();
    v["frames"] = Value::Array(frames);
    edit(&mut v);
    let file = std::env::temp_dir().join(format!("cli_path_{tag}_{}.json", std::process::id()));
    std::fs::write(&file, v.to_string()).expect("the excerpt writes");
    file
}

#[test]
fn replay_prints_a_line_a_frame_and_counts_the_switches() {
    // Frames 144 .. 156 of the cut path: the jump of 100 units (a third of far = 300, past the
    // controller's 10 %) is between the excerpt's frames 5 and 6.
    let file = excerpt("replay", 144, 156, |_| {});
    let p = file.to_str().expect("a UTF-8 path");
    let (code, out, err) = run(&["replay", "--path", p, "--max-error", "2", "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).expect("JSON");
    let frames = v["frames"].as_array().expect("frames");
    assert_eq!(frames.len(), 12);
    let switched = frames
        .iter()
        .filter(|f| f["switched"].as_bool().expect("switched"))
        .count();
    let s = &v["summary"];
    assert_eq!(s["frames"], 12);
    assert_eq!(s["switches"].as_u64(), Some(switched as u64));
    // The cuts: the first frame and the jump, no other.
    let cuts: Vec<usize> = frames
        .iter()
        .enumerate()
        .filter(|(_, f)| f["cut"].as_bool().expect("cut"))
        .map(|(i, _)| i)
        .collect();
    assert_eq!(cuts, [0, 6]);
    assert_eq!(s["cuts"], 2);
    // Never claims the target where the error misses it.
    for f in frames {
        let e = f["max_error_pixels"].as_f64().expect("error");
        assert_eq!(f["meets_target"].as_bool(), Some(e <= 2.0), "{f}");
        let (maps, res) = (
            f["maps"].as_u64().unwrap(),
            f["resolution"].as_u64().unwrap(),
        );
        assert_eq!(f["texels"].as_u64(), Some(maps * res * res), "{f}");
    }
    // Every key docs/cli.md's replay table names is there.
    let docs = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/cli.md"))
        .expect("docs/cli.md reads");
    let section = docs
        .split("## `shadow-aliasing replay`")
        .nth(1)
        .and_then(|s| s.split("\n## ").next())
        .expect("docs/cli.md has the replay section");
    let table: Vec<&str> = section.lines().filter(|l| l.starts_with("| `")).collect();
    assert_eq!(table.len(), 3, "{table:?}");
    let keys = |row: &str| -> Vec<String> {
        row.split('`')
            .skip(1)
            .step_by(2)
            .map(str::to_string)
            .collect()
    };
    for k in keys(table[0]) {
        assert!(v.get(&k).is_some(), "top-level {k}");
    }
    for k in keys(table[1]).iter().skip(1) {
        assert!(frames[0].get(k).is_some(), "frames[].{k}");
    }
    for k in keys(table[2]).iter().skip(1) {
        assert!(s.get(k).is_some(), "summary.{k}");
    }
    // The text: one line a frame.
    let (code, out, err) = run(&["replay", "--path", p, "--max-error", "2"]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().filter(|l| l.starts_with("frame ")).count(), 12);
    assert!(out.lines().all(|l| l == l.trim_end()), "{out}");
    assert!(
        out.contains(&format!("summary: {switched} switches, 2 cuts")),
        "{out}"
    );
    let _ = std::fs::remove_file(&file);
}

/// A refused path file: its tag, the edit of a valid excerpt, what the message must hold.
type Refusal = (
    &'static str,
    Box<dyn Fn(&mut Value)>,
    &'static [&'static str],
);

#[test]
fn unknown_keys_and_missing_files_are_refused_by_name() {
    let cases: [Refusal; 5] = [
        (
            "frame_key",
            Box::new(|v| v["frames"][2]["eyes"] = v["frames"][2]["eye"].clone()),
            &["unknown key `eyes`", "frames[2]"],
        ),
        (
            "top_key",
            Box::new(|v| v["lights"] = Value::Null),
            &["unknown key `lights`", "the top level"],
        ),
        (
            "camera_key",
            Box::new(|v| v["camera"]["fov"] = 1.into()),
            &["unknown key `fov`", "camera"],
        ),
        (
            "no_light",
            Box::new(|v| {
                v.as_object_mut().unwrap().remove("light_dir");
            }),
            &["frames[0].light_dir", "is needed"],
        ),
        (
            "eye_is_target",
            Box::new(|v| v["frames"][1]["target"] = v["frames"][1]["eye"].clone()),
            &["frames[1].target", "must differ from the eye"],
        ),
    ];
    for (tag, edit, needles) in cases {
        let file = excerpt(tag, 0, 3, edit);
        let p = file.to_str().expect("a UTF-8 path");
        let (code, out, err) = run(&["replay", "--path", p, "--max-error", "2"]);
        assert_eq!(code, 1, "{tag}: {out}");
        assert!(out.is_empty(), "{tag}: {out}");
        assert!(
            err.starts_with("error: path file ") && err.contains(p),
            "{tag}: {err}"
        );
        for n in needles {
            assert!(err.contains(n), "{tag}: {n} not in {err}");
        }
        assert_eq!(err.lines().count(), 1, "{tag}: {err}");
        let _ = std::fs::remove_file(&file);
    }
    let missing = std::env::temp_dir().join("cli_path_no_such_file.json");
    let m = missing.to_str().expect("a UTF-8 path");
    let (code, _, err) = run(&["replay", "--path", m, "--max-error", "2"]);
    assert_eq!(code, 1);
    assert!(
        err.starts_with("error: cannot read path file ") && err.contains(m),
        "{err}"
    );
    // Not an object at the top; receivers out of view in every frame (named with the frame).
    let file = excerpt("top", 0, 2, |v| *v = Value::Array(vec![]));
    let p = file.to_str().expect("a UTF-8 path");
    let (code, _, err) = run(&["replay", "--path", p, "--max-error", "2"]);
    assert_eq!(code, 1);
    assert!(
        err.contains("the top level: must be a JSON object"),
        "{err}"
    );
    let _ = std::fs::remove_file(&file);
    let file = excerpt("away", 0, 2, |v| {
        v["scene"]["receivers"] =
            serde_json::json!([[1e4, 1e4, 1e4, 1e4 + 1.0, 1e4 + 1.0, 1e4 + 1.0]]);
    });
    let p = file.to_str().expect("a UTF-8 path");
    let (code, _, err) = run(&["replay", "--path", p, "--max-error", "2"]);
    assert_eq!(code, 1);
    assert!(
        err.starts_with(&format!("error: path file {p}, frame 0: receivers")),
        "{err}"
    );
    let _ = std::fs::remove_file(&file);
    // A bad target is named by its flag.
    let file = excerpt("target", 0, 2, |_| {});
    let p = file.to_str().expect("a UTF-8 path");
    let (code, _, err) = run(&["replay", "--path", p, "--max-error", "0"]);
    assert_eq!(code, 1);
    assert!(err.starts_with("error: --max-error must be"), "{err}");
    let _ = std::fs::remove_file(&file);
}

/// The five paths of `paths/` parse and have the frames and the kinds docs/paths.md says.
#[test]
fn the_paths_in_the_repository_are_well_formed() {
    for name in ["walk", "flyover", "turn", "sun_sweep", "cut"] {
        let file = format!("{}/paths/{name}.json", env!("CARGO_MANIFEST_DIR"));
        let v: Value =
            serde_json::from_str(&std::fs::read_to_string(&file).expect("reads")).expect("JSON");
        let frames = v["frames"].as_array().expect("frames");
        assert_eq!(frames.len(), 300, "{name}");
        let eye = |i: usize, k: usize| frames[i]["eye"][k].as_f64().unwrap();
        match name {
            // Eye height 1.7 throughout.
            "walk" | "turn" => assert!((0..300).all(|i| eye(i, 1) == 1.7), "{name}"),
            // From 2 to 200 units.
            "flyover" => assert_eq!((eye(0, 1), eye(299, 1)), (2.0, 200.0)),
            // A still camera, a light per frame.
            "sun_sweep" => {
                assert!((0..300).all(|i| frames[i]["eye"] == frames[0]["eye"]));
                assert!(frames.iter().all(|f| f.get("light_dir").is_some()));
            }
            // One jump of 100 units between frames 149 and 150, 0.9 a frame elsewhere.
            _ => {
                let step = |i: usize| (eye(i + 1, 0) - eye(i, 0)).hypot(eye(i + 1, 2) - eye(i, 2));
                let jumps: Vec<usize> = (0..299).filter(|&i| step(i) > 10.0).collect();
                assert_eq!(jumps, [149]);
            }
        }
    }
}

/// Numbers of an SVG attribute `name="…"` in `element`.
fn attr(element: &str, name: &str) -> String {
    let start = element
        .find(&format!(" {name}=\""))
        .unwrap_or_else(|| panic!("{name} in {element}"))
        + name.len()
        + 3;
    element[start..]
        .split('"')
        .next()
        .expect("closed")
        .to_string()
}

#[test]
fn the_figure_draws_every_frame_against_the_target() {
    let file = excerpt("figure", 144, 156, |_| {});
    let p = file.to_str().expect("a UTF-8 path");
    let svg_file = std::env::temp_dir().join(format!("cli_path_{}.svg", std::process::id()));
    let s = svg_file.to_str().expect("a UTF-8 path");
    let (code, out, err) = run(&[
        "replay",
        "--path",
        p,
        "--max-error",
        "2",
        "--json",
        "--figure",
        s,
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).expect("JSON");
    let frames = v["frames"].as_array().expect("frames");
    let svg = std::fs::read_to_string(&svg_file).expect("the figure is written");
    let elements: Vec<&str> = svg.split('<').collect();
    let series: Vec<Vec<(f64, f64)>> = elements
        .iter()
        .filter(|e| e.starts_with("polyline class=\"series\""))
        .map(|e| {
            attr(e, "points")
                .split_whitespace()
                .map(|xy| {
                    let (x, y) = xy.split_once(',').expect("x,y");
                    (x.parse().expect("x"), y.parse().expect("y"))
                })
                .collect()
        })
        .collect();
    assert_eq!(series.len(), 2, "error and texels");
    assert!(series.iter().all(|s| s.len() == frames.len()));
    // A linear axis from 0 at the panel's bottom: each frame's height over the bottom is its
    // error's fraction of the target line's height.
    let target = elements
        .iter()
        .find(|e| e.starts_with("line class=\"target\""))
        .expect("the target line");
    let ty: f64 = attr(target, "y1").parse().expect("y1");
    let panel = elements
        .iter()
        .find(|e| e.starts_with("rect x="))
        .expect("the error panel");
    let bottom: f64 = attr(panel, "y").parse::<f64>().expect("y")
        + attr(panel, "height").parse::<f64>().expect("height");
    let mut errors = Vec::new();
    for (f, (_, y)) in frames.iter().zip(&series[0]) {
        let e = f["max_error_pixels"].as_f64().expect("error");
        let drawn = (bottom - y) / (bottom - ty) * 2.0;
        assert!((drawn - e).abs() < 1e-3 * e, "{e} px drawn as {drawn}");
        errors.push(e);
    }
    // The excerpt's errors differ before and after the jump, so that the check can see a
    // series drawn flat.
    assert!(
        errors.iter().any(|e| (e - errors[0]).abs() > 0.01),
        "{errors:?}"
    );
    // A grey line at each cut frame's x, no other.
    let cuts: Vec<f64> = elements
        .iter()
        .filter(|e| e.starts_with("line class=\"cut\""))
        .map(|e| attr(e, "x1").parse().expect("x1"))
        .collect();
    let expected: Vec<f64> = frames
        .iter()
        .zip(&series[0])
        .filter(|(f, _)| f["cut"].as_bool().expect("cut"))
        .map(|(_, (x, _))| *x)
        .collect();
    assert_eq!(cuts, expected);
    // A figure that cannot be written is named.
    let (code, _, err) = run(&[
        "replay",
        "--path",
        p,
        "--max-error",
        "2",
        "--figure",
        "/nonexistent-dir/f.svg",
    ]);
    assert_eq!(code, 1);
    assert!(
        err.starts_with("error: cannot write /nonexistent-dir/f.svg: "),
        "{err}"
    );
    let _ = std::fs::remove_file(&file);
    let _ = std::fs::remove_file(&svg_file);
}

/// `replay --budget-texels` keeps every frame within the budget, `--per-map` gives each map its
/// own resolution (their squares summing to the frame's texels), and a missing or bad goal is
/// refused naming its flag.
#[test]
fn replay_takes_a_budget_and_a_resolution_per_map() {
    let file = excerpt("goals", 0, 8, |_| {});
    let p = file.to_str().expect("a UTF-8 path");
    let json = |extra: &[&str]| -> Value {
        let mut argv = vec!["replay", "--path", p, "--json"];
        argv.extend_from_slice(extra);
        let (code, out, err) = run(&argv);
        assert_eq!(code, 0, "{extra:?}: {err}");
        serde_json::from_str(&out).expect("JSON")
    };
    let budget = 20_000_000u64;
    let v = json(&["--budget-texels", "20000000"]);
    assert_eq!(v["budget_texels"].as_u64(), Some(budget));
    assert!(v["max_error"].is_null());
    assert_eq!(v["per_map"], false);
    for f in v["frames"].as_array().expect("frames") {
        assert!(f["texels"].as_u64().unwrap() <= budget, "{f}");
        assert_eq!(f["within_budget"], true, "{f}");
    }
    assert_eq!(v["summary"]["over_budget"], 0);
    let v = json(&["--max-error", "2", "--per-map"]);
    assert_eq!(v["per_map"], true);
    let mut summed = 0;
    for f in v["frames"].as_array().expect("frames") {
        let each: Vec<u64> = f["resolutions"]
            .as_array()
            .expect("resolutions")
            .iter()
            .map(|r| r.as_u64().unwrap())
            .collect();
        let maps = f["maps"].as_u64().unwrap() as usize;
        assert!(each.len() >= maps, "{f}");
        assert_eq!(f["resolution"].as_u64(), each.iter().copied().max(), "{f}");
        if each.len() == maps {
            let sum: u64 = each.iter().map(|r| r * r).sum();
            assert_eq!(f["texels"].as_u64(), Some(sum), "{f}");
            summed += 1;
        }
        let e = f["max_error_pixels"].as_f64().unwrap();
        assert_eq!(f["meets_target"].as_bool(), Some(e <= 2.0), "{f}");
    }
    assert!(summed > 0);
    let (code, out, _) = run(&["replay", "--path", p, "--max-error", "2", "--per-map"]);
    assert_eq!(code, 0);
    assert!(out.contains(", a resolution per map"), "{out}");
    assert!(
        out.contains(" maps "),
        "each line lists the maps' resolutions: {out}"
    );
    for (args, want) in [
        (&[][..], "error: --max-error or --budget-texels is needed"),
        (
            &["--budget-texels", "0"][..],
            "error: --budget-texels must be at least 1 texel",
        ),
        (
            &["--budget-texels", "10"][..],
            "error: --budget-texels is 10, less than one map",
        ),
    ] {
        let mut argv = vec!["replay", "--path", p];
        argv.extend_from_slice(args);
        let (code, _, err) = run(&argv);
        assert_eq!(code, 1, "{args:?}");
        assert!(err.starts_with(want), "{args:?}: {err}");
    }
    let _ = std::fs::remove_file(&file);
}
