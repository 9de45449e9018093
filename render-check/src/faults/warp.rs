//! The warp refit behind the n′ faults ([`super::Fault::NPrimeDouble`],
//! [`super::Fault::LispsmNoSin`], [`super::Fault::TsmFocus`]): a frame map's matrix with its n′
//! scaled, refitted to the map's focus body as the crate's builders fit a warp.

use glam::{DMat4, DVec3, DVec4};

/// `built` with its warp's n′ multiplied by `k`, refitted to `body` (eye space) as the builders
/// fit a warp: t spans [−1, 1] over the body's range along the warp axis, s is refitted tightly
/// about the same centre line, and the depth keeps the original range (scaled conservatively so
/// that every point the original map held in depth, casters included, stays in it). `None` for an
/// orthographic map (w constant over the body).
///
/// A perspective warp along the axis z with centre of projection n′ before the body's near end
/// has w ∝ u + ν (u ∈ [0, 1] the position along the body, ν = n′/Δ) and
/// t = −1 + 2u(1 + ν)/(u + ν); so ν follows from w's ratio between t = 1 and t = −1,
/// `w₊/w₋ = 1 + 1/ν`, and the axis is the gradient of w.
pub fn n_prime_scaled(built: DMat4, body: &[DVec3], k: f64) -> Option<DMat4> {
    let rows = [built.row(0), built.row(1), built.row(2), built.row(3)];
    let eval = |r: DVec4, p: DVec3| r.dot(p.extend(1.0));
    // 1/w is affine in t: fit it through the body's extreme vertices in t.
    let tw: Vec<(f64, f64)> = body
        .iter()
        .map(|&p| {
            let w = eval(rows[3], p);
            (eval(rows[1], p) / w, w)
        })
        .collect();
    let lo = tw.iter().min_by(|a, b| a.0.total_cmp(&b.0))?;
    let hi = tw.iter().max_by(|a, b| a.0.total_cmp(&b.0))?;
    if hi.0 - lo.0 < 1e-9 {
        return None;
    }
    let inv_at = |t: f64| 1.0 / lo.1 + (t - lo.0) * (1.0 / hi.1 - 1.0 / lo.1) / (hi.0 - lo.0);
    let (w_m, w_p) = (1.0 / inv_at(-1.0), 1.0 / inv_at(1.0));
    // The warp runs toward larger w: flip t when w falls with it.
    let sigma = if w_p >= w_m { 1.0 } else { -1.0 };
    let (w_near, w_far) = if sigma > 0.0 { (w_m, w_p) } else { (w_p, w_m) };
    let ratio = w_far / w_near;
    // Also refuses NaN: an orthographic map, or no usable w.
    if ratio.is_nan() || ratio <= 1.0 + 1e-9 || !ratio.is_finite() {
        return None;
    }
    let nu = 1.0 / (ratio - 1.0);
    let nu2 = k * nu;
    let c_delta = w_far - w_near;
    let e_w = DVec4::W;
    let w_row = rows[3];
    // u (c Δ) = w − ν c Δ; w₂ = c Δ (u + ν₂); y₂ = c Δ ((1 + 2ν₂) u − ν₂).
    let w2 = w_row + e_w * ((nu2 - nu) * c_delta);
    let y2 = (w_row * (1.0 + 2.0 * nu2) - e_w * (c_delta * ((1.0 + 2.0 * nu2) * nu + nu2))) * sigma;
    // Remove the part of x and depth that follows w (their offsets), keep the rest.
    let g = w_row.truncate();
    let pure = |r: DVec4| r - w_row * (r.truncate().dot(g) / g.length_squared());
    let x_pure = pure(rows[0]);
    let z_pure = pure(rows[2]);
    // s refitted over the body.
    let (mut slo, mut shi) = (f64::INFINITY, f64::NEG_INFINITY);
    for &p in body {
        let s = eval(x_pure, p) / eval(w2, p);
        slo = slo.min(s);
        shi = shi.max(s);
    }
    if shi - slo <= 0.0 || (shi - slo).is_nan() {
        return None;
    }
    let x2 = (x_pure * 2.0 - w2 * (slo + shi)) / (shi - slo);
    // Depth: z_pure/w ∈ [−1 − β, 1 − β] held the original range (β the offset removed); over
    // u ∈ [0, 1] w/w₂ lies between ν/ν₂ and (1 + ν)/(1 + ν₂) (times the same c Δ).
    let beta = rows[2].truncate().dot(g) / g.length_squared();
    let (r0, r1) = (nu / nu2, (1.0 + nu) / (1.0 + nu2));
    let ends = [
        r0 * (-1.0 - beta),
        r1 * (-1.0 - beta),
        r0 * (1.0 - beta),
        r1 * (1.0 - beta),
    ];
    let zlo = ends.iter().copied().fold(f64::INFINITY, f64::min);
    let zhi = ends.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let z2 = (z_pure * 2.0 - w2 * (zlo + zhi)) / (zhi - zlo);
    Some(DMat4::from_cols(x2, y2, z2, w2).transpose())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::faults::Fault;
    use crate::schemes::Scheme;
    use shadow_aliasing::maps::{fit_warp, light_space};
    use shadow_aliasing::{NPrime, ViewFrustum};

    /// The doubled-n′ map equals the crate's own `fit_warp` with 2 n′ in s and t on the body,
    /// for a map `fit_warp` built with n′ (an independent construction of the same warp).
    #[test]
    fn n_prime_doubled_matches_fit_warp() {
        let view = ViewFrustum::new(1.0, 60.0, 0.6).unwrap();
        let ls = light_space(DVec3::new(0.3, -1.0, -0.4), DVec3::NEG_Z).unwrap();
        let body = view.corners();
        let n = 7.5;
        let m1 = fit_warp(&body, &ls, NPrime::finite(n).unwrap()).unwrap();
        let m2 = fit_warp(&body, &ls, NPrime::finite(2.0 * n).unwrap()).unwrap();
        let f = n_prime_scaled(m1, &body, 2.0).unwrap();
        let st = |m: DMat4, p: DVec3| {
            let h = m * p.extend(1.0);
            (h.x / h.w, h.y / h.w, h.z / h.w)
        };
        for p in body {
            let (a, b) = (st(f, p), st(m2, p));
            assert!(
                (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9,
                "{a:?} {b:?}"
            );
            assert!(a.2.abs() <= 1.0 + 1e-9, "{a:?}");
        }
        // An orthographic map has no n′ to scale.
        let u = fit_warp(&body, &ls, NPrime::UNWARPED).unwrap();
        assert!(n_prime_scaled(u, &body, 2.0).is_none());
    }

    /// On the frame's own warped maps, n′ × 2 doubles the n′ the frame reports: the n′ read back
    /// from the faulted matrix (w's ratio across the body and the body's extent along the warp
    /// axis, the gradient of w) is twice `ShadowMatrix::n_prime`.
    #[test]
    fn n_prime_doubled_on_frame_maps() {
        let mut checked = 0;
        for scheme in [Scheme::Lispsm, Scheme::Cascades, Scheme::Faces] {
            let clean = crate::faults::tests::built(scheme, None);
            let f = crate::faults::tests::built(scheme, Some(Fault::NPrimeDouble));
            for ((m, mf), body) in clean.maps.iter().zip(&f.maps).zip(&clean.bodies) {
                let n = m.reported.n_prime;
                if !n.is_finite() {
                    continue;
                }
                let read = |mat: DMat4| {
                    let w = mat.row(3);
                    let axis = w.truncate().normalize();
                    let z: Vec<f64> = body.iter().map(|p| axis.dot(*p)).collect();
                    let ws: Vec<f64> = body.iter().map(|p| w.dot(p.extend(1.0))).collect();
                    let (wlo, whi) = ws
                        .iter()
                        .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
                    let (zlo, zhi) = z
                        .iter()
                        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| {
                            (a.min(x), b.max(x))
                        });
                    (zhi - zlo) / (whi / wlo - 1.0)
                };
                let (n1, n2) = (read(m.built), read(mf.built));
                assert!(
                    (n1 / n - 1.0).abs() < 1e-6,
                    "{}: read {n1}, reported {n}",
                    scheme.name()
                );
                assert!(
                    (n2 / (2.0 * n) - 1.0).abs() < 1e-6,
                    "{}: {n2} vs 2 × {n}",
                    scheme.name()
                );
                checked += 1;
            }
        }
        assert!(checked >= 3, "{checked}");
    }
}
