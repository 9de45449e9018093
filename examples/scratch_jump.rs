//! scratch
use glam::DVec3;
use shadow_aliasing::build::tsm::{tsm, TsmOptions, TsmSearch};
use shadow_aliasing::build::{warp, WarpRule};
use shadow_aliasing::measure::frustum_max;
use shadow_aliasing::ViewFrustum;
fn main() {
    let view = ViewFrustum::new(1.0, 100.0, 30f64.to_radians()).unwrap();
    let sb = |l: DVec3, r: WarpRule| frustum_max(&view, &warp(&view, l, r).unwrap().shadow_map()).unwrap().storage_factor;
    for s in [0.0199999, 0.0200001] {
        let e: f64 = (s as f64).asin();
        for l in [DVec3::new(0.0, -e.sin(), -e.cos()), DVec3::new(0.0, -e.sin(), e.cos())] {
            println!("filament sin={s} l={l}: S̄ {} (uniform {}) n'={:?}", sb(l, WarpRule::Filament), sb(l, WarpRule::Uniform), warp(&view, l, WarpRule::Filament).unwrap().n_prime);
        }
    }
    for l in [DVec3::NEG_Z, DVec3::new(0.0, -1e-6, -1.0), DVec3::new(1e-6, -1e-6, -1.0), DVec3::new(1e-6, 0.0, -1.0), DVec3::Z, DVec3::new(0.0, -1e-6, 1.0)] {
        let t = tsm(&view, l, TsmOptions{focus: 20.0, search: TsmSearch::EightyPercent}).unwrap();
        println!("tsm l={l}: S̄ {} n'={:?} ogre S̄ {} ogre n' {:?}", frustum_max(&view, &t.shadow.shadow_map()).unwrap().storage_factor, t.shadow.n_prime, sb(l, WarpRule::Ogre), warp(&view, l, WarpRule::Ogre).unwrap().n_prime);
    }
    for deg in [0.01f64, 0.05, 0.06, 0.1, 1.0] {
        let e = deg.to_radians();
        let l = DVec3::new(0.0, -e.sin(), -e.cos());
        let t = tsm(&view, l, TsmOptions{focus: 20.0, search: TsmSearch::EightyPercent}).unwrap();
        println!("tsm {deg}°: S̄ {} n'={:?}", frustum_max(&view, &t.shadow.shadow_map()).unwrap().storage_factor, t.shadow.n_prime);
    }
}
