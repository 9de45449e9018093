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

mod figures_style_read;
use figures_style_read as read;
use figures_style_read::forms;
use shadow_aliasing::plot::{render_with, Format, Options};
use std::collections::BTreeMap;
use std::path::Path;

const FIGS: [&str; 2] = ["lloyd2006-fig11", "barroso-fig5"];

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

use read::attr_str as attr;

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

use read::points;

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
            .filter(|e| attr(e, "stroke") == Some("#949494"))
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

/// Whether a stroke colour is a grey (black included): the frustum's and the axes' black,
/// the box of the region a detail enlarges (#6E6E6E, barroso-fig5's overviews, figure review
/// 5), the leaders (#949494); every other polyline of these figures is a map's outline.
fn grey(colour: &str) -> bool {
    let c = colour.to_uppercase();
    c.len() == 7 && c[1..3] == c[3..5] && c[3..5] == c[5..7]
}

/// The maps' outlines (the polylines in a colour, not a grey): per colour, the lengths of
/// their dashes. lloyd2006-fig11's are 4 to 9 wide (the seventh review, R7-X-3: lines under
/// the frustum's, wider than them), barroso-fig5's 1 and 2 (R9-barroso-fig5-1).
fn map_dashes(svg: &str) -> BTreeMap<String, Vec<f64>> {
    let mut by: BTreeMap<String, Vec<f64>> = BTreeMap::new();
    for el in elements(svg, "polyline") {
        if attr(el, "stroke").is_none_or(grey) {
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

/// The maps' colours (R11-barroso-fig5-1, R11-X-1): the sweep's steps (the purple palette:
/// #3F007D, #582A92, #674CA0, #7B6DB4, #9589C0) and ochre #9A6A00, the third map's, a hue no
/// scheme has (Okabe–Ito's orange #E69F00 with each channel × 0.67, computed here).
fn map_palette() -> Vec<String> {
    let ochre: Vec<u8> = [0xE6u8, 0x9F, 0x00]
        .iter()
        .map(|&v| (0.67 * f64::from(v)) as u8)
        .collect();
    ["#3F007D", "#582A92", "#674CA0", "#7B6DB4", "#9589C0"]
        .iter()
        .map(|h| h.to_string())
        .chain([format!("#{:02X}{:02X}{:02X}", ochre[0], ochre[1], ochre[2])])
        .collect()
}

/// The partitions' maps take the maps' palette (the purple sweep and the third map's ochre),
/// never a scheme colour (Okabe–Ito blue #0072B2, vermillion #D55E00, green #009E73, orange
/// #E69F00, pink #CC79A7), one colour per map; and no two maps share a dash pattern: their
/// sets of dash lengths (rounded to the unit, clipped pieces aside: the two most frequent
/// lengths) differ.
#[test]
fn maps_take_the_sweep_palette_and_each_its_own_dash() {
    let palette = map_palette();
    assert_eq!(palette[5], "#9A6A00");
    for (name, maps) in [("lloyd2006-fig11", 3), ("barroso-fig5", 4)] {
        for (form, opts) in forms() {
            let d = map_dashes(&svg(name, form, &opts));
            assert_eq!(d.len(), maps, "{name} {form}: {:?}", d.keys());
            let mut patterns = Vec::new();
            for (colour, lens) in &d {
                assert!(
                    palette.contains(colour),
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
/// so in `--bare` too; the planes read "n = …", "z = …", "f = …" as in Lloyd's Fig 11, except
/// in barroso-fig5's one column, whose six narrow panels set each label on one line with thin
/// spaces, "z = 3.162" (figure review 4: "f =" over "100" read as broken; review 5: the depth
/// alone read as a tick value; review 6: only the details label their planes).
#[test]
fn the_key_and_the_plane_labels_are_in_every_form() {
    for name in FIGS {
        for (form, opts) in forms() {
            let t = texts(&svg(name, form, &opts));
            let depths = name == "barroso-fig5" && form == "single";
            for want in ["Maps, nearest first:", "frustum", "split plane"] {
                assert!(t.iter().any(|x| x == want), "{name} {form}: no {want:?}");
            }
            // No label broken over two lines.
            assert!(!t.iter().any(|x| x.ends_with(" =")), "{name} {form}");
            if depths {
                for want in ["n = 1", "z = 3.162", "z = 10", "z = 40.81", "z = 6.041"] {
                    let want = want.replace(' ', "\u{2009}");
                    assert!(t.contains(&want), "{name} {form}: no {want}");
                }
                assert!(!t.iter().any(|x| x.starts_with("z = ")), "{name} {form}");
                continue;
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
        .map(|p| read::bbox(&p))
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

/// Figure review 3, X6: the horizontal axis cannot read as "light minus x"; since figure review
/// 5 (X3) it is "light-view x" in every form of both figures.
#[test]
fn the_x_axis_cannot_read_as_minus() {
    for name in FIGS {
        for (form, opts) in forms() {
            let t = texts(&svg(name, form, &opts));
            assert!(!t.iter().any(|x| x == "light −x"), "{name} {form}");
            assert!(t.iter().any(|x| x == "light-view x"), "{name} {form}");
        }
    }
}

/// Where a map's outline lies on a black line both show (figure review 3: dashes drawn over a
/// split plane hid it in their gaps; the seventh review, R7-X-3: drawn beside it, 2 units out,
/// the map read as larger than its square). lloyd2006-fig11: every black line of the panel is
/// drawn after (over) every map outline, and each outline is at least 2 units wider than the
/// line it lies on, so it shows at least a unit on either side (maps 1 and 2 on the thin
/// squares z = 2, 4, map 3 on the far face, 2 wide). barroso-fig5 (b), whose fine outlines are
/// no wider than the frustum's edges (R9-barroso-fig5-1): every map is drawn after (over) every
/// black line, dashed where a side holds whole periods, so that the line shows in its gaps;
/// every outline 1.5 to 2 pt wide (R11-barroso-fig5-1: 1 pt outlines of near purples could not
/// be told apart); where two maps share an edge (z = 3.162, 10, 31.62) the nearer is drawn
/// over the farther, whose colour (another hue or 20 L* apart) shows in its gaps.
#[test]
fn maps_show_on_either_side_of_their_lines() {
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig11", form, &opts);
        let lines = lines_between(&s, "split plane", None);
        let is_map = |l: &Line| !grey(&l.colour);
        let last_map = lines.iter().rposition(is_map).unwrap();
        let first_black = lines
            .iter()
            .enumerate()
            .skip(lines.iter().position(is_map).unwrap())
            .find(|(_, l)| l.colour == "#000000")
            .unwrap()
            .0;
        assert!(last_map < first_black, "{form}: a map over a line");
        let width: BTreeMap<String, f64> = lines
            .iter()
            .filter(|l| is_map(l))
            .map(|l| (l.colour.clone(), l.width))
            .collect();
        let thickest = lines[first_black..]
            .iter()
            .filter(|l| l.colour == "#000000")
            .map(|l| l.width)
            .fold(0.0, f64::max);
        assert_eq!(thickest, 2.0, "{form}");
        for (colour, w) in &width {
            assert!(*w >= thickest + 2.0, "{form}: {colour} {w} wide");
        }
        // barroso-fig5 (b).
        let s = svg("barroso-fig5", form, &opts);
        let lines = lines_between(&s, "(b)", Some("(c)"));
        let first_map = lines.iter().position(is_map).unwrap();
        let last_black = lines.iter().rposition(|l| l.colour == "#000000").unwrap();
        assert!(last_black < first_map, "{form}: (b) a line over a map");
        let width: BTreeMap<String, f64> = lines
            .iter()
            .filter(|l| is_map(l))
            .map(|l| (l.colour.clone(), l.width))
            .collect();
        assert_eq!(width.len(), 4, "{form}: (b) maps {width:?}");
        // Every outline 1.5 to 2 pt wide (R11-barroso-fig5-1, R9-barroso-fig5-1).
        let pt = read::points_per_unit(&s);
        for (colour, w) in &width {
            assert!(
                (1.5..=2.0 + 1e-9).contains(&(w * pt)),
                "{form}: (b) {colour} {} pt wide",
                w * pt
            );
        }
        // Maps by depth in (b): the lower of their edges across, nearest (largest SVG y) first.
        let mut by: Vec<(f64, String)> = Vec::new();
        for colour in width.keys() {
            let (_, ys) = sides(
                &lines
                    .iter()
                    .filter(|l| &l.colour == colour)
                    .map(|l| l.points.clone())
                    .collect::<Vec<_>>(),
            );
            by.push((ys[ys.len() - 1], colour.clone()));
        }
        by.sort_by(|a, b| b.0.total_cmp(&a.0));
        // Where two maps share an edge the nearer is drawn over the farther, whose colour
        // shows in its gaps.
        for w in by.windows(2) {
            let (near, far) = (&w[0].1, &w[1].1);
            let last_far = lines.iter().rposition(|l| &l.colour == far).unwrap();
            let first_near = lines.iter().position(|l| &l.colour == near).unwrap();
            assert!(last_far < first_near, "{form}: {far} over {near}");
        }
    }
}

/// Maps 1 and 3 of lloyd2006-fig11 differ in kind, not only in dash length (figure review 3:
/// both dashed, they were one in greyscale): map 3 (ochre #9A6A00 since R11-X-1) is dash-dot,
/// its pieces of two lengths, dots (≤ 3 units) and dashes (≥ 9), while map 1 (#3F007D) has
/// dashes of one length.
#[test]
fn fig11_map_three_is_dash_dot() {
    for (form, opts) in forms() {
        let d = map_dashes(&svg("lloyd2006-fig11", form, &opts));
        let count =
            |lens: &[f64], keep: &dyn Fn(f64) -> bool| lens.iter().filter(|&&l| keep(l)).count();
        let three = &d["#9A6A00"];
        assert!(count(three, &|l| l <= 3.0) >= 8, "{form}: {three:?}");
        assert!(count(three, &|l| l >= 9.0) >= 8, "{form}: {three:?}");
        let one = &d["#3F007D"];
        // At most the two ends of its closed outline, where the pattern is cut, are short.
        assert!(count(one, &|l| l <= 3.0) <= 2, "{form}: {one:?}");
    }
}

/// lloyd2006-fig11's y axis is as long above the frustum as below (figure review 3: it ran to
/// −6.5 for the dimension under the far face and ended at 4.9 above): the labelled y ticks are
/// symmetric about 0 and within the far face's half-side 8 tan 30° = 4.62 (by hand), so no
/// "−6" labels the margin.
#[test]
fn fig11_y_axis_is_centred_on_the_frustum() {
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig11", form, &opts);
        let mut ys: Vec<f64> = Vec::new();
        let mut rest = s.as_str();
        while let Some(i) = rest.find("<text") {
            let open = i + rest[i..].find('>').unwrap();
            let close = open + rest[open..].find("</text>").unwrap();
            let tag = &rest[i..open];
            // The y ticks: right-aligned numbers.
            if attr(tag, "text-anchor") == Some("end") {
                if let Ok(v) = rest[open + 1..close].replace('−', "-").parse::<f64>() {
                    ys.push(v);
                }
            }
            rest = &rest[close..];
        }
        assert!(ys.len() >= 3, "{form}: {ys:?}");
        for v in &ys {
            assert!(v.abs() <= 4.62, "{form}: a y tick {v}");
            assert!(ys.contains(&-v), "{form}: {ys:?} not symmetric");
        }
    }
}

/// The maps' lines stand out from white: each at least 3:1 against white by WCAG's relative
/// luminance (computed here from the sRGB values; the lightest sweep step, #9589C0, map 2's
/// since R11-X-1, is 3.17:1, and the half tints of lloyd2006-fig11's old light bands, 2.7:1
/// and lighter, fail), and each narrow one (under 8 units wide) but map 2's at least 4:1
/// (figure review 3: "low contrast"); lloyd2006-fig11's even maps are bands at least 8 wide,
/// the width of a band behind lines (tests/figures_style_strokes.rs); barroso-fig5's outlines,
/// at most 2 wide since R9-barroso-fig5-1, have no bands.
#[test]
fn map_colours_have_contrast() {
    let lum = |hex: &str| {
        let c: Vec<f64> = (0..3)
            .map(|k| f64::from(u8::from_str_radix(&hex[1 + 2 * k..3 + 2 * k], 16).unwrap()) / 255.0)
            .map(|v| {
                if v <= 0.03928 {
                    v / 12.92
                } else {
                    ((v + 0.055) / 1.055).powf(2.4)
                }
            })
            .collect();
        0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]
    };
    let ratio = |hex: &str| 1.05 / (lum(hex) + 0.05);
    assert!((ratio("#9589C0") - 3.17).abs() < 0.01);
    // The old band of map 2, #582A92's half tint #AC95C9.
    assert!(ratio("#AC95C9") < 3.0);
    for name in FIGS {
        for (form, opts) in forms() {
            let s = svg(name, form, &opts);
            let (maps, _) = maps_and_frustum(&lines_between(&s, "split plane", None));
            let mut bands = 0;
            for (colour, _) in maps {
                let w = lines_between(&s, "split plane", None)
                    .iter()
                    .find(|l| l.colour == colour)
                    .unwrap()
                    .width;
                let r = ratio(&colour);
                assert!(r >= 3.0, "{name} {form}: {colour} at {r:.2}:1");
                if w >= 8.0 {
                    bands += 1;
                } else if colour != "#9589C0" {
                    assert!(r >= 4.0, "{name} {form}: {colour} at {r:.2}:1");
                }
            }
            if name == "lloyd2006-fig11" {
                assert!(bands >= 1, "{name} {form}");
            } else {
                assert_eq!(bands, 0, "{name} {form}");
            }
        }
    }
}

/// barroso-fig5's panel titles: on one baseline across each row and from one left edge down
/// each column, in every form (figure review 3: centred over cells narrowed to their drawings,
/// "(a) perpendicular" stood 9 units below "(b) parallel", and "(c) Eq 19, not in the paper"
/// started 3 units from the page's edge, left of (a) and (e)).
#[test]
fn barroso_titles_share_baselines_and_left_edges() {
    let font = read::Font::dejavu();
    for (form, opts) in forms() {
        let all = read::texts(&font, &svg("barroso-fig5", form, &opts));
        let title = |letter: &str| -> (f64, f64) {
            // Not a caption line (grey #323232) that starts with a panel's letter.
            let t = all
                .iter()
                .find(|t| t.content.starts_with(letter) && !t.tag.contains("#323232"))
                .unwrap_or_else(|| panic!("{form}: no title {letter}"));
            (t.bbox[0], t.y)
        };
        let [a, b, c, d, e, f] = ["(a)", "(b)", "(c)", "(d)", "(e)", "(f)"].map(title);
        for (l, r) in [(a, b), (c, d), (e, f)] {
            assert!((l.1 - r.1).abs() < 0.5, "{form}: baselines {l:?} {r:?}");
        }
        for col in [[a, c, e], [b, d, f]] {
            assert!(
                col.iter().all(|t| (t.0 - col[0].0).abs() < 0.5),
                "{form}: left edges {col:?}"
            );
        }
    }
}

/// No text of either figure comes within 3 units of the page's left or right edge, captioned or
/// in one column, nor outside the bare page (figure review 3: barroso-fig5's "(a) perpendicular" started 0.5 units from it in one
/// column), each text's box measured with DejaVu Sans' advance widths.
#[test]
fn no_text_within_three_units_of_the_edge() {
    let font = read::Font::dejavu();
    for name in FIGS {
        for (form, opts) in forms() {
            let s = svg(name, form, &opts);
            let head = &s[..s.find('>').unwrap()];
            let vb: Vec<f64> = read::attr_str(head, "viewBox")
                .unwrap()
                .split_whitespace()
                .map(|v| v.parse().unwrap())
                .collect();
            let (x0, x1) = (vb[0], vb[0] + vb[2]);
            for t in read::texts(&font, &s) {
                if t.content.trim().is_empty() {
                    continue;
                }
                // A bare page is cut 2 units from its ink (tests/figures_bare.rs checks 1.5 to
                // 3 units of white): its texts' advance boxes lie inside it.
                let edge = if form == "bare" { 0.0 } else { 3.0 };
                assert!(
                    t.bbox[0] >= x0 + edge && t.bbox[2] <= x1 - edge,
                    "{name} {form}: {:?} spans {:.1}–{:.1} of {x0}–{x1}",
                    t.content,
                    t.bbox[0],
                    t.bbox[2]
                );
            }
        }
    }
}

/// barroso-fig5 in one column sets its text as the other one-column figures do (figure review
/// 3, X9: its ticks and labels were 8.065 units, 6.45 pt printed, against 10.48 units, 8.4 pt,
/// elsewhere): every text but the page's title and caption is at least 10.48 units, and the
/// plane labels and ticks are 10.48 (13 / 1.24 = 10.484, plotters' size in the SVG).
#[test]
fn barroso_single_type_matches_the_other_single_figures() {
    let font = read::Font::dejavu();
    let s = svg("barroso-fig5", "single", &forms()[2].1);
    let all = read::texts(&font, &s);
    assert!(!all.is_empty());
    for t in &all {
        assert!(t.fs >= 10.48, "{:?} at {}", t.content, t.fs);
    }
    for want in ["z\u{2009}=\u{2009}3.162", "−50", "Maps, nearest first:"] {
        let t = all.iter().find(|t| t.content == want).unwrap();
        assert!((t.fs - 13.0 / 1.24).abs() < 0.01, "{want}: {}", t.fs);
    }
}

/// barroso-fig5's caption names Barroso's α as his target ratio (figure review 3, X2: α is f/n
/// in the Lloyd figures), and names the thick line across (c) and (f), which is the far face's
/// lower edge seen from a light 45° up, not a split plane; (f) names it in the figure too, so
/// `--bare` keeps it, and so does one column.
#[test]
fn barroso_alpha_is_the_target_ratio_and_the_far_face_is_named() {
    let s = svg("barroso-fig5", "double", &Options::default());
    let flat = s.replace('\u{a0}', " ");
    assert!(
        flat.contains("target ratio α = 2 (Barroso&apos;s Eq 19)")
            || flat.contains("target ratio α = 2 (Barroso's Eq 19)"),
        "no target ratio in the caption"
    );
    assert!(flat.contains("far face"));
    // In every form, one column's too (the eighth review, R8-barroso-fig5-2: its caption's "thick
    // line: the far face" could mean any thick edge, and no tag said which): "far face" is a
    // label in (f)'s gutter, its left edge at the planes' labels' ("z = 40.81"), with a grey
    // leader (#949494) ending just left of it at its height (bent there in one column).
    let font = read::Font::dejavu();
    for (form, opts) in forms() {
        let s = svg("barroso-fig5", form, &opts);
        let all = read::texts(&font, &s);
        let plain = |c: &str| c.replace(['\u{a0}', '\u{2009}', '\u{202f}'], " ");
        // The last of each: (f) is drawn after (e).
        let last = |c: &str| {
            all.iter()
                .rev()
                .find(|t| plain(&t.content) == c)
                .unwrap_or_else(|| panic!("{form}: no {c:?}"))
        };
        let (far, plane) = (last("far face"), last("z = 40.81"));
        assert!(
            (far.bbox[0] - plane.bbox[0]).abs() < 1.0,
            "{form}: {:?} against {:?}",
            far.bbox,
            plane.bbox
        );
        let leader = elements(&s, "polyline")
            .into_iter()
            .filter(|e| attr(e, "stroke") == Some("#949494"))
            .map(points)
            .any(|p| {
                let end = p[p.len() - 1];
                (end.1 - far.y).abs() < 0.5 && (far.x - end.0).abs() < 4.0
            });
        assert!(leader, "{form}: no leader to \"far face\" at y {}", far.y);
    }
}

/// A `<polyline>` as drawn: its colour, stroke width and points.
struct Line {
    colour: String,
    width: f64,
    points: Vec<(f64, f64)>,
}

/// The polylines of `svg` after the first text whose content starts with `from` and before the
/// next one starting with `to` (a panel's elements, from its title to the next panel's).
fn lines_between(svg: &str, from: &str, to: Option<&str>) -> Vec<Line> {
    let start = read::title_at(svg, 0, from).unwrap_or_else(|| panic!("no text {from:?}"));
    let end = to.map_or(svg.len(), |t| {
        read::title_at(svg, start + 1, t).unwrap_or(svg.len())
    });
    svg[start..end]
        .lines()
        .filter(|l| l.starts_with("<polyline"))
        .map(|l| Line {
            colour: attr(l, "stroke").unwrap_or("").to_uppercase(),
            width: num(l, "stroke-width"),
            points: points(l),
        })
        .collect()
}

/// Polylines by colour.
type ByColour = BTreeMap<String, Vec<Vec<(f64, f64)>>>;

/// A panel's maps (their dashes by colour) and the frustum's black lines: the maps' outlines
/// are every stroke not a grey ([`grey`]); the black lines those after the first stroke not
/// black (a leader or a map), so that the axes and their ticks, drawn first, are left out.
fn maps_and_frustum(lines: &[Line]) -> (ByColour, Vec<&Line>) {
    let is_map = |l: &Line| !grey(&l.colour);
    assert!(lines.iter().any(is_map), "a map outline");
    let first = lines
        .iter()
        .position(|l| l.colour != "#000000")
        .expect("a stroke not black");
    let mut maps: ByColour = BTreeMap::new();
    for l in lines.iter().filter(|l| is_map(l)) {
        maps.entry(l.colour.clone())
            .or_default()
            .push(l.points.clone());
    }
    let black = lines[first..]
        .iter()
        .filter(|l| l.colour == "#000000")
        .collect();
    (maps, black)
}

/// Each dash of a map outline runs along the rectangle, turning at most at its corners: each
/// of its segments is horizontal or vertical; its fixed coordinate, and whether it is an x (a
/// vertical segment).
fn dash_sides(dashes: &[Vec<(f64, f64)>]) -> Vec<(bool, f64)> {
    dashes
        .iter()
        .flat_map(|d| d.windows(2))
        .filter(|w| w[0] != w[1])
        .map(|w| {
            let b = read::bbox(w);
            if b[2] - b[0] <= 1e-6 {
                (true, b[0])
            } else {
                assert!(b[3] - b[1] <= 1e-6, "a slanted dash {w:?}");
                (false, b[1])
            }
        })
        .collect()
}

/// A map outline's sides read from its dashes: the x's of its vertical segments and the y's of
/// its horizontal ones, each side once (a side's dashes share their coordinate exactly).
fn sides(dashes: &[Vec<(f64, f64)>]) -> (Vec<f64>, Vec<f64>) {
    let (mut xs, mut ys) = (Vec::new(), Vec::new());
    for (vertical, at) in dash_sides(dashes) {
        let v = if vertical { &mut xs } else { &mut ys };
        if !v.iter().any(|&u: &f64| (u - at).abs() < 1e-9) {
            v.push(at);
        }
    }
    xs.sort_by(f64::total_cmp);
    ys.sort_by(f64::total_cmp);
    (xs, ys)
}

/// Whether `half` is `d` tan θ page units (`k` a light-space unit) for one of the depths
/// `planes`, within `tol`: that depth.
fn on_square(half: f64, planes: &[f64], t: f64, k: f64, tol: f64) -> Option<f64> {
    planes
        .iter()
        .copied()
        .find(|d| (half - d * t * k).abs() <= tol + 1e-9)
}

/// R7-X-3 / R7-2006f11-1 (lloyd2006-fig11): every map outline lies exactly on its far plane's
/// square, half-side z tan θ for z = 2, 4, 8 (the self-similar splits n (f/n)^{i/3} of n = 1,
/// f = 8), within 0.1 pt, in every form; the old outlines lay 2 units outside (the review
/// measured ±1.20, 2.38, 4.73 against ±1.155, 2.309, 4.619). The page's scale is read from the
/// far face (half-side f tan θ), the centre from the near and far faces, and the thin
/// split-plane squares are checked at z = 2 and 4 too.
#[test]
fn fig11_maps_lie_on_their_far_planes() {
    let t = 30f64.to_radians().tan();
    let planes: Vec<f64> = (0..4).map(|i| 8f64.powf(f64::from(i) / 3.0)).collect();
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig11", form, &opts);
        let tol = 0.1 / read::points_per_unit(&s);
        let lines = lines_between(&s, "split plane", None);
        let (maps, black) = maps_and_frustum(&lines);
        let closed: Vec<([f64; 4], f64)> = black
            .iter()
            .filter(|l| l.points.len() == 5 && l.points[0] == l.points[4])
            .map(|l| (read::bbox(&l.points), l.width))
            .collect();
        let half = |b: &[f64; 4]| 0.25 * (b[2] - b[0] + b[3] - b[1]);
        let centre = |b: &[f64; 4]| (0.5 * (b[0] + b[2]), 0.5 * (b[1] + b[3]));
        let mut thick: Vec<[f64; 4]> = closed.iter().filter(|c| c.1 == 2.0).map(|c| c.0).collect();
        thick.sort_by(|a, b| half(a).total_cmp(&half(b)));
        assert_eq!(thick.len(), 2, "{form}: {thick:?}");
        let (near, far) = (thick[0], thick[1]);
        let k = half(&far) / (8.0 * t);
        let c = centre(&far);
        assert!((half(&near) - t * k).abs() <= tol, "{form}: near {near:?}");
        let mut thin: Vec<[f64; 4]> = closed.iter().filter(|c| c.1 == 1.0).map(|c| c.0).collect();
        thin.sort_by(|a, b| half(a).total_cmp(&half(b)));
        assert_eq!(thin.len(), 2, "{form}: {thin:?}");
        for (b, z) in thin.iter().zip(&planes[1..3]) {
            assert!(
                (half(b) - z * t * k).abs() <= tol,
                "{form}: the z = {z} square's half-side {} against {}",
                half(b),
                z * t * k
            );
        }
        // Each map's sides: two across, two up, on the square of z = 2, 4 or 8, one each.
        assert_eq!(maps.len(), 3, "{form}: {:?}", maps.keys());
        let mut found = Vec::new();
        for (colour, dashes) in &maps {
            let (xs, ys) = sides(dashes);
            assert!(
                xs.len() == 2 && ys.len() == 2,
                "{form}: {colour} {xs:?} {ys:?}"
            );
            let b = [xs[0], ys[0], xs[1], ys[1]];
            let z = on_square(half(&b), &planes[1..], t, k, tol).unwrap_or_else(|| {
                panic!(
                    "{form}: {colour}'s half-sides {:?} on no far plane's square {:?}",
                    (0.5 * (b[2] - b[0]), 0.5 * (b[3] - b[1])),
                    planes[1..].iter().map(|z| z * t * k).collect::<Vec<_>>()
                )
            });
            for h in [0.5 * (b[2] - b[0]), 0.5 * (b[3] - b[1])] {
                assert!(
                    (h - z * t * k).abs() <= tol + 1e-9,
                    "{form}: {colour} {b:?}"
                );
            }
            let m = centre(&b);
            assert!(
                (m.0 - c.0).abs() <= tol + 1e-9 && (m.1 - c.1).abs() <= tol + 1e-9,
                "{form}: {colour} centred at {m:?}, the frustum at {c:?}"
            );
            found.push(z);
        }
        found.sort_by(f64::total_cmp);
        assert_eq!(found, planes[1..].to_vec(), "{form}");
    }
}

/// R7-X-3 / R7-B5-2 (barroso-fig5 (b), the light overhead, z ≤ 31.62 since R9-barroso-fig5-1):
/// the edge-on planes z = 1, 3.162, 10, 31.62 lie at Eq 5's depths (100^{i/4}: the z = 3.162
/// and z = 31.62 lines where the near face and the z = 10 line put them, within 0.1 pt); every
/// map outline's edge across lies on one of them and its sides at x = ±z tan θ of its far
/// plane, within 0.1 pt; where two maps share an edge both are drawn on it: at z = 3.162 maps 1
/// and 2, at z = 10 maps 2 and 3, at z = 31.62 maps 3 and 4 (the review read map 2's top at
/// 10.3 and map 3's bottom at 9.7). (d), the light behind: each map's dashes
/// lie on its far plane's square (half-side z tan θ), as in lloyd2006-fig11.
#[test]
fn barroso_maps_lie_on_their_planes() {
    let t = 30f64.to_radians().tan();
    let z: Vec<f64> = (0..5).map(|i| 100f64.powf(f64::from(i) / 4.0)).collect();
    for (form, opts) in forms() {
        let s = svg("barroso-fig5", form, &opts);
        let tol = 0.1 / read::points_per_unit(&s);
        let lines = lines_between(&s, "(b)", Some("(c)"));
        let (maps, black) = maps_and_frustum(&lines);
        // The edge-on planes: black horizontal segments (y, left, right), near face first.
        let mut flat: Vec<(f64, f64, f64)> = black
            .iter()
            .filter(|l| l.points.len() == 2 && l.points[0].1 == l.points[1].1)
            .map(|l| {
                let (a, b) = (l.points[0].0, l.points[1].0);
                (l.points[0].1, a.min(b), a.max(b))
            })
            .collect();
        flat.sort_by(|a, b| b.0.total_cmp(&a.0));
        assert_eq!(flat.len(), 4, "{form}: {flat:?}");
        let y = |d: f64| flat[0].0 + (d - z[0]) * (flat[2].0 - flat[0].0) / (z[2] - z[0]);
        for i in [1, 3] {
            assert!(
                (flat[i].0 - y(z[i])).abs() <= tol,
                "{form}: the z = {} plane at {} against {}",
                z[i],
                flat[i].0,
                y(z[i])
            );
        }
        // Across: the z = 10 plane is 2 · 10 tan θ long, centred on the axis.
        let k = (flat[2].2 - flat[2].1) / (2.0 * z[2] * t);
        let cx = 0.5 * (flat[2].1 + flat[2].2);
        let mut at_plane: BTreeMap<usize, Vec<String>> = BTreeMap::new();
        for (colour, dashes) in &maps {
            let (xs, ys) = sides(dashes);
            for at in ys {
                let i = (0..4)
                    .find(|&i| (at - y(z[i])).abs() <= tol + 1e-9)
                    .unwrap_or_else(|| {
                        panic!(
                            "{form}: an edge of {colour} at y {at}, the planes at {:?}",
                            [y(z[0]), y(z[1]), y(z[2]), y(z[3])]
                        )
                    });
                at_plane.entry(i).or_default().push(colour.clone());
            }
            if xs.len() == 2 {
                let h = 0.5 * (xs[1] - xs[0]);
                assert!(
                    on_square(h, &z[1..], t, k, tol).is_some(),
                    "{form}: {colour}'s half-width {h}, no far plane's"
                );
                assert!((0.5 * (xs[0] + xs[1]) - cx).abs() <= tol + 1e-9, "{form}");
            }
        }
        for i in [1, 2, 3] {
            let c = at_plane.get(&i).cloned().unwrap_or_default();
            assert_eq!(c.len(), 2, "{form}: maps on z = {}: {c:?}", z[i]);
        }
        // (d): the light behind, squares; the scale from z = 10's (the largest thin one).
        let lines = lines_between(&s, "(d)", Some("(e)"));
        let (maps, black) = maps_and_frustum(&lines);
        let big = black
            .iter()
            .filter(|l| l.width == 1.0 && l.points.len() == 5)
            .map(|l| read::bbox(&l.points))
            .max_by(|a, b| (a[2] - a[0]).total_cmp(&(b[2] - b[0])))
            .unwrap();
        let k = 0.5 * (big[2] - big[0]) / (z[2] * t);
        assert!(maps.len() >= 2, "{form}: (d) {:?}", maps.keys());
        for (colour, dashes) in &maps {
            let (xs, ys) = sides(dashes);
            for v in [xs, ys] {
                if v.len() == 2 {
                    let h = 0.5 * (v[1] - v[0]);
                    assert!(
                        on_square(h, &z[1..], t, k, tol).is_some(),
                        "{form}: (d) {colour}'s half-side {h}, no far plane's"
                    );
                }
            }
        }
    }
}

/// R7-2006f11-2 (lloyd2006-fig11): the four plane labels stand at their own corners' heights, so
/// that every leader runs straight (the review: "n = 1"'s leader bent while the others were
/// straight, its label spread 5 units below its corner): each label's centre line is within
/// half a unit of its anchor dot's height across two columns and bare, and within 4 units in one
/// column, where the corners of n = 1 and z = 2 are 8 units apart (it was 8 below).
#[test]
fn fig11_labels_at_their_corners_heights() {
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig11", form, &opts);
        let mut dots: Vec<f64> = elements(&s, "circle")
            .into_iter()
            .filter(|e| attr(e, "fill") == Some("#5A5A5A"))
            .map(|e| num(e, "cy"))
            .collect();
        dots.sort_by(f64::total_cmp);
        let y = |label: &str| {
            let i = s.find(&format!(">{label}<")).unwrap();
            num(&s[s[..i].rfind("<text").unwrap()..i], "y")
        };
        // Top to bottom, as the dots.
        let labels = [y("f = 8"), y("z = 4"), y("z = 2"), y("n = 1")];
        let most = if form == "single" { 4.0 } else { 0.5 };
        for (l, d) in labels.iter().zip(&dots) {
            assert!(
                (l - d).abs() <= most,
                "{form}: labels {labels:?}, dots {dots:?}"
            );
        }
    }
}

/// R7-B5-4 (barroso-fig5, two columns): the details (b), (d), (f) have no y name of their own
/// and ten times smaller ticks than their overviews; the caption says they share the units.
#[test]
fn barroso_caption_says_the_details_share_the_units() {
    let t = texts(&svg("barroso-fig5", "double", &Options::default()));
    let caption = t
        .iter()
        .skip_while(|x| !x.starts_with("Barroso"))
        .cloned()
        .collect::<Vec<_>>()
        .join(" ");
    assert!(caption.contains("same units"), "{caption}");
    // The ticks: (a) reads 100 and (b) 10 up, in the same units.
    assert!(t.iter().any(|x| x == "100") && t.iter().any(|x| x == "10"));
}

/// One panel's axes read from an SVG: the data range its plot shows, from its tick labels'
/// positions (a line fitted through value against position, across and up) taken at its axis
/// lines' ends, and the linear maps data → SVG unit.
#[derive(Debug)]
struct PanelAxes {
    /// Where the y axis line stands (its x) and the x axis line (its y), in SVG units.
    at: (f64, f64),
    /// Data range shown: (x min, x max), (y min, y max).
    range: ((f64, f64), (f64, f64)),
    /// SVG unit = a + b · value, across and up.
    map: ((f64, f64), (f64, f64)),
    /// The labelled values the maps were fitted through, across and up.
    ticks: (Vec<f64>, Vec<f64>),
}

/// How far off (SVG units) the position of value `v` can be when read through the least-squares
/// line fitted to tick labels at `vals` whose positions are each rounded to a whole unit (the SVG
/// writes text at whole units): the estimate is Σ cᵢ pᵢ with cᵢ = 1/n + (v − v̄)(vᵢ − v̄)/S, S =
/// Σ (vⱼ − v̄)², so each position's error of at most half a unit adds at most ½ Σ |cᵢ|. Far
/// outside the ticks it grows: (e)'s lower limit, −1.5 read from the ticks 50 and 100, is off
/// by up to ½ (2.03 + 1.03) = 1.53 units.
fn read_error(vals: &[f64], v: f64) -> f64 {
    let n = vals.len() as f64;
    let mean = vals.iter().sum::<f64>() / n;
    let s: f64 = vals.iter().map(|u| (u - mean).powi(2)).sum();
    0.5 * vals
        .iter()
        .map(|u| (1.0 / n + (v - mean) * (u - mean) / s).abs())
        .sum::<f64>()
}

/// The line a + b·v through (v, p) by least squares.
fn fit_line(pts: &[(f64, f64)]) -> (f64, f64) {
    let n = pts.len() as f64;
    let (mv, mp) = (
        pts.iter().map(|q| q.0).sum::<f64>() / n,
        pts.iter().map(|q| q.1).sum::<f64>() / n,
    );
    let b = pts.iter().map(|q| (q.0 - mv) * (q.1 - mp)).sum::<f64>()
        / pts.iter().map(|q| (q.0 - mv).powi(2)).sum::<f64>();
    (mp - b * mv, b)
}

/// The panels with both axes labelled (their tick labels numbers, "−" the minus sign), in
/// reading order (rows of two, top to bottom, left to right): each axis line is a black 1-unit
/// two-point line with tick labels beside it, the y axis's left of it (anchored at their end),
/// the x axis's below it (centred); a y axis and an x axis form a panel where they meet.
fn panel_axes(svg: &str) -> Vec<PanelAxes> {
    let font = read::Font::dejavu();
    let ticks: Vec<(f64, f64, f64, bool)> = read::texts(&font, svg)
        .iter()
        .filter(|t| !t.rotated)
        .filter_map(|t| {
            let v: f64 = t.content.replace('−', "-").parse().ok()?;
            Some((v, t.x, t.y, attr(&t.tag, "text-anchor") == Some("end")))
        })
        .collect();
    let lines: Vec<((f64, f64), (f64, f64))> = elements(svg, "polyline")
        .into_iter()
        .filter(|e| attr(e, "stroke") == Some("#000000") && num(e, "stroke-width") == 1.0)
        .filter_map(|e| match points(e)[..] {
            [a, b] => Some((a, b)),
            _ => None,
        })
        .collect();
    let mut out = Vec::new();
    for &(a, b) in lines
        .iter()
        .filter(|(a, b)| a.0 == b.0 && (a.1 - b.1).abs() > 20.0)
    {
        let (x, y0, y1) = (a.0, a.1.min(b.1), a.1.max(b.1));
        let ys: Vec<(f64, f64)> = ticks
            .iter()
            .filter(|t| {
                t.3 && x - t.1 > 3.0 && x - t.1 < 15.0 && t.2 >= y0 - 0.5 && t.2 <= y1 + 0.5
            })
            .map(|t| (t.0, t.2))
            .collect();
        // The x axis meeting it at its foot.
        let Some(&(c, d)) = lines.iter().find(|(c, d)| {
            c.1 == d.1 && (c.1 - y1).abs() <= 2.0 && (c.0.min(d.0) - x).abs() <= 2.0
        }) else {
            continue;
        };
        let (xy, x0, x1) = (c.1, c.0.min(d.0), c.0.max(d.0));
        let xs: Vec<(f64, f64)> = ticks
            .iter()
            .filter(|t| {
                !t.3 && t.2 - xy > 3.0 && t.2 - xy < 15.0 && t.1 >= x0 - 0.5 && t.1 <= x1 + 0.5
            })
            .map(|t| (t.0, t.1))
            .collect();
        if xs.len() < 2 || ys.len() < 2 {
            continue;
        }
        let (mx, my) = (fit_line(&xs), fit_line(&ys));
        let inv = |m: (f64, f64), p: f64| (p - m.0) / m.1;
        out.push(PanelAxes {
            at: (x, xy),
            // The plot's edges: the x axis line's ends across, the y axis line's up (its top
            // the largest value: SVG y grows down).
            range: ((inv(mx, x0), inv(mx, x1)), (inv(my, y1), inv(my, y0))),
            map: (mx, my),
            ticks: (
                xs.iter().map(|t| t.0).collect(),
                ys.iter().map(|t| t.0).collect(),
            ),
        });
    }
    // Rows by their x axes' heights (in one column an overview's and its detail's differ by a
    // few units), then, in each row of two, left to right.
    out.sort_by(|p, q| p.at.1.total_cmp(&q.at.1));
    for row in out.chunks_mut(2) {
        row.sort_by(|p, q| p.at.0.total_cmp(&q.at.0));
    }
    out
}

/// The eighth review, R8-barroso-fig5-1: the grey box in each overview (a), (c), (e) outlines
/// the range its detail (b), (d), (f) shows, as the caption says ("(b), (d), (f) enlarge the
/// grey boxes"): the detail's axis limits, read from its tick labels at its axis lines' ends,
/// mapped through the overview's own ticks, and moved 3 units outwards (the twelfth review), lie
/// within 0.5 pt of the box's corners in every form, plus what reading the positions through tick labels written at whole units can
/// be off ([`read_error`], in both panels: up to 1.6 units for (e)'s lower edge, extrapolated
/// from the ticks 50 and 100, where the box is read 1.3 units off since R9-barroso-fig5-1 made
/// the overviews' outlines fine and their plots larger). The old box was the detail's window
/// grown by the maps' reach: (a)'s ±17.3 for (b)'s ±6.1, 11 pt off in two columns.
#[test]
fn barroso_grey_boxes_are_their_details_axis_limits() {
    // The twelfth review, R12-barroso-fig5-1: on the limits the box lay under the maps'
    // outlines ((c)'s under map 2's), so it is drawn 3 units outside them: its line's half
    // width, a unit of white, and a 2-unit outline's half width.
    const OUT: f64 = 3.0;
    for (form, opts) in forms() {
        let svg = svg("barroso-fig5", form, &opts);
        let pt = read::points_per_unit(&svg);
        let panels = panel_axes(&svg);
        assert_eq!(panels.len(), 6, "{form}: {panels:#?}");
        let boxes: Vec<Vec<(f64, f64)>> = elements(&svg, "polyline")
            .into_iter()
            .filter(|e| attr(e, "stroke") == Some("#6E6E6E"))
            .map(points)
            .collect();
        assert_eq!(boxes.len(), 3, "{form}: {boxes:?}");
        for (k, (overview, detail)) in [(0, 1), (2, 3), (4, 5)].into_iter().enumerate() {
            let (o, d) = (&panels[overview], &panels[detail]);
            // The detail's ranges in the overview's SVG units.
            let to = |m: (f64, f64), v: f64| m.0 + m.1 * v;
            let want_x = [to(o.map.0, d.range.0 .0), to(o.map.0, d.range.0 .1)];
            let want_y = [to(o.map.1, d.range.1 .1), to(o.map.1, d.range.1 .0)];
            // The box that lies in this overview: its corners' ranges.
            let b = boxes
                .iter()
                .find(|b| {
                    let cx = b.iter().map(|q| q.0).sum::<f64>() / b.len() as f64;
                    let cy = b.iter().map(|q| q.1).sum::<f64>() / b.len() as f64;
                    cx > o.at.0 && cx < d.at.0 && (cy - 0.5 * (want_y[0] + want_y[1])).abs() < 40.0
                })
                .unwrap_or_else(|| panic!("{form}: no box in overview {k}: {boxes:?}"));
            let bx = b
                .iter()
                .map(|q| q.0)
                .fold((f64::MAX, f64::MIN), |m, v| (m.0.min(v), m.1.max(v)));
            let by = b
                .iter()
                .map(|q| q.1)
                .fold((f64::MAX, f64::MIN), |m, v| (m.0.min(v), m.1.max(v)));
            // How far off each wanted edge may be read: the overview's reading of the detail's
            // limit, and the detail's reading of its limit, scaled into the overview.
            let err = |across: bool, v: f64| {
                let (ot, dt, om, dm) = if across {
                    (&o.ticks.0, &d.ticks.0, o.map.0, d.map.0)
                } else {
                    (&o.ticks.1, &d.ticks.1, o.map.1, d.map.1)
                };
                read_error(ot, v) + read_error(dt, v) * (om.1 / dm.1).abs()
            };
            // The box runs OUT units outside the limits (R12-barroso-fig5-1), in SVG order.
            let (lx, hx) = (want_x[0].min(want_x[1]), want_x[0].max(want_x[1]));
            let (ly, hy) = (want_y[0].min(want_y[1]), want_y[0].max(want_y[1]));
            for (got, want, tol) in [
                (bx.0, lx - OUT, err(true, d.range.0 .0)),
                (bx.1, hx + OUT, err(true, d.range.0 .1)),
                (by.0, ly - OUT, err(false, d.range.1 .1)),
                (by.1, hy + OUT, err(false, d.range.1 .0)),
            ] {
                assert!(
                    (got - want).abs() <= 0.5 / pt + tol,
                    "{form}: overview {k}: box edge {got:.2} where the detail's limit maps to \
                     {want:.2} (detail {:?}; box x {bx:?} y {by:?}, wanted x {want_x:?} y {want_y:?})",
                    d.range
                );
            }
        }
    }
}

/// The sides of a map's outline read from its pieces: each axis-aligned segment on the side it
/// lies on (bottom, top: SVG y of the bounding box's min and max; left, right: x), as
/// intervals along it, touching ones joined. Returns the bounding box (x0, y0, x1, y1) and the
/// four sides' intervals in the order top (SVG y min), bottom, left, right.
#[allow(clippy::type_complexity)]
fn outline_sides(pieces: &[Vec<(f64, f64)>]) -> ([f64; 4], [Vec<(f64, f64)>; 4]) {
    let pts: Vec<(f64, f64)> = pieces.iter().flatten().copied().collect();
    let b = read::bbox(&pts);
    let mut sides: [Vec<(f64, f64)>; 4] = Default::default();
    for w in pieces.iter().flat_map(|p| p.windows(2)) {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        let (k, a, c) = if (y0 - y1).abs() <= 1e-6 {
            let k = if (y0 - b[1]).abs() <= 1e-6 {
                0
            } else if (y0 - b[3]).abs() <= 1e-6 {
                1
            } else {
                panic!("a segment across inside the outline {w:?}, box {b:?}")
            };
            (k, x0.min(x1), x0.max(x1))
        } else {
            assert!((x0 - x1).abs() <= 1e-6, "a slanted segment {w:?}");
            let k = if (x0 - b[0]).abs() <= 1e-6 {
                2
            } else if (x0 - b[2]).abs() <= 1e-6 {
                3
            } else {
                panic!("a segment up inside the outline {w:?}, box {b:?}")
            };
            (k, y0.min(y1), y0.max(y1))
        };
        sides[k].push((a, c));
    }
    for s in &mut sides {
        s.sort_by(|p, q| p.0.total_cmp(&q.0));
        let mut joined: Vec<(f64, f64)> = Vec::new();
        for &(a, c) in s.iter() {
            match joined.last_mut() {
                Some(last) if a <= last.1 + 1e-6 => last.1 = last.1.max(c),
                _ => joined.push((a, c)),
            }
        }
        *s = joined;
    }
    (b, sides)
}

/// The period of the dashes along one side (`dashes`: intervals along it): from each dash's
/// start to the start of the next dash of its own length (within 5 %), the longest such (a
/// dash-dot's period spans a dash and a dot); `None` for a side drawn in one piece.
fn dash_period(dashes: &[(f64, f64)]) -> Option<f64> {
    if dashes.len() < 2 {
        return None;
    }
    let len = |d: &(f64, f64)| d.1 - d.0;
    let mut period: f64 = 0.0;
    for (i, d) in dashes.iter().enumerate() {
        if let Some(e) = dashes[i + 1..]
            .iter()
            .find(|e| (len(e) - len(d)).abs() <= 0.05 * len(d))
        {
            period = period.max(e.0 - d.0);
        }
    }
    Some(period)
}

/// The ninth review, R9-barroso-fig5-1: in the overviews (a), (c), (e) every map's outline is
/// drawn at most 2 pt wide, from corner to corner along each of its four sides, and a side at
/// least 29.2 pt long is dashed with a period of at most a quarter of the side (read from the
/// dashes' starts: from a dash to the next of its length), in every form: 29.2 pt holds four
/// periods and a dash of every map's kind at its shortest that prints (the dash-dot's 3.2 +
/// 0.8 + 1 + 1.5 pt, four times, and 3.2: `overview_outlines_show_their_keyed_dash_kinds`,
/// tests/figures_b_maps_told_apart.rs, reads the shorter sides, which since the thirteenth
/// review, R13-barroso-fig5-1, take fewer, longer periods rather than be solid). The old
/// outlines were 4 to 9 units wide, and (a)'s map 3, 19 × 11 units, was dash-dotted with a
/// period of 20.
#[test]
fn barroso_overview_outlines_are_fine_and_their_dashes_fit_their_sides() {
    for (form, opts) in forms() {
        let s = svg("barroso-fig5", form, &opts);
        let pt = read::points_per_unit(&s);
        for (from, to) in [("(a)", "(b)"), ("(c)", "(d)"), ("(e)", "(f)")] {
            let lines = lines_between(&s, from, Some(to));
            let mut maps: ByColour = BTreeMap::new();
            for l in lines.iter().filter(|l| !grey(&l.colour)) {
                assert!(
                    l.width * pt <= 2.0 + 1e-9,
                    "{form} {from}: {} drawn {} pt wide",
                    l.colour,
                    l.width * pt
                );
                maps.entry(l.colour.clone())
                    .or_default()
                    .push(l.points.clone());
            }
            assert_eq!(maps.len(), 4, "{form} {from}: maps {:?}", maps.keys());
            // The far map's sides across, 42 to 60 units, are dashed: the period check reads
            // them (its sides up, 25 units in one column's (a), are solid there).
            let mut dashed = 0;
            for (colour, pieces) in &maps {
                let (b, sides) = outline_sides(pieces);
                for (k, side) in sides.iter().enumerate() {
                    let length = if k < 2 { b[2] - b[0] } else { b[3] - b[1] };
                    assert!(!side.is_empty(), "{form} {from}: {colour} has no side {k}");
                    // Drawn from corner to corner.
                    let (lo, hi) = if k < 2 { (b[0], b[2]) } else { (b[1], b[3]) };
                    assert!(
                        (side[0].0 - lo).abs() <= 1e-6
                            && (side[side.len() - 1].1 - hi).abs() <= 1e-6,
                        "{form} {from}: {colour} side {k} {side:?} not corner to corner"
                    );
                    if let Some(p) = dash_period(side) {
                        dashed += 1;
                        if length * pt < 29.2 {
                            continue;
                        }
                        assert!(
                            p <= 0.25 * length + 1e-6,
                            "{form} {from}: {colour}'s dash period {p:.2} on a side {length:.2} long"
                        );
                    }
                }
            }
            assert!(dashed >= 2, "{form} {from}: {dashed} sides dashed");
        }
    }
}

/// The ninth review, R9-barroso-fig5-1: map 3 of the perpendicular light (z = 10 to 31.62) is
/// readable in the detail (b), not only in (a), where it is about 20 × 12 units. By hand: the
/// light overhead sees the plane at depth z edge-on at light-view y = z, x from −z tan 30° to
/// z tan 30°, so map 3 is the rectangle x = ±31.623 · 0.57735 = ±18.257, y = 10 … 31.623.
/// In every form (b)'s axis limits, read from its tick labels, hold that rectangle (by more
/// than the reading can be off); and map 3's outline (ochre, #9A6A00) read in
/// (b) through (b)'s ticks, and in (a) through (a)'s, is that rectangle, drawn on all four
/// sides, within the reading's error and 0.1 pt. The old (b) showed z ≤ 10 (y up to 10.3).
/// (Map 3 was the third sweep step, #674CA0, until the eleventh review, R11-barroso-fig5-1.)
#[test]
fn barroso_b_holds_the_perpendicular_lights_map_three() {
    let t = 30f64.to_radians().tan();
    let (x, y0, y1) = (31.6228 * t, 10.0, 31.6228);
    assert!((x - 18.257).abs() < 1e-3);
    for (form, opts) in forms() {
        let s = svg("barroso-fig5", form, &opts);
        let pt = read::points_per_unit(&s);
        let panels = panel_axes(&s);
        assert_eq!(panels.len(), 6, "{form}");
        let b = &panels[1];
        // A value's reading error in data units, across or up.
        let err = |p: &PanelAxes, across: bool, v: f64| {
            let (ticks, m) = if across {
                (&p.ticks.0, p.map.0)
            } else {
                (&p.ticks.1, p.map.1)
            };
            (read_error(ticks, v) + 0.1 / pt) / m.1.abs()
        };
        let ((bx0, bx1), (by0, by1)) = b.range;
        assert!(
            bx0 + err(b, true, bx0) < -x
                && bx1 - err(b, true, bx1) > x
                && by0 + err(b, false, by0) < y0
                && by1 - err(b, false, by1) > y1,
            "{form}: (b) shows {:?}, map 3 is x ±{x:.3}, y {y0} … {y1:.3}",
            b.range
        );
        for (k, (from, to)) in [(1, ("(b)", "(c)")), (0, ("(a)", "(b)"))] {
            let p = &panels[k];
            let pieces: Vec<Vec<(f64, f64)>> = lines_between(&s, from, Some(to))
                .into_iter()
                .filter(|l| l.colour == "#9A6A00")
                .map(|l| l.points)
                .collect();
            let (bb, sides) = outline_sides(&pieces);
            assert!(
                sides.iter().all(|s| !s.is_empty()),
                "{form} {from}: map 3 misses a side"
            );
            let inv = |m: (f64, f64), q: f64| (q - m.0) / m.1;
            for (got, want, across) in [
                (inv(p.map.0, bb[0]), -x, true),
                (inv(p.map.0, bb[2]), x, true),
                (inv(p.map.1, bb[1]), y1, false),
                (inv(p.map.1, bb[3]), y0, false),
            ] {
                assert!(
                    (got - want).abs() <= err(p, across, want),
                    "{form} {from}: map 3's edge at {got:.3}, by hand {want:.3}"
                );
            }
        }
    }
}

/// The eleventh review, R11-barroso-fig5-2: (b)'s x ticks read −10 and 10 without 0, unlike
/// (d) and (f). The tick labels are now measured as DejaVu sets them (a digit 0.636 em, the
/// minus 0.838 em, an em 0.86 of the size in the PNG), no longer 1.24 times wider: in two
/// columns and bare, (b)'s 74-unit plot holds −10, 0 and 10 (a 10-unit step is about 20 units,
/// the labels' half widths and gap 19.3), and in every form (d) and (f) label 0 with their
/// ends. (One column's (b), 16 units a step, still holds −10 and 10 only.)
#[test]
fn barroso_details_label_zero_across() {
    for (form, opts) in forms() {
        let s = svg("barroso-fig5", form, &opts);
        let panels = panel_axes(&s);
        assert_eq!(panels.len(), 6, "{form}");
        let has = |k: usize, v: f64| panels[k].ticks.0.iter().any(|t| (t - v).abs() < 1e-9);
        if form != "single" {
            for v in [-10.0, 0.0, 10.0] {
                assert!(has(1, v), "{form} (b): {:?}", panels[1].ticks.0);
            }
        }
        for (k, end) in [(3, 5.0), (5, 20.0)] {
            for v in [-end, 0.0, end] {
                assert!(has(k, v), "{form} panel {k}: {:?}", panels[k].ticks.0);
            }
        }
    }
}

/// The thirteenth review, R13-barroso-fig5-2: the titles "(a) perpendicular" and "(c) parallel
/// light" did not say to what ("parallel light" reads as a directional light). In every form
/// the panel titles say the light is across or along the view, "(a) light ⊥ view" and
/// "(c) light ∥ view", read from the SVG's texts, and no text says "perpendicular" or
/// "parallel" in a title; the symbols are in DejaVu Sans: its cmap and hmtx read by hand (a
/// script over the font file) map ⊥ (U+22A5) to glyph 3376, 0.871 em wide, and ∥ (U+2225) to
/// glyph 3248, 0.5 em, and ⟂ (U+27C2) to none (the .notdef box, 0.600 em), which the titles
/// therefore do not use.
#[test]
fn barroso_titles_say_what_the_light_is_perpendicular_or_parallel_to() {
    let font = read::Font::dejavu();
    for c in ['⊥', '∥'] {
        assert!(
            font.advance(c) > font.advance(' '),
            "{c}: {}",
            font.advance(c)
        );
    }
    for (form, opts) in forms() {
        let s = svg("barroso-fig5", form, &opts);
        let texts: Vec<String> = read::texts(&font, &s)
            .into_iter()
            .map(|t| t.content)
            .collect();
        for title in ["(a) light ⊥ view", "(c) light ∥ view"] {
            assert!(
                texts.iter().any(|t| t == title),
                "{form}: no {title:?} in {texts:?}"
            );
        }
        for t in texts
            .iter()
            .filter(|t| t.starts_with("(a)") || t.starts_with("(c)"))
        {
            assert!(
                !t.contains("perpendicular") && !t.contains("parallel"),
                "{form}: {t:?}"
            );
        }
    }
}
