//! The papers' expectations, computed here from their equations and the set-up alone, without
//! the crate's rule or builder functions (docs/rendered.md, "What is measured", 8–10):
//!
//! - LiSPSM's n′ (Wimmer et al. 2004, n_opt = n + √(f n); Lloyd 2006 §4.1 divides it by sin γ,
//!   γ the angle between the view direction and the light);
//! - PSM's n′ (Lloyd 2006 §4.1: "PSMs use n′ = n", n′ the distance from the centre of
//!   projection to the near plane, which puts the centre at the eye: Stamminger & Drettakis
//!   2002's map in the camera's post-perspective space, for the light overhead);
//! - TSM's 80 % line (Martin & Tan 2004 §4.2: the focus point, δ beyond the near plane on the
//!   view axis, maps to ξ = −0.6 of the trapezoid's [1, −1], 80 % of the map from its top line;
//!   §6.4: for a body shorter than the frustum, δ scaled by the body's depth over the frustum's);
//! - the practical split planes (Zhang et al. 2006: the logarithmic plane n (f/n)^(i/k) and the
//!   uniform one n + (f − n) i/k, mixed λ : 1 − λ);
//! - the blend bands a requested overlap o makes: each split but the last reaches o of its own
//!   depth into the next, `[z_{i+1}, z_{i+1} + o (z_{i+1} − z_i)]`.
//!
//! What they take from the crate: the focus body's eye-depth range (the frame's `FrameMap::body`,
//! where the rules are applied) and nothing else.

use glam::DVec3;

/// LiSPSM's n′ with the 1/sin γ of Lloyd 2006 §4.1: `(n + √(f n)) / sin γ` for a body spanning
/// eye depths `[n, f]`, `sin_gamma` the sine of the angle between view direction and light.
pub fn lispsm_n_prime(n: f64, f: f64, sin_gamma: f64) -> f64 {
    (n + (f * n).sqrt()) / sin_gamma
}

/// PSM's n′ for a body whose nearest eye depth is `n` (Lloyd 2006 §4.1: n′ = n, the centre of
/// projection n before the body's near end, i.e. at the eye when the light is overhead). With a
/// tilted light Stamminger & Drettakis's own map is no one-point perspective in light space
/// (Lloyd 2006 §4.4); this is the light-space warp with PSM's parameter, as the paper's Fig 4
/// and Eq 7–12 use it.
pub fn psm_n_prime(n: f64) -> f64 {
    n
}

/// sin γ between the view direction (−z in eye space) and the light's direction `light_eye`
/// (eye space, any length).
pub fn sin_gamma(light_eye: DVec3) -> f64 {
    let l = light_eye.normalize();
    l.cross(DVec3::NEG_Z).length()
}

/// The unit axis of a warp perpendicular to the light (eye space): the view direction with its
/// component along the light removed (Wimmer et al. 2004 §4; Martin & Tan's centre line for a
/// symmetric frustum). `None` when view and light are parallel.
pub fn warp_axis(light_eye: DVec3) -> Option<DVec3> {
    let l = light_eye.normalize();
    let v = DVec3::NEG_Z;
    let a = v - l * v.dot(l);
    (a.length() > 1e-9).then(|| a.normalize())
}

/// Martin & Tan's focus line: the fraction of the map, from its top line, that the trapezoid
/// gives to the focus region (ξ = −0.6 on [1, −1]: (1 − ξ)/2).
pub const TSM_FOCUS_FRACTION: f64 = 0.8;

/// Martin & Tan §6.4: where the focus body (eye depths `[n_b, f_b]`) is not the whole frustum
/// (`[n, f]`), the near and far planes are pushed to bound it and the focus region, δ beyond the
/// near plane for the frustum (§4.2), lies within `δ f′/f` of the pushed near plane, f′ = f_b − n_b
/// and f = f − n their distances: the focus point's eye depth, `n_b + δ (f_b − n_b)/(f − n)`.
pub fn tsm_focus_depth(delta: f64, (n_b, f_b): (f64, f64), (n, f): (f64, f64)) -> f64 {
    n_b + delta * (f_b - n_b) / (f - n)
}

/// The focus distance δ render-check asks TSM for: a quarter of the camera's depth range.
pub const TSM_FOCUS_SHARE: f64 = 0.25;

/// The eye-space focus point render-check's TSM is asked for: on the view axis at
/// [`tsm_focus_depth`], δ being [`TSM_FOCUS_SHARE`] of the camera's depth range `(n, f)` and
/// `(n_b, f_b)` the focus body's eye depths.
pub fn tsm_focus_point(body: (f64, f64), (n, f): (f64, f64)) -> DVec3 {
    DVec3::new(
        0.0,
        0.0,
        -tsm_focus_depth(TSM_FOCUS_SHARE * (f - n), body, (n, f)),
    )
}

/// Martin & Tan §4.2: the distance η of the centre of projection before the top line that maps
/// the focus line, δ′ beyond the top line of a trapezoid of height λ, to ξ (on [1, −1]):
/// `η = λ δ′ (1 + ξ) / (λ − 2 δ′ − λ ξ)`.
pub fn tsm_eta(lambda: f64, delta: f64, xi: f64) -> f64 {
    lambda * delta * (1.0 + xi) / (lambda - 2.0 * delta - lambda * xi)
}

/// The k + 1 practical split planes over `[n, f]` (λ of the logarithmic part).
pub fn practical_planes(n: f64, f: f64, k: usize, lambda: f64) -> Vec<f64> {
    (0..=k)
        .map(|i| {
            if i == 0 {
                return n;
            }
            if i == k {
                return f;
            }
            let x = i as f64 / k as f64;
            let log = n * (f / n).powf(x);
            let uni = n + (f - n) * x;
            lambda * log + (1.0 - lambda) * uni
        })
        .collect()
}

/// The blend bands of `planes` (k + 1 planes) for the overlap `o`: band i lies beyond plane
/// i + 1, `o` of slice i's depth wide, for every slice but the last.
pub fn blend_bands(planes: &[f64], o: f64) -> Vec<(f64, f64)> {
    planes
        .windows(2)
        .take(planes.len().saturating_sub(2))
        .map(|w| {
            (
                w[1],
                (w[1] + o * (w[1] - w[0])).min(planes[planes.len() - 1]),
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hand values: n = 1, f = 100: n + √(f n) = 11; at γ = 30° twice that.
    #[test]
    fn lispsm_by_hand() {
        assert!((lispsm_n_prime(1.0, 100.0, 1.0) - 11.0).abs() < 1e-12);
        assert!((lispsm_n_prime(1.0, 100.0, 0.5) - 22.0).abs() < 1e-12);
        let s = sin_gamma(DVec3::new(0.0, -1.0, -3f64.sqrt()));
        assert!((s - 0.5).abs() < 1e-12, "{s}");
    }

    /// Martin & Tan: with η from ξ, the perspective map along the axis whose centre of
    /// projection lies η before the top line, y(u) = A + B/(u + η) with y(0) = 1 and y(λ) = −1,
    /// sends the focus line u = δ′ to ξ.
    #[test]
    fn tsm_eta_maps_the_focus_line() {
        let (lambda, delta, xi) = (10.0, 2.5, -0.6);
        let eta = tsm_eta(lambda, delta, xi);
        // y(u) = A + B/(u + η), y(0) = 1, y(λ) = −1.
        let b = 2.0 / (1.0 / eta - 1.0 / (lambda + eta));
        let a = 1.0 - b / eta;
        let y = |u: f64| a + b / (u + eta);
        assert!((y(0.0) - 1.0).abs() < 1e-12 && (y(lambda) + 1.0).abs() < 1e-12);
        assert!((y(delta) - xi).abs() < 1e-12, "{}", y(delta));
    }

    /// §6.4 by hand: the frustum [1, 101], δ = 25; a body [11, 61] (half the depth) has its
    /// focus 12.5 beyond its near end; the whole frustum keeps δ.
    #[test]
    fn tsm_focus_scaled_to_the_body() {
        assert!((tsm_focus_depth(25.0, (11.0, 61.0), (1.0, 101.0)) - 23.5).abs() < 1e-12);
        assert!((tsm_focus_depth(25.0, (1.0, 101.0), (1.0, 101.0)) - 26.0).abs() < 1e-12);
    }

    /// Practical planes by hand: n = 1, f = 16, k = 4, λ = 1 gives 1, 2, 4, 8, 16; λ = 0 the
    /// uniform 1, 4.75, 8.5, 12.25, 16; bands of o = 0.25 beyond each inner plane.
    #[test]
    fn planes_and_bands_by_hand() {
        let log = practical_planes(1.0, 16.0, 4, 1.0);
        for (a, b) in log.iter().zip([1.0, 2.0, 4.0, 8.0, 16.0]) {
            assert!((a - b).abs() < 1e-12, "{log:?}");
        }
        let uni = practical_planes(1.0, 16.0, 4, 0.0);
        for (a, b) in uni.iter().zip([1.0, 4.75, 8.5, 12.25, 16.0]) {
            assert!((a - b).abs() < 1e-12, "{uni:?}");
        }
        let bands = blend_bands(&log, 0.25);
        assert_eq!(bands, vec![(2.0, 2.25), (4.0, 4.5), (8.0, 9.0)]);
    }
}
