//! The named rules that choose the warp parameter n′ ([`WarpRule`]), and the builders of the
//! whole view frustum's map with them ([`warp()`], [`n_prime_for`]). The warp itself, fitted
//! around a point set, is [`crate::maps::fit`]'s.

use crate::analytic::tsm::tsm_eta_finite;
use crate::error::{fmt_num, Error, Result};
use crate::frustum::{LightAngle, LightDir, NPrime, ViewFrustum};
use crate::maps::fit::{fit_frustum, fit_frustum_from_corner};
use crate::maps::lightspace::{light_space_unit, LightSpace};
use crate::maps::matrix::ShadowMatrix;
use crate::maps::minimax;
use crate::numeric::lane::Lane;
use glam::DVec3;

pub use crate::analytic::tilted::Falloff;
pub use crate::maps::fit::fit_warp;
// The fit's pieces, at the paths the crate's other modules use.
pub(crate) use crate::maps::fit::{
    clip_at_slices, light_corners, sin_gamma, slices, verify_clip, warp_matrix, warp_rows,
    FrustumInLight, Ranges,
};

/// How the warp parameter n′ is chosen. Each rule names its source; the engines' rules reproduce
/// the shipped code's arithmetic for a frustum-only focus body (no scene bound), so that their
/// matrices can be measured against the papers.
///
/// γ below is the angle between the light and the view direction folded into [0, π/2]; n and f the
/// view frustum's near and far depths; Δ the extent of the view frustum along the warp axis in
/// light space (the reference code's and Filament's `d`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum WarpRule {
    /// n′ = ∞: the orthographic map fitted tightly to the frustum.
    Uniform,
    /// Lloyd 2006 Eq 11: n′(η) = n(√α + 1 − η(α − 1))/(η + 1) for −1 ≤ η ≤ 0 (η = −1 is
    /// n′ = ∞) and n(√α + 1)/(η√α + 1) for 0 < η ≤ 1, α = f/n. η = 0 is LiSPSM, η = 1 PSM.
    Eta(f64),
    /// PSM's n′ = n (Lloyd 2006 §4.1). This is PSM exactly only with the light overhead; for
    /// other directions a perspective shadow map is not a one-point perspective in light space
    /// (Lloyd 2006 §4.4), and this rule is the light-space warp with PSM's parameter. It keeps
    /// n′ = n at every light direction, where Lloyd 2006 §4.4 has perspective shadow maps revert
    /// to the orthographic map with the light behind or in front of the viewer: there it only
    /// stretches the map along the view. A renderer that wants a warp which reverts uses
    /// [`WarpRule::Lispsm`].
    Psm,
    /// LiSPSM as its authors apply it to every light direction (Wimmer et al. 2004 §5; Lloyd 2006
    /// §4.1, §4.4, the rule behind Lloyd 2006 Fig 7's warped panel): n′ = (n + √(f n))/sin γ.
    /// With the light overhead (γ = π/2) it is the overhead optimum n′_LSPSM = n + √(f n); as the
    /// light turns parallel to the view n′ grows without bound, so the map tends continuously to
    /// the uniform map, which it is at γ = 0 (Lloyd 2006 §4.4: LiSPSM "reverts to" the
    /// orthographic map with the light behind or in front). It equals [`WarpRule::Uniform`]
    /// there, and z-partitions warped with it (ZP+W) have the S̄ of Lloyd 2006 Eq 20 behind and
    /// in front. Near those directions it is worse than the uniform map: with n = 1, f = 1000,
    /// θ = 30° its S̄ exceeds the uniform map's for γ below about 25° (up to 4.3 × at 12° above
    /// the view from behind; docs/builders.md, "Where the other rules are worse than no
    /// warping"), where n′ is still too short for a frustum seen almost end-on.
    /// [`WarpRule::Minimax`] is never worse than the uniform map.
    Lispsm,
    /// LiSPSM's light-overhead n′ = n + √(f n) held fixed for every light direction. It is LiSPSM
    /// only with the light overhead: behind or in front it keeps the full warp, which there only
    /// stretches the map along the view (f/n = 10, θ = 30°, light behind: S̄ 427 against the
    /// uniform map's 100; see docs/builders.md). Kept for analysis (Lloyd 2006 §4.3 compares
    /// fixed n′), not as a renderer's choice.
    LispsmFixed,
    /// Barroso & Celes' generalised n′ (their Eq 13, 15, 16 with the fall-off of Eq 17 or 18).
    Barroso(Falloff),
    /// Martin & Tan's 80 % rule (TSM §6.2): the n′ that maps the point `focus` beyond the near
    /// plane on the view axis to the 80 % line; n′ = ∞ when no finite centre of projection can.
    Tsm {
        /// Focus distance δ beyond the near plane, world units, `0 < focus ≤ f − n`.
        focus: f64,
    },
    /// The LiSPSM reference implementation (D. Scherzer, TU Vienna 2005, for Wimmer et al. 2004;
    /// `LispSM<REAL>::calcNoptGeneral` with `getNearCameraPointE` and `getZ0_ls`):
    /// n′ = Δ/(√(z₁/z₀) − 1) with z₀ = n, z₁ = n + Δ sin γ the eye depths at the near and far ends
    /// of the warp axis, computed as Δ(√(1 + x) + 1)/x, x = Δ sin γ/n; n′ = ∞ at γ = 0.
    LispsmReference,
    /// Filament's `ShadowMap::applyLISPSM` with its default hints (near 1, far 100 world units).
    ///
    /// Filament aligns the map with the view only while |cos γ| < 0.9997
    /// (`ShadowMap::computeLightRotation`); from there to the parallel light (γ ≤ 1.4037°) it keeps
    /// the light's own frame, whose up vector is the camera's right vector
    /// (`computeDirectionalShadowBounds`), so the warp axis, and the depth range d along it, run
    /// along the camera's x axis projected perpendicular to the light. It still warps there while
    /// sin γ > 0.02 (γ > 1.1459°). The crate does the same: for 1.1459° < γ ≤ 1.4037° the warp runs
    /// along eye x with n′ from that axis's d (docs/builders.md has the numbers at the switch).
    Filament,
    /// Filament's rule with explicit hints: n′ = max((z₀ + √(v₀ v₁))/sin γ, dzn/(2 − 3 dzn/(f − n)))
    /// with dzn = max(0, near_hint − n), dzf = max(0, f − far_hint), z₀ = n, z₁ = n + Δ sin γ,
    /// v₀ = n + dzn, v₁ = min(f − dzf, z₁); orthographic when sin γ ≤ 0.02 or 3 dzn/(f − n) ≥ 2.
    /// For a focus body B (the frame API) dzn and dzf come from the camera's planes (a cascade's
    /// split planes, as Filament's `updateCascadeShadowMaps` sets the cascade camera's), and n, f
    /// everywhere else are B's depth range, as in `ShadowMap::applyLISPSM`.
    FilamentHints {
        /// `ShadowOptions::shadowNearHint`.
        near_hint: f64,
        /// `ShadowOptions::shadowFarHint`.
        far_hint: f64,
    },
    /// OGRE's default LiSPSM as OGRE 1.x through 13.5 ship it
    /// (`LiSPSMShadowCameraSetup::calculateNOptSimple`, `mUseSimpleNOpt = true`):
    /// n′ = (|e_z| + √(n f)) · 0.1 · k, e_z the near camera point's eye depth (n for the frustum),
    /// 0.1 the default `mOptAdjustFactor`, and k = 1 + 20 (|cos γ| − 0.9)/0.1 when |cos γ| ≥ 0.9,
    /// else 1 (`getShadowCamera`'s ramp, `mCosCamLightDirThreshold = 0.9`); n′ ≤ 0 (underflow) is
    /// OGRE's "uniform shadow mapping". It does not tend to the uniform map as the light turns
    /// parallel (k ≤ 21).
    ///
    /// The centre of projection is OGRE's `C_start = (e_ls.x, e_ls.y, z_max)`: it lies on the
    /// light-space x and y of the near camera point e (`getNearCameraPoint_ws`, the body vertex
    /// nearest the camera; for the view frustum the first near-plane vertex of OGRE's
    /// `ConvexBody::define` order, the top right (+w, +h, −n), as the four tie), not on the eye.
    /// These versions build the light space with the unit projection `Affine3::getScale(1, 1, −1)`
    /// (13.4.0 and 13.5 restore it for the orthographic camera), so n′ is in world units.
    Ogre,
    /// OGRE 13.6 and later: as [`WarpRule::Ogre`], but `getShadowCamera` builds LiSPSM's light
    /// space from `DefaultShadowCameraSetup`'s orthographic camera, whose window is
    /// 2 · shadowDist wide (OGRECave/ogre commit b3f63b4, "LiSPSM - drop obsolete workaround",
    /// first in 13.6.0). n_opt, computed in world units, is then applied in that space scaled
    /// by 1/shadowDist, so the effective n′ is n_opt × shadowDist.
    OgreOrtho {
        /// OGRE's `shadowDist` (world units, > 0): the shadow camera's far clip distance if set,
        /// else the light's shadow far distance, else 300 × the camera's near distance.
        shadow_distance: f64,
    },
    /// The crate's minimax, the default: the n′ ∈ (0, ∞] that minimises the storage factor
    /// S̄ = M_x M_z of the fitted map, the product of the frustum's maximum errors, which is the
    /// texel count a map needs for a given maximum error (Lloyd 2006 §4.2)
    /// ([`crate::maps::minimax::minimax_n_prime`]). n′ = ∞ is a candidate, so it is never worse
    /// than [`WarpRule::Uniform`].
    #[default]
    Minimax,
    /// The n′ ∈ (0, ∞] that minimises the maximum z error M_z alone, found exactly
    /// ([`crate::maps::minimax::minimax_mz_n_prime`]). With the light overhead it is
    /// n + √(f n); for grazing lights it can lose up to ≈ 19 % of S̄ against the uniform map,
    /// which is why [`WarpRule::Minimax`] minimises S̄ instead.
    MinimaxMz,
}

/// The shadow matrix of `rule` for the whole view frustum and a light travelling along
/// `light_dir` (eye space): the light space of [`light_space`](crate::maps::light_space) with the view direction as axis,
/// n′ from [`n_prime_for`], the warp fitted to the eight corners by [`fit_warp`]. No heap
/// allocation.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir` for a zero or non-finite vector, or the rule's
/// parameter (`eta`, `focus`, `near_hint`, `far_hint`) outside its domain; [`Error::Degenerate`]
/// when the frustum's depth ratio is beyond what f64 can warp with this n′ (every corner is checked
/// to land in the clip volume; near 1, half field of view 0.5 rad and light (0, −1, −0.3), from
/// f/n = 6.1·10¹¹ for PSM and 4.1·10²³ for LiSPSM; from 2·10¹¹ to 4·10¹² and 5·10²² to 2·10²⁵ over
/// half fields of view 0.2 to 1.2 rad, and lower, from about 3·10⁹ and 5·10¹⁷, where the light's
/// direction lies inside a wide field of view: docs/builders.md).
///
/// ```
/// # use shadow_aliasing::maps::{warp, WarpRule};
/// # use shadow_aliasing::measure::frustum_max;
/// # use shadow_aliasing::ViewFrustum;
/// # use glam::DVec3;
/// let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
/// let s = warp(&view, DVec3::new(0.0, -1.0, 0.0), WarpRule::Lispsm)?;
/// // Light overhead: S̄ = (f/n − 1)/(2 tan θ) (Lloyd 2006 Eq 12).
/// let e = frustum_max(&view, &s.shadow_map())?;
/// let expect = 99.0 / (2.0 * 30f64.to_radians().tan());
/// assert!((e.storage_factor - expect).abs() < 1e-9 * expect);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn warp(view: &ViewFrustum, light_dir: DVec3, rule: WarpRule) -> Result<ShadowMatrix> {
    let fl = FrustumInLight::new(view, light_dir)?;
    warp_in(view, &fl, rule)
}

/// A light's view-axis light space, computed once for several (sub)frusta: `warp_prepared`
/// with it is [`warp()`] bit for bit.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PreparedLight {
    l: LightDir,
    ls: LightSpace,
}

impl PreparedLight {
    #[inline]
    pub(crate) fn new(l: LightDir) -> Self {
        Self {
            l,
            ls: light_space_unit(l, DVec3::NEG_Z),
        }
    }
}

/// [`warp()`] for a prepared light.
#[inline]
pub(crate) fn warp_prepared(
    view: &ViewFrustum,
    light: &PreparedLight,
    rule: WarpRule,
) -> Result<ShadowMatrix> {
    let fl = FrustumInLight::in_light_space(view, light.l, light.ls);
    warp_in(view, &fl, rule)
}

#[inline(always)]
fn warp_in(view: &ViewFrustum, fl: &FrustumInLight, rule: WarpRule) -> Result<ShadowMatrix> {
    in_rule_frame(view, fl, rule, |fl| warp_fitted(view, fl, rule))
}

#[inline(always)]
fn warp_fitted(view: &ViewFrustum, fl: &FrustumInLight, rule: WarpRule) -> Result<ShadowMatrix> {
    let n_prime = rule_n_prime(view, fl, rule)?;
    let matrix = match rule {
        // OGRE's C_start: the first near-plane vertex in OGRE's order, (+w, +h, −n), index 2 of
        // `ViewFrustum::corners`.
        WarpRule::Ogre | WarpRule::OgreOrtho { .. } => fit_frustum_from_corner(fl, n_prime, 2)?,
        _ => fit_frustum(fl, n_prime)?,
    };
    Ok(fl.shadow_matrix(view, matrix, n_prime))
}

/// The n′ that `rule` chooses for the whole view frustum and this light (see [`WarpRule`]).
///
/// # Errors
/// As [`warp`].
///
/// ```
/// # use shadow_aliasing::maps::{n_prime_for, WarpRule};
/// # use shadow_aliasing::{NPrime, ViewFrustum};
/// # use glam::DVec3;
/// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
/// let overhead = DVec3::new(0.0, -1.0, 0.0);
/// assert_eq!(n_prime_for(&view, overhead, WarpRule::Lispsm)?, NPrime::finite(11.0)?);
/// // The M_z minimax n′ overhead is LiSPSM's (M_z equal on the near and far planes).
/// let m = n_prime_for(&view, overhead, WarpRule::MinimaxMz)?.value();
/// assert!((m - 11.0).abs() < 1e-9);
/// // Light from behind: every generalised rule falls back to the uniform map.
/// assert_eq!(n_prime_for(&view, DVec3::NEG_Z, WarpRule::Lispsm)?, NPrime::UNWARPED);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn n_prime_for(view: &ViewFrustum, light_dir: DVec3, rule: WarpRule) -> Result<NPrime> {
    let fl = FrustumInLight::new(view, light_dir)?;
    in_rule_frame(view, &fl, rule, |fl| rule_n_prime(view, fl, rule))
}

pub(crate) fn rule_n_prime(
    view: &ViewFrustum,
    fl: &FrustumInLight,
    rule: WarpRule,
) -> Result<NPrime> {
    rule_n_prime_on(view, view, fl, rule)
}

/// The n′ of `rule` for a body in light space `fl` whose eye-depth range is `view`'s
/// `[near, far]` (a sub-frustum `[n_B, f_B]` for the frame API's focus body B), seen by a camera
/// with near and far planes `camera`'s (the frame API passes its slice's: the camera's for one
/// map, the split planes for a cascade, as Filament's and OGRE's cascades set them): the rules of the papers see the body's depth range as their
/// frustum (as a z-partition's rule sees its partition); Filament's hints are measured from the
/// camera's planes, and its z₀, the orthographic test, nopt1 and the virtual far plane use the
/// body's depth range (`ShadowMap::applyLISPSM`: `dzn`, `dzf` from `camera.zn`, `camera.zf`;
/// `zn`, `zf` the shadow volume's range clamped to the camera's, `z0 = zn`); OGRE's n_opt is `|e_z| + √(n f)` with e the body's
/// vertex nearest the camera and n, f the camera's (`calculateNOptSimple`). With
/// `camera == view` and the frustum's corners this is [`rule_n_prime`] bit for bit.
pub(crate) fn rule_n_prime_on<const N: usize>(
    camera: &ViewFrustum,
    view: &ViewFrustum,
    fl: &FrustumInLight<N>,
    rule: WarpRule,
) -> Result<NPrime> {
    let (n, f) = (view.near(), view.far());
    let sin_g = fl.sin_gamma;
    Ok(match rule {
        WarpRule::Uniform => NPrime::UNWARPED,
        WarpRule::Eta(eta) => crate::analytic::eta::n_prime_from_eta(n, f, eta)?,
        WarpRule::Psm => NPrime::finite_unchecked(n),
        WarpRule::LispsmFixed => NPrime::finite_unchecked(view.n_prime_lispsm()),
        WarpRule::Lispsm => lane_n_prime(lispsm_sin_n_prime(view.n_prime_lispsm(), sin_g)),
        WarpRule::Barroso(falloff) => {
            let gamma = LightAngle::from_light_dir(fl.ls.light_dir())?;
            crate::analytic::tilted::generalized_n_prime(view, gamma, falloff)
        }
        WarpRule::Tsm { focus } => tsm_rule(view, fl, focus)?,
        WarpRule::LispsmReference => lane_n_prime(reference_n_prime(fl.delta, sin_g, n)),
        WarpRule::Filament => filament_n_prime(camera, view, fl, 1.0, 100.0)?,
        WarpRule::FilamentHints {
            near_hint,
            far_hint,
        } => filament_n_prime(camera, view, fl, near_hint, far_hint)?,
        WarpRule::Ogre => NPrime::finite_or_unwarped(ogre_n_opt(camera, view, fl)),
        WarpRule::OgreOrtho { shadow_distance } => {
            let d = crate::error::positive("shadow_distance", shadow_distance)?;
            NPrime::finite_or_unwarped(ogre_n_opt(camera, view, fl) * d)
        }
        WarpRule::Minimax => minimax::min_storage(view, fl).n_prime,
        WarpRule::MinimaxMz => minimax::minimax_mz(view, fl).n_prime,
    })
}

/// The n′ of a rule the sweep's lanes also compute: `Finite(v)` where the rule's guard holds,
/// else `Unwarped`.
#[inline(always)]
fn lane_n_prime((v, ok): (f64, bool)) -> NPrime {
    if ok {
        NPrime::finite_unchecked(v)
    } else {
        NPrime::UNWARPED
    }
}

/// [`WarpRule::Lispsm`]'s n′ = n′_LSPSM / sin γ and whether it is a warp: sin γ > 0 and the
/// quotient finite and positive (else the map is unwarped).
#[inline(always)]
pub(crate) fn lispsm_sin_n_prime<T: Lane>(n_lispsm: T, sin_g: T) -> (T, T::Mask) {
    let v = n_lispsm / sin_g;
    let zero = T::splat(0.0);
    (v, T::and(sin_g.gt(zero), T::and(v.finite(), v.gt(zero))))
}

/// [`WarpRule::LispsmReference`]'s n′ = Δ(√(1 + x) + 1)/x with x = Δ sin γ/n, and whether it is a
/// warp: x > 0 and n′ finite and positive.
#[inline(always)]
pub(crate) fn reference_n_prime<T: Lane>(delta: T, sin_g: T, n: T) -> (T, T::Mask) {
    let one = T::splat(1.0);
    let x = delta * sin_g / n;
    let v = delta * ((one + x).sqrt() + one) / x;
    let zero = T::splat(0.0);
    (v, T::and(x.gt(zero), T::and(v.finite(), v.gt(zero))))
}

/// OGRE's `calculateNOptSimple` with `getShadowCamera`'s ramp (see [`WarpRule::Ogre`]).
fn ogre_n_opt<const N: usize>(
    camera: &ViewFrustum,
    view: &ViewFrustum,
    fl: &FrustumInLight<N>,
) -> f64 {
    let (n, f) = (camera.near(), camera.far());
    let e_z = view.near();
    let cos_g = fl.ls.light_dir().z.abs().min(1.0);
    let tweak = if cos_g >= 0.9 {
        1.0 + 20.0 * ((cos_g - 0.9) / (1.0 - 0.9))
    } else {
        1.0
    };
    (e_z + (n * f).sqrt()) * 0.1 * tweak
}

/// Filament's `computeLightRotation` threshold on |cos γ| = |(Mv V).z| (a `float` constant).
const FILAMENT_PARALLEL_COS: f64 = 0.9997f32 as f64;

/// The frame a rule fits its map in when it is not the view-axis frame of `fl`: Filament keeps
/// the light's own frame, with the camera's right vector as up, once |cos γ| ≥ 0.9997
/// ([`WarpRule::Filament`]).
#[inline]
pub(crate) fn rule_frame(
    view: &ViewFrustum,
    fl: &FrustumInLight,
    rule: WarpRule,
) -> Option<FrustumInLight> {
    match rule {
        WarpRule::Filament | WarpRule::FilamentHints { .. }
            if fl.ls.light_dir().z.abs() >= FILAMENT_PARALLEL_COS =>
        {
            let l = fl.ls.light();
            Some(FrustumInLight::in_light_space(
                view,
                l,
                light_space_unit(l, DVec3::X),
            ))
        }
        _ => None,
    }
}

/// The warp axis `rule` builds its light space with for the unit light direction `l` (eye space):
/// the view direction −Z, or eye x where Filament keeps the light's own frame ([`rule_frame`]).
#[inline]
pub(crate) fn rule_axis(l: DVec3, rule: WarpRule) -> DVec3 {
    match rule {
        WarpRule::Filament | WarpRule::FilamentHints { .. }
            if l.z.abs() >= FILAMENT_PARALLEL_COS =>
        {
            DVec3::X
        }
        _ => DVec3::NEG_Z,
    }
}

/// `f` on the frame `rule` fits its map in: [`rule_frame`]'s, or `fl` itself.
#[inline(always)]
fn in_rule_frame<T>(
    view: &ViewFrustum,
    fl: &FrustumInLight,
    rule: WarpRule,
    f: impl FnOnce(&FrustumInLight) -> T,
) -> T {
    match rule_frame(view, fl, rule) {
        Some(frame) => f(&frame),
        None => f(fl),
    }
}

use crate::analytic::tsm::EIGHTY_PERCENT_LINE;

/// Martin & Tan's focus distance δ beyond the near plane: `0 < focus ≤ f − n` (the TSM rule and
/// the trapezoidal builders).
pub(crate) fn focus_in_range(view: &ViewFrustum, focus: f64) -> Result<f64> {
    let focus = crate::error::positive("focus", focus)?;
    if focus > view.far() - view.near() {
        return Err(Error::invalid(
            "focus",
            format!(
                "must be at most far − near = {} (got {})",
                fmt_num(view.far() - view.near()),
                fmt_num(focus)
            ),
        ));
    }
    Ok(focus)
}

fn tsm_rule<const N: usize>(
    view: &ViewFrustum,
    fl: &FrustumInLight<N>,
    focus: f64,
) -> Result<NPrime> {
    let focus = focus_in_range(view, focus)?;
    let p = fl.ls.to_light(DVec3::new(0.0, 0.0, -(view.near() + focus)));
    Ok(
        match tsm_eta_finite(fl.delta, p.z - fl.z0, EIGHTY_PERCENT_LINE) {
            Some(eta) => NPrime::finite_unchecked(eta),
            None => NPrime::UNWARPED,
        },
    )
}

fn filament_n_prime<const N: usize>(
    camera: &ViewFrustum,
    view: &ViewFrustum,
    fl: &FrustumInLight<N>,
    near_hint: f64,
    far_hint: f64,
) -> Result<NPrime> {
    // Filament's hints are distances from the eye (`ShadowOptions`: 1 m and 100 m by default);
    // its code does not check them, but a hint at or behind the eye, or a far hint not beyond
    // the near hint, describes no virtual near and far planes (vz₁ would clamp to 0 and n′ to
    // z₀/sin γ silently).
    let near_hint = crate::error::positive("near_hint", near_hint)?;
    let far_hint = crate::error::positive("far_hint", far_hint)?;
    if far_hint <= near_hint {
        return Err(Error::invalid(
            "far_hint",
            format!(
                "must be greater than near_hint (got near_hint={}, far_hint={})",
                fmt_num(near_hint),
                fmt_num(far_hint)
            ),
        ));
    }
    // `applyLISPSM`: the hints' dzn, dzf from the camera's planes (`camera.zn`, `camera.zf`);
    // zn, zf the shadow volume's depth range clamped to them (`max(camera.zn, znf[0])`,
    // `min(camera.zf, znf[1])`: the body's depths, which lie inside the camera's), used in the
    // orthographic test, in nopt1 and in the virtual far plane.
    let (czn, czf) = (camera.near(), camera.far());
    let (zn, zf) = (view.near().max(czn), view.far().min(czf));
    let sin_lv = fl.sin_gamma;
    let dzn = (near_hint - czn).max(0.0);
    let dzf = (czf - far_hint).max(0.0);
    let z0 = zn;
    let z1 = z0 + fl.delta * sin_lv;
    const EPSILON: f64 = 0.02;
    if !(sin_lv > EPSILON && 3.0 * (dzn / (zf - zn)) < 2.0) {
        return Ok(NPrime::UNWARPED);
    }
    let vz0 = zn.max(czn + dzn).max(z0).max(0.0);
    let vz1 = zf.min(czf - dzf).min(z1).max(0.0);
    let nopt0 = (z0 + (vz0 * vz1).sqrt()) / sin_lv;
    let nopt1 = dzn / (2.0 - 3.0 * (dzn / (zf - zn)));
    Ok(NPrime::finite_or_unwarped(nopt0.max(nopt1)))
}
