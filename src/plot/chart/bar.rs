//! Colour bars: a scale's bands as one raster, an outline, and the range's ends labelled.

use super::super::Fail;
use super::axis::{Axis, Chart2d, Ticked};
use super::heat::ColourScale;
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
/// axis's own ticks (decades on a log scale) that keep clear of the ends (at least 7 % of the
/// bar from either).
pub(crate) fn colour_bar_ticks(axis: &Axis) -> Vec<(f64, String)> {
    let (lo, hi) = axis.range();
    let clear = 0.07 * (hi - lo).abs();
    let end = |a: f64| {
        let v = three_digits(axis.to_data(a));
        (a, axis.tick_label(axis.to_axis(v).unwrap_or(a)))
    };
    let mut ticks = vec![end(lo)];
    ticks.extend(
        axis.ticks()
            .0
            .into_iter()
            .filter(|&t| (t - lo).abs() >= clear && (t - hi).abs() >= clear)
            .map(|t| (t, axis.tick_label(t))),
    );
    ticks.push(end(hi));
    ticks
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
    let ticks = colour_bar_ticks(&scale.axis);
    let yb: Vec<f64> = ticks.iter().map(|t| t.0).collect();
    let mut chart = ChartBuilder::on(area)
        .margin_top(30)
        .margin_bottom(30)
        .margin_right(6)
        .y_label_area_size(0)
        .right_y_label_area_size(62)
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
    /// "865" and "4.74×10⁶" (three significant digits) level with its bottom and top edges, and
    /// the decades between them that keep clear of the ends (10³ lies 0.06 decades from 865:
    /// left out; 10⁴, 10⁵, 10⁶ labelled).
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
        let lo = label_y("865").expect("a label at the bottom");
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
