//! The figures fit a journal page (issue 35): every figure, captioned and bare, is at most
//! 640 pt tall (a 9-inch text block is 648 pt) at its 520 pt width, and the figures whose two
//! panels were stacked now have them side by side. Read from the SVGs as written: their `width`
//! and `height` in points, the positions of the panels' titles, and the caption's lines (at most
//! five).
#![cfg(feature = "plot")]

mod figures_style_read;
use figures_style_read::render_svg;
use shadow_aliasing::plot::{
    render_with, Column, Format, Options, PlotError, FIGURES, SINGLE_COLUMN,
};
use std::path::Path;

/// The page-height cap, in points.
const CAP: f64 = 640.0;

/// Figures still taller than [`CAP`], with the reason. Each must still be taller (so that a
/// figure brought under the cap leaves this list). None is left.
const OVER: &[(&str, &str)] = &[];

fn svg(name: &str, bare: bool) -> String {
    render_svg(
        name,
        &Options {
            bare,
            ..Options::default()
        },
    )
}

/// The width of the SVG's view box, in layout units.
fn view_width(head: &str) -> f64 {
    let at = head.find("viewBox=\"").unwrap() + "viewBox=\"".len();
    let v: Vec<f64> = head[at..at + head[at..].find('"').unwrap()]
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    v[2]
}

/// The number of the attribute `name` of `tag` (a unit `pt` dropped).
fn attr(tag: &str, name: &str) -> f64 {
    let key = format!(" {name}=\"");
    let at = tag.find(&key).unwrap() + key.len();
    tag[at..at + tag[at..].find('"').unwrap()]
        .trim_end_matches("pt")
        .parse()
        .unwrap()
}

/// The page's width across two columns, in points: every figure's, with no exception (the
/// eighteenth review, R18-lloyd2006-fig11-1: lloyd2006-fig11, 346 pt wide since the fifth
/// review's X2, was printed scaled 1.5× at 520 pt).
const PAGE_WIDTH: f64 = 520.0;

#[test]
fn every_figure_is_at_most_640_pt_tall() {
    let mut bad = Vec::new();
    for &name in FIGURES {
        for bare in [false, true] {
            let s = svg(name, bare);
            let head = &s[..s.find('>').unwrap()];
            let (w, h) = (attr(head, "width"), attr(head, "height"));
            let want = PAGE_WIDTH;
            // A bare figure is the captioned one cut to its ink: no wider, and printed at the
            // same point a unit.
            if bare {
                assert!(w <= want, "{name} (bare): {w} pt wide, over {want}");
                assert!(
                    (w / view_width(head) - 1.0).abs() < 1e-9,
                    "{name} (bare): {w} pt"
                );
            } else {
                assert_eq!(w, want, "{name}: {w} pt wide");
            }
            let over = OVER.iter().any(|(n, _)| *n == name);
            // The captioned figure of an exception must still be one; its bare form is cut
            // from it.
            if over {
                assert!(
                    bare || h > CAP,
                    "{name} is {h} pt tall: take it off the list of exceptions"
                );
            } else if h > CAP {
                bad.push(format!("{name} (bare {bare}): {h} pt tall"));
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The (x, y) of the first `<text>` outside the caption (grey, #323232) whose content starts
/// with `label`.
fn title_at(svg: &str, label: &str) -> (f64, f64) {
    let mut rest = svg;
    while let Some(i) = rest.find("<text ") {
        let tag_end = i + rest[i..].find('>').unwrap();
        let tag = &rest[i..tag_end];
        if rest[tag_end + 1..].starts_with(label) && !tag.contains("fill=\"#323232\"") {
            return (attr(tag, "x"), attr(tag, "y"));
        }
        rest = &rest[tag_end..];
    }
    panic!("no text {label:?}")
}

/// The two-panel figures that stacked (a) over (b) (lloyd2006-fig5 was 860 pt tall, fig10 and
/// fig12 926) have them side by side: the titles in one row, (b)'s at least 200 units right of
/// (a)'s.
#[test]
fn panel_pairs_are_side_by_side() {
    for name in [
        "lloyd2006-fig5",
        "lloyd2006-fig10",
        "lloyd2006-fig12",
        "barroso-fig7",
        "lloyd2006-worst-case",
        "martin-tan-fig6",
    ] {
        let s = svg(name, false);
        let (a, b) = (title_at(&s, "(a)"), title_at(&s, "(b)"));
        // One row: the titles within a title's height (a hemisphere panel's title sits 9
        // units above a line chart's).
        assert!(
            (a.1 - b.1).abs() <= 12.0,
            "{name}: (a) at {a:?}, (b) at {b:?}"
        );
        assert!(b.0 - a.0 >= 200.0, "{name}: (a) at {a:?}, (b) at {b:?}");
    }
}

/// Every caption is at most five lines (issue 35: nine had six, and earlier ones 17 to 20):
/// the caption's lines are the grey (#323232) texts of the captioned SVG, one `<text>` a line.
#[test]
fn every_caption_is_at_most_five_lines() {
    let mut bad = Vec::new();
    for &name in FIGURES {
        let s = svg(name, false);
        let lines = s.matches("fill=\"#323232\"").count();
        assert!(lines >= 1, "{name}: no caption");
        if lines > 5 {
            bad.push(format!("{name}: {lines} caption lines"));
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// The size every `<text>` and `<tspan>` of an SVG prints at, in points: its `font-size` (the
/// text's own where a tspan has none) times the SVG's `width` in points over its view box's
/// width. Returns the smallest, with its text.
fn smallest_printed_text(svg: &str) -> (f64, String) {
    let head = &svg[..svg.find('>').unwrap()];
    let per_unit = attr(head, "width") / view_width(head);
    let mut least = (f64::INFINITY, String::new());
    let mut rest = svg;
    while let Some(i) = rest.find("<text ") {
        let tag_end = i + rest[i..].find('>').unwrap();
        let close = tag_end + rest[tag_end..].find("</text>").unwrap();
        let content = &rest[tag_end + 1..close];
        let mut sizes = vec![attr(&rest[i..tag_end], "font-size")];
        let mut inner = content;
        while let Some(j) = inner.find("<tspan") {
            let end = j + inner[j..].find('>').unwrap();
            let tag = &inner[j..end];
            if tag.contains(" font-size=\"") {
                sizes.push(attr(tag, "font-size"));
            }
            inner = &inner[end..];
        }
        for s in sizes {
            if s * per_unit < least.0 {
                least = (s * per_unit, content.to_string());
            }
        }
        rest = &rest[close..];
    }
    least
}

fn svg_with(name: &str, opts: &Options) -> Result<String, shadow_aliasing::plot::PlotError> {
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "figures-page-fit-single-{name}-{}-{call}",
        std::process::id()
    ));
    let files = render_with(name, &dir, Format::Svg, opts)?;
    let s = std::fs::read_to_string(&files[0]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    Ok(s)
}

/// One column (issue 35): each figure of `SINGLE_COLUMN`, captioned and bare, is 240 pt
/// (3.3 in) wide and at most 640 pt tall, and every text of it, subscripts and superscripts
/// included, prints at 6 pt or more at that width; every other figure is refused by name.
#[test]
fn single_column_figures_print_text_of_at_least_6_pt() {
    for &name in FIGURES {
        for bare in [false, true] {
            let opts = Options {
                bare,
                column: Column::Single,
                ..Options::default()
            };
            let s = match svg_with(name, &opts) {
                Ok(s) => s,
                Err(PlotError::InvalidOption(m)) if !SINGLE_COLUMN.contains(&name) => {
                    assert!(m.contains(name) && m.contains("single"), "{m}");
                    continue;
                }
                Err(e) => panic!("{name}: {e}"),
            };
            assert!(SINGLE_COLUMN.contains(&name), "{name} drawn in one column");
            let head = &s[..s.find('>').unwrap()];
            let (w, h) = (attr(head, "width"), attr(head, "height"));
            // 300 units printed 240 pt wide: 0.8 pt a unit; a bare figure is cut to its ink
            // at that scale.
            if bare {
                assert!(w <= 240.0, "{name} (bare): {w} pt wide");
                assert!(
                    (w / view_width(head) - 0.8).abs() < 1e-9,
                    "{name} (bare): {w} pt"
                );
            } else {
                assert_eq!(w, 240.0, "{name}: {w} pt wide");
            }
            assert!(h <= CAP, "{name} (bare {bare}): {h} pt tall");
            let (pt, text) = smallest_printed_text(&s);
            assert!(pt >= 6.0, "{name} (bare {bare}): {text:?} at {pt:.2} pt");
        }
    }
}

/// The double-column figures printed at 240 pt wide, shrunk, would not pass: their subscripts
/// fall to 7.55 × 240/520 = 3.5 pt (the measure finds text under 6 pt there).
#[test]
fn double_column_figures_shrunk_to_one_column_would_be_too_small() {
    let s = svg("lloyd2006-fig5", false);
    let (pt, _) = smallest_printed_text(&s);
    assert!(pt * 240.0 / 520.0 < 6.0, "{pt}");
}
