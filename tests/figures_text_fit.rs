//! No text of any figure runs past its page (issue 35: martin-tan-fig6's axis label ran past the
//! right edge). Every `<text>` of every figure's SVG is measured with DejaVu Sans' own advance
//! widths, read here from the font file (its `cmap` and `hmtx` tables), at its font size (a
//! `<tspan>` at its own size), placed by its anchor, and must lie inside the view box: across for
//! a horizontal text, along the page's height for a rotated one. The PNG draws the same texts at
//! the same anchors but larger: plotters' text size s is `font-size` s/1.24 in the SVG (DejaVu's
//! line height) and an em of s/1.164 in the bitmap (its ascent − descent), so each width is
//! checked at the PNG's 1.24/1.164 times the SVG's size, the wider of the two.
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{
    render_all, render_with, Column, Format, Options, FIGURES, SINGLE_COLUMN,
};
use std::path::Path;

mod figures_style_read;
use figures_style_read::{attr, unescape, width, Font, PNG_TEXT};

/// One `<text>` of an SVG: its tag and content, its anchor (x, y) and font size, its measured
/// width (at the PNG's larger size, [`width`]) and how much of it lies before the anchor (by its
/// `text-anchor`).
struct Text<'s> {
    tag: &'s str,
    content: &'s str,
    x: f64,
    y: f64,
    fs: f64,
    w: f64,
    before: f64,
}

/// Every `<text>` of `svg`, in order.
fn texts<'s>(font: &Font, svg: &'s str) -> Vec<Text<'s>> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find("<text ") {
        let tag_end = i + rest[i..].find('>').unwrap();
        let close = tag_end + rest[tag_end..].find("</text>").unwrap();
        let tag = &rest[i..tag_end];
        let content = &rest[tag_end + 1..close];
        rest = &rest[close..];
        let (x, y, fs) = (
            attr(tag, "x").unwrap(),
            attr(tag, "y").unwrap(),
            attr(tag, "font-size").unwrap(),
        );
        let w = width(font, content, fs) * PNG_TEXT;
        let before = match tag
            .split("text-anchor=\"")
            .nth(1)
            .and_then(|t| t.split('"').next())
        {
            Some("middle") => 0.5 * w,
            Some("end") => w,
            _ => 0.0,
        };
        out.push(Text {
            tag,
            content,
            x,
            y,
            fs,
            w,
            before,
        });
    }
    out
}

/// The texts of an SVG that leave its view box: (content, extent, page range).
fn overflowing(font: &Font, svg: &str) -> Vec<String> {
    let head = &svg[..svg.find('>').unwrap()];
    let vb: Vec<f64> = {
        let at = head.find("viewBox=\"").unwrap() + "viewBox=\"".len();
        head[at..at + head[at..].find('"').unwrap()]
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect()
    };
    let mut bad = Vec::new();
    for Text {
        tag,
        content,
        x,
        y,
        w,
        before,
        ..
    } in texts(font, svg)
    {
        // Horizontal text runs along x; a text rotated by 90° or 270° about its anchor runs
        // along y (rotate(270) upwards, so its start is below the anchor).
        let (lo, hi, page) = if tag.contains("rotate(270") {
            (y - (w - before), y + before, (vb[1], vb[1] + vb[3]))
        } else if tag.contains("rotate(90") {
            (y - before, y + w - before, (vb[1], vb[1] + vb[3]))
        } else {
            (x - before, x + w - before, (vb[0], vb[0] + vb[2]))
        };
        if lo < page.0 - 0.5 || hi > page.1 + 0.5 {
            bad.push(format!(
                "{:?} spans {lo:.1}..{hi:.1}, the page {:.0}..{:.0}",
                unescape(content),
                page.0,
                page.1
            ));
        }
    }
    bad
}

/// The measure itself: "Mx" is M's and x's advances (DejaVu Sans: 1767 and 1212 of 2048 units
/// per em, from its hmtx table), and a text too wide for its page is reported.
#[test]
fn the_font_is_measured_from_its_tables() {
    let font = Font::dejavu();
    assert_eq!(font.units_per_em, 2048.0);
    assert!((font.advance('M') - 1767.0 / 2048.0).abs() < 1e-12);
    assert!((font.advance('x') - 1212.0 / 2048.0).abs() < 1e-12);
    let svg = "<svg viewBox=\"0 0 100 50\">\n<text x=\"90\" y=\"10\" text-anchor=\"start\" \
               font-size=\"10\">Mx</text>\n</svg>";
    // 14.55 wide in the SVG, 15.50 in the PNG: from 85.3 it fits the SVG's page (to 99.85) but
    // not the PNG's (to 100.80, half a unit of tolerance allowed).
    let png_only = svg.replace("x=\"90\"", "x=\"85.3\"");
    assert_eq!(overflowing(&font, &png_only).len(), 1);
    assert_eq!(overflowing(&font, svg).len(), 1);
    let fits = svg.replace("x=\"90\"", "x=\"10\"");
    assert!(overflowing(&font, &fits).is_empty());
}

#[test]
fn no_text_runs_past_the_page() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("figures-text-fit-{}", std::process::id()));
    let files = render_all(&dir, Format::Svg, &[], |_| {}).unwrap();
    let font = Font::dejavu();
    let mut bad = Vec::new();
    for f in &files {
        let svg = std::fs::read_to_string(f).unwrap();
        for b in overflowing(&font, &svg) {
            bad.push(format!("{}: {b}", f.file_name().unwrap().to_string_lossy()));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// A text's box on the page, (x0, y0, x1, y1): across, its measured width (at the PNG's larger
/// size) from its anchor; up and down, from DejaVu Sans' cap height (0.73 em) above its baseline
/// to its descent (0.24 em) below, the baseline placed by the `dy` the SVG writer gives each
/// vertical anchor (0.76 em below `y` for a top anchor, 0.5 ex = 0.27 em for a centred one,
/// −0.27 em for a bottom one). A text rotated by 90° or 270° has the box turned about its anchor.
fn text_boxes(font: &Font, svg: &str) -> Vec<(String, [f64; 4])> {
    let mut out = Vec::new();
    for Text {
        tag,
        content,
        x,
        y,
        fs,
        w,
        before,
    } in texts(font, svg)
    {
        let base = match tag.split("dy=\"").nth(1).and_then(|t| t.split('"').next()) {
            Some("0.76em") => 0.76 * fs,
            Some("0.5ex") => 0.27 * fs,
            Some("-0.5ex") => -0.27 * fs,
            _ => 0.0,
        };
        // Across the text: from `before` left of the anchor; up and down: about the baseline.
        let (a0, a1) = (-before, w - before);
        let (b0, b1) = (base - 0.73 * fs, base + 0.24 * fs);
        let b = if tag.contains("rotate(270") {
            // Reading upwards: "across" runs to −y, "down" to +x.
            [x + b0, y - a1, x + b1, y - a0]
        } else if tag.contains("rotate(90") {
            [x - b1, y + a0, x - b0, y + a1]
        } else {
            [x + a0, y + b0, x + a1, y + b1]
        };
        out.push((unescape(content), b));
    }
    out
}

/// The pairs of texts of an SVG whose boxes ([`text_boxes`]) overlap by more than half a unit
/// both ways.
fn overlapping(font: &Font, svg: &str) -> Vec<String> {
    let boxes = text_boxes(font, svg);
    let mut bad = Vec::new();
    for (i, (ta, a)) in boxes.iter().enumerate() {
        for (tb, b) in &boxes[..i] {
            let across = a[2].min(b[2]) - a[0].max(b[0]);
            let down = a[3].min(b[3]) - a[1].max(b[1]);
            if across > 0.5 && down > 0.5 {
                bad.push(format!(
                    "{tb:?} and {ta:?} overlap by {across:.1} × {down:.1}"
                ));
            }
        }
    }
    bad
}

/// The overlap measure itself: two texts 10 units high (font size 10) on baselines 8 units
/// apart overlap; 12 apart, they do not; side by side on one baseline, they overlap only when
/// the first's measured width reaches past the second's start.
#[test]
fn overlapping_texts_are_found() {
    let font = Font::dejavu();
    let two = |x2: f64, y2: f64| {
        format!(
            "<svg viewBox=\"0 0 200 100\">\n<text x=\"10\" y=\"50\" font-size=\"10\">Mx</text>\n\
             <text x=\"{x2}\" y=\"{y2}\" font-size=\"10\">Mx</text>\n</svg>"
        )
    };
    assert_eq!(overlapping(&font, &two(10.0, 58.0)).len(), 1);
    assert!(overlapping(&font, &two(10.0, 62.0)).is_empty());
    // "Mx" at size 10 is 14.55 wide in the SVG, 15.50 at the PNG's size: from x = 10 it ends
    // at 25.50.
    assert_eq!(overlapping(&font, &two(24.0, 50.0)).len(), 1);
    assert!(overlapping(&font, &two(26.5, 50.0)).is_empty());
}

/// No two texts of any figure overlap and none runs past the page, captioned or bare, across
/// two columns and, for the figures that have it, in one (issue 35: "no text overlaps in any
/// output").
#[test]
fn no_two_texts_overlap() {
    let mut bad = Vec::new();
    let font = Font::dejavu();
    for (column, names) in [(Column::Double, FIGURES), (Column::Single, SINGLE_COLUMN)] {
        for bare in [false, true] {
            let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
                "figures-text-overlap-{column:?}-{bare}-{}",
                std::process::id()
            ));
            let opts = Options {
                bare,
                column,
                ..Options::default()
            };
            for name in names {
                let files = render_with(name, &dir, Format::Svg, &opts).unwrap();
                let svg = std::fs::read_to_string(&files[0]).unwrap();
                for b in overlapping(&font, &svg) {
                    bad.push(format!("{name} ({column:?}, bare {bare}): {b}"));
                }
                if column == Column::Single {
                    for b in overflowing(&font, &svg) {
                        bad.push(format!("{name} ({column:?}, bare {bare}): {b}"));
                    }
                }
            }
            let _ = std::fs::remove_dir_all(&dir);
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
