//! Reading back the figures' SVGs for the style and text-fit tests (tests/figures_style_*.rs,
//! tests/figures_text_fit.rs): their texts measured with DejaVu Sans' own advance widths (read
//! here from the font file's `cmap` and `hmtx` tables, not from the crate), their polylines,
//! marker polygons and legend boxes, and the figures rendered in every layout.
#![allow(dead_code)]

use shadow_aliasing::plot::{render_with, Column, Format, Options, FIGURES, SINGLE_COLUMN};
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::OnceLock;

/// The PNG draws text 1.24/1.164 times the SVG's size (plotters' size s is `font-size` s/1.24
/// in the SVG and an em of s/1.164 in the bitmap): widths are measured at the PNG's, the wider.
pub const PNG_TEXT: f64 = 1.24 / 1.164;

/// DejaVu Sans' advance widths, in em, by character.
pub struct Font {
    data: &'static [u8],
    pub units_per_em: f64,
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
    pub fn dejavu() -> Self {
        let data = dejavu::sans::regular();
        let table = |tag: &[u8; 4]| -> usize {
            let n = usize::from(u16_at(data, 4));
            (0..n)
                .map(|i| 12 + 16 * i)
                .find(|&r| &data[r..r + 4] == tag)
                .map(|r| u32_at(data, r + 8) as usize)
                .unwrap_or_else(|| panic!("no {} table", String::from_utf8_lossy(tag)))
        };
        let (head, hhea, cmap) = (table(b"head"), table(b"hhea"), table(b"cmap"));
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

    fn glyph(&self, c: char) -> u16 {
        let Ok(c) = u16::try_from(u32::from(c)) else {
            return 0;
        };
        let (d, t) = (self.data, self.cmap4);
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
            let g = u16_at(d, ranges + 2 * i + range + 2 * usize::from(c - start));
            return if g == 0 { 0 } else { g.wrapping_add(delta) };
        }
        0
    }

    /// The advance of `c`, in em.
    pub fn advance(&self, c: char) -> f64 {
        let g = self.glyph(c).min(self.metrics - 1);
        f64::from(u16_at(self.data, self.hmtx + 4 * usize::from(g))) / self.units_per_em
    }
}

/// The number of the attribute `name` of a tag.
pub fn attr(tag: &str, name: &str) -> Option<f64> {
    let key = format!(" {name}=\"");
    let at = tag.find(&key)? + key.len();
    tag[at..at + tag[at..].find('"')?].parse().ok()
}

/// The text of the attribute `name` of a tag.
pub fn attr_str<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let at = tag.find(&key)? + key.len();
    Some(&tag[at..at + tag[at..].find('"')?])
}

pub fn unescape(s: &str) -> String {
    s.replace("&apos;", "'")
        .replace("&quot;", "\"")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

/// The width of a `<text>`'s content at font size `size` (each `<tspan>` at its own size).
pub fn width(font: &Font, content: &str, size: f64) -> f64 {
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

/// A `<text>`: its tag, visible content (tags removed), anchor, font size, and its box on the page
/// [x0, y0, x1, y1]: across, its measured width at the PNG's size from its anchor; up and down,
/// from DejaVu Sans' cap height (0.73 em) above its baseline to its descent (0.24 em) below,
/// the baseline placed by the `dy` the SVG writer gives each vertical anchor. A text rotated
/// by 90° or 270° has the box turned about its anchor.
#[derive(Debug, Clone)]
pub struct Text {
    pub tag: String,
    pub content: String,
    pub x: f64,
    pub y: f64,
    pub fs: f64,
    pub rotated: bool,
    pub bbox: [f64; 4],
}

/// Every `<text>` of `svg`, in order.
pub fn texts(font: &Font, svg: &str) -> Vec<Text> {
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
        let before = match attr_str(tag, "text-anchor") {
            Some("middle") => 0.5 * w,
            Some("end") => w,
            _ => 0.0,
        };
        let base = match attr_str(tag, "dy") {
            Some("0.76em") => 0.76 * fs,
            Some("0.5ex") => 0.27 * fs,
            Some("-0.5ex") => -0.27 * fs,
            _ => 0.0,
        };
        let (a0, a1) = (-before, w - before);
        // Up and down: each `<tspan>` moves the baseline by its `dy` (cumulative) and has its
        // own size; a raised superscript reaches above the main text's capitals.
        let (mut b0, mut b1) = (base - 0.73 * fs, base + 0.24 * fs);
        let mut shift = 0.0;
        let mut rest = content;
        while let Some(i) = rest.find("<tspan") {
            let tag_end = i + rest[i..].find('>').unwrap();
            let t = &rest[i..tag_end];
            shift += attr(t, "dy").unwrap_or(0.0);
            let f = attr(t, "font-size").unwrap_or(fs);
            b0 = f64::min(b0, base + shift - 0.73 * f);
            b1 = f64::max(b1, base + shift + 0.24 * f);
            rest = &rest[tag_end..];
        }
        let (rotated, bbox) = if tag.contains("rotate(270") {
            (true, [x + b0, y - a1, x + b1, y - a0])
        } else if tag.contains("rotate(90") {
            (true, [x - b1, y + a0, x - b0, y + a1])
        } else {
            (false, [x + a0, y + b0, x + a1, y + b1])
        };
        let mut visible = String::new();
        let mut in_tag = false;
        for c in content.chars() {
            match c {
                '<' => in_tag = true,
                '>' => in_tag = false,
                _ if !in_tag => visible.push(c),
                _ => {}
            }
        }
        out.push(Text {
            tag: tag.to_string(),
            content: unescape(&visible),
            x,
            y,
            fs,
            rotated,
            bbox,
        });
    }
    out
}

/// The points of a `points="x,y x,y …"` attribute (none where `tag` has no such attribute).
pub fn points(tag: &str) -> Vec<(f64, f64)> {
    attr_str(tag, "points")
        .unwrap_or("")
        .split_whitespace()
        .filter_map(|p| {
            let (a, b) = p.split_once(',')?;
            Some((a.parse().ok()?, b.parse().ok()?))
        })
        .collect()
}

/// The bounding box [x min, y min, x max, y max] of some points.
pub fn bbox(p: &[(f64, f64)]) -> Box4 {
    p.iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, q| [b[0].min(q.0), b[1].min(q.1), b[2].max(q.0), b[3].max(q.1)],
    )
}

/// A stroked `<polyline>` or a filled `<polygon>`: its colour and points.
#[derive(Debug, Clone)]
pub struct Shape {
    pub colour: String,
    pub points: Vec<(f64, f64)>,
}

/// Every `<polyline>` of `svg` (the data lines, their dashes and legend samples).
pub fn polylines(svg: &str) -> Vec<Shape> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline"))
        .map(|l| Shape {
            colour: attr_str(l, "stroke").unwrap_or("").to_string(),
            points: points(l),
        })
        .collect()
}

/// Every `<polygon>` of `svg` (markers, fills).
pub fn polygons(svg: &str) -> Vec<Shape> {
    svg.lines()
        .filter(|l| l.starts_with("<polygon"))
        .map(|l| Shape {
            colour: attr_str(l, "fill").unwrap_or("").to_string(),
            points: points(l),
        })
        .collect()
}

/// A box [x0, y0, x1, y1].
pub type Box4 = [f64; 4];

/// The legend boxes of `svg`: a white translucent `<rect>` (opacity 0.9) outlined by the next
/// `<rect>` at the same place.
pub fn legend_boxes(svg: &str) -> Vec<Box4> {
    let lines: Vec<&str> = svg.lines().collect();
    let rect = |l: &str| -> Option<Box4> {
        let (x, y) = (attr(l, "x")?, attr(l, "y")?);
        Some([x, y, x + attr(l, "width")?, y + attr(l, "height")?])
    };
    lines
        .windows(2)
        .filter(|w| {
            w[0].starts_with("<rect")
                && w[0].contains("fill=\"#FFFFFF\"")
                && w[0].contains("opacity=\"0.9\"")
                && w[1].starts_with("<rect")
                && w[1].contains("fill=\"none\"")
        })
        .filter_map(|w| {
            let (a, b) = (rect(w[0])?, rect(w[1])?);
            (a == b).then_some(a)
        })
        .collect()
}

/// Whether the segment a–b passes through the inside of box `r` (Liang–Barsky, strictly
/// inside by `tol` on every side).
pub fn segment_enters(a: (f64, f64), b: (f64, f64), r: &Box4, tol: f64) -> bool {
    let (x0, y0, x1, y1) = (r[0] + tol, r[1] + tol, r[2] - tol, r[3] - tol);
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q <= 0.0 {
                return false;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    t0 < t1
}

/// Whether every point lies within `r` (a legend's own sample or marker).
pub fn within(points: &[(f64, f64)], r: &Box4) -> bool {
    points
        .iter()
        .all(|p| p.0 >= r[0] && p.0 <= r[2] && p.1 >= r[1] && p.1 <= r[3])
}

/// The SVG of figure `name` rendered with `opts`, in a folder of its own (one per call: tests
/// rendering the same figure at once must not share it), removed afterwards.
pub fn render_svg(name: &str, opts: &Options) -> String {
    static CALLS: AtomicUsize = AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, Ordering::Relaxed);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("figures-svg-{name}-{}-{call}", std::process::id()));
    let files = render_with(name, &dir, Format::Svg, opts).unwrap();
    let svg = std::fs::read_to_string(&files[0]).unwrap();
    let _ = std::fs::remove_dir_all(&dir);
    svg
}

/// Every figure's SVG in every layout: (name, layout, svg), captioned across two columns and
/// in one, and bare across two columns; rendered once per test binary.
pub fn all_svgs() -> &'static [(String, String, String)] {
    static ALL: OnceLock<Vec<(String, String, String)>> = OnceLock::new();
    ALL.get_or_init(|| {
        let mut out = Vec::new();
        for (column, bare, names) in [
            (Column::Double, false, FIGURES),
            (Column::Single, false, SINGLE_COLUMN),
            (Column::Double, true, FIGURES),
        ] {
            let opts = Options {
                bare,
                column,
                ..Options::default()
            };
            for name in names {
                out.push((
                    name.to_string(),
                    format!("{column:?}{}", if bare { ", bare" } else { "" }),
                    render_svg(name, &opts),
                ));
            }
        }
        out
    })
}

/// The scheme a label or key text names, by whole tokens ("ZP+W" is not "ZP"): FP+ZP+W, ZP+W,
/// ZP, LiSPSM, PSM, uniform, Zhang, Barroso; none for a text naming none or two (a curve ZP and
/// ZP+W share).
pub fn scheme_of(label: &str) -> Option<&'static str> {
    let tokens: Vec<&str> = label
        .split(|c: char| !(c.is_alphanumeric() || c == '+'))
        .filter(|t| !t.is_empty())
        .collect();
    let named: Vec<&'static str> = [
        "FP+ZP+W", "ZP+W", "ZP", "LiSPSM", "PSM", "uniform", "Zhang", "Barroso",
    ]
    .into_iter()
    .filter(|s| tokens.contains(s))
    .collect();
    match named[..] {
        [one] => Some(one),
        _ => None,
    }
}

/// A coloured mark of an SVG: its colour and its box.
pub fn marks(svg: &str) -> Vec<(String, Box4)> {
    let mut out = Vec::new();
    let bbox = |pts: &[(f64, f64)]| -> Box4 {
        let xs = pts.iter().map(|p| p.0);
        let ys = pts.iter().map(|p| p.1);
        [
            xs.clone().fold(f64::INFINITY, f64::min),
            ys.clone().fold(f64::INFINITY, f64::min),
            xs.fold(f64::NEG_INFINITY, f64::max),
            ys.fold(f64::NEG_INFINITY, f64::max),
        ]
    };
    for s in polylines(svg).into_iter().chain(polygons(svg)) {
        if !s.points.is_empty() {
            out.push((s.colour, bbox(&s.points)));
        }
    }
    for l in svg.lines().filter(|l| l.starts_with("<rect")) {
        let fill = attr_str(l, "fill").unwrap_or("none");
        if let (Some(x), Some(y), Some(w), Some(h)) = (
            attr(l, "x"),
            attr(l, "y"),
            attr(l, "width"),
            attr(l, "height"),
        ) {
            if fill != "none" && fill != "#FFFFFF" && w < 40.0 && h < 40.0 {
                out.push((fill.to_string(), [x, y, x + w, y + h]));
            }
        }
    }
    out
}

/// Each key entry of `svg` naming one scheme ([`scheme_of`]): (scheme, colour of the mark
/// nearest left of its black text on its row, at most 40 units away: a line or marker sample or
/// a swatch).
pub fn key_colours(font: &Font, svg: &str) -> Vec<(&'static str, String)> {
    let marks = marks(svg);
    texts(font, svg)
        .into_iter()
        .filter(|t| !t.rotated && t.tag.contains("fill=\"#000000\""))
        .filter_map(|t| {
            let scheme = scheme_of(&t.content)?;
            let left = t.bbox[0];
            let mid = 0.5 * (t.bbox[1] + t.bbox[3]);
            marks
                .iter()
                .filter(|(_, b)| {
                    let cy = 0.5 * (b[1] + b[3]);
                    b[2] <= left + 0.5 && b[2] >= left - 40.0 && (cy - mid).abs() <= 6.0
                })
                .max_by(|a, b| a.1[2].total_cmp(&b.1[2]))
                .map(|(c, _)| (scheme, c.clone()))
        })
        .collect()
}

/// The three forms a figure is written in, named as the figure tests report them: two columns
/// with title and caption, bare (no title or caption, cropped), one column.
pub fn forms() -> [(&'static str, Options); 3] {
    [
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

/// Points (1/72 in) per unit of `svg`'s view box: its `width="…pt"` over the view box's width.
pub fn points_per_unit(svg: &str) -> f64 {
    let head = &svg[..svg.find('>').unwrap()];
    let w: f64 = attr_str(head, "width")
        .unwrap()
        .trim_end_matches("pt")
        .parse()
        .unwrap();
    let vb: Vec<f64> = attr_str(head, "viewBox")
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    w / vb[2]
}

/// A `<polyline>` with its stroke width: its stroke colour, width (1 where the tag gives
/// none) and points.
#[derive(Debug, Clone)]
pub struct Stroke {
    pub stroke: String,
    pub width: f64,
    pub points: Vec<(f64, f64)>,
}

/// Every `<polyline>` of `svg` with its stroke width (rings, contour dashes and their halos).
pub fn strokes(svg: &str) -> Vec<Stroke> {
    svg.lines()
        .filter(|l| l.starts_with("<polyline"))
        .map(|l| Stroke {
            stroke: attr_str(l, "stroke").unwrap_or("").to_string(),
            width: attr(l, "stroke-width").unwrap_or(1.0),
            points: points(l),
        })
        .collect()
}

/// The distance from `p` to the segment a–b.
pub fn to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// The distance from `p` to the polyline `line` (infinite for no points).
pub fn to_polyline(p: (f64, f64), line: &[(f64, f64)]) -> f64 {
    match line {
        [] => f64::INFINITY,
        [a] => to_segment(p, *a, *a),
        _ => line
            .windows(2)
            .map(|w| to_segment(p, w[0], w[1]))
            .fold(f64::INFINITY, f64::min),
    }
}

/// The distance from `p` to the box `r` (0 inside it).
pub fn to_box(p: (f64, f64), r: &Box4) -> f64 {
    let dx = (r[0] - p.0).max(p.0 - r[2]).max(0.0);
    let dy = (r[1] - p.1).max(p.1 - r[3]).max(0.0);
    dx.hypot(dy)
}

/// The byte offset in `svg`, at or after `from`, of ">`title`" in the first `<text>` line that
/// is no caption's (their grey, #323232) and whose text starts with `title` (a panel's title,
/// "(e)": a caption line may start with "(e)" too, and captions are written first).
pub fn title_at(svg: &str, from: usize, title: &str) -> Option<usize> {
    let key = format!(">{title}");
    let mut at = 0;
    for line in svg.split_inclusive('\n') {
        let start = at;
        at += line.len();
        if line.starts_with("<text") && !line.contains("fill=\"#323232\"") {
            if let Some(i) = line.find(&key) {
                if start + i >= from {
                    return Some(start + i);
                }
            }
        }
    }
    None
}
