//! The figures fit a journal page (issue 35): every figure, captioned and bare, is at most
//! 640 pt tall (a 9-inch text block is 648 pt) at its 520 pt width, and the figures whose two
//! panels were stacked now have them side by side. Read from the SVGs as written: their `width`
//! and `height` in points, the positions of the panels' titles, and the caption's lines (at most
//! five).
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render_with, Format, Options, FIGURES};
use std::path::Path;

/// The page-height cap, in points.
const CAP: f64 = 640.0;

/// Figures still taller than [`CAP`], with the reason. Each must still be taller (so that a
/// figure brought under the cap leaves this list).
const OVER: &[(&str, &str)] = &[(
    "lloyd2005-fig8",
    "its texture panel (c) writes four lines in each partition's rectangle and needs the page's \
     width to hold them",
)];

fn svg(name: &str, bare: bool) -> String {
    // One folder per call: tests rendering the same figure at once must not share it.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "figures-page-fit-{name}-{bare}-{}-{call}",
        std::process::id()
    ));
    let opts = Options {
        bare,
        ..Options::default()
    };
    let files = render_with(name, &dir, Format::Svg, &opts).unwrap();
    let s = std::fs::read_to_string(&files[0]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    s
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

#[test]
fn every_figure_is_at_most_640_pt_tall() {
    let mut bad = Vec::new();
    for &name in FIGURES {
        for bare in [false, true] {
            let s = svg(name, bare);
            let head = &s[..s.find('>').unwrap()];
            let (w, h) = (attr(head, "width"), attr(head, "height"));
            assert_eq!(w, 520.0, "{name}: {w} pt wide");
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
        "lloyd2006-fig6",
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
