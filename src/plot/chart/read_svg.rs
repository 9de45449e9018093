//! Test support: figures and panels drawn into a plain SVG, read back (text, attributes).

use super::super::svg::Svg;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The SVG of what `draw` draws on a page of `size` units.
pub(crate) fn draw_svg(
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<Svg<'_>, Shift>),
) -> String {
    super::super::ensure_font().unwrap();
    let mut svg = String::new();
    {
        let area = Svg::new(&mut svg, size, 1).into_drawing_area();
        draw(&area);
        area.present().unwrap();
    }
    svg
}

/// The number in the attribute `name="v"` of an element's line.
pub(crate) fn attr(el: &str, name: &str) -> Option<f64> {
    let at = el.find(&format!(" {name}=\""))? + name.len() + 3;
    el[at..at + el[at..].find('"')?].parse().ok()
}

/// The corners in the attribute `points="x,y x,y …"` of a `<polygon>` or `<polyline>` line.
pub(crate) fn points(el: &str) -> Option<Vec<(f64, f64)>> {
    let at = el.find(" points=\"")? + 9;
    Some(
        el[at..at + el[at..].find('"')?]
            .split_whitespace()
            .filter_map(|p| {
                let (x, y) = p.split_once(',')?;
                Some((x.parse().ok()?, y.parse().ok()?))
            })
            .collect(),
    )
}

/// The visible text of an SVG `<text>` line, tags removed and superscript digits written
/// as digits (a backend may set them as `<tspan>`s).
pub(crate) fn visible(line: &str) -> String {
    let Some(body) = line.find('>').map(|i| &line[i + 1..]) else {
        return String::new();
    };
    let body = body.strip_suffix("</text>").unwrap_or(body);
    let mut out = String::new();
    let mut tag = false;
    for c in body.chars() {
        match c {
            '<' => tag = true,
            '>' => tag = false,
            _ if tag => {}
            _ => out.push(match "⁰¹²³⁴⁵⁶⁷⁸⁹".chars().position(|d| d == c) {
                Some(d) => char::from(b'0' + d as u8),
                None => c,
            }),
        }
    }
    out
}

/// Every `<text>` line of an SVG with its visible text and its y.
pub(crate) fn texts(svg: &str) -> Vec<(&str, String, f64)> {
    svg.lines()
        .filter(|l| l.starts_with("<text"))
        .filter_map(|l| Some((l, visible(l), attr(l, "y")?)))
        .collect()
}

fn unbase64(s: &str) -> Vec<u8> {
    let val = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        _ => 63,
    };
    let digits: Vec<u8> = s.bytes().filter(|&c| c != b'=').map(val).collect();
    let mut out = Vec::new();
    for ch in digits.chunks(4) {
        let n = ch
            .iter()
            .enumerate()
            .fold(0u32, |a, (i, &d)| a | u32::from(d) << (18 - 6 * i));
        out.extend(&n.to_be_bytes()[1..ch.len()]);
    }
    out
}

/// An embedded PNG `<image>` of an SVG, decoded.
pub(crate) struct Image {
    /// Its top-left corner, in view-box units.
    pub at: (f64, f64),
    /// Its pixels per view-box unit (across).
    pub density: f64,
    pub rgba: image::RgbaImage,
    /// The PNG's colour type (2 RGB, 6 RGBA).
    pub colour_type: u8,
}

/// Every embedded PNG image of an SVG.
pub(crate) fn embedded_images(svg: &str) -> Vec<Image> {
    svg.lines()
        .filter(|l| l.starts_with("<image"))
        .map(|el| {
            let at = el.find("base64,").unwrap() + 7;
            let png = unbase64(&el[at..at + el[at..].find('"').unwrap()]);
            let rgba = image::load_from_memory(&png).unwrap().to_rgba8();
            Image {
                at: (attr(el, "x").unwrap(), attr(el, "y").unwrap()),
                density: f64::from(rgba.width()) / attr(el, "width").unwrap(),
                rgba,
                colour_type: png[25],
            }
        })
        .collect()
}
