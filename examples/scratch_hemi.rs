use glam::DVec3;
use shadow_aliasing::build::{warp, Falloff, WarpRule};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::ViewFrustum;
fn main() {
    for (n, f, fov) in [
        (1.0, 100.0, 30.0f64),
        (1.0, 1000.0, 30.0),
        (0.1, 100.0, 60.0),
        (1.0, 10.0, 45.0),
    ] {
        let view = ViewFrustum::new(n, f, fov.to_radians()).unwrap();
        let rules = [
            WarpRule::Uniform,
            WarpRule::Minimax,
            WarpRule::MinimaxMz, WarpRule::Tsm { focus: 0.2 * (f - n) },
            WarpRule::LispsmSin,
            WarpRule::Lispsm,
            WarpRule::Barroso(Falloff::Barroso),
            WarpRule::LispsmReference,
            WarpRule::Filament,
            WarpRule::Ogre,
            WarpRule::Psm,
        ];
        let mut worse = vec![0usize; rules.len()];
        let mut worst = vec![(0.0f64, 0.0, 0.0); rules.len()];
        let mut sum_log = vec![0.0f64; rules.len()];
        let mut cnt = 0;
        for ie in 0..=45 {
            let elev = ie as f64 / 45.0 * std::f64::consts::FRAC_PI_2;
            for ia in 0..72 {
                let az = ia as f64 / 72.0 * std::f64::consts::TAU;
                let (se, ce) = elev.sin_cos();
                let l = DVec3::new(ce * az.sin(), -se, -ce * az.cos());
                let su = frustum_max(
                    &view,
                    &warp(&view, l, WarpRule::Uniform).unwrap().shadow_map(),
                )
                .unwrap()
                .storage_factor;
                cnt += 1;
                for (k, r) in rules.iter().enumerate() {
                    let s = frustum_max(&view, &warp(&view, l, *r).unwrap().shadow_map())
                        .unwrap()
                        .storage_factor;
                    sum_log[k] += (s / su).ln();
                    if s > su * (1.0 + 1e-9) {
                        worse[k] += 1;
                        if s / su > worst[k].0 {
                            worst[k] = (s / su, elev.to_degrees(), az.to_degrees());
                        }
                    }
                }
            }
        }
        println!("n={n} f={f} fov={fov}");
        for (k, r) in rules.iter().enumerate() {
            println!("  {:?}: worse-than-uniform {} / {cnt}, worst ratio {:.4} at elev {:.1} az {:.1}, geo-mean ratio {:.4}", r, worse[k], worst[k].0, worst[k].1, worst[k].2, (sum_log[k]/cnt as f64).exp());
        }
    }
}
#[allow(dead_code)]
fn jumps() {}
