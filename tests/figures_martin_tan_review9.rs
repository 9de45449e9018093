//! martin-tan-fig3's inset after the ninth figure review, read back from the SVGs as written, in
//! all three forms (two columns captioned and bare, one column):
//!
//! - R9-martin-tan-fig3-1: the inset's hull C lies between T's sides there (T ⊇ C), and it is
//!   (a)'s hull cut to (a)'s grey box and enlarged as the frame is to the box; the review found
//!   the tan fill running from the frame's top corners, far outside T. Since (a)'s shapes are
//!   placed to a tenth of a unit (R9-martin-tan-fig3-3) the two agree to the frame's rounding.
//! - R9-martin-tan-fig3-2: one column, which does not join the inset to its window, says in its
//!   caption what the inset shows and how much it enlarges it ("inset: (a)'s grey box ×10"),
//!   the factor the one the inset is labelled with and drawn at; two columns say "the inset
//!   enlarges (a)'s grey box".
#![cfg(feature = "plot")]

#[path = "figures_style_read/mod.rs"]
mod read;

use read::{attr, attr_str, forms, points, render_svg, texts, Box4, Font};

/// The hull C's fill, in every panel of the figure.
const HULL: &str = "#D8C498";

/// The grey outlines: (a)'s window (the smaller) and the inset's frame (the larger), each
/// [x0, y0, x1, y1].
fn window_and_frame(svg: &str) -> (Box4, Box4) {
    let mut rects: Vec<Box4> = svg
        .lines()
        .filter(|l| {
            l.starts_with("<rect")
                && l.contains("stroke=\"#5A5A5A\"")
                && l.contains("fill=\"none\"")
        })
        .map(|l| {
            let n = |k: &str| attr(l, k).unwrap();
            [n("x"), n("y"), n("x") + n("width"), n("y") + n("height")]
        })
        .collect();
    assert_eq!(rects.len(), 2, "{rects:?}");
    let area = |r: &Box4| (r[2] - r[0]) * (r[3] - r[1]);
    rects.sort_by(|p, q| area(p).total_cmp(&area(q)));
    (rects[0], rects[1])
}

/// Whether every point lies in `r` grown by `tol`.
fn inside(p: &[(f64, f64)], r: &Box4, tol: f64) -> bool {
    p.iter()
        .all(|q| q.0 >= r[0] - tol && q.0 <= r[2] + tol && q.1 >= r[1] - tol && q.1 <= r[3] + tol)
}

/// Twice the signed area of the triangle o, a, b.
fn cross(o: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

/// The convex hull of points, its corners turning one way (monotone chain).
fn convex_hull(pts: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut p = pts.to_vec();
    p.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    p.dedup();
    fn half(seq: impl Iterator<Item = (f64, f64)>) -> Vec<(f64, f64)> {
        let mut h: Vec<(f64, f64)> = Vec::new();
        for q in seq {
            while h.len() >= 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0.0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
        h
    }
    let mut lower = half(p.iter().copied());
    lower.extend(half(p.iter().rev().copied()));
    lower
}

/// The shoelace area of a polygon.
fn area(poly: &[(f64, f64)]) -> f64 {
    let n = poly.len();
    0.5 * (0..n)
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % n]);
            a.0 * b.1 - b.0 * a.1
        })
        .sum::<f64>()
        .abs()
}

/// How far `p` lies outside the convex polygon `poly` (as [`convex_hull`] turns): the largest
/// distance past one of its sides' lines, 0 or less inside.
fn outside_by(poly: &[(f64, f64)], p: (f64, f64)) -> f64 {
    (0..poly.len())
        .map(|i| {
            let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
            -cross(a, b, p) / (b.0 - a.0).hypot(b.1 - a.1)
        })
        .fold(f64::NEG_INFINITY, f64::max)
}

/// `poly` cut to the box `r`, one side of the box after the other (Sutherland–Hodgman).
fn cut_to(poly: &[(f64, f64)], r: &Box4) -> Vec<(f64, f64)> {
    let mut out = poly.to_vec();
    // Each side: a point's signed distance inside it.
    let sides: [&dyn Fn((f64, f64)) -> f64; 4] =
        [&|p| p.0 - r[0], &|p| r[2] - p.0, &|p| p.1 - r[1], &|p| {
            r[3] - p.1
        }];
    for d in sides {
        let input = std::mem::take(&mut out);
        for (i, &b) in input.iter().enumerate() {
            let a = input[(i + input.len() - 1) % input.len()];
            let (da, db) = (d(a), d(b));
            if (da >= 0.0) != (db >= 0.0) {
                let t = da / (da - db);
                out.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
            }
            if db >= 0.0 {
                out.push(b);
            }
        }
    }
    out
}

/// R9-martin-tan-fig3-1. In every form: the inset's hull C (its one tan polygon inside the
/// frame) has every corner within T's outline in the inset (the hull of T's black 2-unit pieces
/// there, T cut to the window), to 1.5 units; and its area is that of (a)'s hull (the tan
/// polygon reaching into the window) cut to the window and enlarged by the frame's width and
/// height over the window's, to 8 % (the window and the frame are whole-unit rectangles: a
/// half unit on the window's 15 to 36 units; 4.5 % and 2 % as drawn). The old inset, its fill
/// pulled onto the frame's top corners, was 1.5 (two columns) and 1.7 (one) times too large and
/// reached 19 units past T's side across two columns; with (a)'s shapes rounded to whole units
/// (R9-martin-tan-fig3-3, before they were placed to a tenth) (a)'s C cut to the window was
/// 12 % larger than the inset's across two columns.
#[test]
fn inset_hull_lies_within_t_and_is_a_hull_cut_to_the_window() {
    for (form, opts) in forms() {
        let svg = render_svg("martin-tan-fig3", &opts);
        let (window, frame) = window_and_frame(&svg);
        let tans: Vec<Vec<(f64, f64)>> = svg
            .lines()
            .filter(|l| l.starts_with("<polygon") && attr_str(l, "fill") == Some(HULL))
            .map(points)
            .collect();
        let in_frame: Vec<&Vec<(f64, f64)>> =
            tans.iter().filter(|p| inside(p, &frame, 2.0)).collect();
        assert_eq!(
            in_frame.len(),
            1,
            "{form}: hull polygons in the inset {in_frame:?}"
        );
        let c = in_frame[0];
        let t_pieces: Vec<(f64, f64)> = svg
            .lines()
            .filter(|l| {
                l.starts_with("<polyline")
                    && attr_str(l, "stroke") == Some("#000000")
                    && attr(l, "stroke-width") == Some(2.0)
            })
            .map(points)
            .filter(|p| inside(p, &frame, 2.0))
            .flatten()
            .collect();
        let t = convex_hull(&t_pieces);
        assert!(t.len() >= 3, "{form}: T's pieces in the inset {t_pieces:?}");
        for &p in c {
            let by = outside_by(&t, p);
            assert!(
                by <= 1.5,
                "{form}: the inset's C corner {p:?} lies {by:.1} units outside T {t:?}"
            );
        }
        // (a)'s hull: the tan polygon with a corner in the window (the apex), not the inset's.
        let a: Vec<&Vec<(f64, f64)>> = tans
            .iter()
            .filter(|p| !inside(p, &frame, 2.0) && p.iter().any(|q| inside(&[*q], &window, 0.0)))
            .collect();
        assert_eq!(a.len(), 1, "{form}: (a)'s hull {a:?}");
        let (sx, sy) = (
            (frame[2] - frame[0]) / (window[2] - window[0]),
            (frame[3] - frame[1]) / (window[3] - window[1]),
        );
        let want = area(&cut_to(a[0], &window)) * sx * sy;
        let got = area(c);
        assert!(
            (got / want - 1.0).abs() <= 0.08,
            "{form}: the inset's C is {got:.0} square units, (a)'s cut to the window and \
             enlarged {want:.0}"
        );
    }
}

/// R9-martin-tan-fig3-2. One column's caption says "inset: (a)'s grey box ×k" where "×k" is the
/// inset's own label and k is the frame's width over the window's (to the rounding of both
/// whole-unit widths and of k); two columns' says "the inset enlarges (a)'s grey box".
#[test]
fn one_column_caption_names_the_inset_and_its_enlargement() {
    let font = Font::dejavu();
    for (form, opts) in forms() {
        if form == "bare" {
            continue;
        }
        let svg = render_svg("martin-tan-fig3", &opts);
        let all = texts(&font, &svg);
        let caption = all
            .iter()
            .filter(|t| t.tag.contains("fill=\"#323232\""))
            .map(|t| t.content.as_str())
            .collect::<Vec<_>>()
            .join(" ")
            .replace('\u{a0}', " ");
        let label = all
            .iter()
            .find(|t| t.tag.contains("fill=\"#5A5A5A\"") && t.content.starts_with('×'))
            .unwrap_or_else(|| panic!("{form}: no ×k label in the inset"))
            .content
            .replace('\u{a0}', " ");
        if form == "double" {
            assert!(
                caption.contains("the inset enlarges (a)'s grey box"),
                "{form}: {caption}"
            );
            continue;
        }
        assert!(
            caption.contains(&format!("inset: (a)'s grey box {label}")),
            "{form}: the caption does not name the inset {label}: {caption}"
        );
        let k: f64 = label.trim_start_matches('×').parse().unwrap();
        let (window, frame) = window_and_frame(&svg);
        let (ww, fw) = (window[2] - window[0], frame[2] - frame[0]);
        let drawn = fw / ww;
        assert!(
            (k - drawn).abs() <= 0.5 + drawn * 2.0 / ww,
            "{form}: the caption says ×{k}, the inset is drawn {drawn:.2}×"
        );
    }
}
