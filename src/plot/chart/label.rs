//! Text placed at a data position of a chart on a white box, so that it stays readable over
//! lines and fills (annotations, dimension labels).

use super::super::canvas::anchor_offset;
use super::super::Fail;
use super::axis::Chart2d;
use super::line::clip_segment;
use super::FONT;
use plotters::prelude::*;
use plotters::style::text_anchor::Pos;

/// The white margin around a boxed label's text, in pixels.
pub(crate) const LABEL_PAD: i32 = 2;

/// The least contrast of a label's text against white (WCAG 2's level AA for text).
pub(crate) const MIN_CONTRAST: f64 = 4.5;

/// WCAG 2's relative luminance of an sRGB colour.
pub(crate) fn luminance(c: RGBColor) -> f64 {
    let lin = |v: u8| {
        let v = f64::from(v) / 255.0;
        if v <= 0.040_45 {
            v / 12.92
        } else {
            ((v + 0.055) / 1.055).powf(2.4)
        }
    };
    0.2126 * lin(c.0) + 0.7152 * lin(c.1) + 0.0722 * lin(c.2)
}

/// `c` as text on white: itself where it reaches [`MIN_CONTRAST`] against white, otherwise the
/// same hue darkened (its sRGB channels scaled down together) until it does, so that a direct
/// label keeps its line's colour and stays readable (#E69F00 and #56B4E9 reach only 2.3 : 1).
pub(crate) fn legible(c: RGBColor) -> RGBColor {
    let contrast = |c: RGBColor| 1.05 / (luminance(c) + 0.05);
    let scaled = |t: f64| {
        let ch = |v: u8| (f64::from(v) * t).floor() as u8;
        RGBColor(ch(c.0), ch(c.1), ch(c.2))
    };
    if contrast(c) >= MIN_CONTRAST {
        return c;
    }
    // The largest scale in 1/256 steps that reaches the contrast (black always does).
    (0..=256)
        .rev()
        .map(|k| scaled(f64::from(k) / 256.0))
        .find(|&d| contrast(d) >= MIN_CONTRAST)
        .unwrap_or(RGBColor(0, 0, 0))
}

/// Writes `text` at the data point `at` of `chart`, anchored by `pos`, in `colour` (made
/// [`legible`]) at `size`
/// pixels, over a white box a little larger than the text (80 % opaque, so that a line under it
/// still shows faintly).
pub(crate) fn boxed_text<DB: DrawingBackend>(
    chart: &mut Chart2d<'_, DB>,
    at: (f64, f64),
    text: &str,
    pos: Pos,
    size: u32,
    colour: RGBColor,
) -> Result<(), Fail> {
    boxed_text_within(chart, at, text, pos, size, colour, None)
}

/// [`boxed_text`], its white box cut to the data rectangle `within` ([x0, y0], [x1, y1]) less
/// a unit at each side, so that it leaves the rectangle's outline (a unit wide, centred on
/// its edges) uncovered (lloyd2005-fig8's one-column "N" in a column narrower than its box:
/// the nineteenth review, R19-lloyd2005-fig8-2).
pub(crate) fn boxed_text_within<DB: DrawingBackend>(
    chart: &mut Chart2d<'_, DB>,
    at: (f64, f64),
    text: &str,
    pos: Pos,
    size: u32,
    colour: RGBColor,
    within: Option<[(f64, f64); 2]>,
) -> Result<(), Fail> {
    let ink = legible(colour);
    let style = TextStyle::from((FONT, size).into_font())
        .color(&ink)
        .pos(pos);
    let (w, h) = chart
        .plotting_area()
        .estimate_text_size(text, &style)
        .map_err(|e| Fail::Draw(e.to_string()))?;
    let (dx, dy) = anchor_offset(pos, f64::from(w), f64::from(h));
    let (x0, y0, w, h) = (dx.round() as i32, dy.round() as i32, w as i32, h as i32);
    let p = LABEL_PAD;
    let (mut a, mut b) = ((x0 - p, y0 - p), (x0 + w + p, y0 + h + p));
    if let Some([c0, c1]) = within {
        // The rectangle's corners in pixels from `at`, whichever way the axes run.
        let o = chart.backend_coord(&at);
        let (q0, q1) = (chart.backend_coord(&c0), chart.backend_coord(&c1));
        let (l, r) = (q0.0.min(q1.0) - o.0 + 1, q0.0.max(q1.0) - o.0 - 1);
        let (t, u) = (q0.1.min(q1.1) - o.1 + 1, q0.1.max(q1.1) - o.1 - 1);
        a = (a.0.max(l), a.1.max(t));
        b = (b.0.min(r), b.1.min(u));
    }
    chart.draw_series(std::iter::once(
        EmptyElement::at(at)
            + Rectangle::new([a, b], WHITE.mix(0.8).filled())
            + Text::new(text.to_string(), (0, 0), style.clone()),
    ))?;
    Ok(())
}

/// A box in backend units: left, top, right, bottom.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rect {
    pub x0: f64,
    pub y0: f64,
    pub x1: f64,
    pub y1: f64,
}

impl Rect {
    /// The box `w` × `h` whose anchor `pos` is at `at`.
    pub fn anchored(at: (f64, f64), pos: Pos, w: f64, h: f64) -> Self {
        let (dx, dy) = anchor_offset(pos, w, h);
        Self {
            x0: at.0 + dx,
            y0: at.1 + dy,
            x1: at.0 + dx + w,
            y1: at.1 + dy + h,
        }
    }

    /// The box grown by `d` on every side.
    pub fn grown(self, d: f64) -> Self {
        Self {
            x0: self.x0 - d,
            y0: self.y0 - d,
            x1: self.x1 + d,
            y1: self.y1 + d,
        }
    }

    pub fn overlaps(&self, o: &Rect) -> bool {
        self.x0 < o.x1 && o.x0 < self.x1 && self.y0 < o.y1 && o.y0 < self.y1
    }

    pub fn contains(&self, o: &Rect) -> bool {
        self.x0 <= o.x0 && o.x1 <= self.x1 && self.y0 <= o.y0 && o.y1 <= self.y1
    }

    /// Whether the segment `a`–`b` passes through the box.
    pub fn crosses(&self, a: (f64, f64), b: (f64, f64)) -> bool {
        clip_segment(a, b, (self.x0, self.x1, self.y0, self.y1)).is_some()
    }
}

/// A drawn segment (backend units) and the index of its series.
pub(crate) type Segment = ((f64, f64), (f64, f64), usize);

/// What a label must not cover: the drawn lines and markers of a chart's series (backend
/// units), each with the index of its series, and the boxes already placed.
#[derive(Debug, Default)]
pub(crate) struct Obstacles {
    pub segments: Vec<Segment>,
    pub markers: Vec<(Rect, usize)>,
    pub boxes: Vec<Rect>,
    /// Series whose lines no label is read as belonging to (`Series::quiet`).
    pub quiet: Vec<usize>,
}

impl Obstacles {
    /// How many lines and markers of series other than `own` and boxes the box touches, with
    /// the markers of `own` that its text (the box less [`LABEL_PAD`]) touches (the line
    /// charts draw markers over the labels' halos, so a halo may reach under its own line's
    /// markers but its text may not), and how many segments of `own`.
    pub fn hits(&self, r: &Rect, own: Option<usize>) -> (usize, usize) {
        let mut other = 0;
        let mut mine = 0;
        for &(a, b, s) in &self.segments {
            if r.crosses(a, b) {
                if Some(s) == own {
                    mine += 1;
                } else {
                    other += 1;
                }
            }
        }
        let text = r.grown(-f64::from(LABEL_PAD));
        other += self
            .markers
            .iter()
            .filter(|(m, s)| {
                if Some(*s) == own {
                    text.overlaps(m)
                } else {
                    r.overlaps(m)
                }
            })
            .count();
        other += self.boxes.iter().filter(|b| r.overlaps(b)).count();
        (other, mine)
    }
}

/// Where a series' direct label goes: among boxes of `w` × `h` beside each of `points` (its
/// drawn points, backend units; `preferred` is the index of the point asked for), the one inside
/// `area` that covers no other series' line or marker nor a placed box, crosses its own line
/// least, and lies nearest the preferred point. Returns the box.
pub(crate) fn place_label(
    points: &[(f64, f64)],
    preferred: usize,
    (w, h): (f64, f64),
    area: &Rect,
    own: usize,
    obstacles: &Obstacles,
) -> Option<Rect> {
    use plotters::style::text_anchor::{HPos, VPos};
    let p0 = *points.get(preferred)?;
    // Beside the point 4 units off (the text, 2 units inside its box, then clears a marker of
    // a line 2 wide, 5 units about its point, on a flat line), or 9 or 15 (clear of larger
    // markers and of the lines next to it), the farther costing a little more.
    let mut corners = Vec::new();
    for gap in [4.0, 9.0, 15.0] {
        corners.extend([
            (HPos::Right, VPos::Bottom, (-gap, -gap)),
            (HPos::Left, VPos::Bottom, (gap, -gap)),
            (HPos::Right, VPos::Top, (-gap, gap)),
            (HPos::Left, VPos::Top, (gap, gap)),
            (HPos::Center, VPos::Bottom, (0.0, -gap)),
            (HPos::Center, VPos::Top, (0.0, gap)),
        ]);
    }
    // On the line itself (covering a piece of its own line only).
    corners.push((HPos::Center, VPos::Center, (0.0, 0.0)));
    // Beside every drawn point, and every 4 units along the line between them.
    let mut along = vec![p0];
    for w2 in points.windows(2) {
        let (a, b) = (w2[0], w2[1]);
        let n = ((b.0 - a.0).hypot(b.1 - a.1) / 4.0).ceil().max(1.0);
        along.extend((0..n as usize).map(|j| {
            let t = j as f64 / n;
            (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
        }));
    }
    along.extend(points.last());
    let mut candidates = Vec::new();
    for p in along {
        for (k, &(hp, vp, (dx, dy))) in corners.iter().enumerate() {
            let r = Rect::anchored((p.0 + dx, p.1 + dy), Pos::new(hp, vp), w, h);
            let far = (p.0 - p0.0).hypot(p.1 - p0.1);
            // A label nearer another line than its own would be read as that line's.
            let c = (0.5 * (r.x0 + r.x1), 0.5 * (r.y0 + r.y1));
            let nearest = |mine: bool| {
                obstacles
                    .segments
                    .iter()
                    .filter(|s| (s.2 == own) == mine && (mine || !obstacles.quiet.contains(&s.2)))
                    .map(|&(a, b, _)| distance(c, a, b))
                    .fold(f64::INFINITY, f64::min)
            };
            // Equally near both reads as either (lloyd2006-fig4's ξ = −½ label stood 24.0
            // units from its curve and 24.1 from the uniform map's: the eighteenth and
            // nineteenth reviews): its own line at least 3 units nearer.
            let ambiguous = if nearest(false) < nearest(true) + AMBIGUOUS {
                1e3
            } else {
                0.0
            };
            candidates.push((r, far + k as f64 + ambiguous));
        }
    }
    best_box(candidates, area, Some(own), obstacles)
}

/// How much nearer its own line than any other a direct label's centre must be, in units.
const AMBIGUOUS: f64 = 3.0;

/// The distance from `p` to the segment `a`–`b`.
fn distance(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// The best of `candidates` (boxes with a cost of their own): inside `area`, covering the fewest
/// lines, markers and boxes of other series than `own`, then crossing `own`'s line least, then
/// the cheapest.
pub(crate) fn best_box(
    candidates: Vec<(Rect, f64)>,
    area: &Rect,
    own: Option<usize>,
    obstacles: &Obstacles,
) -> Option<Rect> {
    let mut best: Option<(f64, Rect)> = None;
    for (r, base) in candidates {
        if !area.contains(&r) {
            continue;
        }
        let (other, mine) = obstacles.hits(&r, own);
        let cost = 1e6 * other as f64 + 40.0 * mine as f64 + base;
        if best.is_none_or(|(c, _)| cost < c) {
            best = Some((cost, r));
        }
    }
    best.map(|(_, r)| r)
}

/// Where a note goes whose text's top left is asked at `at`: its box (text `w` × `h` and the
/// padding) there, or moved by the least distance (up to 24 units) that clears every line,
/// marker and box, inside `area`; where nothing is clear, where it was asked.
pub(crate) fn place_note(
    at: (f64, f64),
    (w, h): (f64, f64),
    area: &Rect,
    obstacles: &Obstacles,
) -> Rect {
    use plotters::style::text_anchor::{HPos, VPos};
    let p = f64::from(LABEL_PAD);
    let asked = Rect::anchored(at, Pos::new(HPos::Left, VPos::Top), w, h).grown(p);
    let mut candidates = Vec::new();
    for i in -12..=12 {
        for j in -12..=12 {
            let (dx, dy) = (2.0 * f64::from(i), 2.0 * f64::from(j));
            let r = Rect {
                x0: asked.x0 + dx,
                y0: asked.y0 + dy,
                x1: asked.x1 + dx,
                y1: asked.y1 + dy,
            };
            candidates.push((r, dx.hypot(dy)));
        }
    }
    match best_box(candidates, area, None, obstacles) {
        Some(r) if obstacles.hits(&r, None).0 == 0 => r,
        _ => asked,
    }
}

/// Writes `text` in `colour` (made [`legible`]) at `size` pixels on a white box (as
/// [`boxed_text`]) filling the
/// box `r` of backend units (a box from [`place_label`]), aligned to the box's left or right
/// (`h`: a series' label ends at its right, as a label written left of its line's end).
pub(crate) fn text_in_box<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    r: &Rect,
    (text, h): (&str, plotters::style::text_anchor::HPos),
    size: u32,
    colour: RGBColor,
) -> Result<(), Fail> {
    use plotters::style::text_anchor::{HPos, VPos};
    let (bx, by) = area.get_base_pixel();
    let x0 = r.x0.round() as i32 - bx;
    let y0 = r.y0.round() as i32 - by;
    let x1 = r.x1.round() as i32 - bx;
    let y1 = r.y1.round() as i32 - by;
    let p = LABEL_PAD;
    area.draw(&Rectangle::new(
        [(x0, y0), (x1, y1)],
        WHITE.mix(0.8).filled(),
    ))?;
    let ink = legible(colour);
    let style = TextStyle::from((FONT, size).into_font())
        .color(&ink)
        .pos(Pos::new(h, VPos::Top));
    let x = if matches!(h, HPos::Right) {
        x1 - p
    } else {
        x0 + p
    };
    area.draw(&Text::new(text.to_string(), (x, y0 + p), style))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A label at the end of a flat line whose points carry markers (half size 5, as for a line
    /// 2 wide) keeps its text clear of its own line's markers, and its whole box clear of
    /// another line's (the review found the halos of lloyd2005-fig7's labels over the markers
    /// at k = 9; the line charts draw markers over the halos). By hand, a 60 × 14 box 4 units
    /// above and left of the end point (100, 100) spans x 36–96, y 82–96; its text (less the
    /// pad of 2) y 84–94 clears the own markers' boxes (y 95–105), so the label stays there.
    #[test]
    fn a_label_keeps_clear_of_its_own_lines_markers() {
        let points: Vec<(f64, f64)> = (0..=10).map(|i| (10.0 * f64::from(i), 100.0)).collect();
        let mut o = Obstacles::default();
        o.segments
            .extend(points.windows(2).map(|w| (w[0], w[1], 0)));
        for &p in &points {
            o.markers.push((
                Rect {
                    x0: p.0 - 5.0,
                    y0: p.1 - 5.0,
                    x1: p.0 + 5.0,
                    y1: p.1 + 5.0,
                },
                0,
            ));
        }
        let area = Rect {
            x0: 0.0,
            y0: 0.0,
            x1: 110.0,
            y1: 200.0,
        };
        let box_at = |x0: f64, y0: f64| Rect {
            x0,
            y0,
            x1: x0 + 60.0,
            y1: y0 + 14.0,
        };
        let r = place_label(&points, 10, (60.0, 14.0), &area, 0, &o).unwrap();
        assert_eq!(r, box_at(36.0, 82.0));
        let other = |o: &Obstacles, dy: f64| {
            let mut o2 = Obstacles::default();
            o2.segments.clone_from(&o.segments);
            o2.markers.clone_from(&o.markers);
            for &p in &points {
                o2.markers.push((
                    Rect {
                        x0: p.0 - 5.0,
                        y0: p.1 - 5.0 + dy,
                        x1: p.0 + 5.0,
                        y1: p.1 + 5.0 + dy,
                    },
                    1,
                ));
            }
            o2
        };
        // Another line's markers 10 units below (y 105–115): the box above stays.
        let below = other(&o, 10.0);
        assert_eq!(
            place_label(&points, 10, (60.0, 14.0), &area, 0, &below),
            Some(box_at(36.0, 82.0))
        );
        // 15 units above (y 80–90, under the box): the label goes 4 units below its line,
        // y 104–118, its text (106–116) clear of its own markers (95–105).
        let above = other(&o, -15.0);
        assert_eq!(
            place_label(&points, 10, (60.0, 14.0), &area, 0, &above),
            Some(box_at(36.0, 104.0))
        );
        // Its own line rising 3 units to its last but one point (90, 97): that marker's box
        // (y 92–102) reaches the text above (84–94), so the label goes below, 104–118 (the
        // text there, 106–116, clears the markers at 95–105 and 92–102).
        let mut rising = points.clone();
        rising[9].1 = 97.0;
        let mut o = Obstacles::default();
        o.segments
            .extend(rising.windows(2).map(|w| (w[0], w[1], 0)));
        for &p in &rising {
            o.markers.push((
                Rect {
                    x0: p.0 - 5.0,
                    y0: p.1 - 5.0,
                    x1: p.0 + 5.0,
                    y1: p.1 + 5.0,
                },
                0,
            ));
        }
        assert_eq!(
            place_label(&rising, 10, (60.0, 14.0), &area, 0, &o),
            Some(box_at(36.0, 104.0))
        );
    }
}
