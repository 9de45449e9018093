//! Text placed at a data position of a chart on a white box, so that it stays readable over
//! lines and fills (annotations, dimension labels).

use super::super::canvas::anchor_offset;
use super::super::Fail;
use super::axis::Chart2d;
use super::FONT;
use plotters::prelude::*;
use plotters::style::text_anchor::Pos;

/// The white margin around a boxed label's text, in pixels.
pub(crate) const LABEL_PAD: i32 = 2;

/// Writes `text` at the data point `at` of `chart`, anchored by `pos`, in `colour` at `size`
/// pixels, over a white box a little larger than the text (80 % opaque, so that a line under it
/// still shows faintly).
pub(crate) fn boxed_text<DB: DrawingBackend>(
    chart: &mut Chart2d<'_, DB>,
    at: (f64, f64),
    text: &str,
    pos: Pos,
    size: u32,
    colour: RGBColor,
) -> Result<(), Fail> {
    let style = TextStyle::from((FONT, size).into_font())
        .color(&colour)
        .pos(pos);
    let (w, h) = chart
        .plotting_area()
        .estimate_text_size(text, &style)
        .map_err(|e| Fail::Draw(e.to_string()))?;
    let (dx, dy) = anchor_offset(pos, f64::from(w), f64::from(h));
    let (x0, y0, w, h) = (dx.round() as i32, dy.round() as i32, w as i32, h as i32);
    let p = LABEL_PAD;
    chart.draw_series(std::iter::once(
        EmptyElement::at(at)
            + Rectangle::new(
                [(x0 - p, y0 - p), (x0 + w + p, y0 + h + p)],
                WHITE.mix(0.8).filled(),
            )
            + Text::new(text.to_string(), (0, 0), style.clone()),
    ))?;
    Ok(())
}
