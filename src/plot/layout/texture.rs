//! lloyd2005-fig8 (c): the texture laid out by Eq 6, each part's rectangle in its look and
//! tagged.

use super::{Fig8, SIZE, TAG};
use crate::plot::chart::{
    boxed_text, build_chart_styled, column, equal_aspect, plot_size, Axis, Chart2d, ChartStyle,
    FONT, TICK,
};
use crate::plot::{Column, Fail};
use glam::DVec2;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

impl Fig8 {
    /// The s axis' last tick (the texture's end, `n`) and its label, right-aligned to the
    /// frame's end, at the other tick labels' height (the tick's length and 5 units under the
    /// axis, as the chart draws them).
    fn last_s_label<DB: DrawingBackend>(
        body: &DrawingArea<DB, Shift>,
        chart: &Chart2d<'_, DB>,
        n: f64,
        style: &ChartStyle,
    ) -> Result<(), Fail> {
        let (bx, by) = body.get_base_pixel();
        // The x axis is the plot's bottom edge (under t = 0: the equal aspect pads the range).
        let (x, _) = chart.backend_coord(&(n, 0.0));
        let (_, yr) = chart.plotting_area().get_pixel_range();
        let (x, y) = (x - bx, yr.end - by);
        let tick = TICK as i32;
        body.draw(&PathElement::new(
            vec![(x, y), (x, y + tick)],
            BLACK.stroke_width(1),
        ))?;
        body.draw(&Text::new(
            format!("{}", n as u32),
            (x, y + tick + 5),
            TextStyle::from((FONT, style.tick_size).into_font())
                .pos(Pos::new(HPos::Right, VPos::Top)),
        ))?;
        Ok(())
    }

    /// (c): the texture, square, each partition's rectangle in its look with its tag.
    pub(super) fn draw_texture<DB: DrawingBackend>(
        &self,
        body: &DrawingArea<DB, Shift>,
        style: &ChartStyle,
    ) -> Result<(), Fail> {
        let n = f64::from(SIZE);
        let title = "(c) texture by Eq 6";
        // One column's tags of parts too low to hold them stand left of the texture
        // ([`Fig8::tags_left`]): its s axis starts 0.35 of the texture before 0.
        let s0 = if column() == Column::Single {
            -0.35 * n
        } else {
            0.0
        };
        let (x, y) = (
            Axis::linear("s (texels)", s0, n),
            Axis::linear("t (texels)", 0.0, n),
        );
        // A panel wider than the texture at its height is narrowed, centred, so that equal
        // aspect widens no range (one column's s ran from −5000 to 2048).
        let (w, h) = plot_size(body, title, &x, &y, style)?;
        let spare = (w - h * (n - s0) / n).max(0.0) as u32;
        let (bw, bh) = body.dim_in_pixel();
        let body = &body
            .clone()
            .shrink((spare / 2, 0), (bw - spare.min(bw / 2), bh));
        // Equal aspect: the square texture drawn square.
        let (xa, ya) = equal_aspect(body, title, &x, &y, style)?;
        // Labelled at the texture's ends and middle only: four-digit labels every 500 texels
        // run together on a narrow panel. The s axis' last label, 2048, is written right-aligned
        // to the frame's end below ([`Fig8::last_s_label`]): centred on it, it came within 3.5
        // units of "1024" in one column and ran past the page across two (the sixth review,
        // R6-lloyd2005-fig8-3).
        // In one column, whose plot is about 60 units wide, s is labelled at its ends only.
        let ends = [0.0, 0.5 * n, n];
        let s_at = if column() == Column::Single {
            &ends[..1]
        } else {
            &ends[..2]
        };
        let (xa, ya) = (xa.labelled_at(s_at), ya.labelled_at(&ends));
        let mut chart = build_chart_styled(body, title, &xa, &ya, false, style)?;
        Self::last_s_label(body, &chart, n, style)?;
        let (pw, _) = chart.plotting_area().dim_in_pixel();
        let per_px = (xa.max - xa.min) / f64::from(pw);
        for (i, c) in self.cells.iter().enumerate() {
            let v = c.viewport;
            let (x0, y0) = (f64::from(v.x), f64::from(v.y));
            let (x1, y1) = (x0 + f64::from(v.width), y0 + f64::from(v.height));
            let rect = [
                DVec2::new(x0, y0),
                DVec2::new(x1, y0),
                DVec2::new(x1, y1),
                DVec2::new(x0, y1),
            ];
            self.fill_hatched(&mut chart, &rect, i, per_px)?;
            chart.draw_series(std::iter::once(Rectangle::new(
                [(x0, y0), (x1, y1)],
                BLACK.stroke_width(1),
            )))?;
        }
        // Tags inside their rectangles where they fit (with a box's margin); the others left
        // of the texture at their parts' heights, spread apart, each joined to its part by a
        // leader (one column's L1 and L2 straddled their boundary: the sixth review,
        // R6-lloyd2005-fig8-3).
        let tag_style =
            TextStyle::from((FONT, TAG).into_font()).pos(Pos::new(HPos::Right, VPos::Center));
        let mut outside: Vec<(f64, f64, &str)> = Vec::new();
        for c in &self.cells {
            let v = c.viewport;
            let at = (
                f64::from(v.x) + 0.5 * f64::from(v.width),
                f64::from(v.y) + 0.5 * f64::from(v.height),
            );
            let (tw, th) = body
                .estimate_text_size(&c.tag, &tag_style)
                .map_err(|e| Fail::Draw(e.to_string()))?;
            let fits = f64::from(tw) + 2.0 <= f64::from(v.width) / per_px
                && f64::from(th) + 2.0 <= f64::from(v.height) / per_px;
            if fits {
                boxed_text(
                    &mut chart,
                    at,
                    &c.tag,
                    Pos::new(HPos::Center, VPos::Center),
                    TAG,
                    BLACK,
                )?;
            } else {
                outside.push((at.0, at.1, c.tag.as_str()));
            }
        }
        self.tags_left(&mut chart, outside, per_px, &tag_style)
    }

    /// (c)'s tags `outside` their rectangles ((s, t) of the rectangle's centre, tag) left of
    /// the texture: right-aligned 5 units left of s = 0, at their parts' heights, spread a
    /// tag's height apart, each joined by a leader to a point a quarter into its part.
    fn tags_left<DB: DrawingBackend>(
        &self,
        chart: &mut Chart2d<'_, DB>,
        mut outside: Vec<(f64, f64, &str)>,
        per_px: f64,
        style: &TextStyle<'_>,
    ) -> Result<(), Fail> {
        outside.sort_by(|a, b| b.1.total_cmp(&a.1));
        let step = (f64::from(TAG) + 2.0) * per_px;
        let mut ts: Vec<f64> = outside.iter().map(|o| o.1).collect();
        // Spread about their mean where closer than a step.
        for k in 1..ts.len() {
            if ts[k - 1] - ts[k] < step {
                let mid = 0.5 * (ts[k - 1] + ts[k]);
                ts[k - 1] = ts[k - 1].max(mid + 0.5 * step);
                ts[k] = ts[k - 1] - step;
            }
        }
        let x = -4.0 * per_px;
        for ((s, t, tag), ty) in outside.into_iter().zip(ts) {
            let into = 0.25 * s;
            chart.draw_series(LineSeries::new(
                [(x + 1.0 * per_px, ty), (into, t)],
                RGBColor(90, 90, 90).stroke_width(1),
            ))?;
            chart.draw_series(std::iter::once(Text::new(
                tag.to_string(),
                (x - 1.0 * per_px, ty),
                style.clone(),
            )))?;
        }
        Ok(())
    }
}
