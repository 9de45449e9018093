//! barroso-fig5, lloyd2006-fig11 and barroso-fig7 after the fifth figure review (§4.9, §4.12,
//! §4.13, X3, X5–X7), read back from their SVGs in every form they change in:
//! - barroso-fig5: each overview beside its detail, the region each detail enlarges a grey box
//!   in its overview; faces seen edge-on drawn as one line (not a flat closed outline); the far
//!   face named in the gutter by a leader; one column's labels "z = 3.162" (thin spaces,
//!   figure review 6; "z=31.62" before), never a bare depth
//!   that reads as a tick value; the page shorter than 640 units;
//! - both diagrams seen from the light: axes "light-view x" and "light-view y" (no "light z");
//!   no tinted fill that no key explains;
//! - barroso-fig7: the fall-offs in no scheme's colour; γ_lim, n′₁ and n′₂ defined in the
//!   caption; in one column taller plots, smaller markers, none across the frame, and the grid
//!   at 2 and 5 of each decade only.
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read as read;
use figures_style_read::forms;

/// The view box's height.
fn height(svg: &str) -> f64 {
    let head = &svg[..svg.find('>').unwrap()];
    read::attr_str(head, "viewBox")
        .unwrap()
        .split_whitespace()
        .nth(3)
        .unwrap()
        .parse()
        .unwrap()
}

fn stroke_width(line: &str) -> f64 {
    read::attr(line, "stroke-width").unwrap_or(1.0)
}

/// The stroked polylines of `colour`: (width, points).
fn strokes(svg: &str, colour: &str) -> Vec<(f64, Vec<(f64, f64)>)> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline") && read::attr_str(l, "stroke") == Some(colour))
        .map(|l| (stroke_width(l), read::points(l)))
        .collect()
}

/// Figure review 5, §4.12.4: a light perpendicular to the view sees the near and far faces and
/// the split planes edge-on. Each is one straight line; the old closed outline of the flat quad
/// (five points, a box less than a unit tall and many units wide) showed as two thin slanted
/// lines. In (a) and (b) the near and far faces are thick horizontal lines of two points.
#[test]
fn barroso_fig5_edge_on_faces_are_one_line() {
    for (form, opts) in forms() {
        let svg = read::render_svg("barroso-fig5", &opts);
        let black = strokes(&svg, "#000000");
        for (w, p) in &black {
            let b = read::bbox(p);
            assert!(
                !(p.len() >= 4 && b[3] - b[1] < 1.0 && b[2] - b[0] > 3.0),
                "{form}: a flat closed outline, width {w}: {p:?}"
            );
        }
        let thick_flat = black
            .iter()
            .filter(|(w, p)| *w == 2.0 && p.len() == 2 && (p[0].1 - p[1].1).abs() < 0.5)
            .count();
        // (a): near and far faces; (b): the near face (its far plane z = 10 is a split plane).
        assert!(thick_flat >= 3, "{form}: {thick_flat} thick edge-on faces");
    }
}

/// §4.12.1: each overview and its detail side by side on one row, titled "(b) detail of (a)",
/// "(d) detail of (c)", "(f) detail of (e)" (they were (d)–(f) under other rows); each overview
/// outlines the region its detail enlarges in grey (#6E6E6E, 2 units: three boxes); and the
/// two-column page is 600 units tall (was 640).
#[test]
fn barroso_fig5_details_beside_their_overviews_with_grey_boxes() {
    let font = read::Font::dejavu();
    for (form, opts) in forms() {
        let svg = read::render_svg("barroso-fig5", &opts);
        let all = read::texts(&font, &svg);
        let title = |start: &str| -> (f64, f64) {
            let t = all
                .iter()
                .find(|t| t.content.starts_with(start) && !t.tag.contains("#323232"))
                .unwrap_or_else(|| panic!("{form}: no title {start:?}"));
            (t.bbox[0], t.y)
        };
        for (overview, detail) in [
            ("(a)", "(b) detail of (a)"),
            ("(c)", "(d) detail of (c)"),
            ("(e)", "(f) detail of (e)"),
        ] {
            let (o, d) = (title(overview), title(detail));
            assert!(
                (o.1 - d.1).abs() < 0.5 && d.0 > o.0 + 100.0,
                "{form}: {o:?} {d:?}"
            );
        }
        let boxes: Vec<_> = strokes(&svg, "#6E6E6E")
            .into_iter()
            .filter(|(w, _)| *w == 2.0)
            .collect();
        assert_eq!(boxes.len(), 3, "{form}: {boxes:?}");
        if form == "double" {
            assert!(height(&svg) <= 600.0, "{form}: {}", height(&svg));
        }
    }
}

/// §4.12.3: "far face" is a label in (f)'s gutter, in the column of the planes' labels (its left
/// edge at "z = 40.81"'s), joined by a leader, not text set in the band above the line.
#[test]
fn barroso_fig5_far_face_is_a_gutter_label() {
    let font = read::Font::dejavu();
    for (form, opts) in forms().into_iter().filter(|(f, _)| *f != "single") {
        let all = read::texts(&font, &read::render_svg("barroso-fig5", &opts));
        // The last of each: (f) is drawn after (e), whose gutter has a "z = 40.81" too.
        let left = |c: &str| {
            all.iter()
                .rev()
                .find(|t| t.content == c)
                .unwrap_or_else(|| panic!("{form}: no {c:?}"))
                .bbox[0]
        };
        let (far, plane) = (left("far face"), left("z = 40.81"));
        assert!((far - plane).abs() < 1.0, "{form}: {far} against {plane}");
    }
}

/// X3: the diagrams seen from the light name their axes "light-view x" (right in the light's
/// view) and "light-view y" (up), never "light z" (z is the eye depth of the planes' labels) nor
/// "−x in light space", in every form of both figures.
#[test]
fn diagrams_from_the_light_name_light_view_axes() {
    let font = read::Font::dejavu();
    for name in ["barroso-fig5", "lloyd2006-fig11"] {
        for (form, opts) in forms() {
            let all = read::texts(&font, &read::render_svg(name, &opts));
            let has = |c: &str| all.iter().any(|t| t.content == c);
            assert!(has("light-view x") && has("light-view y"), "{name} {form}");
            assert!(
                !has("light z") && !has("−x in light space"),
                "{name} {form}"
            );
        }
    }
}

/// §4.9.3: no tinted fill inside the maps (translucent rectangles that no key names).
#[test]
fn diagrams_from_the_light_have_no_unkeyed_tints() {
    for name in ["barroso-fig5", "lloyd2006-fig11"] {
        for (form, opts) in forms() {
            let svg = read::render_svg(name, &opts);
            let tints: Vec<&str> = svg
                .lines()
                .filter(|l| {
                    l.starts_with("<rect")
                        && read::attr(l, "opacity").is_some_and(|o| o < 0.5)
                        && read::attr_str(l, "fill").is_some_and(|f| f != "#FFFFFF")
                })
                .collect();
            assert!(tints.is_empty(), "{name} {form}: {tints:?}");
        }
    }
}

/// The colour of the key entry whose text starts with `start`: the mark nearest left of it on
/// its row (as `figures_style_read::key_colours` reads a scheme's).
fn entry_colour(font: &read::Font, svg: &str, start: &str) -> String {
    let marks = read::marks(svg);
    let t = read::texts(font, svg)
        .into_iter()
        .find(|t| t.content.starts_with(start) && t.tag.contains("fill=\"#000000\""))
        .unwrap_or_else(|| panic!("no key entry {start:?}"));
    let mid = 0.5 * (t.bbox[1] + t.bbox[3]);
    marks
        .iter()
        .filter(|(_, b)| {
            b[2] <= t.bbox[0] + 0.5
                && b[2] >= t.bbox[0] - 40.0
                && (0.5 * (b[1] + b[3]) - mid).abs() <= 6.0
        })
        .max_by(|a, b| a.1[2].total_cmp(&b.1[2]))
        .map(|(c, _)| c.clone())
        .unwrap_or_else(|| panic!("no sample left of {start:?}"))
}

/// X5: Barroso's and Zhang's fall-offs (key entries "Eq 18…", "Eq 17…") are drawn in neither
/// of the warps' and schemes' colours, by hand PSM #00306E, LiSPSM #00664B, uniform #D55E00,
/// ZP #009CA6, ZP+W #A82E66 and FP+ZP+W #4D2E00 (docs/figures.md's table), nor in any colour lloyd2006-fig12's
/// key gives a scheme in the same form; and they differ from each other.
#[test]
fn barroso_fig7_fall_offs_take_no_scheme_colour() {
    let font = read::Font::dejavu();
    for (form, opts) in forms() {
        let svg = read::render_svg("barroso-fig7", &opts);
        let barroso = entry_colour(&font, &svg, "Eq 18");
        let zhang = entry_colour(&font, &svg, "Eq 17");
        assert_ne!(barroso, zhang, "{form}");
        let fig12 = read::render_svg("lloyd2006-fig12", &opts);
        let schemes: Vec<String> = read::key_colours(&font, &fig12)
            .into_iter()
            .map(|(_, c)| c)
            .chain(
                [
                    "#00306E", "#00664B", "#D55E00", "#009CA6", "#A82E66", "#4D2E00",
                ]
                .map(String::from),
            )
            .collect();
        assert!(schemes.len() > 4, "{form}: fig12's key not read");
        for c in [&barroso, &zhang] {
            assert!(!schemes.contains(c), "{form}: {c} is a scheme's colour");
        }
    }
}

/// The caption's text (its grey lines, scripts flattened: "n′₁" reads "n′1", "γ_lim" "γlim").
fn caption(font: &read::Font, svg: &str) -> String {
    read::texts(font, svg)
        .into_iter()
        .filter(|t| t.tag.contains("fill=\"#323232\""))
        .map(|t| t.content.replace('\u{a0}', " ") + " ")
        .collect()
}

/// X7: both captions define n′₁ and n′₂ (Eq 13's two branches, for γ ≥ θ and γ < θ) and γ_lim
/// (Eq 15's angle, below which the fall-off r(γ) divides n′₁(γ_lim)).
#[test]
fn barroso_fig7_caption_defines_its_symbols() {
    let font = read::Font::dejavu();
    for (form, opts) in forms().into_iter().filter(|(f, _)| *f != "bare") {
        let c = caption(&font, &read::render_svg("barroso-fig7", &opts));
        // One column says it in fewer words (five lines with the least max m_z's definition,
        // the tenth review, R10-barroso-fig7-1).
        let (eq13, fall_off) = if form == "single" {
            ("Eq 13 for γ ≥ θ, γ < θ", "n′1(γlim)/r(γ)")
        } else {
            ("Eq 13's n′ for γ ≥ θ, γ < θ", "n′ = n′1(γlim)/r(γ)")
        };
        // θ defined (R21-barroso-fig7-1: in Zhang's paper, whose r(γ) it draws, θ is the
        // light's angle).
        for want in [
            "n′1",
            "n′2",
            eq13,
            "Eq 15",
            fall_off,
            "half field of view θ = 30°",
        ] {
            assert!(c.contains(want), "{form}: no {want:?} in {c}");
        }
    }
}

// §4.13.1–2 (one column: (a)'s plot taller, smaller markers, a sparse grid): the one column
// now draws (a) alone, its plot at least 110 pt tall (the sixth review, R6-barroso-fig7-2; the
// eighth, R8-barroso-fig7-1):
// `key_names_least_max_m_z_and_the_angles_and_one_column_is_a_alone` (src/plot/barroso.rs).
