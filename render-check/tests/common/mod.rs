//! The scene the kernel tests share: a ground box 120 wide seen from 6 above it, looking down and
//! ahead (near 0.5, far 120, half field of view 0.6, aspect 1.5), with the ground as receivers
//! and casters.

#![allow(dead_code)] // each test binary uses what it needs

use glam::{DMat4, DVec3};
use shadow_aliasing::frame::{Aabb, Bound, Camera, FrameInput};

/// The ground box: [−60, 60] × [−1, 0] × [−60, 60].
pub fn ground() -> [Aabb; 1] {
    [Aabb::new([-60.0, -1.0, -60.0], [60.0, 0.0, 60.0]).unwrap()]
}

/// The camera's world → eye matrix: at (0, 6, 20), looking at (2, 0, −10).
pub fn view() -> DMat4 {
    glam::dcamera::rh::view::look_at_mat4(
        DVec3::new(0.0, 6.0, 20.0),
        DVec3::new(2.0, 0.0, -10.0),
        DVec3::Y,
    )
}

/// The frame input of the scene for `light` and `res`-texel maps (the default scheme), 720 rows
/// on screen, the ground as receivers and casters.
pub fn input(ground: &[Aabb], light: DVec3, res: u32) -> FrameInput<'_> {
    let camera = Camera::new(view(), 0.5, 120.0, 0.6, 1.5).unwrap();
    FrameInput::new(camera, light, res, 720)
        .receivers(Bound::Boxes(ground))
        .casters(Bound::Boxes(ground))
}
