//! The crate's own warp parameters: the n′ that minimises the frustum's maximum error, found from
//! the error's exact form in n′ rather than from the light-overhead closed form.
//!
//! Two objectives: the storage factor S̄ = M_x M_z ([`minimax_n_prime`], the default rule
//! [`crate::maps::WarpRule::Minimax`]) and the z error M_z alone ([`minimax_mz_n_prime`]).
//! S̄ is what a fixed texel budget buys (Lloyd 2006 §4.2: the critical-resolution map for
//! maximum error 1 has S̄ texels), and minimising M_z alone can raise M_x enough to lose against
//! the uniform map: for n = 1, f = 100, θ = 30°, light 12° above the horizon from behind the
//! viewer, the M_z optimum has S̄ 1.18 times the uniform map's (tests/minimax.rs,
//! `mz_minimax_can_lose_storage_to_uniform`). The S̄ optimum never does, by construction.
//!
//! # M_z as a function of n′
//!
//! For the warp of [`crate::maps::fit_warp`] the t coordinate depends only on `δ = z − z₀`, the
//! light-space distance along the warp axis from where the warping frustum starts, and with unit
//! resolutions the z error at a frustum vertex i (eye depth zᵢ, offset δᵢ, frustum extent Δ along
//! the axis, half field of view θ) is
//!
//! ```text
//! m_z,i(n′) = Kᵢ (n′ + δᵢ)² / (n′ (n′ + Δ)),   Kᵢ = Δ / (2 zᵢ tan θ)
//! ```
//!
//! (Lloyd 2006 Eq 8 with `z − n` replaced by δᵢ and `f − n` by Δ; Barroso & Celes Eq 12 written in
//! the warp frame). All vertices share the denominator, so
//! `M_z(n′) = G(n′)² / (n′(n′ + Δ))` with `G(n′) = maxᵢ √Kᵢ (n′ + δᵢ)`, the upper envelope of
//! eight lines. On a piece where line i is the maximum, `√Kᵢ (n′ + δᵢ)/√(n′(n′ + Δ))` is stationary
//! only at `n′ = δᵢ Δ/(Δ − 2δᵢ)` (when `0 < δᵢ < Δ/2`, a minimum), and tends to `√Kᵢ` as n′ → ∞.
//! So the minimum of M_z over n′ ∈ (0, ∞] lies at a crossing of two lines, at one of these
//! stationary points, or at n′ = ∞: 28 + 8 + 1 candidates, each evaluated exactly. With the light
//! overhead the optimum is the crossing of the near and far lines, `n + √(f n)` (Lloyd 2006 §4.1).
//!
//! # S̄ as a function of n′
//!
//! The x error at vertex i is `m_x,i = u_h(n′) (1 + δᵢ/n′) / (zᵢ tan θ)`, `u_h` half the range of
//! `xᵢ/(1 + δᵢ/n′)`, so `S̄ = M_x M_z` is a product of piecewise rational functions whose pieces
//! change where the arg-max vertices change. [`minimax_n_prime`] minimises it by a 65-point scan
//! of log n′ over [10⁻³ min(n, Δ), 10⁶ max(n, Δ)] and n′ = ∞, refined by golden-section search
//! between the neighbours of the best sample; ties within a relative 10⁻⁹ go to the larger n′
//! (the least warp: with the light overhead S̄ is flat for n′ ≤ n + √(f n), Lloyd 2006 §4.3, and
//! this picks n + √(f n)). n′ = ∞ is evaluated exactly, so the result is never worse than the
//! uniform map.

use crate::error::{finite_result, fmt_num, Error, Result};
use crate::frustum::{NPrime, ViewFrustum};
use crate::maps::fit::FrustumInLight;
use glam::DVec3;

/// A chosen n′ and the frustum maximum it achieves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Optimum {
    /// The n′ chosen.
    pub n_prime: NPrime,
    /// The maximum z error M_z of the fitted map (unit resolutions).
    pub max_mz: f64,
    /// The maximum x error M_x of the fitted map (unit resolutions).
    pub max_mx: f64,
}

impl Optimum {
    /// S̄ = M_x M_z.
    #[must_use]
    pub fn storage_factor(&self) -> f64 {
        self.max_mx * self.max_mz
    }
}

/// The frustum's vertices as the closed forms above need them, precomputed once per light.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Vertices<const N: usize = 8> {
    /// Light-space x.
    x: [f64; N],
    /// δ = z − z₀ along the warp axis.
    delta: [f64; N],
    /// 1 / eye depth.
    inv_depth: [f64; N],
    /// Δ, the extent along the warp axis.
    extent: f64,
    /// tan θ.
    tan: f64,
}

impl<const N: usize> Vertices<N> {
    pub(crate) fn new(view: &ViewFrustum, fl: &FrustumInLight<N>) -> Self {
        let mut v = Self {
            x: [0.0; N],
            delta: [0.0; N],
            inv_depth: [0.0; N],
            extent: fl.delta,
            tan: view.tan_half_fov(),
        };
        for i in 0..N {
            let q: DVec3 = fl.q[i];
            v.x[i] = q.x;
            v.delta[i] = q.z - fl.z0;
            v.inv_depth[i] = 1.0 / fl.depth[i];
        }
        v
    }

    /// `(M_x, M_z)` of the warp with ρ = 1/n′ fitted to the frustum, from the closed forms of the
    /// module docs: m_x,i = u_h wᵢ/(zᵢ tan θ), m_z,i = Δ wᵢ²/((1 + ρΔ) 2 zᵢ tan θ), wᵢ = 1 + ρδᵢ.
    pub(crate) fn maxima(&self, rho: f64) -> (f64, f64) {
        let (mut u_lo, mut u_hi) = (f64::INFINITY, f64::NEG_INFINITY);
        let mut gx = 0.0f64;
        let mut gz = 0.0f64;
        for i in 0..N {
            let w = 1.0 + rho * self.delta[i];
            let u = self.x[i] / w;
            u_lo = u_lo.min(u);
            u_hi = u_hi.max(u);
            let wd = w * self.inv_depth[i];
            gx = gx.max(wd);
            gz = gz.max(w * wd);
        }
        // Divide by tan θ (up to 1.6·10¹⁶) before multiplying by gx (up to 1/n): the maxima are
        // finite whenever they are representable, not only when u_h gx is.
        let u_h = 0.5 * (u_hi - u_lo);
        let mz = (self.extent / ((1.0 + rho * self.extent) * 2.0 * self.tan)) * gz;
        ((u_h / self.tan) * gx, mz)
    }
}

fn rho_of(n: NPrime) -> f64 {
    n.recip()
}

fn optimum<const N: usize>(view: &ViewFrustum, fl: &FrustumInLight<N>, n_prime: NPrime) -> Optimum {
    let (max_mx, max_mz) = Vertices::new(view, fl).maxima(rho_of(n_prime));
    Optimum {
        n_prime,
        max_mz,
        max_mx,
    }
}

/// The n′ ∈ (0, ∞] minimising M_z of the frustum's fitted warp, exactly (module docs).
pub(crate) fn minimax_mz<const N: usize>(view: &ViewFrustum, fl: &FrustumInLight<N>) -> Optimum {
    let d = fl.delta;
    let t = view.tan_half_fov();
    let mut a = [0.0f64; N];
    let mut b = [0.0f64; N];
    for i in 0..N {
        let k = (d / (2.0 * fl.depth[i] * t)).sqrt();
        a[i] = k;
        b[i] = k * (fl.q[i].z - fl.z0);
    }
    let mz_at = |n: f64| -> f64 {
        let g = (0..N).fold(0.0f64, |m, i| m.max(a[i] * n + b[i]));
        g * g / (n * (n + d))
    };
    // n′ = ∞: M_z = max Kᵢ.
    let mut best_n = f64::INFINITY;
    let mut best = a.iter().fold(0.0f64, |m, &k| m.max(k * k));
    let mut consider = |n: f64| {
        if n.is_finite() && n > 0.0 {
            let v = mz_at(n);
            if v.is_finite() && (v < best * (1.0 - 1e-12) || (v <= best && n > best_n)) {
                best = v;
                best_n = n;
            }
        }
    };
    for i in 0..N {
        let di = fl.q[i].z - fl.z0;
        if di > 0.0 && 2.0 * di < d {
            consider(di * d / (d - 2.0 * di));
        }
        for j in (i + 1)..N {
            let da = a[i] - a[j];
            if da != 0.0 {
                consider((b[j] - b[i]) / da);
            }
        }
    }
    let n_prime = if best_n.is_finite() {
        NPrime::finite_or_unwarped(best_n)
    } else {
        NPrime::UNWARPED
    };
    optimum(view, fl, n_prime)
}

/// Number of intervals of the logarithmic scan of n′ in [`min_storage`].
const SCAN: usize = 64;

/// The n′ ∈ (0, ∞] minimising S̄ = M_x M_z of the frustum's fitted warp (module docs).
pub(crate) fn min_storage<const N: usize>(view: &ViewFrustum, fl: &FrustumInLight<N>) -> Optimum {
    let d = fl.delta;
    let verts = Vertices::new(view, fl);
    // S̄ relative to the uniform map's, (M_x/M_x,∞)(M_z/M_z,∞): the same minimiser, and finite
    // wherever the two ratios are, even when S̄ itself overflows `f64`. A value that is not
    // finite (an overflowing ratio, or NaN) is never chosen.
    let (mx0, mz0) = verts.maxima(0.0);
    let (sx, sz) = if mx0.is_normal() && mz0.is_normal() {
        (1.0 / mx0, 1.0 / mz0)
    } else {
        (1.0, 1.0)
    };
    let sbar = |rho: f64| {
        let (mx, mz) = verts.maxima(rho);
        let v = (mx * sx) * (mz * sz);
        if v.is_finite() {
            v
        } else {
            f64::INFINITY
        }
    };
    // log n′ from 10⁻³ min(n, Δ) to 10⁶ max(n, Δ); n′ = ∞ separately.
    let lo = (1e-3 * view.near().min(d)).ln();
    let hi = (1e6 * view.near().max(d)).ln();
    let step = (hi - lo) / SCAN as f64;
    let at = |x: f64| sbar((-x).exp());
    let s_inf = sbar(0.0);
    let mut samples = [0.0f64; SCAN + 1];
    let mut best = s_inf;
    let mut best_k = usize::MAX;
    for (k, v) in samples.iter_mut().enumerate() {
        *v = at(lo + k as f64 * step);
        if *v < best {
            best = *v;
            best_k = k;
        }
    }
    if best_k == usize::MAX {
        return optimum(view, fl, NPrime::UNWARPED);
    }
    // Golden-section refinement of log n′ between the neighbours of the best sample.
    let mut a = lo + (best_k.saturating_sub(1)) as f64 * step;
    let mut b = lo + (best_k + 1).min(SCAN) as f64 * step;
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = b - g * (b - a);
    let mut x2 = a + g * (b - a);
    let (mut f1, mut f2) = (at(x1), at(x2));
    for _ in 0..48 {
        if f1 <= f2 {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = at(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = at(x2);
        }
    }
    let mut x_best = lo + best_k as f64 * step;
    let xm = 0.5 * (a + b);
    let fm = at(xm);
    if fm < best {
        best = fm;
        x_best = xm;
    }
    // Ties within 10⁻⁹ go to the least warp: n′ = ∞ if it ties, else the largest n′ that does,
    // found by bisection between the largest tying sample and the next one.
    let tol = best * (1.0 + 1e-9);
    if s_inf <= tol {
        return optimum(view, fl, NPrime::UNWARPED);
    }
    if let Some(k) = (0..=SCAN).rev().find(|&k| samples[k] <= tol) {
        let xk = lo + k as f64 * step;
        if xk >= x_best {
            x_best = xk;
            if k < SCAN {
                let (mut a, mut b) = (xk, xk + step);
                for _ in 0..48 {
                    let m = 0.5 * (a + b);
                    if at(m) <= tol {
                        a = m;
                    } else {
                        b = m;
                    }
                }
                x_best = a;
            }
        }
    }
    optimum(view, fl, NPrime::finite_or_unwarped(x_best.exp()))
}

/// The n′ ∈ (0, ∞] minimising M_z of the view frustum's fitted warp for this light, exactly
/// (module docs), with the maxima it achieves.
///
/// # Errors
/// [`crate::Error::InvalidArgument`] naming `light_dir` for a zero or non-finite vector;
/// [`crate::Error::Degenerate`] when the maxima or S̄ of the optimum overflow or underflow `f64`.
///
/// ```
/// # use shadow_aliasing::maps::minimax::minimax_mz_n_prime;
/// # use shadow_aliasing::{NPrime, ViewFrustum};
/// # use glam::DVec3;
/// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
/// let o = minimax_mz_n_prime(&view, DVec3::new(0.0, -1.0, 0.0))?;
/// assert!((o.n_prime.value() - 11.0).abs() < 1e-9); // n + √(f n)
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn minimax_mz_n_prime(view: &ViewFrustum, light_dir: DVec3) -> Result<Optimum> {
    let fl = FrustumInLight::new(view, light_dir)?;
    checked(minimax_mz(view, &fl))
}

/// The optimum, or [`Error::Degenerate`] when its maxima or their product are not finite
/// (the frustum's errors overflow `f64` for every n′) or not normal (they underflow: a frustum
/// of aspect 2·10⁻³⁰⁸ gives M_x = 3·10⁻³⁰⁸, M_x M_z = 0).
fn checked(o: Optimum) -> Result<Optimum> {
    finite_result("M_x of the minimax map", o.max_mx)?;
    finite_result("M_z of the minimax map", o.max_mz)?;
    finite_result(
        "the storage factor M_x M_z of the minimax map",
        o.storage_factor(),
    )?;
    // Normal values: a subnormal maximum (or product) has lost its digits, and a product that
    // underflows to 0 is no storage factor.
    if o.max_mx.is_normal() && o.max_mz.is_normal() && o.storage_factor().is_normal() {
        Ok(o)
    } else {
        Err(Error::Degenerate(format!(
            "the minimax map's maxima or their product underflow f64 (M_x = {}, M_z = {})",
            fmt_num(o.max_mx),
            fmt_num(o.max_mz)
        )))
    }
}

/// The n′ ∈ (0, ∞] minimising the storage factor S̄ = M_x M_z of the view frustum's fitted warp
/// for this light (module docs), with the maxima it achieves. No heap allocation; about 150
/// evaluations of the eight vertex errors.
///
/// # Errors
/// [`crate::Error::InvalidArgument`] naming `light_dir` for a zero or non-finite vector;
/// [`crate::Error::Degenerate`] when the maxima or S̄ of the optimum overflow or underflow `f64`.
///
/// ```
/// # use shadow_aliasing::maps::minimax::minimax_n_prime;
/// # use shadow_aliasing::ViewFrustum;
/// # use glam::DVec3;
/// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
/// // Overhead, S̄ is flat for n′ ≤ n + √(f n); ties go to the least warp, n + √(f n) = 11.
/// let o = minimax_n_prime(&view, DVec3::new(0.0, -1.0, 0.0))?;
/// assert!((o.n_prime.value() - 11.0).abs() < 1e-6);
/// // Light from behind: nothing beats the uniform map.
/// assert!(minimax_n_prime(&view, DVec3::new(0.0, 0.0, -1.0))?.n_prime.is_unwarped());
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn minimax_n_prime(view: &ViewFrustum, light_dir: DVec3) -> Result<Optimum> {
    let fl = FrustumInLight::new(view, light_dir)?;
    checked(min_storage(view, &fl))
}
