//! `--bare` (`Options::bare`) crops: a bare figure is the captioned figure laid out the same, its
//! title and caption left out, and its page cut to the plot area between them: the PNG's rows,
//! the SVG's view box and the PDF's page.
//!
//! For every figure, the captioned and the bare SVG and PNG (and, with the feature `pdf`, the
//! bare PDF) are rendered, and:
//! - the captioned figure's plot area is the band between the bottom of its title (the text at
//!   the top, drawn at the title's size) and the top of its caption (the grey paragraph at the
//!   bottom);
//! - the bare SVG holds exactly the captioned SVG's elements less the title's and the caption's,
//!   unmoved (the same layout, not stretched);
//! - its view box is the page's full width and a band of rows inside that plot area, and every
//!   element's extent lies inside the view box (nothing is cut);
//! - the bare PNG is the captioned PNG's rows of that band, pixel for pixel, and the bare PDF's
//!   page is the view box's size.
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

    // Its view box: the page's width, a band inside the plot area holding every element.
    let (vb, w, h) = view_box(&bare_svg);
    let (top, bottom) = (vb[1], vb[1] + vb[3]);
    assert_eq!((vb[0], vb[2]), (0.0, page_w), "{name}: {vb:?}");
    assert_eq!((w, h), (vb[2], vb[3]), "{name}: size and view box differ");
    assert!(
        top >= title_bottom && bottom <= caption_top,
        "{name}: the bare view box {top}..{bottom} is not inside the plot area \
         {title_bottom}..{caption_top}"
    );
    let page_background = |e: &str| {
        e.starts_with("rect")
            && attr(e, "y") == Some(0.0)
            && attr(e, "height") == Some(page_h)
            && attr(e, "width") == Some(page_w)
    };
    for e in plot.iter().filter(|e| !page_background(e)) {
        if let Some((a, b)) = extent(e) {
            assert!(
                a >= top - 1e-9 && b <= bottom + 1e-9,
                "{name}: {a}..{b} is cut by the view box {top}..{bottom}: <{e}"
            );
        }
    }
    text_margin_below(name, &bare_svg);

    // The PNG: the captioned PNG's rows of the band, pixel for pixel.
    let cap_png = image::load_from_memory(&read(&cap_dir, "png"))
        .unwrap()
        .to_rgb8();
    let bare_png = image::load_from_memory(&read(&bare_dir, "png"))
        .unwrap()
        .to_rgb8();
    let z = PNG_ZOOM;
    assert_eq!(
        bare_png.dimensions(),
        (cap_png.width(), vb[3] as u32 * z),
        "{name}: PNG size"
    );
    let row = 3 * cap_png.width() as usize;
    let y0 = vb[1] as usize * z as usize;
    let band = &cap_png.as_raw()[y0 * row..y0 * row + bare_png.as_raw().len()];
    if let Some(at) = (0..bare_png.as_raw().len()).find(|&i| bare_png.as_raw()[i] != band[i]) {
        let (x, y) = ((at % row) / 3, at / row);
        panic!(
            "{name}: PNG pixel ({x}, {y}) differs from the captioned figure's ({x}, {})",
            y + y0
        );
    }

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

/// The least white under the lowest text of a bare SVG, in units: its glyphs' bottom (DejaVu's
/// descent) to the view box's bottom. The sixth figure review found 0.3 units under a colour
/// bar's name (lloyd2006-fig7 in one column, martin-tan-fig6 in two): a crop on the descender.
const BARE_TEXT_MARGIN: f64 = 1.5;

fn text_margin_below(name: &str, bare_svg: &str) {
    let (vb, _, _) = view_box(bare_svg);
    let bottom = vb[1] + vb[3];
    let lowest = elements(bare_svg)
        .into_iter()
        .filter(|e| e.starts_with("text"))
        .filter_map(extent)
        .map(|(_, b)| b)
        .fold(f64::NEG_INFINITY, f64::max);
    assert!(
        bottom - lowest >= BARE_TEXT_MARGIN,
        "{name}: {:.2} units of white under the lowest text (at {lowest:.2}, the crop at {bottom})",
        bottom - lowest
    );
}

/// The one-column bare figures keep white under their lowest text too (SVG only: the checks of
/// `check` above are the two-column figures').
#[test]
fn one_column_bare_figures_keep_white_under_their_text() {
    let opts = Options {
        bare: true,
        column: shadow_aliasing::plot::Column::Single,
        ..Options::default()
    };
    let dir = out_dir("figures-bare-single");
    for name in FIGURES {
        render_with(name, &dir, Format::Svg, &opts).unwrap();
        let svg = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
        text_margin_below(name, &svg);
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
