//! lloyd2005-fig8 (a): the partitions seen from the light, tagged, with an enlarged inset of
//! the apex region, where the smallest parts meet (the sixth review, R6-lloyd2005-fig8-1).

use super::leaders::leader_order;
use super::{inside, Fig8, TAG, X_NAME, Z_NAME};
use crate::plot::chart::{
    boxed_text, build_chart_styled, equal_aspect, Axis, ChartStyle, Ticked, FONT,
};
use crate::plot::Fail;
use glam::DVec2;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The apex region the inset enlarges, light-view (x, y): (min, max). The inset widens it
/// about its centre to its own shape.
pub(super) const APEX: (DVec2, DVec2) = (DVec2::new(-2.0, 0.0), DVec2::new(3.0, 3.0));

/// The grey of leaders, the inset's frame and the lines joining it to its window in (a).
const GREY: RGBColor = RGBColor(90, 90, 90);

/// `poly` (convex) clipped to the rectangle `(lo, hi)` (Sutherland–Hodgman).
pub(super) fn clip_to(poly: &[DVec2], (lo, hi): (DVec2, DVec2)) -> Vec<DVec2> {
    let mut out = poly.to_vec();
    // Each edge of the rectangle: a point is kept where `keep` holds; the crossing by `cut`.
    let edges: [(usize, f64, f64); 4] = [
        (0, lo.x, 1.0),
        (0, hi.x, -1.0),
        (1, lo.y, 1.0),
        (1, hi.y, -1.0),
    ];
    for (axis, at, sign) in edges {
        let side = |p: DVec2| sign * (p[axis] - at);
        let input = std::mem::take(&mut out);
        for (k, &p) in input.iter().enumerate() {
            let q = input[(k + 1) % input.len()];
            let (sp, sq) = (side(p), side(q));
            if sp >= 0.0 {
                out.push(p);
            }
            if (sp >= 0.0) != (sq >= 0.0) {
                out.push(p + (q - p) * (sp / (sp - sq)));
            }
        }
        if out.is_empty() {
            break;
        }
    }
    out
}

impl Fig8 {
    /// (a): every partition's face part seen from the light, filled and hatched in its look,
    /// with its tag, and the inset of the apex region ([`APEX`]) in a strip `inset_h` tall under
    /// it, framed, its
    /// window outlined in (a) and joined to it. A tag stands inside its part in (a) where it
    /// fits, else inside the part's piece in the inset where it fits there, else in a row under
    /// (a)'s drawing joined to its part by a leader.
    pub(super) fn draw_faces<DB: DrawingBackend>(
        &self,
        whole: &DrawingArea<DB, Shift>,
        style: &ChartStyle,
        inset_h: u32,
    ) -> Result<(), Fail> {
        let (lo, hi) = Self::window(self.cells.iter().flat_map(|c| c.outline.iter().copied()));
        // Room under the drawing for the tags of parts too small to hold them in (a) or the
        // inset (one column kept 0.3 before the inset took the apex's tags).
        let room = 0.14;
        let lo = lo - DVec2::new(0.0, room * (hi.y - lo.y));
        let title = "(a) from the light";
        let (x, y) = (
            Axis::linear(X_NAME, lo.x, hi.x),
            Axis::linear(Z_NAME, lo.y, hi.y),
        );
        // (a) as wide as its area (its x range so the same in both forms: the sixth review,
        // R6-lloyd2005-fig8-2, found one column's −10…10 against −5…5), the inset under it.
        let (_, wh) = whole.dim_in_pixel();
        let (area, inset) = whole.split_vertically(wh.saturating_sub(inset_h));
        let inset = inset.margin(4, 4, 10, 8);
        let (xa, ya) = equal_aspect(&area, title, &x, &y, style)?;
        let mut chart = build_chart_styled(&area, title, &xa, &ya, false, style)?;
        let (pw, _) = chart.plotting_area().dim_in_pixel();
        let per_px = (xa.max - xa.min) / f64::from(pw);
        for (i, c) in self.cells.iter().enumerate() {
            self.fill_hatched(&mut chart, &c.outline, i, per_px)?;
            let mut closed: Vec<(f64, f64)> = c.outline.iter().map(|p| (p.x, p.y)).collect();
            closed.push(closed[0]);
            chart.draw_series(LineSeries::new(closed, BLACK.stroke_width(1)))?;
        }
        // The inset's window: APEX widened about its centre to the inset's shape.
        let (iw, ih) = inset.dim_in_pixel();
        let (a0, a1) = APEX;
        let size = a1 - a0;
        let unit = (f64::from(iw) / size.x).min(f64::from(ih) / size.y);
        let half = DVec2::new(f64::from(iw), f64::from(ih)) * (0.5 / unit);
        let mid = 0.5 * (a0 + a1);
        let (w0, w1) = (mid - half, mid + half);
        let tag_style =
            TextStyle::from((FONT, TAG).into_font()).pos(Pos::new(HPos::Center, VPos::Center));
        let fits = |poly: &[DVec2], tag: &str, per: f64| -> Result<Option<DVec2>, Fail> {
            if poly.len() < 3 {
                return Ok(None);
            }
            let mid = poly.iter().copied().sum::<DVec2>() / poly.len() as f64;
            let (tw, th) = area
                .estimate_text_size(tag, &tag_style)
                .map_err(|e| Fail::Draw(e.to_string()))?;
            let half = DVec2::new(f64::from(tw) + 6.0, f64::from(th) + 4.0) * 0.5 * per;
            let ok = |m: DVec2| {
                [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                    .iter()
                    .all(|&(sx, sy)| inside(poly, m + DVec2::new(sx * half.x, sy * half.y)))
            };
            // The centre, else the point nearest it of a 16 × 16 grid over the part where the
            // tag's box fits (a thin part's centre can be too narrow where its wide end is not).
            let (plo, phi) = Self::window(poly.iter().copied());
            let grid = (0..=16).flat_map(|i| {
                (0..=16)
                    .map(move |j| plo + (phi - plo) * DVec2::new(f64::from(i), f64::from(j)) / 16.0)
            });
            Ok(std::iter::once(mid)
                .chain(grid)
                .filter(|&m| ok(m))
                .min_by(|a, b| a.distance(mid).total_cmp(&b.distance(mid))))
        };
        // Tags: in (a), else in the inset, else under the drawing.
        let mut in_inset: Vec<(DVec2, &str)> = Vec::new();
        let mut outside = Vec::new();
        for c in &self.cells {
            if let Some(m) = fits(&c.outline, &c.tag, per_px)? {
                boxed_text(
                    &mut chart,
                    (m.x, m.y),
                    &c.tag,
                    Pos::new(HPos::Center, VPos::Center),
                    TAG,
                    BLACK,
                )?;
            } else if let Some(m) = fits(&clip_to(&c.outline, (w0, w1)), &c.tag, 1.0 / unit)? {
                in_inset.push((m, c.tag.as_str()));
            } else {
                let mid = c.outline.iter().copied().sum::<DVec2>() / c.outline.len() as f64;
                let (tw, _) = area
                    .estimate_text_size(&c.tag, &tag_style)
                    .map_err(|e| Fail::Draw(e.to_string()))?;
                outside.push((mid, (0.5 * f64::from(tw) + 1.0) * per_px, c.tag.as_str()));
            }
        }
        // The row under the drawing, in the order whose leaders cross neither one another nor
        // other parts most briefly ([`leader_order`]), inside the plot.
        let bottom = self
            .cells
            .iter()
            .flat_map(|c| c.outline.iter().map(|p| p.y))
            .fold(f64::INFINITY, f64::min);
        let y = bottom - 10.0 * per_px;
        let outlines: Vec<&[DVec2]> = self.cells.iter().map(|c| c.outline.as_slice()).collect();
        let (outside, xs) = leader_order(
            outside,
            (xa.min, xa.max),
            5.0 * per_px,
            y + 3.0 * per_px,
            &outlines,
        );
        for ((mid, _, tag), x) in outside.into_iter().zip(xs) {
            chart.draw_series(LineSeries::new(
                [(mid.x, mid.y), (x, y + 3.0 * per_px)],
                GREY.stroke_width(1),
            ))?;
            chart.draw_series(std::iter::once(Text::new(
                tag.to_string(),
                (x, y),
                tag_style.pos(Pos::new(HPos::Center, VPos::Top)),
            )))?;
        }
        // The window outlined in (a) and joined by its two corners nearest the inset to the
        // inset's matching corners.
        let (bx, by) = whole.get_base_pixel();
        let px = |p: DVec2| {
            let (x, y) = chart.backend_coord(&(p.x, p.y));
            (x - bx, y - by)
        };
        let (c0, c1) = (px(w0), px(w1));
        whole.draw(&Rectangle::new(
            [(c0.0, c1.1), (c1.0, c0.1)],
            GREY.stroke_width(1),
        ))?;
        let (ix, iy) = inset.get_base_pixel();
        let (ix, iy) = (ix - bx, iy - by);
        let iw = iw as i32;
        let joins = [((c0.0, c0.1), (ix, iy)), ((c1.0, c0.1), (ix + iw - 1, iy))];
        for (from, to) in joins {
            whole.draw(&PathElement::new(vec![from, to], GREY.stroke_width(1)))?;
        }
        self.draw_inset(&inset, (w0, w1), unit, per_px, &in_inset)
    }

    /// The inset: every part clipped to the window `(w0, w1)` filled and hatched as in (a),
    /// `unit` units a light-view unit, framed, with the tags `tags` at their points and its
    /// enlargement over (a) (`per_a`: (a)'s light-view units a unit) in its lower right corner.
    fn draw_inset<DB: DrawingBackend>(
        &self,
        inset: &DrawingArea<DB, Shift>,
        (w0, w1): (DVec2, DVec2),
        unit: f64,
        per_a: f64,
        tags: &[(DVec2, &str)],
    ) -> Result<(), Fail> {
        inset.fill(&WHITE)?;
        let mut zoom = ChartBuilder::on(inset).build_cartesian_2d(
            Ticked::new(w0.x, w1.x, Vec::new(), Vec::new()),
            Ticked::new(w0.y, w1.y, Vec::new(), Vec::new()),
        )?;
        for (i, c) in self.cells.iter().enumerate() {
            let piece = clip_to(&c.outline, (w0, w1));
            if piece.len() < 3 {
                continue;
            }
            self.fill_hatched(&mut zoom, &piece, i, 1.0 / unit)?;
            let mut closed: Vec<(f64, f64)> = piece.iter().map(|p| (p.x, p.y)).collect();
            closed.push(closed[0]);
            zoom.draw_series(LineSeries::new(closed, BLACK.stroke_width(1)))?;
        }
        for &(m, tag) in tags {
            boxed_text(
                &mut zoom,
                (m.x, m.y),
                tag,
                Pos::new(HPos::Center, VPos::Center),
                TAG,
                BLACK,
            )?;
        }
        let (iw, ih) = inset.dim_in_pixel();
        let (iw, ih) = (iw as i32, ih as i32);
        inset.draw(&Rectangle::new(
            [(0, 0), (iw - 1, ih - 1)],
            GREY.stroke_width(1),
        ))?;
        inset.draw(&Text::new(
            crate::plot::trapezoid::magnification(unit * per_a),
            (iw - 4, ih - 3),
            TextStyle::from((FONT, TAG).into_font())
                .color(&GREY)
                .pos(Pos::new(HPos::Right, VPos::Bottom)),
        ))?;
        Ok(())
    }
}
