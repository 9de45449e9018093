//! z-partitions (cascaded shadow maps): the view frustum cut along its depth, each partition with
//! its own fitted map (Lloyd 2006 §5.2, Eq 15, 16), and stable cascades as engines build them.
//!
//! # z-partitions
//!
//! [`cascades`] takes the split planes `near = z₀ < z₁ < … < z_k = far` of a
//! [`Splits`] (any [`SplitScheme`]: uniform, self-similar, practical λ, Barroso's adaptive,
//! Unreal's exponent; or explicit depths, [`Splits::from_planes`]; or fractions of the depth range,
//! [`splits_from_fractions`]) and fits one map per partition with [`warp()`] and a [`WarpRule`]:
//! the rule sees the partition as its own view frustum `[z_i, z_{i+1}]`, so `WarpRule::Lispsm`
//! is `n′ = z_i + √(z_i z_{i+1})` per partition, as Lloyd 2006 §5.2 fits "a warping frustum to each
//! partition separately". With the light overhead and self-similar planes this gives Lloyd 2006
//! Eq 17 (uniform maps) and Eq 18 (warped), and with the light behind Eq 20.
//!
//! # Overlap for blending
//!
//! With `overlap = o ∈ [0, 1)`, partition i (except the last) is fitted to
//! `[z_i, min(z_{i+1} + o (z_{i+1} − z_i), far)]`: its far end reaches into the next partition by
//! the fraction `o` of its own depth, the band a renderer cross-fades over. `o = 0` gives
//! disjoint partitions that tile the frustum.
//!
//! # Stable cascades
//!
//! Engines (Unity's "Stable Fit", the stabilised cascades of Valient's ShaderX6 chapter) trade
//! storage for stability under camera motion: each partition is enclosed in its minimal bounding
//! sphere, which does not turn with the camera, and an orthographic map of side `2R` is aligned
//! with a light space fixed in the world, its centre snapped to whole texels of the world-fixed
//! grid so that a moving camera shifts the map by whole texels only. [`stable_cascade`] builds it
//! and reports what the stability costs: the storage factor of the stable map against the tight
//! orthographic fit of the same partition.
//!
//! ```
//! use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
//! use shadow_aliasing::maps::cascades::cascades;
//! use shadow_aliasing::maps::WarpRule;
//! use shadow_aliasing::ViewFrustum;
//! use glam::DVec3;
//! let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians())?;
//! let splits = z_splits(1.0, 1000.0, 4, SplitScheme::SelfSimilar)?;
//! let c = cascades(&view, DVec3::new(0.0, -1.0, 0.0), &splits, WarpRule::Lispsm, 0.0)?;
//! // Light overhead: S̄ = k((f/n)^{1/k} − 1)/(2 tan θ) (Lloyd 2006 Eq 18).
//! let expect = 4.0 * (1000f64.powf(0.25) - 1.0) / (2.0 * 30f64.to_radians().tan());
//! assert!((c.storage_factor() - expect).abs() < 1e-9 * expect);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

pub use crate::analytic::partition::{SplitScheme, Splits, MAX_PARTITIONS};
use crate::error::{finite_result, fmt_num, in_closed, Error, Result};
use crate::frustum::{LightDir, NPrime, ViewFrustum};
use crate::maps::lightspace::light_space_dir;
use crate::maps::warp::{warp_prepared, PreparedLight};
use crate::maps::{warp, ShadowMatrix, WarpRule};
use crate::measure::vertex::vertex_max;
use crate::measure::FrustumError;
use glam::{DMat4, DVec3, DVec4};

/// One z-partition: its fitted map, the depth range it covers, and its measured maximum error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cascade {
    /// The partition's shadow matrix (eye → light clip, OpenGL depth), with the depth range it
    /// was fitted to (`near`, `far`, overlap included) and its n′.
    pub shadow: ShadowMatrix,
    /// Where the partition starts, z_i (the split plane; equal to `shadow.near`).
    pub split_near: f64,
    /// Where the next partition starts, z_{i+1} (without the overlap).
    pub split_far: f64,
    /// M_x, M_z over the fitted sub-frustum's eight corners (unit resolutions).
    pub error: FrustumError,
}

impl Cascade {
    /// S̄ = M_x M_z of this partition.
    #[must_use]
    pub fn storage_factor(&self) -> f64 {
        self.error.storage_factor
    }
}

/// A frame's z-partitions, near to far, in a fixed array (no heap allocation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cascades {
    parts: [Option<Cascade>; MAX_PARTITIONS],
    k: usize,
}

impl Cascades {
    /// Number of partitions k.
    #[must_use]
    pub fn k(&self) -> usize {
        self.k
    }
    /// Partition `i` (0 nearest the viewer), or `None` beyond k.
    #[must_use]
    pub fn get(&self, i: usize) -> Option<&Cascade> {
        self.parts.get(i).and_then(Option::as_ref)
    }
    /// The partitions, near to far.
    pub fn iter(&self) -> impl Iterator<Item = &Cascade> {
        self.parts[..self.k].iter().flatten()
    }
    /// The summed storage factor Σ S̄_i: k maps, each M_x,i M_z,i texels per image pixel
    /// (Lloyd 2006 §5.3, "the storage factor is also multiplied by k").
    #[must_use]
    pub fn storage_factor(&self) -> f64 {
        self.iter().map(Cascade::storage_factor).sum()
    }
}

/// The split planes `near + φ_i (far − near)` for fractions `0 < φ₁ < … < φ_{k−1} < 1` of the
/// depth range (engines' "cascade splits" given as fractions), near and far added at the ends.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `fractions` when there are more than `MAX_PARTITIONS − 1`,
/// or they are not finite, not in (0, 1), or not strictly increasing; as
/// [`Splits::from_planes`] when planes coincide in `f64`.
///
/// ```
/// # use shadow_aliasing::maps::cascades::splits_from_fractions;
/// # use shadow_aliasing::ViewFrustum;
/// let view = ViewFrustum::new(1.0, 101.0, 0.5)?;
/// let s = splits_from_fractions(&view, &[0.1, 0.3])?;
/// assert_eq!(s.planes(), &[1.0, 11.0, 31.0, 101.0]);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn splits_from_fractions(view: &ViewFrustum, fractions: &[f64]) -> Result<Splits> {
    splits_between(view.near(), view.far(), fractions)
}

/// [`splits_from_fractions`] between any depths `near < far` (a frame's visible depth range):
/// planes `near + φ_i (far − near)`.
pub(crate) fn splits_between(near: f64, far: f64, fractions: &[f64]) -> Result<Splits> {
    if fractions.len() >= MAX_PARTITIONS {
        return Err(Error::invalid(
            "fractions",
            format!(
                "must hold at most {} values (got {})",
                MAX_PARTITIONS - 1,
                fractions.len()
            ),
        ));
    }
    let (n, f) = (near, far);
    let mut planes = [0.0; MAX_PARTITIONS + 1];
    planes[0] = n;
    let mut prev = 0.0;
    for (i, &phi) in fractions.iter().enumerate() {
        if !(phi.is_finite() && phi > prev && phi < 1.0) {
            return Err(Error::invalid(
                "fractions",
                format!(
                    "must be finite, strictly increasing and inside (0, 1) (got {} at index {i})",
                    fmt_num(phi)
                ),
            ));
        }
        prev = phi;
        planes[i + 1] = n + phi * (f - n);
    }
    planes[fractions.len() + 1] = f;
    Splits::from_planes(&planes[..fractions.len() + 2])
}

/// One map per z-partition of `splits`, each fitted by [`warp()`] with `rule` to its own
/// sub-frustum (extended by `overlap`, see the module docs), and each measured at the eight
/// corners of that sub-frustum with [`vertex_max`]. No heap allocation.
///
/// The planes of `splits` must lie within `[view.near(), view.far()]`; a renderer that wants
/// its cascades to stop short of the far plane passes splits whose last plane is smaller.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir` (zero or not finite), `overlap` (outside
/// [0, 1)), `splits` (planes outside the view's depth range), or the rule's parameter;
/// [`Error::Degenerate`] when a fitted matrix maps a corner behind its centre of projection.
pub fn cascades(
    view: &ViewFrustum,
    light_dir: DVec3,
    splits: &Splits,
    rule: WarpRule,
    overlap: f64,
) -> Result<Cascades> {
    let mut parts = [None; MAX_PARTITIONS];
    let mut k = 0;
    visit_cascades(
        view,
        LightDir::new(light_dir)?,
        splits,
        rule,
        overlap,
        |c| {
            parts[k] = Some(*c);
            k += 1;
        },
    )?;
    Ok(Cascades { parts, k })
}

/// [`cascades`], handing each partition to `visit`, near to far, as it is built.
pub(crate) fn visit_cascades(
    view: &ViewFrustum,
    light_dir: LightDir,
    splits: &Splits,
    rule: WarpRule,
    overlap: f64,
    mut visit: impl FnMut(&Cascade),
) -> Result<()> {
    let overlap = in_closed("overlap", overlap, 0.0, 1.0)?;
    if overlap >= 1.0 {
        return Err(Error::invalid("overlap", "must be smaller than 1 (got 1)"));
    }
    splits_within(view, splits)?;
    let planes = splits.planes();
    let last = planes[planes.len() - 1];
    let k = splits.k();
    // `warp(&sub, light_dir, rule)` for every partition, with the light space computed once.
    let light = PreparedLight::new(light_dir);
    let tan = view.tan_half_fov();
    for i in 0..k {
        let (a, b) = splits.range(i);
        let end = if i + 1 < k {
            (b + overlap * (b - a)).min(last)
        } else {
            b
        };
        let sub = view.with_depth_range(a, end)?;
        let shadow = warp_prepared(&sub, &light, rule)?;
        let corners = sub.corners();
        let error =
            vertex_max(&shadow.matrix(), shadow.light_dir(), tan, &corners).ok_or_else(|| {
                Error::Degenerate(format!(
                "the map of partition {i} ([{}, {}]) puts a corner behind its centre of projection",
                fmt_num(a),
                fmt_num(end)
            ))
            })?;
        visit(&Cascade {
            shadow,
            split_near: a,
            split_far: b,
            error,
        });
    }
    Ok(())
}

/// A stable cascade: an orthographic map of a partition's bounding sphere, aligned with a
/// world-fixed light space and snapped to whole texels (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StableCascade {
    /// The stable map (eye → light clip, OpenGL depth), [`NPrime::UNWARPED`].
    pub shadow: ShadowMatrix,
    /// Centre of the partition's minimal bounding sphere, eye space (on the view axis).
    pub center: DVec3,
    /// Radius R of that sphere.
    pub radius: f64,
    /// Texel edge of the map in world units, `2 R_map / resolution`, where the map's half-width
    /// `R_map = R · resolution/(resolution − 2)` leaves one texel of margin on each side so that
    /// snapping (a shift of at most half a texel) never cuts the sphere.
    pub texel: f64,
    /// S̄ of the stable map over the partition's eight corners.
    pub storage_factor: f64,
    /// S̄ of the tight orthographic fit ([`WarpRule::Uniform`]) of the same partition.
    pub tight_storage_factor: f64,
}

impl StableCascade {
    /// What stability costs: `storage_factor / tight_storage_factor` (≥ 1 up to rounding).
    #[must_use]
    pub fn storage_loss(&self) -> f64 {
        self.storage_factor / self.tight_storage_factor
    }
}

/// The minimal bounding sphere of the sub-frustum `[near, far]` of `view`: centre on the view
/// axis at depth `c`, radius `R`.
///
/// With `k² = tan²θ (1 + aspect²)` (a corner at depth z is `z k` from the axis), equating the
/// distances to a near and a far corner, `(c − n)² + n² k² = (f − c)² + f² k²`, gives
/// `c = (n + f)(1 + k²)/2`; when that lies beyond the far plane the far cap alone decides and
/// `c = f`. Then `R = √((f − c)² + f² k²)`, computed without squaring a length, and padded by
/// 4 ulps of c + R for the rounding of c, so that the sphere contains every corner as computed.
///
/// # Errors
/// As [`ViewFrustum::with_depth_range`]; [`Error::Degenerate`] when `R` overflows `f64`.
///
/// ```
/// # use shadow_aliasing::maps::cascades::bounding_sphere;
/// # use shadow_aliasing::ViewFrustum;
/// // tan θ = 0.5, square: k² = 0.5; [1, 3]: c = 4 · 1.5/2 = 3 = f, R = 3 √0.5.
/// let v = ViewFrustum::new(1.0, 3.0, 0.5f64.atan())?;
/// let (c, r) = bounding_sphere(&v, 1.0, 3.0)?;
/// assert!((c - 3.0).abs() < 1e-12 && (r - 3.0 * 0.5f64.sqrt()).abs() < 1e-12);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn bounding_sphere(view: &ViewFrustum, near: f64, far: f64) -> Result<(f64, f64)> {
    let sub = view.with_depth_range(near, far)?;
    // k = tan θ √(1 + aspect²); no square of a length is formed, so nothing overflows before
    // the radius itself would (a k² or (n + f)(1 + k²) that overflows puts c at f, as it should).
    let k = sub.tan_half_fov() * 1f64.hypot(sub.aspect());
    let c = ((0.5 * near + 0.5 * far) * (1.0 + k * k)).min(far);
    // The computed c is a few ulps off the exact centre; R grows by 4 ulps of c + R so that every
    // corner lies inside the sphere as computed (a thin, distant partition has R ≪ c: at
    // c = 7.6·10⁷⁸, R = 7.5·10⁷¹ the unpadded sphere missed a corner by 1.2·10⁻⁹ R).
    let r = (far - c).hypot(far * k);
    let r = finite_result(
        "the bounding sphere's radius",
        r + 4.0 * f64::EPSILON * (c + r),
    )?;
    Ok((c, r))
}

/// A stable cascade for the partition `[near, far]` of `view`.
///
/// `world_to_eye` is the camera's view matrix (world → eye, rigid: rotation and translation,
/// glam `dcamera::rh::view::look_at_mat4`); `light_dir_world` the direction light travels in
/// *world* space (a stable map must not turn with the camera); `resolution` the map's texels per side (≥ 3). The light
/// space is [`light_space`](crate::maps::light_space)`(light_dir_world, −Z_world)`, fixed in the world. The sphere's centre,
/// in that light space, is snapped to the nearest multiple of the texel edge along s and t.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `world_to_eye` (not finite, or not rigid to 10⁻⁶),
/// `light_dir_world`, `resolution` (< 3), or as [`ViewFrustum::with_depth_range`].
pub fn stable_cascade(
    view: &ViewFrustum,
    world_to_eye: DMat4,
    light_dir_world: DVec3,
    near: f64,
    far: f64,
    resolution: u32,
) -> Result<StableCascade> {
    if resolution < 3 {
        return Err(Error::invalid(
            "resolution",
            format!("must be at least 3 texels (got {resolution})"),
        ));
    }
    let eye_to_world = rigid_inverse(world_to_eye)?;
    let lw = LightDir::new(light_dir_world)
        .map_err(|_| Error::invalid("light_dir_world", "must be a finite, non-zero vector"))?;
    let sub = view.with_depth_range(near, far)?;
    let (c, r) = bounding_sphere(view, near, far)?;
    let ls = light_space_dir(lw, DVec3::NEG_Z)?;
    let res = f64::from(resolution);
    let half = r * res / (res - 2.0);
    let texel = 2.0 * half / res;
    let center_eye = DVec3::new(0.0, 0.0, -c);
    let cw = eye_to_world.transform_point3(center_eye);
    let q = ls.to_light(cw);
    let sx = (q.x / texel).round() * texel;
    let sz = (q.z / texel).round() * texel;
    // Light space (world) → clip: s from x, t from z, depth from −y over the sphere (±half).
    let ortho = DMat4::from_cols(
        DVec4::new(1.0 / half, 0.0, 0.0, 0.0),
        DVec4::new(0.0, 0.0, -1.0 / half, 0.0),
        DVec4::new(0.0, 1.0 / half, 0.0, 0.0),
        DVec4::new(-sx / half, -sz / half, q.y / half, 1.0),
    );
    let matrix = ortho * ls.rotation() * eye_to_world;
    // A rigid transform of a unit vector, normalised against rounding.
    let light_eye = world_to_eye.transform_vector3(lw.as_dvec3()).normalize();
    let corners = sub.corners();
    let stable = vertex_max(&matrix, light_eye, view.tan_half_fov(), &corners)
        .ok_or_else(|| Error::Degenerate("the stable map is singular at a corner".into()))?;
    let tight_map = warp(&sub, light_eye, WarpRule::Uniform)?;
    let tight = vertex_max(
        &tight_map.matrix(),
        light_eye,
        view.tan_half_fov(),
        &corners,
    )
    .ok_or_else(|| Error::Degenerate("the tight map is singular at a corner".into()))?;
    Ok(StableCascade {
        shadow: ShadowMatrix::new(
            matrix,
            LightDir::from_unit_unchecked(light_eye),
            NPrime::UNWARPED,
            near,
            far,
        ),
        center: center_eye,
        radius: r,
        texel,
        storage_factor: stable.storage_factor,
        tight_storage_factor: tight.storage_factor,
    })
}

/// A frame's stable cascades, near to far, in a fixed array (no heap allocation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StableCascades {
    parts: [Option<StableCascade>; MAX_PARTITIONS],
    k: usize,
}

impl StableCascades {
    /// Number of partitions k.
    #[must_use]
    pub fn k(&self) -> usize {
        self.k
    }
    /// The partitions, near to far.
    pub fn iter(&self) -> impl Iterator<Item = &StableCascade> {
        self.parts[..self.k].iter().flatten()
    }
    /// Σ S̄ of the stable maps.
    #[must_use]
    pub fn storage_factor(&self) -> f64 {
        self.iter().map(|c| c.storage_factor).sum()
    }
    /// Σ S̄ of the tight orthographic fits of the same partitions.
    #[must_use]
    pub fn tight_storage_factor(&self) -> f64 {
        self.iter().map(|c| c.tight_storage_factor).sum()
    }
}

/// [`stable_cascade`] for every partition of `splits` (planes within the view's depth range).
///
/// # Errors
/// As [`stable_cascade`]; [`Error::InvalidArgument`] naming `splits` when a plane lies outside
/// `[view.near(), view.far()]`.
///
/// ```
/// use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
/// use shadow_aliasing::maps::cascades::stable_cascades;
/// use shadow_aliasing::ViewFrustum;
/// use glam::{DMat4, DVec3};
/// let view = ViewFrustum::new(0.5, 200.0, 0.6)?;
/// let splits = z_splits(0.5, 200.0, 4, SplitScheme::Practical { lambda: 0.8 })?;
/// let eye = DVec3::new(3.0, 2.0, 5.0);
/// let camera = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::ZERO, DVec3::Y);
/// let c = stable_cascades(&view, camera, DVec3::new(0.3, -1.0, 0.2), &splits, 2048)?;
/// assert_eq!(c.k(), 4);
/// assert!(c.storage_factor() >= c.tight_storage_factor());
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn stable_cascades(
    view: &ViewFrustum,
    world_to_eye: DMat4,
    light_dir_world: DVec3,
    splits: &Splits,
    resolution: u32,
) -> Result<StableCascades> {
    splits_within(view, splits)?;
    let mut parts = [None; MAX_PARTITIONS];
    for (i, part) in parts.iter_mut().enumerate().take(splits.k()) {
        let (a, b) = splits.range(i);
        *part = Some(stable_cascade(
            view,
            world_to_eye,
            light_dir_world,
            a,
            b,
            resolution,
        )?);
    }
    Ok(StableCascades {
        parts,
        k: splits.k(),
    })
}

/// The inverse of a rigid world → eye matrix, checked to be rigid.
fn rigid_inverse(world_to_eye: DMat4) -> Result<DMat4> {
    if !world_to_eye.is_finite() {
        return Err(Error::invalid("world_to_eye", "must have finite entries"));
    }
    let r = glam::DMat3::from_mat4(world_to_eye);
    let rrt = r * r.transpose();
    let off = (rrt - glam::DMat3::IDENTITY).to_cols_array();
    let bottom = world_to_eye.row(3);
    if off.iter().any(|v| v.abs() > 1e-6) || (bottom - DVec4::W).abs().max_element() > 1e-12 {
        return Err(Error::invalid(
            "world_to_eye",
            "must be a rigid transform (orthonormal rotation and a translation)",
        ));
    }
    Ok(world_to_eye.inverse())
}

/// Checks that split planes lie within the view's [near, far] (to a relative 10⁻¹²).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `splits`, with both ranges.
pub(crate) fn splits_within(view: &ViewFrustum, splits: &Splits) -> Result<()> {
    let planes = splits.planes();
    let (first, last) = (planes[0], planes[planes.len() - 1]);
    let slack = 1e-12 * view.far();
    if first < view.near() - slack || last > view.far() + slack {
        return Err(Error::invalid(
            "splits",
            format!(
                "must lie within [near, far] = [{}, {}] (got [{}, {}])",
                fmt_num(view.near()),
                fmt_num(view.far()),
                fmt_num(first),
                fmt_num(last)
            ),
        ));
    }
    Ok(())
}
