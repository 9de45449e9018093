//! The inset of Martin & Tan's Fig 3 ([`super`]) panel (a): the apex enlarged, in a frame of
//! its own under (a)'s axes (the sixth review, R6-martin-tan-fig3-1: drawn inside (a)'s axes
//! under y = 0, where the y spine ran on, it read as data at negative y).

use super::super::chart::{
    clip_polyline, clip_to_rect, draw_fine_path, fill_fine_points, to_backend, Dash, Rect, Ticked,
    FONT,
};
use super::super::Fail;
use super::{hull, magnification, Fig3, EDGE, EDGES, FOCUS_C, HULL, TRAP};
use glam::DVec2;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The inset's greatest width over its height, and the focus region's share of the inset.
const INSET_ASPECT: f64 = 2.0;
const INSET_FILL: f64 = 0.6;
/// The gap between the strip's top (under (a)'s axis name) and the inset's frame, and under
/// the frame, in units.
const INSET_GAP: (i32, i32) = (4, 8);

/// The grey of the inset's frame and of the window it shows, outlined in (a).
const FRAME: RGBColor = RGBColor(90, 90, 90);

impl Fig3 {
    /// The window (min, max) round the focus region that the inset shows, `aspect` (width over
    /// height) to its pixels: the focus region's bounding box, centred, filling
    /// [`INSET_FILL`] of it.
    pub(in crate::plot) fn inset_window(&self, aspect: f64) -> (DVec2, DVec2) {
        let lo = self
            .focus
            .iter()
            .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p));
        let hi = self
            .focus
            .iter()
            .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p));
        let mid = 0.5 * (lo + hi);
        let size = (hi - lo) / INSET_FILL;
        let h = size.y.max(size.x / aspect);
        let half = DVec2::new(0.5 * h * aspect, 0.5 * h);
        (mid - half, mid + half)
    }

    /// The inset of (a): the apex enlarged in `strip`, the area under (a)'s axes and their
    /// names, framed, centred under the apex as far as the strip allows, labelled with its
    /// enlargement over (a) ("×4"; `unit` is (a)'s units per light-space unit), with the window
    /// it shows outlined in (a) in the frame's grey. With `joined` (an area holding both, across
    /// two columns) the window's lower corners are joined to the frame's upper ones, as
    /// lloyd2005-fig8 joins its inset (R7-MT3-2): the lines cross (a)'s x axis between its tick
    /// labels and pass beside its name. One column joins nothing: its inset, as wide as the
    /// column, would draw them across (a)'s "−50"; its caption names the window and the
    /// enlargement instead. Returns the enlargement.
    pub(super) fn draw_inset<DB: DrawingBackend>(
        &self,
        strip: &DrawingArea<DB, Shift>,
        chart: &super::super::chart::Chart2d<'_, DB>,
        unit: f64,
        joined: Option<&DrawingArea<DB, Shift>>,
    ) -> Result<f64, Fail> {
        let (sw, sh) = strip.dim_in_pixel();
        let (sx, _) = strip.get_base_pixel();
        let h = (sh as i32 - INSET_GAP.0 - INSET_GAP.1).max(20);
        let w = (sw as i32 - 8)
            .min((f64::from(h) * INSET_ASPECT) as i32)
            .max(20);
        let (apex_x, _) = chart.backend_coord(&(0.0, 0.0));
        let x0 = (apex_x - sx - w / 2).clamp(4, (sw as i32 - w - 4).max(4));
        let y0 = INSET_GAP.0;
        let (lo, hi) = self.inset_window(f64::from(w) / f64::from(h));
        // The window outlined in (a).
        let (c0, c1) = (
            chart.backend_coord(&(lo.x, lo.y)),
            chart.backend_coord(&(hi.x, hi.y)),
        );
        let plot = chart.plotting_area().strip_coord_spec();
        let (px, py) = plot.get_base_pixel();
        plot.draw(&Rectangle::new(
            [(c0.0 - px, c1.1 - py), (c1.0 - px, c0.1 - py)],
            FRAME.stroke_width(1),
        ))?;
        if let Some(whole) = joined {
            let (bx, by) = whole.get_base_pixel();
            let (ix, iy) = strip.get_base_pixel();
            let (ix, iy) = (ix - bx + x0, iy - by + y0);
            let joins = [
                ((c0.0 - bx, c0.1 - by), (ix, iy)),
                ((c1.0 - bx, c0.1 - by), (ix + w - 1, iy)),
            ];
            for (from, to) in joins {
                whole.draw(&PathElement::new(vec![from, to], FRAME.stroke_width(1)))?;
            }
        }
        let inset = strip.clone().shrink((x0, y0), (w as u32, h as u32));
        inset.fill(&WHITE)?;
        let zoom = ChartBuilder::on(&inset).build_cartesian_2d(
            Ticked::new(lo.x, hi.x, Vec::new(), Vec::new()),
            Ticked::new(lo.y, hi.y, Vec::new(), Vec::new()),
        )?;
        let clip = |pts: &[DVec2]| -> Vec<Vec<(f64, f64)>> {
            let pts: Vec<Option<(f64, f64)>> = pts.iter().map(|q| Some((q.x, q.y))).collect();
            clip_polyline(&pts, (lo.x, hi.x, lo.y, hi.y))
        };
        // C cut to the window (the ninth review, R9-martin-tan-fig3-1: handed over whole, its
        // corners outside the window were pulled onto the frame one coordinate at a time, and
        // the fill ran from the frame's top corners, far outside T). Lines are cut by `clip`.
        let hull_xy: Vec<(f64, f64)> = hull(&self.eye).iter().map(|p| (p.x, p.y)).collect();
        // In light-space units: the cut needs only x0 ≤ x1 and y0 ≤ y1.
        let window = Rect {
            x0: lo.x,
            y0: lo.y,
            x1: hi.x,
            y1: hi.y,
        };
        // Placed to a tenth of a unit, as in (a) (R9-martin-tan-fig3-3).
        let to = to_backend(&zoom);
        let area = zoom.plotting_area().strip_coord_spec();
        let on_page =
            |piece: Vec<(f64, f64)>| -> Vec<(f64, f64)> { piece.into_iter().map(&to).collect() };
        fill_fine_points(&area, on_page(clip_to_rect(&hull_xy, &window)), HULL)?;
        for (corners, colour, width) in [(&self.eye, EDGE, 1), (&self.focus, FOCUS_C, 2)] {
            for (a, b) in EDGES {
                for piece in clip(&[corners[a], corners[b]]) {
                    draw_fine_path(&area, &on_page(piece), colour, width, Dash::Solid)?;
                }
            }
        }
        let mut closed = self.trapezoid.to_vec();
        closed.push(closed[0]);
        for piece in clip(&closed) {
            draw_fine_path(&area, &on_page(piece), TRAP, 2, Dash::Solid)?;
        }
        inset.draw(&Rectangle::new(
            [(0, 0), (w - 1, h - 1)],
            FRAME.stroke_width(1),
        ))?;
        // The enlargement in the inset's lower left corner, where the apex leaves it empty: the
        // inset's units per light-space unit over (a)'s.
        let zoom_factor = f64::from(w) / (hi.x - lo.x) / unit;
        inset.draw(&Text::new(
            magnification(zoom_factor),
            (4, h - 3),
            TextStyle::from((FONT, 13).into_font())
                .color(&FRAME)
                .pos(Pos::new(HPos::Left, VPos::Bottom)),
        ))?;
        Ok(zoom_factor)
    }
}
