//! lloyd2005-fig8 (c): the texture laid out by Eq 6, each part's rectangle in its look and
//! tagged.

use super::{Fig8, SIZE, TAG};
use crate::plot::chart::{
    boxed_text_within, build_chart_styled, column, equal_aspect, plot_size, Axis, Chart2d,
    ChartStyle, FONT, TICK, TITLE_GAP,
};
use crate::plot::{Column, Fail};
use glam::DVec2;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

impl Fig8 {
    /// The s axis' last tick (the texture's end, `n`) and its label, centred on it as the
    /// other tick labels are (the nineteenth review, R19-lloyd2005-fig8-1: right-aligned to
    /// the frame's end, "2048" read as a label of s ≈ 1730), at the other tick labels' height (the tick's length and 5 units under the
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
                .pos(Pos::new(HPos::Center, VPos::Top)),
        ))?;
        Ok(())
    }

    /// (c): the texture, square, each partition's rectangle in its look with its tag. One
    /// column draws its t axis right of the texture ([`Fig8::t_axis_right`]) and the tags of
    /// parts too small for them left of it ([`Fig8::tags_left`]), so that no tag stands by a
    /// tick label (the seventh review, R7-2005f8-3: "2048 | L2 -" between the t axis and the
    /// texture).
    pub(super) fn draw_texture<DB: DrawingBackend>(
        &self,
        outer: &DrawingArea<DB, Shift>,
        style: &ChartStyle,
    ) -> Result<(), Fail> {
        let n = f64::from(SIZE);
        let title = "(c) texture by Eq 6";
        let single = column() == Column::Single;
        let x = Axis::linear("s (texels)", 0.0, n);
        // One column: no t axis on the left (no name, no ticks), its label area the tags'.
        let (y, style) = if single {
            (
                Axis::linear("", 0.0, n).labelled_at(&[]),
                ChartStyle {
                    y_label_area: TAGS_LEFT,
                    ..*style
                },
            )
        } else {
            (Axis::linear("t (texels)", 0.0, n), *style)
        };
        let style = &style;
        let chart_title = if single { "" } else { title };
        // A panel wider than the texture at its height is narrowed so that equal aspect widens
        // no range (one column's s ran from −5000 to 2048): centred across two columns. One
        // column: the tags' room, the texture and the t axis' room right of it centred, the
        // chart (untitled) exactly the texture's size, its title centred over the texture.
        let (w, h) = plot_size(outer, title, &x, &y, style)?;
        let (bw, bh) = outer.dim_in_pixel();
        let body = if single {
            let side = (w - T_AXIS_RIGHT).min(h).max(1.0) as u32;
            let m = style.margin;
            // The charts' margins: m above and under, m left and 2m right.
            let chart_w = (3 * m + TAGS_LEFT + side).min(bw);
            let group = chart_w + T_AXIS_RIGHT as u32;
            let left = bw.saturating_sub(group) / 2;
            let chart_h = (side + 2 * m + style.x_label_area).min(bh);
            let top = bh - chart_h;
            // The title as the charts set it (plotters' `titled`: its height and half of it, at
            // most 5, above and below), then the charts' gap under it.
            let font = TextStyle::from((FONT, style.title_size).into_font())
                .pos(Pos::new(HPos::Center, VPos::Top));
            let (_, text_h) = outer
                .estimate_text_size(title, &font)
                .map_err(|e| Fail::Draw(e.to_string()))?;
            let pad = (text_h / 2).min(5);
            let title_y = (top + m).saturating_sub(TITLE_GAP + text_h + pad);
            let centre = left + m + TAGS_LEFT + side / 2;
            outer.draw(&Text::new(title, (centre as i32, title_y as i32), font))?;
            outer.clone().shrink((left, top), (chart_w, chart_h))
        } else {
            let spare = (w - h).max(0.0) as u32;
            outer
                .clone()
                .shrink((spare / 2, 0), (bw - spare.min(bw / 2), bh))
        };
        let body = &body;
        // Equal aspect: the square texture drawn square.
        let (xa, ya) = equal_aspect(body, chart_title, &x, &y, style)?;
        // Labelled at the texture's ends and middle only: four-digit labels every 500 texels
        // run together on a narrow panel. The s axis' last label, 2048, is written at the
        // frame's end below ([`Fig8::last_s_label`]; the equal aspect may draw the axis on).
        // In one column, whose plot is about 60 units wide, s is labelled at its ends only (the
        // sixth review, R6-lloyd2005-fig8-3: "1024" and "2048" came within 3.5 units).
        let ends = [0.0, 0.5 * n, n];
        let (xa, ya) = if single {
            (xa.labelled_at(&ends[..1]), ya.labelled_at(&[]))
        } else {
            (xa.labelled_at(&ends[..2]), ya.labelled_at(&ends))
        };
        let mut chart = build_chart_styled(body, chart_title, &xa, &ya, false, style)?;
        Self::last_s_label(body, &chart, n, style)?;
        if single {
            Self::t_axis_right(outer, &chart, &ends, style)?;
        }
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
                // The white box within the part, clear of its outline.
                boxed_text_within(
                    &mut chart,
                    at,
                    &c.tag,
                    Pos::new(HPos::Center, VPos::Center),
                    TAG,
                    BLACK,
                    Some([
                        (f64::from(v.x), f64::from(v.y)),
                        (
                            f64::from(v.x) + f64::from(v.width),
                            f64::from(v.y) + f64::from(v.height),
                        ),
                    ]),
                )?;
            } else {
                outside.push((at.0, at.1, c.tag.as_str()));
            }
        }
        self.tags_left(outer, &chart, outside, per_px, &tag_style)
    }

    /// One column's t axis, right of the texture: its line on the texture's right edge, a
    /// tick outwards at each of `at` with its label left-aligned after it, and its name
    /// "t (texels)" reading upwards right of the labels, as the charts draw a left axis.
    fn t_axis_right<DB: DrawingBackend>(
        outer: &DrawingArea<DB, Shift>,
        chart: &Chart2d<'_, DB>,
        at: &[f64],
        style: &ChartStyle,
    ) -> Result<(), Fail> {
        let (bx, by) = outer.get_base_pixel();
        let n = f64::from(SIZE);
        let px = |t: f64| {
            let (x, y) = chart.backend_coord(&(n, t));
            (x - bx, y - by)
        };
        let tick = TICK as i32;
        let ((x, top), (_, bottom)) = (px(n), px(0.0));
        outer.draw(&PathElement::new(
            vec![(x, top), (x, bottom)],
            BLACK.stroke_width(1),
        ))?;
        let font = TextStyle::from((FONT, style.tick_size).into_font())
            .pos(Pos::new(HPos::Left, VPos::Center));
        let mut widest = 0;
        for &t in at {
            let (x, y) = px(t);
            outer.draw(&PathElement::new(
                vec![(x, y), (x + tick, y)],
                BLACK.stroke_width(1),
            ))?;
            let label = format!("{}", t as u32);
            let (w, _) = outer
                .estimate_text_size(&label, &font)
                .map_err(|e| Fail::Draw(e.to_string()))?;
            widest = widest.max(w as i32);
            outer.draw(&Text::new(label, (x + tick + TICK_GAP, y), font.clone()))?;
        }
        let name = TextStyle::from((FONT, style.desc_size).into_font())
            .transform(FontTransform::Rotate270)
            .pos(Pos::new(HPos::Center, VPos::Top));
        outer.draw(&Text::new(
            "t (texels)",
            (x + tick + TICK_GAP + widest + NAME_GAP, (top + bottom) / 2),
            name,
        ))?;
        Ok(())
    }

    /// (c)'s tags `outside` their rectangles ((s, t) of the rectangle's centre, tag) left of
    /// the texture: right-aligned 5 units left of s = 0, at their parts' heights, spread a
    /// tag's height apart, each joined by a leader to a point a quarter into its part. Drawn
    /// on the panel's area `outer` (one column's are left of the chart's plot).
    fn tags_left<DB: DrawingBackend>(
        &self,
        outer: &DrawingArea<DB, Shift>,
        chart: &Chart2d<'_, DB>,
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
        let (bx, by) = outer.get_base_pixel();
        let px = |s: f64, t: f64| {
            let (x, y) = chart.backend_coord(&(s, t));
            (x - bx, y - by)
        };
        let x = -4.0 * per_px;
        for ((s, t, tag), ty) in outside.into_iter().zip(ts) {
            let into = 0.25 * s;
            outer.draw(&PathElement::new(
                vec![px(x + 1.0 * per_px, ty), px(into, t)],
                RGBColor(90, 90, 90).stroke_width(1),
            ))?;
            outer.draw(&Text::new(
                tag.to_string(),
                px(x - 1.0 * per_px, ty),
                style.clone(),
            ))?;
        }
        Ok(())
    }
}

/// One column: the width left of (c)'s texture for the tags of parts too small for them, in
/// units (a tag 13 units wide, its leader and gaps).
const TAGS_LEFT: u32 = 24;

/// One column: the width kept right of (c)'s texture for its t axis (tick, "2048", its name).
const T_AXIS_RIGHT: f64 = 46.0;

/// The gap between a tick's end and its label, and between the labels and the axis' name, in
/// units (as the charts' left axes: 4 and about 6).
const TICK_GAP: i32 = 4;
const NAME_GAP: i32 = 6;
