//! Colour bars: a scale's bands as one raster, an outline, and the range's ends labelled.

use super::super::Fail;
use super::axis::{Axis, Chart2d, Ticked};
use super::heat::ColourScale;
use super::page::column;
use super::raster::Raster;
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The length of a colour bar's tick marks, in pixels; its labels start twice that from the bar.
pub(crate) const COLOUR_BAR_TICK: i32 = 5;

/// Three significant digits.
fn three_digits(v: f64) -> f64 {
    if v == 0.0 || !v.is_finite() {
        return v;
    }
    let p = 10f64.powf(v.abs().log10().floor() - 2.0);
    (v / p).round() * p
}

/// The labelled ticks of a colour bar (axis space) with their labels: both ends of its range,
/// written to three significant digits, so that the range can be read off the bar, and the
/// axis's own ticks (decades on a log scale) between them, all in the axis's one format
/// ([`Axis::tick_label`]). A drawn bar leaves out those too near an end ([`clear_of_ends`]).
pub(crate) fn colour_bar_ticks(axis: &Axis) -> Vec<(f64, String)> {
    let (lo, hi) = axis.range();
    let eps = 1e-9 * (hi - lo).abs().max(1e-300);
    let end = |a: f64| {
        let v = three_digits(axis.to_data(a));
        (a, axis.tick_label(axis.to_axis(v).unwrap_or(a)))
    };
    let mut ticks = vec![end(lo)];
    ticks.extend(
        axis.ticks()
            .0
            .into_iter()
            .filter(|&t| (t - lo).abs() > eps && (t - hi).abs() > eps)
            .map(|t| (t, axis.tick_label(t))),
    );
    ticks.push(end(hi));
    ticks
}

/// The least space between a colour bar's end label and a tick label next to it, in points as
/// printed (the review found lloyd2006-fig7's "2430" 3 pt from "10³").
pub(crate) const BAR_END_GAP_PT: f64 = 8.0;

/// The height of a colour bar's tick label, in units: its size 13 is 10.5 units in the SVG,
/// from the top of a raised exponent to the descent about 1.1 of that.
const BAR_LABEL_H: f64 = 11.5;

/// `ticks` ([`colour_bar_ticks`]: the two ends first and last) without the inner ones whose
/// labels come within [`BAR_END_GAP_PT`] of an end's label on a bar `units_per_axis` units long
/// per unit of axis space (a decade on a log bar), printed `points_per_unit` points a unit.
pub(crate) fn clear_of_ends(
    ticks: Vec<(f64, String)>,
    units_per_axis: f64,
    points_per_unit: f64,
) -> Vec<(f64, String)> {
    let (Some(lo), Some(hi)) = (ticks.first().map(|t| t.0), ticks.last().map(|t| t.0)) else {
        return ticks;
    };
    let least = BAR_LABEL_H + BAR_END_GAP_PT / points_per_unit;
    let n = ticks.len();
    ticks
        .into_iter()
        .enumerate()
        .filter(|(i, t)| {
            *i == 0
                || *i == n - 1
                || ((t.0 - lo).abs() * units_per_axis >= least
                    && (t.0 - hi).abs() * units_per_axis >= least)
        })
        .map(|(_, t)| t)
        .collect()
}

/// Fills a colour bar with the bands of `scale` as one raster ([`Raster`]): abutting
/// rectangles at whole units left anti-aliased hairline seams between the bands (issue 25).
/// The chart spans the scale's axis along y (`vertical`) or x, and 0 to 1 across.
pub(crate) fn draw_bar_bands<DB: DrawingBackend>(
    chart: &Chart2d<'_, DB>,
    scale: &ColourScale,
    vertical: bool,
) -> Result<(), Fail> {
    let (lo, hi) = scale.axis.range();
    let base = chart.plotting_area().get_base_pixel();
    let unit = |p: (f64, f64)| {
        let (u, v) = chart.backend_coord(&p);
        (u - base.0, v - base.1)
    };
    let (a, b) = if vertical {
        (unit((0.0, lo)), unit((1.0, hi)))
    } else {
        (unit((lo, 0.0)), unit((hi, 1.0)))
    };
    let (from, to) = if vertical { (a.1, b.1) } else { (a.0, b.0) };
    if from == to {
        return Ok(());
    }
    let levels = scale.levels;
    let colour_at = |u: f64, v: f64| {
        let along = if vertical { v } else { u };
        let t = (along - f64::from(from)) / f64::from(to - from);
        let k = (t * levels as f64).floor().clamp(0.0, (levels - 1) as f64) as usize;
        Some(scale.level_colour(k))
    };
    let bbox = (a.0.min(b.0), a.1.min(b.1), a.0.max(b.0), a.1.max(b.1));
    Raster::sample(bbox, colour_at).draw(&chart.plotting_area().strip_coord_spec())
}

/// Draws a vertical colour bar for `scale` into `area`, its ends labelled
/// ([`colour_bar_ticks`]).
pub(crate) fn draw_colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    scale: &ColourScale,
) -> Result<(), Fail> {
    let (lo, hi) = scale.axis.range();
    // The bar runs between the chart's margins of 30 units at each end.
    let length = f64::from(area.dim_in_pixel().1.saturating_sub(60));
    let ticks = clear_of_ends(
        colour_bar_ticks(&scale.axis),
        length / (hi - lo).abs().max(1e-300),
        column().points_per_unit(),
    );
    let yb: Vec<f64> = ticks.iter().map(|t| t.0).collect();
    // The labels' side: tick, gap, the widest label and the name (14 units across, turned),
    // at least 62 units, leaving the bar at least 8.
    let label_style = TextStyle::from((FONT, 13).into_font());
    let mut widest = 0u32;
    for t in &ticks {
        widest = widest.max(area.estimate_text_size(&t.1, &label_style)?.0);
    }
    let side = (widest + 2 * COLOUR_BAR_TICK as u32 + 26)
        .max(62)
        .min(area.dim_in_pixel().0.saturating_sub(14));
    let mut chart = ChartBuilder::on(area)
        .margin_top(30)
        .margin_bottom(30)
        .margin_right(6)
        .y_label_area_size(0)
        .right_y_label_area_size(side)
        .build_cartesian_2d(
            Ticked::new(0.0, 1.0, vec![], vec![]),
            Ticked::new(lo, hi, yb.clone(), vec![]),
        )?;
    let yf = |v: &f64| {
        ticks
            .iter()
            .min_by(|a, b| (a.0 - v).abs().total_cmp(&(b.0 - v).abs()))
            .map_or_else(String::new, |t| t.1.clone())
    };
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_desc(scale.axis.label.as_str())
        .y_label_formatter(&yf)
        // Tick marks 5 px long outside the bar, the labels twice that from it (plotters' own
        // default put them about 3 px from the bar's edge).
        .set_tick_mark_size(LabelAreaPosition::Right, COLOUR_BAR_TICK)
        .axis_desc_style((FONT, 14))
        .label_style((FONT, 13))
        .draw()?;
    draw_bar_bands(&chart, scale, true)?;
    chart.draw_series(std::iter::once(Rectangle::new(
        [(0.0, lo), (1.0, hi)],
        RGBColor(60, 60, 60).stroke_width(1),
    )))?;
    // Unlabelled minor ticks (2 … 9 times each decade on a log bar), half as long.
    let (_, light) = scale.axis.ticks();
    chart.draw_series(
        light
            .into_iter()
            .filter(|t| yb.iter().all(|b| (b - t).abs() > 1e-9))
            .map(|t| {
                EmptyElement::at((1.0, t))
                    + PathElement::new(
                        vec![(0, 0), (COLOUR_BAR_TICK / 2 + 1, 0)],
                        RGBColor(60, 60, 60).stroke_width(1),
                    )
            }),
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::heat::SMOOTH_LEVELS;
    use super::super::read_svg::{attr, draw_svg, embedded_images, visible};
    use super::*;

    /// A colour bar is one embedded image, not abutting filled rectangles (whose anti-aliased
    /// edges left hairline seams, issue 25): its pixels run from the scale's lowest band at the
    /// bottom to its highest at the top (viridis ends), and no band's colour is left white.
    #[test]
    fn colour_bar_is_one_seamless_raster() {
        let scale = ColourScale::smooth(Axis::log10("S", 865.159, 4.7354e6));
        let svg = draw_svg((90, 500), |area| draw_colour_bar(area, &scale).unwrap());
        let filled = svg
            .lines()
            .filter(|l| l.starts_with("<rect") && !l.contains("fill=\"none\""))
            .count();
        assert_eq!(filled, 0, "{svg}");
        let images = embedded_images(&svg);
        assert_eq!(images.len(), 1);
        let img = &images[0].rgba;
        let (w, h) = img.dimensions();
        let at = |y: u32| {
            let p = img.get_pixel(w / 2, y).0;
            RGBColor(p[0], p[1], p[2])
        };
        assert_eq!(at(h - 1), scale.level_colour(0));
        assert_eq!(at(0), scale.level_colour(SMOOTH_LEVELS - 1));
        assert!(img
            .pixels()
            .all(|p| p.0[3] == 255 && p.0[..3] != [255, 255, 255]));
    }

    /// A colour bar's ends are labelled (issue 25: Fig 7's shared bar, 865 … 4.7·10⁶, had no
    /// tick at its top): the bar of Fig 7's range, read back from its SVG, has the labels
    /// "8.65×10²" and "4.74×10⁶" (three significant digits, in powers as the decades are) level
    /// with its bottom and top edges, and the decades between them that keep clear of the ends
    /// (the bar is 440 units over 3.74 decades, 118 a decade: 10³ lies 0.06 decades, 7 units,
    /// from 865: left out; 10⁴, 10⁵, 10⁶ labelled, 10⁶ 0.68 decades, 79 units, from the top).
    /// lloyd2006-fig7's ratio bar, 1 to 2430 (3.386 decades): on a bar 132 units long (39.0
    /// units a decade) 10³ lies log 2.43 = 0.386 decades, 15.0 units, from the end label
    /// "2.43×10³": under a label's height (11.5) and 8 pt (8 units in two columns, 10 in one),
    /// so it is left out, as the review asked (it was 3 pt from "2430"); 10¹ and 10², 39 and
    /// 78 units from the bottom, stay. On a bar 300 units long (88.6 a decade, 34.2 units)
    /// 10³ stays. The ends are never dropped.
    #[test]
    fn a_decade_next_to_an_end_label_is_left_out() {
        let axis = Axis::log10("(b) ÷ (c)", 1.0, 2430.0);
        let ticks = colour_bar_ticks(&axis);
        let labels = |t: &[(f64, String)]| t.iter().map(|t| t.1.clone()).collect::<Vec<_>>();
        assert_eq!(labels(&ticks), ["10⁰", "10¹", "10²", "10³", "2.43×10³"]);
        let per = |length: f64| length / 2430f64.log10();
        for ppu in [1.0, 0.8] {
            assert_eq!(
                labels(&clear_of_ends(ticks.clone(), per(132.0), ppu)),
                ["10⁰", "10¹", "10²", "2.43×10³"]
            );
            assert_eq!(
                labels(&clear_of_ends(ticks.clone(), per(300.0), ppu)),
                labels(&ticks)
            );
        }
        // 20 units from the end: clear in two columns (19.5 needed), not in one (21.5).
        let l = 20.0 / 2.43f64.log10();
        assert_eq!(clear_of_ends(ticks.clone(), l, 1.0).len(), 5);
        assert_eq!(clear_of_ends(ticks.clone(), l, 0.8).len(), 4);
    }

    #[test]
    fn colour_bar_labels_its_ends() {
        let scale = ColourScale::smooth(Axis::log10("S", 865.159, 4.7354e6));
        let svg = draw_svg((90, 500), |area| draw_colour_bar(area, &scale).unwrap());
        // The bar's outline: the one unfilled rectangle.
        let outline = svg
            .lines()
            .find(|l| l.starts_with("<rect") && l.contains("fill=\"none\""))
            .unwrap();
        let top = attr(outline, "y").unwrap();
        let bottom = top + attr(outline, "height").unwrap();
        let label_y = |text: &str| {
            svg.lines()
                .find(|l| {
                    l.starts_with("<text") && visible(l) == visible(&format!(">{text}</text>"))
                })
                .and_then(|l| attr(l, "y"))
        };
        let hi = label_y("4.74×10⁶").unwrap_or_else(|| panic!("no label at the top: {svg}"));
        let lo = label_y("8.65×10²").expect("a label at the bottom");
        assert!(
            (hi - top).abs() <= 1.0 && (lo - bottom).abs() <= 1.0,
            "{hi} {lo}"
        );
        for d in ["10⁴", "10⁵", "10⁶"] {
            assert!(label_y(d).is_some(), "{d}");
        }
        assert!(label_y("10³").is_none());
    }
}
