//! Line charts: series, notes and legends, with the data clipped to the axes (plotters draws
//! points outside an axis range on the border, so nothing is handed to it unclipped).

use super::super::Fail;
use super::axis::{build_chart_styled, Axis, ChartStyle, TICK};
use super::fine::{
    clip_to_rect, draw_fine_line, fill_fine_points, fill_fine_polygon, stroke_fine_outline,
    to_backend,
};
use super::label::{place_label, place_note, text_in_box, Obstacles, Rect, LABEL_PAD};
use super::legend::{draw_legend_clear, Entry, Placed};
use super::marker::Marker;
use super::probe::probe_area;
use super::FONT;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The size of direct labels, notes and legend texts.
const LABEL_SIZE: u32 = 13;

/// How a series' line is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Dash {
    Solid,
    Dashed,
    Dotted,
}

/// Where a line without a marker at every point carries its shape: at these fractions of its
/// points, shifted a little per series so that the markers of lines that meet do not coincide.
const MARKER_AT: [f64; 5] = [0.08, 0.29, 0.5, 0.71, 0.92];

/// One line of a line chart, in data coordinates.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Series {
    pub label: Option<String>,
    pub points: Vec<(f64, f64)>,
    pub colour: RGBColor,
    pub dash: Dash,
    pub width: u32,
    pub markers: bool,
    /// A reference line (an asymptote, an optimum): never markers, in the chart or its legend.
    pub reference: bool,
    /// The label is written at the line's right end, just above it, instead of in the legend.
    pub direct: bool,
    /// With `direct`: the label's point is the one at this x instead of the last.
    pub direct_at: Option<f64>,
    /// The marker's shape where it is not its colour's ([`Marker::of`]): a scheme drawn in one
    /// colour for two lights keeps its colour and differs by shape.
    pub shape: Option<Marker>,
    /// A line no other label is read as belonging to (a grey reference line among coloured
    /// curves): it still keeps labels off itself, but a label nearer it than its own line is
    /// not taken for its label.
    pub quiet: bool,
    /// A key entry only (no points): its sample shows the line and the marker of a line drawn
    /// elsewhere without a label (its markers a separate series).
    pub sample: bool,
    /// The markers' radius in units where it is not the line's width + 2 (a small one-column
    /// plot, whose markers would be wider than the spacing of its curves).
    pub marker_radius: Option<i32>,
    /// Hollow markers (outlines 2 units wide), drawn after every filled one: a line that lies
    /// under another still shows its points.
    pub hollow: bool,
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
            reference: false,
            direct: false,
            direct_at: None,
            shape: None,
            quiet: false,
            sample: false,
            marker_radius: None,
            hollow: false,
        }
    }
    /// The same series labelled directly at its right end instead of in the legend.
    pub fn direct(mut self) -> Self {
        self.direct = true;
        self
    }
    /// The same series as a reference line: no markers.
    pub fn reference(mut self) -> Self {
        self.reference = true;
        self
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
    /// Whether the legend is drawn (a panel whose key another panel of the figure shows has
    /// none).
    pub show_legend: bool,
    pub notes: Vec<Note>,
    /// Horizontal bands shaded behind the series: from, to (data units of y), colour.
    pub bands: Vec<(f64, f64, RGBColor)>,
    /// The legend goes below the plot even where a clear place inside exists (a figure's one
    /// key under all its panels).
    pub legend_below: bool,
    /// The legend's columns where they fit (entries row by row); `None`: as many as fit.
    pub legend_columns: Option<usize>,
    /// The width kept left of the plot for the y tick labels and the y axis' name, where the
    /// default's is too narrow (lloyd2005-fig7's m×10ⁿ labels ran into its name).
    pub y_label_area: Option<u32>,
    /// The height kept under the plot for the x tick labels and the x axis' name, where it is
    /// not the default's (a panel whose x axis is named under another panel: ticks only).
    pub x_label_area: Option<u32>,
    /// The margin round the chart in its cell where it is not the default's 8 units (a
    /// one-column page whose plots need the height).
    pub margin: Option<u32>,
    /// Markers cut at the plot's frame, so that none is drawn across it (one at the top of an
    /// axis range, such as a curve's marker just under n′ = 10⁴).
    pub clip_markers: bool,
    /// Words written under two x values' tick labels, on a row of their own over the x axis'
    /// name (the x label area grows by it), where the tick labels alone do not say which end
    /// is which (martin-tan-fig6 (b) reads 0, 45, 90, 45, 0: "behind" under the first 0, "in
    /// front" under the last).
    pub x_ends: Option<[(f64, String); 2]>,
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
            show_legend: true,
            notes: Vec::new(),
            bands: Vec::new(),
            legend_below: false,
            legend_columns: None,
            y_label_area: None,
            x_label_area: None,
            margin: None,
            clip_markers: false,
            x_ends: None,
        }
    }
}

/// Clips the segment `a`–`b` to the box `[x0, x1] × [y0, y1]` (Liang–Barsky).
pub(crate) fn clip_segment(
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

/// Draws a line chart into `area`, its legend inside the plot where it covers no data and
/// below the plot otherwise ([`legend_below`]).
pub(crate) fn draw_line_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    c: &LineChart,
) -> Result<(), Fail> {
    let size = area.dim_in_pixel();
    let below = legend_below(size, c, f64::from(size.0))?;
    draw_line_chart_reserving(area, c, below).map(|_| ())
}

/// The height of a strip `width` units wide that a chart drawn on an area of `size` units
/// needs below it for its legend: 0 where the legend finds a place inside the plot that covers
/// no line, marker or label (the chart is laid out once on a [`super::probe::Probe`] to find
/// out).
pub(crate) fn legend_below(size: (u32, u32), c: &LineChart, width: f64) -> Result<u32, Fail> {
    if !c.show_legend {
        return Ok(0);
    }
    Ok(match draw_chart(&probe_area(size), c, None, width)? {
        Placed::Inside => 0,
        Placed::Below(h) => h,
    })
}

/// Draws a line chart into `area` with `below` units under it kept for its legend, which goes
/// there only where no clear place inside the plot exists. Returns where the legend went.
pub(crate) fn draw_line_chart_reserving<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    c: &LineChart,
    below: u32,
) -> Result<Placed, Fail> {
    if below == 0 {
        return draw_line_chart_over(area, c, None);
    }
    let h = area.dim_in_pixel().1;
    let (top, strip) = area.split_vertically(h.saturating_sub(below));
    draw_line_chart_over(&top, c, Some(&strip))
}

/// Draws a line chart into `area`, its legend inside the plot where it covers no data, else in
/// `strip` (an area below it, such as one under a row of panels). Returns where it went.
pub(crate) fn draw_line_chart_over<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    c: &LineChart,
    strip: Option<&DrawingArea<DB, Shift>>,
) -> Result<Placed, Fail> {
    let width = f64::from(area.dim_in_pixel().0);
    draw_chart(area, c, strip, width)
}

/// Draws a line chart into `area`, its legend (if any) where [`draw_legend_clear`] puts it,
/// in `strip` when it goes below the plot (without a strip: the height one `below_width` wide
/// would need).
fn draw_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    c: &LineChart,
    strip: Option<&DrawingArea<DB, Shift>>,
    below_width: f64,
) -> Result<Placed, Fail> {
    let tick_font = TextStyle::from((FONT, ChartStyle::default().tick_size).into_font());
    // The row of `x_ends`: their height less 2 units of the room the x label area leaves
    // between the tick labels and the axis' name.
    let ends_row = match &c.x_ends {
        Some(_) => area
            .estimate_text_size("0", &tick_font)?
            .1
            .saturating_sub(2),
        None => 0,
    };
    let style = ChartStyle {
        y_label_area: c.y_label_area.unwrap_or(ChartStyle::default().y_label_area),
        x_label_area: c.x_label_area.unwrap_or(ChartStyle::default().x_label_area) + ends_row,
        margin: c.margin.unwrap_or(ChartStyle::default().margin),
        ..ChartStyle::default()
    };
    let mut chart = build_chart_styled(area, &c.title, &c.x, &c.y, true, &style)?;
    if let Some(ends) = &c.x_ends {
        draw_x_ends(area, &chart, &c.x, ends, &tick_font)?;
    }
    let (x0, x1) = c.x.range();
    let (y0, y1) = c.y.range();
    let bounds = (x0, x1, y0, y1);
    let colours = {
        let mut cs: Vec<RGBColor> = c
            .series
            .iter()
            .filter(|s| s.label.is_some())
            .map(|s| s.colour)
            .collect();
        cs.dedup();
        cs.sort_by_key(|c| (c.0, c.1, c.2));
        cs.dedup();
        cs.len()
    };
    for &(from, to, colour) in &c.bands {
        if let (Some(a), Some(b)) = (c.y.to_axis(from), c.y.to_axis(to)) {
            let (a, b) = (a.clamp(y0, y1), b.clamp(y0, y1));
            chart.draw_series(std::iter::once(Rectangle::new(
                [(x0, a), (x1, b)],
                colour.filled(),
            )))?;
        }
    }
    let to = to_backend(&chart);
    let plot = chart.plotting_area().strip_coord_spec();
    let mut obstacles = Obstacles::default();
    let mut entries = Vec::new();
    // The markers, drawn after the labels and notes so that no white halo hides one.
    let mut markers = Vec::new();
    // Each direct label: its series, its drawn points (backend units) and the one asked for.
    let mut direct = Vec::new();
    for (k, s) in c.series.iter().enumerate() {
        if s.quiet {
            obstacles.quiet.push(k);
        }
        let pts: Vec<Option<(f64, f64)>> = s
            .points
            .iter()
            .map(|&(x, y)| Some((c.x.to_axis(x)?, c.y.to_axis(y)?)))
            .collect();
        for piece in clip_polyline(&pts, bounds) {
            draw_fine_line(&chart, &piece, s.colour, s.width, s.dash)?;
            let px: Vec<(f64, f64)> = piece.iter().map(|&p| to(p)).collect();
            obstacles
                .segments
                .extend(px.windows(2).map(|w| (w[0], w[1], k)));
        }
        // Markers: at every point of a series that asks for them, and a few along every other
        // labelled line of a chart with more than one colour (greyscale print).
        let shape = s.shape.unwrap_or_else(|| Marker::of(s.colour));
        let along: Vec<(f64, f64)> = if s.reference {
            Vec::new()
        } else if s.markers {
            pts.iter().flatten().copied().collect()
        } else if s.label.is_some() && colours > 1 && pts.len() > 1 {
            let shift = 0.035 * (k % 3) as f64;
            MARKER_AT
                .iter()
                .filter_map(|f| {
                    pts[((f + shift - 0.035) * (pts.len() - 1) as f64).round() as usize]
                })
                .collect()
        } else {
            Vec::new()
        };
        let r = s.marker_radius.unwrap_or(s.width as i32 + 2);
        let outline = shape.outline(r);
        for at in along
            .into_iter()
            .filter(|&(x, y)| x >= x0 && x <= x1 && y >= y0 && y <= y1)
        {
            let p = to(at);
            markers.push((p, outline.clone(), s.colour, s.hollow));
            let m = Rect::anchored(p, Pos::new(HPos::Center, VPos::Center), 0.0, 0.0);
            obstacles.markers.push((m.grown(f64::from(r + 1)), k));
        }
        let inside = |p: &(f64, f64)| p.0 >= x0 && p.0 <= x1 && p.1 >= y0 && p.1 <= y1;
        let shown: Vec<(f64, f64)> = pts.iter().flatten().copied().filter(inside).collect();
        let anchor = s
            .direct_at
            .and_then(|x| {
                let a = c.x.to_axis(x)?;
                shown.iter().position(|p| (p.0 - a).abs() < 1e-9)
            })
            .or_else(|| {
                pts.last()
                    .copied()
                    .flatten()
                    .filter(inside)
                    .map(|_| shown.len() - 1)
            });
        match (&s.label, s.direct) {
            (Some(label), true) => {
                if let Some(i) = anchor {
                    direct.push((
                        k,
                        label,
                        shown.iter().map(|&p| to(p)).collect::<Vec<_>>(),
                        i,
                    ));
                }
            }
            (Some(label), false) => entries.push(Entry {
                label: label.clone(),
                colour: s.colour,
                width: s.width,
                dash: s.dash,
                marker: (!s.reference && (s.markers || s.sample || colours > 1)).then_some(shape),
                // A reference line always shows its line (it has no marker; with no points of
                // its own, a key for lines drawn elsewhere, the sample was empty).
                line: s.reference
                    || s.sample
                    || s.points
                        .windows(2)
                        .any(|w| w[0].1.is_finite() && w[1].1.is_finite()),
                hollow: s.hollow,
            }),
            (None, _) => {}
        }
    }
    // Direct labels beside their own line, clear of every other line, marker and label, near
    // the point asked for (its right end by default).
    let (xr, yr) = plot.get_pixel_range();
    let area = Rect {
        x0: f64::from(xr.start),
        y0: f64::from(yr.start),
        x1: f64::from(xr.end),
        y1: f64::from(yr.end),
    };
    for (k, label, points, i) in direct {
        let style = TextStyle::from((FONT, LABEL_SIZE).into_font());
        let (w, h) = plot.estimate_text_size(label, &style)?;
        let pad = f64::from(2 * LABEL_PAD);
        let size = (f64::from(w) + pad, f64::from(h) + pad);
        if let Some(r) = place_label(&points, i, size, &area, k, &obstacles) {
            text_in_box(
                &plot,
                &r,
                (label, HPos::Right),
                LABEL_SIZE,
                c.series[k].colour,
            )?;
            obstacles.boxes.push(r);
        }
    }
    // Notes on a white box, so that they read over the lines and the grid, moved a little
    // where they would cover a line or marker.
    for n in &c.notes {
        if let (Some(x), Some(y)) = (c.x.to_axis(n.at.0), c.y.to_axis(n.at.1)) {
            if x >= x0 && x <= x1 && y >= y0 && y <= y1 {
                let style = TextStyle::from((FONT, LABEL_SIZE).into_font());
                let (w, h) = plot.estimate_text_size(&n.text, &style)?;
                let size = (f64::from(w), f64::from(h));
                let r = place_note(to((x, y)), size, &area, &obstacles);
                text_in_box(&plot, &r, (&n.text, HPos::Left), LABEL_SIZE, n.colour)?;
                obstacles.boxes.push(r);
            }
        }
    }
    if c.legend_below {
        // No place inside is clear.
        obstacles.boxes.push(area);
    }
    markers.sort_by_key(|m| m.3);
    for (p, outline, colour, hollow) in &markers {
        if *hollow {
            stroke_fine_outline(&plot, *p, outline, *colour)?;
        } else if c.clip_markers {
            let points: Vec<(f64, f64)> = outline
                .iter()
                .map(|&(x, y)| (p.0 + f64::from(x), p.1 + f64::from(y)))
                .collect();
            fill_fine_points(&plot, clip_to_rect(&points, &area), *colour)?;
        } else {
            fill_fine_polygon(&plot, *p, outline, *colour)?;
        }
    }
    if c.show_legend {
        draw_legend_clear(
            &plot,
            strip,
            below_width,
            (&entries, c.legend_columns),
            &c.legend,
            &obstacles,
        )
    } else {
        Ok(Placed::Inside)
    }
}

/// Writes `ends` (x values and their words) centred under the x values' tick labels (which
/// stand [`TICK`] + 5 units under the plot, as tall as a "0"), 4 units under them.
fn draw_x_ends<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    chart: &super::axis::Chart2d<'_, DB>,
    x: &Axis,
    ends: &[(f64, String); 2],
    font: &TextStyle<'_>,
) -> Result<(), Fail> {
    let to = to_backend(chart);
    let y_axis = chart.y_range().start;
    let tick_h = area.estimate_text_size("0", font)?.1;
    let (bx, by) = area.get_base_pixel();
    let style = font.pos(Pos::new(HPos::Center, VPos::Top));
    for (v, word) in ends {
        let Some(a) = x.to_axis(*v) else { continue };
        let (px, bottom) = to((a, y_axis));
        let top = bottom.round() as i32 + TICK as i32 + 5 + tick_h as i32 + 4;
        area.draw(&Text::new(
            word.clone(),
            (px.round() as i32 - bx, top - by),
            style.clone(),
        ))?;
    }
    Ok(())
}

/// The line colours, each at least 3 : 1 against white (WCAG's least for lines; sixth figure
/// review, X-11): the warps PSM dark blue #00306E, the uniform map vermillion #D55E00 and
/// LiSPSM green #00664B (CIE L* 21, 54, 38); other quantities' reddish purple #CC79A7 (L* 61);
/// the schemes ZP teal #009CA6 and ZP+W rose #A82E66 (L* 59, 40); black; olive #96961E (L* 60);
/// FP+ZP+W brown #4D2E00 (L* 22). [`super::Look::colour`] names the warps' and schemes'.
pub(crate) const PALETTE: [RGBColor; 9] = [
    RGBColor(0, 48, 110),
    RGBColor(213, 94, 0),
    RGBColor(0, 102, 75),
    RGBColor(204, 121, 167),
    RGBColor(0, 156, 166),
    RGBColor(168, 46, 102),
    RGBColor(0, 0, 0),
    RGBColor(150, 150, 30),
    RGBColor(77, 46, 0),
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::chart::scheme::SWEEP;

    /// Greyscale (issue 25): the colours a figure may set side by side have their own marker
    /// shapes (the warps with the other colours, and the schemes with the other colours; a
    /// scheme has the shape of the warp at its place in the other set), and a chart of two
    /// solid lines of different colours draws that many marker polygons along each (counted in
    /// the SVG), and none for a chart of one colour (nor in its legend).
    #[test]
    fn lines_of_different_colours_carry_different_markers() {
        use super::super::Look;
        super::super::super::ensure_font().unwrap();
        let others = [PALETTE[3], PALETTE[6], PALETTE[7]];
        for set in [
            [Look::Psm, Look::Lispsm, Look::Uniform],
            [Look::Zp, Look::ZpW, Look::FpZpW],
        ] {
            let colours: Vec<RGBColor> = set
                .iter()
                .map(|l| l.colour())
                .chain(others)
                .chain(SWEEP)
                .collect();
            let shapes: Vec<Vec<(i32, i32)>> =
                colours.iter().map(|&c| Marker::of(c).outline(4)).collect();
            for i in 0..shapes.len() {
                for j in 0..i {
                    assert_ne!(shapes[i], shapes[j], "{set:?}: colours {i} and {j}");
                }
            }
        }
        assert_eq!(
            Marker::of(Look::Zp.colour()),
            Marker::of(Look::Psm.colour())
        );
        assert_eq!(Marker::of(Look::FpZpW.colour()), Marker::TriangleUp);
        let polygons = |colours: &[RGBColor]| {
            let mut c = LineChart::new(
                "t",
                Axis::linear("x", 0.0, 1.0),
                Axis::linear("y", 0.0, 1.0),
            );
            for (k, &col) in colours.iter().enumerate() {
                let y = 0.2 + 0.3 * k as f64;
                let pts = (0..=100).map(|i| (f64::from(i) / 100.0, y)).collect();
                c.series.push(Series::line(format!("s{k}"), pts, col));
            }
            let mut svg = String::new();
            {
                let area =
                    super::super::super::svg::Svg::new(&mut svg, (400, 300), 1).into_drawing_area();
                draw_line_chart(&area, &c).unwrap();
                area.present().unwrap();
            }
            svg.matches("<polygon").count()
        };
        // Five along each line and one in each legend entry.
        assert_eq!(
            polygons(&[PALETTE[0], PALETTE[1]]),
            2 * (MARKER_AT.len() + 1)
        );
        assert_eq!(polygons(&[PALETTE[0]]), 0);
    }

    /// Greyscale for sweeps: the five sweep colours get five shapes, by hand the star, pentagon,
    /// cross, saltire (×) and bowtie, none of them the shape of a palette colour (a sweep drawn
    /// beside schemes stays apart by shape), and each outline by hand at r = 4: the cross has 12
    /// corners at ±5 and ±(5/3 + 1 = 2), the saltire the same turned by 45° (its first corners
    /// (−2, −5) and (2, −5) to (2.1, −4.9) and (4.9, −2.1), rounded (2, −5) and (5, −2)), the star 10 corners alternating 5 and
    /// 0.45·5 from the centre, the pentagon 5 corners, its first straight up at (0, −4), the
    /// bowtie 6 corners, its waist ±5/3 → ±1 high.
    #[test]
    fn sweep_colours_carry_their_own_markers() {
        let sweep: Vec<Marker> = SWEEP.iter().map(|&c| Marker::of(c)).collect();
        assert_eq!(
            sweep,
            vec![
                Marker::Star,
                Marker::Pentagon,
                Marker::Cross,
                Marker::Saltire,
                Marker::Bowtie
            ]
        );
        let palette: Vec<Vec<(i32, i32)>> =
            PALETTE.iter().map(|&c| Marker::of(c).outline(4)).collect();
        let outlines: Vec<Vec<(i32, i32)>> = sweep.iter().map(|m| m.outline(4)).collect();
        for (i, o) in outlines.iter().enumerate() {
            assert!(!palette.contains(o), "sweep step {i} has a palette shape");
            for p in &outlines[..i] {
                assert_ne!(o, p, "sweep step {i}");
            }
        }
        let cross = &outlines[2];
        assert_eq!(cross.len(), 12);
        assert!(cross
            .iter()
            .all(|p| [2, 5].contains(&p.0.abs()) && [2, 5].contains(&p.1.abs())));
        let star = &outlines[0];
        assert_eq!(star.len(), 10);
        assert_eq!(star[0], (0, -5));
        for (k, p) in star.iter().enumerate() {
            let d = f64::from(p.0).hypot(f64::from(p.1));
            let want = if k % 2 == 0 { 5.0 } else { 2.25 };
            assert!((d - want).abs() < 0.75, "star corner {k} at {d}");
        }
        assert_eq!(outlines[1].len(), 5);
        assert_eq!(outlines[1][0], (0, -4));
        assert_eq!(outlines[3].len(), 12);
        assert_eq!(outlines[3][0], (2, -5));
        assert_eq!(outlines[3][1], (5, -2));
        assert_eq!(
            outlines[4],
            vec![(-5, -5), (0, -1), (5, -5), (5, 5), (0, 1), (-5, 5)]
        );
    }

    /// A legend-only reference series (no points: the key for dashed optima drawn in other
    /// colours, lloyd2006-fig10) shows its dashed line in the legend (it had an empty key):
    /// its colour is stroked in the SVG although no data of it is drawn.
    #[test]
    fn a_reference_key_without_points_shows_its_line() {
        super::super::super::ensure_font().unwrap();
        let mut c = LineChart::new(
            "t",
            Axis::linear("x", 0.0, 1.0),
            Axis::linear("y", 0.0, 1.0),
        );
        c.series.push(
            Series::line("optimum", Vec::new(), RGBColor(90, 90, 90))
                .dashed()
                .reference(),
        );
        let mut svg = String::new();
        {
            let area =
                super::super::super::svg::Svg::new(&mut svg, (400, 300), 1).into_drawing_area();
            draw_line_chart(&area, &c).unwrap();
            area.present().unwrap();
        }
        assert!(svg.contains("stroke=\"#5A5A5A\""), "{svg}");
    }

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
