//! The face partitions' Σ S̄ with a chosen side-face axis (tests/faces.rs and tests/errata.rs).

use glam::DVec3;
use shadow_aliasing::maps::faces::{face_partitions, visible_faces, Face, FaceWarp};
use shadow_aliasing::ViewFrustum;

/// Σ S̄ of face partitions (k = 1, LiSPSM n′ per face) with each side face's warp axis either the
/// angle bisector ê′₀ + ê′₁ (the crate) or the printed e′₀ + e′₁ of the projected far-corner
/// vectors. `None` when the axis leaves a face vertex at or behind the projected eye (d_n ≤ 0), so
/// that no warp centred on the eye can be fitted.
pub fn faces_with_axis(view: &ViewFrustum, l: DVec3, unit: bool) -> Option<f64> {
    let mut total = 0.0;
    for &f in visible_faces(view, l).unwrap().faces() {
        let Some(_) = f.side_edges(view) else {
            let parts = face_partitions(view, l, FaceWarp::Lispsm, 1).unwrap();
            total += parts
                .iter()
                .find(|p| p.face == Face::Near)
                .unwrap()
                .storage_factor();
            continue;
        };
        total += side_face_with_axis(view, l, f, unit)?;
    }
    Some(total)
}

/// S̄ of side face `f`'s map (k = 1, LiSPSM n′ from its extent) with the warp axis of
/// [`faces_with_axis`], whether or not the crate's `visible_faces` keeps the face (it skips one
/// within `EDGE_ON` of edge-on). `None` when the axis leaves a vertex at or behind the projected
/// eye.
pub fn side_face_with_axis(view: &ViewFrustum, l: DVec3, f: Face, unit: bool) -> Option<f64> {
    use shadow_aliasing::maps::{fit_warp, light_space};
    use shadow_aliasing::measure::vertex::vertex_max;
    use shadow_aliasing::NPrime;
    let v = f.vertices(view, view.near(), view.far());
    // The vectors from the viewpoint through the side edges, to the far plane.
    let (e0, e1) = (v[3], v[2]);
    let p0 = e0 - e0.dot(l) * l;
    let p1 = e1 - e1.dot(l) * l;
    let axis = if unit {
        p0.normalize() + p1.normalize()
    } else {
        p0 + p1
    };
    let ls = light_space(l, axis).unwrap();
    let (mut dn, mut df) = (f64::INFINITY, f64::NEG_INFINITY);
    for q in v {
        dn = dn.min(ls.z.dot(q));
        df = df.max(ls.z.dot(q));
    }
    if dn <= 0.0 {
        return None;
    }
    let mut pts = v.to_vec();
    for q in v {
        pts.push(q + 3.0 * view.far() * l);
        pts.push(q - 3.0 * view.far() * l);
    }
    let m = fit_warp(&pts, &ls, NPrime::finite(dn + (dn * df).sqrt()).unwrap()).unwrap();
    Some(
        vertex_max(&m, l, view.tan_half_fov(), &v)
            .unwrap()
            .storage_factor,
    )
}
