//! lloyd2005-fig8 (a)'s tags for parts too small to hold them: a row under the drawing, in
//! the order whose leaders do not cross.

use super::inside;
use glam::DVec2;

/// A tag under panel (a)'s drawing: its part's centre, the tag's half width (data units), the tag.
pub(super) type Outside<'a> = (DVec2, f64, &'a str);

/// The x of tags in a row under a drawing, in the order given: each at its part's centre
/// where room allows, at least `gap` from its neighbours and inside `(lo, hi)` (pushed right
/// from the left, then back from the right).
fn pack(outside: &[Outside<'_>], (lo, hi): (f64, f64), gap: f64) -> Vec<f64> {
    let mut xs: Vec<f64> = Vec::with_capacity(outside.len());
    for (k, (mid, hw, _)) in outside.iter().enumerate() {
        // Clear of the frame: a tag at the left end touched the y axis.
        let low = match k {
            0 => lo + hw + gap,
            _ => xs[k - 1] + outside[k - 1].1 + gap + hw,
        };
        xs.push(mid.x.max(low));
    }
    for k in (0..xs.len()).rev() {
        let high = match outside.get(k + 1) {
            Some(next) => xs[k + 1] - next.1 - gap - outside[k].1,
            None => hi - outside[k].1 - gap,
        };
        xs[k] = xs[k].min(high);
    }
    xs
}

/// Whether the segments `a`–`b` and `c`–`d` cross (touching ends do not count).
fn segments_cross(a: DVec2, b: DVec2, c: DVec2, d: DVec2) -> bool {
    let side = |p: DVec2, q: DVec2, r: DVec2| (q - p).perp_dot(r - p);
    let (d1, d2) = (side(c, d, a), side(c, d, b));
    let (d3, d4) = (side(a, b, c), side(a, b, d));
    d1 * d2 < 0.0 && d3 * d4 < 0.0
}

/// The order of the tags under panel (a) (and their x, [`pack`]) whose leaders, from each
/// part's centre to its tag's top at height `end_y`, cross one another least, then run least
/// over other parts (`outlines`, convex) and slant least: every order of up to six tags is
/// tried (the figure has five), more keep their centres' order.
pub(super) fn leader_order<'a>(
    outside: Vec<Outside<'a>>,
    range: (f64, f64),
    gap: f64,
    end_y: f64,
    outlines: &[&[DVec2]],
) -> (Vec<Outside<'a>>, Vec<f64>) {
    let mut by_x = outside;
    by_x.sort_by(|a, b| a.0.x.total_cmp(&b.0.x));
    if by_x.len() > 6 {
        let xs = pack(&by_x, range, gap);
        return (by_x, xs);
    }
    let cost = |order: &[Outside<'_>], xs: &[f64]| -> f64 {
        let leaders: Vec<(DVec2, DVec2)> = order
            .iter()
            .zip(xs)
            .map(|(o, &x)| (o.0, DVec2::new(x, end_y)))
            .collect();
        let mut crossings = 0;
        for (i, a) in leaders.iter().enumerate() {
            for b in &leaders[..i] {
                crossings += usize::from(segments_cross(a.0, a.1, b.0, b.1));
            }
        }
        // How many of each leader's 23 samples lie over parts other than its own.
        let mut over = 0;
        for &(from, to) in &leaders {
            for j in 1..24 {
                let p = from + (to - from) * (f64::from(j) / 24.0);
                over += usize::from(outlines.iter().any(|o| !inside(o, from) && inside(o, p)));
            }
        }
        // Leaders that slant far read as pointing elsewhere: the squares of their runs
        // across (data units).
        let slant: f64 = leaders.iter().map(|(a, b)| (b.x - a.x).powi(2)).sum();
        1e6 * crossings as f64 + 10.0 * over as f64 + slant
    };
    let mut best = (f64::INFINITY, by_x.clone(), pack(&by_x, range, gap));
    let mut order: Vec<usize> = (0..by_x.len()).collect();
    permute(&mut order, 0, &mut |perm| {
        let tried: Vec<Outside<'a>> = perm.iter().map(|&i| by_x[i]).collect();
        let xs = pack(&tried, range, gap);
        let c = cost(&tried, &xs);
        if c < best.0 {
            best = (c, tried, xs);
        }
    });
    (best.1, best.2)
}

/// Calls `f` with every order of `items[k..]` after `items[..k]`.
fn permute(items: &mut [usize], k: usize, f: &mut impl FnMut(&[usize])) {
    if k == items.len() {
        f(items);
        return;
    }
    for i in k..items.len() {
        items.swap(k, i);
        permute(items, k + 1, f);
        items.swap(k, i);
    }
}
