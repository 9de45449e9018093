//! The frame's reported maxima against what the GPU drew (measurements 4 and 6 of
//! [`crate::analysis`]): the rendered perspective error's and the lens's ratios to each map's
//! reported maximum, and whether the body's worst point shows on screen.

use crate::analysis::{Class, Pixel, VISIBLE_PIXELS};
use crate::schemes::{Built, View};
use glam::DVec3;
use shadow_aliasing::measure::vertex::vertex_max;

/// The frame's reported maxima against the rendered ones: the largest rendered/reported ratio
/// over maps and over x and z, and the smallest where the body's worst point is visible.
pub(crate) fn frame_ratios(
    px: &[Pixel],
    view: &View,
    built: &Built,
    rendered_m: &[(f64, f64)],
    (width, height, res): (u32, u32, u32),
) -> (f64, Option<f64>) {
    let to_pixels = f64::from(height) / f64::from(res);
    let tan = view.frustum.tan_half_fov();
    let (mut ratio, mut worst) = (0.0f64, None::<f64>);
    for (k, map) in built.maps.iter().enumerate() {
        let reported = (
            map.reported.max_mx * to_pixels,
            map.reported.max_mz * to_pixels,
        );
        let got = rendered_m[k];
        ratio = ratio.max(got.0 / reported.0).max(got.1 / reported.1);
        // Each body vertex's m_x, m_z under the map as rendered; the worst ones, and whether any
        // of them is a visible surface point.
        let body = built.bodies.get(k).map_or(&[][..], Vec::as_slice);
        let per: Vec<(DVec3, f64, f64)> = body
            .iter()
            .filter_map(|&v| {
                vertex_max(&map.built, view.light_eye, tan, &[v]).map(|e| (v, e.max_mx, e.max_mz))
            })
            .collect();
        if got == (0.0, 0.0) {
            // No rendered error measured in this map (a clipmap's last level can be a sliver at
            // the horizon, no pixel of it with two neighbours in it): nothing to compare.
            continue;
        }
        for (axis, rep, got) in [(0, reported.0, got.0), (1, reported.1, got.1)] {
            let top = per
                .iter()
                .map(|e| if axis == 0 { e.1 } else { e.2 })
                .fold(0.0f64, f64::max);
            let seen = per.iter().any(|e| {
                let m = if axis == 0 { e.1 } else { e.2 };
                m >= top * (1.0 - 1e-6) && visible_point(px, view, (width, height), e.0, k)
            });
            if seen {
                let r = got / rep;
                worst = Some(worst.map_or(r, |w| w.min(r)));
            }
        }
    }
    (ratio, worst)
}

/// The GPU's lens with the projection factor 1 against the frame's reported maxima: the largest
/// ratio of a map's largest such lens over its visible pixels to its `max_error_pixels` times its
/// largest rendered texel shear `shear_m` (the lens is the texel's largest extent, at most the
/// shear times the larger of Lloyd's widths, which the reported maximum bounds), and the smallest
/// ratio to `max_error_pixels` alone (the extent is at least each width) over the maps whose
/// worst body vertex (the one of the largest max(m_x, m_z) under the map, `vertex_max`) is
/// within [`VISIBLE_PIXELS`] of a visible pixel looked up in the map.
pub(crate) fn lens_ratios(
    px: &[Pixel],
    view: &View,
    built: &Built,
    (lens_m, shear_m): (&[f64], &[f64]),
    (width, height): (u32, u32),
) -> (f64, Option<f64>) {
    let tan = view.frustum.tan_half_fov();
    let (mut ratio, mut worst) = (0.0f64, None::<f64>);
    for (k, map) in built.maps.iter().enumerate() {
        if lens_m[k] == 0.0 {
            // No pixel of this map (a clipmap's last level can be off screen).
            continue;
        }
        let r = lens_m[k] / map.reported.max_error_pixels;
        ratio = ratio.max(r / shear_m[k].max(1.0));
        let body = built.bodies.get(k).map_or(&[][..], Vec::as_slice);
        let per: Vec<(DVec3, f64)> = body
            .iter()
            .filter_map(|&v| {
                vertex_max(&map.built, view.light_eye, tan, &[v])
                    .map(|e| (v, e.max_mx.max(e.max_mz)))
            })
            .collect();
        let top = per.iter().map(|e| e.1).fold(0.0f64, f64::max);
        let seen = per
            .iter()
            .any(|e| e.1 >= top * (1.0 - 1e-6) && visible_point(px, view, (width, height), e.0, k));
        if seen {
            worst = Some(worst.map_or(r, |w| w.min(r)));
        }
    }
    if lens_m.iter().all(|&m| m == 0.0) {
        // No lens at all: not a pass.
        return (f64::NAN, worst);
    }
    (ratio, worst)
}

/// Whether the eye-space point `v` is (within [`VISIBLE_PIXELS`] pixel widths) the surface point
/// of a visible pixel looked up in map `map` (where it shows only on pixels of another map, the
/// map's rendered maximum says nothing about it).
fn visible_point(
    px: &[Pixel],
    view: &View,
    (width, height): (u32, u32),
    v: DVec3,
    map: usize,
) -> bool {
    let c = view.proj * v.extend(1.0);
    if c.w <= 0.0 {
        return false;
    }
    let (w, h) = (f64::from(width), f64::from(height));
    let u = (c.x / c.w + 1.0) * 0.5 * w;
    let r = (1.0 - c.y / c.w) * 0.5 * h;
    let reach = VISIBLE_PIXELS * 2.0 * (-v.z) * view.frustum.tan_half_fov() / h;
    let span = VISIBLE_PIXELS.ceil() as isize;
    for dy in -span..=span {
        for dx in -span..=span {
            let (x, y) = (u.floor() as isize + dx, r.floor() as isize + dy);
            if x < 0 || y < 0 || x >= width as isize || y >= height as isize {
                continue;
            }
            let q = px[y as usize * width as usize + x as usize];
            if q.class != Class::Sky && q.part == map && (q.p - v).length() <= reach {
                return true;
            }
        }
    }
    false
}
