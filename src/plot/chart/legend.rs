//! A line chart's legend, drawn by the chart itself (not by plotters) so that its box is known:
//! it goes inside the plotting area where it covers no line, marker or label (the chart's
//! preferred position first), and below the plot, in as many columns as fit, where no such
//! place exists: a legend never covers data.

use super::super::Fail;
use super::fine::{draw_fine_path, fill_fine_polygon, stroke_fine_outline};
use super::label::{Obstacles, Rect};
use super::line::Dash;
use super::marker::Marker;
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// One entry: a sample of the series' line (and marker) and its label.
#[derive(Debug, Clone)]
pub(crate) struct Entry {
    pub label: String,
    pub colour: RGBColor,
    pub width: u32,
    pub dash: Dash,
    pub marker: Option<Marker>,
    /// The series joins its points: the sample shows its line (a series of unjoined points
    /// shows only its marker).
    pub line: bool,
    /// The marker drawn hollow, as the series draws it ([`super::Series::hollow`]).
    pub hollow: bool,
}

/// Distance of the legend from the plotting area's border, its inner padding, the sample's
/// length and the gap between sample and text, the text size (backend units).
const MARGIN: f64 = 8.0;
const PAD: f64 = 5.0;
const SAMPLE: f64 = 24.0;
const GAP: f64 = 6.0;
const TEXT: u32 = 13;

/// Where an entry's sample starts and where its marker sits, along the sample: a solid line
/// from the start with the marker at its centre; a dashed or dotted line with a marker starts at
/// the marker's centre, the marker's half width in from the start, so that the marker, inside
/// the legend's box, lies on the first dash and leaves the first gap visible (a dash's first
/// gap starts 9 units along it, `super::fine::dash_lengths`).
fn sample(e: &Entry) -> (f64, f64) {
    match e.marker {
        Some(m) if e.line && e.dash != Dash::Solid => {
            let half = m
                .outline(e.width as i32 + 2)
                .iter()
                .map(|p| f64::from(p.0.abs()))
                .fold(0.0, f64::max);
            (half, half)
        }
        _ => (0.0, 0.5 * SAMPLE),
    }
}

/// The clearance kept between a legend inside the plot and every line, marker and label (more
/// than half the widest line the figures draw).
const CLEAR: f64 = 3.0;

/// The space between the columns of a legend below its plot.
const COLUMN_GAP: f64 = 12.0;

/// The row height of entries whose texts measure `sizes`.
fn row_height(sizes: &[(u32, u32)]) -> f64 {
    sizes.iter().map(|s| f64::from(s.1)).fold(12.0, f64::max) + 4.0
}

/// The box of a `w` × `h` legend at `pos` inside `plot`.
fn at(pos: &SeriesLabelPosition, plot: &Rect, w: f64, h: f64) -> Rect {
    use SeriesLabelPosition as P;
    let (hp, vp) = match pos {
        P::UpperLeft => (HPos::Left, VPos::Top),
        P::UpperMiddle => (HPos::Center, VPos::Top),
        P::UpperRight => (HPos::Right, VPos::Top),
        P::MiddleLeft => (HPos::Left, VPos::Center),
        P::MiddleMiddle => (HPos::Center, VPos::Center),
        P::MiddleRight => (HPos::Right, VPos::Center),
        P::LowerLeft => (HPos::Left, VPos::Bottom),
        P::LowerMiddle => (HPos::Center, VPos::Bottom),
        P::LowerRight | P::Coordinate(..) => (HPos::Right, VPos::Bottom),
    };
    let x = match hp {
        HPos::Left => plot.x0 + MARGIN,
        HPos::Center => 0.5 * (plot.x0 + plot.x1),
        HPos::Right => plot.x1 - MARGIN,
    };
    let y = match vp {
        VPos::Top => plot.y0 + MARGIN,
        VPos::Center => 0.5 * (plot.y0 + plot.y1),
        VPos::Bottom => plot.y1 - MARGIN,
    };
    Rect::anchored((x, y), Pos::new(hp, vp), w, h)
}

/// Where a `w` × `h` legend goes inside `plot`: a box that lies wholly inside the plot (with
/// [`MARGIN`] to its border) and keeps [`CLEAR`] units from every line, marker and label of
/// `o`. The nine usual positions are tried first (`preferred` first), then boxes on a grid over
/// the plot, nearest a corner first. `None` where no such box exists: the legend then goes
/// below the plot ([`strip_height`]).
fn clear_inside(
    preferred: &SeriesLabelPosition,
    plot: &Rect,
    w: f64,
    h: f64,
    o: &Obstacles,
) -> Option<Rect> {
    use SeriesLabelPosition as P;
    let room = (
        plot.x1 - plot.x0 - 2.0 * MARGIN - w,
        plot.y1 - plot.y0 - 2.0 * MARGIN - h,
    );
    if room.0 < 0.0 || room.1 < 0.0 {
        return None;
    }
    let usual = [
        P::UpperRight,
        P::UpperLeft,
        P::LowerRight,
        P::LowerLeft,
        P::UpperMiddle,
        P::LowerMiddle,
        P::MiddleRight,
        P::MiddleLeft,
        P::MiddleMiddle,
    ];
    const STEPS: u32 = 12;
    let mut grid: Vec<(f64, Rect)> = Vec::new();
    for i in 0..=STEPS {
        for j in 0..=STEPS {
            let (fx, fy) = (
                f64::from(i) / f64::from(STEPS),
                f64::from(j) / f64::from(STEPS),
            );
            let x0 = plot.x0 + MARGIN + fx * room.0;
            let y0 = plot.y0 + MARGIN + fy * room.1;
            let corner = fx.min(1.0 - fx) * room.0 + fy.min(1.0 - fy) * room.1;
            grid.push((
                corner,
                Rect {
                    x0,
                    y0,
                    x1: x0 + w,
                    y1: y0 + h,
                },
            ));
        }
    }
    grid.sort_by(|a, b| a.0.total_cmp(&b.0));
    std::iter::once(at(preferred, plot, w, h))
        .chain(usual.iter().map(|p| at(p, plot, w, h)))
        .chain(grid.into_iter().map(|g| g.1))
        .find(|r| o.hits(&r.grown(CLEAR), None).0 == 0)
}

/// The texts' sizes of `entries` as `area` measures them.
fn measure<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    entries: &[Entry],
) -> Result<Vec<(u32, u32)>, Fail> {
    let style = text_style();
    Ok(entries
        .iter()
        .map(|e| area.estimate_text_size(&e.label, &style))
        .collect::<Result<Vec<_>, _>>()?)
}

fn text_style() -> TextStyle<'static> {
    TextStyle::from((FONT, TEXT).into_font()).pos(Pos::new(HPos::Left, VPos::Center))
}

/// A legend below its plot: the entries in `columns` columns (row by row), each column as wide
/// as its widest entry; the box's size.
struct Grid {
    columns: usize,
    widths: Vec<f64>,
    row: f64,
    w: f64,
    h: f64,
}

/// The legend of entries whose texts measure `sizes` in `columns` columns.
fn in_columns(sizes: &[(u32, u32)], columns: usize) -> Grid {
    let row = row_height(sizes);
    let columns = columns.clamp(1, sizes.len().max(1));
    let cell = |i: usize| SAMPLE + GAP + f64::from(sizes[i].0);
    let widths: Vec<f64> = (0..columns)
        .map(|c| {
            (c..sizes.len())
                .step_by(columns)
                .map(cell)
                .fold(0.0, f64::max)
        })
        .collect();
    let w = 2.0 * PAD + widths.iter().sum::<f64>() + COLUMN_GAP * (columns - 1) as f64;
    let h = 2.0 * PAD + row * sizes.len().div_ceil(columns).max(1) as f64;
    Grid {
        columns,
        widths,
        row,
        w,
        h,
    }
}

/// The most columns (at most one per entry, at most `most`) whose box is no wider than
/// `width`; one column where even that is wider.
fn grid(sizes: &[(u32, u32)], width: f64, most: Option<usize>) -> Grid {
    (1..=most.unwrap_or(usize::MAX).min(sizes.len()).max(1))
        .rev()
        .map(|c| in_columns(sizes, c))
        .find(|g| g.w <= width)
        .unwrap_or_else(|| in_columns(sizes, 1))
}

/// Where a chart's legend went.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Placed {
    /// Inside the plot, clear of its data (or there is no legend).
    Inside,
    /// Below the plot, in a strip of this height: no box inside was clear. Where the chart
    /// had no such strip, nothing is drawn and the height is what the strip needs.
    Below(u32),
}

/// Draws the legend of `entries` on `plot_area` (a chart's plotting area without its
/// coordinates) where it covers none of `obstacles` ([`clear_inside`]); failing that, in
/// `strip` (an area below the chart; centred under the plot where it is no wider, else in the
/// strip) when there is one. Returns where it went: without a strip, the height a strip
/// `below_width` units wide would need. `most`: at most this many columns (entries row by row:
/// a key whose columns group its entries).
pub(crate) fn draw_legend_clear<DB: DrawingBackend>(
    plot_area: &DrawingArea<DB, Shift>,
    strip: Option<&DrawingArea<DB, Shift>>,
    below_width: f64,
    (entries, most): (&[Entry], Option<usize>),
    preferred: &SeriesLabelPosition,
    obstacles: &Obstacles,
) -> Result<Placed, Fail> {
    if entries.is_empty() {
        return Ok(Placed::Inside);
    }
    let sizes = measure(plot_area, entries)?;
    let plot = pixel_rect(plot_area);
    // One column, else two or three (a wide, low box may fit above or below the data).
    for columns in 1..=sizes.len().min(3).min(most.unwrap_or(3)) {
        let g = in_columns(&sizes, columns);
        if let Some(r) = clear_inside(preferred, &plot, g.w, g.h, obstacles) {
            draw_box(plot_area, entries, &r, &g)?;
            return Ok(Placed::Inside);
        }
    }
    let Some(strip) = strip else {
        let g = grid(&sizes, below_width - 2.0 * MARGIN, most);
        return Ok(Placed::Below((g.h + 2.0 * MARGIN).ceil() as u32));
    };
    let s = pixel_rect(strip);
    let g = grid(&sizes, s.x1 - s.x0 - 2.0 * MARGIN, most);
    let x0 = if g.w <= plot.x1 - plot.x0 {
        0.5 * (plot.x0 + plot.x1 - g.w)
    } else {
        0.5 * (s.x0 + s.x1 - g.w)
    }
    .min(s.x1 - MARGIN - g.w)
    .max(s.x0 + MARGIN);
    let y0 = s.y0 + MARGIN;
    let r = Rect {
        x0,
        y0,
        x1: x0 + g.w,
        y1: y0 + g.h,
    };
    draw_box(strip, entries, &r, &g)?;
    Ok(Placed::Below((s.y1 - s.y0) as u32))
}

/// The pixel extent of `area` (backend units).
fn pixel_rect<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>) -> Rect {
    let (xr, yr) = area.get_pixel_range();
    Rect {
        x0: f64::from(xr.start),
        y0: f64::from(yr.start),
        x1: f64::from(xr.end),
        y1: f64::from(yr.end),
    }
}

/// Draws the box `r` (absolute backend units) on `area` with the entries laid out by `g`.
fn draw_box<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    entries: &[Entry],
    r: &Rect,
    g: &Grid,
) -> Result<(), Fail> {
    let style = text_style();
    let (bx, by) = area.get_base_pixel();
    let local = |x: f64, y: f64| ((x.round() as i32) - bx, (y.round() as i32) - by);
    let (a, b) = (local(r.x0, r.y0), local(r.x1, r.y1));
    area.draw(&Rectangle::new([a, b], WHITE.mix(0.9).filled()))?;
    area.draw(&Rectangle::new([a, b], RGBColor(120, 120, 120)))?;
    for (i, e) in entries.iter().enumerate() {
        let (column, line) = (i % g.columns, i / g.columns);
        let y = r.y0 + PAD + g.row * (line as f64 + 0.5);
        let x = r.x0 + PAD + g.widths[..column].iter().sum::<f64>() + COLUMN_GAP * column as f64;
        let (start, marker_at) = sample(e);
        if e.line {
            draw_fine_path(
                area,
                &[(x + start, y), (x + SAMPLE, y)],
                e.colour,
                e.width,
                e.dash,
            )?;
        }
        if let Some(m) = e.marker {
            let outline = m.outline(e.width as i32 + 2);
            if e.hollow {
                stroke_fine_outline(area, (x + marker_at, y), &outline, e.colour)?;
            } else {
                fill_fine_polygon(area, (x + marker_at, y), &outline, e.colour)?;
            }
        }
        area.draw(&Text::new(
            e.label.clone(),
            local(x + SAMPLE + GAP, y),
            style.clone(),
        ))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::fine::dash_lengths;
    use super::*;

    /// Every marker shape at the widest line width the figures use (5) lies inside the sample
    /// (so inside the legend's box) and leaves at least one whole gap of a dashed or dotted
    /// sample uncovered, so the sample still reads as dashed (with the marker at the sample's
    /// centre, a dashed sample's only gap, 9 to 15, was covered).
    #[test]
    fn a_dashed_samples_marker_leaves_a_gap_visible() {
        let shapes = [
            Marker::Circle,
            Marker::Square,
            Marker::TriangleUp,
            Marker::Diamond,
            Marker::TallBar,
            Marker::Hexagon,
            Marker::Star,
            Marker::Pentagon,
            Marker::Cross,
            Marker::Saltire,
            Marker::Bowtie,
        ];
        for dash in [Dash::Dashed, Dash::Dotted] {
            let (on, off) = dash_lengths(dash).unwrap();
            for m in shapes {
                for width in 1..=5u32 {
                    let e = Entry {
                        label: String::new(),
                        colour: BLACK,
                        width,
                        dash,
                        marker: Some(m),
                        line: true,
                        hollow: false,
                    };
                    let half = m
                        .outline(width as i32 + 2)
                        .iter()
                        .map(|p| f64::from(p.0.abs()))
                        .fold(0.0, f64::max);
                    let (line, at) = sample(&e);
                    let (lo, hi) = (at - half, at + half);
                    assert!(lo >= 0.0 && hi <= SAMPLE, "{m:?} width {width} outside");
                    let mut start = line + on;
                    let mut visible = 0;
                    while start + off <= SAMPLE {
                        if start >= hi || start + off <= lo {
                            visible += 1;
                        }
                        start += on + off;
                    }
                    assert!(visible >= 1, "{dash:?} {m:?} width {width}: no gap visible");
                }
            }
        }
    }
}
