//! Martin & Tan 2004 Fig 6: the area of the focus region in the shadow map against the light
//! direction, measured on the crate's TSM matrices.
//!
//! The focus region is the eye's frustum truncated at δ beyond the near plane (Martin & Tan
//! §6.2). For each light direction the trapezoidal map is built by [`crate::maps::tsm::tsm`]
//! (the 80 % rule, and the iterative variant over the map's lines), which reports the fraction of
//! the map the focus region covers ([`crate::maps::tsm::TsmMap::focus_area`]).

use super::chart::{
    column, draw_hemisphere, draw_line_chart, frame, linspace, Axis, ColourScale, LineChart,
    Marker, PolarGrid, Series, PALETTE,
};
use super::hemisphere::{draw_bar, BAR_WIDTH};
use super::Column;
use super::{Fail, Figure};
use crate::maps::tsm::{tsm, TsmOptions, TsmSearch};
use crate::ViewFrustum;
use glam::DVec3;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::f64::consts::{FRAC_PI_2, TAU};

/// The focus distance δ beyond the near plane (as in Zhang Fig 3).
const FOCUS: f64 = super::zhang::TSM_FOCUS;

/// Hemisphere grid: elevation rows (both ends) and azimuth columns, every 1° (at 3° the cells
/// showed as steps along the dueling-frusta bands).
const ELEVATIONS: usize = 91;
const AZIMUTHS: usize = 360;

/// The shape that marks the 80 % rule's values exactly behind and in front (0° and 180°), as
/// the caption says; no line of the profile carries it ([`Marker::of`] gives the blue line
/// circles and the vermillion one squares).
const JUMP_MARKER: Marker = Marker::Diamond;
/// The same shape in the caption's text.
const JUMP_GLYPH: &str = "◆";

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
        // A tick every 45°: behind, overhead and in front are ticks.
        Axis::every("light angle from behind (°)", 0.0, 180.0, 0.0, 45.0),
        Axis::log10(
            "share of the map (log)",
            profile_floor(&eighty, &iterative),
            1.0,
        ),
    );
    profile.legend = SeriesLabelPosition::LowerMiddle;
    // The 80 % rule jumps back to the dueling-frusta value exactly behind and in front (0° and
    // 180°, on the plot's border): those two points marked with a shape of their own (the
    // lines carry theirs along them), unjoined and unlabelled.
    let (first, last) = (eighty[0], eighty[eighty.len() - 1]);
    let dueling = first.1;
    profile
        .series
        .push(Series::line("80 % rule", eighty, PALETTE[0]));
    profile.series.push(Series {
        label: None,
        shape: Some(JUMP_MARKER),
        ..Series::line("", vec![first, (90.0, f64::NAN), last], PALETTE[0]).with_markers()
    });
    profile
        .series
        .push(Series::line("iterative", iterative, PALETTE[1]).dashed());
    Ok(Fig6 {
        grid,
        // Logarithmic, as the profile: the dueling-frusta band near the horizon (0.003 to
        // 0.01) is two decades below overhead (0.49) and would be one colour on a linear bar.
        // Its own short name: the profile's y axis, beside it, names the quantity in full.
        scale: ColourScale::smooth(Axis::log10("share", lo, hi)),
        profile,
        caption: vec![format!(
            "Martin & Tan 2004, Fig. 6: the share of the trapezoidal map (80 % rule; \
             iterative: over 1024 lines) covered by the focus region, n to n\u{a0}+\u{a0}δ, for \
             light directions over the hemisphere (a; rings at 10°, 20°, 30°, 60°) and in the \
             view's vertical plane (b). n\u{a0}=\u{a0}{n}, f\u{a0}=\u{a0}{f}, \
             θ\u{a0}=\u{a0}{theta:.0}°, δ\u{a0}=\u{a0}{FOCUS}. {JUMP_GLYPH}: light exactly \
             behind or in front, {dueling:.4}.",
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

    /// One column: the hemisphere with its bar over the profile.
    fn single_size(&self) -> Option<(u32, u32)> {
        Some((Column::Single.width(), 760))
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption: Vec<&str> = self.caption.iter().map(String::as_str).collect();
        let body = frame(
            root,
            "Area of the focus region in the trapezoidal map",
            &caption,
        )?;
        let (w, h) = body.dim_in_pixel();
        // Two columns: the hemisphere with its bar on the left, the profile beside it (issue
        // 35: stacked, the figure was 928 units tall); one column: the profile under them.
        let (left, right) = match column() {
            Column::Double => body.split_horizontally(w * 27 / 50),
            Column::Single => body.split_vertically(h * 47 / 100),
        };
        let (w, _) = left.dim_in_pixel();
        let (disk, bar) = left.split_horizontally(w.saturating_sub(BAR_WIDTH));
        let rows = draw_hemisphere(&disk, "(a) over the hemisphere", &self.grid, &self.scale)?;
        draw_bar(&bar, &self.scale, rows)?;
        draw_line_chart(&right, &self.profile)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The caption's marker claim is what the profile draws (figure review: it said
    /// "markers: exactly behind and in front" while the lines carry markers all along). Read
    /// back from the profile's SVG: exactly two polygons are diamonds (four corners, the top
    /// and bottom on one vertical, the left and right on one horizontal), the shape the
    /// caption names, at the plot's left and right ends (0° and 180°) and at one height (the
    /// same share, ((n + δ)/f)² = (11/100)² = 0.0121 by hand, which the caption prints); the
    /// lines' own markers are other shapes.
    #[test]
    fn the_caption_names_the_marks_exactly_behind_and_in_front() {
        use super::super::chart::read_svg::draw_svg;
        let fig = fig6().map_err(|e| e.named("martin-tan-fig6")).unwrap();
        let caption = fig.caption.join(" ");
        assert!(
            caption.contains("◆: light exactly behind or in front, 0.0121."),
            "{caption}"
        );
        let svg = draw_svg((300, 300), |area| {
            draw_line_chart(area, &fig.profile).unwrap();
        });
        let polygons: Vec<Vec<(f64, f64)>> = svg
            .lines()
            .filter(|l| l.starts_with("<polygon"))
            .map(|l| {
                let at = l.find("points=\"").unwrap() + 8;
                l[at..at + l[at..].find('"').unwrap()]
                    .split_whitespace()
                    .map(|p| {
                        let (x, y) = p.split_once(',').unwrap();
                        (x.parse().unwrap(), y.parse().unwrap())
                    })
                    .collect()
            })
            .collect();
        let diamond = |p: &Vec<(f64, f64)>| {
            p.len() == 4
                && (p[0].0 - p[2].0).abs() < 0.01
                && (p[1].1 - p[3].1).abs() < 0.01
                && (p[0].1 - p[1].1).abs() > 1.0
        };
        let diamonds: Vec<(f64, f64)> = polygons
            .iter()
            .filter(|p| diamond(p))
            .map(|p| (p[0].0, p[1].1))
            .collect();
        assert_eq!(diamonds.len(), 2, "{diamonds:?}");
        assert!(polygons.len() > 4, "the lines carry markers of their own");
        // The plot's ends: the leftmost and rightmost points of the 80 % rule's line (blue,
        // hundreds of points; the legend's sample has two).
        let xs: Vec<f64> = svg
            .lines()
            .filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#0072B2\""))
            .filter(|l| l.matches(',').count() > 50)
            .flat_map(|l| {
                let at = l.find("points=\"").unwrap() + 8;
                l[at..at + l[at..].find('"').unwrap()]
                    .split_whitespace()
                    .map(|p| p.split_once(',').unwrap().0.parse::<f64>().unwrap())
                    .collect::<Vec<_>>()
            })
            .collect();
        let (left, right) = (
            xs.iter().copied().fold(f64::INFINITY, f64::min),
            xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        );
        let (a, b) = (diamonds[0], diamonds[1]);
        assert!(
            (a.0 - left).abs() < 1.0 && (b.0 - right).abs() < 1.0,
            "{diamonds:?} {left} {right}"
        );
        assert!((a.1 - b.1).abs() < 0.01, "{diamonds:?}");
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
