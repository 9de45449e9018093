//! `--bare` (`Options::bare`) crops: a bare figure is the captioned figure laid out the same, its
//! title and caption left out, and its page cut to the box of its ink with 3 units of white on
//! each side (the sixth figure review, R6-X-7): the PNG's pixels, the SVG's view box and the
//! PDF's page.
//!
//! For every figure, the captioned and the bare SVG and PNG (and, with the feature `pdf`, the
//! bare PDF) are rendered, and:
//! - the captioned figure's plot area is the band between the bottom of its title (the text at
//!   the top, drawn at the title's size) and the top of its caption (the grey paragraph at the
//!   bottom);
//! - the bare SVG holds exactly the captioned SVG's elements less the title's and the caption's,
//!   unmoved (the same layout, not stretched);
//! - its view box is a box inside that plot area holding every shape it draws, and the captioned
//!   PNG has no ink in the plot area outside it (nothing is cut);
//! - the bare PNG is the captioned PNG's pixels of that box, pixel for pixel, the white between
//!   its ink and each of its four edges is 2.5 to 4 units, and the bare PDF's page is the view
//!   box's size.
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render_with, Format, Options, FIGURES, PNG_ZOOM};
use std::path::{Path, PathBuf};

/// A fresh directory per test and per process.
fn out_dir(sub: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{sub}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn attr(tag: &str, name: &str) -> Option<f64> {
    let key = format!(" {name}=\"");
    let at = tag.find(&key)? + key.len();
    tag[at..at + tag[at..].find('"')?].parse().ok()
}

fn attr_str<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let at = tag.find(&key)? + key.len();
    Some(&tag[at..at + tag[at..].find('"')?])
}

/// The elements of an SVG written by the crate: one per line after the `<svg>` line (a text
/// element may hold line breaks inside its content, so elements are split at `\n<`).
fn elements(svg: &str) -> Vec<&str> {
    let body = &svg[svg.find('>').unwrap() + 1..svg.rfind("</svg>").unwrap()];
    body.split("\n<")
        .map(|e| e.trim_matches('\n'))
        .filter(|e| !e.is_empty())
        .collect()
}

/// The `<svg>` header's view box `(x, y, width, height)` and its `width`, `height`.
fn view_box(svg: &str) -> ([f64; 4], f64, f64) {
    let head = &svg[..svg.find('>').unwrap()];
    let vb: Vec<f64> = attr_str(head, "viewBox")
        .unwrap()
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    let points = |name: &str| -> f64 {
        let v = attr_str(head, name).unwrap();
        v.strip_suffix("pt")
            .expect("a length in points")
            .parse()
            .unwrap()
    };
    (
        [vb[0], vb[1], vb[2], vb[3]],
        points("width"),
        points("height"),
    )
}

/// The title's size as written (plotters' 20 over DejaVu's line height 1.24) and the caption's
/// colour.
const TITLE_FONT: &str = "font-size=\"16.129\"";
const CAPTION_FILL: &str = "fill=\"#323232\"";

/// The vertical extent `[top, bottom]` of an element, in view-box units: a text's glyphs from its
/// baseline (DejaVu Sans: ascent 0.93 em, descent 0.24 em; a rotated text at its anchor), a
/// shape's coordinates.
fn extent(e: &str) -> Option<(f64, f64)> {
    let ys = |name: &str| attr(e, name);
    if e.starts_with("text") {
        let y = ys("y")?;
        let fs = ys("font-size")?;
        if e.contains(" transform=\"rotate") {
            return Some((y, y));
        }
        let base = match attr_str(e, "dy") {
            Some("0.76em") => y + 0.76 * fs,
            Some("0.5ex") => y + 0.5 * 0.55 * fs,
            Some("-0.5ex") => y - 0.5 * 0.55 * fs,
            other => panic!("text anchored by {other:?}"),
        };
        return Some((base - 0.93 * fs, base + 0.24 * fs));
    }
    if e.starts_with("rect") || e.starts_with("image") {
        let y = ys("y")?;
        return Some((y, y + ys("height")?));
    }
    if e.starts_with("line") {
        let (a, b) = (ys("y1")?, ys("y2")?);
        return Some((a.min(b), a.max(b)));
    }
    if e.starts_with("circle") {
        let (c, r) = (ys("cy")?, ys("r")?);
        return Some((c - r, c + r));
    }
    if e.starts_with("polyline") || e.starts_with("polygon") {
        let pts = attr_str(e, "points")?;
        let y: Vec<f64> = pts
            .split_whitespace()
            .map(|p| p.split_once(',').unwrap().1.parse().unwrap())
            .collect();
        return Some((
            y.iter().copied().fold(f64::INFINITY, f64::min),
            y.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        ));
    }
    None
}

/// Checks one figure's bare SVG, PNG and PDF against its captioned SVG and PNG.
fn check(name: &str, dir: &Path) {
    let opts = Options::default();
    let bare = Options { bare: true, ..opts };
    let cap_dir = dir.join("captioned");
    let bare_dir = dir.join("bare");
    render_with(name, &cap_dir, Format::Both, &opts).unwrap();
    render_with(name, &bare_dir, Format::Both, &bare).unwrap();
    let read = |d: &Path, ext: &str| std::fs::read(d.join(format!("{name}.{ext}"))).unwrap();
    let cap_svg = String::from_utf8(read(&cap_dir, "svg")).unwrap();
    let bare_svg = String::from_utf8(read(&bare_dir, "svg")).unwrap();

    // The captioned page: the whole of it, its title at the top and its caption at the bottom.
    let (cap_vb, _, _) = view_box(&cap_svg);
    let (page_w, page_h) = (cap_vb[2], cap_vb[3]);
    assert_eq!((cap_vb[0], cap_vb[1]), (0.0, 0.0), "{name}");
    let cap = elements(&cap_svg);
    let is_title = |e: &str| {
        e.starts_with("text") && e.contains(TITLE_FONT) && {
            let (_, bottom) = extent(e).unwrap();
            bottom < 0.2 * page_h
        }
    };
    let is_caption = |e: &str| e.starts_with("text") && e.contains(CAPTION_FILL);
    let title_bottom = cap
        .iter()
        .filter(|e| is_title(e))
        .map(|e| extent(e).unwrap().1)
        .fold(f64::NAN, f64::max);
    let caption_top = cap
        .iter()
        .filter(|e| is_caption(e))
        .map(|e| extent(e).unwrap().0)
        .fold(f64::NAN, f64::min);
    assert!(
        title_bottom > 0.0 && caption_top < page_h,
        "{name}: no title or no caption found in the captioned figure"
    );

    // The bare SVG: the captioned one's elements less the title and caption, unmoved.
    let plot: Vec<&str> = cap
        .iter()
        .copied()
        .filter(|e| !is_title(e) && !is_caption(e))
        .collect();
    let bare_elements = elements(&bare_svg);
    assert_eq!(
        bare_elements.len(),
        plot.len(),
        "{name}: the bare figure has other elements than the captioned one's plot"
    );
    for (b, c) in bare_elements.iter().zip(&plot) {
        assert_eq!(
            b, c,
            "{name}: an element differs from the captioned figure's"
        );
    }

    // Its view box: a box inside the plot area holding every shape drawn (a text's extent is
    // read from the PNG below: its glyphs' ink, not its font's box).
    let (vb, w, h) = view_box(&bare_svg);
    let (left, top, right, bottom) = (vb[0], vb[1], vb[0] + vb[2], vb[1] + vb[3]);
    assert_eq!((w, h), (vb[2], vb[3]), "{name}: size and view box differ");
    assert!(
        left >= 0.0 && right <= page_w && top >= title_bottom && bottom <= caption_top,
        "{name}: the bare view box {vb:?} is not inside the plot area \
         0..{page_w} x {title_bottom}..{caption_top}"
    );
    let page_background = |e: &str| {
        e.starts_with("rect")
            && attr(e, "y") == Some(0.0)
            && attr(e, "height") == Some(page_h)
            && attr(e, "width") == Some(page_w)
    };
    for e in plot.iter().filter(|e| !page_background(e)) {
        if let Some([x0, y0, x1, y1]) = shape_box(e) {
            assert!(
                x0 >= left - 1e-9 && x1 <= right + 1e-9 && y0 >= top - 1e-9 && y1 <= bottom + 1e-9,
                "{name}: {x0}..{x1} x {y0}..{y1} is cut by the view box {vb:?}: <{e}"
            );
        }
    }

    // The PNG: the captioned PNG's pixels of the box, pixel for pixel.
    let cap_png = image::load_from_memory(&read(&cap_dir, "png"))
        .unwrap()
        .to_rgb8();
    let bare_png = image::load_from_memory(&read(&bare_dir, "png"))
        .unwrap()
        .to_rgb8();
    let z = PNG_ZOOM;
    assert_eq!(
        bare_png.dimensions(),
        (vb[2] as u32 * z, vb[3] as u32 * z),
        "{name}: PNG size"
    );
    let (x0, y0) = (vb[0] as u32 * z, vb[1] as u32 * z);
    for (x, y, p) in bare_png.enumerate_pixels() {
        assert_eq!(
            p,
            cap_png.get_pixel(x + x0, y + y0),
            "{name}: PNG pixel ({x}, {y}) differs from the captioned figure's ({}, {})",
            x + x0,
            y + y0
        );
    }
    // Nothing is cut: the captioned PNG has no ink in the plot area outside the box (less 3
    // units at either end: the PNG's glyphs of the title and caption, a prime or a superscript,
    // stand up to 2 units beyond the SVG's font box; the body is 5 units from either).
    let (band0, band1) = (
        ((title_bottom + 3.0) * z as f64).ceil() as u32,
        ((caption_top - 3.0) * z as f64) as u32,
    );
    for y in band0..band1.min(cap_png.height()) {
        for x in 0..cap_png.width() {
            let inside = (x0..x0 + bare_png.width()).contains(&x)
                && (y0..y0 + bare_png.height()).contains(&y);
            assert!(
                inside || !is_ink(cap_png.get_pixel(x, y)),
                "{name}: ink at ({x}, {y}) of the captioned PNG is cut by the bare box {vb:?}"
            );
        }
    }
    white_margins(name, &bare_png, z as f64);

    #[cfg(feature = "pdf")]
    {
        render_with(name, &bare_dir, Format::Pdf, &bare).unwrap();
        let pdf = read(&bare_dir, "pdf");
        let text = String::from_utf8_lossy(&pdf);
        let at = text.find("/MediaBox [").expect("a MediaBox") + "/MediaBox [".len();
        let media: Vec<f64> = text[at..at + text[at..].find(']').unwrap()]
            .split_whitespace()
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(media, vec![0.0, 0.0, vb[2], vb[3]], "{name}: PDF page");
    }
}

/// A PNG pixel that is not white: darker than 250 in a channel.
fn is_ink(p: &image::Rgb<u8>) -> bool {
    p.0.iter().any(|&c| c < 250)
}

/// The least and the most white a bare figure keeps between its ink and each edge, in units
/// (the sixth figure review, R6-X-7: the crops kept about 14 pt above the panel titles and the
/// page's full width; and 0.3 units under a colour bar's name, a crop on the descender; the ninth
/// and eleventh, R9-X-5 and R11-X-6: 1.5 to 3 units left a text's box 1 pt or less from the
/// crop).
const BARE_MARGIN: (f64, f64) = (2.5, 4.0);

/// The white between the ink of the bare PNG `png` (at `z` pixels a unit) and each of its four
/// edges lies within [`BARE_MARGIN`].
fn white_margins(name: &str, png: &image::RgbImage, z: f64) {
    let (mut x0, mut y0, mut x1, mut y1) = (u32::MAX, u32::MAX, 0, 0);
    for (x, y, p) in png.enumerate_pixels() {
        if is_ink(p) {
            (x0, y0, x1, y1) = (x0.min(x), y0.min(y), x1.max(x + 1), y1.max(y + 1));
        }
    }
    assert!(x0 < x1, "{name}: no ink");
    let sides = [
        ("left", x0),
        ("top", y0),
        ("right", png.width() - x1),
        ("bottom", png.height() - y1),
    ];
    for (side, px) in sides {
        let units = f64::from(px) / z;
        assert!(
            (BARE_MARGIN.0..=BARE_MARGIN.1).contains(&units),
            "{name}: {units:.2} units of white at the {side} (want {:?})",
            BARE_MARGIN
        );
    }
}

/// The box `[x0, y0, x1, y1]` of a shape of the SVG (not a text, not white), in view-box units.
fn shape_box(e: &str) -> Option<[f64; 4]> {
    let paint = |k: &str| attr_str(e, k).unwrap_or("none");
    let white = |c: &str| c == "none" || c.eq_ignore_ascii_case("#FFFFFF");
    if !e.starts_with("image") && white(paint("fill")) && white(paint("stroke")) {
        return None;
    }
    let a = |k: &str| attr(e, k);
    if e.starts_with("rect") || e.starts_with("image") {
        let (x, y) = (a("x")?, a("y")?);
        return Some([x, y, x + a("width")?, y + a("height")?]);
    }
    if e.starts_with("line") {
        let (xa, ya, xb, yb) = (a("x1")?, a("y1")?, a("x2")?, a("y2")?);
        return Some([xa.min(xb), ya.min(yb), xa.max(xb), ya.max(yb)]);
    }
    if e.starts_with("circle") {
        let (x, y, r) = (a("cx")?, a("cy")?, a("r")?);
        return Some([x - r, y - r, x + r, y + r]);
    }
    if e.starts_with("polyline") || e.starts_with("polygon") {
        let pts: Vec<(f64, f64)> = attr_str(e, "points")?
            .split_whitespace()
            .map(|p| {
                let (x, y) = p.split_once(',').unwrap();
                (x.parse().unwrap(), y.parse().unwrap())
            })
            .collect();
        let f = |g: fn(&(f64, f64)) -> f64, m: fn(f64, f64) -> f64, i: f64| {
            pts.iter().map(g).fold(i, m)
        };
        return Some([
            f(|p| p.0, f64::min, f64::INFINITY),
            f(|p| p.1, f64::min, f64::INFINITY),
            f(|p| p.0, f64::max, f64::NEG_INFINITY),
            f(|p| p.1, f64::max, f64::NEG_INFINITY),
        ]);
    }
    None
}

/// The one-column bare figures keep 2.5 to 4 units of white around their ink too (PNG only:
/// the checks of `check` above are the two-column figures').
#[test]
fn one_column_bare_figures_keep_white_around_their_ink() {
    let opts = Options {
        bare: true,
        column: shadow_aliasing::plot::Column::Single,
        ..Options::default()
    };
    let dir = out_dir("figures-bare-single");
    for name in FIGURES {
        render_with(name, &dir, Format::Png, &opts).unwrap();
        let png = image::open(dir.join(format!("{name}.png")))
            .unwrap()
            .to_rgb8();
        white_margins(name, &png, PNG_ZOOM as f64);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// One test per figure, so that they run in parallel and a failure names its figure.
macro_rules! bare_tests {
    ($($test:ident => $name:literal,)*) => {
        $(
            #[test]
            fn $test() {
                let dir = out_dir(concat!("figures-bare-", $name));
                check($name, &dir);
                let _ = std::fs::remove_dir_all(&dir);
            }
        )*
        /// The tests above cover every figure.
        #[test]
        fn every_figure_has_its_bare_test() {
            assert_eq!(&[$($name),*], FIGURES);
        }
    };
}

bare_tests! {
    bare_lloyd2005_fig4 => "lloyd2005-fig4",
    bare_lloyd2005_fig7 => "lloyd2005-fig7",
    bare_lloyd2006_fig5 => "lloyd2006-fig5",
    bare_lloyd2006_fig6 => "lloyd2006-fig6",
    bare_lloyd2006_fig7 => "lloyd2006-fig7",
    bare_lloyd2006_fig10 => "lloyd2006-fig10",
    bare_lloyd2006_fig12 => "lloyd2006-fig12",
    bare_lloyd2006_fig13 => "lloyd2006-fig13",
    bare_barroso_fig7 => "barroso-fig7",
    bare_zhang_fig3 => "zhang-fig3",
    bare_martin_tan_fig6 => "martin-tan-fig6",
    bare_lloyd2006_worst_case => "lloyd2006-worst-case",
    bare_lloyd2006_fig4 => "lloyd2006-fig4",
    bare_martin_tan_fig3 => "martin-tan-fig3",
    bare_barroso_fig5 => "barroso-fig5",
    bare_lloyd2006_fig11 => "lloyd2006-fig11",
    bare_lloyd2005_fig8 => "lloyd2005-fig8",
}
