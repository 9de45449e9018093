//! A renderer's frame loop with the scene-aware frame API, as docs/renderer.md lays it out:
//! "What to call each frame" (camera, light and scene bounds in, `frame_into` on a `Frame` kept
//! between frames), "What to upload" (one `GpuShadowMap` record per map, its matrix relative to
//! the camera's position, its bias from the map's exact footprint), "Uploading" (the record's
//! bytes, reversed depth), and "Skipping maps that did not change" (stable cascades: a map whose
//! matrix is bit for bit last frame's is not drawn again).
//!
//! Conventions: world and eye space right-handed, the camera's view matrix maps world → eye with
//! the camera looking down −Z (glam `dcamera::rh::view::look_at_mat4`); the light direction is the
//! direction light travels, in world space.
//!
//! Run with `cargo run --example frame_loop`.

use glam::DVec3;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame_into, Aabb, Bound, Camera, CascadeSplits, Frame, FrameInput, FrameScheme, GpuShadowMap,
};
use shadow_aliasing::maps::ClipDepth;
use shadow_aliasing::Result;

/// The PCF kernel the lighting shader filters with (texels): the records' bias values are for it
/// (`gpu_with_pcf`), and the shader passes the same r to `sa_visibility`.
const PCF_RADIUS: f64 = 1.0;

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
    // allocates nothing; the record buffer keeps its capacity).
    let mut out = Frame::default();
    let mut records: Vec<u8> = Vec::with_capacity(4 * GpuShadowMap::SIZE);
    // The camera orbits the tower 60 units away, 5 up, in 4 steps of an eighth of a turn; then
    // it stays still for two frames and moves 10⁻⁶ units, far below a texel.
    let angles = [0.0, 1.0, 2.0, 3.0, 3.0, 3.0];
    for (n, step) in angles.iter().enumerate() {
        let a = step * std::f64::consts::TAU / 8.0;
        let nudge = if n == angles.len() - 1 { 1e-6 } else { 0.0 };
        let eye = DVec3::new(60.0 * a.cos() + nudge, 5.0, 60.0 * a.sin());
        let view = glam::dcamera::rh::view::look_at_mat4(eye, DVec3::new(0.0, 5.0, 0.0), DVec3::Y);
        // 1. The camera: world → eye and the projection (far 1000, far beyond the scene).
        let camera = Camera::new(view, 0.5, 1000.0, 30f64.to_radians(), 16.0 / 9.0)?;
        // 2. The scene, and the scheme: stable cascades (world-fixed squares, snapped to texels).
        let input = FrameInput::new(camera, sun, 2048, 1080) // map texels per side, image height
            .receivers(Bound::Boxes(&receivers))
            .casters(Bound::Boxes(&casters))
            .depth_clamp(false) // true if the shadow pass clamps depth (wgpu unclipped_depth)
            .scheme(FrameScheme::Stable(CascadeSplits::Scheme {
                scheme: SplitScheme::Practical { lambda: 0.8 },
                k: 4,
                overlap: 0.1,
            }));
        // 3. The maps, written into the Frame kept between frames.
        frame_into(&input, &mut out)?;
        if out.is_empty() {
            println!("frame {n}: scene out of view, no shadow map");
            continue;
        }
        // 4. The upload: one 144-byte record per map, its matrix relative to the camera's
        // position (vertex positions are uploaded as p − eye), reversed depth, the bias for the
        // shader's PCF kernel.
        records.clear();
        let mut redraw = 0;
        for m in out.maps().iter() {
            let record = m.gpu_relative_with_pcf(eye, ClipDepth::Reversed, PCF_RADIUS)?;
            records.extend_from_slice(&record.to_bytes());
            // 5. Only maps that changed need their depth texture drawn again.
            if !m.unchanged() {
                redraw += 1;
            }
        }
        println!(
            "frame {n}: {} maps ({redraw} to draw), worst predicted error {:5.2} px (1080p, 2048² maps), {} bytes of records",
            out.len(),
            out.maps()
                .iter()
                .map(|m| m.max_error_pixels)
                .fold(0.0, f64::max),
            records.len()
        );
        for m in out.maps().iter() {
            let bias = m.bias(PCF_RADIUS, ClipDepth::Reversed)?;
            println!(
                "    split [{:7.2}, {:7.2}] blend [{:7.2}, {:7.2}] normal offset {:.4} {}",
                m.split.0,
                m.split.1,
                m.blend.0,
                m.blend.1,
                bias.normal_offset,
                if m.unchanged() {
                    "unchanged"
                } else {
                    "changed"
                }
            );
        }
    }
    Ok(())
}
