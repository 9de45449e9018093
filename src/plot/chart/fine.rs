//! Curves and markers placed finer than a figure unit ([`Fine`]): plotters rounds every point to
//! a whole unit, which shows as steps along a smooth curve in an SVG (and at the PNG's zoom).
//! Here a chart's points are mapped to the backend in floating point, dashed along their exact
//! length, and handed over as [`Fine`] shapes.

use super::super::canvas::Fine;
use super::super::Fail;
use super::axis::Chart2d;
use super::line::Dash;
use plotters::coord::Shift;
use plotters::prelude::*;

/// The lengths (in figure units) of a dash and of the gap after it.
pub(crate) fn dash_lengths(dash: Dash) -> Option<(f64, f64)> {
    match dash {
        Dash::Solid => None,
        Dash::Dashed => Some((9.0, 6.0)),
        Dash::Dotted => Some((2.0, 4.0)),
    }
}

/// The backend position (absolute figure units, not rounded) of an axis-space point of `chart`.
pub(crate) fn to_backend<DB: DrawingBackend>(
    chart: &Chart2d<'_, DB>,
) -> impl Fn((f64, f64)) -> (f64, f64) {
    let x = chart.x_range();
    let y = chart.y_range();
    // The corners of the axis ranges map to the ends of the plotting area exactly.
    let (a0, b0) = chart.backend_coord(&(x.start, y.start));
    let (a1, b1) = chart.backend_coord(&(x.end, y.end));
    let along = |v: f64, lo: f64, hi: f64, p0: i32, p1: i32| {
        let t = if hi == lo { 0.5 } else { (v - lo) / (hi - lo) };
        f64::from(p0) + t * f64::from(p1 - p0)
    };
    move |(u, v)| {
        (
            along(u, x.start, x.end, a0, a1),
            along(v, y.start, y.end, b0, b1),
        )
    }
}

/// The dashes of a polyline (backend units): the pieces drawn, each at least two points.
pub(crate) fn dashes(points: &[(f64, f64)], dash: Dash) -> Vec<Vec<(f64, f64)>> {
    let Some((on, off)) = dash_lengths(dash) else {
        return vec![points.to_vec()];
    };
    let mut out = Vec::new();
    let Some(&first) = points.first() else {
        return out;
    };
    let mut solid = true;
    // Length left in the current dash or gap.
    let mut left = on;
    let mut cur = vec![first];
    for w in points.windows(2) {
        let (mut a, b) = (w[0], w[1]);
        loop {
            let d = (b.0 - a.0).hypot(b.1 - a.1);
            if d <= left {
                left -= d;
                if solid {
                    cur.push(b);
                }
                break;
            }
            let t = left / d;
            a = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
            if cur.last() != Some(&a) {
                cur.push(a);
            }
            if solid {
                out.push(std::mem::take(&mut cur));
            }
            solid = !solid;
            left = if solid { on } else { off };
        }
    }
    if solid && cur.len() >= 2 {
        out.push(cur);
    }
    out.retain(|p| p.len() >= 2);
    out
}

/// Draws a polyline given in backend units (absolute) on `area`'s backend, solid, dashed or
/// dotted, at sub-unit precision.
pub(crate) fn draw_fine_path<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    points: &[(f64, f64)],
    colour: RGBColor,
    width: u32,
    dash: Dash,
) -> Result<(), Fail> {
    for piece in dashes(points, dash) {
        area.draw(&Fine {
            points: piece,
            colour: colour.to_backend_color(),
            stroke: Some(width),
        })?;
    }
    Ok(())
}

/// Draws a polyline in `chart`'s axis space at sub-unit precision.
pub(crate) fn draw_fine_line<DB: DrawingBackend>(
    chart: &Chart2d<'_, DB>,
    points: &[(f64, f64)],
    colour: RGBColor,
    width: u32,
    dash: Dash,
) -> Result<(), Fail> {
    let to = to_backend(chart);
    let pts: Vec<(f64, f64)> = points.iter().map(|&p| to(p)).collect();
    draw_fine_path(
        &chart.plotting_area().strip_coord_spec(),
        &pts,
        colour,
        width,
        dash,
    )
}

/// Fills a polygon given as offsets (backend units) about a backend point, at sub-unit
/// precision (a marker centred on a curve's exact point).
pub(crate) fn fill_fine_polygon<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    centre: (f64, f64),
    outline: &[(i32, i32)],
    colour: RGBColor,
) -> Result<(), Fail> {
    area.draw(&Fine {
        points: outline
            .iter()
            .map(|&(x, y)| (centre.0 + f64::from(x), centre.1 + f64::from(y)))
            .collect(),
        colour: colour.to_backend_color(),
        stroke: None,
    })?;
    Ok(())
}

/// Strokes a marker's `outline` about `centre` (backend units) as a closed line 2 units wide,
/// inside left empty: a hollow marker, which shows the marker drawn under it. The path starts
/// and ends halfway along the first side, so that every corner is a join: a path that starts
/// and ends at a corner meets itself there in two square ends, which leave a notch at a sharp
/// corner (a triangle's apex).
pub(crate) fn stroke_fine_outline<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    centre: (f64, f64),
    outline: &[(i32, i32)],
    colour: RGBColor,
) -> Result<(), Fail> {
    let at = |&(x, y): &(i32, i32)| (centre.0 + f64::from(x), centre.1 + f64::from(y));
    let corners: Vec<(f64, f64)> = outline.iter().map(at).collect();
    let (Some(&a), Some(&b)) = (corners.first(), corners.get(1)) else {
        return Ok(());
    };
    let mid = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
    let mut points = Vec::with_capacity(corners.len() + 2);
    points.push(mid);
    points.extend(corners.iter().skip(1));
    points.push(a);
    points.push(mid);
    area.draw(&Fine {
        points,
        colour: colour.to_backend_color(),
        stroke: Some(2),
    })?;
    Ok(())
}

/// Fills the polygon of `points` (backend units), as [`fill_fine_polygon`] does an outline about
/// a centre; nothing where fewer than three points are left.
pub(crate) fn fill_fine_points<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    points: Vec<(f64, f64)>,
    colour: RGBColor,
) -> Result<(), Fail> {
    if points.len() < 3 {
        return Ok(());
    }
    area.draw(&Fine {
        points,
        colour: colour.to_backend_color(),
        stroke: None,
    })?;
    Ok(())
}

/// A convex or concave polygon cut to the rectangle `r` (Sutherland–Hodgman: each of the four
/// edges in turn keeps the part inside it).
pub(crate) fn clip_to_rect(points: &[(f64, f64)], r: &super::label::Rect) -> Vec<(f64, f64)> {
    type Edge = (
        fn(&(f64, f64), f64) -> bool,
        fn((f64, f64), (f64, f64), f64) -> (f64, f64),
    );
    let across_x =
        |a: (f64, f64), b: (f64, f64), x: f64| (x, a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0));
    let across_y =
        |a: (f64, f64), b: (f64, f64), y: f64| (a.0 + (b.0 - a.0) * (y - a.1) / (b.1 - a.1), y);
    let edges: [(Edge, f64); 4] = [
        ((|p, v| p.0 >= v, across_x), r.x0),
        ((|p, v| p.0 <= v, across_x), r.x1),
        ((|p, v| p.1 >= v, across_y), r.y0),
        ((|p, v| p.1 <= v, across_y), r.y1),
    ];
    let mut out = points.to_vec();
    for ((keep, cross), v) in edges {
        let input = std::mem::take(&mut out);
        for (i, &b) in input.iter().enumerate() {
            let a = input[(i + input.len() - 1) % input.len()];
            match (keep(&a, v), keep(&b, v)) {
                (true, true) => out.push(b),
                (true, false) => out.push(cross(a, b, v)),
                (false, true) => {
                    out.push(cross(a, b, v));
                    out.push(b);
                }
                (false, false) => {}
            }
        }
    }
    out
}

/// The pieces of a polyline drawn with a dash `pattern` (lengths on, off, … in pixels, at
/// `per_unit` pixels per data unit), in data units.
pub(crate) fn dash_pattern(
    points: &[(f64, f64)],
    pattern: &[f64],
    per_unit: f64,
) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let Some(&first) = points.first() else {
        return out;
    };
    let len = |k: usize| pattern[k % pattern.len()] / per_unit;
    let (mut k, mut left) = (0, len(0));
    let mut cur = vec![first];
    for w in points.windows(2) {
        let (mut a, b) = (w[0], w[1]);
        loop {
            let d = (b.0 - a.0).hypot(b.1 - a.1);
            if d <= left {
                left -= d;
                if k % 2 == 0 {
                    cur.push(b);
                }
                break;
            }
            let t = left / d;
            a = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
            if k % 2 == 0 {
                cur.push(a);
                out.push(std::mem::take(&mut cur));
            } else {
                cur = vec![a];
            }
            k += 1;
            left = len(k);
        }
    }
    if k % 2 == 0 && cur.len() >= 2 {
        out.push(cur);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square of side 4 centred on the rectangle's top edge y = 0 (x from 0 to 10, y from 0
    /// down to 10) keeps its lower half, by hand: (1, 0), (3, 0), (3, 2), (1, 2); a polygon
    /// inside is kept whole, one outside is gone.
    #[test]
    fn clip_to_rect_keeps_the_part_inside() {
        let r = super::super::label::Rect {
            x0: 0.0,
            y0: 0.0,
            x1: 10.0,
            y1: 10.0,
        };
        let square = [(1.0, -2.0), (3.0, -2.0), (3.0, 2.0), (1.0, 2.0)];
        let mut got = clip_to_rect(&square, &r);
        got.sort_by(|a, b| a.partial_cmp(b).unwrap());
        got.dedup();
        assert_eq!(got, vec![(1.0, 0.0), (1.0, 2.0), (3.0, 0.0), (3.0, 2.0)]);
        let inside = [(4.0, 4.0), (6.0, 4.0), (5.0, 6.0)];
        assert_eq!(clip_to_rect(&inside, &r).len(), 3);
        assert!(clip_to_rect(&[(20.0, 20.0), (22.0, 20.0), (21.0, 22.0)], &r).is_empty());
    }

    fn length(p: &[(f64, f64)]) -> f64 {
        p.windows(2)
            .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
            .sum()
    }

    /// G1 (issue 25): a smooth curve in an SVG keeps positions finer than a unit of the view
    /// box. y = x² over [0, 1] is drawn as the figures' SVGs are (10 units per view-box unit);
    /// each coordinate of its polyline is within 0.05 units (half a step) of the exact
    /// parabola through the polyline's own ends (plotters' whole units were up to 1 unit off, with visible steps).
    #[test]
    fn curves_in_an_svg_keep_sub_unit_positions() {
        use super::super::super::canvas::{Canvas, SUBUNIT, SVG_TEXT};
        use super::super::super::svg::Svg;
        use super::super::line::{draw_line_chart, LineChart, Series};
        use super::super::Axis;
        super::super::super::ensure_font().unwrap();
        let mut c = LineChart::new("", Axis::linear("x", 0.0, 1.0), Axis::linear("y", 0.0, 1.0));
        let xs = super::super::linspace(0.0, 1.0, 201);
        let curve = RGBColor(1, 2, 3);
        c.series
            .push(Series::line("x²", xs.iter().map(|&x| (x, x * x)).collect(), curve).direct());
        let mut svg = String::new();
        {
            let k = SUBUNIT as u32;
            let doc = Svg::new(&mut svg, (437, 311), 1).units(k);
            let area = Canvas::new(doc, k, SVG_TEXT).vector().into_drawing_area();
            draw_line_chart(&area, &c).unwrap();
            area.present().unwrap();
        }
        assert!(svg.contains("viewBox=\"0 0 437 311\""), "{svg}");
        let line = svg
            .lines()
            .find(|l| l.starts_with("<polyline") && l.contains("#010203"))
            .unwrap();
        assert!(line.contains("stroke-width=\"2\""), "{line}");
        let pts = crate::plot::chart::read_svg::points(line).unwrap();
        assert_eq!(pts.len(), xs.len());
        let (p0, p1) = (pts[0], pts[pts.len() - 1]);
        let mut fractional = 0;
        for (&(px, py), &x) in pts.iter().zip(&xs) {
            // Each coordinate is the exact one rounded to 1/10.
            let exact = (p0.0 + x * (p1.0 - p0.0), p0.1 + x * x * (p1.1 - p0.1));
            assert!(
                (px - exact.0).abs() <= 0.0501 && (py - exact.1).abs() <= 0.0501,
                "x {x}: ({px}, {py}), exact {exact:?}"
            );
            fractional += usize::from(px.fract() != 0.0 || py.fract() != 0.0);
        }
        assert!(fractional > pts.len() / 2, "{fractional} of {}", pts.len());
    }

    #[test]
    fn dashes_follow_the_exact_length_across_corners() {
        // An L of 30 + 30 units: dashes of 9 with gaps of 6 start at 0, 15, 30, 45.
        let l = [(0.0, 0.0), (30.0, 0.0), (30.0, 30.0)];
        let d = dashes(&l, Dash::Dashed);
        assert_eq!(d.len(), 4);
        for piece in &d {
            assert!((length(piece) - 9.0).abs() < 1e-9, "{piece:?}");
        }
        // The third dash starts at the corner; the second ends 24 units along.
        assert_eq!(d[1].last().copied(), Some((24.0, 0.0)));
        assert_eq!(d[2][0], (30.0, 0.0));
        // A dash across the corner keeps the corner point.
        let d = dashes(&[(0.0, 0.0), (20.0, 0.0), (20.0, 10.0)], Dash::Dashed);
        assert_eq!(d[1], vec![(15.0, 0.0), (20.0, 0.0), (20.0, 4.0)]);
        // Solid: the line itself.
        assert_eq!(dashes(&l, Dash::Solid), vec![l.to_vec()]);
    }
}
