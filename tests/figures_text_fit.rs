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

/// The PNG's text over the SVG's (see the file's header).
const PNG_TEXT: f64 = 1.24 / 1.164;

/// DejaVu Sans' advance widths, in em, by character.
struct Font {
    data: &'static [u8],
    units_per_em: f64,
    hmtx: usize,
    metrics: u16,
    cmap4: usize,
}

fn u16_at(d: &[u8], at: usize) -> u16 {
    u16::from_be_bytes([d[at], d[at + 1]])
}

fn u32_at(d: &[u8], at: usize) -> u32 {
    u32::from_be_bytes([d[at], d[at + 1], d[at + 2], d[at + 3]])
}

impl Font {
    fn dejavu() -> Self {
        let data = dejavu::sans::regular();
        let table = |tag: &[u8; 4]| -> usize {
            let n = usize::from(u16_at(data, 4));
            (0..n)
                .map(|i| 12 + 16 * i)
                .find(|&r| &data[r..r + 4] == tag)
                .map(|r| u32_at(data, r + 8) as usize)
                .unwrap_or_else(|| panic!("no {} table", String::from_utf8_lossy(tag)))
        };
        let head = table(b"head");
        let hhea = table(b"hhea");
        let cmap = table(b"cmap");
        // The Unicode BMP subtable (platform 3, encoding 1), format 4.
        let cmap4 = (0..usize::from(u16_at(data, cmap + 2)))
            .map(|i| cmap + 4 + 8 * i)
            .find(|&r| u16_at(data, r) == 3 && u16_at(data, r + 2) == 1)
            .map(|r| cmap + u32_at(data, r + 4) as usize)
            .expect("a (3, 1) cmap");
        assert_eq!(u16_at(data, cmap4), 4, "cmap format");
        Self {
            data,
            units_per_em: f64::from(u16_at(data, head + 18)),
            hmtx: table(b"hmtx"),
            metrics: u16_at(data, hhea + 34),
            cmap4,
        }
    }

    /// The glyph of `c` (0, the missing glyph, where the font has none).
    fn glyph(&self, c: char) -> u16 {
        let Ok(c) = u16::try_from(u32::from(c)) else {
            return 0;
        };
        let d = self.data;
        let t = self.cmap4;
        let segs = usize::from(u16_at(d, t + 6) / 2);
        let ends = t + 14;
        let starts = ends + 2 * segs + 2;
        let deltas = starts + 2 * segs;
        let ranges = deltas + 2 * segs;
        for i in 0..segs {
            if c > u16_at(d, ends + 2 * i) {
                continue;
            }
            let start = u16_at(d, starts + 2 * i);
            if c < start {
                return 0;
            }
            let delta = u16_at(d, deltas + 2 * i);
            let range = usize::from(u16_at(d, ranges + 2 * i));
            if range == 0 {
                return c.wrapping_add(delta);
            }
            let at = ranges + 2 * i + range + 2 * usize::from(c - start);
            let g = u16_at(d, at);
            return if g == 0 { 0 } else { g.wrapping_add(delta) };
        }
        0
    }

    /// The advance of `c`, in em.
    fn advance(&self, c: char) -> f64 {
        let g = self.glyph(c).min(self.metrics - 1);
        f64::from(u16_at(self.data, self.hmtx + 4 * usize::from(g))) / self.units_per_em
    }
}

fn attr(tag: &str, name: &str) -> Option<f64> {
    let key = format!(" {name}=\"");
    let at = tag.find(&key)? + key.len();
    tag[at..at + tag[at..].find('"')?].parse().ok()
}

fn unescape(s: &str) -> String {
    s.replace("&apos;", "'")
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

/// The width of a `<text>`'s content at its font size `size`: plain runs at `size`, each
/// `<tspan>` with a `font-size` at that size.
fn width(font: &Font, content: &str, size: f64) -> f64 {
    let run = |s: &str, fs: f64| unescape(s).chars().map(|c| font.advance(c)).sum::<f64>() * fs;
    let mut w = 0.0;
    let mut rest = content;
    while let Some(i) = rest.find("<tspan") {
        w += run(&rest[..i], size);
        let tag_end = i + rest[i..].find('>').unwrap();
        let close = tag_end + rest[tag_end..].find("</tspan>").unwrap();
        let fs = attr(&rest[i..tag_end], "font-size").unwrap_or(size);
        w += run(&rest[tag_end + 1..close], fs);
        rest = &rest[close + "</tspan>".len()..];
    }
    w + run(rest, size)
}

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
