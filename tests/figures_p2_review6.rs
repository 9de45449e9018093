//! The sixth figure review's items on the maps and views (lloyd2006-fig11, lloyd2006-fig7,
//! martin-tan-fig6), read back from the rendered SVGs in all three forms (captioned double
//! column, `--bare`, `--column single`):
//! - lloyd2006-fig11: every plane's leader starts at its square's upper right corner
//!   (R6-lloyd2006-fig11-1: "n = 1"'s started at the lower one, beside the dimension); the frame
//!   leaves no empty band above the drawing (R6-lloyd2006-fig11-2: 2 units above and below);
//!   the near face's dimension lies clear of map 2's outline, its label above the far face, and
//!   the far face's label clear of map 3's outline (R6-lloyd2006-fig11-3);
//! - lloyd2006-fig7's captions: the disks' top is the viewer's left (R6-lloyd2006-fig7-4), and
//!   LiSPSM exceeds no warping near behind, by the factor printed (R6-lloyd2006-fig7-6);
//! - martin-tan-fig6's captions: the 80 % rule's collapse off behind (R6-martin-tan-fig6-4);
//! - lloyd2006-fig4: one title size for all panels, and one column's maps titled "(d) map of
//!   (a)" without a row label (R6-lloyd2006-fig4-1, -3).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read as read;
use figures_style_read::forms;
use shadow_aliasing::plot::{render_with, Format, Options};
use std::path::Path;

fn svg(name: &str, form: &str, opts: &Options) -> String {
    // A directory of its own for each call: tests run in parallel.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "figures-p2-{name}-{form}-{}-{call}",
        std::process::id()
    ));
    let files = render_with(name, &dir, Format::Svg, opts).unwrap();
    let s = std::fs::read_to_string(&files[0]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    s
}

/// The opening tags of one kind of element.
fn elements<'a>(svg: &'a str, kind: &str) -> Vec<&'a str> {
    svg.split('<')
        .filter(|e| e.starts_with(kind))
        .map(|e| &e[..e.find('>').unwrap_or(e.len())])
        .collect()
}

/// Black polylines of a stroke width: their points.
fn black(svg: &str, width: &str) -> Vec<Vec<(f64, f64)>> {
    elements(svg, "polyline")
        .into_iter()
        .filter(|e| {
            read::attr_str(e, "stroke") == Some("#000000")
                && read::attr_str(e, "stroke-width") == Some(width)
        })
        .map(read::points)
        .collect()
}

/// Closed black squares of a stroke width (their boxes), largest first.
fn squares(svg: &str, width: &str) -> Vec<[f64; 4]> {
    let mut out: Vec<[f64; 4]> = black(svg, width)
        .into_iter()
        .filter(|p| p.len() == 5 && p[0] == p[4])
        .map(|p| read::bbox(&p))
        .collect();
    out.sort_by(|a, b| (b[2] - b[0]).total_cmp(&(a[2] - a[0])));
    out
}

/// lloyd2006-fig11 (R6-lloyd2006-fig11-1): the four leaders' anchors (dark grey dots) all lie
/// above the squares' common centre, the upper right corners (z tan θ, z tan θ); the old
/// "n = 1" anchor lay at the near square's lower corner.
#[test]
fn fig11_every_leader_starts_at_an_upper_corner() {
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig11", form, &opts);
        let far = squares(&s, "2")[0];
        let centre = 0.5 * (far[1] + far[3]);
        let dots: Vec<f64> = elements(&s, "circle")
            .into_iter()
            .filter(|e| read::attr_str(e, "fill") == Some("#5A5A5A"))
            .map(|e| read::attr(e, "cy").unwrap())
            .collect();
        assert_eq!(dots.len(), 4, "{form}: {dots:?}");
        for y in &dots {
            assert!(
                *y < centre,
                "{form}: an anchor at y {y}, below the centre {centre}"
            );
        }
    }
}

/// lloyd2006-fig11 (R6-lloyd2006-fig11-2): the frame's band above the far face is no wider
/// than its bands left and right of it (each within 3 units): the old frame ran 2 data units
/// (35 units) above the face and 0.37 (6 units) beside it.
#[test]
fn fig11_frame_has_no_empty_band_above() {
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig11", form, &opts);
        let far = squares(&s, "2")[0];
        let lines = black(&s, "1");
        let y_axis = lines
            .iter()
            .filter(|p| p.len() == 2 && p[0].0 == p[1].0)
            .max_by(|a, b| (a[1].1 - a[0].1).abs().total_cmp(&(b[1].1 - b[0].1).abs()))
            .unwrap();
        let x_axis = lines
            .iter()
            .filter(|p| p.len() == 2 && p[0].1 == p[1].1)
            .max_by(|a, b| (a[1].0 - a[0].0).abs().total_cmp(&(b[1].0 - b[0].0).abs()))
            .unwrap();
        let top = far[1] - y_axis[0].1.min(y_axis[1].1);
        let left = far[0] - y_axis[0].0;
        let right = x_axis[0].0.max(x_axis[1].0) - far[2];
        assert!(
            (top - left).abs() <= 3.0 && (top - right).abs() <= 3.0,
            "{form}: above {top}, left {left}, right {right}"
        );
    }
}

/// lloyd2006-fig11 (R6-lloyd2006-fig11-3): the near face's dimension line (as long as the near
/// face is wide) lies at least 6 units under map 2's outline (on the z = 4 square, the middle
/// thin square, reaching half its width under it: the seventh review, R7-X-3), so that its
/// 4-unit bars end clear of it; its label ends above the far face; the far face's label starts
/// at least 4 units under map 3's outline (on the far face, reaching half its width under it).
#[test]
fn fig11_dimensions_clear_the_maps_outlines() {
    let font = read::Font::dejavu();
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig11", form, &opts);
        let thick = squares(&s, "2");
        let (far, near) = (thick[0], thick[1]);
        let z4 = squares(&s, "1")[0];
        // Each map outline's reach beyond its square: half its stroke (map 2 the widest).
        let reach = |colour_not: &[&str], widest: bool| -> f64 {
            let w = elements(&s, "polyline")
                .into_iter()
                .filter(|e| {
                    let c = read::attr_str(e, "stroke").unwrap_or("");
                    !colour_not.contains(&c)
                })
                .filter_map(|e| read::attr(e, "stroke-width"))
                .filter(|&w| w >= 3.0);
            0.5 * if widest {
                w.fold(0.0, f64::max)
            } else {
                w.fold(f64::INFINITY, f64::min)
            }
        };
        let grey = ["#000000", "#949494", "#5A5A5A"];
        let (wide, narrow) = (reach(&grey, true), reach(&grey, false));
        let near_w = near[2] - near[0];
        let dim = black(&s, "1")
            .into_iter()
            .find(|p| {
                p.len() == 2 && p[0].1 == p[1].1 && ((p[1].0 - p[0].0).abs() - near_w).abs() <= 1.5
            })
            .unwrap_or_else(|| panic!("{form}: no line {near_w} long"));
        assert!(
            dim[0].1 - (z4[3] + wide) >= 6.0,
            "{form}: the dimension at y {} is {} under map 2's outline",
            dim[0].1,
            dim[0].1 - (z4[3] + wide)
        );
        let texts = read::texts(&font, &s);
        let label = |t: &str| texts.iter().find(|x| x.content == t).unwrap().bbox;
        let n = label("2n tan θ");
        assert!(
            n[3] < far[3] - 1.0,
            "{form}: 2n tan θ at {n:?}, far face {far:?}"
        );
        let f = label("2f tan θ");
        assert!(
            f[1] >= far[3] + narrow + 4.0,
            "{form}: 2f tan θ at {f:?}, far face {far:?}, map 3 {narrow} under it"
        );
    }
}

/// The caption's text (its lines, #323232, joined by spaces) of a rendered figure.
fn caption(svg: &str) -> String {
    let font = read::Font::dejavu();
    read::texts(&font, svg)
        .into_iter()
        .filter(|t| t.tag.contains("#323232"))
        .map(|t| t.content)
        .collect::<Vec<_>>()
        .join(" ")
}

/// The number printed after `before` in `text`, up to `after`.
fn number_between(text: &str, before: &str, after: &str) -> f64 {
    let i = text
        .find(before)
        .unwrap_or_else(|| panic!("no {before:?} in {text}"))
        + before.len();
    let j = i + text[i..].find(after).unwrap();
    text[i..j].trim().parse().unwrap()
}

/// lloyd2006-fig7 (R6-lloyd2006-fig7-4, -6): both captions state the disks' convention (top:
/// viewer's left) and say that near behind LiSPSM's S̄ (b) exceeds the unwarped map's (a),
/// because its n′ does not revert for γ < θ (Lloyd 2006 §4.4). The factor printed lies
/// between 4.1 and 5: the sixth review's own Python read log₁₀ S̄ 6.63 for (b) against 6.01 for
/// (a) at elevation 10° behind, 10^0.62 = 4.17, so the largest factor is at least that.
#[test]
fn fig7_captions_state_the_left_side_and_lispsm_above_no_warping() {
    for (form, opts) in [&forms()[0], &forms()[2]] {
        let text = caption(&svg("lloyd2006-fig7", form, opts));
        assert!(text.contains("top: viewer's left"), "{form}: {text}");
        // Two columns give the reason; one column, four lines, points to §4.4 for it.
        if *form == "double" {
            assert!(text.contains("does not revert"), "{form}: {text}");
        }
        // One column's four lines gave §4.4 and "is" to "(d), (e) not in the paper" (R16).
        if *form == "double" {
            assert!(text.contains("§4.4"), "{form}: {text}");
        }
        let worse = number_between(&text, "up to", "×");
        assert!((4.1..5.0).contains(&worse), "{form}: {worse} in {text}");
    }
}

/// martin-tan-fig6 (R6-martin-tan-fig6-4): the caption (two columns; the one-column caption
/// keeps five lines without it) says the 80 % rule collapses the
/// trapezoid off exactly behind, below the exact-behind share ((11/100)² = 0.0121), up to an
/// elevation the sixth review's Python brackets: its share is 0.0031 at 20° (below) and 0.055
/// at 30° (above), so the angle printed lies in [20, 30).
#[test]
fn martin_tan_caption_names_the_eighty_percent_collapse() {
    let (form, opts) = &forms()[0];
    let text = caption(&svg("martin-tan-fig6", form, opts));
    assert!(text.contains("collapses"), "{form}: {text}");
    let up_to = number_between(&text, "up to", "° from behind");
    assert!((20.0..30.0).contains(&up_to), "{form}: {up_to} in {text}");
}

/// lloyd2006-fig4 (R6-lloyd2006-fig4-1, -3): every panel title, the columns' headings "(a) η =
/// …" and the maps' "(e) map of (a)", is set at one size in every form (the maps' were 12.1
/// units, the headings' 10.5); one column titles its maps "(d) map of (a)" … "(f) map of (c)"
/// and writes no row label "(d)–(f): (a)–(c) in the map (s, t)" (an in-figure caption).
#[test]
fn fig4_titles_are_one_size_and_name_their_panels() {
    let font = read::Font::dejavu();
    for (form, opts) in forms() {
        let s = svg("lloyd2006-fig4", form, &opts);
        let texts = read::texts(&font, &s);
        let titles: Vec<&read::Text> = texts
            .iter()
            .filter(|t| {
                t.content.len() > 4
                    && t.content.starts_with('(')
                    && t.content.as_bytes()[2] == b')'
                    && !t.tag.contains("#323232")
            })
            .collect();
        let panels = if form == "single" { 6 } else { 8 };
        assert_eq!(titles.len(), panels, "{form}: {titles:?}");
        for t in &titles {
            assert!(
                (t.fs - titles[0].fs).abs() < 0.01,
                "{form}: {:?} at {} and {:?} at {}",
                t.content,
                t.fs,
                titles[0].content,
                titles[0].fs
            );
        }
        if form == "single" {
            for want in ["(d) map of (a)", "(e) map of (b)", "(f) map of (c)"] {
                assert!(texts.iter().any(|t| t.content == want), "{want}");
            }
            assert!(!texts
                .iter()
                .any(|t| t.content.contains("in the map (s, t)") && !t.tag.contains("#323232")));
        }
    }
}

// The sixth figure review's remaining items on barroso-fig5 and lloyd2006-fig7, read back
// from the rendered SVGs:
// - lloyd2006-fig7 (R6-lloyd2006-fig7-2): panel (a) (no warping, S̄ from 8.65×10⁵ to 2.0×10⁶)
//   was one flat green under the shared 10²–10⁷ bar; it now carries dashed contour lines at
//   10⁶ and 1.5×10⁶, each labelled inside the disk, in the two-column and bare forms;
// - barroso-fig5 (R6-barroso-fig5-4): the far face's thick edge is named in the overview (e)
//   as in its detail (f), in the two-column and bare forms.

/// The points of the polylines of one stroke colour and width.
fn strokes(svg: &str, colour: &str, width: &str) -> Vec<Vec<(f64, f64)>> {
    elements(svg, "polyline")
        .into_iter()
        .filter(|e| {
            read::attr_str(e, "stroke") == Some(colour)
                && read::attr_str(e, "stroke-width") == Some(width)
        })
        .map(read::points)
        .collect()
}

/// lloyd2006-fig7 (R6-lloyd2006-fig7-2), two columns and bare: (a)'s disk (the largest ring,
/// grey #808080 half a unit wide since the eleventh review, left of x = 173 and above y = 270:
/// the first of three disks across 520 units, in the first of two rows) holds dashed black
/// contour lines (1.5 units wide since the eleventh review), at least 100 dashes, every point
/// within the disk (half a line width outside the horizon at most), and none in any other panel
/// (the key's level samples of their styles under the key disk aside); they are named in the
/// key, "(a) S̄ = 10⁶" and "(a) S̄ = 1.5×10⁶" (a `<tspan>` superscript 6, read "106"), not on
/// their lines (R12-lloyd2006-fig7-1, R13-lloyd2006-fig7-1). The sixth review's figure drew no
/// contour.
#[test]
fn fig7_a_has_keyed_contours_inside_its_disk() {
    let font = read::Font::dejavu();
    for (form, opts) in forms().into_iter().take(2) {
        let s = svg("lloyd2006-fig7", form, &opts);
        let rings: Vec<[f64; 4]> = strokes(&s, "#808080", "0.5")
            .iter()
            .map(|p| read::bbox(p))
            .filter(|b| b[2] < 173.0 && b[3] < 270.0)
            .collect();
        let horizon = rings
            .iter()
            .copied()
            .max_by(|a, b| (a[2] - a[0]).total_cmp(&(b[2] - b[0])))
            .unwrap_or_else(|| panic!("{form}: no ring in (a)"));
        let (cx, cy) = (
            0.5 * (horizon[0] + horizon[2]),
            0.5 * (horizon[1] + horizon[3]),
        );
        let r = 0.5 * (horizon[2] - horizon[0]);
        assert!(r > 40.0, "{form}: (a)'s radius {r}");
        let dashes = strokes(&s, "#000000", "1.5");
        let in_a: Vec<&Vec<(f64, f64)>> = dashes
            .iter()
            .filter(|p| p.iter().all(|q| q.0 < 173.0))
            .collect();
        assert!(in_a.len() >= 100, "{form}: {} dashes in (a)", in_a.len());
        for p in &in_a {
            for q in p.iter() {
                let d = (q.0 - cx).hypot(q.1 - cy);
                assert!(
                    d <= r + 1.0,
                    "{form}: a contour at {q:?}, {d} from the centre"
                );
            }
        }
        // The other panels' dashes: 1.5-unit black lines are the contours only, and the key's
        // samples of their styles (R7-2006f7-1), level, under the key disk in the last third
        // of the page's width and its second row.
        for p in dashes.iter().filter(|p| p.iter().any(|q| q.0 >= 173.0)) {
            assert!(
                p.iter()
                    .all(|q| q.0 > 346.0 && q.1 > 270.0 && q.1 == p[0].1),
                "{form}: a contour outside (a): {p:?}"
            );
        }
        // Named in the key, not on their lines (the twelfth and thirteenth reviews): the key's
        // rows "(a) S̄ = 10⁶" and "(a) S̄ = 1.5×10⁶", right of (a), and no level written in (a).
        let texts = read::texts(&font, &s);
        for want in ["10", "1.5×10"] {
            let level = format!("{want}6");
            assert!(
                texts
                    .iter()
                    .any(|t| t.content == format!("(a) S = {level}") && t.x >= 173.0),
                "{form}: no key row for {want}⁶"
            );
            assert!(
                !texts.iter().any(|t| t.content == level && t.x < 173.0),
                "{form}: {want}⁶ written in (a)"
            );
        }
    }
}

/// barroso-fig5 (R6-barroso-fig5-4), two columns and bare: "far face" is written twice, once
/// in the left column's gutter (the overview (e), left of the page's middle, 260 units) and
/// once in the right's ((f)); both in the bottom row, below every "f = 100" but the last
/// (the overviews (a), (c) label f = 100 above it). The old figure named it in (f) only.
#[test]
fn barroso_far_face_named_in_e_and_f() {
    let font = read::Font::dejavu();
    for (form, opts) in forms().into_iter().take(2) {
        let s = svg("barroso-fig5", form, &opts);
        let texts = read::texts(&font, &s);
        let far: Vec<&read::Text> = texts.iter().filter(|t| t.content == "far face").collect();
        assert_eq!(far.len(), 2, "{form}: {} far face labels", far.len());
        assert!(far.iter().any(|t| t.x < 260.0), "{form}: none in (e)");
        assert!(far.iter().any(|t| t.x > 260.0), "{form}: none in (f)");
        let f100: Vec<f64> = texts
            .iter()
            .filter(|t| t.content == "f = 100")
            .map(|t| t.y)
            .collect();
        assert_eq!(f100.len(), 3, "{form}: {f100:?}");
        let e_label = far.iter().find(|t| t.x < 260.0).unwrap();
        let mut ys = f100.clone();
        ys.sort_by(f64::total_cmp);
        assert!(
            e_label.y > ys[2],
            "{form}: (e)'s far face at {} above (e)'s f = 100 at {}",
            e_label.y,
            ys[2]
        );
    }
}
