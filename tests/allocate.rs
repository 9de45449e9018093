//! Texel allocation by error (`plan::allocate`, issue 24 item 2) against brute force: every
//! allocation of small budgets enumerated, the least largest error compared.

mod common;

use common::Lcg;
use shadow_aliasing::plan::allocate::{
    allocate, allocate_atlas, continuous_error, MapError, Rounding,
};

/// The allowed resolutions up to `max` (brute force's own list, not the library's rounding).
fn allowed(rounding: Rounding, max: u64) -> Vec<u64> {
    (1..=max)
        .filter(|&r| match rounding {
            Rounding::Whole => true,
            Rounding::PowerOfTwo => r.is_power_of_two(),
            Rounding::Multiple(m) => r % u64::from(m) == 0,
        })
        .collect()
}

/// The least largest error over every allocation of `maps` within `budget` texels.
fn brute(maps: &[MapError], h: f64, budget: u64, values: &[u64]) -> Option<f64> {
    fn rec(maps: &[MapError], h: f64, left: u64, values: &[u64], worst: f64, best: &mut f64) {
        let Some((m, rest)) = maps.split_first() else {
            *best = best.min(worst);
            return;
        };
        for &s in values {
            for &t in values {
                if s * t > left {
                    break;
                }
                let e = (m.max_mx * h / s as f64).max(m.max_mz * h / t as f64);
                if e.max(worst) < *best {
                    rec(rest, h, left - s * t, values, e.max(worst), best);
                }
            }
        }
    }
    let mut best = f64::INFINITY;
    rec(maps, h, budget, values, 0.0, &mut best);
    best.is_finite().then_some(best)
}

fn random_maps(rng: &mut Lcg, n: usize) -> Vec<MapError> {
    (0..n)
        .map(|_| MapError {
            max_mx: 0.05 + 3.0 * rng.next(),
            max_mz: 0.05 + 3.0 * rng.next(),
        })
        .collect()
}

#[test]
fn least_largest_error_matches_brute_force() {
    let mut rng = Lcg(24);
    let mut cases = 0;
    for (n, budgets) in [(2usize, 2u64..=48), (3, 3..=24), (4, 4..=14)] {
        for budget in budgets {
            for rounding in [Rounding::Whole, Rounding::PowerOfTwo, Rounding::Multiple(2)] {
                let maps = random_maps(&mut rng, n);
                let h = 1.0 + (7.0 * rng.next()).floor();
                let values = allowed(rounding, budget);
                let want = brute(&maps, h, budget, &values);
                let got = allocate(&maps, h as u32, budget, rounding);
                match (want, got) {
                    (None, Err(e)) => assert!(e.to_string().starts_with("budget_texels "), "{e}"),
                    (Some(w), Ok(a)) => {
                        cases += 1;
                        assert!(
                            (a.max_error_pixels - w).abs() <= 1e-12 * w,
                            "{n} maps, {budget} texels, {rounding:?}: {} vs brute force {w}",
                            a.max_error_pixels
                        );
                        assert!(a.texels <= budget);
                        let sum: u64 = a.maps().iter().map(|m| m.res_s * m.res_t).sum();
                        assert_eq!(sum, a.texels);
                        for (m, r) in maps.iter().zip(a.maps()) {
                            assert!(values.contains(&r.res_s) && values.contains(&r.res_t));
                            let e =
                                (m.max_mx * h / r.res_s as f64).max(m.max_mz * h / r.res_t as f64);
                            assert!((e - r.error_pixels).abs() <= 1e-15 * e);
                        }
                    }
                    (w, g) => {
                        panic!("{n} maps, {budget}, {rounding:?}: brute {w:?}, allocate {g:?}")
                    }
                }
            }
        }
    }
    assert!(cases > 150, "{cases}");
}

/// Large budgets: the allocation tends to Lloyd 2005 Eq 6 generalised, each resolution
/// proportional to its unit-resolution error and every error E = H √(Σ S̄ / T), computed here by
/// hand; never below it.
#[test]
fn large_budgets_approach_equal_errors() {
    let maps = [
        MapError {
            max_mx: 1.0,
            max_mz: 3.0,
        },
        MapError {
            max_mx: 2.0,
            max_mz: 0.5,
        },
        MapError {
            max_mx: 0.7,
            max_mz: 0.7,
        },
    ];
    let h = 1080u32;
    for budget in [1u64 << 20, 1 << 24, 1 << 28] {
        let s_bar = 1.0 * 3.0 + 2.0 * 0.5 + 0.7 * 0.7;
        let e = 1080.0 * (s_bar / budget as f64).sqrt();
        assert!((continuous_error(&maps, h, budget).unwrap() - e).abs() <= 1e-12 * e);
        let a = allocate(&maps, h, budget, Rounding::Whole).unwrap();
        assert!(a.max_error_pixels >= e * (1.0 - 1e-12));
        // Rounding up by at most one texel per axis: within 2/res of E.
        let res_min = a.maps().iter().map(|m| m.res_s.min(m.res_t)).min().unwrap() as f64;
        assert!(a.max_error_pixels <= e * (1.0 + 2.0 / res_min), "{budget}");
        for (m, r) in maps.iter().zip(a.maps()) {
            let want_s = m.max_mx * 1080.0 / e;
            assert!(
                (r.res_s as f64 - want_s).abs() <= 0.02 * want_s + 1.0,
                "{r:?}"
            );
        }
    }
}

/// In an atlas: the least largest error over every split of the width into columns (brute force),
/// and the viewports tile the atlas left to right.
#[test]
fn atlas_columns_match_brute_force() {
    fn splits(n: usize, width: u32) -> Vec<Vec<u32>> {
        if n == 1 {
            return vec![vec![width]];
        }
        (1..width)
            .flat_map(|w| {
                splits(n - 1, width - w).into_iter().map(move |mut rest| {
                    rest.insert(0, w);
                    rest
                })
            })
            .collect()
    }
    let mut rng = Lcg(7);
    for n in 1..=4usize {
        for width in n as u32..=24 {
            let maps = random_maps(&mut rng, n);
            let (h, height) = (720.0, 1 + (rng.next() * 30.0) as u32);
            let best = splits(n, width)
                .iter()
                .map(|ws| {
                    maps.iter()
                        .zip(ws)
                        .map(|(m, &w)| {
                            (m.max_mx * h / f64::from(w)).max(m.max_mz * h / f64::from(height))
                        })
                        .fold(0.0, f64::max)
                })
                .fold(f64::INFINITY, f64::min);
            let (a, vps) = allocate_atlas(&maps, 720, width, height).unwrap();
            assert!(
                (a.max_error_pixels - best).abs() <= 1e-12 * best,
                "{n} maps in {width}: {} vs {best}",
                a.max_error_pixels
            );
            let mut x = 0;
            for (r, v) in a.maps().iter().zip(&vps[..n]) {
                assert_eq!((v.x, v.y, v.height), (x, 0, height));
                assert_eq!(u64::from(v.width), r.res_s);
                x += v.width;
            }
            assert_eq!(x, width);
        }
    }
}

#[test]
fn bad_input_is_refused_by_name() {
    let ok = [MapError {
        max_mx: 1.0,
        max_mz: 1.0,
    }];
    let cases: Vec<(Result<_, _>, &str)> = vec![
        (allocate(&[], 1080, 100, Rounding::Whole), "maps "),
        (
            allocate(
                &[MapError {
                    max_mx: f64::NAN,
                    max_mz: 1.0,
                }],
                1080,
                100,
                Rounding::Whole,
            ),
            "maps ",
        ),
        (allocate(&ok, 0, 100, Rounding::Whole), "image_height "),
        (allocate(&ok, 1080, 100, Rounding::Multiple(0)), "rounding "),
        (
            allocate(&ok, 1080, 3, Rounding::Multiple(2)),
            "budget_texels ",
        ),
        (allocate(&ok, 1080, 0, Rounding::Whole), "budget_texels "),
    ];
    for (r, name) in cases {
        let e = r.unwrap_err().to_string();
        assert!(e.starts_with(name), "{e}");
    }
    assert!(allocate_atlas(&[ok[0], ok[0]], 1080, 1, 10)
        .unwrap_err()
        .to_string()
        .starts_with("width "));
    assert!(allocate_atlas(&ok, 1080, 10, 0)
        .unwrap_err()
        .to_string()
        .starts_with("height "));
}
