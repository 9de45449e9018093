//! Martin & Tan 2004 Fig 6: the area of the focus region in the shadow map against the light
//! direction, measured on the crate's TSM matrices.
//!
//! The focus region is the eye's frustum truncated at δ beyond the near plane (Martin & Tan
//! §6.2). For each light direction the trapezoidal map is built by [`crate::maps::tsm::tsm`]
//! (the 80 % rule, and the iterative variant over the map's lines), which reports the fraction of
//! the map the focus region covers ([`crate::maps::tsm::TsmMap::focus_area`]).

use super::chart::{
    draw_colour_bar, draw_hemisphere, draw_line_chart, frame, linspace, Axis, ColourScale,
    LineChart, PolarGrid, Series, PALETTE,
};
use super::{Fail, Figure};
use crate::maps::tsm::{tsm, TsmOptions, TsmSearch};
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
/// [`crate::scheme::sweep`]: the source lies towards (cos el · sin az, sin el, cos el · cos az);
/// az = 0 behind the viewer, π in front, el = π/2 overhead.
fn light_dir(el: f64, az: f64) -> DVec3 {
    let (se, ce) = el.sin_cos();
    let (sa, ca) = az.sin_cos();
    -DVec3::new(ce * sa, se, ce * ca)
}

/// The fraction of the shadow map the focus region covers for a light travelling along `dir`.
fn focus_area(view: &ViewFrustum, dir: DVec3, search: TsmSearch) -> Result<f64, crate::Error> {
    Ok(tsm(
        view,
        dir,
        TsmOptions {
            focus: FOCUS,
            search,
        },
    )?
    .focus_area)
}

pub(super) struct Fig6 {
    grid: PolarGrid,
    scale: ColourScale,
    profile: LineChart,
    caption: Vec<String>,
}

pub(super) fn fig6() -> Result<Fig6, Fail> {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
    let de = FRAC_PI_2 / (ELEVATIONS - 1) as f64;
    let da = TAU / AZIMUTHS as f64;
    let mut values = Vec::with_capacity(ELEVATIONS * AZIMUTHS);
    for i in 0..ELEVATIONS {
        for j in 0..AZIMUTHS {
            let dir = light_dir(i as f64 * de, j as f64 * da);
            values.push(Some(focus_area(&view, dir, TsmSearch::EightyPercent)?));
        }
    }
    let (lo, hi) = values
        .iter()
        .flatten()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
    let grid = PolarGrid {
        elev_edges: (0..=ELEVATIONS)
            .map(|i| (i as f64 * de - 0.5 * de).clamp(0.0, FRAC_PI_2))
            .collect(),
        az_edges: (0..=AZIMUTHS).map(|j| j as f64 * da - 0.5 * da).collect(),
        values,
    };
    // The vertical plane: from behind the viewer (0°) over the top (90°) to in front (180°).
    let angles = linspace(0.0, 180.0, 361);
    let mut eighty = Vec::with_capacity(angles.len());
    let mut iterative = Vec::with_capacity(angles.len());
    for &a in &angles {
        let r = a.to_radians();
        let dir = DVec3::new(0.0, -r.sin(), -r.cos());
        eighty.push((a, focus_area(&view, dir, TsmSearch::EightyPercent)?));
        iterative.push((
            a,
            focus_area(&view, dir, TsmSearch::Iterative { map_lines: 1024 })?,
        ));
    }
    let mut profile = LineChart::new(
        "(b) in the view's vertical plane",
        Axis::linear("light angle from behind (°)", 0.0, 180.0),
        Axis::log10(
            "share of the map (log)",
            profile_floor(&eighty, &iterative),
            1.0,
        ),
    );
    profile.legend = SeriesLabelPosition::LowerMiddle;
    // The 80 % rule jumps back to the dueling-frusta value exactly behind and in front (0° and
    // 180°, on the plot's border): those two points marked, unjoined and unlabelled.
    let (first, last) = (eighty[0], eighty[eighty.len() - 1]);
    profile
        .series
        .push(Series::line("80 % rule", eighty, PALETTE[0]));
    profile.series.push(Series {
        label: None,
        ..Series::line("", vec![first, (90.0, f64::NAN), last], PALETTE[0]).with_markers()
    });
    profile
        .series
        .push(Series::line("iterative", iterative, PALETTE[1]).dashed());
    Ok(Fig6 {
        grid,
        // Logarithmic, as the profile: the dueling-frusta band near the horizon (0.003 to
        // 0.01) is two decades below overhead (0.49) and would be one colour on a linear bar.
        scale: ColourScale::smooth(Axis::log10("share of the map (log)", lo, hi)),
        profile,
        caption: vec![format!(
            "Martin & Tan 2004, Fig. 6: the share of the trapezoidal map (80 % rule) covered by \
             the focus region (the eye frustum from n to n + δ) for every light direction above \
             the viewer (a) and in its vertical plane (b, iterative: the variant over 1024 lines); \
             n = {n}, f = {f}, θ = {theta:.0}°, δ = {FOCUS}. Unlike the paper, which plots one \
             angle as a surface, the whole hemisphere; markers: exactly behind and in front.",
            n = view.near(),
            f = view.far(),
            theta = view.half_fov().to_degrees(),
        )],
    })
}

/// The bottom of the profile's logarithmic axis: a power of ten below the smallest area.
fn profile_floor(a: &[(f64, f64)], b: &[(f64, f64)]) -> f64 {
    let min = a
        .iter()
        .chain(b)
        .map(|p| p.1)
        .filter(|&v| v > 0.0)
        .fold(1.0f64, f64::min);
    10f64.powf(min.log10().floor())
}

impl Figure for Fig6 {
    fn size(&self) -> (u32, u32) {
        (520, 470)
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption: Vec<&str> = self.caption.iter().map(String::as_str).collect();
        let body = frame(
            root,
            "Area of the focus region in the trapezoidal map",
            &caption,
        )?;
        // The hemisphere with its bar on the left, the profile beside it (issue 35: stacked,
        // the figure was 928 units tall).
        let (w, _) = body.dim_in_pixel();
        let (left, right) = body.split_horizontally(w * 27 / 50);
        let (w, _) = left.dim_in_pixel();
        let (disk, bar) = left.split_horizontally(w.saturating_sub(96));
        draw_hemisphere(&disk, "(a) over the hemisphere", &self.grid, &self.scale)?;
        draw_colour_bar(&bar, &self.scale)?;
        draw_line_chart(&right, &self.profile)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Light exactly behind or in front: the frustum looks square and the map is its bounding
    /// rectangle, the far face (side 2 f tan θ); the focus region is seen as its own far face at
    /// depth n + δ, so its share of the map is ((n + δ)/f)² = (11/100)² = 0.0121 by hand.
    /// The caption says how the figure differs from the paper (issue 25), and the 80 % rule's
    /// jumps at exactly 0° and 180° are marked: an unlabelled marker series at those two angles
    /// with the rule's values there, (11/100)² behind (the dueling-frusta share, by hand).
    #[test]
    fn caption_states_the_difference_and_the_jumps_are_marked() {
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        assert!(fig.caption.join(" ").contains("Unlike the paper"));
        let marks = fig
            .profile
            .series
            .iter()
            .find(|s| s.markers && s.label.is_none())
            .expect("a marker series");
        let finite: Vec<(f64, f64)> = marks
            .points
            .iter()
            .copied()
            .filter(|p| p.1.is_finite())
            .collect();
        assert_eq!(finite.len(), 2);
        assert_eq!((finite[0].0, finite[1].0), (0.0, 180.0));
        assert!((finite[0].1 - 0.0121).abs() < 1e-9, "{finite:?}");
    }

    #[test]
    fn dueling_frusta_area_by_hand() {
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        let want = (11.0f64 / 100.0).powi(2);
        for s in &fig.profile.series {
            let first = s.points[0];
            let last = *s.points.last().unwrap();
            assert_eq!((first.0, last.0), (0.0, 180.0));
            assert!((first.1 - want).abs() < 1e-9, "{}", first.1);
            assert!((last.1 - want).abs() < 1e-9, "{}", last.1);
        }
        // The same directions in the hemisphere grid: horizon row, azimuth 0 and π.
        let behind = fig.grid.values[0].unwrap();
        let front = fig.grid.values[AZIMUTHS / 2].unwrap();
        assert!((behind - want).abs() < 1e-9 && (front - want).abs() < 1e-9);
    }

    /// The hemisphere's colour bar is logarithmic (issue 25): the dueling-frusta value 0.0121
    /// and the overhead one (about 0.49) lie 1.6 decades apart, and on the bar's log₁₀ axis the
    /// dueling value sits at (log 0.0121 − log lo)/(log hi − log lo) of its height (a linear bar
    /// would put it in the bottom 3 %, one colour with everything below).
    #[test]
    fn hemisphere_colour_bar_is_logarithmic() {
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        let v: Vec<f64> = fig.grid.values.iter().flatten().copied().collect();
        let (lo, hi) = v
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
        let axis = &fig.scale.axis;
        let (a, b) = axis.range();
        assert!((a - lo.log10()).abs() < 1e-12 && (b - hi.log10()).abs() < 1e-12);
        let t = (0.0121f64.log10() - lo.log10()) / (hi.log10() - lo.log10());
        let level = fig.scale.level(0.0121).unwrap() as f64 / fig.scale.levels as f64;
        assert!(
            (level - t).abs() < 1.5 / fig.scale.levels as f64,
            "{level} vs {t}"
        );
        assert!(t > 0.2, "{t}");
    }
}
