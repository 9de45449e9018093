//! The error lens drawn by Bevy (docs/bevy.md, "The error lens"), headless on Vulkan (lavapipe
//! without a GPU): the test scene with [`ErrorLens`] on the camera, for Bevy's own cascades
//! (measure mode) and the plugin's (budget mode); at sampled pixels the value the overlay's
//! colour encodes is compared with the lens measured here by finite differences of the matrix
//! Bevy holds and of Bevy's camera on the exact surface (a ray cast), without the crate's lens
//! code.
//!
//! `SHADOW_ALIASING_BEVY_IMAGES=<dir>` also writes the overlay at its default opacity
//! (`lens_bevy.png`, `lens_budget.png`), the screenshots of docs/bevy.md.

mod harness;
mod scene;

use bevy::camera::Hdr;
use bevy::light::{CascadeShadowConfig, Cascades, DirectionalLightShadowMap};
use bevy::prelude::*;
use bevy::render::view::Msaa;
use bevy::render::RenderPlugin;
use harness::{ray_box, Harness, H, W};
use scene::BOXES;
use shadow_aliasing::frame::lens::LENS_RAMP;
use shadow_aliasing::glam::{DMat2, DMat4, DVec2, DVec3, DVec4, Mat4 as SaMat4};
use shadow_aliasing_bevy::{Budget, CascadeMode, ErrorLens, ErrorLensMaps};

const RES: usize = 2048;
/// Sampled pixels: every STEP-th in each direction.
const STEP: u32 = 3;

/// What a render left: the pixels and the cascades Bevy drew them with.
struct Capture {
    pixels: Vec<u8>,
    /// Per cascade: Bevy's world → light clip (`Cascade::clip_from_world`) and far bound.
    cascades: Vec<(DMat4, f64)>,
    /// Bevy's camera: world → clip.
    clip_from_world: DMat4,
    /// The camera's position and unit view axis.
    eye: DVec3,
    forward: DVec3,
    resolution: f64,
    maps: ErrorLensMaps,
}

fn to_dmat4(m: &Mat4) -> DMat4 {
    SaMat4::from_cols_array_2d(&m.to_cols_array_2d()).as_dmat4()
}

/// The test scene with the lens on the camera at `RES`² maps.
fn harness() -> Harness {
    let mut h = Harness::new(RenderPlugin::default(), RES);
    h.app.world_mut().entity_mut(h.camera).insert(ErrorLens {
        opacity: 1.0,
        ..default()
    });
    h
}

/// Renders with `mode`, `msaa`, an HDR view or not and the lens at `opacity` until two
/// read-back frames agree.
fn render(h: &mut Harness, mode: &CascadeMode, msaa: Msaa, hdr: bool, opacity: f32) -> Capture {
    {
        let world = h.app.world_mut();
        *world.get_mut::<CascadeMode>(h.light).unwrap() = mode.clone();
        world.get_mut::<ErrorLens>(h.camera).unwrap().opacity = opacity;
        *world.get_mut::<Msaa>(h.camera).unwrap() = msaa;
        if hdr {
            world.entity_mut(h.camera).insert(Hdr);
        } else {
            world.entity_mut(h.camera).remove::<Hdr>();
        }
    }
    let pixels = h.settle();
    let world = h.app.world();
    let cascades = &world.get::<Cascades>(h.light).unwrap().cascades[&h.camera];
    let config = world.get::<CascadeShadowConfig>(h.light).unwrap();
    let camera = world.get::<Camera>(h.camera).unwrap();
    let transform = world.get::<GlobalTransform>(h.camera).unwrap();
    let clip_from_world =
        to_dmat4(&camera.clip_from_view()) * to_dmat4(&transform.to_matrix()).inverse();
    Capture {
        pixels,
        cascades: cascades
            .iter()
            .zip(&config.bounds)
            .map(|(c, &f)| (to_dmat4(&c.clip_from_world), f64::from(f)))
            .collect(),
        clip_from_world,
        eye: DVec3::from_array(transform.translation().as_dvec3().to_array()),
        forward: DVec3::from_array(transform.forward().as_dvec3().to_array()),
        resolution: world.resource::<DirectionalLightShadowMap>().size as f64,
        maps: world.get::<ErrorLensMaps>(h.camera).unwrap().clone(),
    }
}

/// The first surface the ray meets: the point, the face's outward normal and a face key.
fn first_hit(o: DVec3, d: DVec3) -> Option<(DVec3, DVec3, (usize, usize, i8))> {
    BOXES
        .iter()
        .enumerate()
        .filter_map(|(i, b)| ray_box(o, d, b).map(|h| (h, i)))
        .min_by(|a, b| a.0 .0.total_cmp(&b.0 .0))
        .map(|((t, axis, sign), i)| {
            let mut n = DVec3::ZERO;
            n[axis] = sign;
            (o + d * t, n, (i, axis, sign as i8))
        })
}

/// The world ray through image point (x, y) (pixels, y down) of Bevy's camera.
fn ray(clip_from_world: &DMat4, x: f64, y: f64) -> (DVec3, DVec3) {
    let inv = clip_from_world.inverse();
    let ndc = DVec2::new(2.0 * x / f64::from(W) - 1.0, 1.0 - 2.0 * y / f64::from(H));
    let near = inv * DVec4::new(ndc.x, ndc.y, 1.0, 1.0);
    let far = inv * DVec4::new(ndc.x, ndc.y, 0.5, 1.0);
    let (a, b) = (near.truncate() / near.w, far.truncate() / far.w);
    (a, b - a)
}

/// The lens measured here: at the surface point p with normal n, the surface parametrised by two
/// orthonormal tangents; J_S, the map's NDC (s, t) per unit step along them, and J_P, the
/// camera's pixels per unit step, by central differences of the two matrices; one texel is 2/res
/// of NDC, so the pixels one texel step spans are (2/res) J_P J_S⁻¹, whose larger singular value
/// is the lens.
fn lens_by_differences(map: &DMat4, camera: &DMat4, res: f64, p: DVec3, n: DVec3) -> f64 {
    let (u, v) = n.any_orthonormal_pair();
    let ndc = |m: &DMat4, x: DVec3| {
        let c = *m * x.extend(1.0);
        DVec2::new(c.x / c.w, c.y / c.w)
    };
    let pixel = |x: DVec3| {
        let q = ndc(camera, x);
        DVec2::new(
            0.5 * (q.x + 1.0) * f64::from(W),
            0.5 * (1.0 - q.y) * f64::from(H),
        )
    };
    let h = 1e-4;
    let diff = |f: &dyn Fn(DVec3) -> DVec2, e: DVec3| (f(p + e * h) - f(p - e * h)) / (2.0 * h);
    let map_at = |x: DVec3| ndc(map, x);
    let js = DMat2::from_cols(diff(&map_at, u), diff(&map_at, v));
    let jp = DMat2::from_cols(diff(&pixel, u), diff(&pixel, v));
    let m = jp * js.inverse() * (2.0 / res);
    let (a, b) = (m.x_axis, m.y_axis);
    let f2 = a.length_squared() + b.length_squared();
    let det = m.determinant();
    (0.5 * (f2 + (f2 * f2 - 4.0 * det * det).max(0.0).sqrt())).sqrt()
}

/// The lens value a colour of the ramp encodes (sRGB bytes): the nearest point of the ramp's
/// nine segments (viridis between the values 2^(i − 4) and 2^(i − 3)), or `None` where the colour
/// is more than 3 units from the ramp or at a clamped end (at most 1/16 or at least 32 pixels).
fn decode(rgb: [u8; 3]) -> Option<f64> {
    let c = DVec3::new(f64::from(rgb[0]), f64::from(rgb[1]), f64::from(rgb[2]));
    let col = |k: usize| {
        DVec3::new(
            f64::from(LENS_RAMP[k][0]),
            f64::from(LENS_RAMP[k][1]),
            f64::from(LENS_RAMP[k][2]),
        )
    };
    let (mut best, mut at) = (f64::INFINITY, 0.0);
    for i in 0..LENS_RAMP.len() - 1 {
        let (a, b) = (col(i), col(i + 1));
        let f = ((c - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
        let d = (a + (b - a) * f - c).length();
        if d < best {
            (best, at) = (d, i as f64 + f);
        }
    }
    (best <= 3.0 && at > 0.0 && at < 9.0).then(|| (at - 4.0).exp2())
}

/// The legend's panel (src/lens.wgsl, `legend_geometry` at u = 1 for a 360-pixel view): columns
/// 4 to 427, rows 316 to 351 from the top.
fn in_legend(x: u32, y: u32) -> bool {
    x < 432 && y >= 312
}

#[derive(Debug, Default)]
struct Tally {
    compared: usize,
    per_cascade: [usize; 4],
    vertical: usize,
    worst: f64,
    /// The lens by differences at every compared pixel.
    values: Vec<f64>,
    wrong: Vec<(u32, u32, f64, Option<f64>)>,
}

/// The overlay's value against the lens by differences at every sampled pixel whose ray meets a
/// face that its pixel's corners also meet, more than 3° from edge-on to the light (where the
/// lens is unbounded), inside one cascade's depth range (0.2 % from its far bound) and on its map,
/// the value within the ramp's range.
fn compare(cap: &Capture) -> Tally {
    let mut t = Tally::default();
    let (eye, forward) = (cap.eye, cap.forward);
    let l = DVec3::from_array(scene::sun_dir().as_dvec3().to_array()).normalize();
    for y in (1..H).step_by(STEP as usize) {
        for x in (1..W).step_by(STEP as usize) {
            if in_legend(x, y) {
                continue;
            }
            let (o, d) = ray(&cap.clip_from_world, f64::from(x) + 0.5, f64::from(y) + 0.5);
            let Some((p, n, face)) = first_hit(o, d) else {
                continue;
            };
            let same = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)]
                .iter()
                .all(|&(a, b)| {
                    let (o, d) = ray(&cap.clip_from_world, f64::from(x) + a, f64::from(y) + b);
                    first_hit(o, d).is_some_and(|h| h.2 == face)
                });
            if !same || n.dot(l).abs() < 0.05 {
                continue;
            }
            let z = (p - eye).dot(forward);
            if cap.cascades.iter().any(|c| (z - c.1).abs() < 2e-3 * c.1) {
                continue;
            }
            let Some(i) = cap.cascades.iter().position(|c| z < c.1) else {
                continue;
            };
            let c = cap.cascades[i].0 * p.extend(1.0);
            let q = c.truncate() / c.w;
            if q.x.abs() > 0.999 || q.y.abs() > 0.999 || q.z < 1e-3 || q.z > 0.999 {
                continue;
            }
            let want = lens_by_differences(
                &cap.cascades[i].0,
                &cap.clip_from_world,
                cap.resolution,
                p,
                n,
            );
            if !(want > 0.07 && want < 29.0) {
                continue;
            }
            let k = ((y * W + x) * 4) as usize;
            let got = decode([cap.pixels[k], cap.pixels[k + 1], cap.pixels[k + 2]]);
            let rel = got.map_or(f64::INFINITY, |g| (g / want - 1.0).abs());
            t.compared += 1;
            t.values.push(want);
            t.per_cascade[i] += 1;
            if n.y == 0.0 {
                t.vertical += 1;
            }
            t.worst = t.worst.max(rel);
            if rel > 0.03 {
                t.wrong.push((x, y, want, got));
            }
        }
    }
    t
}

/// The legend's ramp shows the ten colours at their columns (24 + 40 k, row 326 from the top).
fn check_legend(cap: &Capture, name: &str) {
    for (k, want) in LENS_RAMP.iter().enumerate() {
        let (x, y) = (24 + 40 * k as u32, H - 34);
        let i = ((y * W + x) * 4) as usize;
        let got = &cap.pixels[i..i + 3];
        let off = got
            .iter()
            .zip(want)
            .map(|(a, b)| (i32::from(*a) - i32::from(*b)).abs())
            .max()
            .unwrap();
        assert!(
            off <= 2,
            "{name}: the legend's colour {k} at ({x}, {y}) is {got:?}, not {want:?}"
        );
    }
}

fn save(name: &str, cap: &Capture) {
    let Some(dir) = std::env::var_os("SHADOW_ALIASING_BEVY_IMAGES") else {
        return;
    };
    let path = std::path::Path::new(&dir).join(format!("{name}.png"));
    image::save_buffer(&path, &cap.pixels, W, H, image::ExtendedColorType::Rgba8)
        .unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
}

#[test]
fn the_overlay_draws_the_lens_of_bevys_and_the_budgets_cascades() {
    let mut h = harness();
    let budget = CascadeMode::Budget(Budget::new(0.75));
    // The prepass is multisampled under MSAA: the pass reads its first sample. An HDR view
    // (without tone mapping) holds the image in a float texture until Bevy's upscaling pass.
    let modes = [
        ("bevy", CascadeMode::Measure, Msaa::Off, false),
        ("budget", budget.clone(), Msaa::Off, false),
        ("budget_msaa4", budget.clone(), Msaa::Sample4, false),
        ("budget_hdr", budget, Msaa::Off, true),
    ];
    for (name, mode, msaa, hdr) in &modes {
        let cap = render(&mut h, mode, *msaa, *hdr, 1.0);
        assert_eq!(cap.maps.light, Some(h.light), "{name}");
        assert_eq!(cap.maps.maps.len(), cap.cascades.len(), "{name}");
        check_legend(&cap, name);
        let t = compare(&cap);
        let mut sorted = t.values.clone();
        sorted.sort_by(f64::total_cmp);
        let median = sorted.get(sorted.len() / 2).copied().unwrap_or(f64::NAN);
        let measured = cap
            .maps
            .maps
            .iter()
            .map(|m| m.max_error_pixels)
            .fold(0.0f32, f32::max);
        println!(
            "{name}: {} cascades, measured max error {measured:.3} px; lens median {:.3}, max \
             {:.3} px; {} pixels compared (per cascade {:?}, {} on vertical faces), largest \
             relative difference {:.4}",
            cap.cascades.len(),
            median,
            t.values.iter().copied().fold(0.0, f64::max),
            t.compared,
            t.per_cascade,
            t.vertical,
            t.worst
        );
        for w in t.wrong.iter().take(10) {
            println!(
                "  ({}, {}): differences {:.4}, overlay {:?}",
                w.0, w.1, w.2, w.3
            );
        }
        assert!(
            t.wrong.is_empty(),
            "{name}: {} pixels off by more than 3 %",
            t.wrong.len()
        );
        assert!(t.compared > 2000 && t.vertical > 100, "{name}: {t:?}");
        assert!(
            t.per_cascade.iter().filter(|&&c| c > 50).count() >= 2,
            "{name}: {t:?}"
        );
        if std::env::var_os("SHADOW_ALIASING_BEVY_IMAGES").is_some() && *msaa == Msaa::Off && !hdr {
            let shot = render(&mut h, mode, *msaa, *hdr, ErrorLens::default().opacity);
            save(&format!("lens_{name}"), &shot);
        }
    }
}
