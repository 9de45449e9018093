//! Contour lines over a hemisphere panel: lloyd2006-fig7's (a) (no warping) spans 8.65×10⁵ to
//! 2.0×10⁶, 0.36 of a decade, one flat green under the shared 10²–10⁷ bar (the sixth review,
//! R6-lloyd2006-fig7-2), so its structure is drawn as labelled contour lines at 10⁶ and
//! 1.5×10⁶.
//!
//! A contour is traced by marching squares over the sweep's samples (elevation rows, azimuth
//! columns that wrap round), interpolated linearly in log₁₀ of the field, and drawn in the
//! disk's azimuthal equidistant projection ([`hemisphere_xy`]), dashed, with its value written on
//! it in a break of the line.

use super::super::canvas::Fine;
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

/// The contours' ink: black, 2 units wide, dashed, so that they stand apart from the rings
/// (near black, solid, 1 unit): the first level in short dashes (3 on, 2 off), the next in long
/// ones (8 on, 3 off).
const INK: (u8, u8, u8) = (0, 0, 0);
pub(super) const DASHES: [[f64; 2]; 2] = [[3.0, 2.0], [8.0, 3.0]];

/// The size of a contour's label: the ring key's (plotters' size 13, 10.5 units in the SVG;
/// in one column, where a disk's radius is about 38 units, 10, printed 6.5 pt).
fn label_size() -> u32 {
    if column() == Column::Single {
        10
    } else {
        13
    }
}

/// Draws `contours` over the hemisphere panel `area` (as [`draw_hemisphere_keyed`] lays it
/// out: [`hemisphere_disk`]), each dashed, its value ([`fmt_power`]) written once on it at the
/// point of its lines nearest to the disk point `label_at[k]` (radius 1), on a box of the
/// field's own colour there (`fill`, given the light direction), which breaks the line and the
/// rings under the label, as a contour label does, without a white patch on the data.
///
/// [`draw_hemisphere_keyed`]: super::super::chart::draw_hemisphere_keyed
pub(super) fn draw_contours<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    contours: &[Contour],
    label_at: &[(f64, f64)],
    fill: &dyn Fn((f64, f64)) -> Option<RGBColor>,
) -> Result<(), Fail> {
    let (w, h) = area.dim_in_pixel();
    let ((cx, cy), r) = hemisphere_disk(w, h);
    let (bx, by) = area.get_base_pixel();
    let to_units = |(el, az): (f64, f64)| {
        let (x, y) = hemisphere_xy(el, az);
        (cx + r * x, cy - r * y)
    };
    let style = TextStyle::from((FONT, label_size()).into_font());
    let mut labels: Vec<Label> = Vec::new();
    for (k, (c, &want)) in contours.iter().zip(label_at).enumerate() {
        let text = fmt_power(c.level);
        let (tw, th) = area.estimate_text_size(&text, &style)?;
        let lines: Vec<Vec<(f64, f64)>> = c
            .lines
            .iter()
            .map(|l| l.iter().map(|&p| to_units(p)).collect())
            .collect();
        let want = (cx + r * want.0, cy - r * want.1);
        // The label's box, a unit round its glyphs: the line is broken there.
        let (hw, hh) = (0.5 * f64::from(tw) + 1.5, 0.5 * f64::from(th) + 1.0);
        // Its point: the nearest to `want` whose box lies inside the disk (2 units in from the
        // rim) and clear of the labels set before.
        let fits = |p: &(f64, f64)| {
            let inside = [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
                .iter()
                .all(|(sx, sy)| dist((p.0 + sx * hw, p.1 + sy * hh), (cx, cy)) <= r - 2.0);
            let clear = labels.iter().all(|(_, q, (qw, qh), _): &Label| {
                (p.0 - q.0).abs() >= hw + qw || (p.1 - q.1).abs() >= hh + qh
            });
            inside && clear
        };
        let Some((&at, &dir)) = lines
            .iter()
            .flatten()
            .zip(c.lines.iter().flatten())
            .filter(|(p, _)| fits(p))
            .min_by(|a, b| dist(*a.0, want).total_cmp(&dist(*b.0, want)))
        else {
            return Err(Fail::Draw(format!(
                "the contour at {text} has no point for its label inside the disk"
            )));
        };
        let gap = |p: &(f64, f64)| (p.0 - at.0).abs() <= hw && (p.1 - at.1).abs() <= hh;
        for line in &lines {
            for run in line.split(gap).filter(|run| run.len() >= 2) {
                for dash in dash_pattern(run, &DASHES[k % DASHES.len()], 1.0) {
                    area.draw(&Fine {
                        points: dash
                            .iter()
                            .map(|p| (p.0 + f64::from(bx), p.1 + f64::from(by)))
                            .collect(),
                        colour: BackendColor {
                            alpha: 1.0,
                            rgb: INK,
                        },
                        stroke: Some(2),
                    })?;
                }
            }
        }
        labels.push((text, at, (hw, hh), fill(dir)));
    }
    // The labels last, over every contour's line.
    for (text, at, (hw, hh), colour) in labels {
        if let Some(colour) = colour {
            let (x, y) = (at.0.round() as i32, at.1.round() as i32);
            let (hw, hh) = (hw.round() as i32, hh.round() as i32);
            area.draw(&Rectangle::new(
                [(x - hw, y - hh), (x + hw, y + hh)],
                colour.filled(),
            ))?;
        }
        area.draw(&Text::new(
            text,
            (at.0.round() as i32, at.1.round() as i32),
            style.pos(Pos::new(HPos::Center, VPos::Center)),
        ))?;
    }
    Ok(())
}

/// The key of the contours' line styles (the seventh review, R7-2006f7-1: (a)'s dotted and
/// dashed lines were named only by the values written on them): one row a contour, from the
/// top of `area`, a sample of its line, [`KEY_SAMPLE`] units long, dashed as
/// [`draw_contours`] dashes it, and "(a) S̄ = {level}" after it, at the contour labels' size,
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
        let sample = [(0.0, y), (KEY_SAMPLE, y)];
        for dash in dash_pattern(&sample, &DASHES[k % DASHES.len()], 1.0) {
            area.draw(&Fine {
                points: dash
                    .iter()
                    .map(|p| (p.0 + f64::from(bx), p.1 + f64::from(by)))
                    .collect(),
                colour: BackendColor {
                    alpha: 1.0,
                    rgb: INK,
                },
                stroke: Some(2),
            })?;
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

/// A contour's label: its text, centre, half width and height (units), and the colour under it.
type Label = (String, (f64, f64), (f64, f64), Option<RGBColor>);

fn dist(a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}
