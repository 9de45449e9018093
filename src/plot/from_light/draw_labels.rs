//! The labels of the diagrams seen from the light ([`super`]): the panels' short titles in one
//! column, and the split planes' labels in a gutter, spread apart, each joined by its leader to
//! the cross-section corner that moves the labels least.

use glam::DVec2;

/// A panel's title up to its first colon or comma, without a last word "light": "(c) Eq 19,
/// not in the paper" is "(c) Eq 19", "(a) light ⊥ view" is itself.
pub(in super::super) fn short_title(t: &str) -> String {
    let cut = t.find([':', ',']).unwrap_or(t.len());
    t[..cut].trim_end_matches(" light").to_string()
}

/// The labels' heights (backend pixels, `wanted`, any order) moved apart so that neighbours are
/// at least `step` apart, each as close to its wanted height as that allows, all within
/// `range` (relative to `base`, the gutter's top): the wanted heights are clamped, then pushed
/// down from the top and back up from the bottom.
pub(in super::super) fn spread(
    wanted: &[i32],
    step: i32,
    range: (i32, i32),
    base: i32,
) -> Vec<i32> {
    let mut order: Vec<usize> = (0..wanted.len()).collect();
    order.sort_by_key(|&i| wanted[i]);
    let (lo, hi) = (base + range.0, base + range.1);
    let mut ys: Vec<i32> = order.iter().map(|&i| wanted[i].clamp(lo, hi)).collect();
    for k in 1..ys.len() {
        ys[k] = ys[k].max(ys[k - 1] + step);
    }
    for k in (0..ys.len()).rev() {
        let cap = if k + 1 < ys.len() {
            ys[k + 1] - step
        } else {
            hi
        };
        ys[k] = ys[k].min(cap);
    }
    let mut out = vec![0; wanted.len()];
    for (k, &i) in order.iter().enumerate() {
        out[i] = ys[k];
    }
    out
}

/// The corners of a cross-section furthest right (within `tol`), top first, without repeats:
/// one corner, or the two ends of a vertical right edge.
pub(in super::super) fn right_corners(sec: &[DVec2; 4], tol: f64) -> Vec<DVec2> {
    let right = sec.iter().map(|q| q.x).fold(f64::NEG_INFINITY, f64::max);
    let mut out: Vec<DVec2> = sec.iter().copied().filter(|q| q.x >= right - tol).collect();
    out.sort_by(|a, b| b.y.total_cmp(&a.y));
    out.dedup_by(|a, b| (a.y - b.y).abs() <= tol);
    out
}

/// For each label (nearest plane first), which of its candidate heights (backend pixels, top
/// corner first) its leader starts at: the choice whose leaders keep the planes' order (the
/// farthest highest) and whose spread labels ([`spread`]) move least from their leaders, a top
/// corner preferred where that ties (each lower corner costs half a pixel). Returns the chosen
/// index per label.
pub(in super::super) fn choose_corners(
    candidates: &[Vec<i32>],
    step: i32,
    range: (i32, i32),
    base: i32,
) -> Vec<usize> {
    let count: usize = candidates.iter().map(|c| c.len().max(1)).product();
    let mut best = (f64::INFINITY, vec![0; candidates.len()]);
    for code in 0..count.min(1 << 12) {
        let mut rest = code;
        let pick: Vec<usize> = candidates
            .iter()
            .map(|c| {
                let n = c.len().max(1);
                let k = rest % n;
                rest /= n;
                k
            })
            .collect();
        let wanted: Vec<i32> = candidates.iter().zip(&pick).map(|(c, &k)| c[k]).collect();
        let ys = spread(&wanted, step, range, base);
        // The labels keep the planes' order, the farthest on top: a crossing order costs more
        // than any spread.
        let crossed = wanted.windows(2).any(|w| w[1] > w[0]);
        let cost = ys
            .iter()
            .zip(&wanted)
            .map(|(y, w)| f64::from((y - w).abs()))
            .sum::<f64>()
            + 0.5 * pick.iter().filter(|&&k| k > 0).count() as f64
            + if crossed { 1e6 } else { 0.0 };
        if cost < best.0 {
            best = (cost, pick);
        }
    }
    best.1
}
