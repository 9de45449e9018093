//! Cascades' cross-fade (docs/rendered.md, "What is measured", 6): the blend bands the requested
//! overlap makes at a pixel's exact view depth, and whether the shader's cross-fade there is
//! theirs; and the map the paper's split planes and those bands name at a depth (the split
//! check, "What is measured", 10).

use crate::gpu::FrameOutput;
use crate::schemes::Built;

/// How far the shader's weight of a map in a blend band may lie from the frame's at the pixel's
/// exact depth: the GPU's view depth is interpolated in `f32` (about 10⁻⁵ of a band's width).
pub const BLEND_WEIGHT_TOLERANCE: f64 = 1e-3;

/// How far the shaded visibility may lie from `(1 − w) v₁ + w v₂` (the two maps' lookups and the
/// weight the shader applied): `f32` rounding of the mix.
pub const BLEND_VALUE_TOLERANCE: f64 = 1e-4;

/// The blend band of `built` holding view depth `z`: its first map j and the weight of map
/// j + 1, from the bands the requested overlap makes (`Built::bands`, computed by render-check
/// from the paper's split planes and the overlap, not `FrameMap::blend`: a band the frame places
/// wrongly, or drops, is a mismatch).
pub(crate) fn band_at(built: &Built, z: f64) -> Option<(usize, f64)> {
    let n = built.maps.len();
    built.bands.iter().enumerate().find_map(|(j, &(b, e))| {
        (j + 1 < n && b < e && z >= b && z < e).then(|| (j, (z - b) / (e - b)))
    })
}

/// The maps a pixel at view depth `z` is shaded from with a weight above
/// [`BLEND_WEIGHT_TOLERANCE`], by the frame's bands: the pair of its band, or none outside one.
pub(crate) fn band_maps(built: &Built, z: f64) -> Vec<usize> {
    match band_at(built, z) {
        Some((j, w)) => [(j, 1.0 - w), (j + 1, w)]
            .into_iter()
            .filter(|&(_, x)| x > BLEND_WEIGHT_TOLERANCE)
            .map(|(k, _)| k)
            .collect(),
        None => Vec::new(),
    }
}

/// Whether the cross-fade at pixel `i` is right: the shader's weights (first map `part`, second
/// map and its weight from [`FrameOutput::blend`]) against the frame's band at the exact depth
/// `z`, and the shaded visibility against the weighted pair of the two maps' lookups.
pub(crate) fn blend_agrees(
    out: &FrameOutput,
    i: usize,
    part: usize,
    built: &Built,
    z: f64,
) -> bool {
    let [second, wg, v1, v2] = out.blend[i].map(f64::from);
    let vis = f64::from(out.texel[i][3]);
    if (vis - ((1.0 - wg) * v1 + wg * v2)).abs() > BLEND_VALUE_TOLERANCE {
        return false;
    }
    let second = second as usize;
    let weight_of = |k: usize| {
        let mut x = 0.0;
        if part == k {
            x += 1.0 - wg;
        }
        if second == k {
            x += wg;
        }
        x
    };
    match band_at(built, z) {
        Some((j, w)) => {
            (weight_of(j) - (1.0 - w)).abs() <= BLEND_WEIGHT_TOLERANCE
                && (weight_of(j + 1) - w).abs() <= BLEND_WEIGHT_TOLERANCE
        }
        // Outside every band: one map (which one, the coverage tells).
        None => second == part || wg.min(1.0 - wg) <= BLEND_WEIGHT_TOLERANCE,
    }
}

/// Whether pixel `i` lies in a blend band: by the frame's bands at the exact depth `z`, or by the
/// shader's pick.
pub(crate) fn in_band(out: &FrameOutput, i: usize, part: usize, built: &Built, z: f64) -> bool {
    let [second, wg, _, _] = out.blend[i];
    band_at(built, z).is_some()
        || (second as usize != part && f64::from(wg.min(1.0 - wg)) > BLEND_WEIGHT_TOLERANCE)
}

/// How near (relatively) a pixel's depth may lie to a split plane or a band's end and be left
/// out of the split check: the GPU's view depth is interpolated in `f32`.
const PLANE_TOLERANCE: f64 = 1e-4;

/// The map the paper's split planes and requested blend bands name at view depth `z`: in a band,
/// its first map; elsewhere the slice holding `z` (the first and last slices reaching beyond the
/// planes). `None` for a scheme not selected by depth, or within [`PLANE_TOLERANCE`] of a plane.
pub(crate) fn paper_part(built: &Built, z: f64) -> Option<usize> {
    let p = &built.planes;
    if p.len() < 2 {
        return None;
    }
    let near = |x: f64| (z - x).abs() <= PLANE_TOLERANCE * z;
    if p.iter().any(|&x| near(x)) || built.bands.iter().any(|&(_, e)| near(e)) {
        return None;
    }
    if let Some(j) = built.bands.iter().position(|&(b, e)| z >= b && z < e) {
        return Some(j);
    }
    let k = p.len() - 1;
    Some((1..k).take_while(|&i| z >= p[i]).count())
}
