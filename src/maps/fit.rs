//! The perspective warp in light space (Lloyd 2006 §4, Fig 3) fitted around a point set, and the
//! view frustum (or a body) in light space that the rules of [`crate::maps::warp`](mod@crate::maps::warp) read.
//!
//! # The construction
//!
//! In light space ([`LightSpace`]: x along s, y toward the light, z the warp axis) let the points
//! span `z ∈ [z₀, z₀ + Δ]`. The warping frustum's centre of projection `c` lies on the warp axis
//! through the eye, at `z = z₀ − n′`: n′ is the distance from `c` to the plane where the warping
//! frustum starts (Lloyd 2006 Fig 3; in the light-overhead case `z₀ = n` and this is Lloyd's n′
//! exactly; for a tilted light it is Barroso & Celes' n′, their Eq 10, and the reference LiSPSM
//! code's `C = C_start + n·ẑ`). With `ρ = 1/n′` (0 for [`NPrime::UNWARPED`]) and
//! `δ = z − z₀ ∈ [0, Δ]`, the homogeneous map is, in light space,
//!
//! ```text
//! w   = 1 + ρ δ                                  (distance from c over n′)
//! x_c = (x − u_m w) / u_h                         s: u = x/w fitted to [−1, 1]
//! y_c = −1 + 2 δ/Δ + ρ δ                          t: δ = 0 → −1, δ = Δ → +1
//! z_c = −(y − v_m w) / v_h                        depth: v = y/w fitted to [−1, 1], −1 nearest the light
//! ```
//!
//! where `u_m ± u_h` and `v_m ± v_h` are the ranges of `x/w` and `y/w` over the points. After the
//! divide, `y_c/w = −1 + 2 (δ/Δ) (n′ + Δ)/(n′ + δ)`: Lloyd's t(z) (his Eq 8's parameterisation,
//! OpenGL's perspective depth along the warp axis). The form in ρ is exact for every n′ and tends,
//! entry by entry, to the orthographic fit as n′ → ∞ (ρ → 0), so a rule whose n′ grows without
//! bound as the light turns parallel to the view degrades continuously to the uniform map, with a
//! matrix whose entries stay of the size of the frustum's extent (no `1/n′ · n′` cancellation).
//!
//! s is the tight fit of `x/w` with the centre of projection on the eye's light-space x, as the
//! LiSPSM reference code (`C_start = (e.x, e.y, z_max)`) and Filament (`ShadowMap::applyLISPSM`,
//! `p = {lsCameraPosition.x, n − nopt, 0}`) place it; TSM's q on the centre line l is the same
//! point (see the trapezoidal builder). OGRE (`LiSPSMShadowCameraSetup::calculateLiSPSM`) puts it
//! on the near camera point's light-space x and y instead, which [`WarpRule::Ogre`](crate::maps::WarpRule::Ogre) reproduces.

use crate::error::{fmt_num, Error, Result};
use crate::frustum::{LightDir, NPrime, ViewFrustum};
use crate::maps::lightspace::{light_space_unit, LightSpace};
use crate::maps::matrix::{reversed, zero_to_one, ShadowMatrix};
use crate::numeric::lane::{Lane, V3};
use crate::numeric::{fmax, fmin, CLIP_SLACK};
use glam::{DMat4, DVec3, DVec4};

/// The view frustum's corners in light space with what the rules need: no allocation. With
/// `N ≠ 8`, any convex body's vertices ([`FrustumInLight::from_points`], the frame API's focus
/// body), padded to `N` with copies of the first (a repeated vertex changes no minimum or maximum).
#[derive(Debug, Clone, Copy)]
pub(crate) struct FrustumInLight<const N: usize = 8> {
    pub ls: LightSpace,
    /// The eight corners (or the body's vertices), eye space.
    pub corners: [DVec3; N],
    /// Light-space coordinates of the eight corners.
    pub q: [DVec3; N],
    /// Eye depth −p.z of each corner.
    pub depth: [f64; N],
    /// Smallest light-space z of the corners.
    pub z0: f64,
    /// Extent of the corners along the warp axis.
    pub delta: f64,
    /// sin γ between light and view direction.
    pub sin_gamma: f64,
}

impl FrustumInLight {
    // Always inlined (docs/performance.md, "Code-generation notes").
    #[inline(always)]
    pub(crate) fn new(view: &ViewFrustum, light_dir: DVec3) -> Result<Self> {
        Ok(Self::from_dir(view, LightDir::new(light_dir)?))
    }

    /// [`FrustumInLight::new`] for a validated light direction.
    #[inline(always)]
    pub(crate) fn from_dir(view: &ViewFrustum, l: LightDir) -> Self {
        // The validated −Z axis is −Z exactly.
        Self::in_light_space(view, l, light_space_unit(l, DVec3::NEG_Z))
    }

    /// The builders' result for `view`'s whole depth range, fitted in this light space.
    #[inline]
    pub(crate) fn shadow_matrix(
        &self,
        view: &ViewFrustum,
        matrix: DMat4,
        n_prime: NPrime,
    ) -> ShadowMatrix {
        ShadowMatrix::new(matrix, self.ls.light(), n_prime, view.near(), view.far())
    }

    /// As [`FrustumInLight::from_dir`] with `ls = light_space_unit(l, −Z)` already computed
    /// (shared by a light's cascades).
    #[inline(always)]
    pub(crate) fn in_light_space(view: &ViewFrustum, l: LightDir, ls: LightSpace) -> Self {
        let corners = view.corners();
        // The corners are (±w, ±h, −d) at d = near, far; their light-space coordinates
        // `e·c = (e.x c.x + e.y c.y) + e.z c.z` for e = x, y, z share the products e.x w, e.y h,
        // e.z (−d) up to sign (negation is exact), so computing the products once per depth gives
        // the dot products of `LightSpace::to_light` bit for bit, in a third of the multiplications.
        let (x, y, z) = (V3::from(ls.x), V3::from(ls.y), V3::from(ls.z));
        let mut q = [DVec3::ZERO; 8];
        let mut depth = [0.0; 8];
        let (mut z0, mut z1) = (f64::INFINITY, f64::NEG_INFINITY);
        for (k, slice) in slices(&corners).into_iter().enumerate() {
            let d = slice.2;
            for (j, qj) in light_corners(x, y, z, slice).into_iter().enumerate() {
                q[4 * k + j] = qj.into();
                depth[4 * k + j] = d;
                z0 = fmin(z0, qj.z);
                z1 = fmax(z1, qj.z);
            }
        }
        // sin γ = |l × (0, 0, −1)| = √(l.x² + l.y²) for the unit light direction l: accurate near 0.
        Self {
            ls,
            corners,
            q,
            depth,
            z0,
            delta: z1 - z0,
            sin_gamma: sin_gamma(V3::from(l.as_dvec3())),
        }
    }
}

impl<const N: usize> FrustumInLight<N> {
    /// A convex body's vertices `points` (eye space, `1 ≤ len ≤ N`, finite, in front of the eye)
    /// in the light space `ls` of the unit light direction `l`, padded to `N` with copies of
    /// `points[0]`; `None` when `points` is empty or longer than `N`. sin γ is the view
    /// direction's, as for the frustum: the warp axis is the view direction's whatever the body.
    pub(crate) fn from_points(points: &[DVec3], l: DVec3, ls: LightSpace) -> Option<Self> {
        let mut fl = Self::blank(ls);
        fl.set_points(points, l, ls).then_some(fl)
    }

    /// A value for [`FrustumInLight::set_points`] to fill (every number 0).
    pub(crate) fn blank(ls: LightSpace) -> Self {
        Self {
            ls,
            corners: [DVec3::ZERO; N],
            q: [DVec3::ZERO; N],
            depth: [0.0; N],
            z0: 0.0,
            delta: 0.0,
            sin_gamma: 0.0,
        }
    }

    /// [`FrustumInLight::from_points`] written into `self` (a 2 KB value for N = 32, which a
    /// caller may keep in place instead of receiving it moved); `false`, and `self` unchanged,
    /// where that gives `None`.
    pub(crate) fn set_points(&mut self, points: &[DVec3], l: DVec3, ls: LightSpace) -> bool {
        if points.is_empty() || points.len() > N {
            return false;
        }
        self.corners = [points[0]; N];
        self.corners[..points.len()].copy_from_slice(points);
        let (mut z0, mut z1) = (f64::INFINITY, f64::NEG_INFINITY);
        for i in 0..N {
            self.q[i] = ls.to_light(self.corners[i]);
            self.depth[i] = -self.corners[i].z;
            z0 = fmin(z0, self.q[i].z);
            z1 = fmax(z1, self.q[i].z);
        }
        self.ls = ls;
        self.z0 = z0;
        self.delta = z1 - z0;
        self.sin_gamma = sin_gamma(V3::from(l));
        true
    }
}

/// `(w, h, d)` of a view frustum's four corners `(±w, ±h, −d)` at the depths near and far, from
/// its corners in [`ViewFrustum::corners`] order (corner 2 of each depth is `(+w, +h, −d)`).
#[inline(always)]
pub(crate) fn slices(corners: &[DVec3; 8]) -> [(f64, f64, f64); 2] {
    let (a, b) = (corners[2], corners[6]);
    [(a.x, a.y, -a.z), (b.x, b.y, -b.z)]
}

/// sin γ = |l × (0, 0, −1)| = √(l.x² + l.y²) for the unit light direction l (accurate near 0),
/// at most 1.
#[inline(always)]
pub(crate) fn sin_gamma<T: Lane>(l: V3<T>) -> T {
    (l.x * l.x + l.y * l.y).sqrt().min(T::splat(1.0))
}

/// The light-space coordinates `(x·c, y·c, z·c)` of the four corners `(±w, ±h, −d)` of one depth
/// of a view frustum, in `ViewFrustum::corners` order: `e·c = (e.x c.x + e.y c.y) + e.z c.z` for
/// e = x, y, z share the products e.x w, e.y h, e.z (−d) up to sign (negation is exact), so
/// computing them once per depth gives [`LightSpace::to_light`]'s dot products bit for bit, in a
/// third of the multiplications.
#[inline(always)]
pub(crate) fn light_corners<T: Lane>(
    x: V3<T>,
    y: V3<T>,
    z: V3<T>,
    (w, h, d): (f64, f64, f64),
) -> [V3<T>; 4] {
    let (w, h, nd) = (T::splat(w), T::splat(h), T::splat(-d));
    let px = V3::new(x.x * w, y.x * w, z.x * w);
    let py = V3::new(x.y * h, y.y * h, z.y * h);
    let pz = V3::new(x.z * nd, y.z * nd, z.z * nd);
    [
        (-px - py) + pz,
        (px - py) + pz,
        (px + py) + pz,
        (-px + py) + pz,
    ]
}

/// The perspective warp of the module docs along `ls.z` with parameter `n_prime`, fitted tightly
/// around `points` (eye space); orthographic for [`NPrime::UNWARPED`]. s runs along `ls.x`, t along
/// `ls.z` (t = 0 at the points' smallest z), depth along `−ls.y`. Every point maps into the clip
/// volume `[−1, 1]³` with `w ≥ 1`; the extreme points land on its faces.
///
/// When the points' range of `y/w` (their depth range) is zero, it is widened to 10⁻⁹ of their
/// largest extent so that the matrix stays invertible; a zero range of `x/w` or of `z` cannot be
/// mapped and is an error.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `points` when empty or not finite; [`Error::Degenerate`] when the points have
/// no extent along `ls.x` or `ls.z`, or when rounding would put a point outside the clip volume
/// by more than 10⁻⁶ (depth ratios far beyond 10⁶ with a strong warp: the result is checked, never
/// returned wrong).
///
/// ```
/// # use shadow_aliasing::maps::{fit_warp, light_space};
/// # use shadow_aliasing::{NPrime, ViewFrustum};
/// # use glam::{DVec3, DVec4};
/// let view = ViewFrustum::new(1.0, 20.0, 0.5)?;
/// let ls = light_space(DVec3::new(0.0, -1.0, 0.0), DVec3::NEG_Z)?;
/// let m = fit_warp(&view.corners(), &ls, NPrime::finite(view.n_prime_lispsm())?)?;
/// for c in view.corners() {
///     let h = m * DVec4::new(c.x, c.y, c.z, 1.0);
///     assert!(h.w > 0.0 && (h.truncate() / h.w).abs().max_element() <= 1.0 + 1e-12);
/// }
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn fit_warp(points: &[DVec3], ls: &LightSpace, n_prime: NPrime) -> Result<DMat4> {
    fit_points(points, ls, n_prime).map_err(Error::from)
}

/// [`fit_warp`] with its failure as a [`FitFailure`], whose message is written only if it is
/// returned to the caller (a fit that is tried and discarded formats nothing).
pub(crate) fn fit_points(
    points: &[DVec3],
    ls: &LightSpace,
    n_prime: NPrime,
) -> std::result::Result<DMat4, FitFailure> {
    if points.is_empty() {
        return Err(FitFailure::NoPoints);
    }
    let rho = n_prime.recip();
    let (mut z0, mut z1) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut extent = 0.0f64;
    for p in points {
        if !p.is_finite() {
            return Err(FitFailure::NotFinitePoint(*p));
        }
        // Finite values: `fmin`/`fmax` are `f64::min`/`max` here.
        let z = ls.z.dot(*p);
        z0 = fmin(z0, z);
        z1 = fmax(z1, z);
        let a = p.abs();
        extent = fmax(extent, fmax(fmax(a.x, a.y), a.z));
    }
    let delta = z1 - z0;
    let mut range = Ranges::new();
    if rho == 0.0 {
        // w = 1 exactly.
        for p in points {
            let q = ls.to_light(*p);
            range.add(q.x, q.y);
        }
    } else {
        // One division per point, as `fit_frustum` (within an ulp of x/w and y/w).
        for p in points {
            let q = ls.to_light(*p);
            let iw = 1.0 / (1.0 + rho * (q.z - z0));
            range.add(q.x * iw, q.y * iw);
        }
    }
    let m = warp_matrix(ls, z0, delta, rho, &range, extent)?;
    verify_clip(&m, points.iter())?;
    Ok(m)
}

/// Checks what the construction guarantees in exact arithmetic: every point has w ≥ 1 and clip
/// coordinates in [−1, 1]. With rounding the extreme points land within about 10⁻⁹ of the faces
/// for f/n up to 10⁶; a point at w < ½ or more than 10⁻⁶ outside the clip volume means the
/// frustum's depth ratio is beyond what f64 can warp (for the LiSPSM warp the error of w at the far
/// end is about √(f/n) · 10⁻¹⁶, for PSM's n′ = n about (f/n) · 10⁻¹⁶), and the matrix is refused.
/// The depth is checked in every [`crate::maps::ClipDepth`] form (each form's depth row rounds
/// on its own).
pub(crate) fn verify_clip<'a>(
    m: &DMat4,
    points: impl Iterator<Item = &'a DVec3>,
) -> std::result::Result<(), FitFailure> {
    let (m01, mrev) = (zero_to_one(m), reversed(m));
    for p in points {
        let h = *m * p.extend(1.0);
        let ok = in_clip(h.to_array())
            && in_unit_depth((m01 * p.extend(1.0)).z, h.w)
            && in_unit_depth((mrev * p.extend(1.0)).z, h.w);
        if !ok {
            return Err(FitFailure::OutsideClip(h));
        }
    }
    Ok(())
}

/// Why a warp could not be fitted, as a value that costs nothing to make: a candidate fit that
/// fails and is discarded for another (the face partitions' two axes) must not allocate, so the
/// message is written only when the failure becomes the returned [`Error`] (`Error::from`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum FitFailure {
    /// No points to fit.
    NoPoints,
    /// A point with a non-finite coordinate.
    NotFinitePoint(DVec3),
    /// The points have no extent along (`across: false`) or across the warp axis, or one
    /// below 10⁻¹² of their largest coordinate (`scale`), which f64 cannot resolve.
    NoExtent {
        /// Across the axis (along s, after the warp) rather than along it.
        across: bool,
        /// The extent found.
        extent: f64,
        /// The points' largest coordinate magnitude.
        scale: f64,
    },
    /// The matrix has a non-finite entry.
    NotFiniteWarp,
    /// A point maps outside the clip volume (homogeneous clip coordinates, OpenGL depth).
    OutsideClip(DVec4),
}

impl From<FitFailure> for Error {
    #[cold]
    #[inline(never)]
    fn from(f: FitFailure) -> Error {
        match f {
            FitFailure::NoPoints => Error::invalid("points", "must not be empty"),
            FitFailure::NotFinitePoint(p) => {
                Error::invalid("points", format!("must be finite (got {p})"))
            }
            FitFailure::NoExtent {
                across,
                extent,
                scale,
            } => {
                let dir = if across { "across" } else { "along" };
                if extent > 0.0 {
                    Error::Degenerate(format!(
                        "the points' extent {dir} the warp axis{} ({}) is below 10⁻¹² of their \
                         largest coordinate ({}), finer than f64 resolves: the points span too \
                         many orders of magnitude (a depth ratio far/near too large for this \
                         warp, or one bound far larger than the rest); reduce far/near, use \
                         z-partitions or a weaker warp, or tighten the largest bound",
                        if across { " after the warp" } else { "" },
                        fmt_num(extent),
                        fmt_num(scale)
                    ))
                } else {
                    Error::Degenerate(format!(
                        "the points have no extent {dir} the warp axis (extent {})",
                        fmt_num(extent)
                    ))
                }
            }
            FitFailure::NotFiniteWarp => {
                Error::Degenerate("the fitted warp is not finite for these points".into())
            }
            FitFailure::OutsideClip(h) => Error::Degenerate(format!(
                "the map cannot be represented in f64 for this frustum (a point maps to {h}): \
                 reduce far/near or use z-partitions"
            )),
        }
    }
}

/// Running min/max of u = x/w and v = y/w.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Ranges<T = f64> {
    pub u: (T, T),
    pub v: (T, T),
}

impl<T: Lane> Ranges<T> {
    #[inline(always)]
    pub(crate) fn new() -> Self {
        let (lo, hi) = (T::splat(f64::INFINITY), T::splat(f64::NEG_INFINITY));
        Self {
            u: (lo, hi),
            v: (lo, hi),
        }
    }
    #[inline(always)]
    pub(crate) fn add(&mut self, u: T, v: T) {
        self.u = (self.u.0.min(u), self.u.1.max(u));
        self.v = (self.v.0.min(v), self.v.1.max(v));
    }

    /// The ranges of `x/w`, `y/w` over light-space points `q` for the warp `w = 1 + ρ (z − z₀)`:
    /// one division per point (within an ulp of x/w and y/w); where ρ is 0 in every lane, `w = 1`
    /// exactly and the points' x, y are taken as they are (the same values).
    #[inline(always)]
    pub(crate) fn of_warped(q: impl IntoIterator<Item = V3<T>>, z0: T, rho: T) -> Self {
        let mut r = Self::new();
        if rho.all_zero() {
            for q in q {
                r.add(q.x, q.y);
            }
        } else {
            let one = T::splat(1.0);
            for q in q {
                let iw = one / (one + rho * (q.z - z0));
                r.add(q.x * iw, q.y * iw);
            }
        }
        r
    }

    /// `(u_h, u_m, v_h, v_m)`: the half-widths and middles of the ranges, `½ (hi − lo)`,
    /// `½ (hi + lo)` (v_h before [`warp_matrix`]'s floor).
    #[inline(always)]
    pub(crate) fn halves(&self) -> (T, T, T, T) {
        let half = T::splat(0.5);
        (
            half * (self.u.1 - self.u.0),
            half * (self.u.1 + self.u.0),
            half * (self.v.1 - self.v.0),
            half * (self.v.1 + self.v.0),
        )
    }
}

/// One row of a shadow matrix: its eye-space part and its constant.
pub(crate) type Row<T> = (V3<T>, T);

/// The rows of the module docs' warp matrix for the frame `(x, y, z)`, composed with the rotation
/// (rows x, y, z of eye space) directly: `row · (x·p, y·p, z·p, 1) = (row.x x + row.y y + row.z z)
/// · p + row.w`. `w = ρ z + a` with `a = 1 − ρ z₀`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn warp_rows<T: Lane>(
    (x, y, z): (V3<T>, V3<T>, V3<T>),
    z0: T,
    delta: T,
    rho: T,
    (u_h, u_m, v_h, v_m): (T, T, T, T),
) -> [Row<T>; 4] {
    let a = T::splat(1.0) - rho * z0;
    let k = T::splat(2.0) / delta + rho;
    let (um_rho, vm_rho) = (u_m * rho, v_m * rho);
    [
        ((x - z.scale(um_rho)).div(u_h), -u_m * a / u_h),
        (z.scale(k), T::splat(-1.0) - k * z0),
        ((z.scale(vm_rho) - y).div(v_h), v_m * a / v_h),
        (z.scale(rho), a),
    ]
}

/// Assembles the matrix of the module docs. `extent` is the points' largest coordinate magnitude
/// (scale for the degeneracy tests).
#[inline]
pub(crate) fn warp_matrix(
    ls: &LightSpace,
    z0: f64,
    delta: f64,
    rho: f64,
    r: &Ranges,
    extent: f64,
) -> std::result::Result<DMat4, FitFailure> {
    let tiny = 1e-12 * extent.max(f64::MIN_POSITIVE);
    if delta.is_nan() || delta <= tiny {
        return Err(FitFailure::NoExtent {
            across: false,
            extent: delta,
            scale: extent,
        });
    }
    let (u_h, u_m, v_h, v_m) = r.halves();
    if u_h.is_nan() || u_h <= tiny {
        return Err(FitFailure::NoExtent {
            across: true,
            extent: 2.0 * u_h,
            scale: extent,
        });
    }
    let v_h = v_h.max(1e-9 * extent.max(f64::MIN_POSITIVE));
    let frame = (V3::from(ls.x), V3::from(ls.y), V3::from(ls.z));
    let rows = warp_rows(frame, z0, delta, rho, (u_h, u_m, v_h, v_m));
    let [r0, r1, r2, r3] = rows;
    let row = |(v, w): Row<f64>| DVec3::from(v).extend(w);
    let (row0, row1, row2, row3) = (row(r0), row(r1), row(r2), row(r3));
    let m = DMat4::from_cols(row0, row1, row2, row3).transpose();
    if !m.is_finite() {
        return Err(FitFailure::NotFiniteWarp);
    }
    Ok(m)
}

/// [`fit_warp`] on the frustum already in light space.
#[inline]
pub(crate) fn fit_frustum(fl: &FrustumInLight, n_prime: NPrime) -> Result<DMat4> {
    let rho = n_prime.recip();
    let r = Ranges::of_warped(fl.q.iter().map(|&q| V3::from(q)), fl.z0, rho);
    let extent = fl.q.iter().fold(0.0f64, |m, q| {
        let a = q.abs();
        fmax(m, fmax(fmax(a.x, a.y), a.z))
    });
    let m = warp_matrix(&fl.ls, fl.z0, fl.delta, rho, &r, extent)?;
    if clip_ok_at_corners(&m, &fl.corners) {
        Ok(m)
    } else {
        // The generic check finds the same corner and reports it.
        verify_clip(&m, fl.corners.iter())?;
        Ok(m)
    }
}

/// [`verify_clip`]'s test at the eight corners of a view frustum (`ViewFrustum::corners`
/// order), bit for bit, through [`clip_at_slices`].
#[inline]
fn clip_ok_at_corners(m: &DMat4, corners: &[DVec3; 8]) -> bool {
    let row = |i: usize| {
        let r = m.row(i);
        (V3::from(r.truncate()), r.w)
    };
    let rows = [row(0), row(1), row(2), row(3)];
    clip_at_slices(&rows, &slices(corners)).1
}

/// `M (c, 1)` for the four corners `c = (±w, ±h, −d)` of one depth (`ViewFrustum::corners`
/// order), one row of M at a time: `((M₀ c.x + M₁ c.y) + M₂ c.z) + M₃` is glam's order, and the
/// products `M₀ w`, `M₁ h`, `M₂ (−d)` are shared by the four corners up to exact sign changes, so
/// the four values are glam's `M · (c, 1)` bit for bit from a quarter of the multiplications.
#[inline(always)]
pub(crate) fn row_at_slice<T: Lane>((v, w0): &Row<T>, (w, h, d): (f64, f64, f64)) -> [T; 4] {
    let a = v.x * T::splat(w);
    let b = v.y * T::splat(h);
    let c = v.z * T::splat(-d);
    [
        ((-a - b) + c) + *w0,
        ((a - b) + c) + *w0,
        ((a + b) + c) + *w0,
        ((-a + b) + c) + *w0,
    ]
}

/// [`verify_clip`]'s test (every clip-depth form) at the eight corners of two depths
/// `(w, h, d)` of a view frustum, and `M (c, 1)` at each (`[depth][corner][x, y, z, w]`), for
/// the rows of M: the scalar builders' check at `f64` and the sweep's at four directions.
#[inline(always)]
pub(crate) fn clip_at_slices<T: Lane>(
    rows: &[Row<T>; 4],
    slices: &[(f64, f64, f64); 2],
) -> ([[[T; 4]; 4]; 2], T::Mask) {
    // The `[0, 1]`-depth form's depth row, `(M₂ + M₃)/2` as `zero_to_one` forms it.
    let half = T::splat(0.5);
    let (r2, r3) = (&rows[2], &rows[3]);
    let row01 = ((r2.0 + r3.0).scale(half), (r2.1 + r3.1) * half);
    // The reversed form's, `(M₃ − M₂)/2` as `reversed` forms it.
    let rowrev = ((r3.0 - r2.0).scale(half), (r3.1 - r2.1) * half);
    // Plain loops, not `array::map`/`from_fn` closures (which do not always inline).
    let mut ok = T::all_set();
    let mut h = [[[T::splat(0.0); 4]; 4]; 2];
    for (hk, &slice) in h.iter_mut().zip(slices) {
        let r0 = row_at_slice(&rows[0], slice);
        let r1 = row_at_slice(&rows[1], slice);
        let r2 = row_at_slice(&rows[2], slice);
        let r3 = row_at_slice(&rows[3], slice);
        let z01 = row_at_slice(&row01, slice);
        let zrev = row_at_slice(&rowrev, slice);
        for j in 0..4 {
            let hj = [r0[j], r1[j], r2[j], r3[j]];
            let depths = T::and(in_unit_depth(z01[j], hj[3]), in_unit_depth(zrev[j], hj[3]));
            ok = T::and(ok, T::and(in_clip(hj), depths));
            hk[j] = hj;
        }
    }
    (h, ok)
}

/// `h` (OpenGL depth) inside the clip volume, within [`CLIP_SLACK`], with w ∈ [1/2, ∞) finite
/// (an infinite w would admit infinite x, y, z).
#[inline(always)]
fn in_clip<T: Lane>([x, y, z, w]: [T; 4]) -> T::Mask {
    let s = T::splat(1.0 + CLIP_SLACK) * w;
    let and = T::and;
    and(
        and(w.ge(T::splat(0.5)), w.lt(T::splat(f64::INFINITY))),
        and(x.abs().le(s), and(y.abs().le(s), z.abs().le(s))),
    )
}

/// The `[0, 1]`-depth form's z of the same point inside [0, w], within [`CLIP_SLACK`] of its
/// half-width w/2.
#[inline(always)]
fn in_unit_depth<T: Lane>(z01: T, w: T) -> T::Mask {
    let s = T::splat(0.5 * CLIP_SLACK) * w;
    T::and(z01.ge(-s), z01.le(w + s))
}

/// [`fit_frustum`] with the centre of projection on the light-space x and y of `fl.q[i]`
/// instead of the eye's: the map fitted around the corners seen from that point, composed
/// with the translation that puts it at the origin (OGRE's `C_start`, [`WarpRule::Ogre`]).
pub(crate) fn fit_frustum_from_corner(
    fl: &FrustumInLight,
    n_prime: NPrime,
    i: usize,
) -> Result<DMat4> {
    let (x0, y0) = (fl.q[i].x, fl.q[i].y);
    let offset = fl.ls.x * x0 + fl.ls.y * y0;
    let mut moved = *fl;
    for (q, c) in moved.q.iter_mut().zip(moved.corners.iter_mut()) {
        q.x -= x0;
        q.y -= y0;
        *c -= offset;
    }
    let m = fit_frustum(&moved, n_prime)? * DMat4::from_translation(-offset);
    verify_clip(&m, fl.corners.iter())?;
    Ok(m)
}

/// The warp of parameter `n_prime` fitted to a body in light space (`fl`, the frame API's focus
/// body B): s and t to the body's vertices, depth to the body's vertices and `depth_points`
/// together (casters that can shadow the body: they only extend the depth range). `centre` is the
/// index of the vertex whose light-space x and y carry the centre of projection (OGRE's and the
/// LiSPSM reference code's near camera point), or `None` for the eye's own light-space line. Every
/// vertex and depth point is checked to land in the clip volume, in both depth conventions.
///
/// # Errors
/// As [`fit_warp`].
pub(crate) fn fit_body<const N: usize>(
    fl: &FrustumInLight<N>,
    n_prime: NPrime,
    centre: Option<usize>,
    depth_points: &[DVec3],
) -> Result<DMat4> {
    let rho = n_prime.recip();
    let (x0, y0) = match centre {
        Some(i) => (fl.q[i].x, fl.q[i].y),
        None => (0.0, 0.0),
    };
    let mut r = Ranges::new();
    let mut extent = 0.0f64;
    for q in &fl.q {
        let iw = 1.0 / (1.0 + rho * (q.z - fl.z0));
        r.add((q.x - x0) * iw, (q.y - y0) * iw);
        let a = q.abs();
        extent = fmax(extent, fmax(fmax(a.x, a.y), a.z));
    }
    let mut depth = r;
    for p in depth_points {
        if !p.is_finite() {
            return Err(FitFailure::NotFinitePoint(*p).into());
        }
        let q = fl.ls.to_light(*p);
        let iw = 1.0 / (1.0 + rho * (q.z - fl.z0));
        depth.add((q.x - x0) * iw, (q.y - y0) * iw);
        let a = q.abs();
        extent = fmax(extent, fmax(fmax(a.x, a.y), a.z));
    }
    // Casters never widen s (or t: their z is not looked at): only the depth range grows.
    let r = Ranges { u: r.u, v: depth.v };
    let m = warp_matrix(&fl.ls, fl.z0, fl.delta, rho, &r, extent)?;
    let m = if centre.is_some() {
        m * DMat4::from_translation(-(fl.ls.x * x0 + fl.ls.y * y0))
    } else {
        m
    };
    verify_clip(&m, fl.corners.iter())?;
    Ok(m)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// The shared-product clip check at a frustum's eight corners is the plain point-by-point
        /// `verify_clip` (both clip-depth forms), accepting and refusing alike: fitted maps over
        /// views, lights and n′, and the same maps with one row scaled so that some corners leave
        /// the clip volume.
        #[test]
        fn clip_ok_at_corners_is_verify_clip(
            ln_n in -5.0f64..5.0,
            ln_alpha in 0.01f64..14.0,
            theta in 0.05f64..1.5,
            aspect in 0.3f64..3.0,
            el in -1.5f64..1.5,
            az in 0.0f64..std::f64::consts::TAU,
            ln_np in -3.0f64..6.0,
            row in 0usize..4,
            scale in prop::sample::select(vec![1.0, 1.0 + 2e-6, 0.999_999, 1.5, 0.4, -1.0]),
        ) {
            let n = ln_n.exp();
            let view = ViewFrustum::with_aspect(n, n * ln_alpha.exp(), theta, aspect).unwrap();
            let l = -DVec3::new(el.cos() * az.sin(), el.sin(), el.cos() * az.cos());
            let Ok(fl) = FrustumInLight::new(&view, l) else { return Ok(()) };
            let Ok(m) = fit_frustum(&fl, NPrime::finite(n * ln_np.exp()).unwrap()) else { return Ok(()) };
            let mut t = m.transpose();
            let r = t.col_mut(row);
            *r *= scale;
            let m = t.transpose();
            let corners = view.corners();
            prop_assert_eq!(
                clip_ok_at_corners(&m, &corners),
                verify_clip(&m, corners.iter()).is_ok()
            );
        }
    }
}
