//! The clipmap's world-fixed page grid (docs/renderer.md and docs/planning.md, "Clipmaps"): each
//! level's square is snapped to whole pages of `ClipmapOptions::page_texels` texels, so that a
//! virtual-shadow-map renderer caching pages by world position finds the same pages after any
//! camera move. Measured, as `render_check::snap` measures the stable cascades' texel grid, from
//! the maps' `f64` world → clip matrices alone: a fixed world point's texel position in a level
//! (clip x, y mapped to [0, res]) moves between two camera positions by a whole number of pages
//! (`page_texels` texels, the documented option the test set), along s and t. The texel and
//! page sizes come from the resolution and the option asked for, none from the crate's code; a
//! square snapped to whole texels only (the grid then moves with the camera, by up to a page
//! less one texel) fails.

use glam::DVec3;
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, ClipmapOptions, Frame, FrameInput, FrameScheme,
};
use shadow_aliasing::maps::ClipDepth;

const RES: u32 = 256;
const PAGE: u32 = 32;

/// The clipmap frame of a camera at `eye` looking along a fixed direction.
fn clipmap(eye: DVec3, options: &ClipmapOptions) -> Frame {
    let ground = [Aabb::new([-500.0, -1.0, -500.0], [500.0, 0.0, 500.0]).unwrap()];
    let view =
        glam::dcamera::rh::view::look_at_mat4(eye, eye + DVec3::new(0.4, -0.3, -1.0), DVec3::Y);
    let camera = Camera::new(view, 0.1, 200.0, 0.6, 1.5).unwrap();
    let input = FrameInput::new(camera, DVec3::new(0.3, -0.8, -0.4), RES, 720)
        .receivers(Bound::Boxes(&ground))
        .casters(Bound::Boxes(&ground))
        .scheme(FrameScheme::Clipmap(*options));
    frame(&input).unwrap()
}

/// Each level's (level, texel position s, t of the fixed world points) in a frame.
fn positions(f: &Frame, points: &[DVec3]) -> Vec<(i32, Vec<(f64, f64)>)> {
    f.maps()
        .iter()
        .map(|m| {
            assert_eq!(m.resolution(), RES);
            let clip = m.world_to_clip(ClipDepth::ZeroToOne);
            let half = 0.5 * f64::from(RES);
            let level = m.clipmap_level.expect("a clipmap level");
            let st = points
                .iter()
                .map(|&p| {
                    let c = clip.project_point3(p);
                    ((c.x + 1.0) * half, (c.y + 1.0) * half)
                })
                .collect();
            (level, st)
        })
        .collect()
}

#[test]
fn every_clipmap_level_moves_by_whole_pages() {
    let options = ClipmapOptions {
        page_texels: PAGE,
        ..ClipmapOptions::UNREAL
    };
    let points = [
        DVec3::ZERO,
        DVec3::new(3.7, 0.0, -11.3),
        DVec3::new(-21.1, 0.5, 7.9),
    ];
    // Camera positions no page divides (nor a texel).
    let eyes = [
        DVec3::new(0.0, 1.7, 0.0),
        DVec3::new(0.3137, 1.7, -0.2718),
        DVec3::new(5.4321, 2.1, 3.1729),
        DVec3::new(-17.77, 1.9, 29.03),
    ];
    let frames: Vec<_> = eyes
        .iter()
        .map(|&e| positions(&clipmap(e, &options), &points))
        .collect();
    let page = f64::from(PAGE);
    let mut compared = 0;
    let mut moved = 0;
    for b in &frames[1..] {
        for (level, st_b) in b {
            let Some((_, st_a)) = frames[0].iter().find(|(l, _)| l == level) else {
                continue;
            };
            for (k, (pa, pb)) in st_a.iter().zip(st_b).enumerate() {
                for (axis, d) in [("s", pb.0 - pa.0), ("t", pb.1 - pa.1)] {
                    let pages = d / page;
                    // The texel positions are 2^{level} units over a texel: 1e-6 pages of slack.
                    assert!(
                        (pages - pages.round()).abs() <= 1e-6,
                        "level {level}, point {k}: moved {d} texels along {axis}, {pages} pages"
                    );
                    compared += 1;
                    if pages.round() != 0.0 {
                        moved += 1;
                    }
                }
            }
        }
    }
    // Something was compared, and the fine levels did move (by whole pages).
    assert!(compared >= 30, "{compared} comparisons");
    assert!(moved >= 6, "only {moved} moves of a page or more");
}
