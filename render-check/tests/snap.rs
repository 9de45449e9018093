//! The stable cascades' world-fixed grid ([`render_check::snap`]): over the shimmer test's
//! camera moves ([`render_check::run::moved`]), fixed world points move by whole texels in every
//! stable map of every built-in set-up (built on the CPU, no rendering), and a map moved by a
//! fraction of a texel (as a grid step 2/res off the texel moves it) is measured at that
//! fraction.

use glam::{DMat4, DVec3};
use render_check::run::{moved, shimmer_step};
use render_check::schemes::{build, setups, Built, Options, Scheme, View};
use render_check::snap::grid_offset_texels;
use render_check::targets::STABLE_GRID_TEXELS;
use shadow_aliasing::maps::ClipDepth;

/// Frame `i` of the shimmer test for `setup`'s stable cascades at 320 × 240.
fn frame(setup: &str, i: usize) -> (View, Built) {
    let s = setups().into_iter().find(|s| s.name == setup).unwrap();
    let res = s.scene.map_resolution;
    let view0 = View::new(&s.scene.camera, s.scene.light(), 320, 240).unwrap();
    let step = shimmer_step(&view0, res).unwrap();
    let m = moved(&s.scene, i, step);
    let view = View::new(&m.camera, m.light(), 320, 240).unwrap();
    let built = build(
        Scheme::StableCascades,
        &view,
        &m,
        res,
        None,
        ClipDepth::ZeroToOne,
        &Options::default(),
    )
    .unwrap();
    (view, built)
}

/// World points spread over the ground and the boxes' tops in front of the camera of `setup`
/// (frame 0's eye, x and z; the set-ups far from the origin included).
fn points_of(setup: &str) -> Vec<DVec3> {
    let s = setups().into_iter().find(|s| s.name == setup).unwrap();
    let eye = DVec3::from_array(s.scene.camera.eye);
    let mut p = Vec::new();
    for i in 0..12 {
        for j in 0..12 {
            let x = -30.0 + 5.3 * f64::from(i);
            let z = -2.0 - 9.7 * f64::from(j);
            let y = s.scene.ground_y + 0.37 * f64::from((i + j) % 5);
            p.push(DVec3::new(eye.x + x, y, eye.z + z));
        }
    }
    p
}

fn points() -> Vec<DVec3> {
    points_of("tilted_45")
}

/// The texel move of world point `p` in map `k` between two frames, along s (not rounded).
fn s_move(a: &(View, Built), b: &(View, Built), k: usize, p: DVec3) -> f64 {
    let s = |(v, f): &(View, Built)| {
        let m = &f.maps[k];
        let h = m.built * v.world_to_eye.transform_point3(p).extend(1.0);
        h.x / h.w * 0.5 * f64::from(m.res)
    };
    s(b) - s(a)
}

#[test]
fn stable_maps_move_by_whole_texels_in_every_setup() {
    for s in setups() {
        let frames: Vec<(View, Built)> = (0..4).map(|i| frame(&s.name, 3 * i)).collect();
        for w in frames.windows(2) {
            let d = grid_offset_texels((&w[0].0, &w[0].1), (&w[1].0, &w[1].1), &points_of(&s.name));
            // Rounding only: 10⁻⁸ texel, 100 times under the target.
            assert!(d <= 1e-2 * STABLE_GRID_TEXELS, "{}: {d}", s.name);
        }
    }
}

#[test]
fn the_grid_test_is_not_vacuous_and_measures_a_sub_texel_move() {
    let a = frame("tilted_45", 0);
    let mut b = frame("tilted_45", 8);
    // 8 steps of 0.37 texel of the first cascade: its map snapped 2 or 3 whole texels along
    // the motion, so the points did move.
    let moved_texels = points()
        .iter()
        .map(|&p| s_move(&a, &b, 0, p).abs())
        .fold(0.0f64, f64::max);
    assert!(moved_texels >= 1.0 - 1e-9, "{moved_texels}");
    let d = grid_offset_texels((&a.0, &a.1), (&b.0, &b.1), &points());
    assert!(d <= 1e-9, "{d}");
    // Map 2 moved by 1 − 2/res texel more along s (a snap step 2r/res where the texel is
    // 2 half/res, half = r res/(res − 2)): 2/1024 = 1.953e-3 texel off the grid.
    let res = f64::from(b.1.maps[2].res);
    let shift = 1.0 - 2.0 / res;
    b.1.maps[2].built =
        DMat4::from_translation(DVec3::new(shift * 2.0 / res, 0.0, 0.0)) * b.1.maps[2].built;
    let d = grid_offset_texels((&a.0, &a.1), (&b.0, &b.1), &points());
    assert!((d - 2.0 / res).abs() < 1e-9, "{d}");
    assert!(d > STABLE_GRID_TEXELS);
    // Nothing paired (every map of one frame at another resolution): NaN, no pass.
    for m in &mut b.1.maps {
        m.res *= 2;
    }
    assert!(grid_offset_texels((&a.0, &a.1), (&b.0, &b.1), &points()).is_nan());
}
