//! The culling volumes each map hands out, measured against render-check's rebuilt focus body B
//! ([`crate::geometry`], docs/rendered.md, "What is measured", 13), reading only the volumes'
//! planes, the map's matrix and the light:
//!
//! - **The receivers' volume** ([`volume_distance`]): `FrameMap::receivers_volume` against B
//!   itself, both ways.
//! - **The casters' volume** ([`casters_volume_distance`]): `FrameMap::casters_volume` against
//!   B swept toward the light and cut by the map's depth range (the crate's docs/renderer.md,
//!   "Culling per map"), rebuilt here from B's planes and vertices, the light's direction and
//!   the depth planes of the map's matrix, both ways: every vertex of the swept volume inside
//!   the crate's by the documented push-out ([`PUSH_OUT`]), and every vertex of the crate's
//!   volume, less the push-out, inside the swept volume ([`sweep_excess`]).

use crate::geometry::{side, vertices, MISSING};
use glam::{DMat4, DVec3, DVec4};

/// A half-space `n · p + d ≤ 0` (eye space).
type Plane = DVec4;

/// A culling volume `volume` against the polytope `planes` with vertices `body`, over `size`:
/// the larger of the farthest vertex outside the volume (a volume that cuts B) and, for each
/// facet of the polytope (a plane holding three of its vertices or more), the distance from the
/// facet's centroid along its outward normal to where the ray leaves the volume (a volume
/// without that face, or looser than it). [`MISSING`] for an empty body or volume.
pub fn volume_distance(volume: &[Plane], body: &[DVec3], planes: &[Plane], size: f64) -> f64 {
    if body.is_empty() || volume.is_empty() {
        return MISSING;
    }
    let cut = body
        .iter()
        .flat_map(|&p| volume.iter().map(move |&pl| side(pl, p)))
        .fold(0.0f64, f64::max);
    let tol = 1e-9 * size;
    let mut loose = 0.0f64;
    for &pl in planes {
        let on: Vec<DVec3> = body
            .iter()
            .copied()
            .filter(|&p| side(pl, p).abs() <= tol)
            .collect();
        if on.len() < 3 {
            continue;
        }
        let c = on.iter().copied().sum::<DVec3>() / on.len() as f64;
        let n = pl.truncate().normalize();
        // The ray c + λ n leaves the half-space of a volume plane q (q·n > 0) at
        // λ = −side(q, c) / (q·n); it leaves the volume at the least such λ.
        let exit = volume
            .iter()
            .filter(|q| q.truncate().dot(n) > 1e-12)
            .map(|&q| -side(q, c) / q.truncate().dot(n))
            .fold(f64::INFINITY, f64::min);
        loose = loose.max(exit.max(0.0));
    }
    let d = cut.max(loose) / size;
    if d.is_finite() {
        d
    } else {
        MISSING
    }
}

/// How far the crate pushes each culling plane outward, in units of the camera frustum's size
/// far · (1 + tan θ (1 + aspect)) (the crate's docs/renderer.md, "Culling per map": "each is
/// pushed out by 10⁻⁹ of the frustum's size").
pub const PUSH_OUT: f64 = 1e-9;

/// How far the point `p` lies outside the body `planes` (unit normals) swept toward the light,
/// `l` the direction the light travels: p is in the sweep iff some t ≥ 0 puts p + t l in the
/// body. The least over t ≥ 0 of the largest `side` of p + t l over the planes (each `side` is
/// affine in t, so their maximum is convex and piecewise linear, least at t = 0 or where two of
/// them cross): ≤ 0 inside (then minus the depth of the best point of the ray inside the
/// body's nearest plane), > 0 outside (a lower bound of the distance from the sweep along that
/// ray). −∞ for no planes (the whole space).
pub fn sweep_excess(planes: &[Plane], l: DVec3, p: DVec3) -> f64 {
    let lines: Vec<(f64, f64)> = planes
        .iter()
        .map(|&pl| (side(pl, p), pl.truncate().dot(l)))
        .collect();
    let at = |t: f64| {
        lines
            .iter()
            .map(|&(a, b)| a + b * t)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let mut best = at(0.0);
    for (i, &(a0, b0)) in lines.iter().enumerate() {
        for &(a1, b1) in &lines[i + 1..] {
            // The two sides cross at t = (a1 − a0) / (b0 − b1); only a rising one against a
            // falling one can hold the least maximum.
            if (b0 > 0.0) == (b1 > 0.0) {
                continue;
            }
            let t = (a1 - a0) / (b0 - b1);
            if t > 0.0 && t.is_finite() {
                best = best.min(at(t));
            }
        }
    }
    best
}

/// `FrameMap::casters_volume` `volume` (eye space) against the body with vertices `body` and
/// planes `planes` swept toward the light (`l`, the direction the light travels) and cut by the
/// depth range of the map `clip` (eye → light clip, OpenGL depth: |z| ≤ w; no near plane when
/// `depth_clamp`), over `size` (the camera frustum's), the larger of:
///
/// - **too tight**: the swept volume's vertices (B's vertices in the depth range, and each moved
///   toward the light onto the near depth plane) against the volume's planes, each by how much
///   less than the documented push-out (`PUSH_OUT · size`) it lies inside;
/// - **too loose**: the vertices of the volume with the push-out taken back (every triple of its
///   planes, kept where inside all), each by how far it lies outside the sweep ([`sweep_excess`])
///   or the depth range.
///
/// Where no near plane faces the light (depth clamp) both volumes are capped by one plane facing
/// the light 10 sizes past B, and the crate's is closed by a box 1 size around the swept volume's
/// vertices, so that a volume unbounded sideways shows as a vertex on the box. 0 for a volume
/// equal to the sweep pushed out as documented; [`MISSING`] for an empty body or volume.
pub fn casters_volume_distance(
    volume: &[Plane],
    (body, planes): (&[DVec3], &[Plane]),
    l: DVec3,
    (clip, depth_clamp): (&DMat4, bool),
    size: f64,
) -> f64 {
    if body.is_empty() || volume.is_empty() {
        return MISSING;
    }
    let unit = |p: Plane| p / p.truncate().length();
    let (r2, r3) = (clip.row(2), clip.row(3));
    let near = unit(-(r2 + r3));
    let mut depth = vec![unit(r2 - r3)];
    if !depth_clamp {
        depth.push(near);
    }
    let tol = 1e-2 * PUSH_OUT * size;
    // Toward the light: onto the near depth plane where it faces the light, else onto the cap.
    let reach = body
        .iter()
        .map(|v| -l.dot(*v))
        .fold(f64::NEG_INFINITY, f64::max);
    let cap = (-l).extend(-(reach + 10.0 * size));
    let stop = if depth_clamp || near.truncate().dot(l) >= 0.0 {
        cap
    } else {
        near
    };
    let in_range = body
        .iter()
        .copied()
        .filter(|&v| depth.iter().all(|&d| side(d, v) <= tol));
    let mut sweep: Vec<DVec3> = Vec::new();
    for v in in_range {
        // side(stop, v − t l) = side(stop, v) − t (n · l) = 0.
        let t = side(stop, v) / stop.truncate().dot(l);
        sweep.extend([v, v - t * l]);
    }
    let push = PUSH_OUT * size;
    let tight = sweep
        .iter()
        .flat_map(|&p| volume.iter().map(move |&pl| side(pl, p) + push))
        .fold(0.0f64, f64::max);
    // The crate's volume less its push-out, capped and boxed like the sweep.
    let mut crate_planes: Vec<Plane> = volume.iter().map(|&pl| pl + DVec4::W * push).collect();
    if stop == cap {
        crate_planes.push(cap);
    }
    let (lo, hi) = sweep.iter().fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(lo, hi), &p| (lo.min(p), hi.max(p)),
    );
    for axis in [DVec3::X, DVec3::Y, DVec3::Z] {
        crate_planes.push(axis.extend(-(axis.dot(hi) + size)));
        crate_planes.push((-axis).extend(axis.dot(lo) - size));
    }
    let loose = vertices(&crate_planes, tol)
        .into_iter()
        .map(|p| {
            depth
                .iter()
                .map(|&d| side(d, p))
                .fold(sweep_excess(planes, l, p), f64::max)
        })
        .fold(0.0f64, f64::max);
    let d = tight.max(loose) / size;
    if d.is_finite() && !sweep.is_empty() {
        d
    } else {
        MISSING
    }
}
