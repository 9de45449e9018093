//! Contour lines over a hemisphere panel: lloyd2006-fig7's (a) (no warping) spans 8.65×10⁵ to
//! 2.0×10⁶, 0.36 of a decade, one flat green under the shared 10²–10⁷ bar (the sixth review,
//! R6-lloyd2006-fig7-2), so its structure is drawn as contour lines at 10⁶ and 1.5×10⁶, named
//! by their line styles in a key.
//!
//! A contour is traced by marching squares over the sweep's samples (elevation rows, azimuth
//! columns that wrap round), interpolated linearly in log₁₀ of the field, and drawn in the
//! disk's azimuthal equidistant projection ([`hemisphere_xy`]), black dashes on a white line;
//! [`draw_contour_key`] writes each level beside a sample of its line.

use super::super::canvas::FineWidth;
use super::super::chart::{column, dash_pattern, fmt_power, hemisphere_disk, hemisphere_xy, FONT};
use super::super::{Column, Fail};
use crate::scheme::sweep::SweepGrid;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters_backend::BackendColor;
use std::collections::HashMap;

/// One contour: its level and its lines, each a run of light directions (elevation, azimuth,
/// radians).
#[derive(Debug, Clone)]
pub(super) struct Contour {
    pub level: f64,
    pub lines: Vec<Vec<(f64, f64)>>,
}

/// A grid edge a contour crosses: between samples (i, j) and (i + 1, j) (`up`) or (i, j) and
/// (i, j + 1) (round), j wrapping.
type Edge = (usize, usize, bool);

/// The contour of `values` (row-major over `grid`, elevation major) at `level`: marching
/// squares in log₁₀, each crossing on a grid edge where the field passes the level, joined
/// into lines through the cells (a saddle cell split by the value at its centre, the mean of its
/// corners). Cells with a missing sample are skipped.
pub(super) fn contour(values: &[Option<f64>], grid: SweepGrid, level: f64) -> Contour {
    let (ne, na) = (grid.elevations(), grid.azimuths());
    let at = |i: usize, j: usize| -> Option<f64> {
        values
            .get(i * na + j % na)
            .copied()
            .flatten()
            .filter(|v| *v > 0.0)
            .map(f64::log10)
    };
    let l = level.log10();
    // The crossing on an edge, as a light direction.
    let point = |(i, j, up): Edge| -> Option<(f64, f64)> {
        let (i2, j2) = if up { (i + 1, j) } else { (i, j + 1) };
        let (a, b) = (at(i, j)?, at(i2, j2)?);
        let t = ((l - a) / (b - a)).clamp(0.0, 1.0);
        let (e1, e2) = (grid.elevation(i), grid.elevation(i2));
        let (a1, a2) = (
            grid.azimuth(j),
            grid.azimuth(j) + if up { 0.0 } else { grid.azimuth(1) },
        );
        Some((e1 + t * (e2 - e1), a1 + t * (a2 - a1)))
    };
    // Each cell's segments, as pairs of edges.
    let mut segments: Vec<(Edge, Edge)> = Vec::new();
    for i in 0..ne.saturating_sub(1) {
        for j in 0..na {
            let c = [at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)];
            let [Some(v0), Some(v1), Some(v2), Some(v3)] = c else {
                continue;
            };
            let v = [v0, v1, v2, v3];
            // The cell's sides, corner k to k + 1: bottom (round at i), right (up at j + 1),
            // top (round at i + 1), left (up at j).
            let sides: [Edge; 4] = [
                (i, j, false),
                (i, (j + 1) % na, true),
                (i + 1, j, false),
                (i, j, true),
            ];
            let above = |k: usize| v[k] >= l;
            let crossed: Vec<usize> = (0..4).filter(|&k| above(k) != above((k + 1) % 4)).collect();
            match crossed.as_slice() {
                [a, b] => segments.push((sides[*a], sides[*b])),
                [a, b, c, d] => {
                    // A saddle: corners 0 and 2 on one side. Where the centre is on their side
                    // they join across it, cutting off corners 1 and 3, else the reverse.
                    let centre = 0.25 * v.iter().sum::<f64>();
                    if (centre >= l) == above(0) {
                        segments.push((sides[*a], sides[*b]));
                        segments.push((sides[*c], sides[*d]));
                    } else {
                        segments.push((sides[*d], sides[*a]));
                        segments.push((sides[*b], sides[*c]));
                    }
                }
                _ => {}
            }
        }
    }
    Contour {
        level,
        lines: join(&segments)
            .into_iter()
            .map(|run| run.into_iter().filter_map(point).collect::<Vec<_>>())
            .filter(|run| run.len() >= 2)
            .collect(),
    }
}

/// Segments joined end to end into runs of edges: each edge a contour crosses belongs to at
/// most two cells, so the runs are the contour's lines (closed ones end where they began).
fn join(segments: &[(Edge, Edge)]) -> Vec<Vec<Edge>> {
    let mut by_edge: HashMap<Edge, Vec<usize>> = HashMap::new();
    for (k, (a, b)) in segments.iter().enumerate() {
        by_edge.entry(*a).or_default().push(k);
        by_edge.entry(*b).or_default().push(k);
    }
    let mut used = vec![false; segments.len()];
    let mut runs = Vec::new();
    // Open lines first, from an edge with one segment, then the closed ones.
    let mut starts: Vec<usize> = (0..segments.len()).collect();
    starts.sort_by_key(|&k| {
        let (a, b) = segments[k];
        usize::from(by_edge[&a].len() > 1 && by_edge[&b].len() > 1)
    });
    for start in starts {
        if used[start] {
            continue;
        }
        used[start] = true;
        let (a, b) = segments[start];
        // Walk from the end with no other segment, if there is one.
        let (first, mut end) = if by_edge[&b].len() == 1 {
            (b, a)
        } else {
            (a, b)
        };
        let mut run = vec![first, end];
        while let Some(&next) = by_edge[&end].iter().find(|&&k| !used[k]) {
            used[next] = true;
            let (p, q) = segments[next];
            end = if p == end { q } else { p };
            run.push(end);
        }
        runs.push(run);
    }
    runs
}

/// The contours' ink: black dashes 1.5 units wide ([`CORE`] tenths) along a white line under
/// each contour ([`HALO`] tenths: half a unit each side of the dashes), so that they stand apart
/// from the rings (grey, half a unit: [`super::super::chart::RINGS_GREY`]) and show where they
/// run along the disk's rim or along each other (the eleventh review, R11-lloyd2006-fig7-1:
/// black contours 2 units wide over black rings a unit wide could not be told from the rim);
/// the first level in short dashes (3 on, 2 off), the next in long ones (8 on, 3 off).
const INK: (u8, u8, u8) = (0, 0, 0);
const HALO_INK: (u8, u8, u8) = (255, 255, 255);
pub(super) const CORE: u32 = 15;
pub(super) const HALO: u32 = 25;
pub(super) const DASHES: [[f64; 2]; 2] = [[3.0, 2.0], [8.0, 3.0]];

/// The size of the contours' key text: the ring key's (plotters' size 13, 10.5 units in the SVG;
/// in one column, where a disk's radius is about 38 units, 10, printed 6.5 pt).
fn label_size() -> u32 {
    if column() == Column::Single {
        10
    } else {
        13
    }
}

/// Draws `lines` (absolute units) as a contour's white line ([`HALO`]) where `halo`, else as
/// its black dashes ([`CORE`], `dashes` on and off).
fn draw_line<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    lines: &[Vec<(f64, f64)>],
    dashes: &[f64; 2],
    halo: bool,
) -> Result<(), Fail> {
    let colour = |rgb| BackendColor { alpha: 1.0, rgb };
    for line in lines {
        if halo {
            area.draw(&FineWidth {
                points: line.clone(),
                colour: colour(HALO_INK),
                width: HALO,
            })?;
            continue;
        }
        for dash in dash_pattern(line, dashes, 1.0) {
            area.draw(&FineWidth {
                points: dash,
                colour: colour(INK),
                width: CORE,
            })?;
        }
    }
    Ok(())
}

/// Draws `contours` over the hemisphere panel `area` (as [`draw_hemisphere_keyed`] lays it
/// out: [`hemisphere_disk`]): each a white line with black dashes on it (the white lines of all
/// first, so that where two contours run side by side both show). No label is written in the
/// disk: [`draw_contour_key`] names each contour by its line's style (the twelfth and
/// thirteenth reviews, R12-lloyd2006-fig7-1, R13-lloyd2006-fig7-1: a label on its own contour
/// had the line through its glyphs; a gap in the line fits "10⁶" but no lobe holds a gap for
/// "1.5×10⁶" at the figures' least text size, 2 % of the page's width).
///
/// [`draw_hemisphere_keyed`]: super::super::chart::draw_hemisphere_keyed
pub(super) fn draw_contours<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    contours: &[Contour],
) -> Result<(), Fail> {
    let (w, h) = area.dim_in_pixel();
    let ((cx, cy), r) = hemisphere_disk(w, h);
    let (bx, by) = area.get_base_pixel();
    let (bx, by) = (f64::from(bx), f64::from(by));
    // Each contour's lines in absolute units.
    let to_units = |(el, az): (f64, f64)| {
        let (x, y) = hemisphere_xy(el, az);
        (cx + r * x + bx, cy - r * y + by)
    };
    let lines: Vec<Vec<Vec<(f64, f64)>>> = contours
        .iter()
        .map(|c| {
            c.lines
                .iter()
                .map(|l| l.iter().map(|&p| to_units(p)).collect())
                .collect()
        })
        .collect();
    for halo in [true, false] {
        for (k, l) in lines.iter().enumerate() {
            draw_line(area, l, &DASHES[k % DASHES.len()], halo)?;
        }
    }
    Ok(())
}

/// The key of the contours' line styles (the seventh review, R7-2006f7-1: (a)'s dotted and
/// dashed lines were named only by the values written on them): one row a contour, from the
/// top of `area`, a sample of its line, [`KEY_SAMPLE`] units long, dashed as
/// [`draw_contours`] dashes it, and "(a) S̄ = {level}" after it, at the ring key's size,
/// under [`KEY_PAD`] units.
pub(super) fn draw_contour_key<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    contours: &[Contour],
) -> Result<(), Fail> {
    let (bx, by) = area.get_base_pixel();
    let style =
        TextStyle::from((FONT, label_size()).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let row = label_size() + 3;
    for (k, c) in contours.iter().enumerate() {
        let y = KEY_PAD + f64::from(row) * (k as f64 + 0.5);
        let sample = vec![
            (f64::from(bx), y + f64::from(by)),
            (KEY_SAMPLE + f64::from(bx), y + f64::from(by)),
        ];
        for halo in [true, false] {
            draw_line(
                area,
                std::slice::from_ref(&sample),
                &DASHES[k % DASHES.len()],
                halo,
            )?;
        }
        area.draw(&Text::new(
            format!("(a) S̄ = {}", fmt_power(c.level)),
            ((KEY_SAMPLE + 5.0) as i32, y.round() as i32),
            style.clone(),
        ))?;
    }
    Ok(())
}

/// The length of a line sample in [`draw_contour_key`], in units: two of the longer dashes'
/// periods, and the space over its rows (apart from "viewer's right" over it).
const KEY_SAMPLE: f64 = 22.0;
const KEY_PAD: f64 = 5.0;
