//! Face partitions (Lloyd 2006 §5.1, Lloyd 2005 §4): one warped map per frustum face the light
//! sees, optionally z-partitioned along each face.
//!
//! # Which faces
//!
//! Light space has `y` toward the light (against the direction `L` light travels) and `v = −Z` is
//! the view vector. Lloyd 2006 §5.1: "the narrowest image beams are those first encountered by a
//! light beam when v·y < 0 … Therefore the front faces of the view frustum with respect to the
//! light should be used in this case. Likewise, when v·y > 0 … the back faces should be used."
//! With outward face normals `N`:
//!
//! - `v·y < 0` (`L.z < 0`, the light travels along the view, source behind the viewer): the
//!   front faces, `N·L < 0`, where light enters the frustum;
//! - otherwise (`L.z ≥ 0`): the back faces, `N·L > 0`, where light leaves it.
//!
//! Either way, along each light ray the chosen face is where the ray is nearest the eye, so the
//! image beams are narrowest there and the face bounds the error of the whole partition: the
//! partition of a face is the part of the frustum whose light rays pass through it (the prism of
//! the face along the light), and its maximum error is the maximum over the face. The chosen
//! faces tile the frustum's silhouette seen from the light, so the partitions tile the frustum.
//! The far face is never chosen. A face that is edge-on within [`EDGE_ON`] is skipped: its
//! `|N·L| ≤ EDGE_ON` *and* its area projected along the light is at most `EDGE_ON` of the
//! silhouette's. Its prism is then thinner than a millionth of its own size and of the frustum's
//! shadow, so it covers no point a renderer could sample; at exactly `L.z = 0` (light perpendicular
//! to the view) the near face is such a face. The second condition matters for a half field of
//! view near π/2: the frustum is then a slab far wider than deep, every face's `|N·L|` is tiny
//! for an overhead light (the bottom face's is cos θ), yet the bottom face is the whole footprint.
//! The chosen faces tile the silhouette, so one of them holds at least a fifth of it and is never
//! skipped: the partitions are never empty.
//!
//! # One warp per side face part: two candidate axes
//!
//! Lloyd 2006 §5.1: "we first project the vectors from the viewpoint through the two side edges of
//! the face, e₀ and e₁, into a plane perpendicular to the light direction to obtain e′₀ and e′₁. We
//! use the bisector of the projected edge vectors e′₀ + e′₁ to align the z axis." The crate uses
//! the unit vectors `ê′₀ + ê′₁`, the true bisector of the angle (with unequal lengths, `e′₀ + e′₁`
//! leans towards the longer one; [`face_axis`]). The face's prism, projected along the light, is
//! the wedge between e′₀ and e′₁ from the projected eye, cut by the near and far edges; every
//! point of it has a positive coordinate along the bisector.
//!
//! The bisector degenerates when a side edge turns parallel to the light (the light near a side
//! edge of the frustum, the face next to it seen nearly edge-on): that edge's projection e′ shrinks
//! to the projected eye, its direction ê′ (and the bisector with it) swings with the last bits of
//! the light's offset, and the edge's vertices sit at a coordinate near 0 along the axis, so
//! `d_n → 0` and the LiSPSM n′ below → 0: a map warped to a point on the face along an axis that
//! can run across the face's thin projection. Σ S̄ then grew as δ^(−1/2) with the light's angle δ
//! from the edge until [`EDGE_ON`] cut the face off (f/n = 1000, θ = 30°, k = 4: 117 at δ = 10⁻²,
//! 1761 at δ = 10⁻⁵, against 38.0 with the light behind), in slivers of directions a 1° grid misses.
//!
//! So each side face also has its **depth axis** ([`face_depth_axis`]): the direction, in the
//! plane perpendicular to the light, along which the eye depth of the face's points grows,
//! perpendicular to the projected near edge (a line of constant depth). Along it the face's point
//! at depth z has the coordinate `z h`, h the projected eye's distance from the projected near
//! edge, so the face's projection is exactly an overhead frustum's footprint (sheared when the
//! light tilts sideways) from `n h` to `f h`, and as the face turns edge-on, h ∝ |N·L| → 0
//! uniformly: the maps' t range shrinks by h, m_z ∝ h, m_x is unchanged and the face's S̄ → 0
//! with its prism, continuously. The depth axis degenerates only when the light is parallel to the
//! near edge, where the bisector is well conditioned. Every face part is fitted with both axes and
//! keeps the map with the smaller measured S̄ (either is a valid map of the part: the error over a
//! face's prism is its maximum over the face, whatever the axis), so it is never worse than
//! Lloyd's bisector. With the light behind or overhead the two axes coincide.
//!
//! Measured worst case over the hemisphere (Nelder–Mead from a 2° grid, `tests/faces.rs`):
//! at θ ≥ 30° (f/n = 100 to 10⁶) it is the light behind (or in front) itself,
//! `2k((f/n)^{1/k} − 1) + 1`, for every k = 1…8; at θ = 10° it is 2.19–2.32 times that.
//!
//! # The face's n′ (how Eq 19 and Eq 21 come out)
//!
//! A face's projection plays the part the view frustum's footprint plays for an overhead light:
//! the apex is the projected eye, the warp axis (bisector or depth axis) the view axis. Let `d_n`
//! and `d_f` be the smallest and largest coordinates of the (sub-)face's vertices along the axis,
//! measured from the projected eye. The crate's face rules ([`FaceWarp`]) are the overhead rules with (n, f) replaced
//! by (d_n, d_f), the warp's centre of projection on the axis through the projected eye:
//!
//! - [`FaceWarp::Lispsm`]: `n′ = d_n + √(d_n d_f)` (LiSPSM's optimum for the face);
//! - [`FaceWarp::Psm`]: `n′ = d_n` (the centre of projection at the projected eye);
//! - [`FaceWarp::Uniform`]: n′ = ∞, an orthographic map aligned with the axis.
//!
//! Why this reproduces the papers. With the light overhead (L = −Y, `v·y = 0`) the only back face
//! is the bottom face, whose projection is the whole footprint with the bisector along −Z and
//! `(d_n, d_f) = (n, f)`: the map is the LiSPSM map of the frustum and S̄ is Eq 12, Eq 18 with
//! z-partitions, so Eq 19 holds. With the light behind (L = −Z) the front faces are the four sides
//! and the near face. The top face `{(x, z tanθ, −z) : |x| ≤ z tanθ}` projects to
//! `{(x, u) : |x| ≤ u}` with `u = z tanθ` along the bisector +Y and image beams `w_i = 2 z tanθ = 2u`
//! — exactly an overhead frustum with half field of view 45°, near `n tanθ` and far `f tanθ`. So a
//! side face with k self-similar z-partitions and n′ ≤ n′_LSPSM has S̄ = k((f/n)^{1/k} − 1)/2 for
//! *any* θ (square image), and the near face, a square of side `2n tanθ` at depth n seen
//! face-on with an orthographic map aligned with its edges, has S̄ = 1. The sum
//! `4 k((f/n)^{1/k} − 1)/2 + 1` equals Lloyd 2006 Eq 21, `4 S̄_ZP+W,overhead + 1`, at θ = 45°, where
//! the paper states it.
//!
//! # The near face
//!
//! As Lloyd 2006 §5.2 says, the near face is not z-partitioned ("the image beam widths are constant
//! along this face"): it gets one orthographic map, aligned with the projection of the image's up
//! vector +Y (so that, seen face-on, its square fills the map), and contributes S̄ = 1 when the
//! light is exactly behind (the "+1" of Eq 21). Lloyd 2005 §4.1 notes it may instead be covered by
//! stretching the side partitions to the viewpoint; the crate keeps it separate, which is what
//! Eq 21 counts.
//!
//! # Depth
//!
//! Each map's depth range covers the whole frustum along the light (each face vertex is swept to
//! the frustum's nearest and farthest light-space depth before fitting), so every point of the
//! face's prism inside the frustum maps into the clip volume.
//!
//! ```
//! use shadow_aliasing::maps::faces::{face_partitions, FaceWarp};
//! use shadow_aliasing::ViewFrustum;
//! use glam::DVec3;
//! let view = ViewFrustum::new(1.0, 100.0, 45f64.to_radians())?;
//! // Light from behind: four side faces and the near face.
//! let p = face_partitions(&view, DVec3::new(0.0, 0.0, -1.0), FaceWarp::Lispsm, 1)?;
//! assert_eq!(p.len(), 5);
//! // Lloyd 2006 Eq 21 with k = 1, θ = 45°: 4 (f/n − 1)/(2 tan θ) + 1.
//! let expect = 4.0 * 99.0 / 2.0 + 1.0;
//! assert!((p.storage_factor() - expect).abs() < 1e-9 * expect);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::analytic::partition::{z_splits, SplitScheme, Splits, MAX_PARTITIONS};
use crate::error::{fmt_num, Error, Result};
use crate::frustum::{LightDir, NPrime, ViewFrustum};
use crate::maps::fit::{fit_points, FitFailure};
use crate::maps::lightspace::{light_space_dir, LightSpace};
use crate::maps::ShadowMatrix;
use crate::measure::vertex::vertex_max;
use crate::measure::FrustumError;
use crate::numeric::EDGE_ON;
use glam::{DMat4, DVec3};

/// The largest number of face partitions: four side faces of [`MAX_PARTITIONS`] z-partitions
/// each, and the near face.
pub const MAX_FACE_PARTITIONS: usize = 4 * MAX_PARTITIONS + 1;

/// A face of the view frustum.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Face {
    /// The −Y side (through corners −x−y and +x−y).
    Bottom,
    /// The +X side.
    Right,
    /// The +Y side.
    Top,
    /// The −X side.
    Left,
    /// The near plane.
    Near,
    /// The far plane.
    Far,
}

impl Face {
    /// The six faces.
    pub const ALL: [Face; 6] = [
        Face::Bottom,
        Face::Right,
        Face::Top,
        Face::Left,
        Face::Near,
        Face::Far,
    ];

    /// The unit outward normal of the face in eye space.
    ///
    /// With `t = tan θ` and `a` the aspect: bottom `(0, −1, t)`, top `(0, 1, t)`, right
    /// `(1, 0, t a)`, left `(−1, 0, t a)`, each normalised; near `+Z`, far `−Z`.
    #[must_use]
    pub fn outward_normal(self, view: &ViewFrustum) -> DVec3 {
        let t = view.tan_half_fov();
        self.normal_with(t, t * view.aspect())
    }

    #[inline]
    fn normal_with(self, t: f64, ta: f64) -> DVec3 {
        match self {
            Face::Bottom => DVec3::new(0.0, -1.0, t).normalize(),
            Face::Top => DVec3::new(0.0, 1.0, t).normalize(),
            Face::Right => DVec3::new(1.0, 0.0, ta).normalize(),
            Face::Left => DVec3::new(-1.0, 0.0, ta).normalize(),
            Face::Near => DVec3::Z,
            Face::Far => DVec3::NEG_Z,
        }
    }

    /// The directions from the eye through the face's two side edges, at unit depth
    /// (`z = −1`), in counter-clockwise order seen from inside the frustum; `None` for the near
    /// and far faces. With `t = tan θ`, `a` the aspect, the four edge directions are
    /// `c₀ = (−ta, −t, −1)`, `c₁ = (ta, −t, −1)`, `c₂ = (ta, t, −1)`, `c₃ = (−ta, t, −1)`; bottom is
    /// `(c₀, c₁)`, right `(c₁, c₂)`, top `(c₂, c₃)`, left `(c₃, c₀)`.
    #[must_use]
    pub fn side_edges(self, view: &ViewFrustum) -> Option<[DVec3; 2]> {
        let t = view.tan_half_fov();
        self.edges_with(t, t * view.aspect())
    }

    #[inline]
    fn edges_with(self, t: f64, ta: f64) -> Option<[DVec3; 2]> {
        let c = [
            DVec3::new(-ta, -t, -1.0),
            DVec3::new(ta, -t, -1.0),
            DVec3::new(ta, t, -1.0),
            DVec3::new(-ta, t, -1.0),
        ];
        match self {
            Face::Bottom => Some([c[0], c[1]]),
            Face::Right => Some([c[1], c[2]]),
            Face::Top => Some([c[2], c[3]]),
            Face::Left => Some([c[3], c[0]]),
            Face::Near | Face::Far => None,
        }
    }

    /// The four vertices of the part of the face between depths `near` and `far`: for a side face
    /// `[e₀ near, e₁ near, e₁ far, e₀ far]`; for the near (far) face its four corners at depth
    /// `view.near()` (`view.far()`), whatever `near` and `far`.
    #[must_use]
    pub fn vertices(self, view: &ViewFrustum, near: f64, far: f64) -> [DVec3; 4] {
        let t = view.tan_half_fov();
        self.vertices_with(view, t, t * view.aspect(), near, far)
    }

    /// The face's name in lower case (`"bottom"`, `"right"`, `"top"`, `"left"`, `"near"`,
    /// `"far"`), as the command line's JSON and the Python package spell it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Face::Bottom => "bottom",
            Face::Right => "right",
            Face::Top => "top",
            Face::Left => "left",
            Face::Near => "near",
            Face::Far => "far",
        }
    }

    /// Whether this is one of the four side faces.
    #[must_use]
    pub(crate) fn is_side(self) -> bool {
        !matches!(self, Face::Near | Face::Far)
    }

    #[inline]
    pub(crate) fn vertices_with(
        self,
        view: &ViewFrustum,
        t: f64,
        ta: f64,
        near: f64,
        far: f64,
    ) -> [DVec3; 4] {
        match self.edges_with(t, ta) {
            Some([e0, e1]) => [e0 * near, e1 * near, e1 * far, e0 * far],
            None => {
                let d = if self == Face::Near {
                    view.near()
                } else {
                    view.far()
                };
                // c₀, c₁ (bottom edges) then c₂, c₃ (top edges): the corners' order.
                let c = Face::Bottom
                    .edges_with(t, ta)
                    .into_iter()
                    .chain(Face::Top.edges_with(t, ta))
                    .flatten();
                let mut out = [DVec3::ZERO; 4];
                for (o, e) in out.iter_mut().zip(c) {
                    *o = e * d;
                }
                out
            }
        }
    }
}

/// The faces the light sees, as Lloyd 2006 §5.1 chooses them (see the module docs), in the
/// order bottom, right, top, left, near; at most five.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VisibleFaces {
    faces: [Face; 5],
    len: usize,
    /// Whether these are the front faces (`v·y < 0`, light travelling along the view) or the
    /// back faces.
    pub front: bool,
}

impl VisibleFaces {
    /// The chosen faces.
    #[must_use]
    pub fn faces(&self) -> &[Face] {
        &self.faces[..self.len]
    }
}

/// The faces used for face partitioning for a light travelling along `light_dir` (eye space).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir` for a zero or non-finite vector.
///
/// ```
/// # use shadow_aliasing::maps::faces::{visible_faces, Face};
/// # use shadow_aliasing::ViewFrustum;
/// # use glam::DVec3;
/// let view = ViewFrustum::new(1.0, 10.0, 0.5)?;
/// let over = visible_faces(&view, DVec3::new(0.0, -1.0, 0.0))?;
/// assert_eq!(over.faces(), &[Face::Bottom]);
/// let behind = visible_faces(&view, DVec3::new(0.0, 0.0, -1.0))?;
/// assert!(behind.front && behind.faces().len() == 5);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn visible_faces(view: &ViewFrustum, light_dir: DVec3) -> Result<VisibleFaces> {
    let l = LightDir::new(light_dir)?.as_dvec3();
    let t = view.tan_half_fov();
    Ok(visible_with(
        t,
        t * view.aspect(),
        view.near() / view.far(),
        l,
    ))
}

pub(crate) fn visible_with(t: f64, ta: f64, near_over_far: f64, l: DVec3) -> VisibleFaces {
    // v·y = (−Z)·(−L) = L.z; front faces when it is negative.
    let front = l.z < 0.0;
    let sign = if front { -1.0 } else { 1.0 };
    // Signed areas of the faces projected along the light, over f² (positive when the outward
    // normal is along L): a side face between its edges cᵢ, cᵢ₊₁ at unit depth is the trapezoid
    // ½ (f² − n²)(cᵢ × cᵢ₊₁), the near face 4 n² t ta Z, the far face −4 f² t ta Z.
    let q = near_over_far * near_over_far;
    let side = |face: Face| {
        face.edges_with(t, ta)
            .map_or(0.0, |[e0, e1]| 0.5 * (1.0 - q) * e0.cross(e1).dot(l))
    };
    let near = 4.0 * q * t * ta * l.z;
    let area = |face: Face| match face {
        Face::Near => near,
        Face::Far => -4.0 * t * ta * l.z,
        _ => side(face),
    };
    // The silhouette's area: half the summed |areas| of the six faces (each light ray enters
    // once and leaves once).
    let silhouette = 0.5 * Face::ALL.iter().map(|&f| area(f).abs()).sum::<f64>();
    let mut faces = [Face::Near; 5];
    let mut len = 0;
    for face in [Face::Bottom, Face::Right, Face::Top, Face::Left, Face::Near] {
        let facing = sign * face.normal_with(t, ta).dot(l);
        let edge_on = facing <= EDGE_ON && sign * area(face) <= EDGE_ON * silhouette;
        if facing > 0.0 && !edge_on {
            faces[len] = face;
            len += 1;
        }
    }
    VisibleFaces { faces, len, front }
}

/// Lloyd's warp axis of a side face: the bisector `ê′₀ + ê′₁` of its side edges projected
/// perpendicular to the light (Lloyd 2006 §5.1), the first of the two candidates the face
/// partitions try (module docs). For the near and far faces, the image's up
/// vector +Y (projected by [`light_space`](crate::maps::light_space)).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir`; [`Error::Degenerate`] when a side edge is
/// within [`EDGE_ON`] of parallel to the light (the face is then edge-on or nearly so, and the
/// face partitions use its [`face_depth_axis`]).
pub fn face_axis(view: &ViewFrustum, face: Face, light_dir: DVec3) -> Result<DVec3> {
    let l = LightDir::new(light_dir)?.as_dvec3();
    let t = view.tan_half_fov();
    axis_with(face, t, t * view.aspect(), l)
}

fn axis_with(face: Face, t: f64, ta: f64, l: DVec3) -> Result<DVec3> {
    match face.edges_with(t, ta) {
        None => Ok(DVec3::Y),
        Some([e0, e1]) => {
            let p0 = e0 - e0.dot(l) * l;
            let p1 = e1 - e1.dot(l) * l;
            let (l0, l1) = (p0.length(), p1.length());
            if !(l0 > EDGE_ON * e0.length() && l1 > EDGE_ON * e1.length()) {
                return Err(Error::Degenerate(format!(
                    "a side edge of the {face:?} face is parallel to the light {l}"
                )));
            }
            Ok(p0 / l0 + p1 / l1)
        }
    }
}

/// The depth axis of a side face: the direction, perpendicular to the light, along which the eye
/// depth of the face's points grows — perpendicular to the projection of the face's near edge
/// (a line of constant depth), pointing away from the projected eye. `None` for the near and far
/// faces, and when the light is within [`EDGE_ON`] of parallel to the near edge (the edge's
/// projection, and with it the axis, vanishes).
///
/// Along this axis every point of the face at depth z has the coordinate `z h`, with h the
/// distance of the projected eye from the projected near edge, so the face's projection is an
/// overhead frustum's footprint (sheared when the light tilts sideways) of depths `[n h, f h]`.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir`.
pub fn face_depth_axis(view: &ViewFrustum, face: Face, light_dir: DVec3) -> Result<Option<DVec3>> {
    let l = LightDir::new(light_dir)?.as_dvec3();
    let t = view.tan_half_fov();
    Ok(depth_axis_with(face, t, t * view.aspect(), l))
}

fn depth_axis_with(face: Face, t: f64, ta: f64, l: DVec3) -> Option<DVec3> {
    let [e0, e1] = face.edges_with(t, ta)?;
    let e = e1 - e0;
    // L × E is perpendicular to the light and to the projected edge E − (E·L) L.
    let m = l.cross(e);
    if m.length() <= EDGE_ON * e.length() {
        return None;
    }
    Some(if m.dot(e0) < 0.0 { -m } else { m })
}

/// How each face partition's n′ is chosen (see the module docs): the overhead rules with the
/// (sub-)face's extent `[d_n, d_f]` along its bisector in place of `[n, f]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum FaceWarp {
    /// n′ = ∞: orthographic, aligned with the bisector.
    Uniform,
    /// n′ = d_n: the centre of projection at the projected eye.
    Psm,
    /// n′ = d_n + √(d_n d_f). The default; it reproduces Lloyd 2006 Eq 19 and 21.
    #[default]
    Lispsm,
}

/// One face partition: its face, the depth range of its part of the face, its map and its
/// measured maximum error over the (sub-)face's vertices.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FacePartition {
    /// Which face.
    pub face: Face,
    /// The map (eye → light clip, OpenGL depth); `shadow.near`, `shadow.far` are the depths of
    /// this part of the face (both `view.near()` for the near face).
    pub shadow: ShadowMatrix,
    /// The four vertices of this part of the face (where its error is measured).
    pub vertices: [DVec3; 4],
    /// M_x, M_z over `vertices` (unit resolutions).
    pub error: FrustumError,
}

impl FacePartition {
    /// S̄ = M_x M_z of this partition.
    #[must_use]
    pub fn storage_factor(&self) -> f64 {
        self.error.storage_factor
    }
}

/// A frame's face partitions in a fixed array (no heap allocation): for each visible side face
/// (bottom, right, top, left order), its z-partitions near to far, then the near face if visible.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FacePartitions {
    parts: [Option<FacePartition>; MAX_FACE_PARTITIONS],
    len: usize,
    /// The chosen faces.
    pub faces: VisibleFaces,
}

impl FacePartitions {
    /// Number of partitions.
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }
    /// Whether there is none (never: [`face_partitions_with`] refuses an empty choice).
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
    /// The partitions.
    pub fn iter(&self) -> impl Iterator<Item = &FacePartition> {
        self.parts[..self.len].iter().flatten()
    }
    /// The summed storage factor.
    #[must_use]
    pub fn storage_factor(&self) -> f64 {
        self.iter().map(FacePartition::storage_factor).sum()
    }
}

/// Face partitions with `k` self-similar z-partitions on each side face (Lloyd 2006 Eq 15, 16
/// over `[near, far]`), the near face unpartitioned.
///
/// # Errors
/// As [`face_partitions_with`].
pub fn face_partitions(
    view: &ViewFrustum,
    light_dir: DVec3,
    rule: FaceWarp,
    k: usize,
) -> Result<FacePartitions> {
    let splits = z_splits(view.near(), view.far(), k, SplitScheme::SelfSimilar)?;
    face_partitions_with(view, light_dir, rule, &splits)
}

/// Face partitions with the side faces cut at the depths of `splits` (which must lie within
/// `[view.near(), view.far()]`).
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir` (zero or not finite) or `splits` (planes outside
/// the view's depth range); [`Error::Degenerate`] when no face is seen (not reachable for a
/// valid frustum and light, checked all the same) or when neither warp axis of a face part gives
/// a map [`fit_warp`](crate::maps::fit_warp) accepts (a face part with no extent along or across
/// the axis beyond 10⁻¹² of the swept points' extent: met with a half field of view within about
/// 10⁻² of π/2 and a grazing light) and regular at the part's vertices.
pub fn face_partitions_with(
    view: &ViewFrustum,
    light_dir: DVec3,
    rule: FaceWarp,
    splits: &Splits,
) -> Result<FacePartitions> {
    let mut parts = [None; MAX_FACE_PARTITIONS];
    let mut len = 0;
    let faces = visit_face_partitions(view, LightDir::new(light_dir)?, rule, splits, |p| {
        parts[len] = Some(*p);
        len += 1;
    })?;
    Ok(FacePartitions { parts, len, faces })
}

/// [`face_partitions_with`], handing each partition to `visit` as it is built; returns the
/// chosen faces.
pub(crate) fn visit_face_partitions(
    view: &ViewFrustum,
    light: LightDir,
    rule: FaceWarp,
    splits: &Splits,
    mut visit: impl FnMut(&FacePartition),
) -> Result<VisibleFaces> {
    let l = light.as_dvec3();
    crate::maps::cascades::splits_within(view, splits)?;
    let tan = view.tan_half_fov();
    let ta = tan * view.aspect();
    let faces = visible_with(tan, ta, view.near() / view.far(), l);
    // The frustum's extent along the light (toward-the-light coordinate y = −L·p).
    let (mut y_lo, mut y_hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for c in Face::Near
        .vertices_with(view, tan, ta, 0.0, 0.0)
        .into_iter()
        .chain(Face::Far.vertices_with(view, tan, ta, 0.0, 0.0))
    {
        let y = -l.dot(c);
        y_lo = y_lo.min(y);
        y_hi = y_hi.max(y);
    }
    if faces.len == 0 {
        // The chosen faces tile the silhouette, so one of them holds at least a fifth of its area
        // and is never skipped; an empty choice means the light direction or the frustum is not
        // representable (it is refused rather than reported as zero maps).
        return Err(Error::Degenerate(format!(
            "no face of the view frustum is seen by the light {l}"
        )));
    }
    let fitter = PartFitter {
        rule,
        y_range: (y_lo, y_hi),
        l,
        tan,
    };
    for &face in faces.faces() {
        let spaces = face_spaces(face, tan, ta, light);
        let count = if face.is_side() { splits.k() } else { 1 };
        for j in 0..count {
            let (a, b) = if face.is_side() {
                splits.range(j)
            } else {
                (view.near(), view.near())
            };
            let vertices = face.vertices_with(view, tan, ta, a, b);
            let (matrix, n_prime, error) =
                fitter.best::<12>(&spaces, &vertices, &vertices, face, (a, b))?;
            visit(&FacePartition {
                face,
                shadow: ShadowMatrix::new(matrix, light, n_prime, a, b),
                vertices,
                error,
            });
        }
    }
    Ok(faces)
}

#[cold]
#[inline(never)]
fn singular(face: Face, a: f64, b: f64) -> Error {
    Error::Degenerate(format!(
        "the map of the {face:?} face over depths [{}, {}] is singular at a vertex",
        fmt_num(a),
        fmt_num(b)
    ))
}

/// The candidate warp axes of a face as light spaces: Lloyd's bisector, and for a side face its
/// depth axis (module docs). A candidate that cannot be built (a side edge along the light, the
/// light along the near edge) is left out; the bisector's error is reported when no candidate is
/// left ([`FaceSpaces::first_err`], written only then: no allocation while a map is built).
pub(crate) struct FaceSpaces {
    spaces: [Option<LightSpace>; 2],
    face: Face,
    tan: f64,
    ta: f64,
    light: LightDir,
}

pub(crate) fn face_spaces(face: Face, tan: f64, ta: f64, light: LightDir) -> FaceSpaces {
    let l = light.as_dvec3();
    let mut out = FaceSpaces {
        spaces: [None; 2],
        face,
        tan,
        ta,
        light,
    };
    out.spaces[0] = out.bisector().ok();
    if face.is_side() {
        out.spaces[1] =
            depth_axis_with(face, tan, ta, l).and_then(|a| light_space_dir(light, a).ok());
    }
    out
}

impl FaceSpaces {
    /// The light space of Lloyd's bisector, or why it cannot be built.
    fn bisector(&self) -> Result<LightSpace> {
        axis_with(self.face, self.tan, self.ta, self.light.as_dvec3())
            .and_then(|a| light_space_dir(self.light, a))
    }

    /// Why the bisector's light space cannot be built, `None` when it can.
    #[cold]
    fn first_err(&self) -> Option<Error> {
        self.bisector().err()
    }
}

/// Why a face part's fit in one candidate light space failed, as a value that costs nothing to
/// make: the other candidate may succeed, and then nothing is written (or allocated).
#[derive(Debug, Clone, Copy)]
enum PartFailure {
    /// More vertices than the fit holds.
    TooManyVertices,
    /// The warp could not be fitted.
    Fit(FitFailure),
    /// The fitted map is singular at a vertex.
    Singular,
}

impl PartFailure {
    #[cold]
    #[inline(never)]
    fn into_error(self, face: Face, (a, b): (f64, f64)) -> Error {
        match self {
            PartFailure::TooManyVertices => Error::Degenerate(format!(
                "the {face:?} face part has more vertices than the fit holds"
            )),
            PartFailure::Fit(f) => f.into(),
            PartFailure::Singular => singular(face, a, b),
        }
    }
}

/// What every face part's fit shares: the face rule, the extent along the light to cover
/// (toward-the-light coordinate), the unit light direction and tan θ.
pub(crate) struct PartFitter {
    pub(crate) rule: FaceWarp,
    pub(crate) y_range: (f64, f64),
    pub(crate) l: DVec3,
    pub(crate) tan: f64,
}

impl PartFitter {
    /// The face part's map with the candidate axis of smaller measured S̄ (either is a valid map
    /// of the part). `points` set n′ (their extent `[d_n, d_f]` along the axis) and s, t (swept
    /// along the light over `y_range` for the depth); the error is measured at `measured`.
    /// `S` holds the swept points: at least `3 × points.len()`.
    pub(crate) fn best<const S: usize>(
        &self,
        spaces: &FaceSpaces,
        points: &[DVec3],
        measured: &[DVec3],
        face: Face,
        (a, b): (f64, f64),
    ) -> Result<(DMat4, NPrime, FrustumError)> {
        let mut best: Option<(DMat4, NPrime, FrustumError)> = None;
        let mut failure = None;
        for ls in spaces.spaces.iter().flatten() {
            match self.fit::<S>(ls, points, measured, face) {
                Ok(c) => {
                    if best.is_none_or(|b| c.2.storage_factor < b.2.storage_factor) {
                        best = Some(c);
                    }
                }
                Err(e) => {
                    failure.get_or_insert(e);
                }
            }
        }
        // The messages are written only here, when no candidate gave a map: the bisector's
        // failure first, then the first fit's.
        best.ok_or_else(|| {
            spaces
                .first_err()
                .or_else(|| failure.map(|f| f.into_error(face, (a, b))))
                .unwrap_or_else(|| Error::Degenerate(format!("no warp axis for the {face:?} face")))
        })
    }

    /// One face part's map in the light space `ls`: the face rule's n′ from the extent
    /// `[d_n, d_f]` of `points` along `ls.z`, the warp fitted to `points` swept along the light
    /// over `y_range`, and its error at `measured`.
    fn fit<const S: usize>(
        &self,
        ls: &LightSpace,
        points: &[DVec3],
        measured: &[DVec3],
        face: Face,
    ) -> std::result::Result<(DMat4, NPrime, FrustumError), PartFailure> {
        let (y_lo, y_hi) = self.y_range;
        let (mut d_n, mut d_f) = (f64::INFINITY, f64::NEG_INFINITY);
        let mut swept = [DVec3::ZERO; S];
        if 3 * points.len() > S {
            return Err(PartFailure::TooManyVertices);
        }
        for (i, v) in points.iter().enumerate() {
            let d = ls.z.dot(*v);
            d_n = d_n.min(d);
            d_f = d_f.max(d);
            let y = ls.y.dot(*v);
            swept[3 * i] = *v;
            swept[3 * i + 1] = *v + (y_lo - y) * ls.y;
            swept[3 * i + 2] = *v + (y_hi - y) * ls.y;
        }
        let n_prime = if face.is_side() {
            match self.rule {
                FaceWarp::Uniform => NPrime::UNWARPED,
                FaceWarp::Psm => NPrime::try_finite(d_n).unwrap_or(NPrime::UNWARPED),
                FaceWarp::Lispsm => {
                    NPrime::try_finite(d_n + (d_n * d_f).sqrt()).unwrap_or(NPrime::UNWARPED)
                }
            }
        } else {
            NPrime::UNWARPED
        };
        let matrix =
            fit_points(&swept[..3 * points.len()], ls, n_prime).map_err(PartFailure::Fit)?;
        let error = vertex_max(&matrix, self.l, self.tan, measured).ok_or(PartFailure::Singular)?;
        Ok((matrix, n_prime, error))
    }
}
