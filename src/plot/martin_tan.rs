//! Martin & Tan 2004 Fig 6: the area of the focus region in the shadow map against the light
//! direction, measured on the crate's TSM matrices.
//!
//! The focus region is the eye's frustum truncated at δ beyond the near plane (Martin & Tan
//! §6.2). For each light direction the TSM matrix is built ([`crate::build::warp`] with
//! [`WarpRule::Tsm`]: the 80 % rule maps the point n + δ on the view axis to the 80 % line), the
//! eight corners of the focus region are projected into the map, and the area of their convex
//! hull, as a fraction of the map, is plotted.

use super::chart::{
    draw_colour_bar, draw_hemisphere, draw_line_chart, frame, linspace, Axis, ColourScale,
    LineChart, PolarGrid, Series, PALETTE,
};
use super::{Fail, Figure};
use crate::build::{warp, WarpRule};
use crate::ViewFrustum;
use glam::DVec3;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::f64::consts::{FRAC_PI_2, TAU};

/// The focus distance δ beyond the near plane (as in Zhang Fig 3).
const FOCUS: f64 = super::zhang::TSM_FOCUS;

/// Hemisphere grid: elevation rows (both ends) and azimuth columns.
const ELEVATIONS: usize = 31;
const AZIMUTHS: usize = 120;

/// The direction light travels for elevation `el` and azimuth `az` (radians), as in
/// [`crate::measure::sweep`]: the source lies towards (cos el · sin az, sin el, cos el · cos az);
/// az = 0 behind the viewer, π in front, el = π/2 overhead.
fn light_dir(el: f64, az: f64) -> DVec3 {
    let (se, ce) = el.sin_cos();
    let (sa, ca) = az.sin_cos();
    -DVec3::new(ce * sa, se, ce * ca)
}

/// Twice the signed area of the triangle o, a, b.
fn cross(o: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

/// The area of the convex hull of `pts` (Andrew's monotone chain, then the shoelace formula).
pub(super) fn hull_area(pts: &[(f64, f64)]) -> f64 {
    let mut p: Vec<(f64, f64)> = pts.to_vec();
    p.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    p.dedup();
    if p.len() < 3 {
        return 0.0;
    }
    let mut hull: Vec<(f64, f64)> = Vec::with_capacity(2 * p.len());
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &(f64, f64)>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    let n = hull.len();
    0.5 * (0..n)
        .map(|i| {
            let (a, b) = (hull[i], hull[(i + 1) % n]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum::<f64>()
        .abs()
}

/// The fraction of the shadow map the focus region covers for a light travelling along `dir`.
fn focus_area(view: &ViewFrustum, focus: &ViewFrustum, dir: DVec3) -> Result<f64, crate::Error> {
    let m = warp(view, dir, WarpRule::Tsm { focus: FOCUS })?;
    let mut st = [(0.0, 0.0); 8];
    for (k, c) in focus.corners().into_iter().enumerate() {
        let p = m.project(c).ok_or_else(|| {
            crate::Error::Degenerate(format!(
                "a focus-region corner is behind the TSM's centre of projection for light {dir}"
            ))
        })?;
        // Clip x, y ∈ [−1, 1] → s, t ∈ [0, 1].
        st[k] = (0.5 * (p.x + 1.0), 0.5 * (p.y + 1.0));
    }
    Ok(hull_area(&st))
}

pub(super) struct Fig6 {
    grid: PolarGrid,
    scale: ColourScale,
    profile: LineChart,
    caption: Vec<String>,
}

pub(super) fn fig6() -> Result<Fig6, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
    let focus = view.with_depth_range(view.near(), view.near() + FOCUS)?;
    let de = FRAC_PI_2 / (ELEVATIONS - 1) as f64;
    let da = TAU / AZIMUTHS as f64;
    let mut values = Vec::with_capacity(ELEVATIONS * AZIMUTHS);
    for i in 0..ELEVATIONS {
        for j in 0..AZIMUTHS {
            let dir = light_dir(i as f64 * de, j as f64 * da);
            values.push(Some(focus_area(&view, &focus, dir)?));
        }
    }
    let grid = PolarGrid {
        elev_edges: (0..=ELEVATIONS)
            .map(|i| (i as f64 * de - 0.5 * de).clamp(0.0, FRAC_PI_2))
            .collect(),
        az_edges: (0..=AZIMUTHS).map(|j| j as f64 * da - 0.5 * da).collect(),
        values,
    };
    // The vertical plane: from behind the viewer (0°) over the top (90°) to in front (180°).
    let angles = linspace(0.0, 180.0, 361);
    let mut pts = Vec::with_capacity(angles.len());
    for &a in &angles {
        let r = a.to_radians();
        let dir = DVec3::new(0.0, -r.sin(), -r.cos());
        pts.push((a, focus_area(&view, &focus, dir)?));
    }
    let mut profile = LineChart::new(
        "in the view's vertical plane",
        Axis::linear(
            "angle between light and view directions (degrees; 0 behind, 180 in front)",
            0.0,
            180.0,
        ),
        Axis::linear("focus region area / shadow-map area", 0.0, 1.0),
    );
    profile.legend = SeriesLabelPosition::LowerMiddle;
    profile.series.push(Series::line(
        format!("TSM, 80 % rule, δ = {FOCUS}"),
        pts,
        PALETTE[0],
    ));
    Ok(Fig6 {
        grid,
        scale: ColourScale {
            axis: Axis::linear("focus region area / shadow-map area", 0.0, 1.0),
            levels: 40,
        },
        profile,
        caption: vec![
            format!("Martin & Tan 2004, Fig. 6, measured: the area the focus region (the eye frustum from n to n + δ, δ = {FOCUS}) covers in the TSM shadow map (build::warp, WarpRule::Tsm),"),
            "for every light direction above the viewer (left: overhead at the centre, behind on the left, in front on the right) and in the vertical plane (right). n = 1, f = 100, θ = 30°.".to_string(),
        ],
    })
}

impl Figure for Fig6 {
    fn size(&self) -> (u32, u32) {
        (1300, 600)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption: Vec<&str> = self.caption.iter().map(String::as_str).collect();
        let body = frame(
            root,
            "Area of the focus region in the trapezoidal shadow map against the light direction",
            &caption,
        )?;
        let (left, right) = body.split_horizontally(560);
        let (disk, bar) = left.split_horizontally(450);
        draw_hemisphere(&disk, "over the hemisphere", &self.grid, &self.scale)?;
        draw_colour_bar(&bar, &self.scale)?;
        draw_line_chart(&right, &self.profile)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::hull_area;

    #[test]
    fn hull_area_of_a_square_with_inner_points() {
        let pts = [
            (0.0, 0.0),
            (1.0, 0.0),
            (0.5, 0.5),
            (1.0, 1.0),
            (0.0, 1.0),
            (0.2, 0.7),
            (1.0, 0.0),
        ];
        assert!((hull_area(&pts) - 1.0).abs() < 1e-15);
        // A triangle: ½ · 2 · 3.
        assert!((hull_area(&[(0.0, 0.0), (2.0, 0.0), (0.0, 3.0)]) - 3.0).abs() < 1e-15);
        assert_eq!(hull_area(&[(0.0, 0.0), (1.0, 1.0)]), 0.0);
    }
}
