//! A line chart's legend, drawn by the chart itself (not by plotters) so that its box is known:
//! it goes to the position inside the plotting area where it covers the fewest lines, markers
//! and labels, the chart's preferred position first among equals.

use super::super::Fail;
use super::fine::{draw_fine_path, fill_fine_polygon};
use super::label::{Obstacles, Rect};
use super::line::{Dash, Marker};
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

/// The legend's size for entries whose texts measure `sizes`, and its row height.
fn size(sizes: &[(u32, u32)]) -> (f64, f64, f64) {
    let row = sizes.iter().map(|s| f64::from(s.1)).fold(12.0, f64::max) + 4.0;
    let text = sizes.iter().map(|s| f64::from(s.0)).fold(0.0, f64::max);
    (
        2.0 * PAD + SAMPLE + GAP + text,
        2.0 * PAD + row * sizes.len() as f64,
        row,
    )
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

/// Where the legend goes: the position among the nine that touches the fewest lines, markers
/// and boxes, `preferred` first among equals.
fn place(preferred: &SeriesLabelPosition, plot: &Rect, w: f64, h: f64, o: &Obstacles) -> Rect {
    use SeriesLabelPosition as P;
    let mut best = at(preferred, plot, w, h);
    let mut fewest = o.hits(&best, None).0;
    for pos in [
        P::UpperRight,
        P::UpperLeft,
        P::LowerRight,
        P::LowerLeft,
        P::UpperMiddle,
        P::LowerMiddle,
        P::MiddleRight,
        P::MiddleLeft,
        P::MiddleMiddle,
    ] {
        let r = at(&pos, plot, w, h);
        let n = o.hits(&r, None).0;
        if n < fewest {
            (best, fewest) = (r, n);
        }
    }
    best
}

/// Draws the legend of `entries` on `plot_area` (a chart's plotting area without its
/// coordinates), at the best position for `obstacles` (see [`place`]).
pub(crate) fn draw_legend<DB: DrawingBackend>(
    plot_area: &DrawingArea<DB, Shift>,
    entries: &[Entry],
    preferred: &SeriesLabelPosition,
    obstacles: &Obstacles,
) -> Result<(), Fail> {
    if entries.is_empty() {
        return Ok(());
    }
    let style = TextStyle::from((FONT, TEXT).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let sizes = entries
        .iter()
        .map(|e| plot_area.estimate_text_size(&e.label, &style))
        .collect::<Result<Vec<_>, _>>()?;
    let (w, h, row) = size(&sizes);
    let (xr, yr) = plot_area.get_pixel_range();
    let plot = Rect {
        x0: f64::from(xr.start),
        y0: f64::from(yr.start),
        x1: f64::from(xr.end),
        y1: f64::from(yr.end),
    };
    let r = place(preferred, &plot, w, h, obstacles);
    let (bx, by) = plot_area.get_base_pixel();
    let local = |x: f64, y: f64| ((x.round() as i32) - bx, (y.round() as i32) - by);
    let (a, b) = (local(r.x0, r.y0), local(r.x1, r.y1));
    plot_area.draw(&Rectangle::new([a, b], WHITE.mix(0.9).filled()))?;
    plot_area.draw(&Rectangle::new([a, b], RGBColor(120, 120, 120)))?;
    for (i, e) in entries.iter().enumerate() {
        let y = r.y0 + PAD + row * (i as f64 + 0.5);
        let x = r.x0 + PAD;
        let (start, marker_at) = sample(e);
        if e.line {
            draw_fine_path(
                plot_area,
                &[(x + start, y), (x + SAMPLE, y)],
                e.colour,
                e.width,
                e.dash,
            )?;
        }
        if let Some(m) = e.marker {
            let outline = m.outline(e.width as i32 + 2);
            fill_fine_polygon(plot_area, (x + marker_at, y), &outline, e.colour)?;
        }
        plot_area.draw(&Text::new(
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
            Marker::TriangleDown,
            Marker::Diamond,
            Marker::WideBar,
            Marker::TallBar,
            Marker::Hexagon,
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
