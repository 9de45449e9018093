//! Colour bars: a scale's bands as one raster, an outline, and the range's ends labelled.

use super::super::Fail;
use super::axis::{Axis, Chart2d, Ticked};
use super::heat::ColourScale;
use super::raster::Raster;
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The length of a colour bar's tick marks, in pixels; its labels start twice that from the bar.
pub(crate) const COLOUR_BAR_TICK: i32 = 5;

/// The whole decades round `[lo, hi]` (`0 < lo ≤ hi`): a colour bar over them ends at round
/// powers of ten, both labelled, and holds every value, none clipped (a bar over the data's own
/// range ended at computed values such as 9.07×10⁻¹, and one at a round tick short of the
/// data's top hid the clipped values, the figure review's X3).
pub(crate) fn decades(lo: f64, hi: f64) -> (f64, f64) {
    let a = lo.log10().floor() as i32;
    let b = (hi.log10().ceil() as i32).max(a + 1);
    // Written and read back, each the double nearest its power of ten, whose log₁₀ is then
    // the whole number (10f64.powf(−2.0) is 0.010000000000000002, log₁₀ −1.9999999999999996).
    let power = |e: i32| format!("1e{e}").parse::<f64>().unwrap_or(f64::NAN);
    (power(a), power(b))
}

/// The labelled ticks of a colour bar (axis space) with their labels: the axis's own ticks
/// (its decades on a base-10 log scale, which end a bar over [`decades`]), in the axis's one
/// format ([`Axis::tick_label`]); never a computed end value.
pub(crate) fn colour_bar_ticks(axis: &Axis) -> Vec<(f64, String)> {
    axis.ticks()
        .0
        .into_iter()
        .map(|t| (t, axis.tick_label(t)))
        .collect()
}

/// The height of a colour bar's tick label, in units: its size 13 is 10.5 units in the SVG,
/// from the top of a raised exponent to the descent about 1.1 of that.
const BAR_LABEL_H: f64 = 11.5;

/// The size of a colour bar's name (plotters' size), written along the bar.
pub(crate) const BAR_NAME: u32 = 14;

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

/// Draws a vertical colour bar for `scale` into `area`: the bands, tick labels right of it
/// ([`colour_bar_ticks`]) and its name beyond them, turned anticlockwise as a y axis's name is
/// (reading from the bottom up: the figure review's X8).
pub(crate) fn draw_colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    scale: &ColourScale,
) -> Result<(), Fail> {
    let (lo, hi) = scale.axis.range();
    let all = colour_bar_ticks(&scale.axis);
    let yb: Vec<f64> = all.iter().map(|t| t.0).collect();
    // Every tick labelled where neighbouring labels keep 6 units apart along the bar, else
    // every second (those of the top end's parity; the others keep their marks).
    let (_, h) = area.dim_in_pixel();
    let per = f64::from(h.saturating_sub(60)) / (hi - lo).abs().max(1e-300);
    let crowded = all.len() > 1 && (all[1].0 - all[0].0).abs() * per < BAR_LABEL_H + 6.0;
    let n = all.len();
    let ticks: Vec<(f64, String)> = all
        .into_iter()
        .enumerate()
        .filter(|(i, _)| !crowded || (n - 1 - i).is_multiple_of(2))
        .map(|(_, t)| t)
        .collect();
    // The labels' side: tick, gap, the widest label, 6 units and the name (14 across,
    // turned), at least 62 units, leaving the bar at least 8.
    let label_style = TextStyle::from((FONT, 13).into_font());
    let mut widest = 0u32;
    for t in &ticks {
        widest = widest.max(area.estimate_text_size(&t.1, &label_style)?.0);
    }
    let (w, _) = area.dim_in_pixel();
    let side = (widest + 2 * COLOUR_BAR_TICK as u32 + 26)
        .max(62)
        .min(w.saturating_sub(14));
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
    let yf = |v: &f64| tick_text(&ticks, *v);
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_label_formatter(&yf)
        // Tick marks 5 px long outside the bar, the labels twice that from it (plotters' own
        // default put them about 3 px from the bar's edge).
        .set_tick_mark_size(LabelAreaPosition::Right, COLOUR_BAR_TICK)
        .label_style((FONT, 13))
        .draw()?;
    draw_bar_bands(&chart, scale, true)?;
    chart.draw_series(std::iter::once(Rectangle::new(
        [(0.0, lo), (1.0, hi)],
        RGBColor(60, 60, 60).stroke_width(1),
    )))?;
    // The name: its middle 6 + 7 units in from the area's right edge, level with the bar's.
    let base = area.get_base_pixel();
    let (_, top) = chart.backend_coord(&(0.0, hi));
    let (_, bottom) = chart.backend_coord(&(0.0, lo));
    let mid = (top + bottom) / 2 - base.1;
    area.draw(&Text::new(
        scale.axis.label.clone(),
        (w as i32 - 6 - BAR_NAME as i32 / 2, mid.clamp(0, h as i32)),
        TextStyle::from((FONT, BAR_NAME).into_font())
            .transform(FontTransform::Rotate270)
            .pos(Pos::new(HPos::Center, VPos::Center)),
    ))?;
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

/// The label of the tick at `v` among `ticks` (value, text), empty where `v` has none (a tick
/// drawn without a label).
fn tick_text(ticks: &[(f64, String)], v: f64) -> String {
    ticks
        .iter()
        .find(|t| (t.0 - v).abs() < 1e-9)
        .map_or_else(String::new, |t| t.1.clone())
}

/// Draws a colour bar for `scale` across `area`: the bands, tick marks at the axis's ticks,
/// labels under them, and the name under the labels. Where the labels of neighbouring ticks
/// would come within 8 units of each other, every second is labelled (those of the top end's
/// parity), the others keep their marks.
pub(crate) fn draw_colour_bar_across<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    scale: &ColourScale,
) -> Result<(), Fail> {
    let (lo, hi) = scale.axis.range();
    let ticks = colour_bar_ticks(&scale.axis);
    let label_style = TextStyle::from((FONT, 13).into_font());
    let mut widest = 0u32;
    for t in &ticks {
        widest = widest.max(area.estimate_text_size(&t.1, &label_style)?.0);
    }
    let (w, h) = area.dim_in_pixel();
    let end = widest / 2 + 1;
    let length = f64::from(w.saturating_sub(2 * end));
    let apart = |k: usize| {
        ticks.len() < 2
            || (ticks[1].0 - ticks[0].0).abs() * k as f64 * length / (hi - lo).abs().max(1e-300)
                >= f64::from(widest) + 8.0
    };
    let stride = if apart(1) { 1 } else { 2 };
    let n = ticks.len();
    let shown: Vec<(f64, String)> = ticks
        .iter()
        .enumerate()
        .filter(|(i, _)| (n - 1 - i).is_multiple_of(stride))
        .map(|(_, t)| t.clone())
        .collect();
    let xb: Vec<f64> = ticks.iter().map(|t| t.0).collect();
    let mut chart = ChartBuilder::on(area)
        .margin_left(end)
        .margin_right(end)
        .x_label_area_size(h.saturating_sub(14).min(40))
        .y_label_area_size(0)
        .build_cartesian_2d(
            Ticked::new(lo, hi, xb, vec![]),
            Ticked::new(0.0, 1.0, vec![], vec![]),
        )?;
    let xf = |v: &f64| tick_text(&shown, *v);
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_y_axis()
        .x_desc(scale.axis.label.as_str())
        .x_label_formatter(&xf)
        .set_tick_mark_size(LabelAreaPosition::Bottom, COLOUR_BAR_TICK)
        .axis_desc_style((FONT, 13))
        .label_style((FONT, 13))
        .draw()?;
    draw_bar_bands(&chart, scale, false)?;
    chart.draw_series(std::iter::once(Rectangle::new(
        [(lo, 0.0), (hi, 1.0)],
        RGBColor(60, 60, 60).stroke_width(1),
    )))?;
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

    /// A colour bar over [`decades`] is ticked at its decades only, its ends included, and
    /// its name reads from the bottom up (X3, X8): lloyd2006-fig7's S̄, 865.159 to 4.7354×10⁶,
    /// gets the bar 10² … 10⁷ (log₁₀ 865 = 2.94, log₁₀ 4.74×10⁶ = 6.68, by hand), its labels
    /// 10², 10³, …, 10⁷, the lowest level with the bar's bottom edge and the highest with its
    /// top; no label is a computed value such as 8.65×10²; the name is turned 270° (plotters'
    /// clockwise turn, which is a quarter turn anticlockwise), as a left y axis's name is.
    #[test]
    fn colour_bar_ticks_round_decades_and_reads_upwards() {
        let (lo, hi) = decades(865.159, 4.7354e6);
        assert!(
            (lo - 100.0).abs() < 1e-9 && (hi - 1e7).abs() < 1e-3,
            "{lo} {hi}"
        );
        assert_eq!(decades(0.907, 2430.0), (0.1, 10_000.0));
        assert_eq!(decades(0.03, 171.0), (0.01, 1000.0));
        assert_eq!(0.01f64.log10(), -2.0);
        assert_eq!(decades(5.0, 5.0), (1.0, 10.0));
        let scale = ColourScale::smooth(Axis::log10("S", lo, hi));
        let svg = draw_svg((90, 500), |area| draw_colour_bar(area, &scale).unwrap());
        let outline = svg
            .lines()
            .find(|l| l.starts_with("<rect") && l.contains("fill=\"none\""))
            .unwrap();
        let top = attr(outline, "y").unwrap();
        let bottom = top + attr(outline, "height").unwrap();
        let labels: Vec<(String, f64, &str)> = svg
            .lines()
            .filter(|l| l.starts_with("<text"))
            .map(|l| (visible(l), attr(l, "y").unwrap(), l))
            .collect();
        let want: Vec<String> = (2..=7)
            .map(|e| visible(&format!(">10{}</text>", super::super::superscript(e))))
            .collect();
        let ticks: Vec<&(String, f64, &str)> = labels.iter().filter(|t| t.0 != "S").collect();
        assert_eq!(
            ticks.iter().map(|t| t.0.clone()).collect::<Vec<_>>(),
            want,
            "{svg}"
        );
        let y = |k: usize| ticks[k].1;
        assert!((y(5) - top).abs() <= 1.0 && (y(0) - bottom).abs() <= 1.0);
        let name = labels.iter().find(|t| t.0 == "S").unwrap();
        assert!(name.2.contains("rotate(270"), "{}", name.2);
    }
}
