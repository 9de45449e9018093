//! The frame's inputs: the camera, the scene's bounds, the scheme, and their validation.

use super::MAX_BOUND_PLANES;
use crate::analytic::partition::SplitScheme;
use crate::error::{fmt_num, Error, Result};
use crate::frustum::{round3, ViewFrustum};
use crate::maps::faces::FaceWarp;
use crate::maps::{TsmOptions, WarpRule};
use glam::{DMat3, DMat4, DVec3, DVec4, Mat4};

/// A world-space axis-aligned box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// Smallest corner.
    pub min: DVec3,
    /// Largest corner.
    pub max: DVec3,
}

impl Aabb {
    /// From any value that converts into a [`DVec3`]: glam's own, `[f64; 3]`, or with the `mint`
    /// feature a `mint::Vector3<f64>` (another glam version's `DVec3` converts into one).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `min` when a coordinate is not finite or min > max.
    pub fn new(min: impl Into<DVec3>, max: impl Into<DVec3>) -> Result<Self> {
        let b = Self {
            min: min.into(),
            max: max.into(),
        };
        b.check()?;
        Ok(b)
    }

    pub(super) fn check(&self) -> Result<()> {
        if !self.min.is_finite() || !self.max.is_finite() || self.min.cmpgt(self.max).any() {
            return Err(Error::invalid(
                "min",
                format!(
                    "must be finite and not above max (got min={}, max={})",
                    self.min, self.max
                ),
            ));
        }
        Ok(())
    }

    /// The eight corners in the order of [`ViewFrustum::corners`] (min z face first).
    pub(super) fn corners(&self) -> [DVec3; 8] {
        let (a, b) = (self.min, self.max);
        let mut c = [DVec3::ZERO; 8];
        for (k, z) in [a.z, b.z].into_iter().enumerate() {
            c[4 * k] = DVec3::new(a.x, a.y, z);
            c[4 * k + 1] = DVec3::new(b.x, a.y, z);
            c[4 * k + 2] = DVec3::new(b.x, b.y, z);
            c[4 * k + 3] = DVec3::new(a.x, b.y, z);
        }
        c
    }
}

/// A world-space bound of receivers or casters.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Bound<'a> {
    /// No bound: receivers everywhere (B is the frustum); for casters, none known beyond B (the
    /// depth range is B's, as the frustum-only builders fit it; nearer casters need depth clamp).
    #[default]
    Unbounded,
    /// One or many boxes. Receivers: their merged bounding box (as OGRE). Casters: each box.
    Boxes(&'a [Aabb]),
    /// A bounded convex polytope, at most [`MAX_BOUND_PLANES`] world planes `(a, b, c, d)`,
    /// inside where `a x + b y + c z + d ≤ 0`.
    Polytope(&'a [DVec4]),
}

/// The camera: world → eye (rigid) and its projection.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    pub(super) world_to_eye: DMat4,
    pub(super) eye_to_world: DMat4,
    pub(super) view: ViewFrustum,
}

impl Camera {
    /// From the world → eye matrix (glam `dcamera::rh::view::look_at_mat4`: right-handed, looking
    /// down −Z) and the projection's near, far, half vertical field of view and aspect.
    /// `world_to_eye` is any value that converts into a [`DMat4`]: glam's own, or with the `mint`
    /// feature a `mint::ColumnMatrix4<f64>` (another glam version's `DMat4` converts into one;
    /// from plain arrays, [`DMat4::from_cols_array_2d`]).
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `world_to_eye` (not finite, or not a proper rigid
    /// transform: its 3 × 3 part a rotation to 10⁻⁶, no reflection, the bottom row (0, 0, 0, 1)
    /// to 10⁻¹²), or as [`ViewFrustum::with_aspect`].
    pub fn new(
        world_to_eye: impl Into<DMat4>,
        near: f64,
        far: f64,
        half_fov: f64,
        aspect: f64,
    ) -> Result<Self> {
        let world_to_eye: DMat4 = world_to_eye.into();
        let view = ViewFrustum::with_aspect(near, far, half_fov, aspect)?;
        if !world_to_eye.is_finite() {
            return Err(Error::invalid("world_to_eye", "must have finite entries"));
        }
        let r = DMat3::from_mat4(world_to_eye);
        let off = (r * r.transpose() - DMat3::IDENTITY).to_cols_array();
        let bottom = world_to_eye.row(3);
        if off.iter().any(|v| v.abs() > 1e-6)
            || (bottom - DVec4::W).abs().max_element() > 1e-12
            || r.determinant() <= 0.0
        {
            return Err(Error::invalid(
                "world_to_eye",
                "must be a rigid transform (rotation and translation)",
            ));
        }
        Ok(Self {
            world_to_eye,
            eye_to_world: world_to_eye.inverse(),
            view,
        })
    }

    /// As [`Camera::new`] for a single-precision view matrix (a [`Mat4`], or with the `mint`
    /// feature a `mint::ColumnMatrix4<f32>`), widened exactly to `f64`.
    ///
    /// # Errors
    /// As [`Camera::new`].
    pub fn from_mat4(
        world_to_eye: impl Into<Mat4>,
        near: f64,
        far: f64,
        half_fov: f64,
        aspect: f64,
    ) -> Result<Self> {
        Self::new(world_to_eye.into().as_dmat4(), near, far, half_fov, aspect)
    }

    /// The camera's view frustum.
    #[must_use]
    pub fn view(&self) -> &ViewFrustum {
        &self.view
    }

    /// World → eye.
    #[must_use]
    pub fn world_to_eye(&self) -> DMat4 {
        self.world_to_eye
    }
}

/// Where a warp's centre of projection lies across the warp axis (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum WarpCentre {
    /// As [`crate::maps::warp()`] builds each rule: on B's vertex nearest the camera for
    /// [`WarpRule::Ogre`] and [`WarpRule::OgreOrtho`], on the eye's light-space line otherwise.
    #[default]
    Rule,
    /// On the eye's own light-space line (`fit_warp`, Filament).
    Eye,
    /// On the light-space x and y of B's vertex nearest the camera (ties: the largest eye-space
    /// x + y, the top right of OGRE's `ConvexBody::define` order), as the LiSPSM reference code.
    /// OGRE (`OgreShadowCameraSetupLiSPSM.cpp`) takes the camera-nearest point of V ∩ S, the view
    /// frustum ∩ the scene's box, which is B's vertex when the receivers' bound is the scene's.
    NearestVertex,
}

/// How the view's depth range is split into cascades.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CascadeSplits<'a> {
    /// k cascades of a [`SplitScheme`] over the visible depth range; each partition but the last
    /// reaches `overlap` of its own depth into the next (the crate's overlap,
    /// [`crate::maps::cascades`]).
    Scheme {
        /// The split scheme.
        scheme: SplitScheme,
        /// Number of cascades, 1..=16.
        k: usize,
        /// Overlap fraction in [0, 1).
        overlap: f64,
    },
    /// Absolute split distances: every plane from the first cascade's near to the last's far,
    /// strictly increasing, inside the visible depth range.
    Distances {
        /// The planes z₀ < z₁ < … < z_k.
        planes: &'a [f64],
        /// Overlap fraction in [0, 1).
        overlap: f64,
    },
    /// Fractions 0 < φ₁ < … < φ_{k−1} < 1 of the visible depth range.
    Fractions {
        /// The interior fractions.
        fractions: &'a [f64],
        /// Overlap fraction in [0, 1).
        overlap: f64,
    },
    /// Bevy's `CascadeShadowConfigBuilder`: far bounds `first_far_bound · b^i` with
    /// `b = (maximum_distance/first_far_bound)^{1/(k−1)}` (`calculate_cascade_bounds`), the first
    /// cascade starting at `minimum_distance`, cascade i > 0 at `(1 − overlap_proportion)` times
    /// the previous far bound (the band cross-faded with the previous cascade), as
    /// `bevy_light/src/cascade.rs` computes them. Distances are clamped to the visible depth
    /// range (the crate's addition: Bevy does not clamp); k may reach 16 (Bevy renders at most
    /// `MAX_CASCADES_PER_LIGHT` = 4).
    Bevy {
        /// Number of cascades, 1..=16.
        k: usize,
        /// Near bound of the first cascade.
        minimum_distance: f64,
        /// Far bound of the last cascade.
        maximum_distance: f64,
        /// Far bound of the first cascade (ignored for k = 1).
        first_far_bound: f64,
        /// Overlap proportion in [0, 1).
        overlap_proportion: f64,
    },
    /// k cascades whose measured maximum errors over their focus bodies are equal (issue 24):
    /// the k − 1 planes found by a bounded root search on the measured error, over B's depth
    /// range within the visible one (SDSM), for the frame's rule and light. Stable cascades get
    /// them in closed form, B's range split logarithmically (which equalises a stable cascade's
    /// errors) with its ends moved outward onto a grid that keeps the planes under small camera
    /// moves, at a bounded cost in error (`frame/stable_splits.rs`, docs/renderer.md). With
    /// monotone errors no other splits of k cascades have a smaller largest error (stable
    /// cascades: but for the grid's cost); for a frustum-only body they are the logarithmic
    /// splits (Lloyd 2006 Eq 15–16). No overlap
    /// (no blend band): each map covers its selection range's part of B's depth range. The
    /// search: `frame/equal_error.rs` and docs/planning.md.
    EqualError {
        /// Number of cascades, 1..=16.
        k: usize,
    },
}

/// What the frame builds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FrameScheme<'a> {
    /// One map with any warp rule.
    Single(WarpRule),
    /// Cascades, each fitted with the rule to its own focus body.
    Cascades {
        /// The splits.
        splits: CascadeSplits<'a>,
        /// The rule of every cascade.
        rule: WarpRule,
    },
    /// Stable cascades: each cascade's s, t from its slice's bounding sphere in a world-fixed
    /// light space, snapped to whole texels ([`crate::maps::cascades::stable_cascade`]); the
    /// depth range from its focus body and the casters; no map for a slice whose body is empty.
    /// Since s, t do not come from B, a flat B seen edge-on by the light still gets its map
    /// ([`Focus::Flat`](crate::frame::Focus::Flat), where the other schemes say
    /// [`Focus::EdgeOn`](crate::frame::Focus::EdgeOn)).
    Stable(CascadeSplits<'a>),
    /// One trapezoidal map (Martin & Tan) of the focus body: the view-axis light space, B's
    /// vertices as E, the focus region B cut `focus × (f_B − n_B)/(f − n)` beyond B's nearest depth
    /// (the focus distance scaled to B's depth, as [`crate::maps::tsm::tsm_general`] does), the
    /// depth row refitted to B and the casters.
    Tsm(TsmOptions),
    /// Face partitions (Lloyd 2006 §5.1, Lloyd 2005 §4; [`crate::maps::faces`]) of the visible
    /// frustum, each side face cut at k self-similar depths, the near face whole: one map per face
    /// part, fitted to its own focus body B_i = B ∩ the prism of the face part along the light
    /// (the points of B whose light ray passes through that part of the face). The face rule's n′
    /// comes from B_i's extent along the face's warp axis (the face's own extent when B is the
    /// frustum), each part keeps the better of its two candidate axes, the depth covers B along
    /// the light and every caster that can shadow B_i, and the error is measured over B_i's
    /// vertices. A part whose B_i is empty gets no map.
    Faces {
        /// The face rule.
        rule: FaceWarp,
        /// Z-partitions per side face, 1..=[`MAX_FACE_K`](crate::frame::MAX_FACE_K) (4k + 1 maps fit the frame's slots).
        k: usize,
    },
    /// A clipmap, as Unreal 5's virtual shadow maps for a directional light (issue 24): nested,
    /// camera-centred orthographic levels of `map_resolution` texels, the radius doubling per
    /// level, each snapped to its pages; one map per level the visible depths need, finest
    /// first, each covering the depths where the shader picks it
    /// ([`LevelChoice`](crate::frame::LevelChoice), `frame/clipmap.rs`).
    Clipmap(ClipmapOptions),
}

/// Everything the frame needs (see the module docs). Build with [`FrameInput::new`] and the
/// setters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameInput<'a> {
    /// The camera.
    pub camera: Camera,
    /// The direction light travels, world space.
    pub light_dir_world: DVec3,
    /// The receivers' bound.
    pub receivers: Bound<'a>,
    /// The casters' bound.
    pub casters: Bound<'a>,
    /// The visible receivers' depth range `[z_min, z_max]` (a depth-buffer min/max reduction).
    pub depth_range: Option<(f64, f64)>,
    /// The map's texels per side (every map's, unless `map_resolutions` gives each its own).
    pub map_resolution: u32,
    /// Each partition's own texels per side, in slot order (cascade i, face part i in
    /// [`Frame::slots`](super::Frame::slots) order, the single map's slot 0), one entry per
    /// slot of the scheme; `None` (the default): every map at `map_resolution`. Equal-error
    /// splits place their planes by the maps' errors at one resolution (`map_resolution`: the
    /// planes equalise M_x, M_z, whatever it is), then each map is built at its own. Not with a
    /// clipmap, whose levels share one.
    pub map_resolutions: Option<&'a [u32]>,
    /// The image's height in pixels (the predicted error is in these pixels).
    pub image_height: u32,
    /// The device clamps depth: casters are not needed in the depth range.
    pub depth_clamp: bool,
    /// The scheme.
    pub scheme: FrameScheme<'a>,
    /// Where warps put their centre of projection.
    pub centre: WarpCentre,
    /// Report each map's error over its focus body (the default). `false` leaves the figures
    /// out: [`FrameMap::error`](super::FrameMap::error) is then `None` and the figures' fields
    /// hold +∞ (no bound known), unless the frame measured to build the map (face partitions fit
    /// each part by its measured error; equal-error splits are placed by it). The frame
    /// evaluates the map at B's vertices either way, since that is also its check that the map
    /// is regular there: whether a frame is built, and its matrices bit for bit, do not depend
    /// on `measure`.
    pub measure: bool,
}

impl<'a> FrameInput<'a> {
    /// A single minimax map of the whole frustum, no scene bounds, no depth clamp.
    /// `light_dir_world` is any value that converts into a [`DVec3`] (glam's own, `[f64; 3]`, or
    /// with the `mint` feature a `mint::Vector3<f64>`).
    #[must_use]
    pub fn new(
        camera: Camera,
        light_dir_world: impl Into<DVec3>,
        map_resolution: u32,
        image_height: u32,
    ) -> Self {
        Self {
            camera,
            light_dir_world: light_dir_world.into(),
            receivers: Bound::Unbounded,
            casters: Bound::Unbounded,
            depth_range: None,
            map_resolution,
            map_resolutions: None,
            image_height,
            depth_clamp: false,
            scheme: FrameScheme::Single(WarpRule::Minimax),
            centre: WarpCentre::Rule,
            measure: true,
        }
    }
    /// Sets the receivers' bound.
    #[must_use]
    pub fn receivers(mut self, b: Bound<'a>) -> Self {
        self.receivers = b;
        self
    }
    /// Sets the casters' bound.
    #[must_use]
    pub fn casters(mut self, b: Bound<'a>) -> Self {
        self.casters = b;
        self
    }
    /// Sets the visible depth range.
    #[must_use]
    pub fn depth_range(mut self, z_min: f64, z_max: f64) -> Self {
        self.depth_range = Some((z_min, z_max));
        self
    }
    /// Gives each partition its own resolution ([`FrameInput::map_resolutions`]): entry i is
    /// slot i's texels per side.
    #[must_use]
    pub fn map_resolutions(mut self, each: &'a [u32]) -> Self {
        self.map_resolutions = Some(each);
        self
    }
    /// Slot `slot`'s texels per side: its `map_resolutions` entry, else `map_resolution`. (A
    /// slot past the entries is refused by the frame before any map is built.)
    pub(super) fn resolution_at(&self, slot: usize) -> u32 {
        self.map_resolutions
            .and_then(|r| r.get(slot).copied())
            .unwrap_or(self.map_resolution)
    }
    /// Says whether the device clamps depth.
    #[must_use]
    pub fn depth_clamp(mut self, on: bool) -> Self {
        self.depth_clamp = on;
        self
    }
    /// Sets the scheme.
    #[must_use]
    pub fn scheme(mut self, s: FrameScheme<'a>) -> Self {
        self.scheme = s;
        self
    }
    /// Sets the warp centre.
    #[must_use]
    pub fn centre(mut self, c: WarpCentre) -> Self {
        self.centre = c;
        self
    }
    /// Says whether to measure each map's error ([`FrameInput::measure`]; on by default).
    #[must_use]
    pub fn measure(mut self, on: bool) -> Self {
        self.measure = on;
        self
    }
    /// Whether the maps' error is measured: asked for, or needed to place equal-error splits.
    pub(super) fn measures(&self) -> bool {
        self.measure
            || matches!(
                self.scheme,
                FrameScheme::Cascades {
                    splits: CascadeSplits::EqualError { .. },
                    ..
                } | FrameScheme::Stable(CascadeSplits::EqualError { .. })
            )
    }
}

/// `map_resolutions` against the scheme's `slots` partitions: one entry at least 3 per slot
/// (face partitions: at least one per slot, as their slot count depends on the faces the light
/// sees); a clipmap (levels of one resolution) refused.
pub(super) fn check_resolutions(input: &FrameInput<'_>, slots: usize) -> Result<()> {
    let Some(each) = input.map_resolutions else {
        return Ok(());
    };
    if matches!(input.scheme, FrameScheme::Clipmap(_)) {
        return Err(Error::invalid(
            "map_resolutions",
            "cannot be used with a clipmap: its levels share one resolution (its knob is the \
             LOD bias); give one map_resolution",
        ));
    }
    if let Some(r) = each.iter().find(|&&r| r < 3) {
        return Err(Error::invalid(
            "map_resolutions",
            format!("must hold resolutions of at least 3 texels each (got {r})"),
        ));
    }
    let faces = matches!(input.scheme, FrameScheme::Faces { .. });
    if each.len() < slots || (!faces && each.len() != slots) {
        return Err(Error::invalid(
            "map_resolutions",
            format!(
                "has {} entries, and the scheme has {slots} partitions: give one resolution per \
                 partition, in slot order",
                each.len()
            ),
        ));
    }
    Ok(())
}

/// The frame resolves extents down to 10⁻⁹ of a slice's size (`frame/body.rs`): a frustum
/// whose narrowest cross-section (2 tan θ min(aspect, 1) per unit depth) or whose depth is below
/// [`MIN_PROPORTION`] of its size (1 + tan θ (1 + aspect) per unit depth) is too thin for it to
/// tell a body in view from none.
pub(super) const MIN_PROPORTION: f64 = 1e-6;

/// Whether the frustum of `tan θ` and `aspect` is within the frame's resolution
/// ([`MIN_PROPORTION`]).
fn proportions_ok(t: f64, aspect: f64) -> bool {
    let size = MIN_PROPORTION * (1.0 + t * (1.0 + aspect));
    2.0 * t * aspect.min(1.0) >= size && 1.0 >= size
}

/// The camera's frustum within what the frame resolves ([`MIN_PROPORTION`]): an error naming
/// `half_fov` (when even a square frustum of it is too thin or too wide) or `aspect`, with the
/// range that is resolved.
pub(super) fn check_proportions(view: &ViewFrustum) -> Result<()> {
    let (t, a) = (view.tan_half_fov(), view.aspect());
    if proportions_ok(t, a) {
        return Ok(());
    }
    Err(proportions_error(t, a, view.half_fov()))
}

#[cold]
#[inline(never)]
fn proportions_error(t: f64, a: f64, half_fov: f64) -> Error {
    let why = "the frame tells a body in view from none down to 10⁻⁹ of the frustum's size, so \
               its narrowest cross-section and its depth must be at least 10⁻⁶ of that size";
    if proportions_ok(t, 1.0) {
        // 2 t a ≥ p (1 + t + t a) for a < 1; 2 t ≥ p (1 + t (1 + a)) and 1 ≥ p (1 + t (1 + a))
        // for a > 1 (p = MIN_PROPORTION), each bound rounded inward.
        let p = MIN_PROPORTION;
        let lo = round3(p * (1.0 + t) / (t * (2.0 - p)), true);
        let hi = round3(
            ((2.0 * t / p - 1.0) / t - 1.0).min((1.0 / p - 1.0) / t - 1.0),
            false,
        );
        return Error::invalid(
            "aspect",
            format!(
                "is too {} for this field of view: {why}; give aspect within [{}, {}] at \
                 half_fov {} (got aspect={})",
                if a < 1.0 { "small" } else { "large" },
                fmt_num(lo),
                fmt_num(hi),
                fmt_num(half_fov),
                fmt_num(a)
            ),
        );
    }
    // For a square frustum: 2 t ≥ p (1 + 2 t) and 1 ≥ p (1 + 2 t).
    let p = MIN_PROPORTION;
    let lo = round3((p / (2.0 - 2.0 * p)).atan(), true);
    let hi = round3(((1.0 / p - 1.0) / 2.0).atan(), false);
    Error::invalid(
        "half_fov",
        format!(
            "is too {}: {why}; give half_fov within [{}, {}] radians (at aspect 1; an aspect far \
             from 1 narrows it) (got half_fov={})",
            if t < 1.0 { "small" } else { "large" },
            fmt_num(lo),
            fmt_num(hi),
            fmt_num(half_fov)
        ),
    )
}

/// The visible depth range: the camera's, cut to `[z_min, z_max]`.
pub(super) fn visible_range(view: &ViewFrustum, range: Option<(f64, f64)>) -> Result<(f64, f64)> {
    let (n, f) = (view.near(), view.far());
    let Some((a, b)) = range else {
        return Ok((n, f));
    };
    if !(a.is_finite() && b.is_finite() && a < b) {
        return Err(Error::invalid(
            "depth_range",
            format!(
                "must be finite with z_min < z_max (got [{}, {}])",
                fmt_num(a),
                fmt_num(b)
            ),
        ));
    }
    let (a, b) = (a.max(n), b.min(f));
    if a >= b {
        return Err(Error::invalid(
            "depth_range",
            format!(
                "must overlap the camera's [near, far] = [{}, {}] in a range",
                fmt_num(n),
                fmt_num(f)
            ),
        ));
    }
    Ok((a, b))
}

pub(super) fn bad_box(name: &'static str, b: &Aabb) -> Error {
    Error::invalid(
        name,
        format!(
            "boxes must be finite with min not above max (got min={}, max={})",
            b.min, b.max
        ),
    )
}

pub(super) fn validate_casters(b: &Bound<'_>) -> Result<()> {
    match b {
        Bound::Unbounded => Ok(()),
        Bound::Boxes(boxes) => {
            for bx in *boxes {
                bx.check().map_err(|_| bad_box("casters", bx))?;
            }
            Ok(())
        }
        Bound::Polytope(planes) => validate_polytope("casters", planes),
    }
}

/// A bound's polytope, for the argument `name` (`receivers` or `casters`): 1 to
/// [`MAX_BOUND_PLANES`] planes, each finite with a non-zero normal. The error gives the count,
/// or the first bad plane and its index.
pub(super) fn validate_polytope(name: &'static str, planes: &[DVec4]) -> Result<()> {
    if planes.is_empty() || planes.len() > MAX_BOUND_PLANES {
        return Err(Error::invalid(
            name,
            format!(
                "a polytope must have 1 to {MAX_BOUND_PLANES} planes (got {}): merge or drop \
                 planes, or give boxes instead",
                planes.len()
            ),
        ));
    }
    match planes
        .iter()
        .position(|p| !p.is_finite() || p.truncate().length() <= 0.0)
    {
        Some(i) => Err(Error::invalid(
            name,
            format!(
                "planes must be finite with a non-zero normal (got {} at index {i})",
                planes[i]
            ),
        )),
        None => Ok(()),
    }
}

/// The levels that [`ClipmapOptions`] accepts: −64..=64 (radii 2^−63 to 2^65 units).
const LEVEL_RANGE: std::ops::RangeInclusive<i32> = -64..=64;

/// The LOD biases that [`ClipmapOptions`] accepts: a texel 2^±32 pixels wide is not a shadow.
const MAX_LOD_BIAS: f64 = 32.0;

/// The layout of a clipmap ([`FrameScheme::Clipmap`](super::FrameScheme::Clipmap)); the levels'
/// resolution is the frame's `map_resolution`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClipmapOptions {
    /// The finest level (Unreal `r.Shadow.Virtual.Clipmap.FirstLevel`, 6).
    pub first_level: i32,
    /// The coarsest level (Unreal `r.Shadow.Virtual.Clipmap.LastLevel`, 22).
    pub last_level: i32,
    /// The LOD bias b: the chosen level's texel is at most 2^b pixels, and more than 2^{b−1}
    /// (Unreal `r.Shadow.Virtual.ResolutionLodBiasDirectional`, −0.5; −1 doubles the
    /// resolution).
    pub lod_bias: f64,
    /// The world length of one unit of the level sizes: level i covers radius 2^{i+1} units.
    /// Unreal's unit is the centimetre, so 0.01 for a world in metres.
    pub unit: f64,
    /// Texels per page side (Unreal 128); divides the map resolution, at least 2 pages a side.
    pub page_texels: u32,
}

impl ClipmapOptions {
    /// Unreal 5's defaults for a world in metres: levels 6 to 22 of radius 2^{i+1} cm, LOD bias
    /// −0.5, pages of 128² texels (with a `map_resolution` of 16 384: 128 × 128 pages).
    pub const UNREAL: Self = Self {
        first_level: 6,
        last_level: 22,
        lod_bias: -0.5,
        unit: 0.01,
        page_texels: 128,
    };

    /// The half-width of level `level`'s square, world units: `2^{level+2} · unit`.
    #[must_use]
    pub fn half_width(&self, level: i32) -> f64 {
        self.unit * f64::from(level + 2).exp2()
    }

    /// The radius around the camera that level `level` covers, world units: `2^{level+1} · unit`.
    #[must_use]
    pub fn radius(&self, level: i32) -> f64 {
        self.unit * f64::from(level + 1).exp2()
    }

    /// Every field in its domain, for levels of `resolution` texels.
    pub(crate) fn check(&self, resolution: u32) -> Result<()> {
        for (name, l) in [
            ("first_level", self.first_level),
            ("last_level", self.last_level),
        ] {
            if !LEVEL_RANGE.contains(&l) {
                return Err(Error::invalid(
                    name,
                    format!(
                        "must be in {}..={} (got {l}): the levels' radii 2^(level+1) · unit \
                         must be finite; change unit instead",
                        LEVEL_RANGE.start(),
                        LEVEL_RANGE.end()
                    ),
                ));
            }
        }
        if self.first_level > self.last_level {
            return Err(Error::invalid(
                "first_level",
                format!(
                    "must not exceed last_level (got first_level={}, last_level={})",
                    self.first_level, self.last_level
                ),
            ));
        }
        if !(self.lod_bias.is_finite() && self.lod_bias.abs() <= MAX_LOD_BIAS) {
            return Err(Error::invalid(
                "lod_bias",
                format!(
                    "must be finite and within ±{MAX_LOD_BIAS} (got {}); Unreal's default is -0.5",
                    fmt_num(self.lod_bias)
                ),
            ));
        }
        if !(self.unit.is_finite() && self.unit > 0.0) {
            return Err(Error::invalid(
                "unit",
                format!(
                    "must be a finite length > 0 (got {}): 0.01 for a world in metres (Unreal's \
                     levels are in centimetres)",
                    fmt_num(self.unit)
                ),
            ));
        }
        let p = self.page_texels;
        if p == 0 || !resolution.is_multiple_of(p) || resolution / p < 2 {
            return Err(Error::invalid(
                "page_texels",
                format!(
                    "must divide map_resolution into at least 2 pages a side (got page_texels={p}, \
                     map_resolution={resolution}); Unreal's pages are 128 texels of 16384"
                ),
            ));
        }
        Ok(())
    }
}

impl Default for ClipmapOptions {
    /// [`ClipmapOptions::UNREAL`].
    fn default() -> Self {
        Self::UNREAL
    }
}
