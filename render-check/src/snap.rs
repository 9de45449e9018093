//! The stable cascades' world-fixed texel grid (docs/rendered.md, "What is measured", 5): a
//! stable cascade is stable because, whatever the camera does, its texels stay where they are
//! in the world. Between two frames a fixed world point may then move by whole texels only. Over
//! the shimmer test's frames render-check follows fixed world points (the test's shadow-edge
//! points) through each stable map of consecutive frames, in texels (the map's clip x, y
//! times res/2, from the map's `f64` eye → clip matrix after render-check's own world → eye), and
//! reports how far the move lies from a whole number of texels (`stable_grid_texels`).
//!
//! It is independent of the crate's snapping code: it needs no texel size or grid origin of the
//! crate's, only the resolution render-check asked for and the matrices the maps are drawn with.
//! A map snapped to a grid that is not its texel (a step of 2r/res instead of 2·half/res, with
//! half = r·res/(res − 2)) moves world points by 1 − 2/res texels (2·10⁻³ at 1024²); shadow
//! states then flip too rarely for the 0.1 % shimmer target to see.

use crate::schemes::{Built, View};
use glam::DVec3;

/// The texel coordinates (s, t in texels) of the world point `p` in map `k` of `built`, whose
/// camera is `view`.
fn texels(view: &View, built: &Built, k: usize, p: DVec3) -> (f64, f64) {
    let m = &built.maps[k];
    let h = m.built * view.world_to_eye.transform_point3(p).extend(1.0);
    let half = 0.5 * f64::from(m.res);
    (h.x / h.w * half, h.y / h.w * half)
}

/// The distance of `x` from the nearest whole number.
fn off_whole(x: f64) -> f64 {
    (x - x.round()).abs()
}

/// How far the moves of the fixed world `points` between frame `a` and frame `b` (each its view
/// and its maps) lie from whole numbers of texels, along s and t, the largest over the points
/// and every map of `b` that has a map of `a` over the same split range (the same cascade: the
/// splits are fixed relative to the camera) at the same resolution. NaN where no map pairs or
/// no point is given: nothing measured is no pass.
pub fn grid_offset_texels(a: (&View, &Built), b: (&View, &Built), points: &[DVec3]) -> f64 {
    let same = |x: f64, y: f64| (x / y - 1.0).abs() <= 1e-9;
    let mut worst: Option<f64> = None;
    for (kb, mb) in b.1.maps.iter().enumerate() {
        let Some(ka) =
            a.1.maps
                .iter()
                .position(|ma| ma.res == mb.res && same(ma.near, mb.near) && same(ma.far, mb.far))
        else {
            continue;
        };
        for &p in points {
            let (sa, ta) = texels(a.0, a.1, ka, p);
            let (sb, tb) = texels(b.0, b.1, kb, p);
            let d = off_whole(sb - sa).max(off_whole(tb - ta));
            // A NaN (a degenerate matrix) is no pass.
            if d.is_nan() {
                return f64::NAN;
            }
            worst = Some(worst.map_or(d, |w| w.max(d)));
        }
    }
    worst.unwrap_or(f64::NAN)
}
