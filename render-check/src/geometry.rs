//! Each map's geometry measured against render-check's own reconstruction of what the crate's
//! documentation promises, without calling the crate's rule, builder or bias functions
//! (docs/rendered.md, "What is measured", 13). What is read from the crate is its output:
//! the maps' matrices, `FrameMap::body`, the records uploaded (bias values, `texel_world`), the
//! face each face map names and the clipmap's uploaded level offset.
//!
//! - **Focus body** ([`Geometry::body_rel_diff`]): B rebuilt here as the intersection of
//!   half-spaces (the view frustum's slice, the receivers' merged box from the scene, and for a
//!   face map the prism of its frustum face along the light), its vertices found by solving every
//!   triple of planes; every vertex of `FrameMap::body` must lie in it, and every vertex of it
//!   must be one of `FrameMap::body`'s.
//! - **Window fill** ([`Geometry::window_fill`]): the fitted maps' s, t over the rebuilt B's
//!   vertices reach ±1 on all four sides (no wasted margin, no part of B outside the map).
//! - **Stable cascades** ([`Geometry::stable_half_width_rel_diff`],
//!   [`Geometry::stable_centre_texels`]): the least sphere around each slice's corners, found here
//!   by a one-dimensional minimisation along the view axis, against the map's window (its
//!   half-width the sphere's radius padded by one texel each side, its centre the sphere's to
//!   within half a texel of snapping).
//! - **Clipmap levels** ([`Geometry::clipmap_rel_diff`]): the level rule derived from the camera
//!   frustum (the coarsest level whose texel is no coarser than 2^b pixels, raised to the least
//!   level whose disc covers the frustum's corner ray) against the levels' texels, depth ranges
//!   and the offset uploaded to the shader.
//! - **Bias record** ([`Geometry::normal_offset_ratio`], [`Geometry::depth_bias_ratio`]): each body
//!   vertex's need for a lit plane through it, over a grid of normals, from the depths the
//!   kernel's taps read on that plane (solved from the matrix; the normal offset at the offset
//!   point's own footprint, the map's w followed along the normal), against the records' values.
//! - **Texel size** ([`Geometry::texel_world_ratio`]): the largest texel edge over B measured
//!   from the matrix's derivatives against the record's `texel_world`, and the largest along s
//!   and along t against the `texel_extent` decoded from the record's uploaded bytes.

use crate::scene::Scene;
use crate::schemes::{clipmap_options, Built, Map, Scheme, View};
use crate::volumes::{casters_volume_distance, volume_distance};
use glam::{DMat3, DMat4, DVec3, DVec4};
use serde::Serialize;

/// What [`measure`] found for one case: maxima (or minima) over the case's maps; `None` where the
/// measurement does not apply to the scheme.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
pub struct Geometry {
    /// The largest distance between `FrameMap::body` and the rebuilt B (a vertex of either
    /// outside the other), over the diameter of both. B is rebuilt over the map's slice and every
    /// depth its record selects it for. [`MISSING`] (1) where a map has no slice, a slice holding
    /// B has no map, or one of the two bodies is empty and the other not; never NaN.
    pub body_rel_diff: f64,
    /// The fitted maps (every scheme but the stable cascades and the clipmap): the largest
    /// distance, in clip units, of the rebuilt B's extreme s or t from ±1.
    pub window_fill: Option<f64>,
    /// Stable cascades: the window's half-width over the least sphere's radius padded by one
    /// texel each side (`R res/(res − 2)`), |· − 1|, largest over the maps.
    pub stable_half_width_rel_diff: Option<f64>,
    /// Stable cascades: the least sphere's centre's distance from the window's centre, texels,
    /// along s or t, largest over the maps.
    pub stable_centre_texels: Option<f64>,
    /// Clipmaps: the largest of |uploaded offset − L| and the levels' texels and depth ranges
    /// against the rule's, relatively.
    pub clipmap_rel_diff: Option<f64>,
    /// The records' normal offset (r = 0 and r = 1) over the needs: [least over every body
    /// vertex and normal of record / need, record / the largest need].
    pub normal_offset_ratio: [f64; 2],
    /// The records' depth bias (constant + slope-scaled · tan α) over the needs: [least over
    /// every body vertex and normal of record / need, the larger of the constant over the largest
    /// need at α = 0 and the slope term over the largest need at α = 89°].
    pub depth_bias_ratio: [f64; 2],
    /// The record's `texel_world` over the largest texel edge measured over the rebuilt B, and
    /// the uploaded bytes' `texel_extent` along s and t over the largest edge along each: the
    /// ratio furthest from 1 over the three and the case's maps.
    pub texel_world_ratio: f64,
    /// `FrameMap::receivers_volume` against the rebuilt B ([`volume_distance`]), over the
    /// camera frustum's size (far · (1 + tan θ + tan θ · aspect)), largest over the maps.
    pub receivers_volume_rel_diff: f64,
    /// `FrameMap::casters_volume` against the rebuilt B swept toward the light and cut by the
    /// map's depth range ([`casters_volume_distance`]), over the frustum's size, largest over
    /// the maps.
    pub casters_volume_rel_diff: f64,
    /// Cascades: split ranges against render-check's planes ([`crate::options::split_rel_diff`]).
    pub split_rel_diff: Option<f64>,
    /// With `depth_clamp` ([`crate::schemes::Options`]): the map's depth (\[0, 1\]) over the
    /// rebuilt B's vertices against 0 and 1 (B alone fills the depth range), the larger
    /// distance (for stable cascades and clipmap levels, less the one texel their depth snaps
    /// by), largest over the maps; `None` without it, and for face maps (whose depth covers
    /// all of B along the light through the face's warp, a range not rebuilt here).
    pub depth_clamp_fill: Option<f64>,
}

/// A half-space `n · p + d ≤ 0` (eye space).
type Plane = DVec4;

pub(crate) fn side(pl: Plane, p: DVec3) -> f64 {
    pl.truncate().dot(p) + pl.w
}

/// The planes of the view frustum's slice between eye depths `a` and `b` (eye space, −z ahead),
/// `t` = tan θ, `ta` = tan θ · aspect.
fn slice_planes(a: f64, b: f64, t: f64, ta: f64) -> Vec<Plane> {
    let unit = |n: DVec3| n.normalize().extend(0.0);
    vec![
        DVec4::new(0.0, 0.0, 1.0, a),   // −z ≥ a
        DVec4::new(0.0, 0.0, -1.0, -b), // −z ≤ b
        unit(DVec3::new(1.0, 0.0, ta)), // x ≤ ta (−z)
        unit(DVec3::new(-1.0, 0.0, ta)),
        unit(DVec3::new(0.0, 1.0, t)), // y ≤ t (−z)
        unit(DVec3::new(0.0, -1.0, t)),
    ]
}

/// The receivers' merged bounding box (the drawn ground square around the camera and every box,
/// as the scene describes them) as eye-space half-spaces.
fn receiver_planes(scene: &Scene, view: &View) -> Vec<Plane> {
    let c = DVec3::from_array(scene.camera.eye);
    let e = scene.ground_half_extent;
    let mut lo = DVec3::new(c.x - e, scene.ground_y, c.z - e);
    let mut hi = DVec3::new(c.x + e, scene.ground_y, c.z + e);
    for b in &scene.boxes {
        let (mn, mx) = b.world_bounds();
        lo = lo.min(mn);
        hi = hi.max(mx);
    }
    let v = view.world_to_eye;
    // Each face of the box by a point on it and its outward normal, carried to eye space.
    let faces = [
        (hi, DVec3::X),
        (lo, DVec3::NEG_X),
        (hi, DVec3::Y),
        (lo, DVec3::NEG_Y),
        (hi, DVec3::Z),
        (lo, DVec3::NEG_Z),
    ];
    faces
        .iter()
        .map(|&(p, n)| {
            let pe = v.transform_point3(p);
            let ne = v.transform_vector3(n).normalize();
            ne.extend(-ne.dot(pe))
        })
        .collect()
}

/// The quad of frustum face `face` (0 bottom, 1 right, 2 top, 3 left, 4 near, 5 far) between eye
/// depths `a` and `b`.
fn face_quad(face: i32, a: f64, b: f64, t: f64, ta: f64) -> Option<[DVec3; 4]> {
    let at = |z: f64, sx: f64, sy: f64| DVec3::new(sx * ta * z, sy * t * z, -z);
    Some(match face {
        0 => [
            at(a, -1.0, -1.0),
            at(a, 1.0, -1.0),
            at(b, 1.0, -1.0),
            at(b, -1.0, -1.0),
        ],
        1 => [
            at(a, 1.0, -1.0),
            at(a, 1.0, 1.0),
            at(b, 1.0, 1.0),
            at(b, 1.0, -1.0),
        ],
        2 => [
            at(a, -1.0, 1.0),
            at(a, 1.0, 1.0),
            at(b, 1.0, 1.0),
            at(b, -1.0, 1.0),
        ],
        3 => [
            at(a, -1.0, -1.0),
            at(a, -1.0, 1.0),
            at(b, -1.0, 1.0),
            at(b, -1.0, -1.0),
        ],
        4 => [
            at(a, -1.0, -1.0),
            at(a, 1.0, -1.0),
            at(a, 1.0, 1.0),
            at(a, -1.0, 1.0),
        ],
        5 => [
            at(b, -1.0, -1.0),
            at(b, 1.0, -1.0),
            at(b, 1.0, 1.0),
            at(b, -1.0, 1.0),
        ],
        _ => return None,
    })
}

/// The side planes of the prism swept by `quad` along the light `l`: each holds an edge and `l`,
/// facing away from the quad's centre. An edge (nearly) along the light gives none.
fn prism_planes(quad: &[DVec3; 4], l: DVec3) -> Vec<Plane> {
    let centre = quad.iter().copied().sum::<DVec3>() / 4.0;
    let mut out = Vec::new();
    for i in 0..4 {
        let (p, q) = (quad[i], quad[(i + 1) % 4]);
        let n = (q - p).cross(l);
        if n.length() <= 1e-9 * (q - p).length() {
            continue;
        }
        let n = n.normalize();
        let n = if n.dot(centre - p) > 0.0 { -n } else { n };
        out.push(n.extend(-n.dot(p)));
    }
    out
}

/// The vertices of the bounded intersection of `planes`: every point where three of them meet
/// that lies inside all (within `tol`), without repeats closer than `tol`.
pub fn vertices(planes: &[Plane], tol: f64) -> Vec<DVec3> {
    let mut out: Vec<DVec3> = Vec::new();
    let n = planes.len();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let (a, b, c) = (planes[i], planes[j], planes[k]);
                let m = DMat3::from_cols(a.truncate(), b.truncate(), c.truncate()).transpose();
                if m.determinant().abs() < 1e-12 {
                    continue;
                }
                let p = m.inverse() * DVec3::new(-a.w, -b.w, -c.w);
                if !p.is_finite() || planes.iter().any(|&pl| side(pl, p) > tol) {
                    continue;
                }
                if out.iter().all(|q| q.distance(p) > tol) {
                    out.push(p);
                }
            }
        }
    }
    out
}

/// The Hausdorff-like distance between the crate's body `got` and the polytope `planes` with
/// vertices `want`, over the diameter of both: the largest of each `got` vertex's distance
/// outside a plane and each `want` vertex's distance from the nearest `got` vertex. Finite for
/// every input: 0 for two empty bodies, [`MISSING`] for one empty and one not, or for two that
/// differ while both are single points.
pub fn body_distance(got: &[DVec3], want: &[DVec3], planes: &[Plane]) -> f64 {
    match (want.is_empty(), got.is_empty()) {
        (true, true) => return 0.0,
        (true, false) | (false, true) => return MISSING,
        (false, false) => {}
    }
    // The diameter of both together: a rebuilt B that degenerates to a point or a segment (a
    // slice touching the receivers' box at a corner or an edge) still gives a finite distance.
    let mut diam = 0.0f64;
    for p in want.iter().chain(got) {
        for q in want.iter().chain(got) {
            diam = diam.max(p.distance(*q));
        }
    }
    let outside = got
        .iter()
        .flat_map(|&p| planes.iter().map(move |&pl| side(pl, p)))
        .fold(0.0f64, f64::max);
    let missing = want
        .iter()
        .map(|&p| {
            got.iter()
                .map(|q| q.distance(p))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0f64, f64::max);
    let d = outside.max(missing);
    if diam > 0.0 {
        d / diam
    } else if d > 0.0 {
        MISSING
    } else {
        0.0
    }
}

/// [`Geometry::body_rel_diff`] where a whole body is missing or extra (a slice of B with no map,
/// a map with no slice, a body where B has none): its own diameter.
pub const MISSING: f64 = 1.0;

/// The least radius of a sphere centred on the view axis that holds the slice `[a, b]`'s corners
/// (k = the corner ray's slope, |(tan θ aspect, tan θ)|), and its centre's eye depth: the convex
/// largest corner distance minimised by golden-section search over the centre's depth in
/// `[a, b]`. By the slice's symmetry the least enclosing sphere is centred on the axis.
pub fn least_sphere(a: f64, b: f64, k: f64) -> (f64, f64) {
    let r = |c: f64| ((c - a).hypot(a * k)).max((c - b).hypot(b * k));
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut lo, mut hi) = (a, b);
    for _ in 0..200 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if r(x1) <= r(x2) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    let c = 0.5 * (lo + hi);
    (c, r(c))
}

/// The clipmap's level offset L from the camera frustum (docs/rendered.md, "What is measured",
/// 16): a pixel at eye depth z is `2 z tan θ / H` wide and level i's texel `2^{i+3} unit / R`
/// (Unreal's layout: half-width 2^{i+2} unit), so the coarsest level with a texel of at most 2^b
/// pixels is ⌊log₂ z + b + log₂(tan θ R / (4 unit H))⌋; the disc of level i, radius 2^{i+1}
/// unit, covers the frustum's corner ray at depth z, length k z with k = |(tan θ aspect, tan θ,
/// 1)|, from level ⌊log₂ z + log₂(k / unit)⌋ on. L is the larger of the two offsets.
pub fn clipmap_offset(t: f64, aspect: f64, height: u32, res: u32, unit: f64, bias: f64) -> f64 {
    let matched = bias + (t * f64::from(res) / (4.0 * unit * f64::from(height))).log2();
    let k = DVec3::new(t * aspect, t, 1.0).length();
    matched.max((k / unit).log2())
}

/// The texel edge vectors of a map (eye → clip `m`, or any space → clip) at `p`: the vectors ⊥
/// `l` in that space that move clip s, t by one unit each, from the exact derivatives of (x/w,
/// y/w); `None` where they do not exist (the map degenerate at `p`).
pub fn texel_edges(m: &DMat4, l: DVec3, p: DVec3) -> Option<(DVec3, DVec3)> {
    let h = *m * p.extend(1.0);
    let row = |i: usize| m.row(i).truncate();
    let ds = (row(0) * h.w - row(3) * h.x) / (h.w * h.w);
    let dt = (row(1) * h.w - row(3) * h.y) / (h.w * h.w);
    let u1 = l.any_orthonormal_vector();
    let u2 = l.cross(u1);
    let j = glam::DMat2::from_cols(
        glam::DVec2::new(ds.dot(u1), dt.dot(u1)),
        glam::DVec2::new(ds.dot(u2), dt.dot(u2)),
    );
    if j.determinant().abs() < 1e-300 {
        return None;
    }
    let inv = j.inverse();
    let e_s = u1 * inv.col(0).x + u2 * inv.col(0).y;
    let e_t = u1 * inv.col(1).x + u2 * inv.col(1).y;
    Some((e_s, e_t))
}

fn depth(m: &DMat4, p: DVec3) -> f64 {
    let h = *m * p.extend(1.0);
    h.z / h.w
}

/// The point of the plane through `p` with normal `n` whose clip position under `m` is `(s, t)`.
fn plane_point(m: &DMat4, p: DVec3, n: DVec3, s: f64, t: f64) -> Option<DVec3> {
    let r = |i: usize| m.row(i);
    let a = r(0) - r(3) * s;
    let b = r(1) - r(3) * t;
    let mat = DMat3::from_cols(a.truncate(), b.truncate(), n).transpose();
    if mat.determinant().abs() < 1e-300 {
        return None;
    }
    let x = mat.inverse() * DVec3::new(-a.w, -b.w, n.dot(p));
    x.is_finite().then_some(x)
}

/// The unit normals of the grid the needs are taken over: α (from the direction to the light)
/// in steps of 3° to 87° and 89°, φ around it in steps of 7.5°, for the light `l` (travel).
fn normals(l: DVec3) -> Vec<(f64, DVec3)> {
    let u1 = l.any_orthonormal_vector();
    let u2 = l.cross(u1);
    let mut out = Vec::new();
    let mut alphas: Vec<f64> = (0..30).map(|i| 3.0 * f64::from(i)).collect();
    alphas.push(89.0);
    for a in alphas {
        let (sa, ca) = a.to_radians().sin_cos();
        let steps = if a == 0.0 { 1 } else { 48 };
        for j in 0..steps {
            let (sp, cp) = (7.5 * f64::from(j)).to_radians().sin_cos();
            out.push((a, -l * ca + (u1 * cp + u2 * sp) * sa));
        }
    }
    out
}

/// The f32 rounding of the two depths a lookup compares, at depth 1: 8 ulps (the margin the
/// crate's docs add to the constant depth bias).
const ROUNDING: f64 = 8.0 * f32::EPSILON as f64;

/// A map's needs at the vertices `body` for the kernel half-width `rho` texels.
struct Needs {
    /// Least record / need of the normal offset over every vertex and normal.
    offset_least: f64,
    /// The largest normal-offset need.
    offset_max: f64,
    /// Least record / need of the depth bias over every vertex and normal.
    depth_least: f64,
    /// Per α of the grid, the largest depth-bias need.
    depth_max: Vec<(f64, f64)>,
}

/// The needs of the plane through each vertex of `body` in the map `m` (eye → clip, depth
/// [0, 1]) of `res` texels, light `l` (travel), kernel reach `rho` texels, against the record's
/// normal offset `offset` and depth bias `(constant, slope)` (magnitudes, toward the light). A tap
/// reads the plane's depth on the ray through its texel's centre; the plane's depth is affine in
/// (s, t) (a projective map keeps planes), so the worst of the taps within `rho` texels of p in s
/// and t lies `rho` texels away in both, `rho (2/res) (|g_s| + |g_t|)` nearer the light than p
/// (g the plane's depth gradient in (s, t), solved from the matrix). The depth-bias need is that
/// step plus [`ROUNDING`]; the normal-offset need is the o at which p + o n, o / cos α above the
/// plane along the light, is that step nearer the light at its own rate of depth along the light
/// (the footprint followed to the offset point: the map's w there, `w(p) + o (row₃ · n)`, not
/// p's; with p's held, PSM's record passed at 0.574 of what its set-ups need).
fn needs(
    m: &DMat4,
    res: u32,
    l: DVec3,
    body: &[DVec3],
    rho: f64,
    offset: f64,
    (constant, slope): (f64, f64),
) -> Needs {
    let texel = 2.0 / f64::from(res);
    let grid = normals(l);

    let mut out = Needs {
        offset_least: f64::INFINITY,
        offset_max: 0.0,
        depth_least: f64::INFINITY,
        depth_max: Vec::new(),
    };
    let mut per_alpha: Vec<(f64, f64)> = Vec::new();
    for &p in body {
        let h = *m * p.extend(1.0);
        if h.w <= 0.0 {
            continue;
        }
        let (s0, t0, d0) = (h.x / h.w, h.y / h.w, h.z / h.w);
        // ∂d/∂λ along the light at p, exactly: (row₂ w − row₃ z)/w² · l.
        let grad = (m.row(2).truncate() * h.w - m.row(3).truncate() * h.z) / (h.w * h.w);
        let rate_along = grad.dot(l);
        for &(alpha, n) in &grid {
            let (Some(ps), Some(pt)) = (
                plane_point(m, p, n, s0 + texel, t0),
                plane_point(m, p, n, s0, t0 + texel),
            ) else {
                continue;
            };
            let g = ((depth(m, ps) - d0).abs() + (depth(m, pt) - d0).abs()) / texel;
            let step = rho * texel * g;
            let depth_need = step + ROUNDING;
            let record_depth = constant + slope * alpha.to_radians().tan();
            out.depth_least = out.depth_least.min(record_depth / depth_need);
            match per_alpha.iter_mut().find(|(a, _)| *a == alpha) {
                Some(e) => e.1 = e.1.max(depth_need),
                None => per_alpha.push((alpha, depth_need)),
            }
            // The lookup at q = p + o n reads the taps around q's own projection, where the
            // plane's depth has the same step (affine in s, t). The footprint is followed along
            // the normal: the map's w is constant along a light ray, so q lies o / cos α above the plane along the light, worth
            // |∂d/∂λ(p)| · w(p)/w(q) · o / cos α of depth, with w(q) = w(p) + o (row₃ · n);
            // equal to the step at o = Y / (|∂d/∂λ(p)| − Y (row₃ · n)/w(p)), Y = step · cos α.
            // A denominator not above 0 (q at or past the centre of projection): no offset
            // suffices, an infinite need.
            let cos = n.dot(-l);
            let y = step * cos;
            let den = rate_along.abs() - y * m.row(3).truncate().dot(n) / h.w;
            let o = if den > 0.0 { y / den } else { f64::INFINITY };
            if o.is_nan() || o < 0.0 {
                continue;
            }
            out.offset_max = out.offset_max.max(o);
            if o > 0.0 {
                out.offset_least = out.offset_least.min(offset / o);
            }
        }
    }
    out.depth_max = per_alpha;
    out
}

/// The eye-depth slices of the maps as render-check places them: the camera's range for a single
/// map and face maps, the paper's split planes ([`Built::planes`]) for cascades, reaching the
/// requested band ([`Built::bands`]) for blended ones, and the rule's levels for a clipmap.
fn slices(
    scheme: Scheme,
    view: &View,
    built: &Built,
    levels: &[(i32, f64, f64)],
) -> Vec<(f64, f64)> {
    let (n, f) = (view.frustum.near(), view.frustum.far());
    match scheme {
        Scheme::Cascades | Scheme::StableCascades | Scheme::BlendedCascades => built
            .planes
            .windows(2)
            .enumerate()
            .map(|(i, w)| (w[0], built.bands.get(i).map_or(w[1], |b| b.1.max(w[1]))))
            .collect(),
        Scheme::Clipmap => levels.iter().map(|&(_, a, b)| (a, b)).collect(),
        _ => vec![(n, f); built.maps.len()],
    }
}

/// The clipmap's levels by the rule ([`clipmap_offset`]): (level, first depth, last depth) over
/// the camera's range, and L.
fn clipmap_levels(view: &View, res: u32) -> (Vec<(i32, f64, f64)>, f64) {
    let o = clipmap_options(res);
    let fr = &view.frustum;
    let big_l = clipmap_offset(
        fr.tan_half_fov(),
        fr.aspect(),
        view.image_height,
        res,
        o.unit,
        o.lod_bias,
    );
    let (n, f) = (fr.near(), fr.far());
    let level = |z: f64| ((z.log2() + big_l).floor() as i32).clamp(o.first_level, o.last_level);
    let first = level(n);
    let last = (((f.log2() + big_l).ceil() as i32) - 1).clamp(first, o.last_level);
    let start = |i: i32| (f64::from(i) - big_l).exp2();
    let levels = (first..=last)
        .map(|i| {
            let a = if i == first { n } else { start(i).max(n) };
            (i, a, start(i + 1).min(f))
        })
        .collect();
    (levels, big_l)
}

/// Every measurement of this module for one case ([`Geometry`]).
pub fn measure(scheme: Scheme, view: &View, scene: &Scene, built: &Built, res: u32) -> Geometry {
    let fr = &view.frustum;
    let (t, ta) = (fr.tan_half_fov(), fr.tan_half_fov() * fr.aspect());
    let l = view.light_eye.normalize();
    let receivers = receiver_planes(scene, view);
    let (levels, big_l) = if scheme == Scheme::Clipmap {
        clipmap_levels(view, res)
    } else {
        (Vec::new(), 0.0)
    };
    let sl = slices(scheme, view, built, &levels);
    let fitted = !matches!(scheme, Scheme::StableCascades | Scheme::Clipmap);
    let mut g = Geometry {
        body_rel_diff: 0.0,
        window_fill: fitted.then_some(0.0),
        stable_half_width_rel_diff: (scheme == Scheme::StableCascades).then_some(0.0),
        stable_centre_texels: (scheme == Scheme::StableCascades).then_some(0.0),
        clipmap_rel_diff: (scheme == Scheme::Clipmap).then_some(0.0),
        normal_offset_ratio: [f64::INFINITY, 0.0],
        depth_bias_ratio: [f64::INFINITY, 0.0],
        texel_world_ratio: 0.0,
        receivers_volume_rel_diff: 0.0,
        casters_volume_rel_diff: 0.0,
        split_rel_diff: crate::options::split_rel_diff(built),
        depth_clamp_fill: (built.depth_clamp && scheme != Scheme::Faces).then_some(0.0),
    };
    // Each map's slice: by order for one map and face maps; for cascades and clipmaps the unused
    // slice whose start lies nearest the map's near end (in ln z; an empty slice gives no map).
    let depth_selected = matches!(
        scheme,
        Scheme::Cascades | Scheme::StableCascades | Scheme::BlendedCascades | Scheme::Clipmap
    );
    let mut used = vec![false; sl.len()];
    let pair: Vec<Option<usize>> = built
        .maps
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let j = if depth_selected {
                (0..sl.len()).filter(|&j| !used[j]).min_by(|&x, &y| {
                    let d = |j: usize| (m.near / sl[j].0).ln().abs();
                    d(x).total_cmp(&d(y))
                })?
            } else {
                i
            };
            (j < sl.len() && !used[j]).then(|| {
                used[j] = true;
                j
            })
        })
        .collect();
    let body_of = |(a, b): (f64, f64), region: i32| -> (Vec<Plane>, Vec<DVec3>, bool) {
        let mut planes = slice_planes(a, b, t, ta);
        planes.extend_from_slice(&receivers);
        let mut ok = true;
        if scheme == Scheme::Faces {
            match face_quad(region, fr.near(), fr.far(), t, ta) {
                Some(q) => planes.extend(prism_planes(&q, l)),
                None => ok = false,
            }
        }
        let tol = 1e-9 * b * (1.0 + t + ta);
        let body = vertices(&planes, tol);
        (planes, body, ok)
    };
    // A slice left without a map must hold no volume of B: one that does misses a whole body
    // (1, its own diameter).
    for (j, u) in used.iter().enumerate() {
        if !u && body_of(sl[j], -1).1.len() >= 4 {
            g.body_rel_diff = g.body_rel_diff.max(MISSING);
        }
    }
    let mut texel_ratio_worst = 1.0f64;
    let mut first = true;
    for (i, map) in built.maps.iter().enumerate() {
        // A map with no slice of its own (more maps than slices) covers no body of the rule's:
        // a whole body off (1).
        let Some(j) = pair[i] else {
            g.body_rel_diff = g.body_rel_diff.max(MISSING);
            if let Some(c) = &mut g.clipmap_rel_diff {
                *c = c.max(MISSING);
            }
            continue;
        };
        let (a, b) = sl[j];
        // The map must hold B over its slice and over every depth the shader selects it for
        // (its record's range, within the camera's): a split range that reaches past the slice
        // reaches past the map's body.
        let range = if depth_selected {
            (a.min(map.near.max(fr.near())), b.max(map.far.min(fr.far())))
        } else {
            (a, b)
        };
        let (planes, body, ok) = body_of(range, map.region);
        if !ok {
            g.body_rel_diff = g.body_rel_diff.max(MISSING);
        }
        g.body_rel_diff = g
            .body_rel_diff
            .max(body_distance(&built.bodies[i], &body, &planes));
        // The receivers' volume, world → eye (a rigid map: planes by the inverse transpose).
        let to_eye = view.world_to_eye.inverse().transpose();
        let volume: Vec<Plane> = map.receivers.planes().iter().map(|&p| to_eye * p).collect();
        let size = fr.far() * (1.0 + t + ta);
        g.receivers_volume_rel_diff = g
            .receivers_volume_rel_diff
            .max(volume_distance(&volume, &body, &planes, size));
        let casters: Vec<Plane> = map.casters.planes().iter().map(|&p| to_eye * p).collect();
        let range = (&map.built, built.depth_clamp);
        let d = casters_volume_distance(&casters, (&body, &planes), l, range, size);
        g.casters_volume_rel_diff = g.casters_volume_rel_diff.max(d);
        if body.is_empty() {
            continue;
        }
        if let Some(c) = &mut g.depth_clamp_fill {
            let d = body.iter().map(|&p| depth(&map.gpu, p));
            let lo = d.clone().fold(f64::INFINITY, f64::min);
            let hi = d.fold(f64::NEG_INFINITY, f64::max);
            // Stable cascades and clipmap levels snap their depth range outward to whole texels
            // of a world grid (the crate's docs, `FrameScheme::Stable`): each end may lie up to
            // a texel (2/(|row 0| res) world units, |row 2| of depth per unit) past B.
            let snap = if fitted {
                0.0
            } else {
                2.0 / (map.gpu.row(0).truncate().length() * f64::from(map.res))
                    * map.gpu.row(2).truncate().length()
            };
            let gap = lo.abs().max((hi - 1.0).abs());
            *c = c.max((gap - snap).max(0.0));
        }
        if let Some(w) = &mut g.window_fill {
            *w = w.max(fill(&map.built, &body));
        }
        if scheme == Scheme::StableCascades {
            stable(map, (a, b), t.hypot(ta), map.res, &mut g);
        }
        if scheme == Scheme::Clipmap {
            let (level, _, _) = levels[j];
            let c = g.clipmap_rel_diff.as_mut().expect("clipmap");
            *c = c.max(clipmap_map(map, levels[j], map.res));
            if std::mem::take(&mut first) {
                *c = c.max((built.clipmap[0] - big_l).abs());
                *c = c.max((built.clipmap[1] - f64::from(level)).abs());
            }
        }
        bias(map, &body, l, map.res, &mut g);
        // texel_world: the largest texel edge over B; texel_extent: the largest edge along s
        // and along t, read from the bytes uploaded (docs/renderer.md's layout: bytes 112 and
        // 116, little-endian f32).
        let [s, t] = body
            .iter()
            .filter_map(|&p| texel_edges(&map.built, l, p))
            .fold([0.0f64; 2], |[s, t], (es, et)| {
                [s.max(es.length()), t.max(et.length())]
            })
            .map(|e| e * 2.0 / f64::from(map.res));
        let bytes = map.record.to_bytes();
        let at = |i: usize| {
            f64::from(f32::from_le_bytes([
                bytes[i],
                bytes[i + 1],
                bytes[i + 2],
                bytes[i + 3],
            ]))
        };
        for r in [
            f64::from(map.record.texel_world) / s.max(t),
            at(112) / s,
            at(116) / t,
        ] {
            if (r - 1.0).abs() >= (texel_ratio_worst - 1.0).abs() || r.is_nan() {
                texel_ratio_worst = r;
            }
        }
    }
    g.texel_world_ratio = texel_ratio_worst;
    g
}

/// The largest distance of the body's extreme s or t (clip, under the eye → clip `m`) from ±1.
fn fill(m: &DMat4, body: &[DVec3]) -> f64 {
    let (mut lo, mut hi) = (
        glam::DVec2::splat(f64::INFINITY),
        glam::DVec2::splat(f64::NEG_INFINITY),
    );
    for &p in body {
        let h = *m * p.extend(1.0);
        if h.w <= 0.0 {
            return f64::INFINITY;
        }
        let q = glam::DVec2::new(h.x / h.w, h.y / h.w);
        lo = lo.min(q);
        hi = hi.max(q);
    }
    [
        (lo.x + 1.0).abs(),
        (lo.y + 1.0).abs(),
        (hi.x - 1.0).abs(),
        (hi.y - 1.0).abs(),
    ]
    .into_iter()
    .fold(0.0, f64::max)
}

/// A stable cascade's window against the least sphere of its slice `(a, b)` (corner ray slope
/// `k`): an orthographic map's half-width is 1 / |row 0| (eye units, rows 0 and 1 alike), its
/// centre where s = t = 0.
fn stable(map: &Map, (a, b): (f64, f64), k: f64, res: u32, g: &mut Geometry) {
    let (c, r) = least_sphere(a, b, k);
    let m = map.built;
    let resf = f64::from(res);
    let want = r * resf / (resf - 2.0);
    let hw = |i: usize| 1.0 / m.row(i).truncate().length();
    let d = (hw(0) / want - 1.0).abs().max((hw(1) / want - 1.0).abs());
    let h = m * DVec4::new(0.0, 0.0, -c, 1.0);
    // Clip spans 2 over res texels.
    let off = (h.x / h.w).abs().max((h.y / h.w).abs()) * resf / 2.0;
    let w = g.stable_half_width_rel_diff.as_mut().expect("stable");
    *w = w.max(d);
    let o = g.stable_centre_texels.as_mut().expect("stable");
    *o = o.max(off);
}

/// One clipmap level's map against the rule's `(level, a, b)`: its texel (2 / res of its window,
/// 2 / |row 0| eye units wide) against `2^{level+3} unit / res`, its depth range against
/// `[a, b]`, relatively.
fn clipmap_map(map: &Map, (level, a, b): (i32, f64, f64), res: u32) -> f64 {
    let o = clipmap_options(res);
    let texel = 2.0 / map.built.row(0).truncate().length() / f64::from(res);
    let want = f64::from(level + 3).exp2() * o.unit / f64::from(res);
    (texel / want - 1.0)
        .abs()
        .max((map.near / a - 1.0).abs())
        .max((map.far / b - 1.0).abs())
}

/// The records' bias values (r = 0: the uploaded record; r = 1: `record_pcf1`) against the needs
/// at `body`'s vertices.
fn bias(map: &Map, body: &[DVec3], l: DVec3, res: u32, g: &mut Geometry) {
    // Toward the light in the record's convention: depth [0, 1] (code 1) decreases, reversed
    // (code 2) increases. A value of the wrong sign counts as negative.
    let reversed = map.record.clip_depth == 2;
    // ∂d/∂λ along the light at B's first vertex (depth [0, 1]), exactly, for its sign.
    let h = map.gpu * body[0].extend(1.0);
    let grad = (map.gpu.row(2).truncate() * h.w - map.gpu.row(3).truncate() * h.z) / (h.w * h.w);
    let rate = grad.dot(l);
    // The record's depth values move toward the light when their sign is −sign(rate) in depth
    // [0, 1], +sign(rate) in reversed depth (1 − d).
    let toward = if reversed {
        rate.signum()
    } else {
        -rate.signum()
    };
    // The kernels render-check asked for: r = 0 (the uploaded record) and r = 1
    // (`record_pcf1`), reaching r + ½ texels.
    for (rec, rho) in [(&map.record, 0.5), (&map.record_pcf1, 1.5)] {
        let constant = f64::from(rec.constant_depth) * toward;
        let slope = f64::from(rec.slope_scaled_depth) * toward;
        let offset = f64::from(rec.normal_offset);
        let n = needs(&map.gpu, res, l, body, rho, offset, (constant, slope));
        let o = &mut g.normal_offset_ratio;
        o[0] = o[0].min(n.offset_least);
        o[1] = o[1].max(offset / n.offset_max);
        let d = &mut g.depth_bias_ratio;
        d[0] = d[0].min(n.depth_least);
        // Each term against its own need: the constant against the largest need at α = 0 (the
        // plane facing the light: the depth step across the texel and the rounding), the slope
        // term at α = 89° against the largest need there.
        let at = |alpha: f64| {
            n.depth_max
                .iter()
                .find(|&&(a, _)| a == alpha)
                .map_or(f64::NAN, |&(_, need)| need)
        };
        let upper = (constant / at(0.0)).max(slope * 89f64.to_radians().tan() / at(89.0));
        d[1] = d[1].max(upper);
    }
}
