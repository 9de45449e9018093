//! The convex hull of points in the plane, without allocation.

use glam::DVec2;

/// Convex hull (monotone chain, counter-clockwise, no repeated end point) of `pts` into `out`;
/// returns the number of hull vertices. Sorts `pts` in place; no allocation. The chain's stack
/// holds at most 2n − 1 points (the lower hull, then at most n − 1 more), so `out` needs 2n slots.
pub(crate) fn convex_hull(pts: &mut [DVec2], out: &mut [DVec2]) -> usize {
    let n = pts.len();
    if n < 3 {
        out[..n].copy_from_slice(pts);
        return n;
    }
    pts.sort_unstable_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let mut k = 0usize;
    for &p in pts.iter() {
        while k >= 2 && (out[k - 1] - out[k - 2]).perp_dot(p - out[k - 2]) <= 0.0 {
            k -= 1;
        }
        out[k] = p;
        k += 1;
    }
    let lower = k + 1;
    for i in (0..n - 1).rev() {
        while k >= lower && (out[k - 1] - out[k - 2]).perp_dot(pts[i] - out[k - 2]) <= 0.0 {
            k -= 1;
        }
        out[k] = pts[i];
        k += 1;
    }
    k - 1
}
