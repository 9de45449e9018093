//! The error lens as the GPU draws it (the crate's `sa_error_lens`, called by render-check's
//! camera pass for the map each pixel selected) against render-check's own measurement from the
//! GPU's texel coordinates: the pixels one texel step spans on the surface, the larger singular
//! value of the inverse rendered Jacobian (docs/rendered.md, "The error lens"). With no Vulkan
//! adapter this fails, naming `mesa-vulkan-drivers`; it never skips.

use render_check::gpu::Gpu;
use render_check::run::{run_case, CaseResult, Render, Sizes};
use render_check::scene::{Scene, SceneBox};
use render_check::schemes::{setups, Scheme};
use render_check::targets::violations;
use render_check::targets::{
    LENS_FRAME_EXCESS, LENS_FRAME_REACH, LENS_MEDIAN_REL_DIFF, LENS_P99_REL_DIFF,
};

/// `scheme` drawn under the built-in set-up `grazing_10` at 240 × 180, without shimmer frames.
fn grazing(gpu: &Gpu, scheme: Scheme) -> Result<CaseResult, String> {
    let setup = setups()
        .into_iter()
        .find(|s| s.name == "grazing_10")
        .expect("the built-in set-up grazing_10");
    let sizes = Sizes {
        width: 240,
        height: 180,
        res: None,
        frames: 0,
        shimmer_points: 0,
        fault: None,
        render: Render::DEFAULT,
    };
    run_case(gpu, &setup.name, &setup.scene, scheme, sizes)
}

/// Under a sun 10° above the horizon, across the view (`grazing_10`), every scheme's drawn lens
/// is the rendered one to the targets (median ≤ 10⁻³, p99 ≤ 5·10⁻³ relatively), on at least half
/// the visible pixels; its perspective part (the lens with the projection factor 1) exceeds the
/// map's reported `max_error_pixels` times its rendered texel shear by at most 1 %
/// (`LENS_FRAME_EXCESS`), and reaches 95 % of
/// it where the worst body vertex shows. The scene's projection factor is far from 1 (the lens differs from its perspective
/// part by more than 50 % on most compared pixels), so a lens that leaves the projection factor
/// out fails the comparison: `sa_error_lens` with its projection onto the surface removed
/// (`ps = es`, `pt = et`) in src/frame/shadow.wgsl, this test failed on its first scheme,
/// uniform, with a median of 0.78 (and the next test's LiSPSM shows 0.82, p99 0.93).
#[test]
fn the_drawn_lens_is_the_pixels_a_texel_step_spans_on_the_surface() {
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("{e}"));
    for scheme in Scheme::ALL {
        let r = grazing(&gpu, scheme).unwrap_or_else(|e| panic!("{}: {e}", scheme.name()));
        let m = &r.summary.measured;
        let name = scheme.name();
        assert!(
            m.lens_pixels_compared * 2 >= m.visible_pixels,
            "{name}: {} of {} pixels compared",
            m.lens_pixels_compared,
            m.visible_pixels
        );
        assert!(
            m.lens_median_rel_diff <= LENS_MEDIAN_REL_DIFF,
            "{name}: median {}",
            m.lens_median_rel_diff
        );
        assert!(
            m.lens_p99_rel_diff <= LENS_P99_REL_DIFF,
            "{name}: p99 {}",
            m.lens_p99_rel_diff
        );
        assert!(
            m.lens_frame_ratio <= 1.0 + LENS_FRAME_EXCESS,
            "{name}: lens at projection factor 1 over the reported maximum {}",
            m.lens_frame_ratio
        );
        if let Some(w) = m.lens_frame_ratio_worst_visible {
            assert!(
                w >= LENS_FRAME_REACH,
                "{name}: worst vertex visible, ratio {w}"
            );
        }
        // The projection factor matters here: the lens and its perspective part differ.
        let a = &r.analysis;
        let (mut both, mut apart) = (0usize, 0usize);
        for (l, p) in a.lens.iter().zip(&a.perspective_lens) {
            if l.is_finite() && p.is_finite() {
                both += 1;
                apart += usize::from((l / p - 1.0).abs() > 0.5);
            }
        }
        assert!(
            apart * 2 > both,
            "{name}: the projection factor is far from 1 on {apart} of {both} pixels"
        );
    }
}

/// The lens targets have teeth: with `sa_error_lens`'s projection onto the surface removed from
/// the module (the texel's edges taken in the plane ⊥ L as they are, `ps = es`, `pt = et`: the
/// projection factor left out), the drawn lens of LiSPSM under the grazing sun violates
/// `lens_median_rel_diff` and `lens_p99_rel_diff` (median 0.82, p99 0.93 measured), while the
/// lens with the projection factor 1, which the projection does not change, still meets the
/// frame's maximum.
#[test]
fn a_lens_without_the_projection_factor_fails_the_targets() {
    let clean = render_check::gpu::shader_source();
    let broken = clean
        .replace("let ps = es - (dot(n, es) / nl) * l;", "let ps = es;")
        .replace("let pt = et - (dot(n, et) / nl) * l;", "let pt = et;");
    assert_eq!(
        clean.len() - broken.len(),
        2 * " - (dot(n, es) / nl) * l".len(),
        "sa_error_lens's projection onto the surface is written as this test expects"
    );
    let gpu = Gpu::with_source(&broken).unwrap_or_else(|e| panic!("{e}"));
    let r = grazing(&gpu, Scheme::Lispsm).unwrap();
    let m = &r.summary.measured;
    assert!(m.lens_median_rel_diff > LENS_MEDIAN_REL_DIFF, "{m:?}");
    assert!(m.lens_p99_rel_diff > LENS_P99_REL_DIFF, "{m:?}");
    assert!(m.lens_frame_ratio <= 1.0 + LENS_FRAME_EXCESS, "{m:?}");
}

/// Twenty slats 0.05 wide under a sun 8° high, drawn with face partitions at 320 × 240: a face
/// map's perspective warp shears its texels (the t step off perpendicular to the s step far from
/// the warp's centre line), and the texel's largest extent, the lens with the projection factor
/// 1, is 1.47 × the reported `max_error_pixels` where the rendered m_x, m_z stay within 1 % of the
/// reported M_x, M_z: the rendered shear (`max_texel_shear`, from the GPU's texel coordinates)
/// is 1.62 there. Held to the lens target against the reported maximum times that shear, the case
/// meets every target; against the reported maximum alone (the former target) it failed with 1.47.
#[test]
fn a_sheared_texels_lens_is_bounded_by_its_shear() {
    let mut scene = Scene::builtin();
    scene.boxes = (0..20)
        .map(|i| {
            let z = -14.0 + 0.4 * f64::from(i);
            SceneBox::aligned([-6.0, 1.5, z], [6.0, 1.6, z + 0.05])
        })
        .collect();
    scene
        .boxes
        .push(SceneBox::aligned([-6.2, 0.0, -14.2], [-6.0, 1.6, -5.8]));
    scene
        .boxes
        .push(SceneBox::aligned([6.0, 0.0, -14.2], [6.2, 1.6, -5.8]));
    scene.ground_half_extent = 80.0;
    scene.camera.eye = [0.0, 4.0, 0.0];
    scene.camera.target = [0.0, 0.0, -20.0];
    scene.camera.up = [0.0, 1.0, 0.0];
    scene.camera.near = 0.5;
    scene.camera.far = 60.0;
    scene.camera.fov_y_deg = 55.0;
    scene.light_dir = [0.0, -0.1405, -1.0];
    scene.map_resolution = 1024;
    scene.validate().unwrap();
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("{e}"));
    let sizes = Sizes {
        width: 320,
        height: 240,
        res: None,
        frames: 0,
        shimmer_points: 0,
        fault: None,
        render: Render::DEFAULT,
    };
    let r = run_case(&gpu, "slats", &scene, Scheme::Faces, sizes).unwrap();
    let v = violations(&r.summary);
    assert!(v.is_empty(), "{v:?}");
    let m = &r.summary.measured;
    // The texels are sheared, and the lens exceeds the reported maximum by more than the 1 %.
    assert!(m.max_texel_shear > 1.2, "{m:?}");
    assert!(
        m.lens_frame_ratio_worst_visible.unwrap_or(0.0) > 1.0 + LENS_FRAME_EXCESS,
        "{m:?}"
    );
}
