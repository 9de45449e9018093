//! The shader paths' normal offsets measured on a strongly perspective map (render_check::paths,
//! docs/rendered.md, "What is measured", 11): PSM's map under a light 10° high across the view
//! (`grazing_10`), whose centre of projection lies near the focus body, rendered for real (wgpu on
//! Vulkan; lavapipe without a GPU).

use render_check::gpu::Gpu;
use render_check::paths::{check, PathSummary, LIFT_SLACK, PATHS};
use render_check::run::{case_clip_depth, Render, Sizes};
use render_check::schemes::{setups, Scheme};

/// The lift of the GPU's lookup point over the need, which render-check derives from the map's
/// matrix and the pixel's plane (not from the crate's `normal_offset_at`): exactly 1 for the
/// per-point offset, at least 1 for the record's, and each offset the one it is defined to be.
/// The per-point offset's point moves the map's w by up to 5 % or more here, so an offset that
/// got the `(row₃ · n)/w` term of its closed form wrong (its sign, or left out) would lift by
/// 1/(1 ± 2 × that) of the need and fail; on `behind_5`'s LiSPSM map the term is 2·10⁻⁴ and
/// could not tell.
#[test]
fn normal_offsets_lift_by_the_need_on_a_perspective_map() {
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("{e}"));
    let (si, s) = setups()
        .into_iter()
        .enumerate()
        .find(|(_, s)| s.name == "grazing_10")
        .unwrap();
    let sizes = Sizes {
        width: 320,
        height: 240,
        res: None,
        frames: 1,
        shimmer_points: 1,
        fault: None,
        render: Render {
            clip_depth: case_clip_depth(si, Scheme::Psm),
            ..Render::DEFAULT
        },
    };
    let sums: Vec<PathSummary> = check(&gpu, &s.scene, Scheme::Psm, sizes).unwrap();
    assert_eq!(sums.len(), PATHS.len());
    for (path, p) in PATHS.iter().zip(&sums) {
        assert_eq!(path.name, p.path);
        if !path.offset() {
            assert!(
                p.lift_over_need.is_none() && p.offset_rel_diff.is_none(),
                "{p:?}"
            );
            continue;
        }
        let [lo, hi] = p.lift_over_need.unwrap_or_else(|| panic!("{p:?}"));
        assert!(lo >= 1.0 - LIFT_SLACK, "{p:?}");
        assert!(p.offset_rel_diff.unwrap() <= LIFT_SLACK, "{p:?}");
        if path.local() {
            assert!(hi <= 1.0 + LIFT_SLACK, "{p:?}");
            // Nearly every lookup measured, and the offset point's footprint matters.
            assert!(p.offset_lookups as f64 >= 0.95 * p.lookups as f64, "{p:?}");
            assert!(p.max_w_change.unwrap() >= 0.05, "{p:?}");
        }
    }
}
