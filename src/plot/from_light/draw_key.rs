//! The key under the diagrams seen from the light ([`super`]): "Maps, nearest first:" with each
//! map's stroke and number, the frustum's and the split planes' (moved out of draw.rs, which
//! stays under 800 lines).

use super::super::super::canvas::Fine;
use super::super::super::chart::{dash_pattern, FONT};
use super::super::super::Fail;
use super::maps::{fine_stroke, side_dashes};
use super::{map_stroke, FRUSTUM_WIDTH, PLANE_WIDTH};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// A key item's stroke: colour, width, dash pattern (empty: solid).
type Stroke = (RGBColor, u32, &'static [f64]);

/// The key under the panels: "Maps, nearest first:" with each map's stroke and its
/// number, then the frustum's stroke and the split planes'. Its items flow in rows, centred;
/// returns the height it takes (drawing nothing when `draw` is false).
pub(super) fn key<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    maps: usize,
    fine: bool,
    size: u32,
    draw: bool,
) -> Result<u32, Fail> {
    let style = TextStyle::from((FONT, size).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let width = |t: &str| -> Result<f64, Fail> {
        let (w, _) = area
            .estimate_text_size(t, &style)
            .map_err(|e| Fail::Draw(e.to_string()))?;
        Ok(f64::from(w))
    };
    let sample = 2.0 * f64::from(size);
    let (gap, space) = (0.3 * f64::from(size), f64::from(size));
    let mut items: Vec<(Option<Stroke>, String)> = vec![(None, "Maps, nearest first:".into())];
    for i in 0..maps {
        let stroke = if fine { fine_stroke(i) } else { map_stroke(i) };
        items.push((Some(stroke), format!("{}", i + 1)));
    }
    items.push((Some((BLACK, FRUSTUM_WIDTH, &[])), "frustum".into()));
    items.push((Some((BLACK, PLANE_WIDTH, &[])), "split plane".into()));
    let (w, _) = area.dim_in_pixel();
    let avail = f64::from(w) - 8.0;
    let mut rows: Vec<Vec<(f64, usize)>> = vec![Vec::new()];
    let mut x = 0.0;
    for (i, (stroke, text)) in items.iter().enumerate() {
        let wi = if stroke.is_some() { sample + gap } else { 0.0 } + width(text)?;
        if x > 0.0 && x + wi > avail {
            rows.push(Vec::new());
            x = 0.0;
        }
        rows.last_mut().expect("one row").push((x, i));
        x += wi + space;
    }
    let row_h = f64::from(size) + 6.0;
    let height = (row_h * rows.len() as f64 + 6.0).ceil() as u32;
    if !draw {
        return Ok(height);
    }
    for (r, row) in rows.iter().enumerate() {
        let &(last_x, last) = row.last().expect("a row has an item");
        let (stroke, text) = &items[last];
        let row_w = last_x + if stroke.is_some() { sample + gap } else { 0.0 } + width(text)?;
        let x0 = 0.5 * (f64::from(w) - row_w);
        let y = 3.0 + row_h * (r as f64 + 0.5);
        for &(x, i) in row {
            let (stroke, text) = &items[i];
            let mut tx = x0 + x;
            if let Some((colour, width, pattern)) = stroke {
                let line = [(tx, y), (tx + sample, y)];
                let pieces = if pattern.is_empty() {
                    vec![line.to_vec()]
                } else if fine {
                    // A fine map's sample as its outline's sides: whole periods, ending on a
                    // dash.
                    side_dashes(sample, pattern, 1.0)
                        .into_iter()
                        .map(|(a, b)| vec![(tx + a, y), (tx + b, y)])
                        .collect()
                } else {
                    dash_pattern(&line, pattern, 1.0)
                };
                let (bx, by) = area.get_base_pixel();
                for piece in pieces {
                    if fine {
                        // At a tenth of a unit, as in the panels: dashes of 1.2 units rounded
                        // to whole ones were 1 or 2 long.
                        area.draw(&Fine {
                            points: piece
                                .iter()
                                .map(|p| (p.0 + f64::from(bx), p.1 + f64::from(by)))
                                .collect(),
                            colour: colour.to_backend_color(),
                            stroke: Some(*width),
                        })?;
                        continue;
                    }
                    let pts: Vec<(i32, i32)> = piece
                        .iter()
                        .map(|p| (p.0.round() as i32, p.1.round() as i32))
                        .collect();
                    area.draw(&PathElement::new(pts, colour.stroke_width(*width)))?;
                }
                tx += sample + gap;
            }
            area.draw(&Text::new(
                text.clone(),
                (tx.round() as i32, y.round() as i32),
                style.clone(),
            ))?;
        }
    }
    Ok(height)
}
