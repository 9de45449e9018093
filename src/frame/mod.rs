//! The frame API: a renderer's one call per light per frame, in world space, with the map focused
//! on the scene (issue 9).
//!
//! # The focus body
//!
//! B = (the view frustum, or a cascade's slice of it, cut to the visible depth range) ∩ the
//! receivers' bound, by exact convex clipping (Sutherland–Hodgman on every face of the frustum,
//! each cut closed by a cap face, in fixed arrays). Several receiver boxes combine as their merged
//! bounding box (as OGRE does). B is *empty* when the intersection has no volume: a box that only
//! touches the frustum at a face, an edge or a point gives no map ([`Focus::Empty`], "no map
//! needed"). A receivers' bound that is itself flat (a ground plane of zero thickness) gives a
//! flat B, which is mapped ([`Focus::Flat`]) as long as the light sees it with an area.
//!
//! The casters that can shadow B are the casters' bound ∩ the sweep of B toward the light. For the
//! maps' depth only the point of that set nearest the light matters, and over the prism of B's
//! light-space footprint (x, z) it is the same point (a point of the prism nearer the light than
//! every point of B lies in the sweep), so each caster box is clipped by the prism's side planes
//! and its vertex nearest the light (in the warp's depth, y/w) extends the depth range. With
//! `depth_clamp` the casters are not looked at: the map's depth covers B alone and casters nearer
//! the light fall below the map's near depth (0, or −1 in OpenGL's convention), which the device
//! clamps ("pancaking").
//!
//! # Conventions (the tests and the command line rely on them)
//!
//! - Light space is [`crate::maps::light_space`]'s: the warp axis is the view direction projected
//!   perpendicular to the light whatever B is (not B's centroid, as
//!   [`crate::maps::tsm::tsm_general`] does).
//! - s, t are fitted to B's vertices: the uniform map to the bounding rectangle of B's vertices in
//!   light space; a warp of parameter n′ with its centre of projection on the eye's own light-space
//!   line ([`WarpCentre::Eye`], as [`crate::maps::fit_warp`] and Filament do), or on B's vertex
//!   nearest the camera ([`WarpCentre::NearestVertex`], the LiSPSM reference code's and OGRE's
//!   `C_start`); n′ is measured from B's nearest extent along the warp axis, f′ = n′ + B's depth
//!   along it.
//! - Every n′ rule sees B's eye-depth range `[n_B, f_B]` as its frustum (as a z-partition's rule
//!   sees its partition): the papers' rules use n_B, f_B; the LiSPSM reference code's z₀ is n_B and
//!   its d is B's extent Δ_B along the warp axis; Filament's z₀ is n_B (the nearest receiver) with d
//!   = Δ_B and its hints measured from the camera's planes; OGRE's e_z is n_B with the camera's
//!   √(n f); TSM's focus distance is scaled by (f_B − n_B)/(slice depth), as
//!   [`crate::maps::tsm::tsm_general`] does; minimax minimises S̄ over B's vertices with the eye's
//!   centre, or with B's nearest vertex's under [`WarpCentre::NearestVertex`] (the centre of the
//!   map that is built), so it is never above the uniform map over B.
//! - Casters only extend the light-depth range (or rely on depth clamp), never s, t or S̄.
//! - The error is measured over B's vertices ([`crate::measure::vertex::vertex_max`]): the papers'
//!   warps have m_x quasi-linear and m_z convex over a convex body, so the maxima lie at vertices
//!   (tests/frame.rs checks it densely).
//! - Face partitions ([`FrameScheme::Faces`]): the part B_i of B whose light rays pass a face
//!   part is B clipped by the prism of that part along the light; n′ and s, t come from B_i's
//!   vertices on the face's own warp axes ([`crate::maps::faces`]), the depth covers B's extent
//!   along the light (as the frustum-only builder covers the frustum's) and the casters of B_i.
//! - A receivers' bound that contains the frustum (slice) gives the frustum-only builders'
//!   matrices: [`crate::maps::warp()`], [`crate::maps::cascades::cascades`] bit for bit,
//!   [`crate::maps::faces::face_partitions`] to within the clipper's rounding (B_i's vertices come
//!   from the clipper): 10⁻¹² relative at ordinary depth ratios (tests/frame_faces.rs), more where
//!   the face warp is ill-conditioned (1.4·10⁻⁹ at f/n = 3274, half field of view 55°, PSM, k = 2,
//!   a review found).
//!
//! ```
//! use glam::{DMat4, DVec3};
//! use shadow_aliasing::frame::{frame, Aabb, Bound, Camera, FrameInput, FrameScheme, Focus};
//! use shadow_aliasing::maps::{ClipDepth, WarpRule};
//! let view = glam::dcamera::rh::view::look_at_mat4(DVec3::new(0.0, 2.0, 0.0), DVec3::new(0.0, 2.0, -1.0), DVec3::Y);
//! let camera = Camera::new(view, 0.1, 1000.0, 30f64.to_radians(), 16.0 / 9.0)?;
//! let ground = [Aabb::new(DVec3::new(-50.0, -1.0, -100.0), DVec3::new(50.0, 0.0, 0.0))?];
//! let input = FrameInput::new(camera, DVec3::new(0.3, -1.0, -0.2), 2048, 1080)
//!     .receivers(Bound::Boxes(&ground))
//!     .casters(Bound::Boxes(&ground))
//!     .scheme(FrameScheme::Single(WarpRule::Lispsm));
//! let f = frame(&input)?;
//! assert_eq!(f.focus(), Focus::Body);
//! let map = &f.maps()[0];
//! let gpu = map.to_mat4(ClipDepth::ZeroToOne); // world → light clip, upload per frame
//! assert!(gpu.is_finite() && map.texel_world > 0.0);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::analytic::partition::{z_splits, SplitScheme, Splits, MAX_PARTITIONS};
use crate::error::{fmt_num, in_closed, positive, Error, Result};
use crate::frustum::{LightDir, NPrime, ViewFrustum};
use crate::geom::polytope::{extents, ConvexBody};
use crate::maps::cascades::{bounding_sphere, splits_between};
use crate::maps::faces::{face_spaces, visible_with, Face, FaceSpaces, FaceWarp, PartFitter};
use crate::maps::lightspace::{light_space_unit, LightSpace};
use crate::maps::matrix::zero_to_one;
use crate::maps::tsm::{tsm_on_points, validate as validate_tsm};
use crate::maps::warp::{
    fit_body, focus_in_range, rule_axis, rule_n_prime_on, verify_clip, warp_prepared,
    FrustumInLight, PreparedLight,
};
use crate::maps::{ClipDepth, ShadowMatrix, TsmOptions, WarpRule};
use crate::measure::vertex::vertex_max;
use crate::measure::FrustumError;
use crate::numeric::{fmax, EDGE_ON};
use glam::{DMat3, DMat4, DVec2, DVec3, DVec4, Mat4};

/// The largest number of vertices of a focus body (a frustum slice cut by up to 6 planes has at
/// most 2·12 − 4 = 20; the rest is room for a polytope bound's extra planes).
pub const MAX_BODY_VERTICES: usize = 32;

/// The largest number of planes of a [`Bound::Polytope`].
pub const MAX_BOUND_PLANES: usize = 12;

/// The largest k of [`FrameScheme::Faces`]: 4 side faces × k parts + the near face fit the
/// frame's [`MAX_PARTITIONS`] slots.
pub const MAX_FACE_K: usize = (MAX_PARTITIONS - 1) / 4;

/// The largest number of planes of a receivers' [`Bound::Polytope`] with [`FrameScheme::Faces`]:
/// with the frustum's 6 and a face part's 4 prism planes, B_i has at most 2·18 − 4 = 32 vertices,
/// what a map holds.
pub const MAX_FACE_BOUND_PLANES: usize = 8;

/// The receivers' body: 6 frustum faces + 12 bound planes, a face at most 4 + 12 vertices, at
/// most 2·18 − 4 = 32 vertices (a margin for points that coincide within the tolerance).
type BodyClip = ConvexBody<18, 18, 48>;
/// A caster box cut by the prism of B's footprint (at most 20 edges): 26 faces of at most 24,
/// at most 48 vertices.
type CasterClip = ConvexBody<28, 28, 64>;
/// A caster polytope: a box, 12 planes and the prism.
type PolytopeClip = ConvexBody<40, 40, 96>;

/// A world-space axis-aligned box.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    /// Smallest corner.
    pub min: DVec3,
    /// Largest corner.
    pub max: DVec3,
}

impl Aabb {
    /// # Errors
    /// [`Error::InvalidArgument`] naming `min` when a coordinate is not finite or min > max.
    pub fn new(min: DVec3, max: DVec3) -> Result<Self> {
        let b = Self { min, max };
        b.check()?;
        Ok(b)
    }

    fn check(&self) -> Result<()> {
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
    fn corners(&self) -> [DVec3; 8] {
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
    world_to_eye: DMat4,
    eye_to_world: DMat4,
    view: ViewFrustum,
}

impl Camera {
    /// From the world → eye matrix (glam `dcamera::rh::view::look_at_mat4`: right-handed, looking
    /// down −Z) and the projection's near, far, half vertical field of view and aspect.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `world_to_eye` (not finite, or not a proper rigid
    /// transform: its 3 × 3 part a rotation to 10⁻⁶, no reflection, the bottom row (0, 0, 0, 1)
    /// to 10⁻¹²), or as [`ViewFrustum::with_aspect`].
    pub fn new(
        world_to_eye: DMat4,
        near: f64,
        far: f64,
        half_fov: f64,
        aspect: f64,
    ) -> Result<Self> {
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

    /// As [`Camera::new`] for a single-precision view matrix.
    ///
    /// # Errors
    /// As [`Camera::new`].
    pub fn from_mat4(
        world_to_eye: Mat4,
        near: f64,
        far: f64,
        half_fov: f64,
        aspect: f64,
    ) -> Result<Self> {
        Self::new(world_to_eye.as_dmat4(), near, far, half_fov, aspect)
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
    /// ([`Focus::Flat`], where the other schemes say [`Focus::EdgeOn`]).
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
        /// Z-partitions per side face, 1..=[`MAX_FACE_K`] (4k + 1 maps fit the frame's slots).
        k: usize,
    },
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
    /// The map's texels per side.
    pub map_resolution: u32,
    /// The image's height in pixels (the predicted error is in these pixels).
    pub image_height: u32,
    /// The device clamps depth: casters are not needed in the depth range.
    pub depth_clamp: bool,
    /// The scheme.
    pub scheme: FrameScheme<'a>,
    /// Where warps put their centre of projection.
    pub centre: WarpCentre,
}

impl<'a> FrameInput<'a> {
    /// A single minimax map of the whole frustum, no scene bounds, no depth clamp.
    #[must_use]
    pub fn new(
        camera: Camera,
        light_dir_world: DVec3,
        map_resolution: u32,
        image_height: u32,
    ) -> Self {
        Self {
            camera,
            light_dir_world,
            receivers: Bound::Unbounded,
            casters: Bound::Unbounded,
            depth_range: None,
            map_resolution,
            image_height,
            depth_clamp: false,
            scheme: FrameScheme::Single(WarpRule::Minimax),
            centre: WarpCentre::Rule,
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
}

/// What the focus body is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Focus {
    /// A body with volume: maps built.
    #[default]
    Body,
    /// The scene is out of view (B has no volume, touching included): no map needed.
    Empty,
    /// The receivers' bound is flat (no thicker than 10⁻⁹ of the frustum's size: a box with
    /// min = max in one coordinate or nearly, or a polytope with two opposite planes at the same
    /// place) and B is a polygon: mapped.
    Flat,
    /// B has no area as the light sees it (no extent across or along the warp axis, or its
    /// footprint a line in any direction: an edge-on flat receiver): no map can be fitted to it
    /// and none is needed (stable cascades, whose square does not depend on B, map it anyway).
    EdgeOn,
    /// B has no extent in eye depth (f_B = n_B, a wall facing the camera): mapped with n′ = ∞,
    /// since every warp rule needs a depth range. Single maps and cascades report it; TSM,
    /// stable cascades and face partitions fit such a B with their own construction and report
    /// it as `Body` or `Flat`.
    ZeroDepth,
}

/// The light's relation to the camera and the world.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum LightCase {
    /// Nothing special.
    #[default]
    General,
    /// The light travels straight down the world's −Y (no world-up vector is used: the warp axis is
    /// the view direction projected, so nothing degenerates).
    SunStraightDown,
    /// The light is parallel to the view direction (sin γ < 10⁻⁶): every rule's map is (close to)
    /// the uniform map, in the fallback light space of [`crate::maps::lightspace`].
    ParallelToView,
}

/// One map of a frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrameMap {
    /// Eye → light clip (OpenGL depth), with n′ and the eye-depth range of its body.
    pub shadow: ShadowMatrix,
    /// World → light clip, OpenGL depth [−1, 1].
    pub world_to_clip: DMat4,
    /// The view-depth range where the shader selects this map.
    pub split: (f64, f64),
    /// The band at the far end of `split` (or beyond it) that this map and the next both cover,
    /// to cross-fade over; `(split.1, split.1)` when there is none.
    pub blend: (f64, f64),
    /// The largest world-space texel edge over the body at the map's resolution (normal-offset
    /// bias: Bevy's `texel_size`, Filament's `texelSizeWorldSpace`).
    pub texel_world: f64,
    /// M_x over the body's vertices (unit resolutions).
    pub max_mx: f64,
    /// M_z over the body's vertices (unit resolutions).
    pub max_mz: f64,
    /// S̄ = M_x M_z over the body.
    pub storage_factor: f64,
    /// The predicted maximum error in screen pixels, `max(M_x, M_z) · image_height /
    /// map_resolution`.
    pub max_error_pixels: f64,
    /// What the body is (Body, Flat or ZeroDepth for a built map).
    pub focus: Focus,
    /// The frustum face of a face partition (the shader picks the map by the face its light ray
    /// passes and, for a side face, by `split`, the depths of that part of the face); `None` for
    /// every other scheme.
    pub face: Option<Face>,
    world_to_eye: DMat4,
    body: [DVec3; MAX_BODY_VERTICES],
    body_len: usize,
}

impl FrameMap {
    /// World → light clip in the requested clip-depth convention.
    #[must_use]
    pub fn world_to_clip(&self, depth: ClipDepth) -> DMat4 {
        match depth {
            ClipDepth::NegOneToOne => self.world_to_clip,
            ClipDepth::ZeroToOne => zero_to_one(&self.shadow.matrix()) * self.world_to_eye,
        }
    }
    /// [`FrameMap::world_to_clip`] in single precision for the GPU.
    #[must_use]
    pub fn to_mat4(&self, depth: ClipDepth) -> Mat4 {
        self.world_to_clip(depth).as_mat4()
    }
    /// The focus body's vertices, eye space.
    #[must_use]
    pub fn body(&self) -> &[DVec3] {
        &self.body[..self.body_len]
    }
}

/// A frame's maps, in a fixed array (no heap allocation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    maps: [Option<FrameMap>; MAX_PARTITIONS],
    /// Slot i of the scheme's partitions (None where its body is empty).
    k: usize,
    len: usize,
    /// A partition without a map was edge-on to the light.
    none_edge_on: bool,
    focus: Focus,
    light: LightCase,
    light_dir_eye: DVec3,
}

impl Default for Frame {
    /// An empty frame, for [`frame_into`] to fill.
    fn default() -> Self {
        Self {
            maps: [None; MAX_PARTITIONS],
            k: 0,
            len: 0,
            none_edge_on: false,
            focus: Focus::Empty,
            light: LightCase::General,
            light_dir_eye: DVec3::NEG_Y,
        }
    }
}

impl Frame {
    /// The built maps: near to far for cascades (those whose body is empty are left out), in
    /// face order (bottom, right, top, left, then the near or far face; each side face's parts near
    /// to far) for face partitions.
    pub fn maps(&self) -> FrameMaps<'_> {
        FrameMaps(&self.maps[..self.k])
    }
    /// The partition slots, `None` where the slice's body is empty (no map needed).
    #[must_use]
    pub fn slots(&self) -> &[Option<FrameMap>] {
        &self.maps[..self.k]
    }
    /// The number of maps built.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }
    /// No map built: the scene is out of view (or edge-on to the light).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
    /// The focus of the whole frame: the first built map's, or why none was built.
    #[must_use]
    pub fn focus(&self) -> Focus {
        self.focus
    }
    /// The light's case.
    #[must_use]
    pub fn light_case(&self) -> LightCase {
        self.light
    }
    /// The unit direction light travels, eye space.
    #[must_use]
    pub fn light_dir_eye(&self) -> DVec3 {
        self.light_dir_eye
    }
    /// Σ S̄ over the built maps, `None` when none was built.
    #[must_use]
    pub fn storage_factor(&self) -> Option<f64> {
        (self.len > 0).then(|| self.maps().iter().map(|m| m.storage_factor).sum())
    }
}

/// The built maps of a [`Frame`], indexable and iterable.
#[derive(Debug, Clone, Copy)]
pub struct FrameMaps<'f>(&'f [Option<FrameMap>]);

impl<'f> FrameMaps<'f> {
    /// The built maps in order.
    pub fn iter(&self) -> impl Iterator<Item = &'f FrameMap> {
        self.0.iter().flatten()
    }
    /// The number of built maps.
    #[must_use]
    pub fn len(&self) -> usize {
        self.iter().count()
    }
    /// Whether no map was built.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

impl std::ops::Index<usize> for FrameMaps<'_> {
    type Output = FrameMap;
    fn index(&self, i: usize) -> &FrameMap {
        self.0
            .iter()
            .flatten()
            .nth(i)
            .expect("map index out of range")
    }
}

impl Frame {
    /// Puts the next partition's outcome into slot `k` (`None` where no map is needed).
    fn push(&mut self, m: Built) {
        self.maps[self.k] = match m {
            Built::Map(m) => {
                self.len += 1;
                Some(m)
            }
            Built::None(f) => {
                self.none_edge_on |= f == Focus::EdgeOn;
                None
            }
        };
        self.k += 1;
    }

    /// The frame's focus once every partition is in: the first built map's, or why none was
    /// built (edge-on if any partition was, else empty).
    fn settle(&mut self) {
        let first = self.maps().iter().next().map(|m| m.focus);
        self.focus = match first {
            Some(f) => f,
            None if self.none_edge_on => Focus::EdgeOn,
            None => Focus::Empty,
        };
    }
}

/// One slice to map: covered depth range, selection range, blend band.
#[derive(Debug, Clone, Copy)]
struct Slice {
    cover: (f64, f64),
    split: (f64, f64),
    blend: (f64, f64),
}

/// The receivers' bound as eye-space planes.
#[derive(Debug, Clone, Copy)]
struct Planes {
    p: [DVec4; MAX_BOUND_PLANES],
    n: usize,
    /// The bound itself has no volume (a flat box).
    flat: bool,
}

/// The frame's maps (module docs). No heap allocation on success or for the typed outcomes.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir_world`, `map_resolution` (< 3), `image_height`
/// (0), `depth_range` (not finite, z_min ≥ z_max, or no overlap with the camera's [near, far]),
/// `receivers`/`casters` (a bad box, too many planes — more than [`MAX_FACE_BOUND_PLANES`] with
/// face partitions — a polytope unbounded toward the light; for receivers also an empty list of
/// boxes, while an empty list of casters is no caster), `overlap`, `k` (1..=[`MAX_FACE_K`] for face
/// partitions), the splits or the rule's parameter; [`Error::Degenerate`] when a map cannot be
/// represented in `f64`, or its world → clip matrix (either depth convention) not in `f32`
/// (a camera very far from the world origin: its translation times the map's scale overflows).
pub fn frame(input: &FrameInput<'_>) -> Result<Frame> {
    let mut out = Frame::default();
    frame_into(input, &mut out)?;
    Ok(out)
}

/// As [`frame`], writing into `out` (reused between frames).
///
/// # Errors
/// As [`frame`].
pub fn frame_into(input: &FrameInput<'_>, out: &mut Frame) -> Result<()> {
    out.k = 0;
    out.len = 0;
    out.none_edge_on = false;
    out.focus = Focus::Empty;
    let cam = &input.camera;
    let lw = LightDir::new(input.light_dir_world)
        .map_err(|_| Error::invalid("light_dir_world", "must be a finite, non-zero vector"))?
        .as_dvec3();
    if input.map_resolution < 3 {
        return Err(Error::invalid(
            "map_resolution",
            format!("must be at least 3 texels (got {})", input.map_resolution),
        ));
    }
    if input.image_height == 0 {
        return Err(Error::invalid("image_height", "must be at least 1 pixel"));
    }
    let l = cam.world_to_eye.transform_vector3(lw).normalize();
    out.light_dir_eye = l;
    let sin_gamma = (l.x * l.x + l.y * l.y).sqrt();
    out.light = if sin_gamma < 1e-6 {
        LightCase::ParallelToView
    } else if lw.x.hypot(lw.z) < 1e-6 && lw.y < 0.0 {
        LightCase::SunStraightDown
    } else {
        LightCase::General
    };
    let view = &cam.view;
    let (zn, zf) = visible_range(view, input.depth_range)?;
    let planes = receiver_planes(cam, &input.receivers)?;
    validate_casters(&input.casters)?;
    let ctx = Ctx {
        input,
        view,
        l,
        lw,
        planes,
    };
    let mut slices = [Slice {
        cover: (0.0, 0.0),
        split: (0.0, 0.0),
        blend: (0.0, 0.0),
    }; MAX_PARTITIONS];
    let (k, rule, _) = match input.scheme {
        FrameScheme::Single(rule) => {
            slices[0] = Slice {
                cover: (zn, zf),
                split: (zn, zf),
                blend: (zf, zf),
            };
            (1, rule, false)
        }
        FrameScheme::Cascades { splits, rule } => {
            (cascade_slices(splits, zn, zf, &mut slices)?, rule, false)
        }
        FrameScheme::Stable(splits) => (
            cascade_slices(splits, zn, zf, &mut slices)?,
            WarpRule::Uniform,
            true,
        ),
        FrameScheme::Tsm(_) => {
            slices[0] = Slice {
                cover: (zn, zf),
                split: (zn, zf),
                blend: (zf, zf),
            };
            (1, WarpRule::Uniform, false)
        }
        FrameScheme::Faces { rule, k } => return ctx.faces_into(rule, k, (zn, zf), out),
    };
    for s in &slices[..k] {
        let m = match input.scheme {
            FrameScheme::Stable(_) => ctx.stable_map(s)?,
            FrameScheme::Tsm(opts) => ctx.tsm_map(s, opts)?,
            _ => ctx.map(s, rule)?,
        };
        out.push(m);
    }
    out.settle();
    Ok(())
}

/// The visible depth range: the camera's, cut to `[z_min, z_max]`.
fn visible_range(view: &ViewFrustum, range: Option<(f64, f64)>) -> Result<(f64, f64)> {
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

/// The frustum's size, the unit of the frame's "no extent" tests (10⁻⁹ of it).
fn frustum_scale(v: &ViewFrustum) -> f64 {
    v.far() * (1.0 + v.tan_half_fov() * (1.0 + v.aspect()))
}

/// The receivers' bound as eye-space planes; `n = 0` for no bound. The bound is flat when it is
/// no thicker than 10⁻⁹ of the frustum's size (B's own "no thickness", so that a thin bound in
/// view is mapped as flat, never taken for one that only touches the frustum) or 10⁻¹² of its own
/// size.
fn receiver_planes(cam: &Camera, b: &Bound<'_>) -> Result<Planes> {
    let small = 1e-9 * frustum_scale(&cam.view);
    let mut out = Planes {
        p: [DVec4::ZERO; MAX_BOUND_PLANES],
        n: 0,
        flat: false,
    };
    let it = cam.eye_to_world.transpose(); // a world plane π is (V⁻¹)ᵀ π in eye space
    match b {
        Bound::Unbounded => {}
        Bound::Boxes(boxes) => {
            let Some(first) = boxes.first() else {
                return Err(Error::invalid("receivers", "must hold at least one box"));
            };
            let (mut lo, mut hi) = (first.min, first.max);
            for bx in *boxes {
                bx.check().map_err(|_| bad_box("receivers", bx))?;
                lo = lo.min(bx.min);
                hi = hi.max(bx.max);
            }
            let world = [
                DVec4::new(1.0, 0.0, 0.0, -hi.x),
                DVec4::new(-1.0, 0.0, 0.0, lo.x),
                DVec4::new(0.0, 1.0, 0.0, -hi.y),
                DVec4::new(0.0, -1.0, 0.0, lo.y),
                DVec4::new(0.0, 0.0, 1.0, -hi.z),
                DVec4::new(0.0, 0.0, -1.0, lo.z),
            ];
            for (k, w) in world.iter().enumerate() {
                out.p[k] = it * *w;
            }
            out.n = 6;
            let size = (hi - lo).abs().max_element().max(1.0);
            out.flat = (hi - lo).min_element() <= small.max(1e-12 * size);
        }
        Bound::Polytope(planes) => {
            if planes.is_empty() || planes.len() > MAX_BOUND_PLANES {
                return Err(Error::invalid(
                    "receivers",
                    format!(
                        "a polytope must have 1 to {MAX_BOUND_PLANES} planes (got {})",
                        planes.len()
                    ),
                ));
            }
            for (k, p) in planes.iter().enumerate() {
                if !p.is_finite() || p.truncate().length() <= 0.0 {
                    return Err(Error::invalid(
                        "receivers",
                        format!("planes must be finite with a non-zero normal (got {p})"),
                    ));
                }
                out.p[k] = it * *p;
            }
            out.n = planes.len();
            out.flat = has_zero_thickness(planes, small);
        }
    }
    Ok(out)
}

/// Whether two of a polytope's planes bound it to zero thickness: opposite unit normals at the
/// same place (within `small` or 10⁻¹² relative to the offsets), as a flat box's top and bottom
/// planes.
fn has_zero_thickness(planes: &[DVec4], small: f64) -> bool {
    let unit = |p: &DVec4| *p / p.truncate().length();
    planes.iter().enumerate().any(|(i, a)| {
        let a = unit(a);
        planes[i + 1..].iter().any(|b| {
            let b = unit(b);
            let scale = 1.0 + a.w.abs().max(b.w.abs());
            (a.truncate() + b.truncate()).length() <= 1e-12
                && (a.w + b.w).abs() <= small.max(1e-12 * scale)
        })
    })
}

fn bad_box(name: &'static str, b: &Aabb) -> Error {
    Error::invalid(
        name,
        format!(
            "boxes must be finite with min not above max (got min={}, max={})",
            b.min, b.max
        ),
    )
}

fn validate_casters(b: &Bound<'_>) -> Result<()> {
    match b {
        Bound::Unbounded => Ok(()),
        Bound::Boxes(boxes) => {
            for bx in *boxes {
                bx.check().map_err(|_| bad_box("casters", bx))?;
            }
            Ok(())
        }
        Bound::Polytope(planes) => {
            if planes.is_empty() || planes.len() > MAX_BOUND_PLANES {
                return Err(Error::invalid(
                    "casters",
                    format!("a polytope must have 1 to {MAX_BOUND_PLANES} planes"),
                ));
            }
            if planes
                .iter()
                .any(|p| !p.is_finite() || p.truncate().length() <= 0.0)
            {
                return Err(Error::invalid(
                    "casters",
                    "planes must be finite with a non-zero normal",
                ));
            }
            Ok(())
        }
    }
}

fn overlap_ok(o: f64) -> Result<f64> {
    let o = in_closed("overlap", o, 0.0, 1.0)?;
    if o >= 1.0 {
        return Err(Error::invalid("overlap", "must be smaller than 1 (got 1)"));
    }
    Ok(o)
}

/// The cascades' slices over the visible range `[zn, zf]`; returns k.
fn cascade_slices(
    splits: CascadeSplits<'_>,
    zn: f64,
    zf: f64,
    out: &mut [Slice; MAX_PARTITIONS],
) -> Result<usize> {
    let crate_overlap =
        |s: &Splits, overlap: f64, out: &mut [Slice; MAX_PARTITIONS]| -> Result<usize> {
            let o = overlap_ok(overlap)?;
            let planes = s.planes();
            let (first, last) = (planes[0], planes[planes.len() - 1]);
            let slack = 1e-12 * zf;
            if first < zn - slack || last > zf + slack {
                return Err(Error::invalid(
                    "splits",
                    format!(
                        "must lie within the visible depth range [{}, {}] (got [{}, {}])",
                        fmt_num(zn),
                        fmt_num(zf),
                        fmt_num(first),
                        fmt_num(last)
                    ),
                ));
            }
            let k = s.k();
            for (i, slot) in out.iter_mut().enumerate().take(k) {
                let (a, b) = s.range(i);
                let end = if i + 1 < k {
                    (b + o * (b - a)).min(last)
                } else {
                    b
                };
                *slot = Slice {
                    cover: (a.max(zn), end.min(zf)),
                    split: (a, b),
                    blend: (b, end),
                };
            }
            Ok(k)
        };
    match splits {
        CascadeSplits::Scheme { scheme, k, overlap } => {
            let s = z_splits(zn, zf, k, scheme)?;
            crate_overlap(&s, overlap, out)
        }
        CascadeSplits::Distances { planes, overlap } => {
            let s = Splits::from_planes(planes)?;
            crate_overlap(&s, overlap, out)
        }
        CascadeSplits::Fractions { fractions, overlap } => {
            let s = splits_between(zn, zf, fractions)?;
            crate_overlap(&s, overlap, out)
        }
        CascadeSplits::Bevy {
            k,
            minimum_distance,
            maximum_distance,
            first_far_bound,
            overlap_proportion,
        } => {
            if k == 0 || k > MAX_PARTITIONS {
                return Err(Error::invalid(
                    "k",
                    format!("must be in 1..={MAX_PARTITIONS} (got {k})"),
                ));
            }
            let o = overlap_ok(overlap_proportion)?;
            let max_d = positive("maximum_distance", maximum_distance)?;
            let min_d = in_closed("minimum_distance", minimum_distance, 0.0, max_d)?;
            let first = if k > 1 {
                let f = positive("first_far_bound", first_far_bound)?;
                if !(f > min_d && f < max_d) {
                    return Err(Error::invalid(
                        "first_far_bound",
                        format!(
                            "must lie between minimum_distance and maximum_distance (got {})",
                            fmt_num(f)
                        ),
                    ));
                }
                f
            } else {
                max_d
            };
            // Bevy's `calculate_cascade_bounds`, in f64.
            let base = if k > 1 {
                (max_d / first).powf(1.0 / (k - 1) as f64)
            } else {
                1.0
            };
            let mut prev_far = 0.0;
            let mut n = 0;
            for i in 0..k {
                let far_b = if k == 1 {
                    max_d
                } else {
                    first * base.powi(i as i32)
                };
                let near_b = if i == 0 { min_d } else { (1.0 - o) * prev_far };
                let sel_near = if i == 0 { min_d } else { prev_far };
                let blend = if i + 1 < k {
                    ((1.0 - o) * far_b, far_b)
                } else {
                    (far_b, far_b)
                };
                prev_far = far_b;
                let (a, b) = (near_b.max(zn), far_b.min(zf));
                if a >= b {
                    // Wholly outside the visible range: nothing to map there.
                    continue;
                }
                if sel_near.max(zn) >= b {
                    // The previous cascade already reaches the visible far plane: the shader never
                    // selects this one (nor any later), and the previous has nothing to blend into.
                    if n > 0 {
                        let end = out[n - 1].split.1;
                        out[n - 1].blend = (end, end);
                    }
                    break;
                }
                out[n] = Slice {
                    cover: (a, b),
                    split: (sel_near.max(zn), b),
                    blend: (blend.0.clamp(zn, zf), blend.1.clamp(zn, zf)),
                };
                n += 1;
            }
            if n == 0 {
                return Err(Error::invalid(
                    "minimum_distance",
                    "Bevy's cascades do not meet the visible depth range",
                ));
            }
            Ok(n)
        }
    }
}

// Not boxed: a per-frame heap allocation is what the frame API must not do.
#[allow(clippy::large_enum_variant)]
enum Built {
    Map(FrameMap),
    None(Focus),
}

struct Ctx<'i, 'a> {
    input: &'i FrameInput<'a>,
    view: &'i ViewFrustum,
    l: DVec3,
    lw: DVec3,
    planes: Planes,
}

/// The focus body of one slice.
struct Body {
    v: [DVec3; MAX_BODY_VERTICES],
    n: usize,
    /// B is the slice itself (no receivers' plane cut it).
    whole: bool,
    focus: Focus,
}

impl Ctx<'_, '_> {
    /// B's vertices `pts` in the light space `ls`; `None` when B is edge-on to the light (no
    /// extent across the map or along the warp axis, relative to the frustum's size).
    fn in_light(
        &self,
        pts: &[DVec3],
        ls: LightSpace,
    ) -> Result<Option<FrustumInLight<MAX_BODY_VERTICES>>> {
        let fl = FrustumInLight::<MAX_BODY_VERTICES>::from_points(pts, self.l, ls)
            .ok_or_else(|| Error::Degenerate("the focus body has no vertices".into()))?;
        let (mut xl, mut xh) = (f64::INFINITY, f64::NEG_INFINITY);
        for q in &fl.q {
            xl = xl.min(q.x);
            xh = xh.max(q.x);
        }
        let small = 1e-9 * self.scale();
        if xh - xl <= small || fl.delta <= small {
            return Ok(None);
        }
        // A footprint with no area in any direction (a flat B seen edge-on along a diagonal of
        // the map: a vertical wall under a sun straight down, the camera turned) is edge-on too.
        let mut foot = [DVec3::ZERO; MAX_BODY_VERTICES];
        for (f, q) in foot.iter_mut().zip(&fl.q) {
            *f = DVec3::new(q.x, 0.0, q.z);
        }
        let (_, width, _) = extents(&foot);
        Ok((width > small).then_some(fl))
    }

    fn scale(&self) -> f64 {
        frustum_scale(self.view)
    }

    /// B for the slice `[a, b]`, cut by the planes `extra` as well.
    fn body(&self, a: f64, b: f64, extra: &[DVec4]) -> Result<Body> {
        let sub = self.view.with_depth_range(a, b)?;
        let corners = sub.corners();
        let tol = self.clip_tol();
        let planes = &self.planes.p[..self.planes.n];
        let inside = |p: &DVec3| {
            planes
                .iter()
                .all(|pl| pl.truncate().dot(*p) + pl.w <= tol * pl.truncate().length())
        };
        if extra.is_empty() && corners.iter().all(inside) {
            let mut body = Body {
                v: [DVec3::ZERO; MAX_BODY_VERTICES],
                n: 8,
                whole: true,
                focus: Focus::Body,
            };
            body.v[..8].copy_from_slice(&corners);
            return Ok(body);
        }
        self.body_cut(self.receivers_clip(&corners)?, extra)
    }

    /// The clipper's tolerance, relative to the frustum's size.
    fn clip_tol(&self) -> f64 {
        1e-10 * self.scale()
    }

    /// The hexahedron `corners` (a slice of the frustum) cut by the receivers' planes.
    fn receivers_clip(&self, corners: &[DVec3; 8]) -> Result<BodyClip> {
        let mut cb = BodyClip::hexahedron(corners);
        let tol = self.clip_tol();
        for pl in &self.planes.p[..self.planes.n] {
            if !cb.clip(*pl, tol) {
                return Err(too_many_faces());
            }
        }
        Ok(cb)
    }

    /// B from the slice already cut by the receivers' planes (`Ctx::receivers_clip`), cut by
    /// `extra` as well: the same cuts in the same order as [`Ctx::body`] makes.
    fn body_cut(&self, mut cb: BodyClip, extra: &[DVec4]) -> Result<Body> {
        let tol = self.clip_tol();
        for pl in extra {
            if !cb.clip(*pl, tol) {
                return Err(too_many_faces());
            }
        }
        let mut body = Body {
            v: [DVec3::ZERO; MAX_BODY_VERTICES],
            n: 0,
            whole: false,
            focus: Focus::Body,
        };
        let n = cb.vertices(tol, &mut body.v).ok_or_else(|| {
            Error::Degenerate("the focus body has more vertices than the frame holds".into())
        })?;
        body.n = n;
        let (len, width, thick) = extents(&body.v[..n]);
        let small = 1e-9 * self.scale();
        body.focus = if self.planes.flat {
            if width <= small || len <= small {
                Focus::Empty
            } else {
                Focus::Flat
            }
        } else if thick <= small {
            Focus::Empty
        } else {
            Focus::Body
        };
        Ok(body)
    }

    /// The point that can shadow B nearest the light in the warp's depth (largest (y − y₀)/w),
    /// over every caster; `None` when there is none or casters are not needed.
    fn caster_extreme<const N: usize>(
        &self,
        fl: &FrustumInLight<N>,
        body_len: usize,
        w_of: impl Fn(DVec3) -> f64,
        y0: f64,
    ) -> Result<Option<DVec3>> {
        if self.input.depth_clamp {
            return Ok(None);
        }
        let boxes: &[Aabb] = match self.input.casters {
            Bound::Unbounded => return Ok(None),
            Bound::Boxes(b) => b,
            Bound::Polytope(_) => &[],
        };
        let tol = 1e-10 * self.scale();
        let depth_of = |p: DVec3| (fl.ls.y.dot(p) - y0) / w_of(p);
        // Only a point nearer the light than every point of B extends the range.
        let top = (0..body_len)
            .map(|i| depth_of(fl.corners[i]))
            .fold(f64::NEG_INFINITY, f64::max);
        let mut best: Option<(f64, DVec3)> = None;
        let mut consider = |v: &[DVec3]| {
            for p in v {
                let d = depth_of(*p);
                if best.is_none_or(|(b, _)| d > b) {
                    best = Some((d, *p));
                }
            }
        };
        let mut prism: Option<Prism> = None;
        let w2e = self.input.camera.world_to_eye;
        for bx in boxes {
            let c = bx.corners().map(|p| w2e.transform_point3(p));
            // The depth is linear-fractional: its maximum over the box (and over any part of it)
            // is at most its maximum over the corners. A box no nearer the light than B is skipped.
            // (Only where w > 0 at every corner, hence over the whole box.)
            let w_pos = |p: &DVec3| w_of(*p) > 0.0;
            if c.iter().all(|p| w_pos(p) && depth_of(*p) <= top) {
                continue;
            }
            let prism = prism.get_or_insert_with(|| Prism::new(fl, body_len));
            if c.iter().all(|p| prism.contains(*p, tol)) {
                consider(&c);
                continue;
            }
            let mut cb = CasterClip::hexahedron(&c);
            if !prism.clip(&mut cb, tol) {
                return Err(Error::Degenerate(
                    "a caster's clipped body has more faces than the clipper holds".into(),
                ));
            }
            let mut v = [DVec3::ZERO; 64];
            let n = cb.vertices(tol, &mut v).ok_or_else(|| {
                Error::Degenerate("a caster's clipped body has too many vertices".into())
            })?;
            consider(&v[..n]);
        }
        if let Bound::Polytope(world) = self.input.casters {
            // Start from the prism capped far beyond the body toward the light, then cut by the
            // casters' planes: a result that reaches the cap is unbounded toward the light.
            let reach = 1e6 * self.scale();
            let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
            for q in &fl.q {
                lo = lo.min(*q);
                hi = hi.max(*q);
            }
            let ls = fl.ls;
            let to_eye = |x: f64, y: f64, z: f64| ls.x * x + ls.y * y + ls.z * z;
            let (ya, yb) = (lo.y - 1.0, hi.y + reach);
            let c = [
                to_eye(lo.x, ya, lo.z),
                to_eye(hi.x, ya, lo.z),
                to_eye(hi.x, yb, lo.z),
                to_eye(lo.x, yb, lo.z),
                to_eye(lo.x, ya, hi.z),
                to_eye(hi.x, ya, hi.z),
                to_eye(hi.x, yb, hi.z),
                to_eye(lo.x, yb, hi.z),
            ];
            let mut cb = PolytopeClip::hexahedron(&c);
            let it = self.input.camera.eye_to_world.transpose();
            let mut ok = true;
            for p in world {
                ok &= cb.clip(it * *p, tol);
            }
            ok &= Prism::new(fl, body_len).clip(&mut cb, tol);
            if !ok {
                return Err(Error::Degenerate(
                    "the casters' clipped body has more faces than the clipper holds".into(),
                ));
            }
            let mut v = [DVec3::ZERO; 64];
            let n = cb.vertices(tol, &mut v).unwrap_or(0);
            if v[..n].iter().any(|p| ls.y.dot(*p) >= hi.y + 0.5 * reach) {
                return Err(Error::invalid(
                    "casters",
                    "the polytope is unbounded toward the light",
                ));
            }
            consider(&v[..n]);
        }
        Ok(best.and_then(|(d, p)| (d > top).then_some(p)))
    }

    fn map(&self, s: &Slice, rule: WarpRule) -> Result<Built> {
        let body = self.body(s.cover.0, s.cover.1, &[])?;
        if body.focus == Focus::Empty || body.n == 0 {
            return Ok(Built::None(Focus::Empty));
        }
        let pts = &body.v[..body.n];
        let (n_b, f_b) = depth_extent(pts);
        let cam = self.view;
        let sub_full = cam.with_depth_range(s.cover.0, s.cover.1)?;
        let l = self.l;
        let centre_rule = match self.input.centre {
            WarpCentre::Rule => matches!(rule, WarpRule::Ogre | WarpRule::OgreOrtho { .. }),
            WarpCentre::Eye => false,
            WarpCentre::NearestVertex => true,
        };
        // TSM's focus distance, checked against the slice, scaled to B's depth (the slice's own
        // rule is kept for the frustum-only builder below, which scales nothing).
        let slice_rule = rule;
        let rule = match rule {
            WarpRule::Tsm { focus } => {
                let focus = focus_in_range(&sub_full, focus)?;
                WarpRule::Tsm {
                    focus: focus * (f_b - n_b) / (s.cover.1 - s.cover.0),
                }
            }
            r => r,
        };
        let ls = light_space_unit(LightDir::from_unit_unchecked(l), rule_axis(l, rule));
        let Some(fl) = self.in_light(pts, ls)? else {
            return Ok(Built::None(Focus::EdgeOn));
        };
        let mut focus = body.focus;
        let zero_depth = f_b - n_b <= 1e-9 * f_b;
        if zero_depth {
            focus = Focus::ZeroDepth;
        }
        // The frustum-only builder, exactly, when B is the slice and nothing extends its depth.
        let centre = if centre_rule {
            Some(nearest_vertex(&fl, body.n))
        } else {
            None
        };
        let n_prime = if zero_depth {
            NPrime::UNWARPED
        } else {
            let sub = cam.with_depth_range(n_b, f_b)?;
            match (rule, centre) {
                // Minimax chooses n′ for the map that is built: around a centre off the eye's
                // line the map's s is (x − x_c)/w (`fit_body`), so its search sees each vertex's
                // x from the centre. (For the eye's centre it minimised a map that is not built,
                // up to 6× the uniform map's S̄.) M_z, and so `MinimaxMz`, does not depend on x.
                (WarpRule::Minimax, Some(i)) => {
                    let mut from_centre = fl;
                    let xc = fl.q[i].x;
                    for q in &mut from_centre.q {
                        q.x -= xc;
                    }
                    rule_n_prime_on(cam, &sub, &from_centre, rule)?
                }
                _ => rule_n_prime_on(cam, &sub, &fl, rule)?,
            }
        };
        let rho = n_prime.recip();
        let w_of = |p: DVec3| 1.0 + rho * (fl.ls.z.dot(p) - fl.z0);
        let y0 = centre.map_or(0.0, |i| fl.q[i].y);
        let caster = self.caster_extreme(&fl, body.n, w_of, y0)?;
        let default_centre = self.input.centre == WarpCentre::Rule;
        let shadow = if body.whole && caster.is_none() && default_centre {
            // `warp(&slice, l, rule)` itself, l normalised at the entry as `warp` does: B is the
            // slice and nothing extends its depth.
            warp_prepared(
                &sub_full,
                &PreparedLight::new(LightDir::new(l)?),
                slice_rule,
            )?
        } else {
            ShadowMatrix::new(
                fit_body(&fl, n_prime, centre, caster.as_slice())?,
                LightDir::from_unit_unchecked(l),
                n_prime,
                n_b,
                f_b,
            )
        };
        self.finish(shadow, pts, s, focus).map(Built::Map)
    }

    /// The trapezoidal map of B, its depth row refitted to B and the casters.
    fn tsm_map(&self, s: &Slice, opts: TsmOptions) -> Result<Built> {
        let sub_full = self.view.with_depth_range(s.cover.0, s.cover.1)?;
        validate_tsm(&sub_full, &opts)?;
        let body = self.body(s.cover.0, s.cover.1, &[])?;
        if body.focus == Focus::Empty || body.n == 0 {
            return Ok(Built::None(Focus::Empty));
        }
        let pts = &body.v[..body.n];
        let (n_b, f_b) = depth_extent(pts);
        let l = self.l;
        let ls = light_space_unit(LightDir::from_unit_unchecked(l), DVec3::NEG_Z);
        let Some(fl) = self.in_light(pts, ls)? else {
            return Ok(Built::None(Focus::EdgeOn));
        };
        let focus = opts.focus * (f_b - n_b) / (s.cover.1 - s.cover.0);
        let focus_depth = n_b + focus;
        let region = self.body(
            s.cover.0,
            s.cover.1,
            &[DVec4::new(0.0, 0.0, -1.0, -focus_depth)],
        )?;
        let focus_region: &[DVec3] = if region.n > 0 {
            &region.v[..region.n]
        } else {
            pts
        };
        let centre_line = (ls.z.z * (f_b - n_b)).abs();
        let t = tsm_on_points(
            ls,
            pts,
            focus_region,
            DVec3::new(0.0, 0.0, -focus_depth),
            centre_line,
            opts.search,
            n_b,
            f_b,
        )?;
        let mut m = t.shadow.matrix();
        // Depth: v = y/w over B and the casters' extreme, −1 nearest the light (the form of the
        // crate's warps; monotonic along each light ray, whose w is constant).
        let row3 = m.row(3);
        let w_of = |p: DVec3| row3.dot(p.extend(1.0));
        let caster = self.caster_extreme(&fl, body.n, w_of, 0.0)?;
        let mut r = (f64::INFINITY, f64::NEG_INFINITY);
        for p in pts.iter().chain(caster.as_slice()) {
            let v = ls.y.dot(*p) / w_of(*p);
            r = (r.0.min(v), r.1.max(v));
        }
        let v_m = 0.5 * (r.0 + r.1);
        let v_h = (0.5 * (r.1 - r.0)).max(1e-9 * self.scale());
        let mut mt = m.transpose();
        mt.z_axis = (v_m * row3 - ls.y.extend(0.0)) / v_h;
        m = mt.transpose();
        let shadow = ShadowMatrix::new(
            m,
            LightDir::from_unit_unchecked(l),
            t.shadow.n_prime(),
            n_b,
            f_b,
        );
        self.finish(shadow, pts, s, body.focus).map(Built::Map)
    }

    /// A stable cascade with its depth range from B and the casters.
    fn stable_map(&self, s: &Slice) -> Result<Built> {
        let body = self.body(s.cover.0, s.cover.1, &[])?;
        if body.focus == Focus::Empty || body.n == 0 {
            return Ok(Built::None(Focus::Empty));
        }
        let pts = &body.v[..body.n];
        let cam = &self.input.camera;
        let res = f64::from(self.input.map_resolution);
        let (c, r) = bounding_sphere(self.view, s.cover.0, s.cover.1)?;
        // World-fixed light space (y toward the light, z the world −Z projected).
        let ls_w = light_space_unit(LightDir::from_unit_unchecked(self.lw), DVec3::NEG_Z);
        let half = r * res / (res - 2.0);
        let texel = 2.0 * half / res;
        let cw = cam.eye_to_world.transform_point3(DVec3::new(0.0, 0.0, -c));
        let q = ls_w.to_light(cw);
        let sx = (q.x / texel).round() * texel;
        let sz = (q.z / texel).round() * texel;
        // The light space in eye coordinates (rotation only; offsets cancel in the fit).
        let rot = |v: DVec3| cam.world_to_eye.transform_vector3(v);
        let ls_e = LightSpace {
            x: rot(ls_w.x),
            y: rot(ls_w.y),
            z: rot(ls_w.z),
        };
        let fl = FrustumInLight::<MAX_BODY_VERTICES>::from_points(pts, self.l, ls_e)
            .ok_or_else(|| Error::Degenerate("the focus body has no vertices".into()))?;
        let (mut ylo, mut yhi) = (f64::INFINITY, f64::NEG_INFINITY);
        for q in &fl.q {
            ylo = ylo.min(q.y);
            yhi = yhi.max(q.y);
        }
        if let Some(p) = self.caster_extreme(&fl, body.n, |_| 1.0, 0.0)? {
            yhi = yhi.max(ls_e.y.dot(p));
        }
        let v_m = 0.5 * (ylo + yhi);
        let v_h = (0.5 * (yhi - ylo)).max(1e-9 * self.scale());
        // s, t as `stable_cascade`: world light space, the snapped centre, half-width `half`.
        let ortho = DMat4::from_cols(
            DVec4::new(1.0 / half, 0.0, 0.0, 0.0),
            DVec4::new(0.0, 0.0, 0.0, 0.0),
            DVec4::new(0.0, 1.0 / half, 0.0, 0.0),
            DVec4::new(-sx / half, -sz / half, 0.0, 1.0),
        );
        let mut m = (ortho * ls_w.rotation() * cam.eye_to_world).transpose();
        // Depth from the eye-space light y over B and the casters, −1 nearest the light.
        m.z_axis = (-ls_e.y / v_h).extend(v_m / v_h);
        let matrix = m.transpose();
        // The world-fixed square is built from world positions: far from the world origin (or
        // near f64's range) their rounding, amplified by 1/half, can leave B outside the map.
        if !matrix.is_finite() {
            return Err(Error::Degenerate(
                "the stable cascade's matrix overflows f64 for this frustum".into(),
            ));
        }
        verify_clip(&matrix, pts.iter())?;
        let shadow = ShadowMatrix::new(
            matrix,
            LightDir::from_unit_unchecked(self.l),
            NPrime::UNWARPED,
            depth_extent(pts).0,
            depth_extent(pts).1,
        );
        self.finish(shadow, pts, s, body.focus).map(Built::Map)
    }

    /// The face partitions of the visible frustum `[zn, zf]` (see [`FrameScheme::Faces`]).
    fn faces_into(
        &self,
        rule: FaceWarp,
        k: usize,
        (zn, zf): (f64, f64),
        out: &mut Frame,
    ) -> Result<()> {
        if !(1..=MAX_FACE_K).contains(&k) {
            return Err(Error::invalid(
                "k",
                format!(
                    "must be in 1..={MAX_FACE_K} for face partitions (4k + 1 maps fill at most \
                     the frame's {MAX_PARTITIONS} slots; got {k})"
                ),
            ));
        }
        if self.planes.n > MAX_FACE_BOUND_PLANES {
            return Err(Error::invalid(
                "receivers",
                format!(
                    "must be a polytope of at most {MAX_FACE_BOUND_PLANES} planes for face \
                     partitions (got {})",
                    self.planes.n
                ),
            ));
        }
        let view = self.view.with_depth_range(zn, zf)?;
        let splits = z_splits(zn, zf, k, SplitScheme::SelfSimilar)?;
        let l = self.l;
        let light = LightDir::from_unit_unchecked(l);
        let tan = view.tan_half_fov();
        let ta = tan * view.aspect();
        let faces = visible_with(tan, ta, zn / zf, l);
        if faces.faces().is_empty() {
            return Err(Error::Degenerate(format!(
                "no face of the view frustum is seen by the light {l}"
            )));
        }
        // B of the whole visible range (its extent along the light is every part's depth range)
        // and its clipper, cut by the receivers once for every part (each part adds its prism).
        let receivers = self.receivers_clip(&view.corners())?;
        let whole = self.body_cut(receivers, &[])?;
        if whole.focus == Focus::Empty || whole.n == 0 {
            return Ok(());
        }
        let (mut y_lo, mut y_hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for p in &whole.v[..whole.n] {
            let y = -l.dot(*p);
            y_lo = y_lo.min(y);
            y_hi = y_hi.max(y);
        }
        for &face in faces.faces() {
            let spaces = face_spaces(face, tan, ta, light);
            let count = if face.is_side() { k } else { 1 };
            for j in 0..count {
                let (a, b) = if face.is_side() {
                    splits.range(j)
                } else {
                    (zn, zn)
                };
                let part = FacePart {
                    face,
                    quad: face.vertices_with(&view, tan, ta, a, b),
                    depths: (a, b),
                    spaces: &spaces,
                };
                out.push(self.face_part(&part, &receivers, (y_lo, y_hi), rule)?);
            }
        }
        out.settle();
        Ok(())
    }

    /// One face part's map: B_i = B ∩ the prism of the part's quad along the light (B of the
    /// visible range, `receivers` its clipper cut by the receivers' planes), fitted with the
    /// face's candidate axes over B's extent `y` along the light and the casters of B_i.
    fn face_part(
        &self,
        part: &FacePart<'_>,
        receivers: &BodyClip,
        (y_lo, y_hi): (f64, f64),
        rule: FaceWarp,
    ) -> Result<Built> {
        let FacePart {
            face,
            quad,
            depths: (a, b),
            spaces,
        } = *part;
        let l = self.l;
        let prism = quad_prism(&quad, l);
        let body = self.body_cut(*receivers, prism.as_slice())?;
        if body.focus == Focus::Empty || body.n == 0 {
            return Ok(Built::None(Focus::Empty));
        }
        let pts = &body.v[..body.n];
        // Any light space with y toward the light serves the casters' prism and depth.
        let ls = light_space_unit(LightDir::from_unit_unchecked(l), DVec3::NEG_Z);
        let Some(fl) = self.in_light(pts, ls)? else {
            return Ok(Built::None(Focus::EdgeOn));
        };
        let mut y_hi = y_hi;
        if let Some(p) = self.caster_extreme(&fl, body.n, |_| 1.0, 0.0)? {
            y_hi = y_hi.max(ls.y.dot(p));
        }
        let fitter = PartFitter {
            rule,
            y_range: (y_lo, y_hi),
            l,
            tan: self.view.tan_half_fov(),
        };
        // The fit measures each candidate over B_i's vertices with the frame's light and tan θ:
        // the chosen one's error is the map's.
        let (matrix, n_prime, err) =
            fitter.best::<{ 3 * MAX_BODY_VERTICES }>(spaces, pts, pts, face, (a, b))?;
        let (n_b, f_b) = depth_extent(pts);
        let shadow = ShadowMatrix::new(matrix, LightDir::from_unit_unchecked(l), n_prime, n_b, f_b);
        let slice = Slice {
            cover: (n_b, f_b),
            split: (a, b),
            blend: (b, b),
        };
        let mut m = self.finish_measured(shadow, err, pts, &slice, body.focus)?;
        m.face = Some(face);
        Ok(Built::Map(m))
    }

    fn finish(
        &self,
        shadow: ShadowMatrix,
        pts: &[DVec3],
        s: &Slice,
        focus: Focus,
    ) -> Result<FrameMap> {
        let err = vertex_max(&shadow.matrix(), self.l, self.view.tan_half_fov(), pts).ok_or_else(
            || Error::Degenerate("the map is singular at a vertex of the focus body".into()),
        )?;
        self.finish_measured(shadow, err, pts, s, focus)
    }

    /// [`Ctx::finish`] with the map's error over `pts` already measured (by `vertex_max` with
    /// the frame's light and tan θ, as `finish` would).
    fn finish_measured(
        &self,
        shadow: ShadowMatrix,
        err: FrustumError,
        pts: &[DVec3],
        s: &Slice,
        focus: Focus,
    ) -> Result<FrameMap> {
        // The largest texel edge over B: clip spans 2 over the map's `res` texels.
        let res = f64::from(self.input.map_resolution);
        let matrix = shadow.matrix();
        let texel = pts
            .iter()
            .filter_map(|p| texel_edges(&matrix, self.l, *p))
            .fold(0.0f64, |a, (es, et)| a.max(es).max(et))
            * 2.0
            / res;
        let mut body = [DVec3::ZERO; MAX_BODY_VERTICES];
        body[..pts.len()].copy_from_slice(pts);
        let image = f64::from(self.input.image_height);
        // The matrices a renderer uploads, in both depth conventions, must be finite in f64 and
        // in the GPU's f32 (a camera far from the world origin scales its translation past them).
        let world_to_eye = self.input.camera.world_to_eye;
        let world_to_clip = matrix * world_to_eye;
        let zero_one = zero_to_one(&matrix) * world_to_eye;
        if ![world_to_clip, zero_one]
            .iter()
            .all(|m| m.is_finite() && m.as_mat4().is_finite())
        {
            return Err(Error::Degenerate(
                "the map's world → clip matrix overflows f32 or f64 (the camera is too far from \
                 the world origin for the map's scale)"
                    .into(),
            ));
        }
        Ok(FrameMap {
            world_to_clip,
            shadow,
            split: s.split,
            blend: s.blend,
            texel_world: texel,
            max_mx: err.max_mx,
            max_mz: err.max_mz,
            storage_factor: err.storage_factor,
            max_error_pixels: err.max_mx.max(err.max_mz) * image / res,
            focus,
            face: None,
            world_to_eye: self.input.camera.world_to_eye,
            body,
            body_len: pts.len(),
        })
    }
}

/// The edges of a texel of `m` (eye → light clip) at `p`, in the plane perpendicular to the unit
/// light direction `l`, per unit of clip s and t: the columns of the inverse of the Jacobian of
/// that plane → (s, t), `(|∇t⊥| / |D|, |∇s⊥| / |D|)` with `D = (∇s × ∇t)·l` (a texel is a light
/// ray's cross-section, so the edges do not depend on where along the ray `p` lies). Filament's
/// `texelSizeWorldSpace` takes the same columns, at the map's centre only. `None` behind the
/// map's centre of projection or where the map is singular.
fn texel_edges(m: &DMat4, l: DVec3, p: DVec3) -> Option<(f64, f64)> {
    let h = *m * p.extend(1.0);
    if h.w.is_nan() || h.w <= 0.0 {
        return None;
    }
    let r3 = m.row(3).truncate();
    let grad = |row: DVec3, v: f64| (row * h.w - r3 * v) / (h.w * h.w);
    let gs = grad(m.row(0).truncate(), h.x);
    let gt = grad(m.row(1).truncate(), h.y);
    let (gs, gt) = (gs - gs.dot(l) * l, gt - gt.dot(l) * l);
    let d = gs.cross(gt).dot(l).abs();
    let edges = (gt.length() / d, gs.length() / d);
    (edges.0.is_finite() && edges.1.is_finite()).then_some(edges)
}

/// The focus body's clipper overflowed (more faces than it holds).
fn too_many_faces() -> Error {
    Error::Degenerate("the focus body has more faces than the clipper holds".into())
}

/// B's vertex nearest the camera (smallest eye depth; ties within 10⁻¹² relative go to the
/// largest x + y, OGRE's top-right near corner of the frustum).
fn nearest_vertex<const N: usize>(fl: &FrustumInLight<N>, n: usize) -> usize {
    let dmin = fl.depth[..n].iter().copied().fold(f64::INFINITY, f64::min);
    let tol = 1e-12 * dmin.abs().max(f64::MIN_POSITIVE);
    let mut best = 0;
    let mut key = f64::NEG_INFINITY;
    for i in 0..n {
        if fl.depth[i] <= dmin + tol {
            let k = fl.corners[i].x + fl.corners[i].y;
            if k > key {
                key = k;
                best = i;
            }
        }
    }
    best
}

/// The prism of B's light-space footprint: the side planes through the edges of the convex hull
/// of B's vertices' (x, z), parallel to the light.
struct Prism {
    planes: [DVec4; 2 * MAX_BODY_VERTICES],
    n: usize,
}

impl Prism {
    fn new<const N: usize>(fl: &FrustumInLight<N>, n: usize) -> Self {
        let mut pts = [DVec2::ZERO; MAX_BODY_VERTICES];
        for (p, q) in pts.iter_mut().zip(&fl.q).take(n) {
            *p = DVec2::new(q.x, q.z);
        }
        let mut hull = [DVec2::ZERO; 2 * MAX_BODY_VERTICES];
        let h = crate::geom::hull::convex_hull(&mut pts[..n], &mut hull);
        // Vertices of B on one light ray (a vertical edge under a sun straight down) project to
        // points within rounding of each other, and the hull can keep both: a plane on such an
        // edge (10⁻¹³ long) has an arbitrary direction and cuts the casters away. Hull vertices
        // within 10⁻⁹ of the footprint's size of the previous one are dropped (the prism moves
        // by no more than that).
        let size = hull[..h]
            .iter()
            .fold(0.0f64, |m, v| fmax(m, fmax(v.x.abs(), v.y.abs())));
        let eps = 1e-9 * size;
        let mut k = 0;
        for i in 0..h {
            if k == 0 || (hull[i] - hull[k - 1]).length() > eps {
                hull[k] = hull[i];
                k += 1;
            }
        }
        while k > 1 && (hull[k - 1] - hull[0]).length() <= eps {
            k -= 1;
        }
        let h = k;
        let mut planes = [DVec4::ZERO; 2 * MAX_BODY_VERTICES];
        let ls = fl.ls;
        for i in 0..h {
            let (a, b) = (hull[i], hull[(i + 1) % h]);
            let e = b - a;
            // Counter-clockwise hull: the outside is to the right, normal (e.y, −e.x).
            let n2 = DVec2::new(e.y, -e.x);
            let n3 = ls.x * n2.x + ls.z * n2.y;
            planes[i] = n3.extend(-n2.dot(a));
        }
        Self { planes, n: h }
    }

    fn clip<const F: usize, const V: usize, const P: usize>(
        &self,
        cb: &mut ConvexBody<F, V, P>,
        tol: f64,
    ) -> bool {
        self.planes[..self.n].iter().all(|p| cb.clip(*p, tol))
    }

    /// Whether `p` lies inside the prism (within `tol` of its planes, which have unit normals
    /// up to the hull edge's length).
    fn contains(&self, p: DVec3, tol: f64) -> bool {
        self.planes[..self.n]
            .iter()
            .all(|pl| pl.truncate().dot(p) + pl.w <= tol * pl.truncate().length())
    }
}

/// The side planes of the prism of a planar quad along the light: each contains an edge and the
/// light direction, outward from the quad. An edge within [`EDGE_ON`] of parallel to the light
/// gives no plane (its neighbours bound the quad's projection, a triangle then).
fn quad_prism(quad: &[DVec3; 4], l: DVec3) -> PlaneList<4> {
    let centre = 0.25 * (quad[0] + quad[1] + quad[2] + quad[3]);
    let mut out = PlaneList {
        p: [DVec4::ZERO; 4],
        n: 0,
    };
    for i in 0..4 {
        let (p, q) = (quad[i], quad[(i + 1) % 4]);
        let e = q - p;
        let n = e.cross(l);
        if n.length() <= EDGE_ON * e.length() {
            continue;
        }
        let n = if n.dot(centre - p) > 0.0 { -n } else { n };
        out.p[out.n] = n.extend(-n.dot(p));
        out.n += 1;
    }
    out
}

/// One part of a frustum face to map: the face, its quad between the part's depths, and the
/// face's candidate light spaces.
#[derive(Clone, Copy)]
struct FacePart<'s> {
    face: Face,
    quad: [DVec3; 4],
    depths: (f64, f64),
    spaces: &'s FaceSpaces,
}

/// Up to `N` planes.
struct PlaneList<const N: usize> {
    p: [DVec4; N],
    n: usize,
}

impl<const N: usize> PlaneList<N> {
    fn as_slice(&self) -> &[DVec4] {
        &self.p[..self.n]
    }
}

/// The nearest and farthest eye depth −z of a body's vertices.
fn depth_extent(pts: &[DVec3]) -> (f64, f64) {
    let (mut near, mut far) = (f64::INFINITY, f64::NEG_INFINITY);
    for p in pts {
        near = near.min(-p.z);
        far = far.max(-p.z);
    }
    (near, far)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::polytope::{frustum_planes, polytope_vertices};

    #[test]
    fn frustum_planes_agree_with_the_body() {
        // The frustum's own planes keep every corner of the frustum body.
        let v = ViewFrustum::new(1.0, 10.0, 0.5).unwrap();
        for p in frustum_planes(&v, v.far()) {
            for c in v.corners() {
                assert!(p.truncate().dot(c) + p.w <= 1e-12 * 10.0);
            }
        }
    }

    /// The clipper's vertices against the triple-plane enumeration of `polytope_vertices` (an
    /// independent algorithm), for random boxes across, inside and around random frusta.
    #[test]
    fn clipped_body_matches_plane_triples() {
        let mut seed = 99u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut nonempty = 0;
        for _ in 0..500 {
            let near = 0.1 + rnd();
            let view = ViewFrustum::with_aspect(
                near,
                near * (2.0 + 50.0 * rnd()),
                0.2 + rnd(),
                0.5 + rnd(),
            )
            .unwrap();
            let f = view.far();
            let lo = DVec3::new((rnd() - 0.7) * f, (rnd() - 0.7) * f, -rnd() * 1.2 * f);
            let hi = lo + DVec3::new(rnd(), rnd(), rnd()) * f;
            let cam = Camera::new(
                DMat4::IDENTITY,
                view.near(),
                view.far(),
                view.half_fov(),
                view.aspect(),
            )
            .unwrap();
            let boxes = [Aabb::new(lo, hi).unwrap()];
            let input = FrameInput::new(cam, DVec3::new(0.3, -1.0, 0.2), 1024, 1024)
                .receivers(Bound::Boxes(&boxes))
                .scheme(FrameScheme::Single(WarpRule::Uniform));
            let planes = receiver_planes(&cam, &input.receivers).unwrap();
            let ctx = Ctx {
                input: &input,
                view: &view,
                l: DVec3::NEG_Y,
                lw: DVec3::NEG_Y,
                planes,
            };
            let body = ctx.body(view.near(), view.far(), &[]).unwrap();
            let mut all = [DVec4::ZERO; 12];
            all[..6].copy_from_slice(&frustum_planes(&view, f));
            all[6..].copy_from_slice(&planes.p[..6]);
            let scale = ctx.scale();
            let mut want = [DVec3::ZERO; 64];
            let n = polytope_vertices(&all, scale, &mut want);
            if body.focus == Focus::Empty {
                // No solid: the enumeration finds no body with volume either.
                let (_, _, thick) = extents(&want[..n]);
                assert!(thick <= 1e-6 * scale, "{lo} {hi}");
                continue;
            }
            nonempty += 1;
            let got = &body.v[..body.n];
            for w in &want[..n] {
                assert!(
                    got.iter().any(|g| (*g - *w).length() <= 1e-7 * scale),
                    "missing {w}"
                );
            }
            for g in got {
                assert!(
                    want[..n].iter().any(|w| (*g - *w).length() <= 1e-7 * scale),
                    "extra {g}"
                );
            }
        }
        assert!(nonempty > 100, "{nonempty}");
    }
}
