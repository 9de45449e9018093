//! The lift of the GPU's lookup point over the need ([`super::PathSummary::lift_over_need`],
//! [`super::PathSummary::offset_rel_diff`]): the offset the camera pass wrote, applied to the
//! pixel's point in `f64`, against the need render-check derives from the map's matrix and the
//! pixel's plane.

use super::{need, record_offset, Exact, MapModel, Path, PathSummary};

/// The lift of the lookup point p + `o` n over the plane of `e` (depth [0, 1]: the plane's depth
/// at the point's map position less the point's own), from the map's matrix in `f64`.
fn lift_at(m: &MapModel, res: f64, e: &Exact, o: f64) -> Option<f64> {
    let (h, s, t) = m.texel(res, e.p + e.n * o);
    let lift = e.plane.at(s, t) - h.z / h.w;
    (h.w > 0.0 && lift.is_finite()).then_some(lift)
}

/// The normal offset that lifts the lookup point of `e` by exactly `need` (depth [0, 1]), and
/// the relative change of the map's w from p to that point; `None` where no offset does. Along
/// the normal every clip coordinate is affine in o and the plane's depth is affine in the map
/// position, so the lift is `B o / (w(p) + o (row₃ · n))` (0 at o = 0): B is taken from the lift
/// at one probe offset, and the need solved for.
fn offset_for_need(m: &MapModel, res: f64, e: &Exact, need: f64) -> Option<(f64, f64)> {
    let wp = (m.wc * e.p.extend(1.0)).w;
    let wn = (m.wc * e.n.extend(0.0)).w;
    // A probe that changes w by at most 10⁻³ of w(p), and at most one world unit.
    let probe = if wn != 0.0 {
        (1e-3 * wp / wn.abs()).min(1.0)
    } else {
        1.0
    };
    let b = lift_at(m, res, e, probe)? * (wp + probe * wn) / probe;
    let den = b - need * wn;
    if !(wp > 0.0 && b > 0.0 && den > 0.0) {
        return None;
    }
    let o = need * wp / den;
    let wq = wp + o * wn;
    (o.is_finite() && wq > 0.0).then_some((o, (wq - wp).abs() / wq))
}

/// Measures the lift of the GPU's lookup point of `e` (offset `o`, world units, as the camera
/// pass wrote it) over the need into `sum`.
pub(super) fn offset_lift(
    sum: &mut PathSummary,
    m: &MapModel,
    res: f64,
    e: &Exact,
    path: &Path,
    o: f64,
) {
    let n = need(path.radius, e.plane.slope());
    let expected = if path.local() {
        match offset_for_need(m, res, e, n) {
            Some((o_need, change)) => {
                sum.max_w_change = Some(sum.max_w_change.map_or(change, |c| c.max(change)));
                o_need
            }
            None => {
                sum.offset_unreachable += 1;
                return;
            }
        }
    } else {
        record_offset(&m.record, path.radius)
    };
    // The record's +∞ (no offset certified) arrives as the shader's 1e30 factor: both so is
    // no lift to measure, one alone a difference of +∞.
    let none = |x: f64| !(x.is_finite() && (0.0..1e29).contains(&x));
    let diff = match (none(o), none(expected)) {
        (true, true) => return,
        (false, false) => (o - expected).abs() / expected,
        _ => f64::INFINITY,
    };
    sum.offset_rel_diff = Some(sum.offset_rel_diff.map_or(diff, |d| d.max(diff)));
    if diff.is_infinite() {
        return;
    }
    let Some(lift) = lift_at(m, res, e, o) else {
        return;
    };
    let ratio = lift / n;
    sum.offset_lookups += 1;
    sum.lift_over_need = Some(match sum.lift_over_need {
        Some([lo, hi]) => [lo.min(ratio), hi.max(ratio)],
        None => [ratio, ratio],
    });
}

#[cfg(test)]
mod tests {
    use super::super::{need, Exact, MapModel, Plane};
    use super::{lift_at, offset_for_need};
    use glam::{DMat4, DVec3, DVec4};
    use shadow_aliasing::frame::GpuShadowMap;

    const RES: f64 = 1024.0;

    fn model(wc: DMat4) -> MapModel {
        MapModel {
            wc,
            inv: wc.inverse(),
            record: GpuShadowMap::default(),
            reversed: false,
        }
    }

    fn exact(m: &MapModel, p: DVec3, n: DVec3) -> Exact {
        Exact {
            p,
            n,
            id: 1,
            own: None,
            shadowed: false,
            part: 0,
            plane: Plane::new(m, RES, p, n).unwrap(),
        }
    }

    /// An orthographic map of light travelling along −y over x, z ∈ [−10, 10], depth
    /// (10 − y)/20, and the plane through p with normal (sin a, cos a, 0): on the plane the
    /// depth rises by 0.05 tan a per unit of x, tan a / res per texel of s, and p + o n lies
    /// o (sin² a / cos a + cos a) = o / cos a above the plane along the light, 0.05 o / cos a of
    /// depth. By hand, the offset for the need N is 20 N cos a, and w does not change.
    #[test]
    fn orthographic_offset_by_hand() {
        let wc = DMat4::from_cols(
            DVec4::new(0.1, 0.0, 0.0, 0.0),
            DVec4::new(0.0, 0.0, -0.05, 0.0),
            DVec4::new(0.0, 0.1, 0.0, 0.0),
            DVec4::new(0.0, 0.0, 0.5, 1.0),
        );
        let m = model(wc);
        let a: f64 = 0.3;
        let e = exact(
            &m,
            DVec3::new(1.0, 2.0, 3.0),
            DVec3::new(a.sin(), a.cos(), 0.0),
        );
        assert!((e.plane.slope() - a.tan() / RES).abs() < 1e-12 * a.tan() / RES);
        let n = need(0, e.plane.slope());
        assert!(
            (n - ((0.5 + 1.0 / 64.0) * a.tan() / RES + 8.0 * f64::from(f32::EPSILON))).abs()
                < 1e-15
        );
        let (o, change) = offset_for_need(&m, RES, &e, n).unwrap();
        assert!((o - 20.0 * n * a.cos()).abs() < 1e-9 * o, "{o}");
        assert_eq!(change, 0.0);
        let lift = lift_at(&m, RES, &e, 2.5).unwrap();
        assert!((lift - 0.05 * 2.5 / a.cos()).abs() < 1e-12, "{lift}");
    }

    /// The same map made projective (w = 1 + 0.04 x): the offset solved from one probe lifts the
    /// point by the need when evaluated directly, and moves w by what 0.04 o sin a over w(q) says.
    #[test]
    fn projective_offset_lifts_by_the_need() {
        let wc = DMat4::from_cols(
            DVec4::new(0.1, 0.0, 0.0, 0.04),
            DVec4::new(0.0, 0.0, -0.05, 0.0),
            DVec4::new(0.0, 0.1, 0.0, 0.0),
            DVec4::new(0.0, 0.0, 0.5, 1.0),
        );
        let m = model(wc);
        let a: f64 = 0.7;
        let p = DVec3::new(1.0, 2.0, 3.0);
        let e = exact(&m, p, DVec3::new(a.sin(), a.cos(), 0.0));
        let n = need(1, e.plane.slope());
        let (o, change) = offset_for_need(&m, RES, &e, n).unwrap();
        let lift = lift_at(&m, RES, &e, o).unwrap();
        assert!((lift - n).abs() < 1e-9 * n, "{lift} {n}");
        let (wp, wq) = (1.0 + 0.04 * p.x, 1.0 + 0.04 * (p.x + o * a.sin()));
        assert!((change - (wq - wp) / wq).abs() < 1e-12, "{change}");
        assert!(change > 0.0);
    }
}
