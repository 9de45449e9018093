//! The option cases ([`render_check::options`]): every case meets its targets on the CPU (both
//! screen sizes), each option reaches the frame (the maps differ from the defaults' as the option
//! says), and each measurement fails when the crate's output is changed as a crate that ignored
//! the option would change it.

use render_check::geometry::clipmap_offset;
use render_check::options::{cases, measure, summarise, violations, OptionCase, OptionSummary};
use render_check::papers::{lispsm_n_prime, sin_gamma};
use render_check::scene::Scene;
use render_check::schemes::{build, setups, Built, Options, Scheme, View};
use shadow_aliasing::maps::ClipDepth;

fn case(name: &str) -> OptionCase {
    cases().into_iter().find(|c| c.name == name).unwrap()
}

/// `c` built with `built_options` (what a faulty crate would have built) and measured against
/// `c`'s own options (what render-check asked for), after `edit`.
fn measured_as(
    c: &OptionCase,
    built_options: &Options,
    edit: impl Fn(&mut Built),
) -> OptionSummary {
    let (view, scene) = view_of(c);
    let res = scene.map_resolution;
    let mut built = built_with(c, &view, built_options);
    // render-check's expectation: the planes for the case's λ, the resolutions it asked for, the
    // depth clamp it asked for.
    let asked = built_with(c, &view, &c.options);
    built.planes.clone_from(&asked.planes);
    built.bands.clone_from(&asked.bands);
    built.depth_clamp = asked.depth_clamp;
    if built.maps.len() == asked.maps.len() {
        for (m, a) in built.maps.iter_mut().zip(&asked.maps) {
            m.res = a.res;
        }
    }
    edit(&mut built);
    summarise(c, &view, &scene, &built, view.image_height, res)
}

/// The view and scene of `c` at 320 × 240 (or the case's own screen), its far plane moved where
/// the case asks.
fn view_of(c: &OptionCase) -> (View, Scene) {
    let mut scene = setups()
        .into_iter()
        .find(|s| s.name == c.setup)
        .unwrap()
        .scene;
    if let Some(far) = c.options.far {
        scene.camera.far = far;
    }
    let (w, h) = c.options.screen.unwrap_or((320, 240));
    let view = View::new(&scene.camera, scene.light(), w, h).unwrap();
    (view, scene)
}

/// Each case of `names` built as a crate that ignored its option would build it (the default
/// options) and measured against the case's own options.
fn option_ignored<'a>(names: &'a [&'a str]) -> impl Iterator<Item = (&'a str, OptionSummary)> {
    names
        .iter()
        .map(|&name| (name, measured_as(&case(name), &Options::default(), |_| {})))
}

fn fails(o: &OptionSummary, target: &str) -> bool {
    violations(o).iter().any(|l| l.starts_with(target))
}

#[test]
fn every_option_case_meets_its_targets() {
    for c in cases() {
        for (w, h) in [(320, 240), (640, 480)] {
            let o = measure(&c, w, h, None).unwrap();
            let v = violations(&o);
            assert!(v.is_empty(), "{} {w}×{h}: {v:?}", c.name);
        }
    }
}

/// Each option changes the frame: the split planes differ from λ = 0.75's, the maps' texels
/// follow the requested resolutions (the texel edge of cascade i at 2048 / 2^i texels against the
/// default's at 1024), and the clamped map's depth range is narrower than the unclamped one's
/// where casters lie nearer the light than B.
#[test]
fn each_option_reaches_the_frame() {
    for (name, o) in option_ignored(&[
        "splits_uniform",
        "splits_logarithmic",
        "splits_practical_0.5",
    ]) {
        assert!(
            o.geometry.split_rel_diff.unwrap() > 0.05 && fails(&o, "split_rel_diff"),
            "{name}: {o:?}"
        );
        assert!(fails(&o, "body_rel_diff"), "{name}: {o:?}");
    }
    // Per-map resolutions ignored (every map at the scene's 1024): the record's texel is the
    // one at 1024 texels, measured at the asked resolution r it reads r/1024: 2048/1024 = 2 for
    // the map asked at 2048 (the farthest from 1 of 2, 1, 1/2, 1/4 over the cascades), 1/2 for
    // the single map asked at 512.
    for (name, o) in option_ignored(&[
        "resolutions_cascades",
        "resolutions_stable",
        "resolutions_single",
    ]) {
        assert!(fails(&o, "|texel_world_ratio − 1|"), "{name}: {o:?}");
        let r = o.geometry.texel_world_ratio;
        let want = match name {
            "resolutions_cascades" => 2.0,
            "resolutions_stable" => 2.0,
            _ => 0.5,
        };
        assert!((r / want - 1.0).abs() < 1e-5, "{name}: {r} against {want}");
    }
    // Depth clamp ignored (the depth range reaches the casters nearer the light).
    for (name, o) in option_ignored(&[
        "depth_clamp_lispsm",
        "depth_clamp_uniform",
        "depth_clamp_tsm",
        "depth_clamp_cascades",
        "depth_clamp_clipmap",
    ]) {
        assert!(fails(&o, "depth_clamp_fill"), "{name}: {o:?}");
        // Its casters' volume keeps the near depth plane the sweep toward the light lacks.
        assert!(fails(&o, "casters_volume_rel_diff"), "{name}: {o:?}");
    }
}

#[test]
fn the_option_targets_fail_on_faulty_output() {
    // A map's receivers' volume without its receivers' box (the slice's planes alone): the
    // facets of B on the box leave the volume far away.
    let c = case("resolutions_cascades");
    let o = measured_as(&c, &c.options, |b| {
        let other = b.maps[3].receivers;
        b.maps[0].receivers = other;
    });
    assert!(fails(&o, "receivers_volume_rel_diff"), "{o:?}");
    // The reported storage factor doubled.
    let c = case("splits_uniform");
    let o = measured_as(&c, &c.options, |b| b.maps[1].reported.storage_factor *= 2.0);
    assert!(fails(&o, "paper_frame_rel_diff"), "{o:?}");
    // A depth range 1 % longer than B's under depth clamp.
    let c = case("depth_clamp_uniform");
    let o = measured_as(&c, &c.options, |b| {
        let m = &mut b.maps[0];
        m.gpu = glam::DMat4::from_scale(glam::DVec3::new(1.0, 1.0, 1.0 / 1.01)) * m.gpu;
    });
    assert!(fails(&o, "depth_clamp_fill"), "{o:?}");
    // The stable cascades' splits at λ = 0.75 measured against the logarithmic planes.
    let c = case("splits_logarithmic_stable");
    let o = measured_as(&c, &Options::default(), |_| {});
    assert!(fails(&o, "body_rel_diff"), "{o:?}");
    assert_eq!(c.scheme, Scheme::StableCascades);
}

/// The `receivers_inside_*` cases' premise: B (every map's focus body) ends well before the far
/// plane, so LiSPSM's n′ of the paper at B's own depth range and at the slice's differ by far
/// more than the tolerance, the crate's n′ being the paper's at B's range; and a reported M_z
/// 10⁻⁴ off the paper's map (an n′ off the paper's, reported with it, as a crate whose rule is
/// wrong reports it) fails `paper_frame_rel_diff` there.
#[test]
fn receivers_inside_b_ends_before_far_and_a_wrong_n_prime_fails() {
    for name in ["receivers_inside_lispsm", "receivers_inside_cascades"] {
        let c = case(name);
        let (view, _) = view_of(&c);
        let built = measured_built(&c, &view);
        let far = view.frustum.far();
        let f_b = built
            .bodies
            .iter()
            .flatten()
            .map(|v| -v.z)
            .fold(f64::NEG_INFINITY, f64::max);
        assert!(f_b < 0.5 * far, "{name}: f_B {f_b}, far {far}");
    }
    let c = case("receivers_inside_lispsm");
    let (view, _) = view_of(&c);
    let built = measured_built(&c, &view);
    let body = &built.bodies[0];
    let n_b = body.iter().map(|v| -v.z).fold(f64::INFINITY, f64::min);
    let f_b = body.iter().map(|v| -v.z).fold(f64::NEG_INFINITY, f64::max);
    let sg = sin_gamma(view.light_eye);
    let (n, f) = (view.frustum.near(), view.frustum.far());
    let on_b = lispsm_n_prime(n_b, f_b, sg);
    let on_slice = lispsm_n_prime(n, f, sg);
    assert!(on_slice / on_b > 1.1, "{on_b} {on_slice}");
    // The reported n′ is the paper's at B's range.
    let rep = built.maps[0].reported.n_prime;
    assert!((rep / on_b - 1.0).abs() < 1e-9, "{rep} {on_b}");
    let o = measured_as(&c, &c.options, |_| {});
    assert!(violations(&o).is_empty(), "{o:?}");
    let o = measured_as(&c, &c.options, |b| b.maps[0].reported.max_mz *= 1.0 + 1e-4);
    assert!(fails(&o, "paper_frame_rel_diff"), "{o:?}");
}

fn measured_built(c: &OptionCase, view: &View) -> Built {
    built_with(c, view, &c.options)
}

/// `c`'s scheme and set-up (its far plane where it moves it) built for `view` with `options`,
/// depth \[0, 1\], no fault.
fn built_with(c: &OptionCase, view: &View, options: &Options) -> Built {
    let (_, scene) = view_of(c);
    let (res, zo) = (scene.map_resolution, ClipDepth::ZeroToOne);
    build(c.scheme, view, &scene, res, None, zo, options).unwrap()
}

/// The `clipmap_lod_bound` case's premise: at its 80 × 60 image the LOD rule's offset (texel ≤
/// 2^b pixels) exceeds the coverage bound's, computed by hand from the camera (tan 30°, 4/3,
/// Unreal's unit 0.01 and bias −0.5 at 1024²), so the level the frame picks is the LOD rule's;
/// a level offset one too coarse (the rule's 4 unit halved) fails `clipmap_rel_diff`.
#[test]
fn clipmap_lod_bound_is_set_by_the_lod_rule() {
    let c = case("clipmap_lod_bound");
    let (view, _) = view_of(&c);
    assert_eq!(view.image_height, 60);
    let t = 30f64.to_radians().tan();
    let matched = -0.5 + (t * 1024.0 / (4.0 * 0.01 * 60.0)).log2();
    let coverage = ((t * t * (1.0 + 16.0 / 9.0) + 1.0).sqrt() / 0.01).log2();
    assert!(matched > coverage + 0.25, "{matched} {coverage}");
    let l = clipmap_offset(t, 4.0 / 3.0, 60, 1024, 0.01, -0.5);
    assert!((l - matched).abs() < 1e-12, "{l} {matched}");
    let built = measured_built(&c, &view);
    assert!(
        (built.clipmap[0] - matched).abs() < 1e-9,
        "{:?}",
        built.clipmap
    );
    let o = measured_as(&c, &c.options, |_| {});
    assert!(violations(&o).is_empty(), "{o:?}");
    let o = measured_as(&c, &c.options, |b| b.clipmap[0] += 1.0);
    assert!(fails(&o, "clipmap_rel_diff"), "{o:?}");
}
