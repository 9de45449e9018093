//! The maps' numbers in barroso-fig5's details (b), (d), (f) (the eleventh review,
//! R11-barroso-fig5-1: the reader could not tell which rectangle belonged to which partition):
//! map i's number, "1" to "4" in its map's colour (made [`legible`]), at a corner of its
//! rectangle, diagonally off the corner by [`GAP`], inside the rectangle where that is clear and
//! else outside, or slid along a side inside it, wherever it covers no line (the frustum's, a
//! map's outline, a leader), no other number, stays inside the plot, and reads as its own map's
//! (no other map's corner nearer, or every other map's outline two units farther); where no such place
//! is clear of the frustum's black lines, the first clear of the others, on an opaque white box
//! that cuts the black line under it. A map none of whose corners has such room (map 1 in (b),
//! 7 × 4 units) is not numbered.

use super::super::super::chart::{clip_segment, legible, Chart2d, FONT};
use super::super::super::Fail;
use super::super::Panel;
use super::{edge_on, map_colour, maps::fine_stroke, FRUSTUM_WIDTH, PLANE_WIDTH};
use glam::DVec2;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// The distance, across and up, from a map's corner to its number's box, in units: half the
/// outline's width and two units of white.
const GAP: f64 = 3.0;

/// A digit's height, with a little room, as a share of the type's size.
const DIGIT_HEIGHT: f64 = 0.68;

/// The white kept between a number's box and any line, in units (beyond the line's half width).
const CLEAR: f64 = 1.0;

/// A box in backend pixels: (left, top, right, bottom).
type PxBox = [f64; 4];

/// A leader in backend pixels: from its anchor dot to the gutter.
pub(super) type Leader = ((i32, i32), (i32, i32));

/// A line in backend pixels: its ends, its half width and whether it is one of the frustum's
/// black lines (a number may cover a piece of one, on a white box, where no corner has room
/// beside the lines).
type PxLine = ((f64, f64), (f64, f64), f64, bool);

/// The distance from the box `r` to the point `c`.
fn distance(r: &PxBox, c: (f64, f64)) -> f64 {
    let dx = (r[0] - c.0).max(c.0 - r[2]).max(0.0);
    let dy = (r[1] - c.1).max(c.1 - r[3]).max(0.0);
    dx.hypot(dy)
}

/// Whether the segment `a`–`b` meets the box `r` (Liang–Barsky clipping).
fn meets(r: PxBox, a: (f64, f64), b: (f64, f64)) -> bool {
    clip_segment(a, b, (r[0], r[2], r[1], r[3])).is_some()
}

/// The lines of panel `p` in backend pixels: the frustum's edges and faces, the split planes,
/// every map's outline (as its rectangle), and `leaders` (each from its anchor dot).
fn lines<DB: DrawingBackend>(
    chart: &Chart2d<'_, DB>,
    p: &Panel,
    leaders: &[Leader],
) -> Vec<PxLine> {
    let px = |q: DVec2| {
        let (x, y) = chart.backend_coord(&(q.x, q.y));
        (f64::from(x), f64::from(y))
    };
    let mut out: Vec<PxLine> = Vec::new();
    let last = p.sections.len().saturating_sub(1);
    for (i, s) in p.sections.iter().enumerate() {
        let w = if i == 0 || i == last {
            FRUSTUM_WIDTH
        } else {
            PLANE_WIDTH
        };
        let hw = 0.5 * f64::from(w);
        match edge_on(s, 1e-9) {
            Some([a, b]) => out.push((px(a), px(b), hw, true)),
            None => out.extend((0..4).map(|k| (px(s[k]), px(s[(k + 1) % 4]), hw, true))),
        }
    }
    if let (Some(first), Some(far)) = (p.sections.first(), p.sections.last()) {
        let hw = 0.5 * f64::from(FRUSTUM_WIDTH);
        out.extend((0..4).map(|k| (px(first[k]), px(far[k]), hw, true)));
    }
    for (i, &(a, b)) in p.maps.iter().enumerate() {
        let hw = 0.5 * f64::from(fine_stroke(i).1);
        let c = [a, DVec2::new(b.x, a.y), b, DVec2::new(a.x, b.y)];
        out.extend((0..4).map(|k| (px(c[k]), px(c[(k + 1) % 4]), hw, false)));
    }
    for &((ax, ay), (gx, gy)) in leaders {
        let (a, g) = (
            (f64::from(ax), f64::from(ay)),
            (f64::from(gx), f64::from(gy)),
        );
        // The anchor dot (radius 2) and the leader.
        out.push((a, a, 2.0, false));
        out.push((a, g, 0.5, false));
    }
    out
}

/// How far a number may slide along a side of its map from the corner, in steps of
/// [`SLIDE_STEP`] units, where the corner itself has no room (a frustum's edge runs through
/// every corner of (d)'s squares, diagonally into them): as far as 120 units, past any side a
/// detail draws (the candidates stop where the box would leave the rectangle).
const SLIDES: usize = 40;
const SLIDE_STEP: f64 = 3.0;

/// The candidate boxes (`w` × `h` pixels) for a number at the corners of the rectangle `lo`–`hi`
/// (backend pixels, y down), at each corner inside `plot`: first the box diagonally inside the
/// rectangle, [`GAP`] from both sides, then the three outside it, then the inside one slid
/// along either side away from the corner, nearest first.
fn candidates(lo: (f64, f64), hi: (f64, f64), w: f64, h: f64, plot: PxBox) -> Vec<PxBox> {
    let inside_plot = |x: f64, y: f64| x >= plot[0] && x <= plot[2] && y >= plot[1] && y <= plot[3];
    // Top left, top right, bottom right, bottom left (y down: top is the smaller y); each with
    // the direction into the rectangle.
    let (x0, x1) = (lo.0.min(hi.0), lo.0.max(hi.0));
    let (y0, y1) = (lo.1.min(hi.1), lo.1.max(hi.1));
    let corners = [
        ((x0, y0), (1.0, 1.0)),
        ((x1, y0), (-1.0, 1.0)),
        ((x1, y1), (-1.0, -1.0)),
        ((x0, y1), (1.0, -1.0)),
    ];
    // The box off corner c in the direction s, (ox, oy) from it (each at least GAP).
    let at = |(cx, cy): (f64, f64), (sx, sy): (f64, f64), (ox, oy): (f64, f64)| -> PxBox {
        let (ax, bx) = if sx > 0.0 {
            (cx + ox, cx + ox + w)
        } else {
            (cx - ox - w, cx - ox)
        };
        let (ay, by) = if sy > 0.0 {
            (cy + oy, cy + oy + h)
        } else {
            (cy - oy - h, cy - oy)
        };
        [ax, ay, bx, by]
    };
    let shown: Vec<_> = corners
        .iter()
        .filter(|(c, _)| inside_plot(c.0, c.1))
        .collect();
    let g = (GAP, GAP);
    let mut out: Vec<PxBox> = shown.iter().map(|&&(c, d)| at(c, d, g)).collect();
    for &&(c, d) in &shown {
        for s in [(-d.0, d.1), (d.0, -d.1), (-d.0, -d.1)] {
            out.push(at(c, s, g));
        }
    }
    // Slid along a side no further than the box stays inside the rectangle, GAP from its far
    // side.
    let (across, up) = (x1 - x0, y1 - y0);
    for k in 1..=SLIDES {
        let slid = GAP + k as f64 * SLIDE_STEP;
        for &&(c, d) in &shown {
            if slid + w + GAP <= across && GAP + h + GAP <= up {
                out.push(at(c, d, (slid, GAP)));
            }
            if slid + h + GAP <= up && GAP + w + GAP <= across {
                out.push(at(c, d, (GAP, slid)));
            }
        }
    }
    out
}

/// Writes each map's number of panel `p` (in `whole`, whose plot is `chart`) at a corner of its
/// rectangle where it covers nothing (see the module's notes), in `size`-unit type; `leaders`:
/// the leaders' ends (anchor, gutter) in backend pixels. Returns how many it wrote.
pub(super) fn numbers<DB: DrawingBackend>(
    chart: &Chart2d<'_, DB>,
    whole: &DrawingArea<DB, Shift>,
    p: &Panel,
    size: u32,
    leaders: &[Leader],
) -> Result<usize, Fail> {
    let obstacles = lines(chart, p, leaders);
    let area = chart.plotting_area();
    let (px0, py0) = area.get_base_pixel();
    let (pw, ph) = area.dim_in_pixel();
    let plot = [
        f64::from(px0) + 1.0,
        f64::from(py0) + 1.0,
        f64::from(px0) + f64::from(pw) - 1.0,
        f64::from(py0) + f64::from(ph) - 1.0,
    ];
    let (wx, wy) = whole.get_base_pixel();
    let mut placed: Vec<PxBox> = Vec::new();
    for (i, &(a, b)) in p.maps.iter().enumerate() {
        let text = format!("{}", i + 1);
        let ink = legible(map_colour(i));
        let style = TextStyle::from((FONT, size).into_font())
            .color(&ink)
            .pos(Pos::new(HPos::Left, VPos::Top));
        let (w, _) = whole
            .estimate_text_size(&text, &style)
            .map_err(|e| Fail::Draw(e.to_string()))?;
        // The digit's box: its advance, and its ink's height and a little: a digit set from the
        // top is inked from its top to 0.61 of the size (its baseline, 0.76 em of a font size
        // of the size ÷ 1.24), the PNG's type 7 % larger.
        let (w, h) = (f64::from(w), DIGIT_HEIGHT * f64::from(size));
        let to = |q: DVec2| {
            let (x, y) = chart.backend_coord(&(q.x, q.y));
            (f64::from(x), f64::from(y))
        };
        // Clear of every line, or (`over_black`) of every line but the frustum's black ones.
        let free = |r: &PxBox, over_black: bool| {
            r[0] >= plot[0]
                && r[2] <= plot[2]
                && r[1] >= plot[1]
                && r[3] <= plot[3]
                && !placed.iter().any(|o| {
                    r[0] < o[2] + CLEAR
                        && o[0] < r[2] + CLEAR
                        && r[1] < o[3] + CLEAR
                        && o[1] < r[3] + CLEAR
                })
                && !obstacles.iter().any(|&(s, e, hw, black)| {
                    let m = hw + CLEAR;
                    !(over_black && black) && meets([r[0] - m, r[1] - m, r[2] + m, r[3] + m], s, e)
                })
        };
        // Every other map's outline at least two units farther from the box than its own map's,
        // so that the number reads
        // as its own map's (a number slid along map 2's side in (d) sat by map 1's corner; one
        // judged by the nearest corner instead found no place off the frustum's diagonals in
        // (d) and stood on a white box across one).
        let outline = |r: &PxBox, q: (DVec2, DVec2)| {
            let (lo, hi) = (to(q.0), to(q.1));
            let (x0, x1) = (lo.0.min(hi.0), lo.0.max(hi.0));
            let (y0, y1) = (lo.1.min(hi.1), lo.1.max(hi.1));
            [
                [x0, y0, x1, y0],
                [x1, y0, x1, y1],
                [x0, y1, x1, y1],
                [x0, y0, x0, y1],
            ]
            .into_iter()
            .map(|e| {
                let dx = (e[0] - r[2]).max(r[0] - e[2]).max(0.0);
                let dy = (e[1] - r[3]).max(r[1] - e[3]).max(0.0);
                dx.hypot(dy)
            })
            .fold(f64::INFINITY, f64::min)
        };
        // Or no other map's corner nearer than its own map's nearest (maps sharing an edge, as
        // in (b), are equally near a box beside it).
        let corner = |r: &PxBox, q: (DVec2, DVec2)| {
            let (lo, hi) = (to(q.0), to(q.1));
            [(lo.0, lo.1), (hi.0, lo.1), (hi.0, hi.1), (lo.0, hi.1)]
                .into_iter()
                .map(|c| distance(r, c))
                .fold(f64::INFINITY, f64::min)
        };
        let own = |r: &PxBox| {
            let (d, e) = (outline(r, (a, b)), corner(r, (a, b)));
            let others = || p.maps.iter().enumerate().filter(|&(j, _)| j != i);
            others().all(|(_, &q)| outline(r, q) >= d + CLEAR + 1.0)
                || others().all(|(_, &q)| corner(r, q) >= e)
        };
        let boxes: Vec<PxBox> = candidates(to(a), to(b), w, h, plot)
            .into_iter()
            .filter(own)
            .collect();
        let clear = boxes.iter().find(|r| free(r, false)).map(|&r| (r, false));
        let Some((r, boxed)) =
            clear.or_else(|| boxes.iter().find(|r| free(r, true)).map(|&r| (r, true)))
        else {
            continue;
        };
        let rel = |x: f64, y: f64| {
            (
                (x - f64::from(wx)).round() as i32,
                (y - f64::from(wy)).round() as i32,
            )
        };
        if boxed {
            // An opaque white box a unit larger than the digit, so that its ink stands on white.
            whole.draw(&Rectangle::new(
                [rel(r[0] - 1.0, r[1] - 1.0), rel(r[2] + 1.0, r[3] + 1.0)],
                WHITE.filled(),
            ))?;
        }
        whole.draw(&Text::new(text, rel(r[0], r[1]), style))?;
        placed.push(r);
    }
    Ok(placed.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A segment meets a box when it crosses it, ends in it or lies along an edge; it misses
    /// it when it passes beside it (by hand: the box 0–10 × 0–10).
    #[test]
    fn segments_meet_boxes_by_hand() {
        let r = [0.0, 0.0, 10.0, 10.0];
        assert!(meets(r, (-5.0, 5.0), (15.0, 5.0)));
        assert!(meets(r, (5.0, 5.0), (5.0, 5.0)));
        assert!(meets(r, (-5.0, -5.0), (20.0, 20.0)));
        assert!(!meets(r, (-5.0, 12.0), (20.0, 12.0)));
        assert!(!meets(r, (11.0, -5.0), (30.0, 5.0)));
    }

    /// The candidates of a 100 × 50 rectangle from (0, 0) to (100, 50), a 6 × 8 box (by
    /// hand): the top left corner's inside box first, 3 right of and below (0, 0), then the
    /// other corners' inside boxes (the bottom right one ends 3 left of and above (100, 50)),
    /// then three outside boxes per corner, then the slid boxes per corner and step, the first
    /// 6 right of the top left corner: across while 3 + 3k + 6 + 3 ≤ 100 (k ≤ 29), up while
    /// 3 + 3k + 8 + 3 ≤ 50 (k ≤ 12); 4 + 12 + 4 · (29 + 12) = 180 in all. Two corners outside
    /// the plot have none: 2 + 6 + 2 · (29 + 12) = 90. In a 20 × 50 rectangle across
    /// 3 + 3k + 6 + 3 ≤ 20 (k ≤ 2), up k ≤ 12: 16 + 4 · (2 + 12) = 72.
    #[test]
    fn candidates_start_inside_the_corners() {
        let plot = [-50.0, -50.0, 200.0, 200.0];
        let c = candidates((0.0, 0.0), (100.0, 50.0), 6.0, 8.0, plot);
        assert_eq!(c.len(), 180);
        assert_eq!(c[0], [3.0, 3.0, 9.0, 11.0]);
        assert_eq!(c[2], [91.0, 39.0, 97.0, 47.0]);
        assert_eq!(c[4], [-9.0, 3.0, -3.0, 11.0]);
        assert_eq!(c[16], [6.0, 3.0, 12.0, 11.0]);
        let c = candidates(
            (0.0, 0.0),
            (100.0, 50.0),
            6.0,
            8.0,
            [-50.0, -50.0, 90.0, 200.0],
        );
        assert_eq!(c.len(), 90);
        let c = candidates((0.0, 0.0), (20.0, 50.0), 6.0, 8.0, plot);
        assert_eq!(c.len(), 72);
    }
}
