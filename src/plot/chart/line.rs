//! Line charts: series, notes and legends, with the data clipped to the axes (plotters draws
//! points outside an axis range on the border, so nothing is handed to it unclipped).

use super::super::Fail;
use super::axis::{build_chart, Axis};
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;

/// How a series' line is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Dash {
    Solid,
    Dashed,
    Dotted,
}

/// One line of a line chart, in data coordinates.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Series {
    pub label: Option<String>,
    pub points: Vec<(f64, f64)>,
    pub colour: RGBColor,
    pub dash: Dash,
    pub width: u32,
    pub markers: bool,
}

impl Series {
    /// A solid line of width 2 with a legend entry.
    pub fn line(label: impl Into<String>, points: Vec<(f64, f64)>, colour: RGBColor) -> Self {
        Self {
            label: Some(label.into()),
            points,
            colour,
            dash: Dash::Solid,
            width: 2,
            markers: false,
        }
    }
    /// The same series, dashed.
    pub fn dashed(mut self) -> Self {
        self.dash = Dash::Dashed;
        self
    }
    /// The same series, dotted.
    pub fn dotted(mut self) -> Self {
        self.dash = Dash::Dotted;
        self
    }
    /// The same series with a marker at each data point.
    pub fn with_markers(mut self) -> Self {
        self.markers = true;
        self
    }
}

/// A text placed at a data position of a chart.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Note {
    pub at: (f64, f64),
    pub text: String,
    pub colour: RGBColor,
}

/// A line chart: title, two axes, series, legend position and notes.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct LineChart {
    pub title: String,
    pub x: Axis,
    pub y: Axis,
    pub series: Vec<Series>,
    pub legend: SeriesLabelPosition,
    pub notes: Vec<Note>,
}

impl LineChart {
    /// A chart with no series yet, legend at the upper right.
    pub fn new(title: impl Into<String>, x: Axis, y: Axis) -> Self {
        Self {
            title: title.into(),
            x,
            y,
            series: Vec::new(),
            legend: SeriesLabelPosition::UpperRight,
            notes: Vec::new(),
        }
    }
}

/// Clips the segment `a`–`b` to the box `[x0, x1] × [y0, y1]` (Liang–Barsky).
fn clip_segment(
    a: (f64, f64),
    b: (f64, f64),
    (x0, x1, y0, y1): (f64, f64, f64, f64),
) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| {
        if t == 0.0 {
            a
        } else if t == 1.0 {
            b
        } else {
            (a.0 + t * dx, a.1 + t * dy)
        }
    };
    Some((at(t0), at(t1)))
}

/// Splits a polyline (in axis space, `None` = a gap) into the pieces inside the box.
pub(crate) fn clip_polyline(
    points: &[Option<(f64, f64)>],
    bounds: (f64, f64, f64, f64),
) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut cur: Vec<(f64, f64)> = Vec::new();
    let flush = |cur: &mut Vec<(f64, f64)>, out: &mut Vec<Vec<(f64, f64)>>| {
        if cur.len() >= 2 {
            out.push(std::mem::take(cur));
        } else {
            cur.clear();
        }
    };
    for w in points.windows(2) {
        match (w[0], w[1]) {
            (Some(a), Some(b)) => match clip_segment(a, b, bounds) {
                Some((p, q)) => {
                    if cur.last() != Some(&p) {
                        flush(&mut cur, &mut out);
                        cur.push(p);
                    }
                    cur.push(q);
                    if q != b {
                        flush(&mut cur, &mut out);
                    }
                }
                None => flush(&mut cur, &mut out),
            },
            _ => flush(&mut cur, &mut out),
        }
    }
    flush(&mut cur, &mut out);
    out
}

/// Draws a line chart into `area`.
pub(crate) fn draw_line_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    c: &LineChart,
) -> Result<(), Fail> {
    let mut chart = build_chart(area, &c.title, &c.x, &c.y, true)?;
    let (x0, x1) = c.x.range();
    let (y0, y1) = c.y.range();
    let bounds = (x0, x1, y0, y1);
    let mut any_label = false;
    for s in &c.series {
        let pts: Vec<Option<(f64, f64)>> = s
            .points
            .iter()
            .map(|&(x, y)| Some((c.x.to_axis(x)?, c.y.to_axis(y)?)))
            .collect();
        let style = ShapeStyle {
            color: s.colour.to_rgba(),
            filled: false,
            stroke_width: s.width,
        };
        for piece in clip_polyline(&pts, bounds) {
            match s.dash {
                Dash::Solid => chart.draw_series(LineSeries::new(piece, style))?,
                Dash::Dashed => chart.draw_series(DashedLineSeries::new(piece, 9, 6, style))?,
                Dash::Dotted => chart.draw_series(DashedLineSeries::new(piece, 2, 4, style))?,
            };
        }
        if s.markers {
            let inside = pts.iter().flatten().filter(|&&(x, y)| {
                x >= x0 && x <= x1 && y >= y0 && y <= y1 && x.is_finite() && y.is_finite()
            });
            let marker_style = s.colour.filled();
            chart.draw_series(
                inside.map(|&(x, y)| Circle::new((x, y), s.width + 2, marker_style)),
            )?;
        }
        if let Some(label) = &s.label {
            let colour = s.colour;
            let width = s.width;
            let dash = s.dash;
            let markers = s.markers;
            chart
                .draw_series(std::iter::empty::<Circle<(f64, f64), u32>>())?
                .label(label.as_str())
                .legend(move |at| {
                    let style = ShapeStyle {
                        color: colour.to_rgba(),
                        filled: false,
                        stroke_width: width,
                    };
                    let p = legend_pieces(dash);
                    let seg = |(a, b): (i32, i32)| PathElement::new(vec![(a, 0), (b, 0)], style);
                    let marker = if markers {
                        colour.filled()
                    } else {
                        TRANSPARENT.filled()
                    };
                    EmptyElement::at(at)
                        + seg(p[0])
                        + seg(p[1])
                        + seg(p[2])
                        + Circle::new((12, 0), width + 2, marker)
                });
            any_label = true;
        }
    }
    for n in &c.notes {
        if let (Some(x), Some(y)) = (c.x.to_axis(n.at.0), c.y.to_axis(n.at.1)) {
            if x >= x0 && x <= x1 && y >= y0 && y <= y1 {
                chart.draw_series(std::iter::once(Text::new(
                    n.text.clone(),
                    (x, y),
                    (FONT, 13).into_font().color(&n.colour),
                )))?;
            }
        }
    }
    if any_label {
        chart
            .configure_series_labels()
            .position(c.legend.clone())
            .background_style(WHITE.mix(0.9))
            .border_style(RGBColor(120, 120, 120))
            .label_font((FONT, 13))
            .margin(8)
            .draw()?;
    }
    Ok(())
}

/// The three segments of a legend sample: its line, dashes drawn as gaps.
fn legend_pieces(dash: Dash) -> [(i32, i32); 3] {
    match dash {
        Dash::Solid => [(0, 8), (8, 16), (16, 24)],
        Dash::Dashed => [(0, 6), (9, 15), (18, 24)],
        Dash::Dotted => [(0, 2), (11, 13), (22, 24)],
    }
}

/// The eight colours the line charts cycle through (colour-blind friendly, Okabe–Ito order).
pub(crate) const PALETTE: [RGBColor; 8] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
    RGBColor(150, 150, 30),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clipping_keeps_inside_and_cuts_at_the_border() {
        let b = (0.0, 1.0, 0.0, 1.0);
        let pts = [Some((-1.0, 0.5)), Some((0.5, 0.5)), Some((2.0, 0.5))];
        let pieces = clip_polyline(&pts, b);
        assert_eq!(pieces, vec![vec![(0.0, 0.5), (0.5, 0.5), (1.0, 0.5)]]);
        // Leaving and re-entering gives two pieces; a gap (None) splits too.
        let pts = [
            Some((0.2, 0.2)),
            Some((0.2, 3.0)),
            Some((0.8, 0.2)),
            None,
            Some((0.1, 0.1)),
            Some((0.3, 0.3)),
        ];
        let pieces = clip_polyline(&pts, b);
        assert_eq!(pieces.len(), 3);
        assert_eq!(pieces[0], vec![(0.2, 0.2), (0.2, 1.0)]);
        // The second piece enters through y = 1 at x = 0.2 + 0.6·(2/2.8).
        let x = 0.2 + 0.6 * (2.0 / 2.8);
        assert!((pieces[1][0].0 - x).abs() < 1e-12 && pieces[1][0].1 == 1.0);
        assert_eq!(pieces[2], vec![(0.1, 0.1), (0.3, 0.3)]);
        // Entirely outside: nothing.
        assert!(clip_polyline(&[Some((2.0, 2.0)), Some((3.0, 3.0))], b).is_empty());
    }
}
