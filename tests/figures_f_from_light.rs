//! lloyd2006-fig11 and barroso-fig5, the frustum seen from the light (figure review 3), read
//! back from their SVGs in all three forms (captioned double column, `--bare`, `--column
//! single`):
//! - each split plane's leader starts at its own cross-section's corner (a dot), not at the
//!   drawing's right edge: fig11's anchors lie at x ∝ z tan θ, so their spacings double from
//!   plane to plane (z = 1, 2, 4, 8);
//! - the partitions' maps take the sweep palette, never a scheme's colour, and each has its own
//!   dash pattern (two maps of the same dash, or of a scheme colour, fail);
//! - the axes fit the drawing: barroso-fig5's frustum spans ±57.7 (100 tan 30°), so no tick reads
//!   "−100" (its axes ran to ±130 and "−100" touched "−50");
//! - the key naming the maps' strokes is in the figure (so in `--bare`), and the split planes are
//!   labelled "z = …" with the near and far planes "n = …", "f = …";
//! - no caption line ends or starts inside a formula ("=" at a line's end or start).
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render_with, Column, Format, Options};
use std::collections::BTreeMap;
use std::path::Path;

const FIGS: [&str; 2] = ["lloyd2006-fig11", "barroso-fig5"];

/// The three forms: (name, options).
fn forms() -> Vec<(&'static str, Options)> {
    vec![
        ("double", Options::default()),
        (
            "bare",
            Options {
                bare: true,
                ..Options::default()
            },
        ),
        (
            "single",
            Options {
                column: Column::Single,
                ..Options::default()
            },
        ),
    ]
}

fn svg(name: &str, form: &str, opts: &Options) -> String {
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "figures-f-{name}-{form}-{}-{call}",
        std::process::id()
    ));
    let files = render_with(name, &dir, Format::Svg, opts).unwrap();
    let s = std::fs::read_to_string(&files[0]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    s
}

fn attr<'a>(el: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let i = el.find(&key)? + key.len();
    Some(&el[i..i + el[i..].find('"')?])
}

fn num(el: &str, name: &str) -> f64 {
    attr(el, name).unwrap().parse().unwrap()
}

/// The elements (their text up to '>') of one kind.
fn elements<'a>(svg: &'a str, kind: &str) -> Vec<&'a str> {
    svg.split('<')
        .filter(|e| e.starts_with(kind))
        .map(|e| &e[..e.find('>').unwrap_or(e.len())])
        .collect()
}

fn points(el: &str) -> Vec<(f64, f64)> {
    attr(el, "points")
        .unwrap()
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').unwrap();
            (x.parse().unwrap(), y.parse().unwrap())
        })
        .collect()
}

/// The texts of an SVG (their content, tags inside dropped).
fn texts(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find("<text") {
        let open = i + rest[i..].find('>').unwrap();
        let close = open + rest[open..].find("</text>").unwrap();
        let inner = &rest[open + 1..close];
        let mut t = String::new();
        let mut depth = false;
        for c in inner.chars() {
            match c {
                '<' => depth = true,
                '>' => depth = false,
                c if !depth => t.push(c),
                _ => {}
            }
        }
        out.push(t.replace("&amp;", "&"));
        rest = &rest[close..];
    }
    out
}

/// The leader anchors (dark grey dots of radius 2) of fig11 and where the leaders (light grey
/// horizontal lines) start: each leader starts at a dot, and the dots' x spacings double from
/// plane to plane, as the squares' corners at x = z tan θ, z = 1, 2, 4, 8 do.
#[test]
fn fig11_leaders_start_at_their_squares_corners() {
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig11", form, &opts);
        let dots: Vec<(f64, f64)> = elements(&s, "circle")
            .into_iter()
            .filter(|e| attr(e, "fill") == Some("#5A5A5A"))
            .map(|e| (num(e, "cx"), num(e, "cy")))
            .collect();
        assert_eq!(dots.len(), 4, "{form}: {dots:?}");
        let leaders: Vec<Vec<(f64, f64)>> = elements(&s, "polyline")
            .into_iter()
            .filter(|e| attr(e, "stroke") == Some("#969696"))
            .map(points)
            .filter(|p| p.len() == 2 && p[0].1 == p[1].1 && p[1].0 - p[0].0 > 20.0)
            .collect();
        for d in &dots {
            assert!(
                leaders
                    .iter()
                    .any(|l| (l[0].0 - d.0).abs() <= 1.0 && (l[0].1 - d.1).abs() <= 1.0),
                "{form}: no leader starts at the dot {d:?}: {leaders:?}"
            );
        }
        let mut xs: Vec<f64> = dots.iter().map(|d| d.0).collect();
        xs.sort_by(f64::total_cmp);
        let gaps: Vec<f64> = xs.windows(2).map(|w| w[1] - w[0]).collect();
        // Whole-unit positions (each ±0.5, so a gap ±1): each gap is within 3 units of twice
        // the one before.
        for w in gaps.windows(2) {
            assert!(
                (w[1] - 2.0 * w[0]).abs() <= 3.0,
                "{form}: anchor spacings {gaps:?} do not double (z tan θ, z = 1, 2, 4, 8)"
            );
        }
    }
}

/// The maps' outlines (width-2 polylines not black): per colour, the lengths of their dashes.
fn map_dashes(svg: &str) -> BTreeMap<String, Vec<f64>> {
    let mut by: BTreeMap<String, Vec<f64>> = BTreeMap::new();
    for el in elements(svg, "polyline") {
        if attr(el, "stroke-width") != Some("2") || attr(el, "stroke") == Some("#000000") {
            continue;
        }
        let p = points(el);
        let len: f64 = p
            .windows(2)
            .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
            .sum();
        by.entry(attr(el, "stroke").unwrap().to_string())
            .or_default()
            .push(len);
    }
    by
}

/// The partitions' maps are a sweep (the purple palette: #3F007D, #582A92, #674CA0, #7B6DB4,
/// #9589C0), never a scheme colour (Okabe–Ito blue #0072B2, vermillion #D55E00, green
/// #009E73, orange #E69F00, pink #CC79A7), one colour per map; and no two maps share a dash
/// pattern: their sets of dash lengths (rounded to the unit, clipped pieces aside: the two
/// most frequent lengths) differ.
#[test]
fn maps_take_the_sweep_palette_and_each_its_own_dash() {
    let sweep = ["#3F007D", "#582A92", "#674CA0", "#7B6DB4", "#9589C0"];
    for (name, maps) in [("lloyd2006-fig11", 3), ("barroso-fig5", 4)] {
        for (form, opts) in forms() {
            let d = map_dashes(&svg(name, form, &opts));
            assert_eq!(d.len(), maps, "{name} {form}: {:?}", d.keys());
            let mut patterns = Vec::new();
            for (colour, lens) in &d {
                assert!(
                    sweep.contains(&colour.as_str()),
                    "{name} {form}: map colour {colour}"
                );
                let mut count: BTreeMap<i64, usize> = BTreeMap::new();
                for l in lens {
                    *count.entry(l.round() as i64).or_default() += 1;
                }
                let mut by_count: Vec<(usize, i64)> = count.iter().map(|(l, c)| (*c, *l)).collect();
                by_count.sort_by(|a, b| b.cmp(a));
                let mut top: Vec<i64> = by_count.iter().take(2).map(|x| x.1).collect();
                top.sort();
                patterns.push((colour.clone(), top));
            }
            for (i, a) in patterns.iter().enumerate() {
                for b in &patterns[i + 1..] {
                    assert_ne!(a.1, b.1, "{name} {form}: {} and {} share a dash", a.0, b.0);
                }
            }
        }
    }
}

/// barroso-fig5's axes fit the frustum (100 tan 30° = 57.7 across each side): no tick reads
/// "−100" or "±150", so "−100" no longer touches "−50"; and every panel has at least two
/// labelled ticks across.
#[test]
fn barroso_axes_fit_the_frustum() {
    for (form, opts) in forms() {
        let t = texts(&svg("barroso-fig5", form, &opts));
        for bad in ["−100", "−150", "150"] {
            assert!(!t.iter().any(|x| x == bad), "{form}: a tick reads {bad}");
        }
        // (a) to (c) span ±57.7: their ticks across are −50 and 50 (with 0 where it fits).
        assert!(
            t.iter().filter(|x| *x == "−50").count() >= 3,
            "{form}: {t:?}"
        );
    }
}

/// The key that names the strokes (maps nearest first, frustum, split plane) is in every form,
/// so in `--bare` too; the planes read "n = …", "z = …", "f = …" as in Lloyd's Fig 11.
#[test]
fn the_key_and_the_plane_labels_are_in_every_form() {
    for name in FIGS {
        for (form, opts) in forms() {
            let t = texts(&svg(name, form, &opts));
            for want in ["Maps, nearest first:", "frustum", "split plane"] {
                assert!(t.iter().any(|x| x == want), "{name} {form}: no {want:?}");
            }
            assert!(t.iter().any(|x| x.starts_with("n = 1")), "{name} {form}");
            assert!(t.iter().any(|x| x.starts_with("z = ")), "{name} {form}");
            assert!(t.iter().any(|x| x.starts_with("f = ")), "{name} {form}");
            // No bare depth: every plane label names its plane.
            assert!(
                !t.iter()
                    .any(|x| x == "31.62" || x == "3.162" || x == "40.81"),
                "{name} {form}: a bare depth label"
            );
        }
    }
}

/// No caption line of either figure, in double or single column, ends or starts inside a
/// formula: a line ending "=" or starting "=" would have broken "z = 4" across lines (the
/// captions join a formula's parts with no-break spaces). The captions are the grey
/// (#323232) texts, at most five lines.
#[test]
fn captions_break_no_formula_and_keep_to_five_lines() {
    for name in FIGS {
        for (form, opts) in forms() {
            if form == "bare" {
                continue;
            }
            let s = svg(name, form, &opts);
            let mut lines = Vec::new();
            let mut rest = s.as_str();
            while let Some(i) = rest.find("<text") {
                let open = i + rest[i..].find('>').unwrap();
                let close = open + rest[open..].find("</text>").unwrap();
                if rest[i..open].contains("fill=\"#323232\"") {
                    lines.push(rest[open + 1..close].replace('\u{a0}', " "));
                }
                rest = &rest[close..];
            }
            assert!((1..=5).contains(&lines.len()), "{name} {form}: {lines:?}");
            for l in &lines {
                let l = l.trim();
                assert!(
                    !l.ends_with('=') && !l.starts_with('='),
                    "{name} {form}: {l:?}"
                );
            }
            // A last line of one word is a widow.
            let last = lines.last().unwrap().trim();
            assert!(last.contains(' '), "{name} {form}: widow {last:?}");
        }
    }
}

/// The closed black polylines of stroke width 2 (the frustum's near and far faces, drawn as
/// thick as its side edges; the split planes are thin): their bounding boxes.
fn thick_faces(svg: &str) -> Vec<[f64; 4]> {
    elements(svg, "polyline")
        .into_iter()
        .filter(|e| attr(e, "stroke") == Some("#000000") && attr(e, "stroke-width") == Some("2"))
        .map(points)
        .filter(|p| p.len() == 5 && p[0] == p[4])
        .map(|p| {
            p.iter().fold(
                [
                    f64::INFINITY,
                    f64::INFINITY,
                    f64::NEG_INFINITY,
                    f64::NEG_INFINITY,
                ],
                |b, q| [b[0].min(q.0), b[1].min(q.1), b[2].max(q.0), b[3].max(q.1)],
            )
        })
        .collect()
}

/// The near and far faces are frustum edges, drawn at its weight (figure review 3: in
/// barroso-fig5 (c) and (f) the far face's lower edge, thin like a split plane, read as an
/// unexplained line). fig11: exactly two thick closed squares, concentric, the far one f/n = 8
/// times the near one's side (2f tan θ against 2n tan θ), within the whole-unit rounding;
/// barroso-fig5: the far face of each overview (a), (b), (c) is thick.
#[test]
fn near_and_far_faces_have_the_frustums_weight() {
    for (form, opts) in forms() {
        let faces = thick_faces(&svg("lloyd2006-fig11", form, &opts));
        assert_eq!(faces.len(), 2, "{form}: {faces:?}");
        let side = |b: &[f64; 4]| b[2] - b[0];
        let (near, far) = if side(&faces[0]) < side(&faces[1]) {
            (faces[0], faces[1])
        } else {
            (faces[1], faces[0])
        };
        let ratio = side(&far) / side(&near);
        assert!((ratio - 8.0).abs() < 0.6, "{form}: far/near {ratio}");
        let centre = |b: &[f64; 4]| ((b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0);
        let (a, b) = (centre(&near), centre(&far));
        assert!(
            (a.0 - b.0).abs() <= 1.0 && (a.1 - b.1).abs() <= 1.0,
            "{form}: {a:?} {b:?}"
        );
        let faces = thick_faces(&svg("barroso-fig5", form, &opts));
        assert!(faces.len() >= 3, "{form}: {faces:?}");
    }
}

/// fig11's labels keep the planes' order down the gutter: f = 8, z = 4, z = 2, n = 1 (a leader
/// choosing corners by spread alone once put n = 1 above z = 2 in one column).
#[test]
fn fig11_labels_keep_the_planes_order() {
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig11", form, &opts);
        let y = |label: &str| {
            let i = s
                .find(&format!(">{label}<"))
                .unwrap_or_else(|| panic!("{form}: {label}"));
            let open = s[..i].rfind("<text").unwrap();
            num(&s[open..i], "y")
        };
        let ys = [y("f = 8"), y("z = 4"), y("z = 2"), y("n = 1")];
        assert!(ys.windows(2).all(|w| w[0] < w[1]), "{form}: {ys:?}");
    }
}
