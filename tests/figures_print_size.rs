//! A figure prints at one size whatever its format: the PNG's pixel size over the density of its
//! `pHYs` chunk, the SVG's `width` and `height` (in points, 72 to the inch) and the PDF's page
//! (in points) give the same inches, with the default density, captioned and bare, at every
//! `scale`. (At the former default of 96 pixels per inch a 520-unit figure's 1040-pixel PNG
//! claimed 10.8 inches against the SVG's and PDF's 7.2.)
#![cfg(feature = "plot")]

use shadow_aliasing::plot::{render_with, Column, Format, Options};
use std::path::{Path, PathBuf};

fn out_dir(sub: &str) -> PathBuf {
    let d = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{sub}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// The PNG's width and height in inches: its IHDR's pixels over its `pHYs` density (pixels per
/// metre, unit byte 1), read from the chunks here.
fn png_inches(png: &[u8]) -> (f64, f64) {
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let be = |b: &[u8]| u32::from_be_bytes(b.try_into().unwrap());
    let (w, h) = (be(&png[16..20]), be(&png[20..24]));
    let mut at = 8;
    while at + 12 <= png.len() {
        let len = be(&png[at..at + 4]) as usize;
        if &png[at + 4..at + 8] == b"pHYs" {
            let d = &png[at + 8..at + 8 + len];
            assert_eq!(d[8], 1, "pHYs unit is not the metre");
            let (px, py) = (f64::from(be(&d[0..4])), f64::from(be(&d[4..8])));
            return (f64::from(w) / px / 0.0254, f64::from(h) / py / 0.0254);
        }
        at += 12 + len;
    }
    panic!("no pHYs chunk");
}

/// The SVG's `width` and `height` in inches (written in points).
/// The width of the view box of the SVG file at `path`, in layout units.
fn svg_view_width(path: &std::path::Path) -> f64 {
    let svg = std::fs::read_to_string(path).unwrap();
    let at = svg.find("viewBox=\"").unwrap() + "viewBox=\"".len();
    let v: Vec<f64> = svg[at..at + svg[at..].find('"').unwrap()]
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    v[2]
}

fn svg_inches(svg: &str) -> (f64, f64) {
    let head = &svg[..svg.find('>').unwrap()];
    let get = |name: &str| -> f64 {
        let key = format!(" {name}=\"");
        let at = head.find(&key).unwrap() + key.len();
        let v = &head[at..at + head[at..].find('"').unwrap()];
        let pt: f64 = v
            .strip_suffix("pt")
            .unwrap_or_else(|| panic!("{name}={v:?} is not in points"))
            .parse()
            .unwrap();
        pt / 72.0
    };
    (get("width"), get("height"))
}

/// The PDF's page in inches (its `/MediaBox` in points).
#[cfg(feature = "pdf")]
fn pdf_inches(pdf: &[u8]) -> (f64, f64) {
    let text = String::from_utf8_lossy(pdf);
    let at = text.find("/MediaBox [").expect("a MediaBox") + "/MediaBox [".len();
    let v: Vec<f64> = text[at..at + text[at..].find(']').unwrap()]
        .split_whitespace()
        .map(|v| v.parse().unwrap())
        .collect();
    ((v[2] - v[0]) / 72.0, (v[3] - v[1]) / 72.0)
}

fn close(a: (f64, f64), b: (f64, f64)) -> bool {
    // The density is written in whole pixels per metre: 17 008 for 432 per inch, 8e-6 off.
    (a.0 / b.0 - 1.0).abs() < 1e-3 && (a.1 / b.1 - 1.0).abs() < 1e-3
}

#[test]
fn png_svg_and_pdf_print_at_one_size() {
    let dir = out_dir("figures-print-size");
    let name = "lloyd2005-fig4";
    for bare in [false, true] {
        for scale in [1, 3] {
            let opts = Options {
                bare,
                scale,
                ..Options::default()
            };
            let d = dir.join(format!("{bare}-{scale}"));
            render_with(name, &d, Format::Both, &opts).unwrap();
            let png_bytes = std::fs::read(d.join(format!("{name}.png"))).unwrap();
            let png = png_inches(&png_bytes);
            let svg = svg_inches(&std::fs::read_to_string(d.join(format!("{name}.svg"))).unwrap());
            assert!(
                close(png, svg),
                "bare {bare}, scale {scale}: PNG {png:?} in, SVG {svg:?} in"
            );
            // At least 300 pixels per inch of the printed figure (journals' halftone minimum;
            // the default was 144): the PNG's pixel width over the SVG's inches.
            let px = u32::from_be_bytes(png_bytes[16..20].try_into().unwrap());
            assert!(
                f64::from(px) / svg.0 >= 300.0,
                "bare {bare}, scale {scale}: {px} px over {} in",
                svg.0
            );
            // The figure is 520 units wide: 520 points, 7.22 inches, times the scale; a bare
            // one is cut to its ink at one point a unit.
            let units = if bare {
                svg_view_width(&d.join(format!("{name}.svg")))
            } else {
                520.0
            };
            assert!(!bare || units < 520.0, "bare: {units} units wide");
            assert!(
                (svg.0 - units / 72.0 * f64::from(scale)).abs() < 1e-9,
                "{svg:?}"
            );
            #[cfg(feature = "pdf")]
            {
                render_with(name, &d, Format::Pdf, &opts).unwrap();
                let pdf = pdf_inches(&std::fs::read(d.join(format!("{name}.pdf"))).unwrap());
                assert!(
                    close(pdf, svg),
                    "bare {bare}, scale {scale}: PDF {pdf:?} in, SVG {svg:?} in"
                );
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// One column (issue 35): the figure is laid out 300 units wide and printed 240 points
/// (3.33 inches) wide, the PNG's 600 pixels (scale 1) at its default density of
/// 2 × 72 / 0.8 = 180 per inch, captioned and bare; the PDF's page the same.
#[test]
fn single_column_prints_240_points_wide_in_every_format() {
    let dir = out_dir("figures-print-size-single");
    let name = "lloyd2006-fig5";
    for bare in [false, true] {
        let opts = Options {
            bare,
            column: Column::Single,
            ..Options::default()
        };
        let d = dir.join(format!("{bare}"));
        render_with(name, &d, Format::Both, &opts).unwrap();
        let png_bytes = std::fs::read(d.join(format!("{name}.png"))).unwrap();
        let png = png_inches(&png_bytes);
        let svg = svg_inches(&std::fs::read_to_string(d.join(format!("{name}.svg"))).unwrap());
        assert!(
            close(png, svg),
            "bare {bare}: PNG {png:?} in, SVG {svg:?} in"
        );
        // 300 units (a bare figure: its ink's width) at 0.8 pt each; 6 pixels a unit, 540 per
        // inch: 1800 pixels over 3.33 inches for the captioned figure.
        let units = if bare {
            svg_view_width(&d.join(format!("{name}.svg")))
        } else {
            300.0
        };
        assert!(!bare || units < 300.0, "bare: {units} units wide");
        assert!((svg.0 - units * 0.8 / 72.0).abs() < 1e-9, "{svg:?}");
        let px = u32::from_be_bytes(png_bytes[16..20].try_into().unwrap());
        assert_eq!(f64::from(px), units * 6.0);
        assert!(f64::from(px) / svg.0 >= 300.0, "{px} px over {svg:?} in");
        #[cfg(feature = "pdf")]
        {
            render_with(name, &d, Format::Pdf, &opts).unwrap();
            let pdf = pdf_inches(&std::fs::read(d.join(format!("{name}.pdf"))).unwrap());
            assert!(
                close(pdf, svg),
                "bare {bare}: PDF {pdf:?} in, SVG {svg:?} in"
            );
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
