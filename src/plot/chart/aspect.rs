//! Equal aspect for geometric diagrams: the axes widened (about their centres) so that one data
//! unit is as many pixels across as up, whatever the panel's shape.

use super::super::canvas::{Canvas, SVG_TEXT};
use super::super::svg::Svg;
use super::super::Fail;
use super::axis::{build_chart_styled, Axis, ChartStyle};
use plotters::coord::Shift;
use plotters::prelude::*;

/// The plotting area's size in pixels of a chart built on `area` with these arguments, measured
/// by building it on a throw-away SVG of the same size.
pub(crate) fn plot_size<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    x: &Axis,
    y: &Axis,
    style: &ChartStyle,
) -> Result<(f64, f64), Fail> {
    let mut scratch = String::new();
    let probe = Canvas::new(Svg::new(&mut scratch, area.dim_in_pixel(), 1), 1, SVG_TEXT)
        .into_drawing_area();
    let chart = build_chart_styled(&probe, title, x, y, false, style)?;
    let (w, h) = chart.plotting_area().dim_in_pixel();
    Ok((f64::from(w.max(1)), f64::from(h.max(1))))
}

/// `x` and `y` (linear) widened about their centres so that a chart built on `area` with them
/// shows one data unit as the same number of pixels in both directions; each range only grows.
pub(crate) fn equal_aspect<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    x: &Axis,
    y: &Axis,
    style: &ChartStyle,
) -> Result<(Axis, Axis), Fail> {
    let widen = |a: &Axis, span: f64| {
        let c = 0.5 * (a.min + a.max);
        // Never narrower than asked: (range / w) · w may round below the range.
        let half = 0.5 * span;
        Axis::linear(
            a.label.clone(),
            (c - half).min(a.min),
            (c + half).max(a.max),
        )
    };
    let (mut xa, mut ya) = (x.clone(), y.clone());
    // The tick labels' widths change with the ranges; two rounds settle them.
    for _ in 0..2 {
        let (w, h) = plot_size(area, title, &xa, &ya, style)?;
        let per_px = ((x.max - x.min) / w).max((y.max - y.min) / h);
        xa = widen(x, per_px * w);
        ya = widen(y, per_px * h);
    }
    Ok((xa, ya))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_unit_is_as_wide_as_high() {
        super::super::super::ensure_font().unwrap();
        // A wide panel and a tall one, with data of the opposite shape.
        for (size, x, y) in [
            ((900u32, 400u32), (0.0, 10.0), (-10.0, 10.0)),
            ((300, 800), (-50.0, 50.0), (0.0, 10.0)),
        ] {
            let mut s = String::new();
            let area = Svg::new(&mut s, size, 1).into_drawing_area();
            let (xa, ya) = equal_aspect(
                &area,
                "t",
                &Axis::linear("x", x.0, x.1),
                &Axis::linear("y", y.0, y.1),
                &ChartStyle::default(),
            )
            .unwrap();
            // Each range contains the asked one.
            assert!(xa.min <= x.0 && xa.max >= x.1 && ya.min <= y.0 && ya.max >= y.1);
            // Measured on a chart built with the result: pixels per unit in x and in y.
            let chart =
                build_chart_styled(&area, "t", &xa, &ya, false, &ChartStyle::default()).unwrap();
            let (x0, y0) = chart.backend_coord(&(xa.min, ya.min));
            let (x1, y1) = chart.backend_coord(&(xa.max, ya.max));
            let kx = f64::from(x1 - x0) / (xa.max - xa.min);
            let ky = f64::from(y0 - y1) / (ya.max - ya.min);
            assert!(
                (kx / ky - 1.0).abs() < 0.01,
                "{size:?}: {kx} px/unit across, {ky} up"
            );
        }
    }
}
