//! What is measured on the read-back frame: the rendered Jacobian against
//! `measure::surface_footprint`, and every pixel's shadow against the exact ray cast.

use crate::gpu::FrameOutput;
use crate::scene::{ray_occluded, Mesh, Scene, FACING};
use crate::schemes::{Built, View};
use glam::{DMat2, DVec2, DVec3};
use shadow_aliasing::measure::{surface_footprint, Footprint, Grids};

/// Per-pixel results (for the heat maps) and the case's numbers.
pub struct Analysis {
    /// Pixels whose rendered and predicted Jacobians were compared.
    pub pixels_compared: usize,
    /// Visible pixels excluded because a neighbour is on another surface or map.
    pub excluded_discontinuity: usize,
    /// Median of ‖J_rendered − J_predicted‖_F / ‖J_predicted‖_F.
    pub median_rel_diff: f64,
    /// 99th percentile of the same.
    pub p99_rel_diff: f64,
    /// Interior pixels in exact shadow rendered lit.
    pub interior_misses: usize,
    /// Interior pixels exactly lit rendered in shadow.
    pub interior_false_shadows: usize,
    /// Interior pixels.
    pub interior_pixels: usize,
    /// Mismatching fraction of the visible pixels outside the interior (the edge band).
    pub edge_band_mismatch_fraction: f64,
    /// Edge-band pixels.
    pub edge_band_pixels: usize,
    /// Largest rendered error (pixels per texel, 1/σ_min of the rendered J) over compared pixels.
    pub max_rendered_error: f64,
    /// Largest predicted error over the same pixels.
    pub max_predicted_error: f64,
    /// Rendered error per pixel (NaN where not compared).
    pub rendered_error: Vec<f64>,
    /// Predicted error per pixel (NaN where not compared).
    pub predicted_error: Vec<f64>,
}

/// The exact eye-space point seen through pixel `(x, y)` on the plane `(n, p0)` (eye space), or
/// `None` when the ray is parallel to the plane or the point is behind the eye.
fn pixel_point(view: &View, w: u32, h: u32, x: u32, y: u32, n: DVec3, p0: DVec3) -> Option<DVec3> {
    pixel_point_at(view, w, h, f64::from(x) + 0.5, f64::from(y) + 0.5, n, p0)
}

/// As [`pixel_point`] at the screen position `(u, v)` (pixel units, from the top left).
fn pixel_point_at(
    view: &View,
    w: u32,
    h: u32,
    u: f64,
    v: f64,
    n: DVec3,
    p0: DVec3,
) -> Option<DVec3> {
    let [_, _, t, ta] = view.frustum_params();
    let xn = 2.0 * u / f64::from(w) - 1.0;
    let yn = 1.0 - 2.0 * v / f64::from(h);
    let d = DVec3::new(xn * ta, yn * t, -1.0);
    let den = n.dot(d);
    if den.abs() < 1e-12 {
        return None;
    }
    let s = n.dot(p0) / den;
    (s > 0.0).then_some(d * s)
}

/// Where the exact shadow is sampled inside a pixel besides its centre: a 5 × 5 grid a quarter
/// of a pixel apart, corners included, so that a shadow a quarter of a pixel wide (the built-in
/// scene's poles far away) marks the pixel as containing an edge.
const SUBSAMPLES: [(f64, f64); 24] = {
    let mut s = [(0.0, 0.0); 24];
    let mut k = 0;
    let mut i = 0;
    while i < 25 {
        if i != 12 {
            s[k] = ((i % 5) as f64 * 0.25 - 0.5, (i / 5) as f64 * 0.25 - 0.5);
            k += 1;
        }
        i += 1;
    }
    s
};

/// Squared Euclidean distance transform in 1D (Felzenszwalb & Huttenlocher).
fn edt_1d(f: &[f64], out: &mut [f64]) {
    let n = f.len();
    let mut v = vec![0usize; n];
    let mut z = vec![0f64; n + 1];
    let mut k = 0usize;
    v[0] = 0;
    z[0] = f64::NEG_INFINITY;
    z[1] = f64::INFINITY;
    for q in 1..n {
        loop {
            let p = v[k];
            let s =
                ((f[q] + (q * q) as f64) - (f[p] + (p * p) as f64)) / (2.0 * (q as f64 - p as f64));
            if s <= z[k] {
                if k == 0 {
                    v[0] = q;
                    z[0] = f64::NEG_INFINITY;
                    z[1] = f64::INFINITY;
                    break;
                }
                k -= 1;
            } else {
                k += 1;
                v[k] = q;
                z[k] = s;
                z[k + 1] = f64::INFINITY;
                break;
            }
        }
    }
    k = 0;
    for (q, o) in out.iter_mut().enumerate() {
        while z[k + 1] < q as f64 {
            k += 1;
        }
        let d = q as f64 - v[k] as f64;
        *o = d * d + f[v[k]];
    }
}

/// Distance from each pixel to the nearest pixel of `set` (Euclidean, pixels); infinite when the
/// set is empty.
pub fn distance_to(set: &[bool], w: usize, h: usize) -> Vec<f64> {
    let big = 1e20;
    let mut g = vec![0f64; w * h];
    let mut col = vec![0f64; h];
    let mut out_col = vec![0f64; h];
    for x in 0..w {
        for y in 0..h {
            col[y] = if set[y * w + x] { 0.0 } else { big };
        }
        edt_1d(&col, &mut out_col);
        for y in 0..h {
            g[y * w + x] = out_col[y];
        }
    }
    let mut row_out = vec![0f64; w];
    let mut d = vec![0f64; w * h];
    for y in 0..h {
        edt_1d(&g[y * w..(y + 1) * w], &mut row_out);
        for x in 0..w {
            d[y * w + x] = if row_out[x] >= big {
                f64::INFINITY
            } else {
                row_out[x].sqrt()
            };
        }
    }
    d
}

fn rel_diff(a: DMat2, b: DMat2) -> f64 {
    let n = |m: DMat2| (m.x_axis.length_squared() + m.y_axis.length_squared()).sqrt();
    n(a - b) / n(b)
}

fn error_of(j: DMat2) -> f64 {
    Footprint {
        jacobian: j,
        pixel: DVec2::ZERO,
        texel: DVec2::ZERO,
    }
    .error()
    .unwrap_or(f64::INFINITY)
}

fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let i = ((sorted.len() - 1) as f64 * q).round() as usize;
    sorted[i]
}

/// Analyses one frame.
///
/// # Errors
/// When nothing could be compared (an empty result is not a success).
#[allow(clippy::too_many_arguments)] // the frame, its inputs and its sizes, each needed once
pub fn analyse(
    out: &FrameOutput,
    view: &View,
    scene: &Scene,
    mesh: &Mesh,
    built: &Built,
    res: u32,
    width: u32,
    height: u32,
) -> Result<Analysis, String> {
    let (w, h) = (width as usize, height as usize);
    let grids = Grids::new(width, height, res, res).map_err(|e| e.to_string())?;
    let eye_to_world = view.world_to_eye.inverse();
    let n = w * h;
    let mut predicted: Vec<Option<Footprint>> = vec![None; n];
    let mut exact_lit = vec![false; n];
    let mut visible = vec![false; n];
    let mut lights = vec![false; n];
    // Whether the exact shadow changes inside the pixel ([`SUBSAMPLES`] on the pixel's plane
    // against its centre): a shadow thinner than a pixel is never interior.
    let mut mixed = vec![false; n];
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            let id = out.id[i];
            if id == 0 {
                continue;
            }
            let surf = mesh.surfaces[(id - 1) as usize];
            let ne = view.world_to_eye.transform_vector3(surf.normal);
            let pe0 = view.world_to_eye.transform_point3(surf.point);
            let Some(p) = pixel_point(view, width, height, x as u32, y as u32, ne, pe0) else {
                continue;
            };
            visible[i] = true;
            let part = out.texel[i][2] as usize;
            if let Some(map) = built.maps.get(part) {
                predicted[i] = surface_footprint(&view.proj, &map.built, grids, p, ne).ok();
            }
            let pw = eye_to_world.transform_point3(p);
            let facing = surf.normal.dot(-view.light_world) > FACING;
            lights[i] = facing;
            exact_lit[i] = facing && !ray_occluded(scene, pw, surf.normal, view.light_world);
            if facing {
                let occ = !exact_lit[i];
                mixed[i] = SUBSAMPLES.iter().any(|&(dx, dy)| {
                    pixel_point_at(
                        view,
                        width,
                        height,
                        x as f64 + 0.5 + dx,
                        y as f64 + 0.5 + dy,
                        ne,
                        pe0,
                    )
                    .map(|q| {
                        ray_occluded(
                            scene,
                            eye_to_world.transform_point3(q),
                            surf.normal,
                            view.light_world,
                        )
                    })
                    .is_some_and(|o| o != occ)
                });
            }
        }
    }
    // Rendered Jacobians: central differences where the 3×3 neighbourhood is one surface and
    // one map.
    let mut rels = Vec::new();
    let mut rendered_error = vec![f64::NAN; n];
    let mut predicted_error = vec![f64::NAN; n];
    let mut excluded = 0usize;
    let (mut max_r, mut max_p) = (0.0f64, 0.0f64);
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if !visible[i] {
                continue;
            }
            let same = x > 0
                && y > 0
                && x + 1 < w
                && y + 1 < h
                && (0..3).all(|dy| {
                    (0..3).all(|dx| {
                        let j = (y + dy - 1) * w + (x + dx - 1);
                        out.id[j] == out.id[i] && out.texel[j][2] == out.texel[i][2]
                    })
                });
            let Some(fp) = predicted[i] else {
                excluded += 1;
                continue;
            };
            if !same {
                excluded += 1;
                continue;
            }
            let t = |j: usize| DVec2::new(f64::from(out.texel[j][0]), f64::from(out.texel[j][1]));
            let c0 = (t(i + 1) - t(i - 1)) * 0.5;
            let c1 = (t(i + w) - t(i - w)) * 0.5;
            let jr = DMat2::from_cols(c0, c1);
            let r = rel_diff(jr, fp.jacobian);
            if !r.is_finite() {
                excluded += 1;
                continue;
            }
            rels.push(r);
            let (er, ep) = (error_of(jr), error_of(fp.jacobian));
            rendered_error[i] = er;
            predicted_error[i] = ep;
            // The maxima over surfaces the light can reach (a face turned away or edge-on is dark
            // whatever its texels; edge-on, its texels are unbounded).
            if lights[i] && er.is_finite() && ep.is_finite() {
                max_r = max_r.max(er);
                max_p = max_p.max(ep);
            }
        }
    }
    if rels.is_empty() {
        return Err("no pixel could be compared (empty frame?)".into());
    }
    rels.sort_by(f64::total_cmp);
    // Shadow correctness. A pixel is interior when no pixel within 2 of its texel footprints
    // (plus one pixel for where the exact boundary lies between pixel centres) differs from it in
    // surface or in exact class (lit, in cast shadow, turned away from the light), and none is sky
    // or off screen: the surroundings of the texel on the pixel's own surface are all of the
    // pixel's exact state.
    let class: Vec<u8> = (0..n)
        .map(|i| {
            if !visible[i] {
                0
            } else if exact_lit[i] {
                1
            } else if lights[i] {
                2
            } else {
                3
            }
        })
        .collect();
    let boundary: Vec<bool> = (0..n)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let key = (out.id[i], class[i]);
            class[i] == 0
                || mixed[i]
                || x == 0
                || y == 0
                || x + 1 == w
                || y + 1 == h
                || [i - 1, i + 1, i - w, i + w]
                    .iter()
                    .any(|&j| (out.id[j], class[j]) != key)
        })
        .collect();
    let dist_b = distance_to(&boundary, w, h);
    let (mut misses, mut falses, mut interior, mut band, mut band_mis) = (0, 0, 0, 0, 0);
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if !visible[i] {
                continue;
            }
            let dist = dist_b[i];
            let reach = predicted[i]
                .and_then(|f| f.error().ok())
                .map_or(f64::INFINITY, |e| 2.0 * e + 1.0);
            let rendered_lit = out.texel[i][3] > 0.5;
            if dist > reach {
                interior += 1;
                if !exact_lit[i] && rendered_lit {
                    misses += 1;
                }
                if exact_lit[i] && !rendered_lit {
                    falses += 1;
                }
                if exact_lit[i] != rendered_lit && std::env::var_os("RENDER_CHECK_DEBUG").is_some()
                {
                    let id = out.id[i] - 1;
                    let sn = mesh.surfaces[id as usize].normal;
                    let pw = {
                        let ne = view.world_to_eye.transform_vector3(sn);
                        let pe0 = view
                            .world_to_eye
                            .transform_point3(mesh.surfaces[id as usize].point);
                        pixel_point(view, width, height, x as u32, y as u32, ne, pe0)
                            .map(|p| eye_to_world.transform_point3(p))
                    };
                    eprintln!(
                        "  interior mismatch at ({x}, {y}) world {pw:?}: surface {id} n {sn} n.l {:.4} exact_lit {} part {} dist {dist:.1} reach {reach:.2} texel {:?}",
                        sn.dot(-view.light_world), exact_lit[i], out.texel[i][2], out.texel[i]
                    );
                }
            } else {
                band += 1;
                if exact_lit[i] != rendered_lit {
                    band_mis += 1;
                }
            }
        }
    }
    Ok(Analysis {
        pixels_compared: rels.len(),
        excluded_discontinuity: excluded,
        median_rel_diff: percentile(&rels, 0.5),
        p99_rel_diff: percentile(&rels, 0.99),
        interior_misses: misses,
        interior_false_shadows: falses,
        interior_pixels: interior,
        edge_band_mismatch_fraction: if band > 0 {
            band_mis as f64 / band as f64
        } else {
            0.0
        },
        edge_band_pixels: band,
        max_rendered_error: max_r,
        max_predicted_error: max_p,
        rendered_error,
        predicted_error,
    })
}
