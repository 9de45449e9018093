//! Heat maps: quantised colour scales, rectangular and hemispherical grids, colour bars.

use super::super::Fail;
use super::axis::{Axis, Chart2d, PANEL_TITLE};
use super::colour_map::{diverging, diverging_position};
use super::raster::Raster;
use super::ColourMap;
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// A colour scale: a value range on an axis (linear or logarithmic), quantised into `levels`
/// bands of a colour map ([`ColourMap`]: viridis, dark blue low, yellow high, for a quantity;
/// a diverging map for a ratio).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ColourScale {
    pub axis: Axis,
    pub levels: usize,
    pub map: ColourMap,
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
            map: ColourMap::Viridis,
        }
    }

    /// A smooth diverging scale over `axis`, neutral at the value `centre` (1 for a ratio).
    pub fn diverging(axis: Axis, centre: f64) -> Self {
        let centre = axis.to_axis(centre).unwrap_or(0.0);
        Self {
            axis,
            levels: SMOOTH_LEVELS,
            map: ColourMap::Diverging { centre },
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
        let t = (level as f64 + 0.5) / self.levels as f64;
        match self.map {
            ColourMap::Viridis => viridis(t),
            ColourMap::Diverging { centre } => {
                let (lo, hi) = self.axis.range();
                let c = if hi > lo {
                    (centre - lo) / (hi - lo)
                } else {
                    0.5
                };
                diverging(diverging_position(t, c))
            }
        }
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

/// The index of the cell `[edges[i], edges[i+1]]` holding `v` (edges increasing or
/// decreasing), or `None` outside them.
fn cell_index(edges: &[f64], v: f64) -> Option<usize> {
    let n = edges.len().checked_sub(1)?;
    let (lo, hi) = (edges[0].min(edges[n]), edges[0].max(edges[n]));
    if n == 0 || !(lo..=hi).contains(&v) {
        return None;
    }
    let i = if edges[0] <= edges[n] {
        edges.partition_point(|&e| e <= v)
    } else {
        edges.partition_point(|&e| e >= v)
    };
    Some(i.saturating_sub(1).min(n - 1))
}

/// Draws a grid into a chart whose axes are linear in the grid's coordinates, as one raster
/// ([`Raster`]): each sample takes the colour of the cell it falls in, and is transparent
/// outside the grid or its clip region, so that a slanted border is cut, not stair-stepped.
pub(crate) fn draw_grid<DB: DrawingBackend>(
    chart: &mut Chart2d<'_, DB>,
    grid: &Grid,
    scale: &ColourScale,
) -> Result<(), Fail> {
    let nx = grid.x_edges.len().saturating_sub(1);
    let (Some(&gx0), Some(&gx1), Some(&gy0), Some(&gy1)) = (
        grid.x_edges.first(),
        grid.x_edges.last(),
        grid.y_edges.first(),
        grid.y_edges.last(),
    ) else {
        return Ok(());
    };
    // The plotting area's units against the data (both axes linear): two corners fix the map.
    let base = chart.plotting_area().get_base_pixel();
    let unit = |(x, y): (f64, f64)| {
        let (u, v) = chart.backend_coord(&(x, y));
        (f64::from(u - base.0), f64::from(v - base.1))
    };
    let (a, b) = (unit((gx0, gy0)), unit((gx1, gy1)));
    if a.0 == b.0 || a.1 == b.1 {
        return Ok(());
    }
    let to_data = |u: f64, v: f64| {
        (
            gx0 + (u - a.0) / (b.0 - a.0) * (gx1 - gx0),
            gy0 + (v - a.1) / (b.1 - a.1) * (gy1 - gy0),
        )
    };
    let colour_at = |u: f64, v: f64| {
        let (x, y) = to_data(u, v);
        if !grid.clip.iter().all(|h| h.0 * x + h.1 * y <= h.2) {
            return None;
        }
        let (i, j) = (cell_index(&grid.x_edges, x)?, cell_index(&grid.y_edges, y)?);
        let level = grid.values[j * nx + i].and_then(|v| scale.level(v))?;
        Some(scale.level_colour(level))
    };
    let (w, h) = chart.plotting_area().dim_in_pixel();
    let bbox = (
        (a.0.min(b.0).floor() as i32).max(0),
        (a.1.min(b.1).floor() as i32).max(0),
        (a.0.max(b.0).ceil() as i32).min(w as i32),
        (a.1.max(b.1).ceil() as i32).min(h as i32),
    );
    Raster::sample(bbox, colour_at).draw(&chart.plotting_area().strip_coord_spec())
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

/// The distance from the disk's centre of the light directions at `elevation` (radians): the
/// azimuthal equidistant projection, 1 at the horizon, 0 overhead, linear in between, so that
/// every 10° of elevation is a ring of the same width (the orthographic view from above
/// squeezed the horizon band, where the storage factor changes the most, into the outer 13 % of
/// the radius).
pub(crate) fn hemisphere_radius(elevation: f64) -> f64 {
    1.0 - elevation / std::f64::consts::FRAC_PI_2
}

/// Where a light direction lands in the hemisphere disk (radius 1): the hemisphere seen from
/// above in the azimuthal equidistant projection ([`hemisphere_radius`]), overhead at the
/// centre, the source behind the viewer on the left (−x), in front on the right (+x), and to
/// the viewer's right (azimuth π/2, eye-space +X) at the bottom, as a map seen from above with
/// the viewer facing right. Azimuth and elevation as in [`crate::scheme::sweep`]: the source
/// lies towards (cos el · sin az, sin el, cos el · cos az).
pub(crate) fn hemisphere_xy(elevation: f64, azimuth: f64) -> (f64, f64) {
    let r = hemisphere_radius(elevation);
    (-r * azimuth.cos(), -r * azimuth.sin())
}

/// The light direction (elevation, azimuth in `[0, 2π)`) drawn at `(x, y)` of the disk; `None`
/// outside it. The inverse of [`hemisphere_xy`].
pub(crate) fn hemisphere_direction(x: f64, y: f64) -> Option<(f64, f64)> {
    let r = x.hypot(y);
    if r > 1.0 {
        return None;
    }
    let elevation = (1.0 - r) * std::f64::consts::FRAC_PI_2;
    let azimuth = (-y).atan2(-x).rem_euclid(std::f64::consts::TAU);
    Some((elevation, azimuth))
}

/// The square of a hemisphere panel `w` × `h` units (its left, top and side): centred under a
/// title 28 units tall.
fn hemisphere_square(w: u32, h: u32) -> (i32, i32, i32) {
    let title_h = 28;
    let side = (w.min(h.saturating_sub(title_h))).max(40) as i32;
    let ox = (w as i32 - side) / 2;
    let oy = title_h as i32 + (h as i32 - title_h as i32 - side) / 2;
    (ox, oy, side)
}

/// The margin round a hemisphere's disk inside its square, in disk radii.
const DISK_PAD: f64 = 0.16;

/// Where [`draw_hemisphere_keyed`] draws the disk of a panel `w` × `h` units: its centre and
/// its radius (units of the panel's area), so that a figure can draw over the field (contour
/// lines) in the disk's coordinates.
pub(crate) fn hemisphere_disk(w: u32, h: u32) -> ((f64, f64), f64) {
    let (ox, oy, side) = hemisphere_square(w, h);
    let half = 0.5 * f64::from(side);
    (
        (f64::from(ox) + half, f64::from(oy) + half),
        f64::from(side) / (2.0 + 2.0 * DISK_PAD),
    )
}

/// Draws a hemisphere panel: a disk of radius 1 with the field (one raster, transparent outside
/// the disk), the elevation rings ([`super::hemisphere_key::draw_rings`]) and the directions
/// named. Returns the rows of the disk's top and bottom in
/// `area` (for a colour bar as tall as the disk).
#[cfg(test)]
pub(crate) fn draw_hemisphere<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    grid: &PolarGrid,
    scale: &ColourScale,
) -> Result<(u32, u32), Fail> {
    draw_hemisphere_keyed(area, title, grid, scale, false, true)
}

/// [`draw_hemisphere`], with the rings' elevations written in the disk where `key`
/// ([`super::hemisphere_key`]): a figure keys one of its panels, so that without its caption it
/// still says what the rings and the centre are; the horizontal diameter (the vertical plane
/// through the view direction) drawn where `diameter`.
pub(crate) fn draw_hemisphere_keyed<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    grid: &PolarGrid,
    scale: &ColourScale,
    key: bool,
    diameter: bool,
) -> Result<(u32, u32), Fail> {
    let dark = super::hemisphere_key::RINGS_DARK;
    draw_hemisphere_ringed(area, title, grid, scale, key, diameter, dark)
}

/// [`draw_hemisphere_keyed`] with its rings and diameter drawn in `rings`.
pub(crate) fn draw_hemisphere_ringed<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    grid: &PolarGrid,
    scale: &ColourScale,
    key: bool,
    diameter: bool,
    rings: super::hemisphere_key::RingStyle,
) -> Result<(u32, u32), Fail> {
    let (w, h) = area.dim_in_pixel();
    let (ox, oy, side) = hemisphere_square(w, h);
    area.draw(&Text::new(
        title.to_string(),
        (w as i32 / 2, 4),
        TextStyle::from((FONT, PANEL_TITLE).into_font()).pos(Pos::new(HPos::Center, VPos::Top)),
    ))?;
    let pad = DISK_PAD;
    let span = 2.0 + 2.0 * pad;
    let to_units = |(x, y): (f64, f64)| -> (f64, f64) {
        (
            f64::from(ox) + (x + 1.0 + pad) / span * f64::from(side),
            f64::from(oy) + (1.0 + pad - y) / span * f64::from(side),
        )
    };
    let to_px = |p: (f64, f64)| -> (i32, i32) {
        let (u, v) = to_units(p);
        (u.round() as i32, v.round() as i32)
    };
    let n_az = grid.az_edges.len().saturating_sub(1);
    let a0 = grid.az_edges.first().copied().unwrap_or(0.0);
    let colour_at = |u: f64, v: f64| {
        let x = (u - f64::from(ox)) / f64::from(side) * span - 1.0 - pad;
        let y = 1.0 + pad - (v - f64::from(oy)) / f64::from(side) * span;
        let (el, az) = hemisphere_direction(x, y)?;
        let i = cell_index(&grid.elev_edges, el)?;
        // Azimuths wrap: the first cell starts half a cell before 0.
        let j = cell_index(
            &grid.az_edges,
            a0 + (az - a0).rem_euclid(std::f64::consts::TAU),
        )?;
        let level = grid.values[i * n_az + j].and_then(|v| scale.level(v))?;
        Some(scale.level_colour(level))
    };
    let (left, top) = to_px((-1.0, 1.0));
    let (right, bottom) = to_px((1.0, -1.0));
    // A key disk has no data: no (blank) raster for it.
    if grid.values.iter().any(Option::is_some) {
        Raster::sample((left - 1, top - 1, right + 1, bottom + 1), colour_at).draw(area)?;
    }
    // Rings and the diameter at sub-unit positions (absolute backend units), so that they are
    // round, not stepped.
    let base = area.get_base_pixel();
    let abs = |p: (f64, f64)| {
        let (u, v) = to_units(p);
        (u + f64::from(base.0), v + f64::from(base.1))
    };
    let gaps = if key {
        super::hemisphere_key::key_boxes(area, to_px)?
    } else {
        Vec::new()
    };
    super::hemisphere_key::draw_rings(area, &abs, diameter, &gaps, rings)?;
    let style = TextStyle::from((FONT, 13).into_font());
    let label = |text: &str, at: (f64, f64), pos: Pos| {
        area.draw(&Text::new(text.to_string(), to_px(at), style.pos(pos)))
    };
    // In the square's top corners, clear of the rim (at 0.97 they touched it); where the
    // disk is narrower than the two labels and 12 units between them, at the panel's corners.
    let width = |t: &str| area.estimate_text_size(t, &style).map(|s| s.0 as i32);
    let (wb, wf) = (width("← behind")?, width("in front →")?);
    let (_, label_y) = to_px((0.0, 1.14));
    let (mut lx, mut rx, mut v) = (left, right, (label_y, VPos::Top));
    if wb + wf + 12 > right - left {
        let spare = (w as i32 - wb - wf - 12).max(0);
        lx = spare / 2;
        rx = w as i32 - spare / 2;
        // Across the disk's top, ending 2 units above its rim (hanging from 1.14 they reached
        // into a small disk).
        let (_, rim) = to_px((0.0, 1.0));
        v = (rim - 2, VPos::Bottom);
    }
    area.draw(&Text::new(
        "← behind",
        (lx, v.0),
        style.pos(Pos::new(HPos::Left, v.1)),
    ))?;
    area.draw(&Text::new(
        "in front →",
        (rx, v.0),
        style.pos(Pos::new(HPos::Right, v.1)),
    ))?;
    label(
        "viewer's right",
        (0.0, -1.02),
        Pos::new(HPos::Center, VPos::Top),
    )?;
    if key {
        super::hemisphere_key::draw_ring_key(area, to_px)?;
    }
    Ok((top.max(0) as u32, bottom.max(0) as u32))
}

#[cfg(test)]
mod tests {
    use super::super::hemisphere_key::RINGS;
    use super::super::read_svg::{attr, draw_svg, embedded_images, visible, Image};
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    #[test]
    fn colour_scale_bands_clamp_and_are_ordered() {
        let s = ColourScale {
            axis: Axis::log10("S", 1.0, 1000.0),
            levels: 30,
            map: ColourMap::Viridis,
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
        // Azimuthal equidistant: 30° of elevation is a third of the radius in from the rim
        // (orthographic: cos 30° = 0.866), and the drawing inverts.
        let (x, y) = hemisphere_xy(30f64.to_radians(), 0.7);
        assert!((x.hypot(y) - 2.0 / 3.0).abs() < 1e-15);
        let (el, az) = hemisphere_direction(x, y).unwrap();
        assert!((el - 30f64.to_radians()).abs() < 1e-12 && (az - 0.7).abs() < 1e-12);
        assert_eq!(hemisphere_direction(0.8, 0.7), None);
    }

    /// The direction labels "← behind" and "in front →" keep clear of the disk's rim (they
    /// touched it, issue 25): every point of their text boxes (top at the SVG's y, 13 units
    /// tall, as wide as the font measures) lies at least 3 units outside the horizon ring.
    #[test]
    fn hemisphere_direction_labels_clear_the_rim() {
        let grid = PolarGrid {
            elev_edges: vec![0.0, FRAC_PI_2],
            az_edges: vec![0.0, std::f64::consts::TAU],
            values: vec![Some(1.0)],
        };
        let scale = ColourScale::smooth(Axis::linear("v", 0.0, 2.0));
        let mut widths = Vec::new();
        let svg = draw_svg((240, 270), |area| {
            draw_hemisphere(area, "t", &grid, &scale).unwrap();
            let style = TextStyle::from((FONT, 13).into_font());
            for t in ["← behind", "in front →"] {
                widths.push(f64::from(area.estimate_text_size(t, &style).unwrap().0));
            }
        });
        // The horizon: the widest polyline, its centre and radius.
        let min = |v: &[f64]| v.iter().copied().fold(f64::INFINITY, f64::min);
        let max = |v: &[f64]| v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let (c, r) = svg
            .lines()
            .filter(|l| l.starts_with("<polyline"))
            .map(|l| {
                let (xs, ys): (Vec<f64>, Vec<f64>) = crate::plot::chart::read_svg::points(l)
                    .unwrap()
                    .into_iter()
                    .unzip();
                let c = ((min(&xs) + max(&xs)) / 2.0, (min(&ys) + max(&ys)) / 2.0);
                (c, (max(&ys) - min(&ys)) / 2.0)
            })
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        for (t, w) in ["← behind", "in front →"].iter().zip(widths) {
            let el = svg
                .lines()
                .find(|l| l.starts_with("<text") && visible(l) == *t)
                .unwrap();
            let (x, y) = (attr(el, "x").unwrap(), attr(el, "y").unwrap());
            let x0 = if el.contains("text-anchor=\"end\"") {
                x - w
            } else {
                x
            };
            let near = (c.0.clamp(x0, x0 + w), c.1.clamp(y, y + 13.0));
            let d = (near.0 - c.0).hypot(near.1 - c.1);
            assert!(d >= r + 3.0, "{t}: {d} from the centre, rim at {r}");
        }
    }

    /// A hemisphere panel as the figures draw it (issue 25, lloyd2006-fig7 and G2), read back
    /// from its SVG:
    /// - the rings lie where the azimuthal equidistant projection puts them, at (90° − el)/90°
    ///   of the horizon's radius (the orthographic view had the 30° ring at cos 30° = 0.87);
    /// - each ring is drawn once, one unit wide, with no halo beside it (issue 35);
    /// - no text lies inside the disk (ring labels and "overhead" covered the field, and a ring
    ///   crossed "overhead"), and the disk's top and bottom rows are returned;
    /// - the heat map is one RGBA image of at least 4 pixels per unit, transparent outside the
    ///   disk (nothing bleeds past the horizon ring) and opaque inside it.
    #[test]
    fn hemisphere_rings_halos_and_raster_by_the_projection() {
        let n = 12;
        let grid = PolarGrid {
            elev_edges: (0..=n).map(|i| FRAC_PI_2 * i as f64 / n as f64).collect(),
            az_edges: (0..=2 * n)
                .map(|j| std::f64::consts::PI * j as f64 / n as f64)
                .collect(),
            values: (0..2 * n * n).map(|k| Some(1.0 + k as f64)).collect(),
        };
        let scale = ColourScale::smooth(Axis::linear("v", 1.0, (2 * n * n) as f64));
        let mut rows = (0, 0);
        let svg = draw_svg((300, 330), |area| {
            rows = draw_hemisphere(area, "t", &grid, &scale).unwrap();
        });
        let lines: Vec<&str> = svg.lines().collect();
        // The circles: closed polylines of many points; centre, radius and width of each, the
        // white halos apart from the dark rings.
        let circles = |white: bool| -> Vec<((f64, f64), f64, f64)> {
            let mut v: Vec<((f64, f64), f64, f64)> = lines
                .iter()
                .filter(|l| l.starts_with("<polyline") && l.contains("stroke=\"#FFFFFF\"") == white)
                .filter_map(|l| {
                    let pts = crate::plot::chart::read_svg::points(l)?;
                    (pts.len() > 100).then(|| {
                        let k = pts.len() as f64;
                        let c = (
                            pts.iter().map(|p| p.0).sum::<f64>() / k,
                            pts.iter().map(|p| p.1).sum::<f64>() / k,
                        );
                        let r = pts
                            .iter()
                            .map(|p| (p.0 - c.0).hypot(p.1 - c.1))
                            .sum::<f64>()
                            / k;
                        (c, r, attr(l, "stroke-width").unwrap_or(1.0))
                    })
                })
                .collect();
            v.sort_by(|a, b| b.1.total_cmp(&a.1));
            v
        };
        let rings = circles(false);
        assert_eq!(rings.len(), RINGS.len());
        let (centre, horizon, _) = rings[0];
        for (&deg, &(_, r, _)) in RINGS.iter().zip(&rings) {
            let want = horizon * (90.0 - deg) / 90.0;
            assert!((r - want).abs() < 0.6, "{deg}° ring at {r}, want {want}");
        }
        // Each ring once, in one style (the fourth review: a light halo beside each dark ring
        // printed as a double ring): no white circle, every ring one unit wide.
        assert!(circles(true).is_empty(), "a halo beside a ring");
        for ring in &rings {
            assert!((ring.2 - 1.0).abs() < 1e-9, "{ring:?}");
        }
        for l in lines.iter().filter(|l| l.starts_with("<text")) {
            let (x, y) = (attr(l, "x").unwrap(), attr(l, "y").unwrap());
            let r = (x - centre.0).hypot(y - centre.1);
            assert!(
                r > horizon,
                "{} at {r} inside the disk ({horizon})",
                visible(l)
            );
        }
        let (top, bottom) = (f64::from(rows.0), f64::from(rows.1));
        assert!((top - (centre.1 - horizon)).abs() <= 1.0, "{rows:?}");
        assert!((bottom - (centre.1 + horizon)).abs() <= 1.0, "{rows:?}");
        // The heat map: one RGBA image, dense, clipped to the disk.
        let images = embedded_images(&svg);
        assert_eq!(images.len(), 1);
        let Image {
            at: (x0, y0),
            density,
            rgba: ref img,
            colour_type,
        } = images[0];
        assert!(density >= 4.0 - 1e-9, "{density} pixels per unit");
        assert_eq!(colour_type, 6, "colour type RGBA");
        let (mut outside, mut inside) = (0, 0);
        for (px, py, p) in img.enumerate_pixels() {
            let u = x0 + (f64::from(px) + 0.5) / density;
            let v = y0 + (f64::from(py) + 0.5) / density;
            let r = (u - centre.0).hypot(v - centre.1);
            if r > horizon + 0.5 {
                assert_eq!(p[3], 0, "pixel ({px}, {py}) outside the disk");
                outside += 1;
            } else if r < horizon - 0.5 {
                assert_eq!(p[3], 255, "pixel ({px}, {py}) inside the disk");
                inside += 1;
            }
        }
        assert!(outside > 1000 && inside > 10_000, "{outside} {inside}");
    }
}
