//! The tables of docs/builders.md: for each n′ rule, over a 46 × 72 grid of the hemisphere of
//! light directions, in how many directions its measured storage factor S̄ exceeds the uniform
//! map's, the worst ratio and where, and the geometric mean of the ratio.
//!
//! Elevation 0° (horizon) to 90° (overhead) in 2° steps; azimuth 0° (light from behind the viewer)
//! to 355° in 5° steps. Run with `cargo run --release --example rule_table`.

use glam::DVec3;
use shadow_aliasing::maps::{warp, Falloff, WarpRule};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::{Result, ViewFrustum};

fn main() -> Result<()> {
    for (n, f, fov) in [
        (1.0, 100.0, 30.0f64),
        (1.0, 1000.0, 30.0),
        (0.1, 100.0, 60.0),
    ] {
        let view = ViewFrustum::new(n, f, fov.to_radians())?;
        let rules = [
            WarpRule::Minimax,
            WarpRule::MinimaxMz,
            WarpRule::Lispsm,
            WarpRule::Barroso(Falloff::Barroso),
            WarpRule::LispsmReference,
            WarpRule::Filament,
            WarpRule::Tsm {
                focus: 0.2 * (f - n),
            },
            WarpRule::LispsmFixed,
            WarpRule::Ogre,
            WarpRule::OgreOrtho {
                shadow_distance: 300.0 * n,
            },
            WarpRule::Psm,
        ];
        let mut worse = [0usize; 11];
        let mut worst = [(0.0f64, 0usize, 0usize); 11];
        let mut sum_log = [0.0f64; 11];
        let mut count = 0usize;
        for ie in 0..=45 {
            let elev = (2.0 * ie as f64).to_radians();
            for ia in 0..72 {
                let az = (5.0 * ia as f64).to_radians();
                let (se, ce) = elev.sin_cos();
                let l = DVec3::new(ce * az.sin(), -se, -ce * az.cos());
                let sbar = |r: WarpRule| -> Result<f64> {
                    Ok(frustum_max(&view, &warp(&view, l, r)?.shadow_map())?.storage_factor)
                };
                let su = sbar(WarpRule::Uniform)?;
                count += 1;
                for (k, r) in rules.iter().enumerate() {
                    let ratio = sbar(*r)? / su;
                    sum_log[k] += ratio.ln();
                    if ratio > 1.0 + 1e-9 {
                        worse[k] += 1;
                        if ratio > worst[k].0 {
                            worst[k] = (ratio, 2 * ie, 5 * ia);
                        }
                    }
                }
            }
        }
        println!("\nn = {n}, f = {f}, θ = {fov}°\n");
        println!("| rule | worse in | worst ratio (elevation, azimuth) | geometric mean |");
        println!("|---|---|---|---|");
        for (k, r) in rules.iter().enumerate() {
            let w = if worse[k] == 0 {
                "—".to_string()
            } else {
                format!("{:.3} ({}°, {}°)", worst[k].0, worst[k].1, worst[k].2)
            };
            let name = match r {
                WarpRule::Tsm { .. } => "Tsm { focus: 0.2 (f − n) }".to_string(),
                other => format!("{other:?}"),
            };
            println!(
                "| `{name}` | {} / {count} | {w} | {:.4} |",
                worse[k],
                (sum_log[k] / count as f64).exp()
            );
        }
    }
    Ok(())
}
