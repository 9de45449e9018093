//! Every shader path of the crate's `sa_visibility` executed and checked (docs/rendered.md, "What
//! is measured", 11): in a few cases ([`CASES`]) the maps are drawn once more as ordinary
//! first-surface maps (every face stored, no rasterizer bias), read back, and the camera pass runs
//! once per path of [`PATHS`]: the depth bias alone, the record's normal offset (its maximum over
//! the focus body), the per-point normal offset, PCF with r = 1 on the records built for r = 1
//! (`FrameMap::gpu_relative_with_pcf`), and PCF with r = 2 on the records built for r = 0 (the
//! module's `sa_kernel_scale`) with the normal offset alone and with the normal offset and the
//! depth bias together.
//!
//! For each path, at every visible pixel facing the light with a map:
//!
//! - **the taps**: render-check's own model of the lookup (the lookup point from the record's
//!   values as `GpuShadowMap`'s docs define them, the taps −r..r around its texel in the read-back
//!   depth maps, the comparison of the convention) gives the shaded fraction, which must be the
//!   GPU's wherever no texel choice or depth comparison lies within the `f32` tolerances
//!   ([`TEXEL_TIE`], [`depth_tie`]);
//! - **acne**: an exactly lit pixel (ray cast) that the GPU shades below 1 although every texel
//!   the lookup reads holds the pixel's own face, lit, at its centre ([`CENTRE_TOLERANCE`]);
//! - **detached shadows** (peter-panning): an exactly shadowed pixel that the GPU shades above 0
//!   although the most lenient tap stores a depth more than the *need* nearer the light than the
//!   pixel's own plane under the lookup point. The need is the plane's depth step across the
//!   kernel's reach, (r + ½ + 1/64) texels along s and along t, plus 8 `f32` ulps
//!   ([`need`]): what any lookup must be lifted by to leave the plane's own texels lit, computed
//!   here from the map's matrix by finite differences on the texels' rays. A lookup that lit the
//!   pixel sat at or below that tap's stored depth, so it was lifted off the plane by more than
//!   the need. The per-point offset (`SA_LOCAL_NORMAL_OFFSET`) must not be; the record's maximum
//!   and the depth bias are maxima over the focus body, larger than the need almost everywhere,
//!   and are reported (`max_lift_over_need`) without a target;
//! - **the offset's lift** (paths with a normal offset): the camera pass writes the offset the
//!   crate's functions give each lookup, and the lookup point's lift off the pixel's plane is
//!   measured here against the need at every lookup, lit or not ([`PathSummary::lift_over_need`],
//!   [`PathSummary::offset_rel_diff`]): the per-point offset must lift by the need exactly, the
//!   record's by at least the need.

use crate::faults::Fault;
use crate::gpu::{FrameOutput, Gpu, Lookup, PathPass};
use crate::run::{Sizes, Upload};
use crate::scene::{lift, ray_occluded, Mesh, Scene, FACING};
use crate::schemes::{build, Options, Scheme, View};
use crate::shadows::box_contains;
use glam::{DMat4, DVec3};
use serde::Serialize;
use shadow_aliasing::frame::bias::normal_offset_at;
use shadow_aliasing::frame::GpuShadowMap;
use shadow_aliasing::maps::ClipDepth;
use std::collections::HashMap;

mod lift;
use lift::offset_lift;

/// `sa_visibility`'s flag: the lookup point moved by the record's normal offset.
pub const SA_NORMAL_OFFSET: u32 = 1;
/// `sa_visibility`'s flag: the record's depth bias added to the receiver's depth.
pub const SA_DEPTH_BIAS: u32 = 2;
/// `sa_visibility`'s flag: the lookup point moved by the per-point normal offset.
pub const SA_LOCAL_NORMAL_OFFSET: u32 = 4;

/// Which record a path looks up.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Record {
    /// `FrameMap::gpu_relative`: bias values for r = 0.
    Plain,
    /// `FrameMap::gpu_relative_with_pcf(…, 1)`: bias values for r = 1.
    Pcf1,
}

/// One camera pass: `sa_visibility`'s flags and PCF radius, and the record it looks up.
#[derive(Debug, Clone, Copy)]
pub struct Path {
    /// The name in summary.json.
    pub name: &'static str,
    /// `sa_visibility`'s bias flags.
    pub flags: u32,
    /// The PCF radius r ((2r + 1)² taps).
    pub radius: u32,
    /// The records uploaded.
    pub record: Record,
}

impl Path {
    /// Whether the path's lift is the per-point offset alone (the detached-shadow target holds).
    pub fn local(&self) -> bool {
        self.flags == SA_LOCAL_NORMAL_OFFSET
    }

    /// Whether the path moves the lookup point by a normal offset (the record's or the per-point
    /// one): its lift over the need is measured ([`PathSummary::lift_over_need`]).
    pub fn offset(&self) -> bool {
        self.flags & (SA_NORMAL_OFFSET | SA_LOCAL_NORMAL_OFFSET) != 0
    }
}

/// The paths checked, in the order of the camera passes.
pub const PATHS: [Path; 6] = [
    Path {
        name: "depth_bias",
        flags: SA_DEPTH_BIAS,
        radius: 0,
        record: Record::Plain,
    },
    Path {
        name: "normal_offset",
        flags: SA_NORMAL_OFFSET,
        radius: 0,
        record: Record::Plain,
    },
    Path {
        name: "local_normal_offset",
        flags: SA_LOCAL_NORMAL_OFFSET,
        radius: 0,
        record: Record::Plain,
    },
    Path {
        name: "pcf1_local_normal_offset",
        flags: SA_LOCAL_NORMAL_OFFSET,
        radius: 1,
        record: Record::Pcf1,
    },
    Path {
        name: "pcf2_normal_offset",
        flags: SA_NORMAL_OFFSET,
        radius: 2,
        record: Record::Plain,
    },
    Path {
        name: "pcf2_normal_offset_depth_bias",
        flags: SA_NORMAL_OFFSET | SA_DEPTH_BIAS,
        radius: 2,
        record: Record::Plain,
    },
];

/// The cases (set-up, scheme) whose shader paths are checked: an orthographic map under the light
/// straight down and at 45°, a warped map under a grazing light from behind, four stable
/// cascades under a low sun with thin casters, and PSM's map (n′ = n_B: its centre of projection
/// near the focus body) under a light 10° high across the view, where the offset point's own
/// footprint changes the per-point offset by up to a quarter (`max_w_change`); in reversed depth
/// and in depth [0, 1] as [`crate::run::case_clip_depth`] gives them.
pub const CASES: [(&str, Scheme); 5] = [
    ("overhead", Scheme::Uniform),
    ("tilted_45", Scheme::Uniform),
    ("behind_5", Scheme::Lispsm),
    ("thin_casters", Scheme::StableCascades),
    ("grazing_10", Scheme::Psm),
];

/// Whether the shader paths are checked in this case.
pub fn applies(setup: &str, scheme: Scheme) -> bool {
    CASES.iter().any(|&(s, k)| s == setup && k == scheme)
}

/// How close to a texel edge (texels) the lookup point's map position must be for the GPU's
/// `f32` to be taken as possibly in the neighbouring texel (the GPU's texel positions are the
/// exact ones' to at most 0.011 texel: docs/rendered.md).
pub const TEXEL_TIE: f64 = 0.02;

/// The texel centre is also sampled this far (texels) from it along each map axis when deciding
/// what a texel stores: near an edge of a face, the rasterizer's `f32` coverage decides.
pub const CENTRE_TOLERANCE: f64 = 0.02;

/// The `f32` rounding of two compared depths the need allows (8 ulps at depth 1, as the crate's
/// bias does).
pub const ROUNDING: f64 = 8.0 * f32::EPSILON as f64;

/// How close (depth units) the lookup's depth and a stored depth must be for the GPU's `f32` to
/// be taken as possibly on the other side: 5·10⁻⁷ plus the plane's depth change over
/// [`TEXEL_TIE`] texels (`slope`: |∂d/∂s| + |∂d/∂t| per texel).
pub fn depth_tie(slope: f64) -> f64 {
    5e-7 + TEXEL_TIE * slope
}

/// The need (depth units): the plane's depth step across a kernel of radius `r` (reach r + ½ +
/// 1/64 texels along s and along t; `slope` = |∂d/∂s| + |∂d/∂t| per texel) plus [`ROUNDING`].
pub fn need(r: u32, slope: f64) -> f64 {
    (f64::from(r) + 0.5 + 1.0 / 64.0) * slope + ROUNDING
}

/// How far (relative) the GPU's lookup point's lift may fall below the need, and, for the
/// per-point offset, exceed it ([`PathSummary::lift_over_need`]): the `f32` rounding of the
/// shader's offset.
pub const LIFT_SLACK: f64 = 1e-3;

/// A detached shadow is a lift beyond this factor of the need (plus twice [`ROUNDING`] and the
/// depth tie): the `f32` lookup's own rounding.
pub const DETACHED_FACTOR: f64 = 1.02;

/// What one path measured (summary.json's `paths`).
#[derive(Debug, Clone, Serialize)]
pub struct PathSummary {
    /// [`Path::name`].
    pub path: &'static str,
    /// `sa_visibility`'s flags.
    pub flags: u32,
    /// The PCF radius.
    pub radius: u32,
    /// Visible pixels facing the light with a map: the lookups.
    pub lookups: usize,
    /// Of those, the ones whose shaded fraction render-check's model of the taps decides (no
    /// texel choice or depth comparison within the `f32` tolerances).
    pub taps_checked: usize,
    /// Of those, the pixels the GPU shades otherwise than the model.
    pub tap_mismatches: usize,
    /// Lookups the exact ray cast lights.
    pub lit_pixels: usize,
    /// Of those, the ones the GPU shades below 1 although every texel read holds the pixel's own
    /// face, lit (acne).
    pub acne: usize,
    /// Of those, the ones the GPU shades below 1 with a texel read that holds another surface or a
    /// shadowed point (a shadow edge within the kernel: not judged).
    pub lit_shaded_near_edge: usize,
    /// Lookups the exact ray cast shadows.
    pub shadow_pixels: usize,
    /// Of those, the ones the GPU shades above 0 (some tap lit: near contact, or at an edge).
    pub shadow_lit: usize,
    /// Of those, the ones whose lookup was lifted by more than the need (a detached shadow;
    /// lookups where the per-point offset fell back to the record's are left out).
    pub detached: usize,
    /// The largest lift the GPU's lit lookups of shadowed pixels prove (the plane's depth under the
    /// lookup point less the most lenient tap's stored depth), over the need; `None` when no
    /// shadowed pixel was lit.
    pub max_lift_over_need: Option<f64>,
    /// Paths with a normal offset: the lookups whose offset point's lift is measured
    /// ([`PathSummary::lift_over_need`]): every lookup with the GPU's offset finite, less those
    /// whose offset point lies at or behind the map's centre of projection (a record's offset
    /// larger than the point can take: `shadow_aliasing::frame::bias`, "Normal offset") and, in a
    /// per-point path, those that no offset lifts by the need (`offset_unreachable`).
    pub offset_lookups: usize,
    /// Per-point paths: the lookups that no offset along the normal lifts by the need (the offset
    /// point would reach the map's centre of projection first): the shader falls back to the
    /// record's offset there, which is not measured.
    pub offset_unreachable: usize,
    /// The least and the largest lift of the GPU's lookup point over the need: the plane's depth
    /// at the map position of p + o n, o the normal offset the GPU's functions give the lookup
    /// (`sa_local_normal_offset`, or the record's `normal_offset` times `sa_offset_scale`), less
    /// that point's own depth, over [`need`]; all in `f64` from the map's matrix and
    /// render-check's plane. The per-point offset is built to lift by the need exactly (1 both
    /// ways); the record's offset is a maximum over the focus body (at least 1). `None` for a
    /// path with no normal offset or no lookup measured.
    pub lift_over_need: Option<[f64; 2]>,
    /// Per-point paths: the largest |w(q) − w(p)| / w(q) over the measured lookups, w the map's
    /// clip w and q = p + o n with the offset render-check derives for the need: how much the
    /// offset point's own footprint (the `(row₃ · n)/w` term of the closed form) matters here (an
    /// offset that held p's footprint would lift by 1/(1 ± this) of the need and less; 0 on an
    /// orthographic map). `None` outside per-point paths.
    pub max_w_change: Option<f64>,
    /// The largest |o − o′| / o′ over the measured lookups, o the GPU's offset and o′ the one it
    /// is defined to be: per-point paths the offset that lifts by the need exactly (solved here,
    /// [`PathSummary::max_w_change`]'s), record paths the record's `normal_offset` times
    /// s (1 − τ)/(1 − s τ) for the path's radius (GpuShadowMap's docs). `None` as
    /// `lift_over_need`.
    pub offset_rel_diff: Option<f64>,
}

/// A map as the model looks it up in one pass.
struct MapModel {
    /// World → light clip, depth [0, 1], `f64`.
    wc: DMat4,
    inv: DMat4,
    record: GpuShadowMap,
    reversed: bool,
}

impl MapModel {
    /// The light-clip position of `q` and its map position (s, t) in texels of a `res`-texel map.
    fn texel(&self, res: f64, q: DVec3) -> (glam::DVec4, f64, f64) {
        let h = self.wc * q.extend(1.0);
        (
            h,
            (h.x / h.w + 1.0) * 0.5 * res,
            (h.y / h.w + 1.0) * 0.5 * res,
        )
    }
}

/// The kernel's factor on a record's depth bias for a PCF kernel of radius `r`:
/// s = (2r + 1)/(2 bias_radius + 1), at least 1 (GpuShadowMap's docs).
fn kernel_scale(rec: &GpuShadowMap, r: u32) -> f64 {
    ((2.0 * f64::from(r) + 1.0) / (2.0 * f64::from(rec.bias_radius).max(0.0) + 1.0)).max(1.0)
}

/// The record's normal offset for a PCF kernel of radius `r` (world units): the record's times
/// s (1 − τ)/(1 − s τ), s [`kernel_scale`], τ the record's growth, and 1e30 times it where
/// s τ ≥ 1 (GpuShadowMap's docs; shadow_aliasing::frame::bias, "Normal offset").
fn record_offset(rec: &GpuShadowMap, r: u32) -> f64 {
    let scale = kernel_scale(rec, r);
    let tau = f64::from(rec.normal_offset_growth).max(0.0);
    let factor = if scale * tau < 1.0 {
        scale * (1.0 - tau) / (1.0 - scale * tau)
    } else {
        1e30
    };
    f64::from(rec.normal_offset) * factor
}

/// A pixel's plane in its map: its depth [0, 1] at its own map position (`s`, `t`, texels) and
/// the depth's steps per texel along s and t (the depth of a plane is affine in the map
/// position: a projective map keeps planes).
#[derive(Clone, Copy)]
struct Plane {
    d: f64,
    s: f64,
    t: f64,
    gs: f64,
    gt: f64,
}

impl Plane {
    /// The plane of `p` with normal `n` in `m`.
    fn new(m: &MapModel, res: f64, p: DVec3, n: DVec3) -> Option<Plane> {
        let (h, s, t) = m.texel(res, p);
        let d = plane_depth(m, res, s, t, p, n)?;
        let gs = plane_depth(m, res, s + 1.0, t, p, n)? - d;
        let gt = plane_depth(m, res, s, t + 1.0, p, n)? - d;
        (h.w > 0.0 && s.is_finite() && t.is_finite()).then_some(Plane { d, s, t, gs, gt })
    }

    /// The plane's depth at map position (`s`, `t`).
    fn at(&self, s: f64, t: f64) -> f64 {
        self.d + self.gs * (s - self.s) + self.gt * (t - self.t)
    }

    /// |∂d/∂s| + |∂d/∂t| per texel.
    fn slope(&self) -> f64 {
        self.gs.abs() + self.gt.abs()
    }
}

/// The lookup of one pixel as render-check models it.
struct Modelled {
    /// The shaded fraction, `None` where a texel choice or a depth comparison is a tie.
    fraction: Option<f64>,
    /// Every texel the lookup may read (both candidates where the texel choice is a tie).
    taps: Vec<(i32, i32)>,
    /// The plane's depth (depth [0, 1]) on the texel ray through the lookup point, less the most
    /// lenient tap's stored depth (depth [0, 1]): the lift a lit lookup proves.
    lift: f64,
    /// The plane's |∂d/∂s| + |∂d/∂t| per texel at the lookup point.
    slope: f64,
    /// The per-point offset fell back to the record's.
    fallback: bool,
    /// The lookup point is off the map (the GPU's fraction 1).
    off_map: bool,
}

/// The plane (`p`, `n`) at map position (`a`, `b`) (texels): its depth [0, 1] on that texel
/// ray.
fn plane_depth(m: &MapModel, res: f64, a: f64, b: f64, p: DVec3, n: DVec3) -> Option<f64> {
    crate::shadows::plane_depth(&m.wc, &m.inv, res, a, b, p, n)
}

/// The texel ray through map position (`a`, `b`) (texels) met with the plane (`p`, `n`).
fn plane_point(m: &MapModel, res: f64, a: f64, b: f64, p: DVec3, n: DVec3) -> Option<DVec3> {
    let (x, y) = (2.0 * a / res - 1.0, 2.0 * b / res - 1.0);
    let q0 = m.inv.project_point3(DVec3::new(x, y, 0.0));
    let d = m.inv.project_point3(DVec3::new(x, y, 1.0)) - q0;
    let den = d.dot(n);
    let x = q0 + d * ((p - q0).dot(n) / den);
    (den.abs() > 1e-300 && x.is_finite()).then_some(x)
}

/// What the model needs of one frame.
struct Frame<'a> {
    res: u32,
    depth: &'a [f32],
    light: DVec3,
    local_factor: f64,
}

impl Frame<'_> {
    /// The depth map `part` stores at texel (`ix`, `iy`) (rows down from t = 1), as stored (the
    /// record's convention).
    fn stored(&self, part: usize, ix: i32, iy: i32) -> f64 {
        let r = self.res as usize;
        f64::from(self.depth[part * r * r + iy as usize * r + ix as usize])
    }

    /// The model of `sa_visibility` for the pixel `e` in its map `m`.
    fn lookup(&self, m: &MapModel, e: &Exact, path: &Path) -> Modelled {
        let (part, p, n, plane) = (e.part, e.p, e.n, &e.plane);
        let res = f64::from(self.res);
        let rec = &m.record;
        let r = f64::from(path.radius);
        // The kernel's factor on the record's depth bias: s = (2r + 1)/(2 bias_radius + 1), at
        // least 1; on its normal offset s (1 − τ)/(1 − s τ), τ the record's growth (1e30 where
        // s τ ≥ 1), as `sa_offset_scale` (GpuShadowMap's docs).
        let scale = kernel_scale(rec, path.radius);
        let record_offset = record_offset(rec, path.radius);
        let (offset, fallback) = if path.flags & SA_LOCAL_NORMAL_OFFSET != 0 {
            match normal_offset_at(&m.wc, ClipDepth::ZeroToOne, self.res, p, n, self.light, r) {
                Some(o) => (o * self.local_factor, false),
                None => (record_offset, true),
            }
        } else if path.flags & SA_NORMAL_OFFSET != 0 {
            (record_offset, false)
        } else {
            (0.0, false)
        };
        let q = p + n * offset;
        let (h, s, t) = m.texel(res, q);
        let here = plane.at(s, t);
        let slope = plane.slope();
        let off = |v: f64| !(0.0..res).contains(&v);
        let near_border = |v: f64| v.abs() < TEXEL_TIE || (v - res).abs() < TEXEL_TIE;
        let ahead = h.w > 0.0;
        if !ahead || off(s) || off(t) {
            let tie = ahead && (near_border(s) || near_border(t));
            return Modelled {
                fraction: (!tie).then_some(1.0),
                taps: Vec::new(),
                lift: f64::NEG_INFINITY,
                slope,
                fallback,
                off_map: true,
            };
        }
        // The lookup's depth in the record's convention (reversed: 1 − depth [0, 1]).
        let mut depth = h.z / h.w;
        if m.reversed {
            depth = 1.0 - depth;
        }
        if path.flags & SA_DEPTH_BIAS != 0 {
            let c = n.dot(-self.light).clamp(1e-3, 1.0);
            let tan_a = (1.0 - c * c).max(0.0).sqrt() / c;
            depth +=
                (f64::from(rec.constant_depth) + f64::from(rec.slope_scaled_depth) * tan_a) * scale;
        }
        let depth = depth.clamp(0.0, 1.0);
        // Candidate texels along each axis: the one holding the point, and its neighbour where
        // the point lies within TEXEL_TIE of their edge.
        let cands = |v: f64| -> Vec<i32> {
            let i = v.floor();
            let f = v - i;
            let mut c = vec![i as i32];
            if f < TEXEL_TIE {
                c.push(i as i32 - 1);
            } else if f > 1.0 - TEXEL_TIE {
                c.push(i as i32 + 1);
            }
            c
        };
        let last = self.res as i32 - 1;
        let k = path.radius as i32;
        let tie = depth_tie(slope);
        let (mut fraction, mut decided) = (None::<f64>, true);
        let mut taps = Vec::new();
        let mut lenient = f64::NEG_INFINITY;
        for &cx in &cands(s) {
            for &cy in &cands(res - t) {
                let mut lit = 0usize;
                for dy in -k..=k {
                    for dx in -k..=k {
                        let (tx, ty) = ((cx + dx).clamp(0, last), (cy + dy).clamp(0, last));
                        // In the record's convention: less-equal, greater-equal reversed.
                        let stored = self.stored(part, tx, ty);
                        decided &= (depth - stored).abs() >= tie;
                        lit += usize::from(if m.reversed {
                            depth >= stored
                        } else {
                            depth <= stored
                        });
                        // The most lenient tap in depth [0, 1] (reversed: 1 − stored).
                        lenient = lenient.max(if m.reversed { 1.0 - stored } else { stored });
                        taps.push((tx, ty));
                    }
                }
                let f = lit as f64 / ((2 * k + 1) * (2 * k + 1)) as f64;
                decided &= fraction.is_none_or(|g| g == f);
                fraction = Some(f);
            }
        }
        taps.sort_unstable();
        taps.dedup();
        Modelled {
            fraction: fraction.filter(|_| decided),
            taps,
            lift: here - lenient,
            slope,
            fallback,
            off_map: false,
        }
    }
}

/// Whether texel (`ix`, `iy`) of `m` stores the face of the pixel at `p` (normal `n`, on box
/// `own` or the ground), lit: the texel ray through its centre, and through points
/// [`CENTRE_TOLERANCE`] from it along each axis, meets the pixel's plane on its own face, outside
/// every other box, at a point the exact ray cast lights.
#[allow(clippy::too_many_arguments)] // one texel and the pixel's surface, each needed once
fn holds_own_lit_face(
    scene: &Scene,
    m: &MapModel,
    res: f64,
    (ix, iy): (i32, i32),
    p: DVec3,
    n: DVec3,
    own: Option<usize>,
    light: DVec3,
) -> bool {
    let (a, b) = (f64::from(ix) + 0.5, res - (f64::from(iy) + 0.5));
    let e = CENTRE_TOLERANCE;
    [(0.0, 0.0), (e, 0.0), (-e, 0.0), (0.0, e), (0.0, -e)]
        .iter()
        .all(|&(da, db)| {
            let Some(x) = plane_point(m, res, a + da, b + db, p, n) else {
                return false;
            };
            let lifted = x + n * lift(scene, x);
            let on_own = match own {
                Some(k) => {
                    box_contains(&scene.boxes[k], x - n * lift(scene, x)) && x.y >= scene.ground_y
                }
                None => true,
            };
            on_own
                && !scene
                    .boxes
                    .iter()
                    .enumerate()
                    .any(|(j, bx)| Some(j) != own && box_contains(bx, lifted))
                && !ray_occluded(scene, x, n, light)
        })
}

/// The exact state of one pixel: its world point and normal, the box it lies on, whether the ray
/// cast shadows it, the map the shader selected and the pixel's plane in it.
struct Exact {
    p: DVec3,
    n: DVec3,
    id: u32,
    own: Option<usize>,
    shadowed: bool,
    part: usize,
    plane: Plane,
}

/// Each pixel's [`Exact`]; `None` for the sky, surfaces not facing the light and pixels with no
/// map.
fn exact_pixels(
    out: &FrameOutput,
    view: &View,
    scene: &Scene,
    mesh: &Mesh,
    maps: &[MapModel],
    (sizes, res): (Sizes, u32),
) -> Vec<Option<Exact>> {
    let (w, h) = (sizes.width as usize, sizes.height as usize);
    let to_world = view.world_to_eye.inverse();
    (0..w * h)
        .map(|i| {
            let id = out.id[i];
            if id == 0 {
                return None;
            }
            let surf = mesh.surfaces[(id - 1) as usize];
            // Facing the light, away from the shader's threshold (its `f32` may round either way).
            if surf.normal.dot(-view.light_world) <= FACING + 1e-6 {
                return None;
            }
            let ne = view.world_to_eye.transform_vector3(surf.normal);
            let pe0 = view.world_to_eye.transform_point3(surf.point);
            let pe = crate::analysis::pixel_point(
                view,
                sizes.width,
                sizes.height,
                i % w,
                i / w,
                ne,
                pe0,
            )?;
            let p = to_world.transform_point3(pe);
            let n = surf.normal;
            let k = out.texel[i][2];
            if !(k >= 0.0 && (k as usize) < maps.len()) {
                return None;
            }
            let part = k as usize;
            let plane = Plane::new(&maps[part], f64::from(res), p, n)?;
            let own = scene
                .boxes
                .iter()
                .position(|b| box_contains(b, p - n * lift(scene, p)));
            Some(Exact {
                p,
                n,
                id,
                own,
                shadowed: ray_occluded(scene, p, n, view.light_world),
                part,
                plane,
            })
        })
        .collect()
}

/// Draws `scheme`'s first-surface maps once and runs the camera pass for every path of
/// [`PATHS`], measuring each ([`PathSummary`]).
///
/// # Errors
/// Building or rendering; a path with no lookup.
pub fn check(
    gpu: &Gpu,
    scene: &Scene,
    scheme: Scheme,
    sizes: Sizes,
) -> Result<Vec<PathSummary>, String> {
    let res = sizes.res.unwrap_or(scene.map_resolution);
    let view = View::new(&scene.camera, scene.light(), sizes.width, sizes.height)?;
    let mesh = Mesh::build(scene);
    let built = build(
        scheme,
        &view,
        scene,
        res,
        sizes.fault,
        sizes.render.clip_depth,
        &Options::default(),
    )?;
    let mut s = sizes;
    s.render.lookup = Lookup::FirstSurface;
    let up = Upload::new(&built, &mesh, s);
    let input = up.input(&view, &mesh, &built, res, s);
    // The model reads every map at `res` texels a side, as the records say the shader does.
    if let Some(m) = built.maps.iter().find(|m| m.record.resolution != res) {
        return Err(format!(
            "shader paths: a record of {} texels a side in a frame of {res}",
            m.record.resolution
        ));
    }
    let plain: Vec<GpuShadowMap> = built.maps.iter().map(|m| m.record).collect();
    let pcf1: Vec<GpuShadowMap> = built.maps.iter().map(|m| m.record_pcf1).collect();
    let passes: Vec<PathPass> = PATHS
        .iter()
        .map(|p| PathPass {
            records: match p.record {
                Record::Plain => &plain,
                Record::Pcf1 => &pcf1,
            },
            flags: p.flags,
            radius: p.radius,
            lens: false,
        })
        .collect();
    let (depth, outs) = gpu.render_paths(&input, &passes)?;
    let models = |record: Record| -> Vec<MapModel> {
        built
            .maps
            .iter()
            .map(|m| {
                let wc = m.gpu * view.world_to_eye;
                MapModel {
                    wc,
                    inv: wc.inverse(),
                    record: match record {
                        Record::Plain => m.record,
                        Record::Pcf1 => m.record_pcf1,
                    },
                    reversed: m.record.clip_depth
                        == GpuShadowMap::clip_depth_code(ClipDepth::Reversed),
                }
            })
            .collect()
    };
    let exact = exact_pixels(
        &outs[0],
        &view,
        scene,
        &mesh,
        &models(Record::Plain),
        (sizes, res),
    );
    let frame = Frame {
        res,
        depth: &depth,
        light: view.light_world,
        local_factor: Fault::local_offset_factor(sizes.fault),
    };
    // The paths measured side by side.
    std::thread::scope(|sc| {
        let handles: Vec<_> = PATHS
            .iter()
            .zip(&outs)
            .map(|(path, out)| {
                let (frame, exact, models) = (&frame, &exact, models(path.record));
                sc.spawn(move || measure(scene, frame, exact, &models, path, out))
            })
            .collect();
        handles
            .into_iter()
            .map(|h| {
                h.join()
                    .map_err(|_| "a shader-path measurement panicked".to_string())?
            })
            .collect()
    })
}

/// One path's measurements over the frame.
fn measure(
    scene: &Scene,
    frame: &Frame,
    exact: &[Option<Exact>],
    models: &[MapModel],
    path: &Path,
    out: &FrameOutput,
) -> Result<PathSummary, String> {
    let res = f64::from(frame.res);
    let mut sum = PathSummary {
        path: path.name,
        flags: path.flags,
        radius: path.radius,
        lookups: 0,
        taps_checked: 0,
        tap_mismatches: 0,
        lit_pixels: 0,
        acne: 0,
        lit_shaded_near_edge: 0,
        shadow_pixels: 0,
        shadow_lit: 0,
        detached: 0,
        max_lift_over_need: None,
        offset_lookups: 0,
        offset_unreachable: 0,
        lift_over_need: None,
        max_w_change: None,
        offset_rel_diff: None,
    };
    let mut memo: HashMap<(usize, u32, i32, i32), bool> = HashMap::new();
    for (i, e) in exact.iter().enumerate() {
        let Some(e) = e else { continue };
        // Every pass selects as the first (the same records' ranges and faces).
        if out.texel[i][2] != e.part as f32 {
            return Err(format!(
                "shader path {}: pixel {i} selects map {} (the first pass: {})",
                path.name, out.texel[i][2], e.part
            ));
        }
        let (part, m) = (e.part, &models[e.part]);
        let look = frame.lookup(m, e, path);
        let gpu = f64::from(out.texel[i][3]);
        sum.lookups += 1;
        if path.offset() {
            offset_lift(&mut sum, m, res, e, path, f64::from(out.lens[i][0]));
        }
        if let Some(f) = look.fraction {
            sum.taps_checked += 1;
            // The GPU's fraction is a count over (2r + 1)² taps in f32: equal to far better than
            // half a tap.
            if (f - gpu).abs() > 1e-4 {
                sum.tap_mismatches += 1;
            }
        }
        if e.shadowed {
            sum.shadow_pixels += 1;
            if gpu > 1e-4 {
                sum.shadow_lit += 1;
                if !look.off_map && !look.fallback {
                    let n = need(path.radius, look.slope);
                    let ratio = look.lift / n;
                    sum.max_lift_over_need =
                        Some(sum.max_lift_over_need.map_or(ratio, |r| r.max(ratio)));
                    if look.lift > DETACHED_FACTOR * n + 2.0 * ROUNDING + depth_tie(look.slope) {
                        sum.detached += 1;
                    }
                }
            }
        } else {
            sum.lit_pixels += 1;
            if gpu < 1.0 - 1e-4 {
                let clear = !look.taps.is_empty()
                    && look.taps.iter().all(|&(x, y)| {
                        *memo.entry((part, e.id, x, y)).or_insert_with(|| {
                            holds_own_lit_face(scene, m, res, (x, y), e.p, e.n, e.own, frame.light)
                        })
                    });
                if clear {
                    sum.acne += 1;
                } else {
                    sum.lit_shaded_near_edge += 1;
                }
            }
        }
    }
    if sum.lookups == 0 {
        return Err(format!("shader path {}: no lookup on screen", path.name));
    }
    Ok(sum)
}
