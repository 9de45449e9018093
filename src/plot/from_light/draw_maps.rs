//! The maps' outlines drawn fine (barroso-fig5; the ninth review, R9-barroso-fig5-1: in the
//! overview (a) map 3's outline, about 35 × 20 units, was drawn 5 units wide with a dash-dot of
//! 20 units, longer than its sides, and printed as scattered purple blobs). A fine outline is
//! at most 2 units wide (2 pt in two columns, 1.6 pt in one) and dashed along each side with
//! its map's pattern fitted to the side: a whole number of periods, the side starting and
//! ending on a dash (so that the corners are drawn). A detail's side ([`detail_dashes`]) takes
//! at least [`DETAIL_LEAST_PERIODS`] periods of the pattern where they fit, else two of the
//! pattern scaled down to no less than [`DETAIL_LEAST_SCALE`] where they print, else it is
//! solid (the eighteenth review, R18-barroso-fig5-1: one column's 15.6-unit map 1 in (d) was
//! solid); an overview's side
//! ([`overview_dashes`]) takes the most periods, up to [`LEAST_PERIODS`], that print (dashes at
//! least [`LEAST_DASH_PT`], gaps [`LEAST_GAP_PT`]), of the pattern scaled down or, shorter
//! still, of its kind at its shortest ([`least_pattern`]), and is solid only where not even one
//! period prints (the thirteenth review, R13-barroso-fig5-1: map 3's sides in the overviews,
//! 10 to 24 units, were solid, and map 3 did not read as the key's dash-dot).
//! lloyd2006-fig11 keeps the wide outlines of [`super::map_stroke`].

use super::super::super::chart::{column, draw_fine_line, Chart2d, Dash};
use super::super::super::Column;
use super::super::super::Fail;
use super::super::Panel;
use super::map_colour;
use glam::DVec2;
use plotters::prelude::*;

/// The fine outlines' dash lengths against the wide outlines' [`super::PATTERNS`], in two
/// columns and in one (units print 1 pt and 0.8 pt), for maps 1 and 2 and for maps 3 and 4:
/// two thirds and five sixths, and a half in both, so that the shortest dash (map 1's) is 4 pt
/// in either (the eleventh review's least, R11-barroso-fig5-1), the long ones 6 and 7 units
/// (at least 4.8 pt), and the overviews' far maps keep four whole periods on their long sides
/// (R9-barroso-fig5-1). Each map's pattern is the wide one's kind, its lengths in the same
/// ratios (R11-X-1: map i has one dash kind in both figures).
pub(super) const FINE_SCALE: [[f64; 2]; 2] = [[2.0 / 3.0, 0.5], [5.0 / 6.0, 0.5]];

/// [`super::PATTERNS`], maps 1 and 2 times `a`, 3 and 4 times `b`.
macro_rules! scaled {
    ($a:expr, $b:expr) => {
        [
            &[6.0 * $a, 3.0 * $a],
            &[4.0 * $a, 3.0 * $a],
            &[12.0 * $b, 3.0 * $b, 2.0 * $b, 3.0 * $b],
            &[14.0 * $b, 4.0 * $b],
        ]
    };
}

/// Each fine map's dash pattern (lengths on, off, … in units, nearest map first), in two
/// columns and in one: dashes, square dots, dash-dot, long dashes, [`super::PATTERNS`] scaled
/// by [`FINE_SCALE`].
pub(super) const FINE_PATTERNS: [[&[f64]; 4]; 2] = [
    scaled!(FINE_SCALE[0][0], FINE_SCALE[0][1]),
    scaled!(FINE_SCALE[1][0], FINE_SCALE[1][1]),
];

/// The least number of whole periods a side of a detail's map ((b), (d), (f)) is dashed with
/// where they fit: two (a dash, a gap, a dash, a gap, a dash at least), so that the dash kinds
/// show on the details' maps, whose sides are 15 to 130 units; the overviews keep
/// [`LEAST_PERIODS`] (R9-barroso-fig5-1). A shorter side takes two of the pattern scaled down,
/// to no less than [`DETAIL_LEAST_SCALE`], else is solid ([`detail_dashes`]).
pub(super) const DETAIL_LEAST_PERIODS: f64 = 2.0;

/// Every fine outline's width: 2 units (2 pt in two columns, 1.6 pt in one), the eleventh
/// review's least of 1.5 pt (R11-barroso-fig5-1: maps 1 and 3 were 1 unit wide) and the ninth
/// review's most of 2 pt (R9-barroso-fig5-1). Where two maps share an edge (a light overhead),
/// the nearer is drawn over the farther, whose colour shows in its gaps; the numbers at the
/// maps' corners ([`super::numbers`]) say which rectangle is which.
const FINE_WIDTH: u32 = 2;

/// The number of whole periods an overview's side is dashed with where they print: fewer
/// only where a side is too short for them ([`overview_dashes`]).
pub(super) const LEAST_PERIODS: f64 = 4.0;

/// The shortest dash that prints, in pt (a dot of a 2 pt wide line is at least 1 pt long).
pub(super) const LEAST_DASH_PT: f64 = 1.0;

/// The shortest gap that prints, in pt.
pub(super) const LEAST_GAP_PT: f64 = 0.8;

/// Page units per pt: 1 in two columns, 1.25 in one (a unit prints 0.8 pt).
fn units_per_pt() -> f64 {
    if column() == Column::Single {
        1.25
    } else {
        1.0
    }
}

/// `pattern`'s kind at its shortest (lengths in pt): each dash with the gap after it keeps its
/// share of the two (the kind), the dash at least [`LEAST_DASH_PT`] and the gap at least
/// [`LEAST_GAP_PT`], each pair as short as that allows. By hand: dashes 6 : 3 (share 2/3) are
/// 1.6, 0.8; a dash-dot 12 : 3 : 2 : 3 (shares 0.8, 0.4) is 3.2, 0.8, 1, 1.5.
pub(super) fn least_pattern(pattern: &[f64]) -> Vec<f64> {
    pattern
        .chunks(2)
        .flat_map(|pair| match *pair {
            [a, b] if a > 0.0 && b > 0.0 => {
                let share = a / (a + b);
                let dash = LEAST_DASH_PT.max(LEAST_GAP_PT * share / (1.0 - share));
                vec![dash, dash * (1.0 - share) / share]
            }
            _ => pair.to_vec(),
        })
        .collect()
}

/// Whether `pattern` (units) times `scale` prints: every dash at least [`LEAST_DASH_PT`], every
/// gap [`LEAST_GAP_PT`].
fn prints(pattern: &[f64], scale: f64) -> bool {
    let per_pt = units_per_pt();
    pattern.iter().enumerate().all(|(j, &v)| {
        let least = if j % 2 == 0 {
            LEAST_DASH_PT
        } else {
            LEAST_GAP_PT
        };
        scale * v >= least * per_pt - 1e-9
    })
}

/// An overview's side `len` units long dashed with `pattern` (units): where the pattern fits at
/// least [`LEAST_PERIODS`] whole periods, as [`side_dashes`] fits them; else the most periods
/// k, from [`LEAST_PERIODS`] down to 1, for which the pattern scaled to k periods and a last
/// dash prints (every dash at least [`LEAST_DASH_PT`], every gap [`LEAST_GAP_PT`]), or else
/// its kind at its shortest ([`least_pattern`]) stretched to k periods does; the whole side
/// where not even one period prints.
pub(super) fn overview_dashes(len: f64, pattern: &[f64]) -> Vec<(f64, f64)> {
    let dashes = side_dashes(len, pattern, LEAST_PERIODS);
    if dashes.len() > 1 || pattern.len() < 2 || len <= 0.0 {
        return dashes;
    }
    let per_pt = units_per_pt();
    let least: Vec<f64> = least_pattern(pattern).iter().map(|v| v * per_pt).collect();
    for k in (1..=LEAST_PERIODS as usize).rev() {
        for p in [pattern, &least[..]] {
            let (period, first): (f64, f64) = (p.iter().sum(), p[0]);
            let scale = len / (k as f64 * period + first);
            if prints(p, scale) {
                return fitted(len, p, k, scale);
            }
        }
    }
    vec![(0.0, len)]
}

/// The most a detail's pattern is scaled down on a short side ([`detail_dashes`]): to three
/// fifths, so that map 1's dashes stay at least 2.4 pt (4 pt × 3/5, 1.2 times the line's width
/// and longer than its gaps) and read as the key's dashes, not as dots; two periods and a last
/// dash of map 1's pattern thus fit a side of 16 × 3/5 = 9.6 units in two columns and
/// 20 × 3/5 = 12 units in one (9.6 pt either way).
pub(super) const DETAIL_LEAST_SCALE: f64 = 0.6;

/// A detail's side `len` units long dashed with `pattern` (units): where the pattern fits at
/// least [`DETAIL_LEAST_PERIODS`] whole periods, as [`side_dashes`] fits them; else that many
/// periods and a last dash of the pattern scaled down to the side, where the scale is at least
/// [`DETAIL_LEAST_SCALE`] and the scaled pattern prints ([`prints`]); else the whole side. The
/// eighteenth review, R18-barroso-fig5-1: in one column map 1's pattern (5, 2.5) fits
/// round((15.6 − 5)/7.5) = 1 period on the 15.6-unit sides of (d)'s square, fewer than two, and
/// the square was drawn solid (in two columns (4, 2) fits 2 on its 18.8-unit sides, dashed);
/// now two periods scaled by 15.6/20 = 0.78 (dashes 3.9 units, 3.1 pt; gaps 1.95 units,
/// 1.56 pt). The maps a few units across in (b) and (f) stay solid (map 1's 7 units in two
/// columns would take a scale of 0.44, its dashes 1.75 pt: dots).
pub(super) fn detail_dashes(len: f64, pattern: &[f64]) -> Vec<(f64, f64)> {
    let dashes = side_dashes(len, pattern, DETAIL_LEAST_PERIODS);
    if dashes.len() > 1 || pattern.len() < 2 || len <= 0.0 {
        return dashes;
    }
    let (period, first): (f64, f64) = (pattern.iter().sum(), pattern[0]);
    let k = DETAIL_LEAST_PERIODS as usize;
    let scale = len / (k as f64 * period + first);
    if (DETAIL_LEAST_SCALE - 1e-12..1.0).contains(&scale) && prints(pattern, scale) {
        return fitted(len, pattern, k, scale);
    }
    dashes
}

/// `k` periods of `pattern` times `scale` and a last dash, from 0, the last dash ending at `len`.
fn fitted(len: f64, pattern: &[f64], k: usize, scale: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let mut s = 0.0;
    for _ in 0..k {
        for pair in pattern.chunks(2) {
            out.push((s, s + scale * pair[0]));
            s += scale * pair.iter().sum::<f64>();
        }
    }
    out.push((s, len));
    out
}

/// Map `i`'s fine outline (0: the nearest): its colour ([`map_colour`]), stroke width and
/// dash pattern.
pub(super) fn fine_stroke(i: usize) -> (RGBColor, u32, &'static [f64]) {
    (
        map_colour(i),
        FINE_WIDTH,
        FINE_PATTERNS[usize::from(column() == Column::Single)][i % 4],
    )
}

/// The dashes along a side `len` units long: intervals (from, to) along it, the first from 0
/// and the last to `len`, the pattern stretched or shrunk to a whole number `k` of periods and
/// a last dash, `k` ≥ `least`; the whole side where fewer fit (or the pattern is empty).
pub(super) fn side_dashes(len: f64, pattern: &[f64], least: f64) -> Vec<(f64, f64)> {
    let period: f64 = pattern.iter().sum();
    let first = pattern.first().copied().unwrap_or(0.0);
    if pattern.len() < 2 || period <= 0.0 || len <= 0.0 {
        return vec![(0.0, len.max(0.0))];
    }
    let k = ((len - first) / period).round();
    if k < least.max(1.0) {
        return vec![(0.0, len)];
    }
    fitted(len, pattern, k as usize, len / (k * period + first))
}

/// The pieces of a rectangle's outline (corners in order, in units, `draw[i]` whether the side
/// from corner i to corner i + 1 is drawn: a side outside the panel is not), each side dashed
/// by `dashes` (its length to its dashes, as [`side_dashes`]); the dashes that meet at a corner are one piece through it, so that the
/// corner is joined. An outline solid all round is one closed line starting and ending halfway
/// along its first side (a line closed at a corner meets itself in two square ends).
pub(super) fn outline_pieces(
    corners: [(f64, f64); 4],
    draw: [bool; 4],
    dashes: impl Fn(f64) -> Vec<(f64, f64)>,
) -> Vec<Vec<(f64, f64)>> {
    let at = |i: usize| corners[i % 4];
    let side = |i: usize| {
        let (a, b) = (at(i), at(i + 1));
        (b.0 - a.0).hypot(b.1 - a.1)
    };
    let total: f64 = (0..4).map(side).sum();
    let start: Vec<f64> = (0..4)
        .scan(0.0, |s, i| {
            let v = *s;
            *s += side(i);
            Some(v)
        })
        .collect();
    // The dashes as intervals of the distance along the outline from corner 0, joined where
    // one ends where the next begins (at a corner).
    let mut runs: Vec<(f64, f64)> = Vec::new();
    for i in (0..4).filter(|&i| draw[i] && side(i) > 0.0) {
        for (a, b) in dashes(side(i)) {
            let (a, b) = (start[i] + a, start[i] + b);
            match runs.last_mut() {
                Some(last) if (last.1 - a).abs() <= 1e-9 * total => last.1 = b,
                _ => runs.push((a, b)),
            }
        }
    }
    if runs.len() > 1 {
        let (first, last) = (runs[0], runs[runs.len() - 1]);
        if first.0.abs() <= 1e-9 * total && (last.1 - total).abs() <= 1e-9 * total {
            runs.pop();
            runs[0] = (last.0 - total, first.1);
        }
    }
    // The point at distance s along the outline (s may run past 0 or the total).
    let point = |s: f64| {
        let s = s.rem_euclid(total);
        let i = (0..4).rev().find(|&i| start[i] <= s).unwrap_or(0);
        let (a, b) = (at(i), at(i + 1));
        let t = if side(i) > 0.0 {
            (s - start[i]) / side(i)
        } else {
            0.0
        };
        (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
    };
    let whole = runs.len() == 1 && runs[0].1 - runs[0].0 >= total * (1.0 - 1e-9);
    if whole {
        let mid = 0.5 * side(0);
        let mut pts = vec![point(mid)];
        pts.extend((1..4).map(at));
        pts.push(at(0));
        pts.push(point(mid));
        return vec![pts];
    }
    runs.iter()
        .map(|&(a, b)| {
            let mut pts = vec![point(a)];
            // The corners strictly inside the run, the outline's and its next lap's.
            for c in (0..12).map(|k| start[k % 4] + total * ((k / 4) as f64 - 1.0)) {
                if c > a + 1e-9 * total && c < b - 1e-9 * total {
                    pts.push(point(c));
                }
            }
            pts.push(point(b));
            pts
        })
        .collect()
}

/// Panel `p`'s maps drawn fine ([`fine_stroke`]) over the frustum's lines, the farthest first,
/// each clipped to the plot (`bounds`: x and y ranges; a side outside it is not drawn) and
/// each drawn side dashed with whole periods ([`outline_pieces`]): in a detail by
/// [`detail_dashes`], in an overview by [`overview_dashes`];
/// `per_unit` page units a data unit. Over the lines: a fine outline is
/// no wider than the frustum's edges, and under them it would not show where it lies on one.
pub(super) fn fine_maps<DB: DrawingBackend>(
    chart: &Chart2d<'_, DB>,
    p: &Panel,
    (x0, x1, y0, y1): (f64, f64, f64, f64),
    per_unit: f64,
) -> Result<(), Fail> {
    // The farthest first: where two maps share an edge the nearer is on top.
    for i in (0..p.maps.len()).rev() {
        let (a, b) = p.maps[i];
        let (lo, hi) = (a.max(DVec2::new(x0, y0)), b.min(DVec2::new(x1, y1)));
        if lo.x > hi.x || lo.y > hi.y {
            continue;
        }
        // Bottom, right, top, left: each drawn where the map's own side is inside the plot.
        let draw = [a.y >= y0, b.x <= x1, b.y <= y1, a.x >= x0];
        let page = |q: DVec2| (q.x * per_unit, q.y * per_unit);
        let corners = [
            page(lo),
            page(DVec2::new(hi.x, lo.y)),
            page(hi),
            page(DVec2::new(lo.x, hi.y)),
        ];
        let (colour, width, pattern) = fine_stroke(i);
        let detail = p.window.is_some();
        let dashes = |len: f64| {
            if detail {
                detail_dashes(len, pattern)
            } else {
                overview_dashes(len, pattern)
            }
        };
        for piece in outline_pieces(corners, draw, dashes) {
            let data: Vec<(f64, f64)> = piece
                .iter()
                .map(|&(x, y)| (x / per_unit, y / per_unit))
                .collect();
            draw_fine_line(chart, &data, colour, width, Dash::Solid)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each fine pattern is its wide one (lloyd2006-fig11's) times one factor, so that map i
    /// has one dash kind in both figures (R11-X-1); its first dash, but map 2's dots, is at
    /// least 4 pt (4 units in two columns, 5 units of 0.8 pt in one; R11-barroso-fig5-1): by
    /// hand, map 1's are 6 · 2/3 = 4 and 6 · 5/6 = 5 units.
    #[test]
    fn fine_patterns_are_the_wide_ones_scaled() {
        for (col, least) in [(0, 4.0), (1, 5.0)] {
            for (i, fine) in FINE_PATTERNS[col].iter().enumerate() {
                let wide = super::super::PATTERNS[i];
                assert_eq!(fine.len(), wide.len());
                let k = fine[0] / wide[0];
                for (f, w) in fine.iter().zip(wide) {
                    assert!((f - k * w).abs() < 1e-12, "map {} {fine:?} {wide:?}", i + 1);
                }
                assert!(i == 1 || fine[0] >= least - 1e-12, "map {} {fine:?}", i + 1);
            }
        }
        assert!((FINE_PATTERNS[0][0][0] - 4.0).abs() < 1e-12);
        assert!((FINE_PATTERNS[1][0][0] - 5.0).abs() < 1e-12);
    }

    /// A side of 40 units with the pattern (3, 1.2): k = round((40 − 3)/4.2) = round(8.81) = 9
    /// periods and a last dash, stretched by 40/(9·4.2 + 3) = 0.98039 (by hand): ten dashes,
    /// the first from 0, the last to 40, starts 4.1176 apart; a side of 15 units (k =
    /// round(2.86) = 3 < 4) is solid.
    #[test]
    fn a_side_holds_whole_periods_or_is_solid() {
        let d = side_dashes(40.0, &[3.0, 1.2], 4.0);
        assert_eq!(d.len(), 10);
        assert_eq!(d[0].0, 0.0);
        assert!((d[9].1 - 40.0).abs() < 1e-12);
        assert!((d[1].0 - d[0].0 - 4.1176).abs() < 1e-4, "{d:?}");
        assert!((d[0].1 - 2.9412).abs() < 1e-4, "{d:?}");
        assert_eq!(side_dashes(15.0, &[3.0, 1.2], 4.0), vec![(0.0, 15.0)]);
    }

    /// R18-barroso-fig5-1, by hand: one column's map 1 pattern (5, 2.5) on (d)'s 15.6-unit side
    /// fits round(10.6/7.5) = 1 period, fewer than two: [`side_dashes`] leaves it solid, while
    /// [`detail_dashes`] scales the pattern by 15.6/20 = 0.78 to two periods and a last dash:
    /// three dashes 3.9 long, 5.85 apart, the last ending at 15.6. A side of 40 keeps
    /// [`side_dashes`]'s periods; two columns' (4, 2) on (b)'s 7-unit map 1 would be scaled by
    /// 7/16 = 0.44 < 3/5 and stays solid, on 9.6 units by 3/5 is dashed.
    #[test]
    fn a_short_detail_side_is_dashed_scaled_down() {
        let p = [5.0, 2.5];
        assert_eq!(
            side_dashes(15.6, &p, DETAIL_LEAST_PERIODS),
            vec![(0.0, 15.6)]
        );
        let d = detail_dashes(15.6, &p);
        assert_eq!(d.len(), 3, "{d:?}");
        for (j, &(a, b)) in d.iter().enumerate() {
            assert!((a - 5.85 * j as f64).abs() < 1e-9, "{d:?}");
            assert!((b - a - 3.9).abs() < 1e-9, "{d:?}");
        }
        assert!((d[2].1 - 15.6).abs() < 1e-9);
        assert_eq!(detail_dashes(7.0, &[4.0, 2.0]), vec![(0.0, 7.0)]);
        assert_eq!(detail_dashes(9.6, &[4.0, 2.0]).len(), 3);
        assert_eq!(
            detail_dashes(40.0, &p),
            side_dashes(40.0, &p, DETAIL_LEAST_PERIODS)
        );
    }

    /// A 10 × 4 rectangle, solid all round: one closed line from the middle of its first side,
    /// (5, 0), round the corners (10, 0), (10, 4), (0, 4), (0, 0) and back.
    #[test]
    fn a_solid_outline_is_closed_mid_side() {
        let c = [(0.0, 0.0), (10.0, 0.0), (10.0, 4.0), (0.0, 4.0)];
        let p = outline_pieces(c, [true; 4], |l| side_dashes(l, &[3.0, 1.2], 4.0));
        assert_eq!(
            p,
            vec![vec![
                (5.0, 0.0),
                (10.0, 0.0),
                (10.0, 4.0),
                (0.0, 4.0),
                (0.0, 0.0),
                (5.0, 0.0)
            ]]
        );
    }

    /// A 40 × 10 rectangle: its long sides dashed (ten dashes each), its short ones solid; the
    /// solid sides and the dashes at their ends are one piece through the corner, so that the
    /// pieces are 2 × 8 inner dashes and 2 corner pieces, 18 in all; without the bottom side
    /// drawn, the pieces at its ends stop at the corners.
    #[test]
    fn dashes_join_at_the_corners() {
        let c = [(0.0, 0.0), (40.0, 0.0), (40.0, 10.0), (0.0, 10.0)];
        let p = outline_pieces(c, [true; 4], |l| side_dashes(l, &[3.0, 1.2], 4.0));
        assert_eq!(p.len(), 18, "{p:?}");
        let right = p
            .iter()
            .find(|q| q.contains(&(40.0, 0.0)))
            .expect("a piece round the corner (40, 0)");
        assert!(right.contains(&(40.0, 10.0)), "{right:?}");
        let p = outline_pieces(c, [false, true, true, true], |l| {
            side_dashes(l, &[3.0, 1.2], 4.0)
        });
        assert_eq!(p.len(), 10, "{p:?}");
        assert!(p.iter().any(|q| q[0] == (40.0, 0.0)));
        assert!(p.iter().any(|q| q[q.len() - 1] == (0.0, 0.0)));
    }

    /// By hand: a dash-dot 12 : 3 : 2 : 3 at its shortest is 3.2, 0.8, 1, 1.5 pt (shares 0.8
    /// and 0.4, gap 0.8 and dot 1 the least), dashes 6 : 3 are 1.6, 0.8. A side 20.8 units long
    /// (two columns, 1 pt a unit) with the dash-dot 10 : 2.5 : 5/3 : 2.5: four periods scaled
    /// (20.8/76.67 = 0.27: a 0.45 pt dot) or of the shortest (20.8/29.2 < 1) do not print, nor
    /// three; two of the shortest do, stretched 20.8/16.2 = 1.284: dashes at 0 and 5.136,
    /// 4.109 long, a dot 1.284 long at 4.109 + 1.027 = 5.136 … five dashes in all; a side of
    /// 9 units (one period needs 9.7) is solid.
    #[test]
    fn an_overview_side_takes_the_most_periods_that_print() {
        let least = least_pattern(&[12.0, 3.0, 2.0, 3.0]);
        for (v, w) in least.iter().zip([3.2, 0.8, 1.0, 1.5]) {
            assert!((v - w).abs() < 1e-12, "{least:?}");
        }
        let least = least_pattern(&[6.0, 3.0]);
        assert!((least[0] - 1.6).abs() < 1e-12 && (least[1] - 0.8).abs() < 1e-12);
        let d = overview_dashes(20.8, &[10.0, 2.5, 5.0 / 3.0, 2.5]);
        assert_eq!(d.len(), 5, "{d:?}");
        assert!(d[0].0 == 0.0 && (d[0].1 - 4.1086).abs() < 1e-3, "{d:?}");
        assert!((d[1].0 - 5.1358).abs() < 1e-3 && (d[1].1 - d[1].0 - 1.2840).abs() < 1e-3);
        assert!((d[4].1 - 20.8).abs() < 1e-12);
        assert_eq!(
            overview_dashes(9.0, &[10.0, 2.5, 5.0 / 3.0, 2.5]),
            vec![(0.0, 9.0)]
        );
    }
}
