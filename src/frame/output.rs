//! The frame's outputs: a frame's maps and their focus, and how a built map is finished (its
//! error, texel size and world → clip matrices).

use super::casters::Prism;
use super::culling::CullVolume;
use super::{Built, Ctx, Slice, MAX_BODY_VERTICES};
use crate::analytic::partition::MAX_PARTITIONS;
use crate::error::{Error, Result};
use crate::maps::faces::Face;
use crate::maps::matrix::in_clip_depth;
use crate::maps::{ClipDepth, ShadowMatrix};
use crate::measure::vertex::vertex_max;
use crate::measure::FrustumError;
use glam::{DMat4, DVec3, DVec4, Mat4};

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

impl Focus {
    /// The focus in lower case, as the command line's JSON and the Python package spell it:
    /// `body`, `empty`, `flat`, `edge_on`, `zero_depth`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Focus::Body => "body",
            Focus::Empty => "empty",
            Focus::Flat => "flat",
            Focus::EdgeOn => "edge_on",
            Focus::ZeroDepth => "zero_depth",
        }
    }
}

impl LightCase {
    /// The case in lower case, as the command line's JSON and the Python package spell it:
    /// `general`, `sun_straight_down`, `parallel_to_view`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            LightCase::General => "general",
            LightCase::SunStraightDown => "sun_straight_down",
            LightCase::ParallelToView => "parallel_to_view",
        }
    }
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
    /// bias: Bevy's `texel_size`; Filament's `texelSizeWorldSpaceAt` gives both edges at one point).
    pub texel_world: f64,
    /// M_x over the body's vertices (unit resolutions); +∞ (no bound known) where the error was
    /// not measured ([`FrameInput::measure`](super::FrameInput::measure) off): read it through
    /// [`FrameMap::error`] to tell.
    pub max_mx: f64,
    /// M_z over the body's vertices (unit resolutions); +∞ where not measured.
    pub max_mz: f64,
    /// S̄ = M_x M_z over the body; +∞ where not measured.
    pub storage_factor: f64,
    /// The predicted maximum error in screen pixels, `max(M_x, M_z) · image_height /
    /// resolution` (the map's own, [`FrameMap::resolution`]); +∞ where not measured.
    pub max_error_pixels: f64,
    /// What the body is (Body, Flat or ZeroDepth for a built map).
    pub focus: Focus,
    /// The frustum face of a face partition (the shader picks the map by the face its light ray
    /// passes and, for a side face, by `split`, the depths of that part of the face); `None` for
    /// every other scheme.
    pub face: Option<Face>,
    /// The level of a clipmap ([`FrameScheme::Clipmap`](super::FrameScheme::Clipmap)); `None`
    /// for every other scheme.
    pub clipmap_level: Option<i32>,
    /// The camera's world → eye (the upload forms in `upload.rs` compose it with the map).
    pub(super) world_to_eye: DMat4,
    body: [DVec3; MAX_BODY_VERTICES],
    body_len: usize,
    casters_volume: CullVolume,
    receivers_volume: CullVolume,
    unchanged: bool,
    measured: bool,
    /// The map's texels per side.
    pub(super) resolution: u32,
}

/// A map's measured error figures ([`FrameMap::error`]): the fields of the same names of
/// [`FrameMap`], each finite.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapError {
    /// M_x over the body's vertices (unit resolutions).
    pub max_mx: f64,
    /// M_z over the body's vertices (unit resolutions).
    pub max_mz: f64,
    /// S̄ = M_x M_z over the body.
    pub storage_factor: f64,
    /// The predicted maximum error in screen pixels, `max(M_x, M_z) · image_height /
    /// resolution` (the map's own).
    pub max_error_pixels: f64,
}

impl FrameMap {
    /// World → light clip in the requested clip-depth convention.
    #[must_use]
    pub fn world_to_clip(&self, depth: ClipDepth) -> DMat4 {
        // A function of `world_to_clip` alone, so that a map `unchanged` is so in every form.
        in_clip_depth(&self.world_to_clip, depth)
    }
    /// [`FrameMap::world_to_clip`] in single precision for the GPU.
    #[must_use]
    pub fn to_mat4(&self, depth: ClipDepth) -> Mat4 {
        self.world_to_clip(depth).as_mat4()
    }
    /// The map's texels per side ([`FrameInput::map_resolution`](super::FrameInput::map_resolution),
    /// or its slot's entry of [`FrameInput::map_resolutions`](super::FrameInput::map_resolutions)).
    #[must_use]
    pub fn resolution(&self) -> u32 {
        self.resolution
    }
    /// The focus body's vertices, eye space.
    #[must_use]
    pub fn body(&self) -> &[DVec3] {
        &self.body[..self.body_len]
    }
    /// The casters' culling volume, world space: B swept toward the light, cut by the map's
    /// depth range (unbounded toward the light with `depth_clamp`). An object outside it
    /// ([`CullVolume::intersects_aabb`] false) casts no shadow on B that the map holds: it
    /// need not be drawn into this map.
    #[must_use]
    pub fn casters_volume(&self) -> &CullVolume {
        &self.casters_volume
    }
    /// The receivers' culling volume, world space: the slice ∩ the receivers' bound (∩ the face
    /// part's prism for face partitions), whose intersection is B.
    #[must_use]
    pub fn receivers_volume(&self) -> &CullVolume {
        &self.receivers_volume
    }
    /// Whether this map is bit for bit the one the same slot held after the previous successful
    /// [`frame_into`](crate::frame::frame_into) on this [`Frame`]: the same map resolution and
    /// every bit of [`FrameMap::world_to_clip`] (OpenGL depth, `f64`) equal; every other form of
    /// the matrix is a function of it. A map that is unchanged need not be rendered again unless
    /// what is drawn into it moved. `false` for a fresh `Frame`, after an error, and for a slot
    /// that was empty.
    #[must_use]
    pub fn unchanged(&self) -> bool {
        self.unchanged
    }
    /// The map's measured error, `None` where it was not measured
    /// ([`FrameInput::measure`](super::FrameInput::measure) off, and the scheme did not measure to
    /// build the map): the fields `max_mx`, `max_mz`, `storage_factor` and `max_error_pixels`
    /// then hold +∞, no bound known.
    #[must_use]
    pub fn error(&self) -> Option<MapError> {
        self.measured.then_some(MapError {
            max_mx: self.max_mx,
            max_mz: self.max_mz,
            storage_factor: self.storage_factor,
            max_error_pixels: self.max_error_pixels,
        })
    }
}

/// A frame's maps, in a fixed array (no heap allocation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    maps: [Option<FrameMap>; MAX_PARTITIONS],
    /// Slot i of the scheme's partitions (None where its body is empty).
    pub(super) k: usize,
    pub(super) len: usize,
    /// A partition without a map was edge-on to the light.
    pub(super) none_edge_on: bool,
    pub(super) focus: Focus,
    pub(super) light: LightCase,
    pub(super) light_dir_eye: DVec3,
    /// The slots of the previous frame that a new map may be compared with (0 after an error).
    prev_k: usize,
}

impl Default for Frame {
    /// An empty frame, for [`frame_into`](crate::frame::frame_into) to fill.
    fn default() -> Self {
        Self {
            maps: [None; MAX_PARTITIONS],
            k: 0,
            len: 0,
            none_edge_on: false,
            focus: Focus::Empty,
            light: LightCase::General,
            light_dir_eye: DVec3::NEG_Y,
            prev_k: 0,
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
    /// Σ S̄ over the built maps, `None` when none was built or a map's error was not measured
    /// ([`FrameMap::error`]).
    #[must_use]
    pub fn storage_factor(&self) -> Option<f64> {
        let measured = self.maps().iter().all(|m| m.error().is_some());
        (self.len > 0 && measured).then(|| self.maps().iter().map(|m| m.storage_factor).sum())
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
    /// Each slot's world → clip matrix and map resolution (`None` where it holds no map): what
    /// [`Frame::mark_unchanged`] compares a later frame with.
    pub(crate) fn fingerprint(&self, out: &mut Vec<Option<(DMat4, u32)>>) {
        out.clear();
        out.extend(
            self.maps[..self.k]
                .iter()
                .map(|m| m.map(|m| (m.world_to_clip, m.resolution))),
        );
    }

    /// Sets every map's [`FrameMap::unchanged`] against `prev` (a [`Frame::fingerprint`])
    /// instead of the frame built before into the same `Frame`: for callers that build several
    /// frames into one `Frame` before choosing (the controller).
    pub(crate) fn mark_unchanged(&mut self, prev: &[Option<(DMat4, u32)>]) {
        for (slot, p) in self.maps[..self.k]
            .iter_mut()
            .zip(prev.iter().chain(std::iter::repeat(&None)))
        {
            if let Some(m) = slot {
                m.unchanged =
                    p.is_some_and(|(p, r)| r == m.resolution && same_bits(&p, &m.world_to_clip));
            }
        }
    }

    /// Starts a frame: the slots held so far are the previous frame's, to compare the new maps
    /// with.
    pub(super) fn begin(&mut self) {
        self.prev_k = self.k;
    }

    /// Builds the next partition's outcome into slot `k` (`build` writes a map into the slot it
    /// is given and says so with [`Built::Map`]; `None` where no map is needed), saying whether a
    /// map is bit for bit the slot's previous one. Built in place: a [`FrameMap`] is 4.8 KB.
    pub(super) fn push_with(
        &mut self,
        build: impl FnOnce(&mut Option<FrameMap>) -> Result<Built>,
    ) -> Result<()> {
        let prev = match &self.maps[self.k] {
            Some(p) if self.k < self.prev_k => Some((p.world_to_clip, p.resolution)),
            _ => None,
        };
        let slot = &mut self.maps[self.k];
        match (build(slot)?, slot) {
            (Built::Map, Some(m)) => {
                self.len += 1;
                m.unchanged =
                    prev.is_some_and(|(p, r)| r == m.resolution && same_bits(&p, &m.world_to_clip));
            }
            // (A builder that says `Map` has filled the slot: only `None` comes here.)
            (built, slot) => {
                *slot = None;
                self.none_edge_on |= matches!(built, Built::None(Focus::EdgeOn));
            }
        }
        self.k += 1;
        Ok(())
    }

    /// The frame's focus once every partition is in: the first built map's, or why none was
    /// built (edge-on if any partition was, else empty).
    pub(super) fn settle(&mut self) {
        let first = self.maps().iter().next().map(|m| m.focus);
        self.focus = match first {
            Some(f) => f,
            None if self.none_edge_on => Focus::EdgeOn,
            None => Focus::Empty,
        };
    }
}

impl Ctx<'_, '_> {
    pub(super) fn finish<'d>(
        &self,
        shadow: ShadowMatrix,
        pts: &[DVec3],
        s: &Slice,
        focus: Focus,
        prism: Option<&Prism>,
        dst: &'d mut Option<FrameMap>,
    ) -> Result<&'d mut FrameMap> {
        // Measured whether or not the figures are reported: the measurement is also the check
        // that the map is regular at every vertex of B, and whether a frame is built must not
        // depend on `measure` (a map it refuses has a zero texel and NaN bias unmeasured).
        let err = vertex_max(&shadow.matrix(), self.l, self.view.tan_half_fov(), pts).ok_or_else(
            || Error::Degenerate("the map is singular at a vertex of the focus body".into()),
        )?;
        let err = self.input.measures().then_some(err);
        self.finish_measured(shadow, err, pts, s, focus, &[], prism, dst)
    }

    /// [`Ctx::finish`] with the map's error over `pts` already measured (by `vertex_max` with
    /// the frame's light and tan θ, as `finish` would; `None`: not measured), B being the slice
    /// `s.cover` ∩ the receivers' bound ∩ the planes `extra` (a face part's prism). `prism`:
    /// the prism of B's footprint in [`Ctx::sweep_space`] where the caller has it (the casters'
    /// volume's sides; built here otherwise).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn finish_measured<'d>(
        &self,
        shadow: ShadowMatrix,
        err: Option<FrustumError>,
        pts: &[DVec3],
        s: &Slice,
        focus: Focus,
        extra: &[DVec4],
        prism: Option<&Prism>,
        dst: &'d mut Option<FrameMap>,
    ) -> Result<&'d mut FrameMap> {
        // The largest texel edge over B: clip spans 2 over the map's `res` texels.
        let res = f64::from(s.res);
        let matrix = shadow.matrix();
        let texel = pts
            .iter()
            .filter_map(|p| texel_edges(&matrix, self.l, *p))
            .fold(0.0f64, |a, (es, et)| a.max(es).max(et))
            * 2.0
            / res;
        let image = f64::from(self.input.image_height);
        // The matrices a renderer uploads, in every depth convention, must be finite in f64 and
        // in the GPU's f32 (a camera far from the world origin scales its translation past them).
        let world_to_eye = self.input.camera.world_to_eye;
        let world_to_clip = matrix * world_to_eye;
        if !ClipDepth::ALL.iter().all(|d| {
            let m = in_clip_depth(&world_to_clip, *d);
            m.is_finite() && m.as_mat4().is_finite()
        }) {
            return Err(Error::Degenerate(
                "the map's world → clip matrix overflows f32 or f64 (the camera is too far from \
                 the world origin for the map's scale)"
                    .into(),
            ));
        }
        let none = FrustumError {
            max_mx: f64::INFINITY,
            max_mz: f64::INFINITY,
            storage_factor: f64::INFINITY,
        };
        // Written into the slot field by field (a reused `Frame` holds one already): every field,
        // and the arrays' unused tails zeroed, so that the map is the same whatever the slot held.
        let m = dst.get_or_insert_with(|| FrameMap {
            shadow,
            world_to_clip,
            split: s.split,
            blend: s.blend,
            texel_world: texel,
            max_mx: f64::INFINITY,
            max_mz: f64::INFINITY,
            storage_factor: f64::INFINITY,
            max_error_pixels: f64::INFINITY,
            focus,
            face: None,
            clipmap_level: None,
            world_to_eye,
            body: [DVec3::ZERO; MAX_BODY_VERTICES],
            body_len: 0,
            casters_volume: CullVolume::EMPTY,
            receivers_volume: CullVolume::EMPTY,
            unchanged: false,
            measured: false,
            resolution: s.res,
        });
        m.shadow = shadow;
        m.world_to_clip = world_to_clip;
        m.split = s.split;
        m.blend = s.blend;
        m.texel_world = texel;
        m.max_mx = err.unwrap_or(none).max_mx;
        m.max_mz = err.unwrap_or(none).max_mz;
        m.storage_factor = err.unwrap_or(none).storage_factor;
        m.max_error_pixels = err.map_or(f64::INFINITY, |e| e.max_mx.max(e.max_mz) * image / res);
        m.focus = focus;
        m.face = None;
        m.clipmap_level = None;
        m.world_to_eye = world_to_eye;
        m.body[..pts.len()].copy_from_slice(pts);
        m.body[pts.len()..].fill(DVec3::ZERO);
        m.body_len = pts.len();
        self.cull_volumes(
            pts,
            &matrix,
            (s.cover, extra, prism),
            &mut m.casters_volume,
            &mut m.receivers_volume,
        );
        m.unchanged = false;
        m.measured = err.is_some();
        m.resolution = s.res;
        Ok(m)
    }
}

/// Whether `a` and `b` are equal bit for bit.
fn same_bits(a: &DMat4, b: &DMat4) -> bool {
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array().iter())
        .all(|(x, y)| x.to_bits() == y.to_bits())
}

/// The edges of a texel of `m` (eye → light clip) at `p`, in the plane perpendicular to the unit
/// light direction `l`, per unit of clip s and t: the columns of the inverse of the Jacobian of
/// that plane → (s, t), `(|∇t⊥| / |D|, |∇s⊥| / |D|)` with `D = (∇s × ∇t)·l` (a texel is a light
/// ray's cross-section, so the edges do not depend on where along the ray `p` lies). Filament's
/// `texelSizeWorldSpaceAt` (ShadowMap.cpp at commit 0362f36e) takes the same columns at the one
/// point it is given; its 2023 releases' `texelSizeWorldSpace` took their larger. `None` behind the
/// map's centre of projection or where the map is singular.
fn texel_edges(m: &DMat4, l: DVec3, p: DVec3) -> Option<(f64, f64)> {
    texel_vectors(m, l, p).map(|(es, et)| (es.length(), et.length()))
}

/// The edge vectors of [`texel_edges`]: `E_s = (∇t⊥ × l) / D` and `E_t = (l × ∇s⊥) / D`, the
/// vectors in the plane ⊥ `l` that move clip s (t) by 1 and t (s) by 0.
pub(super) fn texel_vectors(m: &DMat4, l: DVec3, p: DVec3) -> Option<(DVec3, DVec3)> {
    let h = *m * p.extend(1.0);
    if h.w.is_nan() || h.w <= 0.0 {
        return None;
    }
    let r3 = m.row(3).truncate();
    let grad = |row: DVec3, v: f64| (row * h.w - r3 * v) / (h.w * h.w);
    let gs = grad(m.row(0).truncate(), h.x);
    let gt = grad(m.row(1).truncate(), h.y);
    let (gs, gt) = (gs - gs.dot(l) * l, gt - gt.dot(l) * l);
    let d = gs.cross(gt).dot(l);
    let edges = (gt.cross(l) / d, l.cross(gs) / d);
    (edges.0.is_finite() && edges.1.is_finite()).then_some(edges)
}
