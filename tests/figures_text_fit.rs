//! No text of any figure runs past its page (issue 35: martin-tan-fig6's axis label ran past the
//! right edge). Every `<text>` of every figure's SVG is measured with DejaVu Sans' own advance
//! widths, read here from the font file (its `cmap` and `hmtx` tables), at its font size (a
//! `<tspan>` at its own size), placed by its anchor, and must lie inside the view box: across for
//! a horizontal text, along the page's height for a rotated one. The PNG draws the same texts at
//! the same anchors but larger: plotters' text size s is `font-size` s/1.24 in the SVG (DejaVu's
//! line height) and an em of s/1.164 in the bitmap (its ascent − descent), so each width is
//! checked at the PNG's 1.24/1.164 times the SVG's size, the wider of the two.
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render_all, Format};
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
