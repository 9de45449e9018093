//! Validated inputs: the view frustum, the warp parameter n′, resolutions and light angles.
//!
//! # Conventions
//!
//! Eye space is right-handed with the camera at the origin looking down −Z and Y up
//! (glam's `look_at_rh`). The *depth* of an eye-space point `p` is `z = −p.z`, the distance
//! along the view direction; the papers' `z` is this depth. Angles are in radians.

use crate::error::{fmt_num, in_open, positive, Error, Result};
use glam::DVec3;

/// A symmetric view frustum: near and far plane depths, half of the vertical field of view,
/// and the aspect ratio (width / height) of the image.
///
/// Domain: `0 < near < far`, both finite; `0 < half_fov < π/2`; `aspect > 0`; and every
/// quantity the frustum's accessors and the builders derive from these is a finite, normal `f64`:
/// the depth ratio f/n, tan θ, the near plane's half extents `n tan θ` and `n tan θ · aspect`
/// (the image beam width at the near plane, the denominator of every error), the far plane's
/// half extents, and LiSPSM's n + √(f n). This excludes subnormal near planes and fields of
/// view, whose one or few significant bits make every derived value meaningless. The papers'
/// analysis assumes a square image (`aspect = 1`, the default of [`ViewFrustum::new`]).
///
/// | crate | Lloyd 2005 | Lloyd 2006 | Barroso & Celes | Zhang et al. |
/// |---|---|---|---|---|
/// | `near`, `far` | 1, α | n, f | n, f | n, f |
/// | `half_fov` | θ | θ | φ_y | φ |
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewFrustum {
    near: f64,
    far: f64,
    half_fov: f64,
    aspect: f64,
    /// tan θ, computed once here: every builder and most closed forms need it.
    tan_half_fov: f64,
}

impl ViewFrustum {
    /// A square-image frustum.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `near`, `far` or `half_fov` when a value is not finite,
    /// `near ≤ 0`, `far ≤ near`, `half_fov ∉ (0, π/2)`, or a derived quantity leaves the type's
    /// domain (as [`ViewFrustum::with_aspect`]: f/n overflowing, a subnormal near plane or tan θ).
    ///
    /// ```
    /// # use shadow_aliasing::ViewFrustum;
    /// let v = ViewFrustum::new(1.0, 100.0, 30f64.to_radians())?;
    /// assert_eq!(v.alpha(), 100.0);
    /// assert!(ViewFrustum::new(2.0, 1.0, 0.5).is_err());
    /// # Ok::<(), shadow_aliasing::Error>(())
    /// ```
    pub fn new(near: f64, far: f64, half_fov: f64) -> Result<Self> {
        Self::with_aspect(near, far, half_fov, 1.0)
    }

    /// A frustum with the given aspect ratio (width / height); `half_fov` is vertical.
    ///
    /// # Errors
    /// As [`ViewFrustum::new`], `aspect` when it is not finite and positive, `far` when the far
    /// plane's half extent `f tan θ · max(aspect, 1)`, the ratio f/n or n + √(f n) overflows
    /// `f64`, and `near` or `half_fov` when tan θ or the near plane's half extent
    /// `n tan θ · min(aspect, 1)` is zero or subnormal (the type's domain); `aspect` instead of
    /// `far` or `near` when the square frustum's half extent `f tan θ` or `n tan θ` is in the
    /// domain and the aspect takes it out.
    pub fn with_aspect(near: f64, far: f64, half_fov: f64, aspect: f64) -> Result<Self> {
        let (near, far) = depth_range(near, far)?;
        let half_fov = in_open("half_fov", half_fov, 0.0, std::f64::consts::FRAC_PI_2)?;
        let aspect = positive("aspect", aspect)?;
        let tan_half_fov = half_fov.tan();
        if !(tan_half_fov.is_normal() && tan_half_fov > 0.0) {
            return Err(half_fov_too_small(half_fov));
        }
        check_extent(near, far, tan_half_fov, aspect)?;
        Ok(Self {
            near,
            far,
            half_fov,
            aspect,
            tan_half_fov,
        })
    }

    /// Near plane depth n.
    #[inline]
    #[must_use]
    pub fn near(&self) -> f64 {
        self.near
    }
    /// Far plane depth f.
    #[inline]
    #[must_use]
    pub fn far(&self) -> f64 {
        self.far
    }
    /// Half of the vertical field of view θ, radians.
    #[inline]
    #[must_use]
    pub fn half_fov(&self) -> f64 {
        self.half_fov
    }
    /// Aspect ratio, width / height.
    #[inline]
    #[must_use]
    pub fn aspect(&self) -> f64 {
        self.aspect
    }
    /// The depth ratio α = f/n.
    #[inline]
    #[must_use]
    pub fn alpha(&self) -> f64 {
        self.far / self.near
    }
    /// tan θ.
    #[inline]
    #[must_use]
    pub fn tan_half_fov(&self) -> f64 {
        self.tan_half_fov
    }
    /// LiSPSM's warp parameter for the light overhead, n′ = n + √(f n) (Lloyd 2006 §4.1,
    /// Wimmer et al. 2004).
    #[inline]
    #[must_use]
    pub fn n_prime_lispsm(&self) -> f64 {
        // √(f n) without overflow or underflow of the product.
        self.near + crate::numeric::sqrt_fn(self.near, self.far)
    }

    /// The same frustum cut to the depth range `[near, far]` (a z-partition).
    ///
    /// # Errors
    /// As [`ViewFrustum::with_aspect`].
    #[inline]
    pub fn with_depth_range(&self, near: f64, far: f64) -> Result<Self> {
        let (near, far) = depth_range(near, far)?;
        check_extent(near, far, self.tan_half_fov, self.aspect)?;
        Ok(Self { near, far, ..*self })
    }

    /// The eight corners in eye space: near plane first (−x−y, +x−y, +x+y, −x+y), then far
    /// ([`ViewFrustum::corners_at`] at both depths).
    #[must_use]
    pub fn corners(&self) -> [DVec3; 8] {
        let [a, b, c, d] = self.corners_at(self.near);
        let [e, f, g, h] = self.corners_at(self.far);
        [a, b, c, d, e, f, g, h]
    }

    /// The four corners `(±w, ±h, −d)` of the cross-section at eye depth `d`, with h = d tan θ
    /// and w = h · aspect (in this order, so that a frustum whose tan θ · aspect overflows still
    /// has finite corners), in the order of [`ViewFrustum::corners`]. Every builder and
    /// measurement of the crate forms the frustum's corners here.
    #[must_use]
    pub fn corners_at(&self, d: f64) -> [DVec3; 4] {
        let h = d * self.tan_half_fov();
        let w = h * self.aspect;
        [
            DVec3::new(-w, -h, -d),
            DVec3::new(w, -h, -d),
            DVec3::new(w, h, -d),
            DVec3::new(-w, h, -d),
        ]
    }

    /// Whether an eye-space point lies inside the frustum, with a relative tolerance `tol`.
    #[must_use]
    pub fn contains(&self, p: DVec3, tol: f64) -> bool {
        let z = -p.z;
        let h = z * self.tan_half_fov();
        let w = h * self.aspect;
        let slack = tol * self.far;
        z >= self.near - slack
            && z <= self.far + slack
            && p.y.abs() <= h + slack
            && p.x.abs() <= w + slack
    }
}

/// `0 < near < far`, both finite: the crate's one depth-range check (the constructors of
/// [`ViewFrustum`], and `analytic::eta::near_far` for the closed forms on bare depths).
#[inline(always)]
pub(crate) fn depth_range(near: f64, far: f64) -> Result<(f64, f64)> {
    let near = positive("near", near)?;
    let far = positive("far", far)?;
    if far <= near {
        return Err(far_not_beyond_near(near, far));
    }
    Ok((near, far))
}

/// The derived quantities of the type's domain: the far plane's half extent `f tan θ max(aspect, 1)`,
/// f/n and n + √(f n) finite; the near plane's half extent `n tan θ min(aspect, 1)` normal.
#[inline]
fn check_extent(near: f64, far: f64, tan_half_fov: f64, aspect: f64) -> Result<()> {
    if !(far * tan_half_fov * aspect.max(1.0)).is_finite() {
        // The square frustum's half extent is finite: the aspect is the cause.
        return Err(if (far * tan_half_fov).is_finite() {
            aspect_out_of_range(aspect, far * tan_half_fov)
        } else {
            far_too_large(far)
        });
    }
    if !(far / near).is_finite() || !(near + crate::numeric::sqrt_fn(near, far)).is_finite() {
        return Err(ratio_too_large(near, far));
    }
    if !(near * tan_half_fov * aspect.min(1.0)).is_normal() {
        return Err(if (near * tan_half_fov).is_normal() {
            aspect_out_of_range(aspect, near * tan_half_fov)
        } else {
            near_too_small(near, tan_half_fov)
        });
    }
    Ok(())
}

/// The positive, finite `v` rounded up or down to 3 significant digits: the `f64` nearest that
/// decimal, which [`fmt_num`] prints as it (an error's advice, rounded inward so that following
/// it works).
pub(crate) fn round3(v: f64, up: bool) -> f64 {
    let e = v.log10().floor();
    let m = v / 10f64.powf(e) * 100.0;
    let m = if up { m.ceil() } else { m.floor() };
    format!("{m}e{}", e - 2.0).parse().unwrap_or(v)
}

/// An aspect whose half width `extent · aspect` (the far plane's, `extent` = far tan θ, for a
/// large one; the near plane's, `extent` = near tan θ, for a small one) overflows or is not a
/// normal `f64`, with the range of aspects that keeps it one (rounded inward to 3 digits).
#[cold]
#[inline(never)]
fn aspect_out_of_range(aspect: f64, extent: f64) -> Error {
    let (what, bound) = if aspect > 1.0 {
        (
            "large: the far plane's half width far tan θ aspect overflows; give aspect at most",
            round3(f64::MAX / extent, false),
        )
    } else {
        (
            "small: the near plane's half width near tan θ aspect must be a normal f64; give \
             aspect at least",
            round3(f64::MIN_POSITIVE / extent, true),
        )
    };
    Error::invalid(
        "aspect",
        format!(
            "is too {what} {} for this near, far and field of view (got aspect={})",
            fmt_num(bound),
            fmt_num(aspect)
        ),
    )
}

#[cold]
#[inline(never)]
fn half_fov_too_small(half_fov: f64) -> Error {
    Error::invalid(
        "half_fov",
        format!(
            "is too small: tan θ must be a normal f64, at least {} (got half_fov={})",
            fmt_num(f64::MIN_POSITIVE),
            fmt_num(half_fov)
        ),
    )
}

#[cold]
#[inline(never)]
fn ratio_too_large(near: f64, far: f64) -> Error {
    Error::invalid(
        "far",
        format!(
            "is too large for near: far/near and near + √(far near) must be finite (got near={}, far={})",
            fmt_num(near),
            fmt_num(far)
        ),
    )
}

#[cold]
#[inline(never)]
fn near_too_small(near: f64, tan_half_fov: f64) -> Error {
    Error::invalid(
        "near",
        format!(
            "is too small: the near plane's half extent near tan θ min(aspect, 1) must be a normal f64 (got near={}, tan θ={})",
            fmt_num(near),
            fmt_num(tan_half_fov)
        ),
    )
}

#[cold]
#[inline(never)]
fn far_too_large(far: f64) -> Error {
    Error::invalid(
        "far",
        format!(
            "is too large: the far plane's half extent f tan θ overflows (got far={})",
            fmt_num(far)
        ),
    )
}

#[cold]
#[inline(never)]
fn far_not_beyond_near(near: f64, far: f64) -> Error {
    Error::invalid(
        "far",
        format!(
            "must be greater than near (got near={}, far={})",
            fmt_num(near),
            fmt_num(far)
        ),
    )
}

/// The warp parameter n′: the distance from the warping frustum's centre of projection to the
/// plane where the warping frustum starts (Lloyd 2006 Fig 3; Lloyd 2005's n with near = 1;
/// Zhang's λ). [`NPrime::UNWARPED`] is the orthographic (unwarped) map, n′ = ∞, represented
/// explicitly so that no function returns an infinite `f64`.
///
/// The payload is private: every `NPrime` holds a positive n′, finite or ∞ (never NaN, zero,
/// negative or −∞), so functions that take one do not check it again.
///
/// ```
/// # use shadow_aliasing::NPrime;
/// let n = NPrime::finite(11.0)?;
/// assert_eq!(n.as_finite(), Some(11.0));
/// assert_eq!(NPrime::new(f64::INFINITY)?, NPrime::UNWARPED);
/// assert_eq!(NPrime::UNWARPED.as_finite(), None);
/// assert!(NPrime::finite(0.0).is_err() && NPrime::finite(f64::INFINITY).is_err());
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NPrime(f64);

impl NPrime {
    /// n′ = ∞: an orthographic, unwarped shadow map.
    pub const UNWARPED: Self = Self(f64::INFINITY);

    /// Validates a finite n′ > 0, or maps `f64::INFINITY` to [`NPrime::UNWARPED`].
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `n_prime` for NaN, −∞ or n′ ≤ 0.
    pub fn new(n_prime: f64) -> Result<Self> {
        Self::named("n_prime", n_prime)
    }

    /// [`NPrime::new`] with the error naming `name` (Zhang's `lambda`, Lloyd 2005's `n_warp`).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `name` for NaN, −∞ or n′ ≤ 0.
    pub fn named(name: &'static str, n_prime: f64) -> Result<Self> {
        if n_prime == f64::INFINITY {
            Ok(Self::UNWARPED)
        } else {
            positive(name, n_prime).map(Self)
        }
    }

    /// Validates a finite n′ > 0 (a warped map).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `n_prime` unless n′ is finite and positive.
    pub fn finite(n_prime: f64) -> Result<Self> {
        positive("n_prime", n_prime).map(Self)
    }

    /// A finite n′ > 0 computed inside the crate from validated inputs (LiSPSM's n + √(f n) of a
    /// [`ViewFrustum`], which its domain keeps finite and positive): no check in release builds.
    #[inline]
    pub(crate) fn finite_unchecked(n_prime: f64) -> Self {
        debug_assert!(n_prime.is_finite() && n_prime > 0.0, "n′ = {n_prime}");
        Self(n_prime)
    }

    /// A computed n′: itself when finite and positive, [`NPrime::UNWARPED`] otherwise (an
    /// overflow to ∞, or a rule with no finite answer, is the orthographic limit).
    #[inline]
    pub(crate) fn finite_or_unwarped(n_prime: f64) -> Self {
        Self::try_finite(n_prime).unwrap_or(Self::UNWARPED)
    }

    /// `Some(n′)` for a finite n′ > 0, `None` for a computed value that is not one: NaN, ≤ 0, or
    /// ∞ (use [`NPrime::new`] to map ∞ to [`NPrime::UNWARPED`]).
    #[inline]
    #[must_use]
    pub fn try_finite(n_prime: f64) -> Option<Self> {
        (n_prime.is_finite() && n_prime > 0.0).then_some(Self(n_prime))
    }

    /// n′ as an `f64`, `f64::INFINITY` for [`NPrime::UNWARPED`].
    #[inline]
    #[must_use]
    pub fn value(self) -> f64 {
        self.0
    }

    /// n′ when it is finite, `None` for [`NPrime::UNWARPED`].
    #[inline]
    #[must_use]
    pub fn as_finite(self) -> Option<f64> {
        if self.0.is_finite() {
            Some(self.0)
        } else {
            None
        }
    }

    /// 1/n′, exactly 0 for [`NPrime::UNWARPED`] (the warp written in 1/n′ tends continuously to
    /// the orthographic map).
    #[inline]
    #[must_use]
    pub fn recip(self) -> f64 {
        1.0 / self.0
    }

    /// Whether this is the unwarped (orthographic) map.
    #[inline]
    #[must_use]
    pub fn is_unwarped(self) -> bool {
        self.0 == f64::INFINITY
    }
}

/// Image and shadow-map resolutions: `image` pixels across a square image, and a shadow map of
/// `s × t` texels. Each is a positive, finite number (resolutions enter the formulas only as
/// ratios, so fractional values are allowed). [`Resolutions::default`] is all ones, the papers'
/// normalisation for the storage factor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Resolutions {
    image: f64,
    s: f64,
    t: f64,
}

impl Default for Resolutions {
    fn default() -> Self {
        Self {
            image: 1.0,
            s: 1.0,
            t: 1.0,
        }
    }
}

impl Resolutions {
    /// Validated resolutions.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `res_image`, `res_s` or `res_t` unless finite and positive.
    pub fn new(image: f64, s: f64, t: f64) -> Result<Self> {
        Ok(Self {
            image: positive("res_image", image)?,
            s: positive("res_s", s)?,
            t: positive("res_t", t)?,
        })
    }
    /// Image resolution res_i (pixels across).
    #[inline]
    #[must_use]
    pub fn image(&self) -> f64 {
        self.image
    }
    /// Shadow-map resolution along s (texels).
    #[inline]
    #[must_use]
    pub fn s(&self) -> f64 {
        self.s
    }
    /// Shadow-map resolution along t (texels).
    #[inline]
    #[must_use]
    pub fn t(&self) -> f64 {
        self.t
    }
}

/// The angle between the light direction and the view direction, folded into `[0, π/2]`
/// (Barroso's γ, Zhang's θ): π/2 is the light overhead, 0 light and view parallel.
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct LightAngle(f64);

impl LightAngle {
    /// Validates γ ∈ [0, π/2].
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `light_angle` outside `[0, π/2]` or not finite.
    pub fn new(gamma: f64) -> Result<Self> {
        crate::error::in_closed("light_angle", gamma, 0.0, std::f64::consts::FRAC_PI_2).map(Self)
    }
    /// The folded angle between an eye-space light direction (the direction light travels)
    /// and the view direction −Z.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `light_dir` for a zero or non-finite vector.
    pub fn from_light_dir(light_dir: DVec3) -> Result<Self> {
        LightDir::new(light_dir).map(Self::from_unit)
    }
    /// [`LightAngle::from_light_dir`] for a direction already validated.
    #[must_use]
    pub fn from_unit(light_dir: LightDir) -> Self {
        // |cos| of the angle between the line of the light and the view axis.
        let c = light_dir.as_dvec3().z.abs().min(1.0);
        Self(c.acos())
    }
    /// γ in radians.
    #[inline]
    #[must_use]
    pub fn radians(self) -> f64 {
        self.0
    }
}

/// A unit light direction (the direction light travels), validated and normalised once: every
/// builder normalises its `DVec3` argument into one at its entry and passes this type inside, so
/// that no direction is normalised twice.
///
/// ```
/// # use shadow_aliasing::frustum::LightDir;
/// # use glam::DVec3;
/// let l = LightDir::new(DVec3::new(0.0, -2.0, 0.0))?;
/// assert_eq!(l.as_dvec3(), DVec3::NEG_Y);
/// assert!(LightDir::new(DVec3::ZERO).is_err());
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LightDir(DVec3);

impl LightDir {
    /// Normalises a light direction: any finite, non-zero vector, however large or small its
    /// components (`(1e308, 1e308, 1e308)` and `(1e-320, 0, 0)` included).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `light_dir` for a zero or non-finite vector.
    #[inline]
    pub fn new(light_dir: DVec3) -> Result<Self> {
        let len2 = light_dir.length_squared();
        if len2 > 1e-290 && len2 < 1e290 {
            // No square overflows, and none that underflows matters: l / |l| directly, the same
            // bits as before (glam's `length` is this square root).
            Ok(Self(light_dir / len2.sqrt()))
        } else {
            scaled_unit_light_dir(light_dir).map(Self)
        }
    }

    /// [`LightDir::new`] with the error naming `name` (`light_dir_world` for a world-space light).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `name` for a zero or non-finite vector.
    #[inline]
    pub fn named(name: &'static str, light_dir: DVec3) -> Result<Self> {
        Self::new(light_dir).map_err(|e| match e {
            Error::InvalidArgument { reason, .. } => Error::InvalidArgument { name, reason },
            other => other,
        })
    }

    /// A vector the crate has already normalised (a light space's −y): no check in release
    /// builds.
    #[inline]
    pub(crate) fn from_unit_unchecked(unit: DVec3) -> Self {
        debug_assert!(
            unit.is_finite() && (unit.length() - 1.0).abs() < 1e-12,
            "{unit}"
        );
        Self(unit)
    }

    /// The unit vector.
    #[inline]
    #[must_use]
    pub fn as_dvec3(self) -> DVec3 {
        self.0
    }
}

/// [`LightDir::new`] for a vector whose squared length overflows or underflows (or is not
/// finite): scaled by its largest |component| first, so that the squares lie in [0, 3].
#[cold]
#[inline(never)]
fn scaled_unit_light_dir(light_dir: DVec3) -> Result<DVec3> {
    let m = light_dir.abs().max_element();
    if !light_dir.is_finite() || m == 0.0 {
        return Err(bad_light_dir(light_dir));
    }
    let s = light_dir / m;
    Ok(s / s.length())
}

#[cold]
#[inline(never)]
fn bad_light_dir(light_dir: DVec3) -> Error {
    let v = format!(
        "[{}, {}, {}]",
        fmt_num(light_dir.x),
        fmt_num(light_dir.y),
        fmt_num(light_dir.z)
    );
    if !light_dir.is_finite() {
        Error::invalid("light_dir", format!("must be finite (got {v})"))
    } else {
        Error::invalid("light_dir", format!("must be a non-zero vector (got {v})"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frustum_validation() {
        assert!(ViewFrustum::new(1.0, 1.0, 0.5).is_err());
        assert!(ViewFrustum::new(0.0, 1.0, 0.5).is_err());
        assert!(ViewFrustum::new(1.0, f64::INFINITY, 0.5).is_err());
        assert!(ViewFrustum::new(1.0, 2.0, std::f64::consts::FRAC_PI_2).is_err());
        assert_eq!(
            ViewFrustum::new(2.0, 1.0, 0.5).unwrap_err().to_string(),
            "far must be greater than near (got near=2, far=1)"
        );
        let v = ViewFrustum::new(1.0, 4.0, 0.5).unwrap();
        assert_eq!(v.n_prime_lispsm(), 3.0);
        // √(f n) computed without underflow: n = 1e-200, f = 1e-150 gives n + 1e-175.
        let tiny = ViewFrustum::new(1e-200, 1e-150, 0.5).unwrap();
        assert!((tiny.n_prime_lispsm() - (1e-200 + 1e-175)).abs() <= 1e-189);
        // A far plane whose extent overflows is refused, naming far.
        let e = ViewFrustum::new(1.0, 1e308, 1.5).unwrap_err();
        assert!(e.to_string().starts_with("far is too large"), "{e}");
        assert!(ViewFrustum::new(1.0, 1e308, 0.5)
            .unwrap()
            .corners()
            .iter()
            .all(|c| c.is_finite()));
        for c in v.corners() {
            assert!(v.contains(c, 1e-12));
        }
    }

    #[test]
    fn n_prime_and_angles() {
        assert_eq!(NPrime::new(f64::INFINITY), Ok(NPrime::UNWARPED));
        assert!(NPrime::finite(f64::INFINITY).is_err());
        assert!(NPrime::new(f64::NEG_INFINITY).is_err());
        assert_eq!(NPrime::UNWARPED.recip(), 0.0);
        assert_eq!(NPrime::try_finite(-1.0), None);
        assert!(NPrime::new(f64::NAN).is_err());
        assert!(NPrime::new(0.0).is_err());
        let g = LightAngle::from_light_dir(DVec3::new(0.0, -1.0, 0.0)).unwrap();
        assert!((g.radians() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        let g = LightAngle::from_light_dir(DVec3::new(0.0, 0.0, 1.0)).unwrap();
        assert_eq!(g.radians(), 0.0);
        assert!(LightAngle::from_light_dir(DVec3::ZERO).is_err());
    }
}
