//! Issue 31, defects 2–5: the frame at extreme depth ratios and degenerate frusta. Every slice a
//! scheme asks for is mapped (or the frame is refused with a typed error naming the cause);
//! whether a frame is built does not depend on `measure`; a frustum too thin for the frame is
//! refused naming `aspect` or `half_fov`, never answered "no map needed".
// The commands give --half-fov 0.5236 (30° to 4 digits), not π/6.
#![allow(clippy::approx_constant)]
use glam::{DMat4, DVec3};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera, CascadeSplits, Focus, FrameInput, FrameScheme,
};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::{plan, Goal};
use shadow_aliasing::{Error, ViewFrustum};

const LIGHT: DVec3 = DVec3::new(0.3, -0.8, -0.4);

fn log_cascades(k: usize) -> FrameScheme<'static> {
    FrameScheme::Cascades {
        splits: CascadeSplits::Scheme {
            scheme: SplitScheme::SelfSimilar,
            k,
            overlap: 0.0,
        },
        rule: WarpRule::Lispsm,
    }
}

/// The name of an `InvalidArgument`, or a panic naming what came instead.
fn name_of<T: std::fmt::Debug>(r: Result<T, Error>) -> &'static str {
    match r {
        Err(Error::InvalidArgument { name, .. }) => name,
        other => panic!("expected InvalidArgument, got {other:?}"),
    }
}

/// Defect 2: at far/near = 10¹⁰ and 10¹⁶ the logarithmic cascades' nearest slices were judged
/// edge-on against 10⁻⁹ of the whole frustum (2.15 at far 10⁹, larger than the slice [0.1,
/// 1.778]) and dropped without a word: 7 and 5 maps of 8. Each slice is mapped, its split the
/// hand value n (f/n)^(i/k).
#[test]
fn log_cascades_map_every_slice_at_extreme_depth_ratios() {
    let ground = [Aabb::new(DVec3::new(-1e15, -1.0, -1e15), DVec3::new(1e15, 0.0, 0.0)).unwrap()];
    for (near, far) in [(0.1, 1e9), (1.0, 1e15)] {
        for receivers in [Bound::Unbounded, Bound::Boxes(&ground)] {
            let cam = Camera::new(DMat4::IDENTITY, near, far, 0.5236, 1.0).unwrap();
            let input = FrameInput::new(cam, LIGHT, 2048, 1080)
                .receivers(receivers)
                .scheme(log_cascades(8));
            let f = frame(&input).unwrap();
            assert_eq!(f.len(), 8, "near {near}, far {far}, {receivers:?}");
            let ratio: f64 = far / near;
            for (i, m) in f.maps().iter().enumerate() {
                let a = near * ratio.powf(i as f64 / 8.0);
                let b = near * ratio.powf((i + 1) as f64 / 8.0);
                assert!(
                    (m.split.0 - a).abs() <= 1e-12 * a,
                    "{i}: {:?} vs {a}",
                    m.split
                );
                assert!(
                    (m.split.1 - b).abs() <= 1e-12 * b,
                    "{i}: {:?} vs {b}",
                    m.split
                );
                // The map covers its slice's body, which lies in the slice.
                assert!(
                    m.shadow.near() >= a * (1.0 - 1e-12) && m.shadow.far() <= b * (1.0 + 1e-12)
                );
                assert!(m.error().is_some() && m.texel_world > 0.0);
            }
        }
    }
}

/// Defect 2 for a single map: receivers near the camera at far/near = 10¹² were judged empty (the
/// box's 100 of thickness below 10⁻⁹ of the frustum's 3·10¹²). The hand values of
/// tests/cli_warp_scene.rs's `receivers_focus_the_map_and_report_over_b` hold at any far: B is
/// the lower half of the view between depths 2 and 5 (tan θ = 1), the light straight down, the
/// uniform map; s spans x ∈ [−5, 5], t depth [2, 5]: M_x = 10/(2·2) = 2.5, M_z = 3/(2·2) = 0.75.
#[test]
fn receivers_near_the_camera_are_mapped_at_any_far() {
    let lower_half = [Aabb::new(
        DVec3::new(-100.0, -100.0, -5.0),
        DVec3::new(100.0, 0.0, -2.0),
    )
    .unwrap()];
    for far in [100.0, 1e10, 1e12, 1e100, 1e300] {
        let cam = Camera::new(DMat4::IDENTITY, 1.0, far, std::f64::consts::FRAC_PI_4, 1.0).unwrap();
        let input = FrameInput::new(cam, DVec3::NEG_Y, 2048, 1080)
            .receivers(Bound::Boxes(&lower_half))
            .scheme(FrameScheme::Single(WarpRule::Uniform));
        let f = frame(&input).unwrap();
        assert_eq!(f.len(), 1, "far {far}: {:?}", f.focus());
        let e = f.maps()[0].error().unwrap();
        assert!((e.max_mx - 2.5).abs() < 1e-9, "far {far}: {e:?}");
        assert!((e.max_mz - 0.75).abs() < 1e-9, "far {far}: {e:?}");
    }
}

/// Defect 3: with measurement the issue's frame is refused ("the map is singular at a vertex of
/// the focus body"); without, it was Ok with texel_world = 0 and a NaN bias. Whether a frame is
/// built must not depend on `measure`.
#[test]
fn measure_off_refuses_what_measure_on_refuses() {
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 1e300, 1e-5, 16.0 / 9.0).unwrap();
    let input =
        FrameInput::new(cam, LIGHT, 16384, 1080).scheme(FrameScheme::Single(WarpRule::Uniform));
    let on = frame(&input);
    let off = frame(&input.measure(false));
    assert!(matches!(on, Err(Error::Degenerate(_))), "{on:?}");
    assert_eq!(on.map(|_| ()), off.map(|_| ()));
}

/// Defect 4: a frustum too thin for the frame (aspect 10¹⁰ or 10⁻¹⁰, half_fov 10⁻¹⁰) was
/// answered "no map needed" (edge-on) under a sun straight down on an unbounded scene. It is
/// refused naming the argument, bounded or not, and the advised range is accepted.
#[test]
fn a_frustum_too_thin_for_the_frame_is_refused_naming_the_argument() {
    let ground = [Aabb::new(DVec3::new(-1e12, -1.0, -100.0), DVec3::new(1e12, 0.0, 0.0)).unwrap()];
    for (half_fov, aspect, name) in [
        (0.5236, 1e10, "aspect"),
        (0.5236, 1e-10, "aspect"),
        (1e-10, 1.0, "half_fov"),
        (1.5707963, 1.0, "half_fov"),
    ] {
        let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, half_fov, aspect).unwrap();
        for receivers in [Bound::Unbounded, Bound::Boxes(&ground)] {
            let input = FrameInput::new(cam, DVec3::NEG_Y, 2048, 1080)
                .receivers(receivers)
                .scheme(FrameScheme::Single(WarpRule::Uniform));
            assert_eq!(name_of(frame(&input)), name, "{half_fov} {aspect}");
            assert_eq!(
                name_of(plan(&input, Goal::MaxError(1.0), Rounding::PowerOfTwo)),
                name
            );
        }
    }
    // The advised aspect range at half_fov 0.5236 (tan θ = 0.57735): 2 t a ≥ 10⁻⁶ (1 + t (1 + a))
    // gives a ≥ 1.366·10⁻⁶; 2 t ≥ 10⁻⁶ (1 + t (1 + a)) gives a ≤ 2·10⁶ − 1/t − 1 = 1 999 997.3,
    // and 1 ≥ 10⁻⁶ (1 + t (1 + a)) a ≤ 1 732 048.2: both ends are built.
    for aspect in [1.37e-6, 1.73e6] {
        let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5236, aspect).unwrap();
        let input = FrameInput::new(cam, DVec3::NEG_Y, 2048, 1080)
            .scheme(FrameScheme::Single(WarpRule::Uniform));
        let f = frame(&input).unwrap();
        assert_eq!((f.len(), f.focus()), (1, Focus::Body), "aspect {aspect}");
    }
    for aspect in [1.36e-6, 1.74e6] {
        let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5236, aspect).unwrap();
        let input = FrameInput::new(cam, DVec3::NEG_Y, 2048, 1080);
        assert_eq!(name_of(frame(&input)), "aspect", "aspect {aspect}");
    }
}

/// Defect 4 at far = 10³⁰⁸: the frame said "no map needed"; like the frustum-only `warp` command
/// it is refused (the map is singular there), never an Ok frame without maps.
#[test]
fn an_unmappable_frustum_is_an_error_not_no_map() {
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 1e308, 0.5236, 1.0).unwrap();
    let input = FrameInput::new(cam, DVec3::NEG_Y, 2048, 1080)
        .scheme(FrameScheme::Single(WarpRule::Uniform));
    assert!(matches!(frame(&input), Err(Error::Degenerate(_))));
}

/// A plan of receivers out of view is refused (it was a 0-texel, 0-pixel plan).
#[test]
fn a_plan_of_nothing_is_refused() {
    let behind = [Aabb::new(DVec3::new(-10.0, -10.0, 1.0), DVec3::new(10.0, 10.0, 5.0)).unwrap()];
    let cam = Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5236, 1.0).unwrap();
    let input = FrameInput::new(cam, LIGHT, 2048, 1080).receivers(Bound::Boxes(&behind));
    assert_eq!(frame(&input).unwrap().focus(), Focus::Empty);
    assert_eq!(
        name_of(plan(&input, Goal::MaxError(1.0), Rounding::PowerOfTwo)),
        "receivers"
    );
}

/// Defect 5 (first item): an aspect that takes the frustum's half width out of f64 was blamed
/// on `far` (1e308) or `near` (5e-324). It names `aspect`, and the bound it advises is accepted.
#[test]
fn an_aspect_out_of_f64_names_aspect_with_a_bound_that_works() {
    for (aspect, ok_side) in [(1e308, true), (5e-324, false)] {
        let e = ViewFrustum::with_aspect(1.0, 100.0, 0.5236, aspect).unwrap_err();
        let Error::InvalidArgument { name, reason } = &e else {
            panic!("{e:?}")
        };
        assert_eq!(*name, "aspect", "{e}");
        // "give aspect at most X" / "at least X": X is accepted.
        let word = if ok_side { "at most " } else { "at least " };
        let x: f64 = reason
            .split(word)
            .nth(1)
            .unwrap()
            .split(' ')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert!(
            ViewFrustum::with_aspect(1.0, 100.0, 0.5236, x).is_ok(),
            "{reason}"
        );
        assert!(Camera::new(DMat4::IDENTITY, 1.0, 100.0, 0.5236, aspect).is_err());
    }
    // A far plane that overflows at aspect 1 is still the far plane's fault.
    let e = ViewFrustum::with_aspect(1.0, 1e308, 1.5, 2.0).unwrap_err();
    assert_eq!(name_of::<()>(Err(e)), "far");
}
