//! The shadow comparison's band (docs/rendered.md, "Shadow correctness"): which pixels the
//! shader's one nearest-texel lookup must get right, decided in shadow-map texels from the map's
//! own light rays and exact ray casts, for second-depth maps and for first-surface maps looked up
//! at the crate's normal offset.

use crate::scene::{ray_occluded, Scene, SceneBox};
use crate::schemes::{Built, View};
use glam::{DMat4, DVec3};
use shadow_aliasing::frame::bias::normal_offset_at;
use shadow_aliasing::maps::ClipDepth;

/// The largest depth bias the second-depth shadow pass can apply to a caster face (depth units):
/// the rasterizer's `slope_scale · m + constant · r` (Vulkan's depth bias, as wgpu sets it:
/// [`crate::gpu::SLOPE_BIAS`], [`crate::gpu::CONSTANT_BIAS`]), with m the face's depth slope in
/// the map's window coordinates (`slope`: its depth steps per texel along s and t, `(|∂z/∂s|,
/// |∂z/∂t|)`; Vulkan allows max(|∂z/∂x|, |∂z/∂y|) or their hypotenuse, the larger taken) and r
/// the depth format's resolution at the primitive's largest depth, 2^(e − 23) for `Depth32Float`
/// (e the exponent of a depth ≤ 1: at most 2⁻²³), plus 8 `f32` ulps at depth 1 for the stored and
/// the receiver's depths' rounding. A pixel in a cast shadow is left out of the shadow comparison
/// when, on the light ray the shader reads, the caster face lies within this of it in depth:
/// there the bias lets light leak onto a receiver behind a caster standing on it (the contact
/// band).
pub fn rasterizer_bias(slope: (f64, f64)) -> f64 {
    let ulp = f64::from(f32::EPSILON);
    f64::from(crate::gpu::SLOPE_BIAS) * slope.0.hypot(slope.1)
        + (f64::from(crate::gpu::CONSTANT_BIAS) + 8.0) * ulp
}

/// A map as the shadow test needs it: world ↔ light clip (depth [0, 1]), and for first-surface
/// maps the normal offset of the lookup (world units; `None`: second-depth maps).
pub(crate) struct MapGeom {
    pub(crate) world_to_clip: DMat4,
    pub(crate) clip_to_world: DMat4,
    pub(crate) normal_offset: Option<f64>,
}

/// The texel centre is sampled also this far (texels) from it along each map axis: where the
/// exact boundary passes within it of the centre, the rasterizer's `f32` coverage decides either
/// way.
const CENTRE_TOLERANCE: f64 = 0.02;

/// How close to a texel edge (in texels) a pixel's map position must be for the neighbouring
/// texel to be taken as a lookup the GPU may have made instead (its `f32` position is within
/// about 10⁻⁴ texel of the exact one).
const TEXEL_TIE: f64 = 2e-3;

/// The normal offset a first-surface lookup of the map `world_to_clip` (world or camera-relative
/// positions, as `pw` is given) uses at `pw`: the least that keeps the lookup lit there (the
/// shader's `sa_local_normal_offset`, `frame::bias::normal_offset_at`), the map's maximum `max`
/// where none suffices (the shader's fallback to the record's value).
pub(crate) fn first_surface_offset(
    world_to_clip: &DMat4,
    res: u32,
    pw: DVec3,
    nw: DVec3,
    light: DVec3,
    max: f64,
) -> f64 {
    normal_offset_at(world_to_clip, ClipDepth::ZeroToOne, res, pw, nw, light, 0.0).unwrap_or(max)
}

/// The verdict the render must give at one pixel facing the light (docs/rendered.md, "Shadow
/// correctness"): `Some(true)` in shadow, `Some(false)` lit, `None` where no verdict is certain
/// (the band left out of the comparison).
///
/// The shader reads one texel, nearest, and compares the pixel's light depth with the depth
/// stored there (plus the depth bias): the first caster face turned away from the light along
/// the light ray through the texel's centre (second-depth maps). Its right verdict is therefore
/// the exact state on that ray at the pixel's light depth: the pixel's own state, except where
/// the exact boundary passes between the pixel and the texel's centre, where it is the texel's
/// (the nearest-texel lookup's aliasing, not an error). For the centre `c` of the texel the
/// pixel's map position falls in (and of the neighbouring texel when that position is within
/// [`TEXEL_TIE`] of an edge, where the GPU's `f32` may round across), and for `c` moved
/// [`CENTRE_TOLERANCE`] along either map axis, a verdict is made from:
///
/// - the point `q` where c's light ray meets the pixel's surface plane, which must not be inside
///   a box; its exact state is the verdict; and
/// - the point `r` on c's light ray at the pixel's light depth, which must not be inside a box
///   other than the one the pixel lies on, and must have `q`'s exact state (no caster between the
///   plane and the pixel's depth on that ray); in shadow, the caster face the ray from `r` meets
///   first must lie, in depth, beyond the rasterizer's bias of it ([`rasterizer_bias`]: the slope
///   term from the face's own depth slope in the map's window coordinates, and the constant);
///   on second-depth maps, the ray from `r` toward the light must not run within
///   [`CENTRE_TOLERANCE`] texel of a face edge-on to the light (stored as a zero-area sliver
///   whose depth the rasterizer does not define).
///
/// The pixel is decided when all of them give one verdict: the pixels left out are those whose
/// texel's centre lies within 0.02 texel of the exact boundary, at a contact, or along an
/// edge-on face. The light rays
/// are the map's own (its matrix, so a wrong light direction is not excused); the exact states
/// are ray casts toward the true light.
///
/// First-surface maps (`map.normal_offset` set) store the surface nearest the light along each
/// texel's ray, and the shader looks up the point p + o n (o the per-point normal offset,
/// [`first_surface_offset`]) at its own depth, with no other bias. Their texel is the one holding
/// p + o n, `r` is at p + o n's light depth, and there is no contact band: the shadow of a caster
/// standing on the receiver is decided (a caster within the offset of the receiver along the
/// texel's ray is inside a box or parts `q`'s and `r`'s states, and is left out by the tests
/// above). `q` must also lie on the pixel's
/// own face: where the texel's ray passes beyond an edge of a box's face it meets another
/// surface first (the ground at the box's foot, or where a sunk box's face goes below it), and
/// the texel straddles that edge. A lit pixel that the lookup
/// shadows because the offset is too small (acne: `r` below the pixel's own surface, where the ray
/// cast finds light) is compared, and counts as a false shadow.
#[allow(clippy::too_many_arguments)] // one pixel and its map, each needed once
pub(crate) fn shadow_verdict(
    scene: &Scene,
    map: &MapGeom,
    res: f64,
    pw: DVec3,
    nw: DVec3,
    light: DVec3,
) -> Option<bool> {
    let (wc, inv) = (&map.world_to_clip, &map.clip_to_world);
    let offset = map.normal_offset.map_or(0.0, |max| {
        first_surface_offset(wc, res as u32, pw, nw, light, max)
    });
    let h = *wc * (pw + nw * offset).extend(1.0);
    if h.w <= 0.0 {
        return None;
    }
    let s = (h.x / h.w + 1.0) * 0.5 * res;
    let t = (h.y / h.w + 1.0) * 0.5 * res;
    let depth = h.z / h.w;
    if !(0.0..res).contains(&s) || !(0.0..res).contains(&t) {
        return None;
    }
    let lift = crate::scene::lift(scene, pw);
    // The box the pixel lies on (its point just inside, against the normal).
    let own = scene
        .boxes
        .iter()
        .position(|b| box_contains(b, pw - nw * lift));
    // The faces edge-on to the light (box, axis), on second-depth maps: none for most lights.
    let edge_on = if map.normal_offset.is_none() {
        edge_on_faces(scene, light)
    } else {
        Vec::new()
    };
    // CENTRE_TOLERANCE texel's world length at the pixel's map position and light depth.
    let edge_tol = if edge_on.is_empty() {
        0.0
    } else {
        let at = |a: f64, b: f64| {
            inv.project_point3(DVec3::new(2.0 * a / res - 1.0, 2.0 * b / res - 1.0, depth))
        };
        let r0 = at(s, t);
        (at(s + CENTRE_TOLERANCE, t) - r0)
            .length()
            .max((at(s, t + CENTRE_TOLERANCE) - r0).length())
    };
    let inside = |q: DVec3, skip: Option<usize>| {
        scene
            .boxes
            .iter()
            .enumerate()
            .any(|(k, b)| Some(k) != skip && box_contains(b, q))
    };
    // The texel-centre ray through map position (a, b): its points at light depths 0 and 1.
    let ray = |a: f64, b: f64| -> Option<(DVec3, DVec3)> {
        let (x, y) = (2.0 * a / res - 1.0, 2.0 * b / res - 1.0);
        let q0 = inv.project_point3(DVec3::new(x, y, 0.0));
        let q1 = inv.project_point3(DVec3::new(x, y, 1.0));
        (q0.is_finite() && q1.is_finite()).then_some((q0, q1))
    };
    // The verdict the lookup must give through the texel ray at map position (a, b): whether
    // a caster lies between the light and the pixel's light depth on that ray, from exact ray
    // casts; `None` where no verdict is certain.
    let verdict = |a: f64, b: f64| -> Option<bool> {
        let (q0, q1) = ray(a, b)?;
        let d = q1 - q0;
        let den = d.dot(nw);
        if den.abs() < 1e-300 {
            return None;
        }
        // q: on the pixel's plane (lifted off it as the ray cast lifts the pixel).
        let q = q0 + d * ((pw - q0).dot(nw) / den) + nw * lift;
        if inside(q, None) {
            return None;
        }
        let on_plane = ray_occluded(scene, q, DVec3::ZERO, light);
        // First-surface maps store whatever surface the ray meets first: the texel's ray must
        // meet the pixel's own face (its box's face; the ground is unbounded), not pass beyond an
        // edge of it to another surface (the ground at a box's foot).
        if map.normal_offset.is_some()
            && own.is_some_and(|k| {
                !box_contains(&scene.boxes[k], q - nw * (2.0 * lift)) || q.y < scene.ground_y
            })
        {
            return None;
        }
        // r: at the pixel's light depth.
        let (x, y) = (2.0 * a / res - 1.0, 2.0 * b / res - 1.0);
        let r = inv.project_point3(DVec3::new(x, y, depth));
        if !r.is_finite() {
            return None;
        }
        // r inside the pixel's own box (under its face: the texel's ray passes the face's edge
        // below it): the ray between r and q crosses the own box alone, so r's verdict is q's;
        // the contact band below still applies, for a caster may rest on the face there (a box
        // on a step: its bottom face, which a second-depth map stores, lies in the receiver's
        // plane). Elsewhere r and q must agree: a caster between the plane and the pixel's
        // depth on this ray is a contact no verdict decides.
        // A face edge-on to the light (|n·L| ≤ FACING, stored by the second-depth pass) that
        // this texel's ray runs along, within the sampling tolerance: the face projects to a
        // zero-area sliver whose depth at the texel the rasterizer does not define (a pole's
        // side under a light with no component across it, the texel's centre on the side's
        // line: `parallel_1`'s PSM map at 240 × 180 shadowed such a pixel).
        if !edge_on.is_empty()
            && (!edge_tol.is_finite() || along_edge_on_face(scene, &edge_on, r, light, edge_tol))
        {
            return None;
        }
        let in_own = own.is_some_and(|k| box_contains(&scene.boxes[k], r));
        if !in_own && (inside(r, own) || ray_occluded(scene, r, DVec3::ZERO, light) != on_plane) {
            return None;
        }
        // The depth bias: the caster face the ray from r meets first must lie farther toward
        // the light than the bias, or the stored depth passes r.
        match first_face(scene, r, light) {
            Some((e, n)) if on_plane && map.normal_offset.is_none() => {
                // The face's depth on this texel ray and on the next ones along s and t: its
                // depth slope per texel (a plane's depth is affine in the map position), and
                // the depth it lies nearer the light than r.
                let f = r - light * e;
                let at = |a: f64, b: f64| plane_depth(wc, inv, res, a, b, f, n);
                let (d0, ds, dt) = (at(a, b)?, at(a + 1.0, b)?, at(a, b + 1.0)?);
                (depth - d0 > rasterizer_bias(((ds - d0).abs(), (dt - d0).abs()))).then_some(true)
            }
            _ => Some(on_plane),
        }
    };
    let centres = |v: f64| -> ([f64; 2], usize) {
        let c = v.floor() + 0.5;
        let f = v - v.floor();
        if f < TEXEL_TIE {
            ([c, c - 1.0], 2)
        } else if f > 1.0 - TEXEL_TIE {
            ([c, c + 1.0], 2)
        } else {
            ([c, c], 1)
        }
    };
    let (cs, ns) = centres(s);
    let (ct, nt) = centres(t);
    let e = CENTRE_TOLERANCE;
    // Every texel the GPU may read and every sample about its centre must give one verdict.
    let mut all = cs[..ns].iter().flat_map(|&a| {
        ct[..nt].iter().flat_map(move |&b| {
            [(0.0, 0.0), (e, 0.0), (-e, 0.0), (0.0, e), (0.0, -e)].map(|(da, db)| (a + da, b + db))
        })
    });
    let (a0, b0) = all.next()?;
    let v = verdict(a0, b0)?;
    all.all(|(a, b)| verdict(a, b) == Some(v)).then_some(v)
}

/// The depth [0, 1] (of `wc`, world → clip; `inv` its inverse) of the plane through `p` with
/// normal `n` on the texel ray through map position (`a`, `b`) (texels of a map of `res`).
pub(crate) fn plane_depth(
    wc: &DMat4,
    inv: &DMat4,
    res: f64,
    a: f64,
    b: f64,
    p: DVec3,
    n: DVec3,
) -> Option<f64> {
    let (x, y) = (2.0 * a / res - 1.0, 2.0 * b / res - 1.0);
    let q0 = inv.project_point3(DVec3::new(x, y, 0.0));
    let d = inv.project_point3(DVec3::new(x, y, 1.0)) - q0;
    let den = d.dot(n);
    if den.abs() <= 1e-300 || den.is_nan() || !q0.is_finite() || !d.is_finite() {
        return None;
    }
    let h = *wc * (q0 + d * ((p - q0).dot(n) / den)).extend(1.0);
    let z = h.z / h.w;
    z.is_finite().then_some(z)
}

/// The box faces edge-on to the light (|n·L| ≤ [`crate::scene::FACING`]: the faces the
/// second-depth pass stores besides those turned away), as (box, axis) pairs.
fn edge_on_faces(scene: &Scene, light: DVec3) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for (i, b) in scene.boxes.iter().enumerate() {
        let d = if b.is_rotated() {
            b.rotation().inverse() * -light
        } else {
            -light
        };
        out.extend(
            (0..3)
                .filter(|&k| d[k].abs() <= crate::scene::FACING)
                .map(|k| (i, k)),
        );
    }
    out
}

/// Whether the ray from `x` toward the light (against `light`, the direction it travels) runs
/// within `tol` of one of the `faces` ([`edge_on_faces`]: box, axis), over that face.
fn along_edge_on_face(
    scene: &Scene,
    faces: &[(usize, usize)],
    x: DVec3,
    light: DVec3,
    tol: f64,
) -> bool {
    faces.iter().any(|&(i, k)| {
        let b = &scene.boxes[i];
        let (o, d) = if b.is_rotated() {
            let (c, rot) = (b.centre(), b.rotation().inverse());
            (c + rot * (x - c), rot * -light)
        } else {
            (x, -light)
        };
        {
            if (o[k] - b.min[k]).abs() > tol && (o[k] - b.max[k]).abs() > tol {
                return false;
            }
            // The ray, t ≥ 0, over the face's rectangle (the other two axes, widened by tol).
            let (mut t0, mut t1) = (0.0f64, f64::INFINITY);
            for j in (0..3).filter(|&j| j != k) {
                let (lo, hi) = (b.min[j] - tol, b.max[j] + tol);
                if d[j].abs() < 1e-300 {
                    if o[j] < lo || o[j] > hi {
                        return false;
                    }
                    continue;
                }
                let (p, q) = ((lo - o[j]) / d[j], (hi - o[j]) / d[j]);
                t0 = t0.max(p.min(q));
                t1 = t1.min(p.max(q));
            }
            t0 <= t1
        }
    })
}

/// The first box face the ray from `x` toward the light (against `light`, the direction it
/// travels) meets from outside: its distance and outward world normal (a face turned away from
/// the light: the one a second-depth map stores).
fn first_face(scene: &Scene, x: DVec3, light: DVec3) -> Option<(f64, DVec3)> {
    let mut best: Option<(f64, DVec3)> = None;
    for b in &scene.boxes {
        let (c, rot) = (b.centre(), b.rotation());
        let (o, d) = if b.is_rotated() {
            (c + rot.inverse() * (x - c), rot.inverse() * -light)
        } else {
            (x, -light)
        };
        let (mut t0, mut t1, mut axis) = (f64::NEG_INFINITY, f64::INFINITY, None);
        let mut miss = false;
        for k in 0..3 {
            if d[k].abs() < 1e-300 {
                miss |= o[k] < b.min[k] || o[k] > b.max[k];
                continue;
            }
            let (a, e) = ((b.min[k] - o[k]) / d[k], (b.max[k] - o[k]) / d[k]);
            let (a, e) = if a < e { (a, e) } else { (e, a) };
            if a > t0 {
                t0 = a;
                axis = Some(k);
            }
            t1 = t1.min(e);
        }
        let Some(k) = axis else { continue };
        if miss || t0 > t1 || t0 <= 0.0 || best.is_some_and(|(t, _)| t <= t0) {
            continue;
        }
        let mut n = DVec3::ZERO;
        n[k] = -d[k].signum();
        best = Some((t0, if b.is_rotated() { rot * n } else { n }));
    }
    best
}

/// Whether the world point `q` lies in the (possibly rotated) box `b`, boundary included.
pub(crate) fn box_contains(b: &SceneBox, q: DVec3) -> bool {
    let l = if b.is_rotated() {
        let c = b.centre();
        c + b.rotation().inverse() * (q - c)
    } else {
        q
    };
    (0..3).all(|k| l[k] >= b.min[k] && l[k] <= b.max[k])
}

/// `RENDER_CHECK_DEBUG`: where a compared pixel's shadow disagrees, the texel-centre ray's
/// points and the boxes the exact ray casts meet.
#[allow(clippy::too_many_arguments)] // one pixel and its frame, each needed once
pub(crate) fn debug_pixel(
    scene: &Scene,
    view: &View,
    built: &Built,
    res: u32,
    p: DVec3,
    n: DVec3,
    part: usize,
) {
    let to_world = view.world_to_eye.inverse();
    let (pw, nw) = (to_world.transform_point3(p), to_world.transform_vector3(n));
    let wc = built.maps[part].gpu * view.world_to_eye;
    let inv = wc.inverse();
    let h = wc * pw.extend(1.0);
    let r = f64::from(res);
    let (s, t, d) = (
        (h.x / h.w + 1.0) * 0.5 * r,
        (h.y / h.w + 1.0) * 0.5 * r,
        h.z / h.w,
    );
    let (x, y) = (
        2.0 * (s.floor() + 0.5) / r - 1.0,
        2.0 * (t.floor() + 0.5) / r - 1.0,
    );
    let q0 = inv.project_point3(DVec3::new(x, y, 0.0));
    let dd = inv.project_point3(DVec3::new(x, y, 1.0)) - q0;
    let qc = q0 + dd * ((pw - q0).dot(nw) / dd.dot(nw));
    let rc = inv.project_point3(DVec3::new(x, y, d));
    let hits = |x: DVec3| -> Vec<usize> {
        (0..scene.boxes.len())
            .filter(|&k| {
                let mut one = scene.clone();
                one.boxes = vec![scene.boxes[k]];
                ray_occluded(&one, x, DVec3::ZERO, view.light_world)
            })
            .collect()
    };
    eprintln!(
        "    world {pw:.4} map ({s:.3}, {t:.3}) depth {d:.6}; on the plane {qc:.4} hits boxes {:?}; \
         at its depth {rc:.4} hits {:?}; the pixel's ray hits {:?}",
        hits(qc),
        hits(rc),
        hits(pw + nw * 1e-5),
    );
}
