//! Heat maps: quantised colour scales, rectangular and hemispherical grids, colour bars.

use super::super::Fail;
use super::axis::{Axis, Chart2d, Ticked};
use super::raster::draw_cells;
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// A colour scale: a value range on an axis (linear or logarithmic), quantised into `levels`
/// bands of the viridis colour map (dark blue low, yellow high: perceptually uniform, and
/// readable in grey and by colour-blind readers).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ColourScale {
    pub axis: Axis,
    pub levels: usize,
}

/// Bands of a smooth colour scale: neighbouring bands of viridis differ by less than the eye
/// resolves, so the map reads as continuous, while runs of equal cells still merge in the SVG.
pub(crate) const SMOOTH_LEVELS: usize = 96;

impl ColourScale {
    /// A smooth scale over `axis`.
    pub fn smooth(axis: Axis) -> Self {
        Self {
            axis,
            levels: SMOOTH_LEVELS,
        }
    }

    /// The band of a value, clamped to the range; `None` where the value cannot be shown.
    pub fn level(&self, v: f64) -> Option<usize> {
        let a = self.axis.to_axis(v)?;
        let (lo, hi) = self.axis.range();
        let t = if hi > lo {
            ((a - lo) / (hi - lo)).clamp(0.0, 1.0)
        } else {
            0.5
        };
        Some(((t * self.levels as f64) as usize).min(self.levels - 1))
    }

    /// The colour of a band.
    pub fn level_colour(&self, level: usize) -> RGBColor {
        viridis((level as f64 + 0.5) / self.levels as f64)
    }
}

/// matplotlib's viridis at t = 0, 1/9, …, 1 (its ten-colour table, #440154 … #fde725).
const VIRIDIS: [(u8, u8, u8); 10] = [
    (0x44, 0x01, 0x54),
    (0x48, 0x28, 0x78),
    (0x3e, 0x49, 0x89),
    (0x31, 0x68, 0x8e),
    (0x26, 0x82, 0x8e),
    (0x1f, 0x9e, 0x89),
    (0x35, 0xb7, 0x79),
    (0x6e, 0xce, 0x58),
    (0xb5, 0xde, 0x2b),
    (0xfd, 0xe7, 0x25),
];

/// The viridis colour map at t ∈ [0, 1] (linear between the ten samples).
pub(crate) fn viridis(t: f64) -> RGBColor {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (VIRIDIS.len() - 1) as f64;
    let i = (x.floor() as usize).min(VIRIDIS.len() - 2);
    let f = x - i as f64;
    let (a, b) = (VIRIDIS[i], VIRIDIS[i + 1]);
    let mix = |p: u8, q: u8| (f64::from(p) + f * (f64::from(q) - f64::from(p))).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// A field on a rectangular grid: `values[j * nx + i]` for the cell `[x_i, x_{i+1}] ×
/// [y_j, y_{j+1}]` in data coordinates, cut to the convex region `clip` (half-planes
/// `a x + b y ≤ c`; none: the whole rectangle); `None` cells are left blank.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Grid {
    pub x_edges: Vec<f64>,
    pub y_edges: Vec<f64>,
    pub values: Vec<Option<f64>>,
    pub clip: Vec<(f64, f64, f64)>,
}

/// Cuts a convex polygon to the half-plane `a x + b y ≤ c` (Sutherland–Hodgman).
fn cut(poly: &[(f64, f64)], (a, b, c): (f64, f64, f64)) -> Vec<(f64, f64)> {
    let d = |p: (f64, f64)| a * p.0 + b * p.1 - c;
    let mut out = Vec::with_capacity(poly.len() + 1);
    for k in 0..poly.len() {
        let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
        let (dp, dq) = (d(p), d(q));
        if dp <= 0.0 {
            out.push(p);
        }
        if (dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0) {
            let t = dp / (dp - dq);
            out.push((p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1)));
        }
    }
    out
}

/// The area and centroid of a simple polygon (shoelace).
fn area_centroid(poly: &[(f64, f64)]) -> (f64, (f64, f64)) {
    let (mut a, mut cx, mut cy) = (0.0, 0.0, 0.0);
    for k in 0..poly.len() {
        let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
        let w = p.0 * q.1 - q.0 * p.1;
        a += w;
        cx += (p.0 + q.0) * w;
        cy += (p.1 + q.1) * w;
    }
    if a.abs() < 1e-300 {
        return (0.0, (f64::NAN, f64::NAN));
    }
    (0.5 * a.abs(), (cx / (3.0 * a), cy / (3.0 * a)))
}

impl Grid {
    /// Evaluates `f` at each cell centre of an `nx × ny` grid over `[x0, x1] × [y0, y1]`.
    #[cfg(test)]
    pub fn sample(
        x: (f64, f64, usize),
        y: (f64, f64, usize),
        f: impl FnMut(f64, f64) -> Option<f64>,
    ) -> Self {
        Self::sample_clipped(x, y, Vec::new(), f)
    }

    /// As [`Grid::sample`], with each cell cut to the region `clip` and `f` evaluated at the
    /// centroid of what is left (cells outside the region are blank), so that the cells along a
    /// slanted border follow it and the first cells sample the region's edge, not a centre
    /// half a cell away.
    pub fn sample_clipped(
        (x0, x1, nx): (f64, f64, usize),
        (y0, y1, ny): (f64, f64, usize),
        clip: Vec<(f64, f64, f64)>,
        mut f: impl FnMut(f64, f64) -> Option<f64>,
    ) -> Self {
        let x_edges: Vec<f64> = (0..=nx)
            .map(|i| x0 + (x1 - x0) * i as f64 / nx as f64)
            .collect();
        let y_edges: Vec<f64> = (0..=ny)
            .map(|j| y0 + (y1 - y0) * j as f64 / ny as f64)
            .collect();
        let mut grid = Self {
            x_edges,
            y_edges,
            values: Vec::with_capacity(nx * ny),
            clip,
        };
        for j in 0..ny {
            for i in 0..nx {
                let v = grid
                    .sample_point(i, j)
                    .and_then(|(x, y)| f(x, y))
                    .filter(|v| v.is_finite());
                grid.values.push(v);
            }
        }
        grid
    }

    /// The cell `(i, j)` cut to the clip region (its four corners when nothing is cut), and
    /// whether it was cut.
    pub fn cell(&self, i: usize, j: usize) -> (Vec<(f64, f64)>, bool) {
        let (xa, xb) = (self.x_edges[i], self.x_edges[i + 1]);
        let (ya, yb) = (self.y_edges[j], self.y_edges[j + 1]);
        let rect = vec![(xa, ya), (xb, ya), (xb, yb), (xa, yb)];
        let inside = |p: &(f64, f64)| self.clip.iter().all(|h| h.0 * p.0 + h.1 * p.1 <= h.2);
        if rect.iter().all(inside) {
            return (rect, false);
        }
        let mut poly = rect;
        for &h in &self.clip {
            poly = cut(&poly, h);
            if poly.len() < 3 {
                return (Vec::new(), true);
            }
        }
        (poly, true)
    }

    /// Where the cell `(i, j)` is sampled: the centroid of its part inside the clip region;
    /// `None` when nothing of it is inside.
    pub fn sample_point(&self, i: usize, j: usize) -> Option<(f64, f64)> {
        let (poly, _) = self.cell(i, j);
        if poly.len() < 3 {
            return None;
        }
        let (area, c) = area_centroid(&poly);
        (area > 0.0 && c.0.is_finite() && c.1.is_finite()).then_some(c)
    }
}

/// Draws a grid into a chart whose axes are linear in the grid's coordinates. Runs of
/// neighbouring whole cells in one row that fall in the same colour band are merged into one
/// rectangle, which keeps the SVG small; cells cut by the clip region are drawn as the
/// polygons they are, so that a slanted border is straight, not stair-stepped.
pub(crate) fn draw_grid<DB: DrawingBackend>(
    chart: &mut Chart2d<'_, DB>,
    grid: &Grid,
    scale: &ColourScale,
) -> Result<(), Fail> {
    let nx = grid.x_edges.len() - 1;
    let ny = grid.y_edges.len() - 1;
    // Cells in the plotting area's pixels.
    let base = chart.plotting_area().get_base_pixel();
    let px = |(x, y): (f64, f64)| {
        let (u, v) = chart.backend_coord(&(x, y));
        (f64::from(u - base.0), f64::from(v - base.1))
    };
    let mut cells = Vec::new();
    let level_at = |i: usize, j: usize| grid.values[j * nx + i].and_then(|v| scale.level(v));
    for j in 0..ny {
        let mut i = 0;
        while i < nx {
            let Some(level) = level_at(i, j) else {
                i += 1;
                continue;
            };
            let (poly, was_cut) = grid.cell(i, j);
            if was_cut {
                if poly.len() >= 3 {
                    let poly = poly.into_iter().map(px).collect();
                    cells.push((poly, scale.level_colour(level)));
                }
                i += 1;
                continue;
            }
            let start = i;
            while i + 1 < nx && level_at(i + 1, j) == Some(level) && !grid.cell(i + 1, j).1 {
                i += 1;
            }
            let (xa, xb) = (grid.x_edges[start], grid.x_edges[i + 1]);
            let (ya, yb) = (grid.y_edges[j], grid.y_edges[j + 1]);
            let rect = [(xa, ya), (xb, ya), (xb, yb), (xa, yb)];
            cells.push((
                rect.into_iter().map(px).collect(),
                scale.level_colour(level),
            ));
            i += 1;
        }
    }
    draw_cells(&chart.plotting_area().strip_coord_spec(), &cells)
}

/// A field over the hemisphere of light directions: `values[i * n_az + j]` for the cell between
/// elevations `elev_edges[i]..elev_edges[i+1]` and azimuths `az_edges[j]..az_edges[j+1]`
/// (radians; elevation 0 at the horizon, π/2 overhead; azimuth 0 behind the viewer, π in front).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PolarGrid {
    pub elev_edges: Vec<f64>,
    pub az_edges: Vec<f64>,
    pub values: Vec<Option<f64>>,
}

/// Where a light direction lands in the hemisphere disk: the hemisphere seen from above
/// (orthographic), overhead at the centre, the source behind the viewer on the left (−x), in
/// front on the right (+x), and to the viewer's right (azimuth π/2, eye-space +X) at the bottom,
/// as a map seen from above with the viewer facing right. Azimuth and elevation as in
/// [`crate::scheme::sweep`]: the source lies towards (cos el · sin az, sin el, cos el · cos az).
pub(crate) fn hemisphere_xy(elevation: f64, azimuth: f64) -> (f64, f64) {
    let r = elevation.cos();
    (-r * azimuth.cos(), -r * azimuth.sin())
}

/// Draws a hemisphere panel: a disk of radius 1 with the field, elevation rings every 30°, and
/// the directions named. Runs of cells in one elevation ring that fall in the same colour band
/// are merged into one polygon.
pub(crate) fn draw_hemisphere<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    grid: &PolarGrid,
    scale: &ColourScale,
) -> Result<(), Fail> {
    let (w, h) = area.dim_in_pixel();
    // Square plotting area centred in the panel.
    let title_h = 28;
    let side = (w.min(h.saturating_sub(title_h))).max(40) as i32;
    let ox = (w as i32 - side) / 2;
    let oy = title_h as i32 + (h as i32 - title_h as i32 - side) / 2;
    area.draw(&Text::new(
        title.to_string(),
        (w as i32 / 2, 4),
        TextStyle::from((FONT, 16).into_font()).pos(Pos::new(HPos::Center, VPos::Top)),
    ))?;
    let pad = 0.16;
    let to_px = |(x, y): (f64, f64)| -> (i32, i32) {
        let u = (x + 1.0 + pad) / (2.0 + 2.0 * pad);
        let v = (1.0 + pad - y) / (2.0 + 2.0 * pad);
        (
            ox + (u * side as f64).round() as i32,
            oy + (v * side as f64).round() as i32,
        )
    };
    let n_el = grid.elev_edges.len() - 1;
    let n_az = grid.az_edges.len() - 1;
    const OVERLAP: f64 = 0.25 * std::f64::consts::PI / 180.0;
    let arc = |el: f64, a0: f64, a1: f64, reverse: bool| -> Vec<(i32, i32)> {
        let steps = (((a1 - a0).abs() / 4f64.to_radians()).ceil() as usize).max(1);
        let mut v: Vec<(i32, i32)> = (0..=steps)
            .map(|k| {
                let a = a0 + (a1 - a0) * k as f64 / steps as f64;
                to_px(hemisphere_xy(el, a))
            })
            .collect();
        if reverse {
            v.reverse();
        }
        v
    };
    let mut cells = Vec::new();
    for i in 0..n_el {
        let (e0, e1) = (grid.elev_edges[i], grid.elev_edges[i + 1]);
        let mut j = 0;
        while j < n_az {
            let Some(level) = grid.values[i * n_az + j].and_then(|v| scale.level(v)) else {
                j += 1;
                continue;
            };
            let start = j;
            while j + 1 < n_az
                && grid.values[i * n_az + j + 1].and_then(|v| scale.level(v)) == Some(level)
            {
                j += 1;
            }
            // A hair of overlap (0.25°) so that neighbouring polygons leave no unfilled pixels.
            let (a0, a1) = if start == 0 && j + 1 == n_az {
                // A whole ring: exactly one turn, or the polygon would overlap itself at the
                // seam and the overlap would be left unfilled.
                (grid.az_edges[0], grid.az_edges[0] + std::f64::consts::TAU)
            } else {
                (
                    grid.az_edges[start] - OVERLAP,
                    grid.az_edges[j + 1] + OVERLAP,
                )
            };
            let lo = (e0 - OVERLAP).max(0.0);
            let hi = (e1 + OVERLAP).min(std::f64::consts::FRAC_PI_2);
            let mut poly = arc(lo, a0, a1, false);
            poly.extend(arc(hi, a0, a1, true));
            poly.dedup();
            let poly = poly
                .into_iter()
                .map(|(x, y)| (f64::from(x), f64::from(y)))
                .collect();
            cells.push((poly, scale.level_colour(level)));
            j += 1;
        }
    }
    draw_cells(area, &cells)?;
    // Elevation rings at 0°, 30°, 60° and the axis from behind to in front (the vertical plane
    // through the view direction).
    let ring_style = ShapeStyle {
        color: RGBColor(60, 60, 60).to_rgba(),
        filled: false,
        stroke_width: 1,
    };
    for deg in [0.0f64, 30.0, 60.0] {
        let mut ring = arc(deg.to_radians(), 0.0, std::f64::consts::TAU, false);
        ring.push(ring[0]);
        area.draw(&PathElement::new(ring, ring_style))?;
    }
    // A finer grid near the rim, where the horizon band is squeezed: rings at 10° and 20°.
    for deg in [10.0f64, 20.0] {
        let mut ring = arc(deg.to_radians(), 0.0, std::f64::consts::TAU, false);
        ring.push(ring[0]);
        area.draw(&PathElement::new(
            ring,
            ShapeStyle {
                color: RGBColor(60, 60, 60).mix(0.45),
                ..ring_style
            },
        ))?;
    }
    area.draw(&PathElement::new(
        vec![to_px((-1.0, 0.0)), to_px((1.0, 0.0))],
        ShapeStyle {
            color: RGBColor(60, 60, 60).mix(0.5),
            filled: false,
            stroke_width: 1,
        },
    ))?;
    let label = |text: &str, at: (f64, f64), pos: Pos| {
        area.draw(&Text::new(
            text.to_string(),
            to_px(at),
            TextStyle::from((FONT, 13).into_font()).pos(pos),
        ))
    };
    label("← behind", (-1.0, 0.97), Pos::new(HPos::Left, VPos::Top))?;
    label("in front →", (1.0, 0.97), Pos::new(HPos::Right, VPos::Top))?;
    label(
        "viewer's right",
        (0.0, -1.02),
        Pos::new(HPos::Center, VPos::Top),
    )?;
    label(
        "overhead",
        (0.0, 0.03),
        Pos::new(HPos::Center, VPos::Bottom),
    )?;
    label("30°", (0.02, 0.87), Pos::new(HPos::Left, VPos::Bottom))?;
    label("60°", (0.02, 0.5), Pos::new(HPos::Left, VPos::Bottom))?;
    Ok(())
}

/// The length of a colour bar's tick marks, in pixels; its labels start twice that from the bar.
pub(crate) const COLOUR_BAR_TICK: i32 = 5;

/// Draws a vertical colour bar for `scale` into `area`.
pub(crate) fn draw_colour_bar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    scale: &ColourScale,
) -> Result<(), Fail> {
    let (lo, hi) = scale.axis.range();
    let (yb, _) = scale.axis.ticks();
    let mut chart = ChartBuilder::on(area)
        .margin_top(30)
        .margin_bottom(30)
        .margin_right(6)
        .y_label_area_size(0)
        .right_y_label_area_size(62)
        .build_cartesian_2d(
            Ticked::new(0.0, 1.0, vec![], vec![]),
            Ticked::new(lo, hi, yb, vec![]),
        )?;
    let yf = |v: &f64| scale.axis.tick_label(*v);
    chart
        .configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .y_desc(scale.axis.label.as_str())
        .y_label_formatter(&yf)
        // Tick marks 5 px long outside the bar, the labels twice that from it (plotters' own
        // default put them about 3 px from the bar's edge).
        .set_tick_mark_size(LabelAreaPosition::Right, COLOUR_BAR_TICK)
        .axis_desc_style((FONT, 14))
        .label_style((FONT, 13))
        .draw()?;
    let n = scale.levels;
    chart.draw_series((0..n).map(|k| {
        let a = lo + (hi - lo) * k as f64 / n as f64;
        let b = lo + (hi - lo) * (k + 1) as f64 / n as f64;
        Rectangle::new([(0.0, a), (1.0, b)], scale.level_colour(k).filled())
    }))?;
    chart.draw_series(std::iter::once(Rectangle::new(
        [(0.0, lo), (1.0, hi)],
        RGBColor(60, 60, 60).stroke_width(1),
    )))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colour_scale_bands_clamp_and_are_ordered() {
        let s = ColourScale {
            axis: Axis::log10("S", 1.0, 1000.0),
            levels: 30,
        };
        assert_eq!(s.level(1.0), Some(0));
        assert_eq!(s.level(1000.0), Some(29));
        assert_eq!(s.level(1e9), Some(29));
        assert_eq!(s.level(0.5), Some(0));
        assert_eq!(s.level(-1.0), None);
        assert_eq!(s.level(10f64.powf(1.5)), Some(15));
        // Viridis: matplotlib's end colours #440154 and #fde725, and its lightness rises
        // monotonically (relative luminance, WCAG's formula, computed here).
        assert_eq!(viridis(0.0), RGBColor(0x44, 0x01, 0x54));
        assert_eq!(viridis(1.0), RGBColor(0xfd, 0xe7, 0x25));
        let lum = |c: RGBColor| {
            let lin = |u: u8| {
                let v = f64::from(u) / 255.0;
                if v <= 0.04045 {
                    v / 12.92
                } else {
                    ((v + 0.055) / 1.055).powf(2.4)
                }
            };
            0.2126 * lin(c.0) + 0.7152 * lin(c.1) + 0.0722 * lin(c.2)
        };
        let ls: Vec<f64> = (0..=200).map(|k| lum(viridis(k as f64 / 200.0))).collect();
        assert!(
            ls.windows(2).all(|w| w[1] >= w[0]),
            "lightness not monotonic"
        );
        // plotters' own viridis table (eight samples) at t = 2/7: (54, 92, 141).
        let c = viridis(2.0 / 7.0);
        assert!(
            c.0.abs_diff(54) <= 2 && c.1.abs_diff(92) <= 2 && c.2.abs_diff(141) <= 2,
            "{c:?}"
        );
    }

    /// A 2 × 2 grid over [0, 2]² cut to y ≤ x: the diagonal cells become the triangles below
    /// the diagonal, sampled at their centroids (2/3, 1/3) and (5/3, 4/3); the cell above it
    /// is blank, the one below whole.
    #[test]
    fn clipped_cells_follow_the_border_and_sample_their_centroid() {
        let g = Grid::sample_clipped(
            (0.0, 2.0, 2),
            (0.0, 2.0, 2),
            vec![(-1.0, 1.0, 0.0)],
            |x, y| Some(x + 10.0 * y),
        );
        let (p, cut0) = g.cell(0, 0);
        assert!(cut0 && p.len() == 3);
        let c = g.sample_point(0, 0).unwrap();
        assert!((c.0 - 2.0 / 3.0).abs() < 1e-12 && (c.1 - 1.0 / 3.0).abs() < 1e-12);
        let c = g.sample_point(1, 1).unwrap();
        assert!((c.0 - 5.0 / 3.0).abs() < 1e-12 && (c.1 - 4.0 / 3.0).abs() < 1e-12);
        assert_eq!(g.values[2], None, "cell (0, 1) lies above y = x");
        assert_eq!(
            g.cell(1, 0),
            (vec![(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)], false)
        );
        assert_eq!(g.values[1], Some(1.5 + 5.0));
    }

    #[test]
    fn hemisphere_layout_puts_behind_left_and_overhead_centre() {
        let (x, y) = hemisphere_xy(0.0, 0.0);
        assert!((x + 1.0).abs() < 1e-15 && y.abs() < 1e-15);
        let (x, _) = hemisphere_xy(0.0, std::f64::consts::PI);
        assert!((x - 1.0).abs() < 1e-15);
        let (x, y) = hemisphere_xy(std::f64::consts::FRAC_PI_2, 1.0);
        assert!(x.abs() < 1e-15 && y.abs() < 1e-15);
        // The source on the viewer's right is drawn below the behind–front axis.
        let (x, y) = hemisphere_xy(0.0, std::f64::consts::FRAC_PI_2);
        assert!(x.abs() < 1e-15 && (y + 1.0).abs() < 1e-15);
    }
}
