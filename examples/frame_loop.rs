//! A renderer's frame loop with the scene-aware frame API: camera, light and scene bounds in,
//! this frame's shadow maps out (world → light clip as `Mat4`, split depths, blend bands, texel
//! sizes), with the aliasing error of what was built.
//!
//! Conventions: world and eye space right-handed, the camera's view matrix maps world → eye with
//! the camera looking down −Z (glam `dcamera::rh::view::look_at_mat4`); the light direction is the
//! direction light travels, in world space. docs/renderer.md explains each output.
//!
//! Run with `cargo run --example frame_loop`.

use glam::{DVec3, Mat4};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame_into, Aabb, Bound, Camera, CascadeSplits, Frame, FrameInput, FrameScheme,
};
use shadow_aliasing::maps::{ClipDepth, WarpRule};
use shadow_aliasing::Result;

/// What a renderer uploads for one cascade this frame.
struct Upload {
    world_to_light: Mat4,
    split: (f32, f32),
    blend: (f32, f32),
    normal_bias: f32,
}

fn main() -> Result<()> {
    // The sun's light travels down and slightly sideways.
    let sun = DVec3::new(0.3, -1.0, 0.2);
    // The scene: a ground 200 units across and a tower on it (world space).
    let ground = Aabb::new(
        DVec3::new(-100.0, -1.0, -100.0),
        DVec3::new(100.0, 0.0, 100.0),
    )?;
    let tower = Aabb::new(DVec3::new(-5.0, 0.0, -5.0), DVec3::new(5.0, 40.0, 5.0))?;
    let receivers = [ground, tower];
    let casters = [ground, tower];
    // Both reused every frame: after the first, no heap allocation per frame (the frame API
    // allocates nothing; the upload list keeps its capacity).
    let mut out = Frame::default();
    let mut uploads: Vec<Upload> = Vec::with_capacity(4);
    for n in 0..8 {
        // The camera orbits the tower 60 units away, 5 up; far plane 1000 (far beyond the scene).
        let a = f64::from(n) * std::f64::consts::TAU / 8.0;
        let eye = DVec3::new(60.0 * a.cos(), 5.0, 60.0 * a.sin());
        let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(0.0, 5.0, 0.0), DVec3::Y);
        let camera = Camera::new(view, 0.5, 1000.0, 30f64.to_radians(), 16.0 / 9.0)?;
        let input = FrameInput::new(camera, sun, 2048, 1080)
            .receivers(Bound::Boxes(&receivers))
            .casters(Bound::Boxes(&casters))
            .scheme(FrameScheme::Cascades {
                splits: CascadeSplits::Scheme {
                    scheme: SplitScheme::Practical { lambda: 0.8 },
                    k: 4,
                    overlap: 0.1,
                },
                rule: WarpRule::Lispsm,
            });
        frame_into(&input, &mut out)?;
        if out.is_empty() {
            println!("frame {n}: scene out of view, no shadow map");
            continue;
        }
        uploads.clear();
        uploads.extend(out.maps().iter().map(|m| Upload {
            world_to_light: m.to_mat4(ClipDepth::ZeroToOne),
            split: (m.split.0 as f32, m.split.1 as f32),
            blend: (m.blend.0 as f32, m.blend.1 as f32),
            normal_bias: (1.5 * m.texel_world) as f32,
        }));
        println!(
            "frame {n}: {} maps, S̄ over the scene = {:8.2}, worst predicted error {:5.2} px (1080p, 2048² maps)",
            out.len(),
            out.storage_factor().unwrap_or(0.0),
            out.maps()
                .iter()
                .map(|m| m.max_error_pixels)
                .fold(0.0, f64::max)
        );
        for (m, u) in out.maps().iter().zip(&uploads) {
            println!(
                "    split [{:7.2}, {:7.2}] blend [{:7.2}, {:7.2}] normal bias {:.4}  B has {} vertices, n′ = {:?}",
                u.split.0,
                u.split.1,
                u.blend.0,
                u.blend.1,
                u.normal_bias,
                m.body().len(),
                m.shadow.n_prime()
            );
            // A GPU upload would copy `u.world_to_light.to_cols_array()` (column-major).
            assert!(u.world_to_light.is_finite());
        }
    }
    Ok(())
}
