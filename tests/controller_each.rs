//! The controller with a resolution per map (`ControllerOptions::shared_resolution` false,
//! issue 32: engines whose maps need not share one size). Checked on the scripted walk against
//! hand allocations from the matrices alone: each map's error at one texel a side measured by
//! central differences (`common::audit`), each map's resolution the least power of two that
//! meets the target, the cheapest candidate by brute force on every cut; a texel budget's least
//! largest error by trying every power-of-two allocation; the maps' own resolutions in the
//! decision, the frame and the GPU records; a still camera keeps every map.

mod common;

use common::walk::{allowed, camera, input, scene, FRAMES, H};
use shadow_aliasing::frame::{frame, CascadeSplits, FrameInput, FrameMap, FrameScheme};
use shadow_aliasing::maps::ClipDepth;
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::{Controller, ControllerOptions, Decision};

const TARGET: f64 = 2.0;
const CAP: u32 = 4096;

fn options(shared: bool) -> ControllerOptions {
    ControllerOptions {
        max_maps: 4,
        rounding: Rounding::PowerOfTwo,
        max_resolution: CAP,
        candidates: Some(allowed()),
        shared_resolution: shared,
        ..ControllerOptions::new(TARGET)
    }
}

/// A map's largest error over its body at one texel a side, pixels × texels: from its matrix
/// alone by central differences.
fn product(m: &FrameMap, inp: &FrameInput<'_>) -> f64 {
    common::audit::body_max(m, inp) * f64::from(H)
}

/// The least power of two at least `need` and at least 3 (the frame's least map), by hand.
fn pow2(need: f64) -> u32 {
    let mut r = 4u32;
    while f64::from(r) < need {
        r *= 2;
    }
    r
}

/// Every map of the decision at its own resolution: the decision's list, the frame's maps and
/// their GPU records agree, texels are their sum of squares, and each map's error measured
/// from its matrix is the reported one.
fn check_decision(d: &Decision<'_>, inp: &FrameInput<'_>, i: usize) {
    assert_eq!(d.resolutions.len(), d.frame.slots().len(), "frame {i}");
    let mut texels = 0u64;
    for (slot, (m, &r)) in d.frame.slots().iter().zip(d.resolutions).enumerate() {
        if let Some(m) = m {
            assert_eq!(m.resolution(), r, "frame {i} slot {slot}");
            assert_eq!(m.gpu(ClipDepth::ZeroToOne).resolution, r);
            texels += u64::from(r).pow(2);
            let fd = product(m, inp) / f64::from(r);
            assert!(
                (fd - m.max_error_pixels).abs() <= 1e-5 * fd,
                "frame {i} slot {slot}: {fd} px audited, {} reported",
                m.max_error_pixels
            );
        }
    }
    assert_eq!(texels, d.texels, "frame {i}");
    assert_eq!(d.resolution, *d.resolutions.iter().max().unwrap());
}

/// The fewest texels of any allowed candidate whose maps, each at the least power of two that
/// meets the target by its audited product, all meet it when built so (audited again).
fn cheapest_by_hand(inp: &FrameInput<'_>) -> Option<u64> {
    cheapest_within(inp, u64::MAX)
}

/// [`cheapest_by_hand`] among the set-ups of at most `budget` texels.
fn cheapest_within(inp: &FrameInput<'_>, budget: u64) -> Option<u64> {
    let mut best: Option<u64> = None;
    for s in allowed() {
        let mut at_cap = inp.scheme(s);
        at_cap.map_resolution = CAP;
        let Ok(f) = frame(&at_cap) else { continue };
        if f.maps().is_empty() || f.maps().len() > 4 {
            continue;
        }
        let each: Vec<u32> = f
            .slots()
            .iter()
            .map(|m| m.as_ref().map_or(4, |m| pow2(product(m, &at_cap) / TARGET)))
            .collect();
        if each.iter().any(|&r| r > CAP) {
            continue;
        }
        let Ok(g) = frame(&at_cap.map_resolutions(&each)) else {
            continue;
        };
        let meets = g
            .maps()
            .iter()
            .all(|m| product(m, &at_cap) / f64::from(m.resolution()) <= TARGET * (1.0 + 1e-9));
        if meets {
            let t: u64 = g
                .maps()
                .iter()
                .map(|m| u64::from(m.resolution()).pow(2))
                .sum();
            if t <= budget {
                best = Some(best.map_or(t, |b: u64| b.min(t)));
            }
        }
    }
    best
}

#[test]
fn each_map_its_own_resolution_over_the_walk() {
    let boxes = scene();
    let mut each = Controller::new(options(false)).unwrap();
    let mut shared = Controller::new(options(true)).unwrap();
    let (mut texels_each, mut texels_shared) = (0u64, 0u64);
    let (mut switches, mut feasible, mut met) = (0, 0, 0);
    let retry = options(false).retry_every as usize;
    for i in 0..FRAMES {
        let inp = input(camera(i), &boxes);
        if i % 40 == 0 && i > 0 {
            each.cut();
        }
        let d = each.frame(&inp).unwrap();
        check_decision(&d, &inp, i);
        assert_eq!(d.meets_target, d.max_error_pixels <= TARGET, "frame {i}");
        switches += usize::from(d.switched);
        // Met where any allowed candidate can meet it (by hand), but, after frames where none
        // could, within the `retry_every` frames before the next search.
        let hand = cheapest_by_hand(&inp);
        feasible = if hand.is_some() { feasible + 1 } else { 0 };
        assert!(
            hand.is_none() || d.meets_target || feasible < retry,
            "frame {i}: {} px, and {hand:?} texels meet the target by hand",
            d.max_error_pixels
        );
        if let (true, Some(hand)) = (d.cut, hand) {
            assert!(
                d.texels <= hand,
                "frame {i}: a cut chose {} texels, the cheapest by hand {hand}",
                d.texels
            );
        }
        let s = shared.frame(&inp).unwrap();
        if d.meets_target && s.meets_target {
            met += 1;
            texels_each += d.texels;
            texels_shared += s.texels;
        }
    }
    // A resolution per map pays for each map's own error, not the worst map's.
    assert!(met > FRAMES / 2, "{met} frames met by both");
    assert!(
        (texels_each as f64) < 0.8 * texels_shared as f64,
        "{texels_each} texels against {texels_shared} shared"
    );
    assert!(switches <= FRAMES / 10, "{switches} switches");
}

#[test]
fn a_still_camera_keeps_each_map() {
    let boxes = scene();
    let stable: Vec<FrameScheme<'static>> = allowed()
        .into_iter()
        .filter(|s| matches!(s, FrameScheme::Stable(_)))
        .collect();
    let mut c = Controller::new(ControllerOptions {
        candidates: Some(stable),
        ..options(false)
    })
    .unwrap();
    let inp = input(camera(60), &boxes);
    let first: Vec<u32> = c.frame(&inp).unwrap().resolutions.to_vec();
    // An input's own resolutions are the controller's to choose: ignored, on a cut too.
    let odd = [7u32];
    c.cut();
    let d = c.frame(&inp.map_resolutions(&odd)).unwrap();
    assert_eq!(d.resolutions, &first[..]);
    assert!(!d.switched && d.cut);
    for i in 1..60 {
        let d = c.frame(&inp).unwrap();
        assert!(!d.switched && !d.cut, "frame {i}");
        assert_eq!(d.resolutions, &first[..], "frame {i}");
        assert!(d.frame.maps().iter().all(FrameMap::unchanged), "frame {i}");
    }
}

/// The least largest error of `products` within `budget` texels, trying every power-of-two
/// allocation from 4 to `CAP` per map (at most 4 maps).
fn least_by_hand(products: &[f64], budget: u64) -> f64 {
    let sizes: Vec<u32> = (2..=12).map(|k| 1u32 << k).collect();
    let mut best = f64::INFINITY;
    let n = products.len();
    let mut idx = vec![0usize; n];
    loop {
        let t: u64 = idx.iter().map(|&j| u64::from(sizes[j]).pow(2)).sum();
        if t <= budget {
            let e = products
                .iter()
                .zip(&idx)
                .map(|(p, &j)| p / f64::from(sizes[j]))
                .fold(0.0, f64::max);
            best = best.min(e);
        }
        let mut k = 0;
        while k < n {
            idx[k] += 1;
            if idx[k] < sizes.len() {
                break;
            }
            idx[k] = 0;
            k += 1;
        }
        if k == n {
            return best;
        }
    }
}

/// Both goals per map: the target within the budget where a set-up of at most the budget
/// meets it (then no more texels than the cheapest such by hand), else the least error within
/// the budget (every power-of-two allocation tried by hand), never over it.
#[test]
fn a_target_within_a_budget_per_map() {
    const BUDGET: u64 = 12 * 1024 * 1024;
    let boxes = scene();
    let mut c = Controller::new(ControllerOptions {
        max_texels: Some(BUDGET),
        ..options(false)
    })
    .unwrap();
    let (mut met, mut least) = (0, 0);
    for i in (0..FRAMES).step_by(20) {
        let inp = input(camera(i), &boxes);
        c.cut();
        let d = c.frame(&inp).unwrap();
        check_decision(&d, &inp, i);
        assert!(d.within_budget && d.texels <= BUDGET, "frame {i}");
        match cheapest_within(&inp, BUDGET) {
            Some(hand) => {
                assert!(d.meets_target, "frame {i}: {hand} texels meet it by hand");
                assert!(
                    d.texels <= hand,
                    "frame {i}: {} texels, {hand} by hand",
                    d.texels
                );
                met += 1;
            }
            None => {
                assert!(!d.meets_target, "frame {i}");
                let mut hand = f64::INFINITY;
                for s in allowed() {
                    let mut at_cap = inp.scheme(s);
                    at_cap.map_resolution = CAP;
                    let Ok(f) = frame(&at_cap) else { continue };
                    if f.maps().is_empty() || f.maps().len() > 4 {
                        continue;
                    }
                    let p: Vec<f64> = f.maps().iter().map(|m| product(m, &at_cap)).collect();
                    hand = hand.min(least_by_hand(&p, BUDGET));
                }
                assert!(
                    d.max_error_pixels <= hand * (1.0 + 1e-3),
                    "frame {i}: {} px, the least within the budget by hand {hand} px",
                    d.max_error_pixels
                );
                least += 1;
            }
        }
    }
    assert!(
        met > 0 && least > 0,
        "both outcomes: {met} met, {least} least"
    );
}

#[test]
fn a_budget_buys_the_least_largest_error_per_map() {
    const BUDGET: u64 = 6 * 1024 * 1024;
    let boxes = scene();
    let mut c = Controller::new(ControllerOptions {
        max_error: None,
        max_texels: Some(BUDGET),
        ..options(false)
    })
    .unwrap();
    for i in (0..FRAMES).step_by(30) {
        let inp = input(camera(i), &boxes);
        c.cut();
        let d = c.frame(&inp).unwrap();
        check_decision(&d, &inp, i);
        assert!(d.within_budget && d.texels <= BUDGET, "frame {i}");
        // Every allowed candidate's least error within the budget, by hand.
        let mut hand = f64::INFINITY;
        for s in allowed() {
            let mut at_cap = inp.scheme(s);
            at_cap.map_resolution = CAP;
            let Ok(f) = frame(&at_cap) else { continue };
            if f.maps().is_empty() || f.maps().len() > 4 {
                continue;
            }
            let p: Vec<f64> = f.maps().iter().map(|m| product(m, &at_cap)).collect();
            hand = hand.min(least_by_hand(&p, BUDGET));
        }
        assert!(
            d.max_error_pixels <= hand * (1.0 + 1e-3),
            "frame {i}: {} px chosen, {hand} px the least by hand",
            d.max_error_pixels
        );
    }
}

/// Equal-error candidates per map: planes placed at one resolution, each map then sized; the
/// decision rebuilds bit for bit from its scheme and resolutions; with every candidate allowed
/// (equal-error ones included) a resolution per map never takes more texels on a cut than one
/// shared resolution does.
#[test]
fn per_map_is_never_dearer_than_shared_on_a_cut() {
    let boxes = scene();
    let all = |shared| {
        Controller::new(ControllerOptions {
            candidates: None,
            ..options(shared)
        })
        .unwrap()
    };
    let (mut each, mut shared) = (all(false), all(true));
    for i in (0..FRAMES).step_by(40) {
        let inp = input(camera(i), &boxes);
        each.cut();
        shared.cut();
        let d = each.frame(&inp).unwrap();
        check_decision(&d, &inp, i);
        let s = shared.frame(&inp).unwrap();
        if s.meets_target {
            assert!(d.meets_target, "frame {i}");
            assert!(
                d.texels <= s.texels,
                "frame {i}: {} texels per map, {} shared",
                d.texels,
                s.texels
            );
        }
        if !matches!(
            d.scheme,
            FrameScheme::Cascades {
                splits: CascadeSplits::EqualError { .. },
                ..
            }
        ) {
            let again = frame(&inp.scheme(d.scheme).map_resolutions(d.resolutions)).unwrap();
            let a: Vec<_> = d
                .frame
                .maps()
                .iter()
                .map(|m| m.world_to_clip(ClipDepth::ZeroToOne))
                .collect();
            let b: Vec<_> = again
                .maps()
                .iter()
                .map(|m| m.world_to_clip(ClipDepth::ZeroToOne))
                .collect();
            assert_eq!(a, b, "frame {i}");
        }
    }
    // An equal-error candidate alone: its planes equalise the maps' errors at one resolution,
    // so a resolution per map gives them equal resolutions unless rounding splits them.
    let eq = FrameScheme::Cascades {
        splits: CascadeSplits::EqualError { k: 3 },
        rule: WarpRule::Uniform,
    };
    let mut c = Controller::new(ControllerOptions {
        candidates: Some(vec![eq]),
        ..options(false)
    })
    .unwrap();
    let inp = input(camera(100), &boxes);
    let d = c.frame(&inp).unwrap();
    check_decision(&d, &inp, 100);
    assert_eq!(d.scheme, eq);
}
