//! The single-map sweep evaluated [`LANES`] light directions at a time.
//!
//! Every scalar step of `scheme(view, l, rule, Partition::Single, 1)` — the light direction from
//! its angles and its normalisations, the view-axis light space, the corners in light space, the
//! rule's n′, the fitted warp, its clip check at the corners, and the vertex measurement — is
//! written here once more over arrays of [`LANES`] directions (structure of arrays), so that the
//! compiler evaluates two directions per SSE2 instruction. Each step is the same IEEE operation
//! on the same operands in the same order as the scalar code (no reassociation, no fused
//! multiply-add, the same one-instruction min/max), so every lane's value is the scalar value bit
//! for bit; `tests/sweep.rs` checks that over whole grids.
//!
//! A lane takes none of the scalar code's special paths: where the scalar code would branch (the
//! light parallel to the view axis, a warp with no extent, a point outside the clip volume, a
//! singular map at a vertex, a non-finite value), the lane is marked, and the caller evaluates that
//! direction with the scalar code, which takes the path or reports the error. The clip check and
//! the measurement share `M (c, 1)` at the eight corners when the two corner sets are the same
//! points (they are bit for bit whenever the aspect is 1, and both are formed from shared
//! products either way).

use crate::frustum::{NPrime, ViewFrustum};
use crate::maps::WarpRule;
use crate::numeric::PARALLEL_TOLERANCE;
use glam::DVec3;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Directions per evaluation: four `f64` lanes, two SSE2 registers per value.
pub(crate) const LANES: usize = 4;

/// One `f64` per direction.
#[derive(Clone, Copy)]
struct F([f64; LANES]);

/// One flag per direction.
type Mask = [bool; LANES];

impl F {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        F([v; LANES])
    }
    #[inline(always)]
    fn zip(self, o: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        F(std::array::from_fn(|i| f(self.0[i], o.0[i])))
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        F(std::array::from_fn(|i| self.0[i].sqrt()))
    }
    #[inline(always)]
    fn abs(self) -> Self {
        F(std::array::from_fn(|i| self.0[i].abs()))
    }
    /// The scalar code's `fmin` (one `minpd`).
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        self.zip(o, |a, b| if a < b { a } else { b })
    }
    /// The scalar code's `fmax` (one `maxpd`).
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        self.zip(o, |a, b| if a > b { a } else { b })
    }
    #[inline(always)]
    fn test(self, f: impl Fn(f64) -> bool) -> Mask {
        std::array::from_fn(|i| f(self.0[i]))
    }
    /// `if m { a } else { b }` per lane.
    #[inline(always)]
    fn select(m: Mask, a: Self, b: Self) -> Self {
        F(std::array::from_fn(|i| if m[i] { a.0[i] } else { b.0[i] }))
    }
}

macro_rules! lane_op {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for F {
            type Output = F;
            #[inline(always)]
            fn $f(self, o: F) -> F {
                F(std::array::from_fn(|i| self.0[i] $op o.0[i]))
            }
        }
        impl $tr<f64> for F {
            type Output = F;
            #[inline(always)]
            fn $f(self, o: f64) -> F {
                F(std::array::from_fn(|i| self.0[i] $op o))
            }
        }
        impl $tr<F> for f64 {
            type Output = F;
            #[inline(always)]
            fn $f(self, o: F) -> F {
                F(std::array::from_fn(|i| self $op o.0[i]))
            }
        }
    };
}
lane_op!(Add, add, +);
lane_op!(Sub, sub, -);
lane_op!(Mul, mul, *);
lane_op!(Div, div, /);

impl Neg for F {
    type Output = F;
    #[inline(always)]
    fn neg(self) -> F {
        F(std::array::from_fn(|i| -self.0[i]))
    }
}

#[inline(always)]
fn and(a: Mask, b: Mask) -> Mask {
    std::array::from_fn(|i| a[i] && b[i])
}

/// The scalar code's branch conditions, accumulated per lane without branches: a lane passes when
/// every value given to [`Checks::positive`] is > 0, every value given to
/// [`Checks::non_negative`] is ≥ 0, and every value given to any of the three is finite (their
/// sum is: a NaN or ±∞ makes it NaN or ±∞ for good, where a min would drop a NaN; a finite sum
/// that overflows only sends a lane to the scalar code without need). For finite a and b,
/// `a − b > 0` exactly when `a > b`, so a margin carries a comparison.
struct Checks {
    pos: F,
    nonneg: F,
    sum: F,
}

impl Checks {
    #[inline(always)]
    fn new() -> Self {
        Self {
            pos: F::splat(f64::INFINITY),
            nonneg: F::splat(f64::INFINITY),
            sum: F::splat(0.0),
        }
    }
    #[inline(always)]
    fn positive(&mut self, v: F) {
        self.pos = self.pos.min(v);
        self.sum = self.sum + v;
    }
    #[inline(always)]
    fn non_negative(&mut self, v: F) {
        self.nonneg = self.nonneg.min(v);
        self.sum = self.sum + v;
    }
    #[inline(always)]
    fn finite(&mut self, v: F) {
        self.sum = self.sum + v;
    }
    #[inline(always)]
    fn passed(&self) -> Mask {
        std::array::from_fn(|i| {
            self.pos.0[i] > 0.0 && self.nonneg.0[i] >= 0.0 && self.sum.0[i].is_finite()
        })
    }
}

/// A `DVec3` per direction, with glam's arithmetic in glam's order.
#[derive(Clone, Copy)]
struct V3 {
    x: F,
    y: F,
    z: F,
}

impl V3 {
    /// `(x·x + y·y) + z·z`, glam's `dot`.
    #[inline(always)]
    fn dot(self, o: V3) -> F {
        self.x * o.x + self.y * o.y + self.z * o.z
    }
    /// glam's `cross`.
    #[inline(always)]
    fn cross(self, o: V3) -> V3 {
        V3 {
            x: self.y * o.z - o.y * self.z,
            y: self.z * o.x - o.z * self.x,
            z: self.x * o.y - o.x * self.y,
        }
    }
    /// `self − (self·l) l`, the part perpendicular to the unit vector l (glam's order).
    #[inline(always)]
    fn perp(self, l: V3) -> V3 {
        let s = self.dot(l);
        V3 {
            x: self.x - s * l.x,
            y: self.y - s * l.y,
            z: self.z - s * l.z,
        }
    }
    #[inline(always)]
    fn scale(self, s: F) -> V3 {
        V3 {
            x: self.x * s,
            y: self.y * s,
            z: self.z * s,
        }
    }
}

/// One row of the shadow matrix per direction: `(x, y, z)` the eye-space part, `w` the constant.
#[derive(Clone, Copy)]
struct Row {
    v: V3,
    w: F,
}

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
    /// `(w, h, d)` of the corners at d = near, far as `ViewFrustum::corners` forms them (the clip
    /// check's points).
    clip: [(f64, f64, f64); 2],
    /// The same for the measurement's corners (`Prepared`'s), and whether they are the same.
    meas: [(f64, f64, f64); 2],
    same: bool,
    /// tan θ of the measurement.
    tan: f64,
    /// A bound on every light-space coordinate of the corners, whatever the direction: their
    /// largest eye-space length, with room for the rounding of the rotation.
    extent: f64,
}

impl LaneSweep {
    /// `None` for rules whose n′ is not one of the lane forms (they run the scalar code).
    /// `fixed` is the rule's n′ when it does not depend on the direction (computed by the scalar
    /// rule, so validated and bit for bit the same); `meas_corners` are the measurement's.
    pub(crate) fn new(
        view: &ViewFrustum,
        rule: WarpRule,
        fixed: Option<NPrime>,
        meas_corners: &[DVec3; 8],
        tan: f64,
    ) -> Option<Self> {
        let rule = match rule {
            WarpRule::Uniform | WarpRule::Psm | WarpRule::LispsmFixed | WarpRule::Eta(_) => {
                LaneRule::Fixed(fixed?.recip())
            }
            WarpRule::Lispsm => LaneRule::SinScaled(view.n_prime_lispsm()),
            WarpRule::LispsmReference => LaneRule::Reference(view.near()),
            _ => return None,
        };
        let t = view.tan_half_fov();
        let clip = [view.near(), view.far()].map(|d| {
            let h = d * t;
            (h * view.aspect(), h, d)
        });
        // `Prepared`'s corners, (±ta d, ±tan d, −d) with ta = tan · aspect: they must have the
        // layout of `ViewFrustum::corners` (four sign patterns at two depths) for the shared
        // products.
        let meas = [meas_corners[2], meas_corners[6]].map(|c| (c.x, c.y, -c.z));
        let layout_ok = (0..2).all(|k| {
            let (w, h, d) = meas[k];
            let c = &meas_corners[4 * k..4 * k + 4];
            c[0] == DVec3::new(-w, -h, -d)
                && c[1] == DVec3::new(w, -h, -d)
                && c[2] == DVec3::new(w, h, -d)
                && c[3] == DVec3::new(-w, h, -d)
        });
        // The measurement's depths z = −p.z must be > 0 (`vertex_max`'s check, the same at
        // every direction).
        if !layout_ok || !meas.iter().all(|m| m.2 > 0.0) {
            return None;
        }
        Some(Self {
            rule,
            clip,
            meas,
            same: clip == meas,
            tan,
            extent: clip
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
        let (se, ce) = el;
        let sa = F(az.map(|a| a.0));
        let ca = F(az.map(|a| a.1));
        // The sweep's `one`: l = −(ce sa, se, ce ca), `LightDir::new`: l / |l| (|l| ≈ 1, so
        // finite and far from the scaled path's range).
        let l = V3 {
            x: -(ce * sa),
            y: -F::splat(se),
            z: -(ce * ca),
        };
        let len = l.dot(l).sqrt();
        let mut checks = Checks::new();
        checks.finite(l.x + l.y + l.z);
        checks.positive(len - 1e-300);
        let l = V3 {
            x: l.x / len,
            y: l.y / len,
            z: l.z / len,
        };
        // `light_space_unit(l, −Z)`.
        let y = V3 {
            x: -l.x,
            y: -l.y,
            z: -l.z,
        };
        let a = V3 {
            x: F::splat(0.0),
            y: F::splat(0.0),
            z: F::splat(-1.0),
        };
        let ad = a.dot(y);
        let z = V3 {
            x: 0.0 - ad * y.x,
            y: 0.0 - ad * y.y,
            z: -1.0 - ad * y.z,
        };
        let zl = z.dot(z).sqrt();
        checks.non_negative(zl - PARALLEL_TOLERANCE);
        let z = z.scale(1.0 / zl);
        let x = y.cross(z);
        let x = x.scale(1.0 / x.dot(x).sqrt());
        let z = x.cross(y);
        // `FrustumInLight::in_light_space`: the corners' light coordinates from shared products.
        let (qn, qf) = (
            light_corners(&x, &y, &z, self.clip[0]),
            light_corners(&x, &y, &z, self.clip[1]),
        );
        let q = [qn[0], qn[1], qn[2], qn[3], qf[0], qf[1], qf[2], qf[3]];
        let mut z0 = F::splat(f64::INFINITY);
        let mut z1 = F::splat(f64::NEG_INFINITY);
        for c in &q {
            z0 = z0.min(c.2);
            z1 = z1.max(c.2);
        }
        let delta = z1 - z0;
        // sin γ = √(l.x² + l.y²), at most 1 (`f64::min`: the value is never NaN).
        let sin_g = (l.x * l.x + l.y * l.y).sqrt().min(F::splat(1.0));
        // The rule's 1/n′ (0 for the orthographic map), as `rule_n_prime` + `fit_frustum`.
        let rho = match self.rule {
            LaneRule::Fixed(rho) => F::splat(rho),
            LaneRule::SinScaled(nl) => {
                let v = nl / sin_g;
                let finite = and(
                    sin_g.test(|s| s > 0.0),
                    v.test(|v| v.is_finite() && v > 0.0),
                );
                F::select(finite, 1.0 / v, F::splat(0.0))
            }
            LaneRule::Reference(n) => {
                let xr = delta * sin_g / n;
                let v = delta * ((1.0 + xr).sqrt() + 1.0) / xr;
                let finite = and(xr.test(|s| s > 0.0), v.test(|v| v.is_finite() && v > 0.0));
                F::select(finite, 1.0 / v, F::splat(0.0))
            }
        };
        // `fit_frustum`: u = x/w, v = y/w ranges (w = 1 exactly when rho = 0), the extent.
        let mut u0 = F::splat(f64::INFINITY);
        let mut u1 = F::splat(f64::NEG_INFINITY);
        let mut v0 = u0;
        let mut v1 = u1;
        for &(qx, qy, qz) in &q {
            let iw = 1.0 / (1.0 + rho * (qz - z0));
            let (u, v) = (qx * iw, qy * iw);
            u0 = u0.min(u);
            u1 = u1.max(u);
            v0 = v0.min(v);
            v1 = v1.max(v);
        }
        // `warp_matrix`.
        // `warp_matrix` scales its two degeneracy tests by the corners' largest light-space
        // coordinate, `extent`; the lanes use `self.extent`, a bound on it the same for every
        // direction. `delta > 1e−12 · bound` implies the scalar `delta > 1e−12 · extent`, and
        // `0.5 (v1 − v0) > 1e−9 · bound` that the scalar's `max` picks 0.5 (v1 − v0) as v_h: a
        // lane where either fails goes to the scalar code.
        let tiny = 1e-12 * self.extent;
        checks.positive(delta - tiny);
        let u_h = 0.5 * (u1 - u0);
        let u_m = 0.5 * (u1 + u0);
        checks.positive(u_h - tiny);
        let v_h = 0.5 * (v1 - v0);
        checks.positive(v_h - 1e-9 * self.extent);
        let v_m = 0.5 * (v1 + v0);
        let aw = 1.0 - rho * z0;
        let kz = 2.0 / delta + rho;
        let um_rho = u_m * rho;
        let vm_rho = v_m * rho;
        let rows = [
            Row {
                v: V3 {
                    x: (x.x - um_rho * z.x) / u_h,
                    y: (x.y - um_rho * z.y) / u_h,
                    z: (x.z - um_rho * z.z) / u_h,
                },
                w: -u_m * aw / u_h,
            },
            Row {
                v: z.scale(kz),
                w: -1.0 - kz * z0,
            },
            Row {
                v: V3 {
                    x: (vm_rho * z.x - y.x) / v_h,
                    y: (vm_rho * z.y - y.y) / v_h,
                    z: (vm_rho * z.z - y.z) / v_h,
                },
                w: v_m * aw / v_h,
            },
            Row {
                v: z.scale(rho),
                w: aw,
            },
        ];
        for r in &rows {
            checks.finite(((r.v.x + r.v.y) + r.v.z) + r.w);
        }
        // `clip_ok_at_corners` and `vertex_max` (light direction `−ls.y` = l), corner by corner;
        // `M (c, 1)` once for both when their corners are the same points.
        let (g0, g1, g3) = (rows[0].v, rows[1].v, rows[3].v);
        let ca = g0.cross(g1).dot(l);
        let cb = g0.cross(g3).dot(l);
        let cc = g1.cross(g3).dot(l);
        let (g1p, g3p) = (g1.perp(l), g3.perp(l));
        // The `[0, 1]`-depth form's depth row, `(M₂ + M₃)/2` as `ShadowMatrix::with_clip_depth`
        // forms it, checked as `clip_ok_at_corners` checks it.
        let half = F::splat(0.5);
        let (r2, r3) = (&rows[2], &rows[3]);
        let row01 = Row {
            v: V3 {
                x: (r2.v.x + r3.v.x) * half,
                y: (r2.v.y + r3.v.y) * half,
                z: (r2.v.z + r3.v.z) * half,
            },
            w: (r2.w + r3.w) * half,
        };
        let mut mx2 = F::splat(0.0);
        let mut mz2 = F::splat(0.0);
        for k in 0..2 {
            let hc = homogeneous(&rows, self.clip[k]);
            let z01 = row_at(&row01, self.clip[k]);
            let hm_own;
            let hm = if self.same {
                &hc
            } else {
                hm_own = homogeneous(&rows, self.meas[k]);
                &hm_own
            };
            // z = −p.z, the depth of the measurement's corners (> 0: checked by `new`).
            let zd = self.meas[k].2;
            for j in 0..4 {
                let [hx, hy, hz, hw] = hc[j];
                checks.finite(((hx + hy) + hz) + hw);
                let sw = SLACK * hw;
                checks.non_negative(hw - 0.5);
                checks.non_negative(sw - hx.abs().max(hy.abs()).max(hz.abs()));
                let s01 = hw * HALF_SLACK;
                checks.non_negative(z01[j] + s01);
                checks.non_negative((hw + s01) - z01[j]);
                let [hx, hy, _, hw] = hm[j];
                let d = hw * (hw * ca - hy * cb + hx * cc);
                let d2 = d * d;
                let tx = hw * g1p.x - hy * g3p.x;
                let ty = hw * g1p.y - hy * g3p.y;
                let tz = hw * g1p.z - hy * g3p.z;
                let gtp2 = tx * tx + ty * ty + tz * tz;
                let w2 = hw * hw;
                let w4 = w2 * w2;
                let inv = 1.0 / (d2 * gtp2 * zd * zd);
                checks.positive(hw);
                checks.positive(gtp2);
                checks.finite(inv);
                mx2 = mx2.max(w4 * gtp2 * gtp2 * inv);
                mz2 = mz2.max(w4 * d2 * inv);
            }
        }
        // `finish`, and the scheme's sum over its one partition (0 + S̄ = S̄).
        let t2 = self.tan * self.tan;
        let mx = (mx2 / t2).sqrt();
        let mz = (mz2 / t2).sqrt();
        checks.positive(mx);
        checks.positive(mz);
        ((0.0 + mx * mz).0, checks.passed())
    }
}

/// The light-space coordinates `(x·c, y·c, z·c)` of the four corners `(±w, ±h, −d)` of one depth
/// (`ViewFrustum::corners` order), from the products shared by the four corners, as
/// `FrustumInLight::in_light_space` computes them.
#[inline(always)]
fn light_corners(x: &V3, y: &V3, z: &V3, (w, h, d): (f64, f64, f64)) -> [(F, F, F); 4] {
    let px = (x.x * w, y.x * w, z.x * w);
    let py = (x.y * h, y.y * h, z.y * h);
    let nd = -d;
    let pz = (x.z * nd, y.z * nd, z.z * nd);
    [
        (
            (-px.0 - py.0) + pz.0,
            (-px.1 - py.1) + pz.1,
            (-px.2 - py.2) + pz.2,
        ),
        (
            (px.0 - py.0) + pz.0,
            (px.1 - py.1) + pz.1,
            (px.2 - py.2) + pz.2,
        ),
        (
            (px.0 + py.0) + pz.0,
            (px.1 + py.1) + pz.1,
            (px.2 + py.2) + pz.2,
        ),
        (
            (-px.0 + py.0) + pz.0,
            (-px.1 + py.1) + pz.1,
            (-px.2 + py.2) + pz.2,
        ),
    ]
}

/// The clip check's slack (`clip_ok_at_corners`).
const SLACK: f64 = 1.0 + crate::numeric::CLIP_SLACK;
/// The `[0, 1]`-depth check's slack, half the clip volume's (`in_unit_depth`).
const HALF_SLACK: f64 = 0.5 * crate::numeric::CLIP_SLACK;

/// One row of `M` at the four corners `(±w, ±h, −d)` of one depth, in glam's order
/// `((M₀ x + M₁ y) + M₂ z) + M₃` with the products shared up to exact sign changes.
#[inline(always)]
fn row_at(row: &Row, (w, h, d): (f64, f64, f64)) -> [F; 4] {
    let a = row.v.x * w;
    let b = row.v.y * h;
    let c = row.v.z * -d;
    [
        ((-a - b) + c) + row.w,
        ((a - b) + c) + row.w,
        ((a + b) + c) + row.w,
        ((-a + b) + c) + row.w,
    ]
}

/// `M (c, 1)` at the four corners `(±w, ±h, −d)` of one depth in `ViewFrustum::corners` order,
/// from the products `M₀ w`, `M₁ h`, `M₂ (−d)` shared by the four corners (sign changes are
/// exact): per row `((±M₀ w ± M₁ h) + M₂ (−d)) + M₃`, bit for bit `vertex_max`'s
/// `((r.x p.x + r.y p.y) + r.z p.z) + r.w` and glam's `M · (c, 1)`.
#[inline(always)]
fn homogeneous(rows: &[Row; 4], corner: (f64, f64, f64)) -> [[F; 4]; 4] {
    let at = |row: &Row| row_at(row, corner);
    let r = [at(&rows[0]), at(&rows[1]), at(&rows[2]), at(&rows[3])];
    std::array::from_fn(|j| [r[0][j], r[1][j], r[2][j], r[3][j]])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scheme::sweep::light_dir_from_angles;
    use crate::scheme::{scheme, Partition, Prepared};

    /// The lanes take ordinary directions themselves (the bit-for-bit tests in tests/sweep.rs
    /// would also pass if every lane went to the scalar code) and send the light exactly along the
    /// view axis (the light-space fallback) to the scalar code.
    #[test]
    fn lanes_take_ordinary_directions_and_refuse_the_parallel_one() {
        let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians()).unwrap();
        let prep = Prepared::new(&view);
        let lanes = LaneSweep::new(&view, WarpRule::Lispsm, None, &prep.corners, prep.tan).unwrap();
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
        assert!(LaneSweep::new(&view, WarpRule::Minimax, None, &prep.corners, prep.tan).is_none());
        assert!(
            LaneSweep::new(&view, WarpRule::LispsmFixed, None, &prep.corners, prep.tan).is_none()
        );
    }
}
