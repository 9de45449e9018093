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
