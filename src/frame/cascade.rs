//! Cascades: the slices of the visible depth range (the crate's split schemes, distances,
//! fractions, Bevy's splits) and the stable cascade of a slice.

use super::body::depth_extent;
use super::body::Body;
use super::equal_error::SliceMap;
use super::input::CascadeSplits;
use super::output::{Focus, FrameMap};
use super::{Built, Ctx, Slice, MAX_BODY_VERTICES};
use crate::analytic::partition::{z_splits, Splits, MAX_PARTITIONS};
use crate::error::{fmt_num, in_closed, positive, Error, Result};
use crate::frustum::{LightDir, NPrime};
use crate::maps::cascades::{bounding_sphere, splits_between};
use crate::maps::fit::{verify_clip, FrustumInLight};
use crate::maps::lightspace::{light_space_unit, LightSpace};
use crate::maps::ShadowMatrix;
use glam::{DMat4, DVec3, DVec4};

fn overlap_ok(o: f64) -> Result<f64> {
    let o = in_closed("overlap", o, 0.0, 1.0)?;
    if o >= 1.0 {
        return Err(Error::invalid("overlap", "must be smaller than 1 (got 1)"));
    }
    Ok(o)
}

impl Ctx<'_, '_> {
    /// The cascades' slices over the visible range `[zn, zf]`, each mapped as `how` (which the
    /// equal-error splits measure); returns k.
    pub(super) fn cascade_slices(
        &self,
        splits: CascadeSplits<'_>,
        how: SliceMap,
        zn: f64,
        zf: f64,
        out: &mut [Slice; MAX_PARTITIONS],
    ) -> Result<usize> {
        match splits {
            CascadeSplits::EqualError { k } => self.equal_error_slices(k, how, zn, zf, out),
            s => cascade_slices(s, zn, zf, out),
        }
    }
}

/// The slices of the splits that do not depend on the maps (every [`CascadeSplits`] but
/// `EqualError`, which [`Ctx::cascade_slices`] places); returns k.
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
                    res: 0, // each slot's, set by the frame
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
                    res: 0, // each slot's, set by the frame
                };
                n += 1;
            }
            if n == 0 {
                return Err(Error::invalid(
                    "minimum_distance",
                    format!(
                        "and maximum_distance must overlap the visible depth range [{}, {}] \
                         (got minimum_distance={}, maximum_distance={}: every Bevy cascade \
                         would lie outside it)",
                        fmt_num(zn),
                        fmt_num(zf),
                        fmt_num(min_d),
                        fmt_num(max_d)
                    ),
                ));
            }
            Ok(n)
        }
        // Placed by measuring the maps (`Ctx::cascade_slices`), never here.
        CascadeSplits::EqualError { .. } => Err(Error::invalid(
            "splits",
            "EqualError is placed by the frame's measured errors, not by depth alone",
        )),
    }
}

impl Ctx<'_, '_> {
    /// A stable cascade with its depth range from B and the casters.
    pub(super) fn stable_map(&self, s: &Slice, dst: &mut Option<FrameMap>) -> Result<Built> {
        let body = self.body(s.cover.0, s.cover.1, &[])?;
        if body.focus == Focus::Empty || body.n == 0 {
            return Ok(Built::None(Focus::Empty));
        }
        let res = f64::from(s.res);
        let (c, r) = bounding_sphere(self.view, s.cover.0, s.cover.1)?;
        let half = r * res / (res - 2.0);
        let texel = 2.0 * half / res;
        let cw = self
            .input
            .camera
            .eye_to_world
            .transform_point3(DVec3::new(0.0, 0.0, -c));
        self.square_map(s, &body, (cw, half, texel), dst)
    }

    /// The map of `body` (the slice `s`'s B, not empty) on the square of half-width `half` of
    /// the world-fixed light space (y toward the light, z the world −Z projected), centred on
    /// the world point `centre`'s light-space x, z snapped to whole multiples of `snap`; its depth
    /// range from B and the casters, snapped to whole texels. Stable cascades snap to a texel,
    /// clipmap levels to a page (`frame/clipmap.rs`).
    pub(super) fn square_map(
        &self,
        s: &Slice,
        body: &Body,
        (centre, half, snap): (DVec3, f64, f64),
        dst: &mut Option<FrameMap>,
    ) -> Result<Built> {
        let pts = &body.v[..body.n];
        let cam = &self.input.camera;
        let res = f64::from(s.res);
        // World-fixed light space (y toward the light, z the world −Z projected).
        let ls_w = light_space_unit(LightDir::from_unit_unchecked(self.lw), DVec3::NEG_Z);
        let texel = 2.0 * half / res;
        let q = ls_w.to_light(centre);
        let sx = (q.x / snap).round() * snap;
        let sz = (q.z / snap).round() * snap;
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
        // Past B's vertices `fl.q` repeats the first: only the vertices are read.
        for q in &fl.q[..body.n] {
            ylo = ylo.min(q.y);
            yhi = yhi.max(q.y);
        }
        if let Some(p) = self.caster_extreme(&fl, body.n, |_| 1.0, 0.0, &mut None)? {
            yhi = yhi.max(ls_e.y.dot(p));
        }
        // The depth range in world light y, snapped outward to whole texels of a world-fixed grid
        // offset by half a texel (round scene coordinates, a ground at y = 0, lie inside a cell,
        // not on its edge): a camera move that keeps B's and the casters' extent within the same
        // cells keeps the whole matrix bit for bit, as the snapped square keeps s, t
        // (`FrameMap::unchanged`). It widens the range by at most a texel at each end.
        let y_off = ls_w.y.dot(cam.eye_to_world.w_axis.truncate());
        let lo = (((ylo + y_off) / texel + 0.5).floor() - 0.5) * texel;
        let hi = (((yhi + y_off) / texel - 0.5).ceil() + 0.5) * texel;
        let v_m = 0.5 * (lo + hi);
        let v_h = (0.5 * (hi - lo)).max(1e-9 * self.scale());
        // s, t as `stable_cascade`: world light space, the snapped centre, half-width `half`.
        let ortho = DMat4::from_cols(
            DVec4::new(1.0 / half, 0.0, 0.0, 0.0),
            DVec4::new(0.0, 0.0, 0.0, 0.0),
            DVec4::new(0.0, 1.0 / half, 0.0, 0.0),
            DVec4::new(-sx / half, -sz / half, 0.0, 1.0),
        );
        // World → clip from world-fixed quantities only; depth −1 nearest the light.
        let mut w = (ortho * ls_w.rotation()).transpose();
        w.z_axis = (-ls_w.y / v_h).extend(v_m / v_h);
        let world = w.transpose();
        let matrix = world * cam.eye_to_world;
        // The world-fixed square is built from world positions: far from the world origin (or
        // near f64's range) their rounding, amplified by 1/half, can leave B outside the map.
        if !matrix.is_finite() {
            return Err(Error::Degenerate(
                "the world-fixed map's matrix (stable cascade or clipmap level) overflows f64 for this frustum".into(),
            ));
        }
        if let Err(f) = verify_clip(&matrix, pts.iter()) {
            // World positions round by about |p| ε; amplified by 1/half they move B's vertices
            // in the map by that over the clip slack (10⁻⁶) when the camera is far from the
            // origin: then the offset, not the depth ratio, is the cause.
            let dist = centre.length();
            return Err(if dist * f64::EPSILON / half > 1e-8 {
                stable_far_from_origin(dist, half)
            } else {
                f.into()
            });
        }
        let shadow = ShadowMatrix::new(
            matrix,
            LightDir::from_unit_unchecked(self.l),
            NPrime::UNWARPED,
            depth_extent(pts).0,
            depth_extent(pts).1,
        );
        // The world-fixed light space is not the casters' volume's.
        self.finish(shadow, pts, s, body.focus, None, dst)?
            .world_to_clip = world;
        Ok(Built::Map)
    }
}

/// A world-fixed square (a stable cascade or a clipmap level) that cannot hold its focus body
/// because the camera is far from the world origin (world positions round by |p| ε there).
#[cold]
#[inline(never)]
fn stable_far_from_origin(dist: f64, half: f64) -> Error {
    Error::Degenerate(format!(
        "a stable cascade or clipmap level of half-width {} lies {} from the world origin, where f64 rounds world \
         positions by about {:.1e} ({:.0e} of the half-width), too coarse to snap its world-fixed \
         square and keep the focus body inside it: move the world origin near the camera \
         (render relative to the camera or rebase the scene), or use cascades that are not \
         stable (FrameScheme::Cascades)",
        fmt_num(half),
        fmt_num(dist),
        dist * f64::EPSILON,
        dist * f64::EPSILON / half
    ))
}
