//! Drawing helpers shared by the figures: axes with linear or logarithmic scales and chosen tick
//! marks, line charts that clip their data to the axes (plotters draws points outside an axis
//! range on the border, so nothing is handed to it unclipped), heat maps on rectangular and
//! hemispherical grids with a quantised colour scale, colour bars, and the page frame (title on
//! top, the caption naming the paper and figure at the bottom).
//!
//! Everything here works in *axis space*: a logarithmic axis is drawn as a linear plotters axis
//! over log_b of the data, with tick marks placed and labelled by [`Axis`]. That keeps one
//! concrete chart type for every combination of linear and logarithmic axes.

use super::Fail;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The font family every figure uses; registered from the compiled-in DejaVu Sans.
pub(crate) const FONT: &str = "sans-serif";

/// The chart type of every panel: both axes linear in axis space, with explicit ticks.
pub(crate) type Chart2d<'a, DB> = ChartContext<'a, DB, Cartesian2d<Ticked, Ticked>>;

/// A linear plotters coordinate over `[lo, hi]` whose bold (labelled) and light (grid) tick
/// positions are given, not computed by plotters.
#[derive(Debug, Clone)]
pub(crate) struct Ticked {
    lo: f64,
    hi: f64,
    bold: Vec<f64>,
    light: Vec<f64>,
}

impl Ticked {
    fn new(lo: f64, hi: f64, bold: Vec<f64>, light: Vec<f64>) -> Self {
        Self {
            lo,
            hi,
            bold,
            light,
        }
    }
}

impl Ranged for Ticked {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, v: &f64, limit: (i32, i32)) -> i32 {
        if self.hi == self.lo {
            return (limit.0 + limit.1) / 2;
        }
        let t = (v - self.lo) / (self.hi - self.lo);
        let len = f64::from(limit.1 - limit.0);
        let px = f64::from(limit.0) + (len * t).round();
        // Keep pixel positions finite and inside i32 even for wild values.
        px.clamp(-1e6, 1e6) as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.light.clone()
        } else {
            self.bold.clone()
        }
    }

    fn range(&self) -> std::ops::Range<f64> {
        self.lo..self.hi
    }
}

/// How an axis maps data to position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Scale {
    /// Position proportional to the value.
    Linear,
    /// Position proportional to log_b of the value (b > 1).
    Log(f64),
}

/// One axis: its label (with the unit), its data range and its scale.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Axis {
    pub label: String,
    pub min: f64,
    pub max: f64,
    pub scale: Scale,
}

impl Axis {
    /// A linear axis over `[min, max]`.
    pub fn linear(label: impl Into<String>, min: f64, max: f64) -> Self {
        Self {
            label: label.into(),
            min,
            max,
            scale: Scale::Linear,
        }
    }

    /// A base-10 logarithmic axis over `[min, max]`, `0 < min < max`.
    pub fn log10(label: impl Into<String>, min: f64, max: f64) -> Self {
        Self {
            label: label.into(),
            min,
            max,
            scale: Scale::Log(10.0),
        }
    }

    /// A logarithmic axis of base `b`.
    pub fn log_base(label: impl Into<String>, min: f64, max: f64, b: f64) -> Self {
        Self {
            label: label.into(),
            min,
            max,
            scale: Scale::Log(b),
        }
    }

    /// Data value → axis space; `None` for values the axis cannot show at all (non-finite, or
    /// ≤ 0 on a logarithmic axis). Values outside `[min, max]` are mapped, not dropped: the
    /// drawing code clips.
    pub fn to_axis(&self, v: f64) -> Option<f64> {
        if !v.is_finite() {
            return None;
        }
        match self.scale {
            Scale::Linear => Some(v),
            Scale::Log(b) => (v > 0.0).then(|| v.ln() / b.ln()),
        }
    }

    /// Axis space → data value.
    pub fn to_data(&self, a: f64) -> f64 {
        match self.scale {
            Scale::Linear => a,
            Scale::Log(b) => b.powf(a),
        }
    }

    /// The axis range in axis space.
    pub fn range(&self) -> (f64, f64) {
        let lo = self.to_axis(self.min).unwrap_or(0.0);
        let hi = self.to_axis(self.max).unwrap_or(1.0);
        (lo, hi)
    }

    /// Bold (labelled) and light (grid only) tick positions, in axis space.
    pub fn ticks(&self) -> (Vec<f64>, Vec<f64>) {
        let (lo, hi) = self.range();
        let eps = 1e-9 * (hi - lo).abs().max(1e-300);
        let inside = |v: f64| v >= lo - eps && v <= hi + eps;
        match self.scale {
            Scale::Linear => {
                let step = nice_step((hi - lo) / 8.0);
                let bold = multiples(lo, hi, step, eps);
                let mantissa = step / 10f64.powf(step.log10().floor());
                let minor = if (mantissa - 2.0).abs() < 1e-9 {
                    2.0
                } else {
                    5.0
                };
                let light = multiples(lo, hi, step / minor, eps);
                (bold, light)
            }
            Scale::Log(b) => {
                let decades = hi - lo;
                let first = (lo - eps).ceil() as i64;
                let last = (hi + eps).floor() as i64;
                let every = if decades > 12.0 {
                    3
                } else if decades > 7.0 {
                    2
                } else {
                    1
                };
                let mut bold: Vec<f64> = (first..=last)
                    .filter(|e| e.rem_euclid(every) == 0)
                    .map(|e| e as f64)
                    .collect();
                let mut light = Vec::new();
                if (b - 10.0).abs() < 1e-12 && decades <= 6.0 {
                    let lf = (lo - eps).floor() as i64;
                    for e in lf..=last {
                        for m in 2..10 {
                            let v = e as f64 + (m as f64).log10();
                            if inside(v) {
                                light.push(v);
                            }
                        }
                    }
                    if decades <= 2.0 + 1e-9 {
                        // Two decades or less: label 2 and 5 as well.
                        for e in lf..=last {
                            for m in [2.0f64, 5.0] {
                                let v = e as f64 + m.log10();
                                if inside(v) {
                                    bold.push(v);
                                }
                            }
                        }
                        bold.sort_by(f64::total_cmp);
                    }
                } else if bold.len() < 2 {
                    let step = nice_step((hi - lo) / 5.0);
                    bold = multiples(lo, hi, step, eps);
                }
                light.extend(bold.iter().copied());
                light.sort_by(f64::total_cmp);
                (bold, light)
            }
        }
    }

    /// The label of a tick at axis-space position `a`.
    pub fn tick_label(&self, a: f64) -> String {
        match self.scale {
            Scale::Linear => {
                let (lo, hi) = self.range();
                fmt_linear(a, nice_step((hi - lo) / 8.0))
            }
            Scale::Log(b) => {
                let e = a.round();
                if (a - e).abs() < 1e-9 {
                    let e = e as i64;
                    if (b - 10.0).abs() < 1e-12 && (-2..=3).contains(&e) {
                        fmt_plain(10f64.powi(e as i32))
                    } else {
                        format!("{}{}", fmt_plain(b), superscript(e))
                    }
                } else {
                    fmt_plain(self.to_data(a))
                }
            }
        }
    }
}

/// 1, 2 or 5 times a power of ten, at least `raw`.
fn nice_step(raw: f64) -> f64 {
    if raw.is_nan() || raw <= 0.0 || raw.is_infinite() {
        return 1.0;
    }
    let p = 10f64.powf(raw.log10().floor());
    for m in [1.0, 2.0, 5.0, 10.0] {
        if m * p >= raw * (1.0 - 1e-12) {
            return m * p;
        }
    }
    10.0 * p
}

fn multiples(lo: f64, hi: f64, step: f64, eps: f64) -> Vec<f64> {
    let first = ((lo - eps) / step).ceil() as i64;
    let last = ((hi + eps) / step).floor() as i64;
    (first..=last).map(|i| i as f64 * step).collect()
}

/// A tick label on a linear axis with the decimals the step needs.
fn fmt_linear(v: f64, step: f64) -> String {
    let decimals = (0..12)
        .find(|&d| {
            let scaled = step * 10f64.powi(d);
            (scaled - scaled.round()).abs() < 1e-9 * scaled.max(1.0)
        })
        .unwrap_or(12) as usize;
    let s = format!(
        "{:.*}",
        decimals,
        if v.abs() < 1e-12 * step { 0.0 } else { v }
    );
    trim_zeros(&s)
}

/// A number without trailing zeros, up to four significant decimals.
pub(crate) fn fmt_plain(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    let mag = v.abs().log10().floor();
    let decimals = (3.0 - mag).clamp(0.0, 12.0) as usize;
    trim_zeros(&format!("{v:.decimals$}"))
}

fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// An integer in Unicode superscript digits (DejaVu Sans has them all).
pub(crate) fn superscript(e: i64) -> String {
    let digits = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = String::new();
    if e < 0 {
        s.push('⁻');
    }
    for c in e.unsigned_abs().to_string().chars() {
        s.push(digits[c as usize - '0' as usize]);
    }
    s
}

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

/// Sizes of a chart's text and label areas, in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct ChartStyle {
    pub title_size: u32,
    pub x_label_area: u32,
    pub y_label_area: u32,
    pub tick_size: u32,
    pub desc_size: u32,
    pub margin: u32,
}

impl Default for ChartStyle {
    fn default() -> Self {
        Self {
            title_size: 17,
            x_label_area: 46,
            y_label_area: 64,
            tick_size: 13,
            desc_size: 15,
            margin: 8,
        }
    }
}

/// Builds a chart over two axes with the mesh and axis labels drawn.
pub(crate) fn build_chart<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: &str,
    x: &Axis,
    y: &Axis,
    grid_lines: bool,
) -> Result<Chart2d<'a, DB>, Fail> {
    build_chart_styled(area, title, x, y, grid_lines, &ChartStyle::default())
}

/// [`build_chart`] with explicit text and label-area sizes (for small panels).
pub(crate) fn build_chart_styled<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    title: &str,
    x: &Axis,
    y: &Axis,
    grid_lines: bool,
    style: &ChartStyle,
) -> Result<Chart2d<'a, DB>, Fail> {
    let (x0, x1) = x.range();
    let (y0, y1) = y.range();
    let (xb, xl) = x.ticks();
    let (yb, yl) = y.ticks();
    let mut builder = ChartBuilder::on(area);
    builder
        .margin(style.margin)
        .margin_right(2 * style.margin)
        .x_label_area_size(style.x_label_area)
        .y_label_area_size(style.y_label_area);
    if !title.is_empty() {
        builder.caption(title, (FONT, style.title_size));
    }
    let mut chart =
        builder.build_cartesian_2d(Ticked::new(x0, x1, xb, xl), Ticked::new(y0, y1, yb, yl))?;
    let xf = |v: &f64| x.tick_label(*v);
    let yf = |v: &f64| y.tick_label(*v);
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x.label.as_str())
        .y_desc(y.label.as_str())
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .axis_desc_style((FONT, style.desc_size))
        .label_style((FONT, style.tick_size))
        .bold_line_style(RGBColor(205, 205, 205))
        .light_line_style(RGBColor(238, 238, 238));
    if !grid_lines {
        mesh.disable_mesh();
    }
    mesh.draw()?;
    Ok(chart)
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

/// A colour scale: a value range on an axis (linear or logarithmic), quantised into `levels`
/// bands of the jet colour map (blue low, red high, as in the papers' plots).
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ColourScale {
    pub axis: Axis,
    pub levels: usize,
}

impl ColourScale {
    /// The band of a value, clamped to the range; `None` where the value cannot be shown.
    pub fn level(&self, v: f64) -> Option<usize> {
        let a = self.axis.to_axis(v)?;
        let (lo, hi) = self.axis.range();
        let t = ((a - lo) / (hi - lo)).clamp(0.0, 1.0);
        Some(((t * self.levels as f64) as usize).min(self.levels - 1))
    }

    /// The colour of a band.
    pub fn level_colour(&self, level: usize) -> RGBColor {
        jet((level as f64 + 0.5) / self.levels as f64)
    }
}

/// The jet colour map at t ∈ [0, 1].
pub(crate) fn jet(t: f64) -> RGBColor {
    let c = |x: f64| (255.0 * (1.5 - x.abs()).clamp(0.0, 1.0)).round() as u8;
    RGBColor(c(4.0 * t - 3.0), c(4.0 * t - 2.0), c(4.0 * t - 1.0))
}

/// A field on a rectangular grid: `values[j * nx + i]` for the cell `[x_i, x_{i+1}] ×
/// [y_j, y_{j+1}]` in data coordinates; `None` cells are left blank.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Grid {
    pub x_edges: Vec<f64>,
    pub y_edges: Vec<f64>,
    pub values: Vec<Option<f64>>,
}

impl Grid {
    /// Evaluates `f` at each cell centre of an `nx × ny` grid over `[x0, x1] × [y0, y1]`.
    pub fn sample(
        (x0, x1, nx): (f64, f64, usize),
        (y0, y1, ny): (f64, f64, usize),
        mut f: impl FnMut(f64, f64) -> Option<f64>,
    ) -> Self {
        let x_edges: Vec<f64> = (0..=nx)
            .map(|i| x0 + (x1 - x0) * i as f64 / nx as f64)
            .collect();
        let y_edges: Vec<f64> = (0..=ny)
            .map(|j| y0 + (y1 - y0) * j as f64 / ny as f64)
            .collect();
        let mut values = Vec::with_capacity(nx * ny);
        for j in 0..ny {
            for i in 0..nx {
                let x = 0.5 * (x_edges[i] + x_edges[i + 1]);
                let y = 0.5 * (y_edges[j] + y_edges[j + 1]);
                values.push(f(x, y).filter(|v| v.is_finite()));
            }
        }
        Self {
            x_edges,
            y_edges,
            values,
        }
    }
}

/// Draws a grid into a chart whose axes are linear in the grid's coordinates. Runs of
/// neighbouring cells in one row that fall in the same colour band are merged into one
/// rectangle, which keeps the SVG small.
pub(crate) fn draw_grid<DB: DrawingBackend>(
    chart: &mut Chart2d<'_, DB>,
    grid: &Grid,
    scale: &ColourScale,
) -> Result<(), Fail> {
    let nx = grid.x_edges.len() - 1;
    let ny = grid.y_edges.len() - 1;
    let mut rects = Vec::new();
    for j in 0..ny {
        let mut i = 0;
        while i < nx {
            let Some(level) = grid.values[j * nx + i].and_then(|v| scale.level(v)) else {
                i += 1;
                continue;
            };
            let start = i;
            while i + 1 < nx
                && grid.values[j * nx + i + 1].and_then(|v| scale.level(v)) == Some(level)
            {
                i += 1;
            }
            rects.push(Rectangle::new(
                [
                    (grid.x_edges[start], grid.y_edges[j]),
                    (grid.x_edges[i + 1], grid.y_edges[j + 1]),
                ],
                scale.level_colour(level).filled(),
            ));
            i += 1;
        }
    }
    chart.draw_series(rects)?;
    Ok(())
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
/// [`crate::measure::sweep`]: the source lies towards (cos el · sin az, sin el, cos el · cos az).
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
            area.draw(&Polygon::new(poly, scale.level_colour(level).filled()))?;
            j += 1;
        }
    }
    // Elevation rings at 0°, 30°, 60° and the axis from behind to in front.
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
            TextStyle::from((FONT, 12).into_font()).pos(pos),
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
        .right_y_label_area_size(58)
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
        .axis_desc_style((FONT, 14))
        .label_style((FONT, 12))
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

/// Fills the page white, writes the title at the top and the caption lines at the bottom, and
/// returns the area left between them.
pub(crate) fn frame<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    title: &str,
    caption: &[&str],
) -> Result<DrawingArea<DB, Shift>, Fail> {
    root.fill(&WHITE)?;
    let (w, h) = root.dim_in_pixel();
    root.draw(&Text::new(
        title.to_string(),
        (w as i32 / 2, 10),
        TextStyle::from((FONT, 22).into_font()).pos(Pos::new(HPos::Center, VPos::Top)),
    ))?;
    let line_h = 18;
    let bottom = caption.len() as i32 * line_h + 10;
    for (k, line) in caption.iter().enumerate() {
        // Shrink a long line until it fits the page width.
        let mut size = 14.0;
        while size > 9.0 {
            let (tw, _) =
                root.estimate_text_size(line, &TextStyle::from((FONT, size).into_font()))?;
            if tw as f64 <= f64::from(w) - 28.0 {
                break;
            }
            size -= 0.5;
        }
        root.draw(&Text::new(
            (*line).to_string(),
            (14, h as i32 - bottom + 4 + k as i32 * line_h),
            TextStyle::from((FONT, size).into_font())
                .color(&RGBColor(50, 50, 50))
                .pos(Pos::new(HPos::Left, VPos::Top)),
        ))?;
    }
    Ok(root.margin(44, bottom, 6, 6))
}

/// A page of line charts side by side: the common shape of the closed-form figures.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Charts {
    pub size: (u32, u32),
    pub title: String,
    pub caption: Vec<String>,
    pub charts: Vec<LineChart>,
}

impl super::Figure for Charts {
    fn size(&self) -> (u32, u32) {
        self.size
    }

    fn draw<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), Fail> {
        let caption: Vec<&str> = self.caption.iter().map(String::as_str).collect();
        let body = frame(root, &self.title, &caption)?;
        let panels = body.split_evenly((1, self.charts.len().max(1)));
        for (panel, chart) in panels.iter().zip(&self.charts) {
            draw_line_chart(panel, chart)?;
        }
        Ok(())
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

/// Evenly spaced samples of `[a, b]`, both ends included.
pub(crate) fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1).max(1) as f64)
        .collect()
}

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

    #[test]
    fn log_axis_ticks_are_decades_and_labels_read_as_numbers() {
        let a = Axis::log10("S", 1.0, 1e4);
        let (bold, light) = a.ticks();
        assert_eq!(bold, vec![0.0, 1.0, 2.0, 3.0, 4.0]);
        assert_eq!(light.len(), 4 * 8 + 5);
        assert_eq!(a.tick_label(3.0), "1000");
        assert_eq!(a.tick_label(4.0), "10⁴");
        assert_eq!(Axis::log10("S", 1e-6, 1.0).tick_label(-6.0), "10⁻⁶");
        assert_eq!(a.to_axis(100.0), Some(2.0));
        assert_eq!(a.to_axis(0.0), None);
        let five = Axis::log_base("E", 1.0, 625.0, 5.0);
        assert_eq!(five.ticks().0, vec![0.0, 1.0, 2.0, 3.0, 4.0]);
        assert_eq!(five.tick_label(2.0), "5²");
        // Less than a decade: 2 and 5 are labelled too.
        let short = Axis::log10("g", 0.1, 1.0);
        assert_eq!(short.ticks().0.len(), 4);
    }

    #[test]
    fn linear_ticks_are_round_numbers() {
        let a = Axis::linear("z", 1.0, 20.0);
        let (bold, _) = a.ticks();
        assert_eq!(bold, vec![5.0, 10.0, 15.0, 20.0]);
        let k = Axis::linear("k", 1.0, 16.0);
        assert_eq!(
            k.ticks().0,
            vec![2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0]
        );
        assert_eq!(k.tick_label(6.0), "6");
        let small = Axis::linear("g", 0.0, 1.05);
        assert_eq!(small.tick_label(0.4), "0.4");
        let b = Axis::linear("η", -1.0, 1.0);
        assert_eq!(b.ticks().0, vec![-1.0, -0.5, 0.0, 0.5, 1.0]);
        assert_eq!(b.tick_label(-0.5), "-0.5");
        assert_eq!(b.tick_label(0.0), "0");
    }

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
        // Jet: blue at the bottom, red at the top.
        assert_eq!(jet(0.0), RGBColor(0, 0, 128));
        assert_eq!(jet(1.0), RGBColor(128, 0, 0));
        assert_eq!(jet(0.5), RGBColor(128, 255, 128));
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
