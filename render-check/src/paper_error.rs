//! The maps' perspective error against the papers at any light direction (docs/rendered.md,
//! "What is measured", 12): each map of a scheme whose map a paper fixes is built again here, in
//! render-check's own code, as Lloyd 2006 §4.1 and §4.4 build it, and the rendered m_x, m_z
//! of every compared pixel (measurement 4: the GPU's texel coordinates, the projection factor
//! divided out) must be that map's at the pixel's point.
//!
//! # The paper's map
//!
//! Light space (Lloyd 2006 Fig 3, Wimmer et al. 2004's with s and t swapped): y toward the light,
//! z the view direction with its part along the light removed, x = y × z. A warp with parameter
//! n′ is the one-point perspective along z whose centre of projection lies n′ before the body's
//! near end z₀, so w = 1 + (z − z₀)/n′ (n′ = ∞: the orthographic map, w = 1); the map's s spans
//! the range of x/w over the focus body, its t the body's extent Δ along z (Eq 5–6 fitted to the
//! body rather than to the frustum's sides, which is the same map when the body is the frustum).
//! A texel step is then, in the plane Π ⊥ L (Eq 3–4),
//!
//! ```text
//! w_lx = w · (max x/w − min x/w) / res,     w_lz = Δ w² / (w(z₀ + Δ) · res)
//! ```
//!
//! and the errors are m_x = w_lx / w_i, m_z = w_lz / w_i with w_i = 2 z tan θ / H the pixel's
//! beam at its eye depth z (Eq 2; §4.4: z = p · v). With the light overhead and the body the
//! frustum these are Eq 7 and 8 (`each_beam_is_eq_7_and_8_overhead` below). The maxima over the
//! body's vertices are §4.4's M_x, M_z for any light direction.
//!
//! n′ per scheme, from the papers ([`crate::papers`]): the uniform map ∞; PSM n_B, the body's
//! nearest eye depth (Lloyd 2006 §4.1's n′ = n); LiSPSM (the single map
//! and each cascade of both cascade schemes) (n_B + √(f_B n_B)) / sin γ (Wimmer et al. 2004;
//! Lloyd 2006 §4.1, §4.4), n_B and f_B the body's eye-depth range; TSM Martin & Tan's η, which
//! sends the focus point (a quarter of the camera's depth range beyond the body's near eye depth)
//! to ξ = −0.6. The crate's minimax map is the paper's map for the n′ the frame reports, and that
//! n′ must minimise the paper's storage factor S̄ = M_x M_z (Lloyd 2006 §4.2) over n′ ∈ (0, ∞],
//! searched here ([`least_storage`]). The other schemes (the stable cascades, the face
//! partitions, the clipmap) have no map that these papers fix: `None`.
//!
//! What it takes from the crate: each map's focus body (`FrameMap::body`), and for the minimax
//! map its n′; the rendered error comes from the GPU's texel coordinates.

use crate::schemes::{Built, Scheme, View};
use glam::DVec3;

/// A map as the paper builds it (module docs).
#[derive(Debug, Clone, Copy)]
pub struct PaperWarp {
    /// Light-space z (the warp axis), eye space.
    z: DVec3,
    /// The body's near end along z.
    z0: f64,
    /// The body's extent along z.
    delta: f64,
    /// 1/n′ (0 for the orthographic map).
    rho: f64,
    /// The range of x/w over the body.
    width: f64,
}

impl PaperWarp {
    /// The paper's map for a light travelling along `light_eye` (eye space), focused on `body`
    /// (eye-space points) with parameter `n_prime` (∞: orthographic). `None` where the light is
    /// along the view (no warp axis) or the body has no extent.
    pub fn new(light_eye: DVec3, body: &[DVec3], n_prime: f64) -> Option<Self> {
        let z = crate::papers::warp_axis(light_eye)?;
        let x = (-light_eye.normalize()).cross(z);
        let rho = if n_prime.is_finite() {
            1.0 / n_prime
        } else {
            0.0
        };
        let along = body.iter().map(|p| z.dot(*p));
        let z0 = along.clone().fold(f64::INFINITY, f64::min);
        let z1 = along.fold(f64::NEG_INFINITY, f64::max);
        let mut warp = Self {
            z,
            z0,
            delta: z1 - z0,
            rho,
            width: 0.0,
        };
        let across = body.iter().map(|p| x.dot(*p) / warp.w(*p));
        let lo = across.clone().fold(f64::INFINITY, f64::min);
        let hi = across.fold(f64::NEG_INFINITY, f64::max);
        warp.width = hi - lo;
        (warp.delta > 0.0 && warp.width > 0.0 && rho >= 0.0).then_some(warp)
    }

    /// The warp's w at the eye-space point `p`.
    fn w(&self, p: DVec3) -> f64 {
        1.0 + self.rho * (self.z.dot(p) - self.z0)
    }

    /// Lloyd 2006 Eq 3–4: the light beam widths `(w_lx, w_lz)` at `p` of a map of `res` texels.
    pub fn beams(&self, p: DVec3, res: f64) -> (f64, f64) {
        let w = self.w(p);
        let w_far = 1.0 + self.rho * self.delta;
        (w * self.width / res, self.delta * w * w / (w_far * res))
    }

    /// `(m_x, m_z)` at `p`, pixels per texel: the beams over w_i = 2 z tan θ / H (z = −p.z, the
    /// eye depth; `tan_theta` the vertical half field of view's tangent, `height` H pixels).
    pub fn m(&self, p: DVec3, tan_theta: f64, height: f64, res: f64) -> (f64, f64) {
        let wi = 2.0 * (-p.z) * tan_theta / height;
        let (bx, bz) = self.beams(p, res);
        (bx / wi, bz / wi)
    }

    /// §4.4's maxima M_x, M_z over `body`'s vertices (the same units as [`PaperWarp::m`]).
    pub fn maxima(&self, body: &[DVec3], tan_theta: f64, height: f64, res: f64) -> (f64, f64) {
        body.iter()
            .filter(|p| p.z < 0.0)
            .map(|&p| self.m(p, tan_theta, height, res))
            .fold((0.0f64, 0.0f64), |a, m| (a.0.max(m.0), a.1.max(m.1)))
    }
}

/// The paper's n′ for a map of `scheme` focused on `body` (module docs); `None` for a scheme no
/// paper fixes, or a light along the view.
pub fn paper_n_prime(scheme: Scheme, view: &View, body: &[DVec3]) -> Option<f64> {
    let light = view.light_eye;
    let n_b = body.iter().map(|v| -v.z).fold(f64::INFINITY, f64::min);
    let f_b = body.iter().map(|v| -v.z).fold(f64::NEG_INFINITY, f64::max);
    match scheme {
        Scheme::Uniform => Some(f64::INFINITY),
        Scheme::Psm => Some(crate::papers::psm_n_prime(n_b)),
        Scheme::Lispsm | Scheme::Cascades | Scheme::BlendedCascades => Some(
            crate::papers::lispsm_n_prime(n_b, f_b, crate::papers::sin_gamma(light)),
        ),
        Scheme::Tsm => {
            let axis = crate::papers::warp_axis(light)?;
            let fr = &view.frustum;
            let focus = crate::papers::tsm_focus_point((n_b, f_b), (fr.near(), fr.far()));
            let a = body.iter().map(|v| axis.dot(*v));
            let lo = a.clone().fold(f64::INFINITY, f64::min);
            let hi = a.fold(f64::NEG_INFINITY, f64::max);
            let eta = crate::papers::tsm_eta(hi - lo, axis.dot(focus) - lo, -0.6);
            (eta > 0.0).then_some(eta)
        }
        _ => None,
    }
}

/// S̄ = M_x M_z of the paper's map with parameter `n_prime` on `body` (unit resolutions, a
/// square image: Lloyd 2006 §4.2, the maxima of §4.4); NaN where no map can be built.
pub fn storage(light_eye: DVec3, body: &[DVec3], n_prime: f64, tan_theta: f64) -> f64 {
    PaperWarp::new(light_eye, body, n_prime).map_or(f64::NAN, |w| {
        let (mx, mz) = w.maxima(body, tan_theta, 1.0, 1.0);
        mx * mz
    })
}

/// The least [`storage`] over n′ ∈ (0, ∞]: n′ = ∞ and a scan of 801 values of log n′ over
/// [10⁻⁴, 10⁷] × the body's near eye depth, refined by golden-section search between the
/// neighbours of the best sample.
pub fn least_storage(light_eye: DVec3, body: &[DVec3], tan_theta: f64) -> f64 {
    let n_b = body
        .iter()
        .map(|v| -v.z)
        .fold(f64::INFINITY, f64::min)
        .max(1e-9);
    let at = |lg: f64| storage(light_eye, body, n_b * 10f64.powf(lg), tan_theta);
    let (lo, hi, steps) = (-4.0, 7.0, 800);
    let step = (hi - lo) / f64::from(steps);
    let (mut best, mut best_i) = (storage(light_eye, body, f64::INFINITY, tan_theta), None);
    for i in 0..=steps {
        let v = at(lo + step * f64::from(i));
        if v < best {
            (best, best_i) = (v, Some(i));
        }
    }
    if let Some(i) = best_i {
        let (mut a, mut b) = (
            lo + step * (f64::from(i) - 1.0),
            lo + step * (f64::from(i) + 1.0),
        );
        let g = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..80 {
            let (c, d) = (b - g * (b - a), a + g * (b - a));
            if at(c) < at(d) {
                b = d;
            } else {
                a = c;
            }
        }
        best = best.min(at(0.5 * (a + b)));
    }
    best
}

/// Accumulates, over a frame's compared pixels, the rendered m_x, m_z against the paper's maps.
pub(crate) struct PaperErrors {
    /// Per map: the paper's map, where one applies.
    warps: Vec<Option<PaperWarp>>,
    tan: f64,
    height: f64,
    res: f64,
    /// Per compared pixel: max(|m_x / paper − 1|, |m_z / paper − 1|).
    diffs: Vec<f64>,
    /// The minimax maps: the largest S̄ at the frame's n′ over the least S̄ found here.
    storage_ratio: Option<f64>,
}

impl PaperErrors {
    /// The paper's map for each map of the frame (none for a scheme no paper fixes).
    pub(crate) fn new(view: &View, built: &Built, scheme: Scheme, height: u32, res: u32) -> Self {
        let tan = view.frustum.tan_half_fov();
        let mut storage_ratio = None::<f64>;
        let warps = built
            .bodies
            .iter()
            .zip(&built.maps)
            .map(|(body, map)| {
                if body.is_empty() {
                    return None;
                }
                let np = if scheme == Scheme::Minimax {
                    let n_prime = map.reported.n_prime;
                    let r = storage(view.light_eye, body, n_prime, tan)
                        / least_storage(view.light_eye, body, tan);
                    let r = if r.is_nan() { f64::INFINITY } else { r };
                    storage_ratio = Some(storage_ratio.map_or(r, |x| x.max(r)));
                    n_prime
                } else {
                    paper_n_prime(scheme, view, body)?
                };
                PaperWarp::new(view.light_eye, body, np)
            })
            .collect();
        Self {
            warps,
            storage_ratio,
            tan,
            height: f64::from(height),
            res: f64::from(res),
            diffs: Vec::new(),
        }
    }

    /// Whether any map has a paper's map (else the measurement is `None`).
    pub(crate) fn applies(&self) -> bool {
        self.warps.iter().any(Option::is_some)
    }

    /// One compared pixel of map `part` at eye-space point `p` with its rendered `(m_x, m_z)`.
    pub(crate) fn add(&mut self, part: usize, p: DVec3, (mx, mz): (f64, f64)) {
        if let Some(Some(w)) = self.warps.get(part) {
            let (ex, ez) = w.m(p, self.tan, self.height, self.res);
            self.diffs
                .push((mx / ex - 1.0).abs().max((mz / ez - 1.0).abs()));
        }
    }

    /// `(p99, largest)` of the per-pixel relative differences; `None` where no map has a paper's
    /// map, NaN where one has but no pixel was compared (no measurement is no pass).
    pub(crate) fn pixel_diffs(&mut self) -> Option<(f64, f64)> {
        if !self.applies() {
            return None;
        }
        if self.diffs.is_empty() {
            return Some((f64::NAN, f64::NAN));
        }
        self.diffs.sort_by(f64::total_cmp);
        let n = self.diffs.len();
        let p99 = self.diffs[((n - 1) as f64 * 0.99).round() as usize];
        Some((p99, self.diffs[n - 1]))
    }

    /// The minimax maps: the largest ratio of S̄ at the frame's n′ to the least S̄ over n′
    /// ([`least_storage`]); `None` for the other schemes.
    pub(crate) fn storage_ratio(&self) -> Option<f64> {
        self.storage_ratio
    }

    /// The frame's reported M_x, M_z and S̄ (`FrameMap::storage_factor`) against §4.4's maxima
    /// of the paper's maps over each body and their product (§4.2): the largest relative
    /// difference over the maps; `None` where no map has a paper's map.
    pub(crate) fn frame_diff(&self, built: &Built) -> Option<f64> {
        let to_pixels = self.height / self.res;
        let mut d = None::<f64>;
        for (k, w) in self.warps.iter().enumerate() {
            let Some(w) = w else { continue };
            let (ex, ez) = w.maxima(&built.bodies[k], self.tan, self.height, self.res);
            let rep = &built.maps[k].reported;
            // S̄ = M_x M_z at unit resolutions (Lloyd 2006 §4.2): the paper's maxima over the
            // body are in pixels at the map's resolution, to_pixels each.
            let storage = rep.storage_factor * to_pixels * to_pixels / (ex * ez);
            let dk = (rep.max_mx * to_pixels / ex - 1.0)
                .abs()
                .max((rep.max_mz * to_pixels / ez - 1.0).abs())
                .max((storage - 1.0).abs());
            let dk = if dk.is_nan() { f64::INFINITY } else { dk };
            d = Some(d.map_or(dk, |x| x.max(dk)));
        }
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::perspective::lloyd2006;

    /// With the light overhead and the body the view frustum (Lloyd 2006 Fig 3), the paper's map
    /// gives Eq 7 and Eq 8 at every depth, for PSM's n′ = n, LiSPSM's, a large n′ and the
    /// orthographic map, with res_i = H for both (square pixels) and W/(2 tan θ_x) = H/(2 tan θ).
    #[test]
    fn each_beam_is_eq_7_and_8_overhead() {
        let (n, f, tan, aspect) = (0.5, 60.0, 30f64.to_radians().tan(), 4.0 / 3.0);
        let (h, res) = (480.0, 1024.0);
        let w = h * aspect;
        let frustum: Vec<DVec3> = [n, f]
            .iter()
            .flat_map(|&d| {
                [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)]
                    .map(|(sx, sy)| DVec3::new(sx * d * tan * aspect, sy * d * tan, -d))
            })
            .collect();
        let light = DVec3::NEG_Y;
        for np in [n, lloyd2006::n_prime_lspsm(n, f), 40.0, f64::INFINITY] {
            let warp = PaperWarp::new(light, &frustum, np).expect("a warp");
            for i in 0..=20 {
                let z = n * (f / n).powf(f64::from(i) / 20.0);
                let p = DVec3::new(0.3 * z * tan * aspect, -0.7 * z * tan, -z);
                let (mx, mz) = warp.m(p, tan, h, res);
                let ex = lloyd2006::m_x(z, n, f, np, w, res);
                let ez = lloyd2006::m_z(z, n, f, np, tan, h, res);
                assert!((mx / ex - 1.0).abs() < 1e-12, "n′ {np} z {z}: {mx} {ex}");
                assert!((mz / ez - 1.0).abs() < 1e-12, "n′ {np} z {z}: {mz} {ez}");
            }
            // §4.4's maxima over the vertices are Eq 9–10.
            let (mx, mz) = warp.maxima(&frustum, tan, h, res);
            let (ex, ez) = lloyd2006::maxima(n, f, np, tan, (w, h), res);
            assert!((mx / ex - 1.0).abs() < 1e-12, "{np}: {mx} {ex}");
            assert!((mz / ez - 1.0).abs() < 1e-12, "{np}: {mz} {ez}");
        }
    }

    /// PSM's n′ (Lloyd 2006 §4.1: n′ = n) puts the centre of projection at the eye: with the
    /// light overhead and the body the frustum, Eq 7 gives m_x = (res_i/res_s) f (n + z − n) /
    /// (z (n + f − n)) = res_i/res_s at every depth (by hand), and Eq 8 m_z ∝ z. The paper's map
    /// with `papers::psm_n_prime` has exactly that m_x and an m_z proportional to the depth.
    #[test]
    fn psm_n_prime_puts_the_centre_at_the_eye() {
        let (n, f, tan, aspect) = (0.5, 60.0, 30f64.to_radians().tan(), 4.0 / 3.0);
        let (h, res) = (480.0, 1024.0);
        let frustum: Vec<DVec3> = [n, f]
            .iter()
            .flat_map(|&d| {
                [(-1.0, -1.0), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)]
                    .map(|(sx, sy)| DVec3::new(sx * d * tan * aspect, sy * d * tan, -d))
            })
            .collect();
        let np = crate::papers::psm_n_prime(n);
        let warp = PaperWarp::new(DVec3::NEG_Y, &frustum, np).expect("a warp");
        let (_, mz0) = warp.m(DVec3::new(0.0, 0.0, -1.0), tan, h, res);
        for i in 0..=20 {
            let z = n * (f / n).powf(f64::from(i) / 20.0);
            let (mx, mz) = warp.m(DVec3::new(0.2 * z, -0.1 * z, -z), tan, h, res);
            assert!(
                (mx / (h * aspect / res) - 1.0).abs() < 1e-12,
                "z {z}: m_x {mx}"
            );
            assert!((mz / (mz0 * z) - 1.0).abs() < 1e-12, "z {z}: m_z {mz}");
        }
    }

    /// The beams are the map's texel steps: the paper's map written out as a point → texel
    /// function, differentiated numerically along light-space x and z on Π, at a tilted light.
    #[test]
    fn beams_are_the_texel_steps_of_the_map() {
        let light = DVec3::new(0.3, -0.8, 0.5).normalize();
        let body = [
            DVec3::new(-1.0, -0.5, -1.0),
            DVec3::new(1.2, -0.4, -1.1),
            DVec3::new(-6.0, -2.0, -20.0),
            DVec3::new(7.0, 1.0, -22.0),
            DVec3::new(0.0, 3.0, -9.0),
        ];
        let res = 512.0;
        let z_axis = crate::papers::warp_axis(light).unwrap();
        let x_axis = (-light).cross(z_axis);
        for np in [2.0, 15.0, f64::INFINITY] {
            let warp = PaperWarp::new(light, &body, np).unwrap();
            let rho = if np.is_finite() { 1.0 / np } else { 0.0 };
            let zs: Vec<f64> = body.iter().map(|p| z_axis.dot(*p)).collect();
            let z0 = zs.iter().copied().fold(f64::INFINITY, f64::min);
            let z1 = zs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let w = |p: DVec3| 1.0 + rho * (z_axis.dot(p) - z0);
            let u: Vec<f64> = body.iter().map(|p| x_axis.dot(*p) / w(*p)).collect();
            let lo = u.iter().copied().fold(f64::INFINITY, f64::min);
            let hi = u.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            // Texel coordinates: s tight on x/w, t the projective map of [z0, z1] onto [0, 1].
            let s = |p: DVec3| (x_axis.dot(p) / w(p) - lo) / (hi - lo) * res;
            let t = |p: DVec3| {
                let v = |zz: f64| (zz - z0) / (1.0 + rho * (zz - z0));
                v(z_axis.dot(p)) / v(z1) * res
            };
            let p = DVec3::new(0.4, 0.2, -8.0);
            let e = 1e-5;
            let ds_dx = (s(p + x_axis * e) - s(p - x_axis * e)) / (2.0 * e);
            let dt_dz = (t(p + z_axis * e) - t(p - z_axis * e)) / (2.0 * e);
            let (bx, bz) = warp.beams(p, res);
            assert!((bx * ds_dx - 1.0).abs() < 1e-7, "{np}: {bx} {ds_dx}");
            assert!((bz * dt_dz - 1.0).abs() < 1e-7, "{np}: {bz} {dt_dz}");
        }
    }
}
