//! The single-map sweep evaluated [`LANES`] light directions at a time.
//!
//! `scheme(view, l, rule, Partition::Single, 1)` for a rule whose n′ is one of the lane forms is,
//! step by step: the light direction from its angles and its normalisations, the view-axis light
//! space ([`project_axis`], [`frame_from_projected`]), the corners in light space
//! ([`light_corners`]), the rule's n′ ([`lispsm_sin_n_prime`], [`reference_n_prime`], or a fixed
//! one), the fitted warp ([`Ranges::of_warped`], [`warp_rows`]), its clip check at the corners
//! ([`clip_at_slices`]) and the vertex measurement ([`Kernel`]). Each of those is written once,
//! generic over [`Lane`], and the scalar builders and measurement call it at `f64`; here the same
//! functions run at [`F4`], four directions at a time (structure of arrays), so that every lane's
//! value is the scalar value bit for bit by construction. `tests/sweep.rs` checks it over whole
//! grids.
//!
//! A lane takes none of the scalar code's special paths: where the scalar code would branch (the
//! light parallel to the view axis, a warp with no extent, a point outside the clip volume, a
//! singular map at a vertex, a non-finite value), the lane is marked, and the caller evaluates that
//! direction with the scalar code, which takes the path or reports the error. The clip check and
//! the measurement share `M (c, 1)` at the eight corners (both use [`ViewFrustum::corners`]).

use crate::frustum::{NPrime, ViewFrustum};
use crate::maps::lightspace::{frame_from_projected, project_axis};
use crate::maps::warp::{
    clip_at_slices, light_corners, lispsm_sin_n_prime, reference_n_prime, sin_gamma, slices,
    warp_rows, Ranges,
};
use crate::maps::WarpRule;
use crate::measure::vertex::{Kernel, Maxima};
use crate::numeric::lane::{Lane, F4, M4, V3};
use crate::numeric::PARALLEL_TOLERANCE;
use glam::DVec3;

pub(crate) use crate::numeric::lane::LANES;

/// One flag per direction.
type Mask = [bool; LANES];

/// How the rule's n′ depends on the direction.
#[derive(Clone, Copy)]
enum LaneRule {
    /// The same 1/n′ for every direction (0 for the orthographic map).
    Fixed(f64),
    /// `WarpRule::Lispsm`: n′ = n′_LiSPSM / sin γ.
    SinScaled(f64),
    /// `WarpRule::LispsmReference`: n′ from Wimmer's reference code, with the near depth.
    Reference(f64),
}

/// What a sweep of one view and rule shares over its directions.
#[derive(Clone, Copy)]
pub(crate) struct LaneSweep {
    rule: LaneRule,
    /// `(w, h, d)` of the view's corners `(±w, ±h, −d)` at d = near, far
    /// ([`ViewFrustum::corners`]): the points of the fit, the clip check and the measurement.
    corners: [(f64, f64, f64); 2],
    /// tan θ of the measurement.
    tan: f64,
    /// A bound on every light-space coordinate of the corners, whatever the direction: their
    /// largest eye-space length, with room for the rounding of the rotation.
    extent: f64,
}

impl LaneSweep {
    /// `None` for rules whose n′ is not one of the lane forms (they run the scalar code).
    /// `fixed` is the rule's n′ when it does not depend on the direction (computed by the scalar
    /// rule, so validated and bit for bit the same).
    pub(crate) fn new(view: &ViewFrustum, rule: WarpRule, fixed: Option<NPrime>) -> Option<Self> {
        let rule = match rule {
            WarpRule::Uniform | WarpRule::Psm | WarpRule::LispsmFixed | WarpRule::Eta(_) => {
                LaneRule::Fixed(fixed?.recip())
            }
            WarpRule::Lispsm => LaneRule::SinScaled(view.n_prime_lispsm()),
            WarpRule::LispsmReference => LaneRule::Reference(view.near()),
            _ => return None,
        };
        let corners = slices(&view.corners());
        Some(Self {
            rule,
            corners,
            tan: view.tan_half_fov(),
            extent: corners
                .iter()
                .map(|&(w, h, d)| (w * w + h * h + d * d).sqrt())
                .fold(f64::MIN_POSITIVE, f64::max)
                * (1.0 + 1e-9),
        })
    }

    /// S̄ of the single map at [`LANES`] directions of one elevation row: `el = (sin, cos)` of the
    /// elevation, `az[i] = (sin, cos)` of each azimuth. Returns the values and, per lane, whether
    /// the lane is valid; an invalid lane must be evaluated by the scalar code.
    #[inline]
    pub(crate) fn run(&self, el: (f64, f64), az: &[(f64, f64); LANES]) -> ([f64; LANES], Mask) {
        let splat = F4::splat;
        let and = F4::and;
        let (se, ce) = (splat(el.0), splat(el.1));
        let (sa, ca) = (F4(az.map(|a| a.0)), F4(az.map(|a| a.1)));
        // The sweep's `one`: l = −(ce sa, se, ce ca) and `LightDir::new`: l / √|l|² where |l|²
        // lies in (10⁻²⁹⁰, 10²⁹⁰).
        let l = -V3::new(ce * sa, se, ce * ca);
        let len2 = l.dot(l);
        let mut ok = and(len2.gt(splat(1e-290)), len2.lt(splat(1e290)));
        let l = l.div(len2.sqrt());
        // `light_space_unit(l, −Z)`, without its fallback for the light along the view axis.
        let y = -l;
        let (z, zl) = project_axis(y, V3::splat(DVec3::NEG_Z));
        ok = and(ok, zl.ge(splat(PARALLEL_TOLERANCE)));
        let (x, z) = frame_from_projected(y, z, zl);
        // `FrustumInLight::in_light_space`: the corners in light space, z₀, Δ, sin γ.
        let qn = light_corners(x, y, z, self.corners[0]);
        let qf = light_corners(x, y, z, self.corners[1]);
        let q = [qn[0], qn[1], qn[2], qn[3], qf[0], qf[1], qf[2], qf[3]];
        let mut z0 = splat(f64::INFINITY);
        let mut z1 = splat(f64::NEG_INFINITY);
        for c in &q {
            z0 = z0.min(c.z);
            z1 = z1.max(c.z);
        }
        let delta = z1 - z0;
        let sin_g = sin_gamma(l);
        // The rule's 1/n′ (0 for the orthographic map), as `rule_n_prime` + `fit_frustum`.
        let warp = |(v, finite): (F4, M4)| F4::select(finite, splat(1.0) / v, splat(0.0));
        let rho = match self.rule {
            LaneRule::Fixed(rho) => splat(rho),
            LaneRule::SinScaled(nl) => warp(lispsm_sin_n_prime(splat(nl), sin_g)),
            LaneRule::Reference(n) => warp(reference_n_prime(delta, sin_g, splat(n))),
        };
        // `fit_frustum` and `warp_matrix`. `warp_matrix` scales its two degeneracy tests by the
        // corners' largest light-space coordinate, `extent`; the lanes use `self.extent`, a bound
        // on it the same for every direction. `delta > 1e−12 · bound` implies the scalar
        // `delta > 1e−12 · extent`, and `v_h > 1e−9 · bound` that the scalar's `max` picks v_h: a
        // lane where either fails goes to the scalar code.
        let (u_h, u_m, v_h, v_m) = Ranges::of_warped(q, z0, rho).halves();
        let tiny = splat(1e-12 * self.extent);
        ok = and(ok, and(delta.gt(tiny), u_h.gt(tiny)));
        ok = and(ok, v_h.gt(splat(1e-9 * self.extent)));
        let rows = warp_rows((x, y, z), z0, delta, rho, (u_h, u_m, v_h, v_m));
        // `m.is_finite()`: a finite sum of the entries (an overflowing sum of finite entries
        // only sends the lane to the scalar code).
        let mut sum = splat(0.0);
        for (v, w) in &rows {
            sum = sum + (((v.x + v.y) + v.z) + *w);
        }
        ok = and(ok, sum.finite());
        // `clip_ok_at_corners`, then `vertex_max` (light direction `−ls.y` = l) corner by corner,
        // with `M (c, 1)` once for both when their corners are the same points.
        let (hc, clip_ok) = clip_at_slices(&rows, &self.corners);
        ok = and(ok, clip_ok);
        let kernel = Kernel::from_rows([rows[0], rows[1], rows[3]], l);
        let mut max = Maxima::new();
        for (hk, slice) in hc.iter().zip(&self.corners) {
            for &[hx, hy, _, hw] in hk {
                let w = kernel.widths([hx, hy, hw], splat(slice.2));
                ok = and(ok, w.ok);
                max.add(&w);
            }
        }
        // `Maxima::finish`, and the scheme's sum over its one partition (0 + S̄ = S̄).
        let (mx, mz) = max.values(splat(self.tan));
        let zero = splat(0.0);
        ok = and(
            ok,
            and(and(mx.finite(), mx.gt(zero)), and(mz.finite(), mz.gt(zero))),
        );
        ((zero + mx * mz).0, ok.to_bools())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scheme::sweep::light_dir_from_angles;
    use crate::scheme::{scheme, Partition};

    /// The lanes take ordinary directions themselves (the bit-for-bit tests in tests/sweep.rs
    /// would also pass if every lane went to the scalar code) and send the light exactly along the
    /// view axis (the light-space fallback) to the scalar code.
    #[test]
    fn lanes_take_ordinary_directions_and_refuse_the_parallel_one() {
        let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap();
        let lanes = LaneSweep::new(&view, WarpRule::Lispsm, None).unwrap();
        let azs = [0.0, 1.0, 2.5, std::f64::consts::PI];
        for el in [0.0, 0.4, std::f64::consts::FRAC_PI_2] {
            let (s, ok) = lanes.run(el.sin_cos(), &azs.map(f64::sin_cos));
            for (j, &az) in azs.iter().enumerate() {
                let l = light_dir_from_angles(el, az);
                let parallel = el == 0.0 && (az == 0.0 || az == std::f64::consts::PI);
                assert_eq!(ok[j], !parallel, "el={el} az={az}");
                if ok[j] {
                    let direct = scheme(&view, l, WarpRule::Lispsm, Partition::Single, 1)
                        .unwrap()
                        .storage_factor();
                    assert_eq!(s[j].to_bits(), direct.to_bits());
                }
            }
        }
        // Rules the lanes do not compute, and fixed rules without their n′, run the scalar code.
        assert!(LaneSweep::new(&view, WarpRule::Minimax, None).is_none());
        assert!(LaneSweep::new(&view, WarpRule::LispsmFixed, None).is_none());
    }
}
