//! The scripted walk the controller's tests play (tests/controller.rs, tests/controller_each.rs):
//! a ground with four boxes, a camera walking along it, the allowed schemes.

use glam::{DMat4, DVec3};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{Aabb, Bound, Camera, CascadeSplits, FrameInput, FrameScheme};
use shadow_aliasing::maps::WarpRule;

/// The image's height, pixels.
pub const H: u32 = 1080;
/// The walk's frames.
pub const FRAMES: usize = 240;

/// A ground 120 × 460 with four boxes on it.
pub fn scene() -> Vec<Aabb> {
    vec![
        Aabb::new([-60.0, -1.0, -400.0], [60.0, 0.0, 60.0]).unwrap(),
        Aabb::new([-8.0, 0.0, -40.0], [-2.0, 6.0, -30.0]).unwrap(),
        Aabb::new([4.0, 0.0, -90.0], [12.0, 15.0, -80.0]).unwrap(),
        Aabb::new([-20.0, 0.0, -170.0], [-5.0, 4.0, -150.0]).unwrap(),
        Aabb::new([0.0, 0.0, -260.0], [30.0, 25.0, -240.0]).unwrap(),
    ]
}

/// Frame `i` of the walk: forward 1.25 units a frame along −z, the eye rising from 1.7 to 9.7
/// and back, the view swinging ±30° and looking 10° down.
pub fn camera(i: usize) -> Camera {
    shifted(i, 0.0)
}

/// Frame `i`'s camera moved `dz` along z.
pub fn shifted(i: usize, dz: f64) -> Camera {
    let t = i as f64 / FRAMES as f64;
    let eye = DVec3::new(
        0.0,
        1.7 + 8.0 * (std::f64::consts::PI * t).sin(),
        40.0 - 300.0 * t + dz,
    );
    let yaw = 30f64.to_radians() * (2.0 * std::f64::consts::PI * t).sin();
    let pitch = -10f64.to_radians();
    let dir = DVec3::new(
        -yaw.sin() * pitch.cos(),
        pitch.sin(),
        -yaw.cos() * pitch.cos(),
    );
    // Eye → world: x right, y up, −z along the view, then its inverse.
    let right = dir.cross(DVec3::Y).normalize();
    let up = right.cross(dir);
    let view = DMat4::from_cols(
        right.extend(0.0),
        up.extend(0.0),
        (-dir).extend(0.0),
        eye.extend(1.0),
    )
    .inverse();
    Camera::new(view, 0.5, 200.0, 30f64.to_radians(), 16.0 / 9.0).unwrap()
}

pub fn input(cam: Camera, boxes: &[Aabb]) -> FrameInput<'_> {
    FrameInput::new(cam, DVec3::new(0.3, -0.8, -0.4), 2048, H)
        .receivers(Bound::Boxes(&boxes[..1]))
        .casters(Bound::Boxes(boxes))
}

/// The allowed schemes: orthographic and LiSPSM single maps, practical cascades of 2 to 4,
/// stable logarithmic cascades of 2 to 4.
pub fn allowed() -> Vec<FrameScheme<'static>> {
    let mut c = vec![
        FrameScheme::Single(WarpRule::Uniform),
        FrameScheme::Single(WarpRule::Lispsm),
    ];
    for k in 2..=4 {
        c.push(FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.5 },
                k,
                overlap: 0.0,
            },
            rule: WarpRule::Uniform,
        });
        c.push(FrameScheme::Stable(CascadeSplits::Scheme {
            scheme: SplitScheme::SelfSimilar,
            k,
            overlap: 0.0,
        }));
    }
    c
}
