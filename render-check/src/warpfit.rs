//! A map's warp read from the GPU's texel coordinates (docs/rendered.md, "What is measured", 9):
//! over the pixels shaded from one map, the texel coordinates (s, t) as the camera pass read them
//! back against the pixels' exact surface points in the light's plane, a along the warp axis
//! ([`crate::papers::warp_axis`]) and b across it. A warp perpendicular to the light is
//! projective with a denominator w ∝ 1 + q a common to s and t, so
//!
//! ```text
//! s = α_s a + β_s b + c_s − q s a,    t = α_t a + β_t b + c_t − q t a
//! ```
//!
//! is linear in the seven unknowns, fitted by least squares (a, b centred and scaled). q = 0 is
//! an orthographic map; the ratio of w between the body's far and near ends along the axis is
//! `1 + Δ/n′` for a warp whose centre of projection lies n′ before the body's near end and Δ the
//! body's extent along the axis. Nothing here uses the map's matrix.

use crate::schemes::{Built, Scheme, View};
use glam::DVec3;

/// Accumulates the normal equations of the fit.
#[derive(Debug, Clone)]
pub struct WarpFit {
    axis: DVec3,
    side: DVec3,
    centre: (f64, f64),
    scale: f64,
    ata: [[f64; 7]; 7],
    atb: [f64; 7],
    n: usize,
}

/// The fitted warp.
#[derive(Debug, Clone, Copy)]
pub struct Warp {
    coef: [f64; 7],
    axis: DVec3,
    side: DVec3,
    centre: (f64, f64),
    scale: f64,
    /// The pixels fitted.
    pub pixels: usize,
}

impl WarpFit {
    /// A fit along `axis` (unit, eye space, perpendicular to `light`), centred at `centre` (an
    /// eye-space point of the map's body) with `scale` (its extent).
    pub fn new(axis: DVec3, light: DVec3, centre: DVec3, scale: f64) -> Self {
        let side = light.normalize().cross(axis).normalize();
        Self {
            axis,
            side,
            centre: (axis.dot(centre), side.dot(centre)),
            scale: scale.max(1e-12),
            ata: [[0.0; 7]; 7],
            atb: [0.0; 7],
            n: 0,
        }
    }

    fn coords(&self, p: DVec3) -> (f64, f64) {
        (
            (self.axis.dot(p) - self.centre.0) / self.scale,
            (self.side.dot(p) - self.centre.1) / self.scale,
        )
    }

    /// Adds one pixel: its exact eye-space point `p` and its texel coordinates `s`, `t` in [0, 1].
    pub fn add(&mut self, p: DVec3, s: f64, t: f64) {
        let (a, b) = self.coords(p);
        for (row, y) in [
            ([a, b, 1.0, 0.0, 0.0, 0.0, -s * a], s),
            ([0.0, 0.0, 0.0, a, b, 1.0, -t * a], t),
        ] {
            for i in 0..7 {
                self.atb[i] += row[i] * y;
                for j in 0..7 {
                    self.ata[i][j] += row[i] * row[j];
                }
            }
        }
        self.n += 1;
    }

    /// The fit, or `None` with fewer than 100 pixels or a singular system.
    pub fn solve(&self) -> Option<Warp> {
        if self.n < 100 {
            return None;
        }
        let coef = solve7(self.ata, self.atb)?;
        Some(Warp {
            coef,
            axis: self.axis,
            side: self.side,
            centre: self.centre,
            scale: self.scale,
            pixels: self.n,
        })
    }
}

impl Warp {
    fn coords(&self, p: DVec3) -> (f64, f64) {
        (
            (self.axis.dot(p) - self.centre.0) / self.scale,
            (self.side.dot(p) - self.centre.1) / self.scale,
        )
    }

    /// w (up to a constant factor) at the eye-space point `p`.
    pub fn w(&self, p: DVec3) -> f64 {
        1.0 + self.coef[6] * self.coords(p).0
    }

    /// The fitted (s, t) at `p`.
    pub fn st(&self, p: DVec3) -> (f64, f64) {
        let (a, b) = self.coords(p);
        let w = 1.0 + self.coef[6] * a;
        (
            (self.coef[0] * a + self.coef[1] * b + self.coef[2]) / w,
            (self.coef[3] * a + self.coef[4] * b + self.coef[5]) / w,
        )
    }

    /// The texel coordinate that follows the axis (the one whose coefficient of a outweighs
    /// that of b): 0 for s, 1 for t.
    pub fn warp_coordinate(&self) -> usize {
        let s = self.coef[0].abs() / self.coef[1].abs().max(1e-300);
        let t = self.coef[3].abs() / self.coef[4].abs().max(1e-300);
        usize::from(t > s)
    }

    /// w at the body's far end over w at its near end along the axis (the body's vertices
    /// `body`, eye space): `1 + Δ/n′` for a warp whose centre lies before the near end.
    pub fn w_ratio(&self, body: &[DVec3]) -> f64 {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for &v in body {
            let a = self.axis.dot(v);
            lo = lo.min(a);
            hi = hi.max(a);
        }
        let at = |a: f64| 1.0 + self.coef[6] * (a - self.centre.0) / self.scale;
        at(hi) / at(lo)
    }
}

/// Gaussian elimination with partial pivoting.
fn solve7(mut a: [[f64; 7]; 7], mut b: [f64; 7]) -> Option<[f64; 7]> {
    for c in 0..7 {
        let p = (c..7).max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))?;
        if a[p][c].abs() < 1e-300 {
            return None;
        }
        a.swap(c, p);
        b.swap(c, p);
        for r in c + 1..7 {
            let f = a[r][c] / a[c][c];
            let pivot = a[c];
            for (x, p) in a[r].iter_mut().zip(pivot).skip(c) {
                *x -= f * p;
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = [0.0; 7];
    for r in (0..7).rev() {
        let mut s = b[r];
        for k in r + 1..7 {
            s -= a[r][k] * x[k];
        }
        x[r] = s / a[r][r];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// Per map, a fit of its warp where the paper's expectation is measured: LiSPSM's maps (the
/// single map and each cascade's), PSM's and TSM's.
pub(crate) fn warp_fits(view: &View, built: &Built, scheme: Scheme) -> Vec<Option<WarpFit>> {
    let measured = matches!(
        scheme,
        Scheme::Lispsm | Scheme::Cascades | Scheme::BlendedCascades | Scheme::Tsm | Scheme::Psm
    );
    let axis = crate::papers::warp_axis(view.light_eye);
    built
        .bodies
        .iter()
        .map(|body| {
            let axis = axis.filter(|_| measured && !body.is_empty())?;
            let c = body.iter().copied().sum::<DVec3>() / body.len() as f64;
            let r = body.iter().map(|v| (*v - c).length()).fold(0.0, f64::max);
            Some(WarpFit::new(axis, view.light_eye, c, r))
        })
        .collect()
}

/// Below this many pixels a map's warp is not fitted (a cascade's sliver at the horizon).
const MIN_FIT_PIXELS: usize = 2000;

/// LiSPSM's and PSM's w ratio against the paper's n′ (the largest relative difference over the
/// maps), and TSM's focus fraction, from the fits (docs/rendered.md, "What is measured", 8–9). A
/// scheme measured with no map fitted gives NaN (no measurement is no pass).
pub(crate) fn warp_measures(
    view: &View,
    built: &Built,
    scheme: Scheme,
    fits: &[Option<WarpFit>],
    debug: bool,
) -> (Option<f64>, Option<f64>) {
    let lispsm = matches!(
        scheme,
        Scheme::Lispsm | Scheme::Cascades | Scheme::BlendedCascades
    );
    let psm = scheme == Scheme::Psm;
    let tsm = scheme == Scheme::Tsm;
    if !(lispsm || psm || tsm) {
        return (None, None);
    }
    let Some(axis) = crate::papers::warp_axis(view.light_eye) else {
        return (None, None);
    };
    let sin_g = crate::papers::sin_gamma(view.light_eye);
    let (mut worst, mut frac, mut any) = (0.0f64, f64::NAN, false);
    for (k, fit) in fits.iter().enumerate() {
        let Some(warp) = fit.as_ref().and_then(WarpFit::solve) else {
            continue;
        };
        if warp.pixels < MIN_FIT_PIXELS {
            continue;
        }
        let body = &built.bodies[k];
        let a: Vec<f64> = body.iter().map(|v| axis.dot(*v)).collect();
        let lo = a.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = a.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let n_b = body.iter().map(|v| -v.z).fold(f64::INFINITY, f64::min);
        let f_b = body.iter().map(|v| -v.z).fold(f64::NEG_INFINITY, f64::max);
        if lispsm || psm {
            let np = if psm {
                crate::papers::psm_n_prime(n_b)
            } else {
                crate::papers::lispsm_n_prime(n_b, f_b, sin_g)
            };
            let expected = 1.0 + (hi - lo) / np;
            let got = warp.w_ratio(body);
            let d = (got / expected - 1.0).abs();
            if debug {
                eprintln!(
                    "  map {k}: w ratio {got:.6} fitted, 1 + Δ/n′ = {expected:.6} (paper n′ {np:.4}, reported {:.4}, Δ {:.4})",
                    built.maps[k].reported.n_prime,
                    hi - lo
                );
            }
            worst = worst.max(if d.is_nan() { f64::INFINITY } else { d });
            any = true;
        } else {
            let fr = &view.frustum;
            let focus = crate::papers::tsm_focus_point((n_b, f_b), (fr.near(), fr.far()));
            let af = axis.dot(focus);
            let c = warp.warp_coordinate();
            let x = |p: DVec3| {
                let st = warp.st(p);
                if c == 0 {
                    st.0
                } else {
                    st.1
                }
            };
            let (top, base) = (focus + axis * (lo - af), focus + axis * (hi - af));
            frac = (x(focus) - x(top)) / (x(base) - x(top));
            if debug {
                eprintln!("  map {k}: focus fraction {frac:.6} (coordinate {c})");
            }
            any = true;
        }
    }
    if lispsm || psm {
        (Some(if any { worst } else { f64::NAN }), None)
    } else {
        (None, Some(frac))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A known projective warp along the axis (centre of projection n′ = 3 before the near end
    /// of a body 10 long): the fit recovers w's ratio 1 + Δ/n′ and the map at a point.
    #[test]
    fn recovers_a_known_warp() {
        let axis = DVec3::new(0.0, 0.6, -0.8);
        let light = DVec3::new(0.0, -0.8, -0.6);
        let side = light.cross(axis).normalize();
        let (np, delta) = (3.0, 10.0);
        let map = |p: DVec3| {
            let (a, b) = (axis.dot(p), side.dot(p));
            let w = a + np; // a ∈ [0, Δ]
            ((0.7 * b + 2.0) / w, (a * (1.0 + np / delta) * 1.0) / w)
        };
        let body: Vec<DVec3> = [0.0, delta]
            .iter()
            .flat_map(|&a| [-4.0, 4.0].map(move |b| axis * a + side * b))
            .collect();
        let mut fit = WarpFit::new(axis, light, axis * 5.0, 10.0);
        for i in 0..40 {
            for j in 0..20 {
                let p = axis * (0.25 * f64::from(i))
                    + side * (-4.0 + 0.4 * f64::from(j))
                    + light * f64::from(j % 3);
                let (s, t) = map(p);
                fit.add(p, s, t);
            }
        }
        let w = fit.solve().unwrap();
        let r = w.w_ratio(&body);
        assert!((r - (1.0 + delta / np)).abs() < 1e-9, "{r}");
        let p = axis * 7.3 + side * 1.1;
        let (a, b) = (w.st(p), map(p));
        assert!((a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9);
        assert_eq!(w.warp_coordinate(), 1);
    }
}
