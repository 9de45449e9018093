//! The scene's receivers and casters as the crate's world boxes, gathered once per frame from
//! every visible mesh's `Aabb` and `GlobalTransform`.

use crate::convert::vec3a_to_crate;
use bevy::camera::primitives::Aabb;
use bevy::camera::visibility::InheritedVisibility;
use bevy::light::{NotShadowCaster, NotShadowReceiver};
use bevy::mesh::Mesh3d;
use bevy::prelude::*;
use shadow_aliasing::frame::Aabb as WorldBox;

/// The world-space boxes of the frame's shadow receivers and casters (meshes with an `Aabb`,
/// visible in the hierarchy; `NotShadowReceiver` leaves a mesh out of the receivers,
/// `NotShadowCaster` out of the casters). Written by [`collect_scene_bounds`] each frame.
#[derive(Resource, Debug, Default, Clone)]
pub struct SceneBounds {
    /// Boxes of the meshes that receive shadows.
    pub receivers: Vec<WorldBox>,
    /// Boxes of the meshes that cast shadows.
    pub casters: Vec<WorldBox>,
}

/// The world box of a local `Aabb` under `transform`: the centre transformed, the half extents
/// through the absolute value of the linear part (the tightest axis-aligned box of the
/// transformed box). `None` for a non-finite box.
#[must_use]
pub fn world_box(aabb: &Aabb, transform: &GlobalTransform) -> Option<WorldBox> {
    let a = transform.affine();
    let c = a.transform_point3a(aabb.center);
    let h = aabb.half_extents;
    let m = a.matrix3;
    let e = m.x_axis.abs() * h.x + m.y_axis.abs() * h.y + m.z_axis.abs() * h.z;
    WorldBox::new(vec3a_to_crate(c - e), vec3a_to_crate(c + e)).ok()
}

type MeshBounds<'a> = (
    &'a Aabb,
    &'a GlobalTransform,
    Option<&'a InheritedVisibility>,
    Has<NotShadowReceiver>,
    Has<NotShadowCaster>,
);

/// Gathers [`SceneBounds`] from the meshes (runs in `PostUpdate` after Bevy computed the
/// `Aabb`s and propagated the transforms: see the crate docs for the order).
pub fn collect_scene_bounds(
    meshes: Query<MeshBounds<'_>, With<Mesh3d>>,
    mut bounds: ResMut<SceneBounds>,
) {
    let b = bounds.as_mut();
    b.receivers.clear();
    b.casters.clear();
    for (aabb, transform, visible, not_receiver, not_caster) in &meshes {
        if visible.is_some_and(|v| !v.get()) {
            continue;
        }
        let Some(w) = world_box(aabb, transform) else {
            continue;
        };
        if !not_receiver {
            b.receivers.push(w);
        }
        if !not_caster {
            b.casters.push(w);
        }
    }
}
