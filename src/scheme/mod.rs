//! One frame's shadow maps for a named scheme (warp rule × partitioning), each with its measured
//! error: what `shadow-aliasing warp --warp W --partition P --k K` prints and what
//! [`crate::scheme::sweep`] sweeps over the hemisphere.
//!
//! | [`Partition`] | maps | planes |
//! |---|---|---|
//! | `Single` | 1 | the whole frustum |
//! | `Uniform` | k | z_i = n + (f − n) i/k |
//! | `Log` | k | z_i = n (f/n)^{i/k} (Lloyd 2006 Eq 15, 16) |
//! | `Practical(λ)` | k | λ-blend of the two |
//! | `Adaptive` | k | Barroso & Celes Eq 19 with γ from the light and α = [`ADAPTIVE_RATIO`] |
//! | `AdaptiveRatio(α)` | k | the same with a chosen α > 1 |
//! | `Faces` | k per visible side face, + near face | self-similar along each face ([`crate::maps::faces`]) |
//!
//! Every z-partition is fitted with the scheme's [`WarpRule`] applied to its own sub-frustum.
//! For `Faces` the rule is mapped onto the face rules of [`FaceWarp`]: `Uniform` and `Eta(−1)` to
//! [`FaceWarp::Uniform`], `Psm` and `Eta(1)` to [`FaceWarp::Psm`], every other rule to
//! [`FaceWarp::Lispsm`] (each face's own n′ = d_n + √(d_n d_f), the choice that reproduces Lloyd
//! 2006 Eq 19 and 21; the view-frustum rules have no meaning for a face's projection).
//!
//! Each partition is measured at its vertices (the sub-frustum's eight corners; a face part's
//! four vertices) with unit resolutions; the scheme's storage factor is the sum over its maps.
//!
//! ```
//! use shadow_aliasing::scheme::{scheme, Partition};
//! use shadow_aliasing::maps::WarpRule;
//! use shadow_aliasing::ViewFrustum;
//! use glam::DVec3;
//! let view = ViewFrustum::new(1.0, 1000.0, 30f64.to_radians())?;
//! let r = scheme(&view, DVec3::new(0.0, -1.0, 0.0), WarpRule::Uniform, Partition::Log, 3)?;
//! assert_eq!(r.partitions().len(), 3);
//! // Light overhead, no warping: S̄ = k α^{1/k}(α^{1/k} − 1)/(2 tan θ) (Lloyd 2006 Eq 17).
//! let expect = 3.0 * 10.0 * 9.0 / (2.0 * 30f64.to_radians().tan());
//! assert!((r.storage_factor() - expect).abs() < 1e-9 * expect);
//! # Ok::<(), shadow_aliasing::Error>(())
//! ```

use crate::analytic::partition::{z_splits, SplitScheme, Splits, MAX_PARTITIONS};
use crate::error::{Error, Result};
use crate::frustum::{LightAngle, LightDir, NPrime, ViewFrustum};
use crate::maps::atlas::{layout, Atlas, AtlasEntry, MAX_ATLAS_ENTRIES};
use crate::maps::cascades::visit_cascades;
use crate::maps::faces::{visit_face_partitions, Face, FaceWarp, MAX_FACE_PARTITIONS};
use crate::maps::matrix::in_clip_depth;
use crate::maps::warp::{warp_prepared, PreparedLight};
use crate::maps::{ClipDepth, WarpRule};
use crate::measure::vertex::vertex_max;
use glam::{DMat4, DVec3, Mat4};

pub mod sweep;

/// Barroso & Celes' far-partition ratio α for [`Partition::Adaptive`]: 2, the value of their
/// Fig 9 ("the proposed adaptive scheme with α = 2").
pub const ADAPTIVE_RATIO: f64 = 2.0;

/// The largest number of maps one scheme produces ([`MAX_FACE_PARTITIONS`]).
pub const MAX_SCHEME_PARTITIONS: usize = MAX_FACE_PARTITIONS;

/// How the view frustum is partitioned (see the module table).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Partition {
    /// One map for the whole frustum (k is ignored).
    #[default]
    Single,
    /// k z-partitions of equal depth.
    Uniform,
    /// k self-similar (logarithmic) z-partitions, Lloyd 2006 Eq 15, 16.
    Log,
    /// k z-partitions, the practical λ-blend (λ ∈ [0, 1]: 0 uniform, 1 logarithmic).
    Practical(f64),
    /// k z-partitions by Barroso & Celes Eq 19, γ from the light, α = [`ADAPTIVE_RATIO`]
    /// (the same as `AdaptiveRatio(ADAPTIVE_RATIO)`).
    Adaptive,
    /// k z-partitions by Barroso & Celes Eq 19, γ from the light, with the far-partition ratio
    /// α > 1 given (the `ratio` of [`SplitScheme::Adaptive`]). The planes exist only while α is
    /// small enough for f/n at the light's γ (at γ = 0, α^{k−1} < f/n): otherwise
    /// [`Error::NoSolution`] advises a lower ratio or k.
    AdaptiveRatio(f64),
    /// Face partitions with k self-similar z-partitions along each side face.
    Faces,
}

/// What a partition covers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Region {
    /// The sub-frustum between two depths (the whole frustum for [`Partition::Single`]).
    Frustum,
    /// The prism along the light of a part of a face (see [`crate::maps::faces`]).
    Face(Face),
}

/// One map of a scheme with its measured error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PartitionResult {
    /// Eye → light clip, OpenGL clip depth [−1, 1]; x, y span the map.
    pub matrix: DMat4,
    /// The warp parameter the map uses.
    pub n_prime: NPrime,
    /// Near end of the partition's depth range (eye depth).
    pub near: f64,
    /// Far end of the partition's depth range (equal to `near` for the near face).
    pub far: f64,
    /// M_x over the partition's vertices (unit resolutions).
    pub max_mx: f64,
    /// M_z over the partition's vertices (unit resolutions).
    pub max_mz: f64,
    /// S̄ = M_x M_z.
    pub storage_factor: f64,
    /// What the map covers.
    pub region: Region,
}

impl Default for PartitionResult {
    fn default() -> Self {
        Self {
            matrix: DMat4::IDENTITY,
            n_prime: NPrime::UNWARPED,
            near: 0.0,
            far: 0.0,
            max_mx: 0.0,
            max_mz: 0.0,
            storage_factor: 0.0,
            region: Region::Frustum,
        }
    }
}

impl PartitionResult {
    /// The matrix in the requested clip-depth convention (see [`crate::maps::ClipDepth`]).
    #[must_use]
    pub fn matrix_with_clip_depth(&self, depth: ClipDepth) -> DMat4 {
        in_clip_depth(&self.matrix, depth)
    }

    /// The matrix in single precision for the GPU, in the requested clip-depth convention.
    #[must_use]
    pub fn to_mat4(&self, depth: ClipDepth) -> Mat4 {
        self.matrix_with_clip_depth(depth).as_mat4()
    }

    /// [`PartitionResult::to_mat4`] as plain column-major arrays (`[column][row]`).
    #[must_use]
    pub fn to_cols(&self, depth: ClipDepth) -> [[f32; 4]; 4] {
        self.to_mat4(depth).to_cols_array_2d()
    }
}

/// A scheme's maps in a fixed array (no heap allocation) and their summed storage factor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SchemeResult {
    parts: [PartitionResult; MAX_SCHEME_PARTITIONS],
    len: usize,
    storage_factor: f64,
    light_dir: DVec3,
}

impl Default for SchemeResult {
    fn default() -> Self {
        Self {
            parts: [PartitionResult::default(); MAX_SCHEME_PARTITIONS],
            len: 0,
            storage_factor: 0.0,
            light_dir: DVec3::NEG_Y,
        }
    }
}

impl SchemeResult {
    /// The maps: near to far for z-partitions; face by face (bottom, right, top, left), near to
    /// far along each, then the near face, for [`Partition::Faces`].
    #[must_use]
    pub fn partitions(&self) -> &[PartitionResult] {
        &self.parts[..self.len]
    }
    /// Σ S̄ over the maps.
    #[must_use]
    pub fn storage_factor(&self) -> f64 {
        self.storage_factor
    }
    /// The unit direction the light travels (eye space).
    #[must_use]
    pub fn light_dir(&self) -> DVec3 {
        self.light_dir
    }
    /// The maps packed into one `width × height` texture ([`crate::maps::atlas::layout`]), grouped
    /// as Lloyd 2005 §4.1 does: the two maps of opposite side faces share a column (left with
    /// right, bottom with top, each face's z-partitions with them), the near face has its own;
    /// z-partitions of the frustum share one column, split along t by their M_z. The viewports
    /// are in the order of [`SchemeResult::partitions`].
    ///
    /// # Errors
    /// As [`crate::maps::atlas::layout`] (a texture too small to give every map a texel).
    ///
    /// ```
    /// use shadow_aliasing::scheme::{scheme, Partition};
    /// use shadow_aliasing::maps::WarpRule;
    /// use shadow_aliasing::ViewFrustum;
    /// use glam::DVec3;
    /// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
    /// let r = scheme(&view, DVec3::new(0.1, -0.2, -1.0), WarpRule::Lispsm, Partition::Faces, 2)?;
    /// let atlas = r.atlas(4096, 4096)?;
    /// let texels: u64 = atlas.viewports().iter().map(|v| v.texels()).sum();
    /// assert_eq!(texels, 4096 * 4096);
    /// # Ok::<(), shadow_aliasing::Error>(())
    /// ```
    pub fn atlas(&self, width: u32, height: u32) -> Result<Atlas> {
        let mut entries = [AtlasEntry {
            group: 0,
            max_mx: 1.0,
            max_mz: 1.0,
        }; MAX_ATLAS_ENTRIES];
        for (e, p) in entries.iter_mut().zip(self.partitions()) {
            *e = AtlasEntry {
                group: match p.region {
                    Region::Frustum => 0,
                    Region::Face(Face::Left | Face::Right) => 0,
                    Region::Face(Face::Bottom | Face::Top) => 1,
                    Region::Face(Face::Near | Face::Far) => 2,
                },
                max_mx: p.max_mx,
                max_mz: p.max_mz,
            };
        }
        layout(width, height, &entries[..self.len])
    }

    fn push(&mut self, p: PartitionResult) {
        if self.len < MAX_SCHEME_PARTITIONS {
            self.parts[self.len] = p;
            self.len += 1;
            self.storage_factor += p.storage_factor;
        }
    }
}

/// The maps of the scheme `(rule, partition, k)` for `view` and a light travelling along
/// `light_dir` (eye space), each with its measured M_x, M_z, S̄, and their sum.
///
/// # Errors
/// [`Error::InvalidArgument`] naming `light_dir`, `k` (outside `1..=MAX_PARTITIONS` for a
/// partitioned scheme), `lambda` (outside [0, 1]), `ratio` (not finite or not above 1) or the
/// rule's parameter; [`Error::NoSolution`] when Barroso's adaptive planes do not exist for this
/// f/n, light, ratio and k;
/// [`Error::Degenerate`] when planes coincide in `f64` or a fitted map is singular at a vertex.
pub fn scheme(
    view: &ViewFrustum,
    light_dir: DVec3,
    rule: WarpRule,
    partition: Partition,
    k: usize,
) -> Result<SchemeResult> {
    let mut out = SchemeResult::default();
    scheme_into(view, light_dir, rule, partition, k, &mut out)?;
    Ok(out)
}

/// As [`scheme`], writing into `out` (reused between calls: no allocation, no large copies).
///
/// # Errors
/// As [`scheme`]; `out` is left empty on error.
pub fn scheme_into(
    view: &ViewFrustum,
    light_dir: DVec3,
    rule: WarpRule,
    partition: Partition,
    k: usize,
    out: &mut SchemeResult,
) -> Result<()> {
    let l = LightDir::new(light_dir)?;
    scheme_into_prepared(&Prepared::new(view), l, rule, partition, k, out)
}

/// What a scheme needs of the view that does not depend on the light: computed once per sweep.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Prepared {
    view: ViewFrustum,
    pub(crate) tan: f64,
    pub(crate) corners: [DVec3; 8],
}

impl Prepared {
    pub(crate) fn new(view: &ViewFrustum) -> Self {
        let tan = view.tan_half_fov();
        let corners = view.corners();
        Self {
            view: *view,
            tan,
            corners,
        }
    }
}

/// [`scheme_into`] with the view prepared and `l` already a unit vector.
pub(crate) fn scheme_into_prepared(
    prep: &Prepared,
    l: LightDir,
    rule: WarpRule,
    partition: Partition,
    k: usize,
    out: &mut SchemeResult,
) -> Result<()> {
    out.len = 0;
    out.storage_factor = 0.0;
    out.light_dir = l.as_dvec3();
    let r = fill(prep, l, rule, partition, k, out);
    if r.is_err() {
        out.len = 0;
        out.storage_factor = 0.0;
    }
    r
}

fn fill(
    prep: &Prepared,
    l: LightDir,
    rule: WarpRule,
    partition: Partition,
    k: usize,
    out: &mut SchemeResult,
) -> Result<()> {
    let view = &prep.view;
    let splits = |scheme: SplitScheme| z_splits(view.near(), view.far(), k, scheme);
    let planes: Splits = match partition {
        Partition::Single => {
            // `warp(view, l, rule)`, inlined here.
            let s = warp_prepared(view, &PreparedLight::new(l), rule)?;
            let e = vertex_max(&s.matrix(), s.light_dir(), prep.tan, &prep.corners).ok_or_else(
                || Error::Degenerate("the map is singular at a frustum corner".into()),
            )?;
            out.push(PartitionResult {
                matrix: s.matrix(),
                n_prime: s.n_prime(),
                near: view.near(),
                far: view.far(),
                max_mx: e.max_mx,
                max_mz: e.max_mz,
                storage_factor: e.storage_factor,
                region: Region::Frustum,
            });
            return Ok(());
        }
        Partition::Uniform => splits(SplitScheme::Uniform)?,
        Partition::Log | Partition::Faces => splits(SplitScheme::SelfSimilar)?,
        Partition::Practical(lambda) => splits(SplitScheme::Practical { lambda })?,
        Partition::Adaptive | Partition::AdaptiveRatio(_) => splits(SplitScheme::Adaptive {
            light_angle: LightAngle::from_unit(l).radians(),
            ratio: match partition {
                Partition::AdaptiveRatio(ratio) => ratio,
                _ => ADAPTIVE_RATIO,
            },
        })?,
    };
    if partition == Partition::Faces {
        let face_rule = face_rule(rule);
        visit_face_partitions(view, l, face_rule, &planes, |p| {
            out.push(PartitionResult {
                matrix: p.shadow.matrix(),
                n_prime: p.shadow.n_prime(),
                near: p.shadow.near(),
                far: p.shadow.far(),
                max_mx: p.error.max_mx,
                max_mz: p.error.max_mz,
                storage_factor: p.error.storage_factor,
                region: Region::Face(p.face),
            });
        })
        .map(|_| ())
    } else {
        visit_cascades(view, l, &planes, rule, 0.0, |c| {
            out.push(PartitionResult {
                matrix: c.shadow.matrix(),
                n_prime: c.shadow.n_prime(),
                near: c.shadow.near(),
                far: c.shadow.far(),
                max_mx: c.error.max_mx,
                max_mz: c.error.max_mz,
                storage_factor: c.error.storage_factor,
                region: Region::Frustum,
            });
        })
    }
}

/// The face rule a view-frustum rule stands for under [`Partition::Faces`] (module docs).
#[must_use]
pub fn face_rule(rule: WarpRule) -> FaceWarp {
    match rule {
        WarpRule::Uniform => FaceWarp::Uniform,
        WarpRule::Psm => FaceWarp::Psm,
        WarpRule::Eta(e) if e <= -1.0 => FaceWarp::Uniform,
        WarpRule::Eta(e) if e >= 1.0 => FaceWarp::Psm,
        _ => FaceWarp::Lispsm,
    }
}

/// The largest number of seams a scheme has: between consecutive z-partitions of each of four
/// faces, between neighbouring faces at each z-partition, and between the near face and four
/// side faces.
pub const MAX_SEAMS: usize = 8 * MAX_PARTITIONS + 4;

/// The jump of error across the seam between two neighbouring partitions `a` and `b` (indices
/// into [`SchemeResult::partitions`]): over the points of the seam, the largest ratio of the two
/// maps' errors, `max(m_a/m_b, m_b/m_a) ≥ 1`, along x and along z. 1 means no jump.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Seam {
    /// The partition on one side.
    pub a: usize,
    /// The partition on the other side.
    pub b: usize,
    /// Largest ratio of m_x across the seam.
    pub jump_mx: f64,
    /// Largest ratio of m_z across the seam.
    pub jump_mz: f64,
}

/// The seams of a scheme, in a fixed array.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Seams {
    seams: [Seam; MAX_SEAMS],
    len: usize,
}

impl Seams {
    /// The seams.
    #[must_use]
    pub fn as_slice(&self) -> &[Seam] {
        &self.seams[..self.len]
    }
    fn push(&mut self, s: Seam) {
        if self.len < MAX_SEAMS {
            self.seams[self.len] = s;
            self.len += 1;
        }
    }
}

/// The jump of error across each seam of `result` (built by [`scheme`] for `view`).
///
/// Seams and the points they are measured at:
/// - consecutive z-partitions `[z_{i−1}, z_i]`, `[z_i, z_{i+1}]`: the four corners of the plane
///   at depth z_i;
/// - consecutive z-partitions of one face: the two ends of the face's line at depth z_i;
/// - two side faces sharing an edge, parts over the same depths `[a, b]`: the shared edge's
///   points at depths a and b;
/// - the near face and a side face's first part: the two ends of their shared near edge.
///
/// # Errors
/// [`Error::Degenerate`] when a map is singular at a seam point (a map built by [`scheme`] never
/// is).
///
/// ```
/// use shadow_aliasing::scheme::{scheme, seams, Partition};
/// use shadow_aliasing::maps::WarpRule;
/// use shadow_aliasing::ViewFrustum;
/// use glam::DVec3;
/// let view = ViewFrustum::new(1.0, 100.0, 0.5)?;
/// let r = scheme(&view, DVec3::new(0.0, -1.0, 0.0), WarpRule::Lispsm, Partition::Log, 2)?;
/// let s = seams(&view, &r)?;
/// // Lloyd 2006 §5.2: with n′ = n′_LSPSM there is no change in z error at a seam.
/// assert!((s.as_slice()[0].jump_mz - 1.0).abs() < 1e-9);
/// # Ok::<(), shadow_aliasing::Error>(())
/// ```
pub fn seams(view: &ViewFrustum, result: &SchemeResult) -> Result<Seams> {
    let parts = result.partitions();
    let l = result.light_dir();
    let tan = view.tan_half_fov();
    let mut out = Seams {
        seams: [Seam::default(); MAX_SEAMS],
        len: 0,
    };
    let jump = |a: usize, b: usize, points: &[DVec3]| -> Result<Seam> {
        let (mut jx, mut jz) = (1.0f64, 1.0f64);
        for p in points {
            let ea = vertex_max(&parts[a].matrix, l, tan, std::slice::from_ref(p));
            let eb = vertex_max(&parts[b].matrix, l, tan, std::slice::from_ref(p));
            let (Some(ea), Some(eb)) = (ea, eb) else {
                return Err(Error::Degenerate(format!(
                    "a map is singular at the seam point {p} between partitions {a} and {b}"
                )));
            };
            jx = jx.max(ea.max_mx / eb.max_mx).max(eb.max_mx / ea.max_mx);
            jz = jz.max(ea.max_mz / eb.max_mz).max(eb.max_mz / ea.max_mz);
        }
        Ok(Seam {
            a,
            b,
            jump_mx: jx,
            jump_mz: jz,
        })
    };
    let same = |x: f64, y: f64| (x - y).abs() <= 1e-12 * view.far();
    for a in 0..parts.len() {
        for b in (a + 1)..parts.len() {
            let (pa, pb) = (&parts[a], &parts[b]);
            match (pa.region, pb.region) {
                (Region::Frustum, Region::Frustum)
                    if same(pa.far, pb.near) && pa.near < pb.near =>
                {
                    let z = pb.near;
                    let c = view.with_depth_range(z, z + view.far())?.corners();
                    out.push(jump(a, b, &c[..4])?);
                }
                (Region::Face(fa), Region::Face(fb)) => {
                    let ea = fa.side_edges(view);
                    let eb = fb.side_edges(view);
                    match (ea, eb) {
                        (Some([a0, a1]), Some(_)) if fa == fb => {
                            if same(pa.far, pb.near) {
                                let z = pb.near;
                                out.push(jump(a, b, &[a0 * z, a1 * z])?);
                            }
                        }
                        (Some([a0, a1]), Some([b0, b1])) => {
                            if same(pa.near, pb.near) && same(pa.far, pb.far) {
                                let shared = if a1 == b0 {
                                    Some(a1)
                                } else if a0 == b1 {
                                    Some(a0)
                                } else {
                                    None
                                };
                                if let Some(e) = shared {
                                    out.push(jump(a, b, &[e * pa.near, e * pa.far])?);
                                }
                            }
                        }
                        (Some([e0, e1]), None) | (None, Some([e0, e1])) => {
                            let side = if ea.is_some() { pa } else { pb };
                            if same(side.near, view.near()) {
                                let n = view.near();
                                out.push(jump(a, b, &[e0 * n, e1 * n])?);
                            }
                        }
                        (None, None) => {}
                    }
                }
                _ => {}
            }
        }
    }
    Ok(out)
}
