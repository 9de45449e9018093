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

pub mod bias;
mod body;
mod cascade;
mod casters;
mod clipmap;
mod culling;
mod equal_error;
mod faces;
mod input;
pub mod lens;
mod output;
mod rules;
mod stable_splits;
mod upload;
mod wgsl;

pub use bias::Bias;
pub use clipmap::LevelChoice;
pub use culling::{CullVolume, MAX_CULL_PLANES};
pub use input::{
    Aabb, Bound, Camera, CascadeSplits, ClipmapOptions, FrameInput, FrameScheme, WarpCentre,
};
pub use output::{Focus, Frame, FrameMap, FrameMaps, LightCase, MapError};
pub use upload::{GpuShadowMap, GPU_SHADOW_MAP_WGSL};
pub use wgsl::SHADOW_WGSL;

use crate::analytic::partition::MAX_PARTITIONS;
use crate::error::{Error, Result};
use crate::frustum::{LightDir, ViewFrustum};
use crate::maps::WarpRule;
use body::{receiver_planes, Planes};
use equal_error::SliceMap;
use glam::DVec3;
use input::{check_proportions, check_resolutions, validate_casters, visible_range};

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

/// One slice to map: covered depth range, selection range, blend band.
#[derive(Debug, Clone, Copy)]
struct Slice {
    cover: (f64, f64),
    split: (f64, f64),
    blend: (f64, f64),
    /// The map's texels per side ([`FrameInput::resolution_at`] of its slot).
    res: u32,
}

/// The frame's maps (module docs). No heap allocation on success or for the typed outcomes.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir_world`, `map_resolution` (< 3), `image_height`
/// (0), `half_fov` or `aspect` (a frustum whose narrowest cross-section or depth is below 10⁻⁶ of
/// its size, too thin for the frame's 10⁻⁹ test of what is in view), `depth_range` (not finite, z_min ≥ z_max, or no overlap with the camera's [near, far]),
/// `receivers`/`casters` (a bad box, too many planes — more than [`MAX_FACE_BOUND_PLANES`] with
/// face partitions — a polytope unbounded toward the light; for receivers also an empty list of
/// boxes, while an empty list of casters is no caster; for casters also a bound reaching so far
/// beyond the focus body that the map cannot be fitted with it), `overlap`, `k`
/// (1..=[`MAX_FACE_K`] for face partitions), the splits or the rule's parameter;
/// [`Error::Degenerate`] when a map cannot be represented in `f64`, or its world → clip matrix
/// (either depth convention) not in `f32` (a camera very far from the world origin: its
/// translation times the map's scale overflows, or a stable cascade's world-fixed square cannot
/// be snapped around its focus body; the message names the offset).
pub fn frame(input: &FrameInput<'_>) -> Result<Frame> {
    let mut out = Frame::default();
    frame_into(input, &mut out)?;
    Ok(out)
}

/// As [`frame`], writing into `out` (reused between frames). Each map says whether it is bit
/// for bit the one the same slot held before ([`FrameMap::unchanged`]: the same map resolution
/// and world → clip matrix as after the previous successful call on `out`).
///
/// # Errors
/// As [`frame`]. After an error `out` holds no map (and the next call reports every map changed).
pub fn frame_into(input: &FrameInput<'_>, out: &mut Frame) -> Result<()> {
    out.begin();
    let r = fill(input, out);
    if r.is_err() {
        out.k = 0;
        out.len = 0;
        out.focus = Focus::Empty;
    }
    r
}

/// [`frame_into`]'s work, `out` begun.
fn fill(input: &FrameInput<'_>, out: &mut Frame) -> Result<()> {
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
    check_proportions(&cam.view)?;
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
        res: input.map_resolution,
    }; MAX_PARTITIONS];
    let (k, rule, _) = match input.scheme {
        FrameScheme::Single(rule) => {
            slices[0] = Slice {
                cover: (zn, zf),
                split: (zn, zf),
                blend: (zf, zf),
                res: input.map_resolution,
            };
            (1, rule, false)
        }
        FrameScheme::Cascades { splits, rule } => (
            ctx.cascade_slices(splits, SliceMap::Rule(rule), zn, zf, &mut slices)?,
            rule,
            false,
        ),
        FrameScheme::Stable(splits) => (
            ctx.cascade_slices(splits, SliceMap::Stable, zn, zf, &mut slices)?,
            WarpRule::Uniform,
            true,
        ),
        FrameScheme::Tsm(_) => {
            slices[0] = Slice {
                cover: (zn, zf),
                split: (zn, zf),
                blend: (zf, zf),
                res: input.map_resolution,
            };
            (1, WarpRule::Uniform, false)
        }
        FrameScheme::Faces { rule, k } => return ctx.faces_into(rule, k, (zn, zf), out),
        FrameScheme::Clipmap(opts) => return ctx.clipmap_into(opts, (zn, zf), out),
    };
    check_resolutions(input, k)?;
    for (i, s) in slices[..k].iter().enumerate() {
        let s = &Slice {
            res: input.resolution_at(i),
            ..*s
        };
        out.push_with(|dst| match input.scheme {
            FrameScheme::Stable(_) => ctx.stable_map(s, dst),
            FrameScheme::Tsm(opts) => ctx.tsm_map(s, opts, dst),
            _ => ctx.map(s, rule, dst),
        })?;
    }
    out.settle();
    Ok(())
}

/// A partition's outcome. The map itself is built in the slot the builder is given (a
/// `&mut Option<FrameMap>`, the frame's own slot: no 4.8 KB move, no heap allocation).
enum Built {
    /// The map is in the slot.
    Map,
    /// No map needed, and why.
    None(Focus),
}

struct Ctx<'i, 'a> {
    input: &'i FrameInput<'a>,
    view: &'i ViewFrustum,
    l: DVec3,
    lw: DVec3,
    planes: Planes,
}
