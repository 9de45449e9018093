//! The headless render on Vulkan (lavapipe without a GPU: scripts/test.sh installs it): the test
//! scene with Bevy's default cascades and with the plugin's replacements, read back and checked
//! pixel by pixel against exact ray casts, and each replacement's measured error against
//! Bevy's at the same map size (docs/bevy.md, "The test scene").
//!
//! `SHADOW_ALIASING_BEVY_IMAGES=<dir>` writes each render there as a PNG.

mod harness;
mod scene;

use bevy::light::{CascadeShadowConfig, Cascades};
use bevy::prelude::*;
use bevy::render::settings::{WgpuFeatures, WgpuSettings};
use bevy::render::RenderPlugin;
use harness::{ray_box, Harness, H, W};
use scene::{camera_transform, sun_dir, BOXES, FOV};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::glam::{DMat4, DVec3, Mat4 as SaMat4};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing_bevy::{
    CascadeErrors, CascadeMode, CascadeSource, Fit, Replace, ReplacedCascades,
    ShadowAliasingSettings, Splits, ViewCascadeErrors,
};
use std::time::Instant;

/// Bevy's default shadow map size.
const RES: usize = 2048;
/// Sampled pixels: every STEP-th in each direction.
const STEP: u32 = 2;

/// The scene on Vulkan with `res`² shadow maps; `clip_control: false` disables the device
/// feature `DEPTH_CLIP_CONTROL`, so that Bevy emulates unclipped depth in the shadow pass.
fn harness(clip_control: bool, res: usize) -> Harness {
    let disabled = if clip_control {
        WgpuFeatures::empty()
    } else {
        WgpuFeatures::DEPTH_CLIP_CONTROL
    };
    Harness::new(
        RenderPlugin {
            render_creation: WgpuSettings {
                disabled_features: Some(disabled),
                ..default()
            }
            .into(),
            ..default()
        },
        res,
    )
}

/// Renders with `mode` (shadows off with `None`) until two read-back frames agree.
fn render(h: &mut Harness, mode: Option<CascadeMode>) -> Capture {
    {
        let world = h.app.world_mut();
        let mut light = world.entity_mut(h.light);
        light
            .get_mut::<DirectionalLight>()
            .unwrap()
            .shadow_maps_enabled = mode.is_some();
        *light.get_mut::<CascadeMode>().unwrap() = mode.unwrap_or_default();
    }
    let pixels = h.settle();
    let world = h.app.world();
    let errors = world.get::<CascadeErrors>(h.light).unwrap();
    let cascades = world.get::<Cascades>(h.light).unwrap();
    let config = world.get::<CascadeShadowConfig>(h.light).unwrap();
    let light = world.get::<DirectionalLight>(h.light).unwrap();
    let texels = cascades
        .cascades
        .get(&h.camera)
        .map(|c| c.iter().map(|c| f64::from(c.texel_size)).collect())
        .unwrap_or_default();
    Capture {
        pixels,
        errors: errors.views.get(&h.camera).cloned(),
        texels,
        far: config.bounds.iter().map(|b| f64::from(*b)).collect(),
        overlap: f64::from(config.overlap_proportion),
        normal_bias: f64::from(light.shadow_normal_bias),
        depth_bias: f64::from(light.shadow_depth_bias),
    }
}

struct Capture {
    pixels: Vec<u8>,
    errors: Option<ViewCascadeErrors>,
    texels: Vec<f64>,
    far: Vec<f64>,
    overlap: f64,
    /// The light's `shadow_normal_bias` and `shadow_depth_bias` as drawn.
    normal_bias: f64,
    depth_bias: f64,
}

fn srgb_to_linear(c: u8) -> f64 {
    let c = f64::from(c) / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

impl Capture {
    fn green(&self, x: u32, y: u32) -> f64 {
        srgb_to_linear(self.pixels[((y * W + x) * 4 + 1) as usize])
    }
    /// The largest texel of the cascades the shader may read at view depth `z` (the selected one
    /// and, in its cross-fade band, the next: bevy_pbr's `fetch_directional_shadow`); `None`
    /// beyond the last far bound (no shadow there).
    fn texel_at(&self, z: f64) -> Option<f64> {
        let i = self.far.iter().position(|&f| z < f)?;
        let mut t = self.texels[i];
        if i + 1 < self.far.len() && z >= (1.0 - self.overlap) * self.far[i] {
            t = t.max(self.texels[i + 1]);
        }
        Some(t)
    }
}

/// A ray's first hit: distance, box index, face axis and sign.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Hit {
    t: f64,
    bx: usize,
    axis: usize,
    sign: f64,
}

fn first_hit(o: DVec3, d: DVec3) -> Option<Hit> {
    BOXES
        .iter()
        .enumerate()
        .filter_map(|(i, b)| {
            ray_box(o, d, b).map(|(t, axis, sign)| Hit {
                t,
                bx: i,
                axis,
                sign,
            })
        })
        .min_by(|a, b| a.t.total_cmp(&b.t))
}

/// The exact shadow state at a point of a face with outward normal `n`: whether the ray toward
/// the sun meets a box (the pole included).
fn occluded(p: DVec3, n: DVec3, to_sun: DVec3) -> bool {
    let o = p + n * 1e-6;
    BOXES.iter().any(|b| ray_box(o, to_sun, b).is_some())
}

fn normal(h: &Hit) -> DVec3 {
    let mut n = DVec3::ZERO;
    n[h.axis] = h.sign;
    n
}

/// Whether `q` lies on the open part of the face `h` hit: inside its rectangle and not under
/// another box standing on it (the ground beneath a box is no surface the light can reach, yet a
/// ray cast from inside that box would leave it unblocked: `ray_box` counts only entries ahead).
fn on_face(q: DVec3, h: &Hit) -> bool {
    let b = &BOXES[h.bx];
    let lifted = q + normal(h) * 1e-6;
    (0..3).all(|k| k == h.axis || (q[k] >= b.min[k] && q[k] <= b.max[k]))
        && !BOXES
            .iter()
            .any(|o| (0..3).all(|k| lifted[k] > o.min[k] && lifted[k] < o.max[k]))
}

struct Eye {
    to_world: DMat4,
    tan: f64,
    aspect: f64,
}

impl Eye {
    fn new() -> Self {
        let t = camera_transform().to_matrix();
        Self {
            to_world: SaMat4::from_cols_array_2d(&t.to_cols_array_2d()).as_dmat4(),
            tan: (0.5 * f64::from(FOV)).tan(),
            aspect: f64::from(W) / f64::from(H),
        }
    }
    /// The world ray through image point (x, y) (pixels, y down): origin, direction.
    fn ray(&self, x: f64, y: f64) -> (DVec3, DVec3) {
        let nx = 2.0 * x / f64::from(W) - 1.0;
        let ny = 1.0 - 2.0 * y / f64::from(H);
        let d = DVec3::new(nx * self.tan * self.aspect, ny * self.tan, -1.0);
        (
            self.to_world.transform_point3(DVec3::ZERO),
            self.to_world.transform_vector3(d),
        )
    }
}

#[derive(Debug, Default)]
struct Tally {
    compared: usize,
    shadowed: usize,
    by_pole: usize,
    wrong: Vec<(u32, u32, bool, f64)>,
}

/// The render's shadow state at every sampled pixel where the exact state is the same over the
/// disc of the surface a lookup may reach (the light's normal bias times Bevy's √2 in texels, the
/// 2×2 hardware filter and one texel of rounding, at least 5 texels (Bevy's default 1.8 gives
/// 4.55), plus the depth bias, each spread by 1/cos of the light's incidence), compared with the
/// exact ray cast.
fn compare(cap: &Capture, reference: &Capture, cam: &Eye) -> Tally {
    let to_sun = -DVec3::from_array(sun_dir().as_dvec3().to_array()).normalize();
    let eye = cam.to_world.transform_point3(DVec3::ZERO);
    let forward = cam.to_world.transform_vector3(DVec3::NEG_Z);
    let mut tally = Tally::default();
    for y in (0..H).step_by(STEP as usize) {
        for x in (0..W).step_by(STEP as usize) {
            let (o, d) = cam.ray(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let Some(h) = first_hit(o, d) else { continue };
            // Silhouettes: the pixel's corners must see the same face.
            let same = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)]
                .iter()
                .all(|&(a, b)| {
                    let (o, d) = cam.ray(f64::from(x) + a, f64::from(y) + b);
                    first_hit(o, d)
                        .is_some_and(|g| (g.bx, g.axis, g.sign) == (h.bx, h.axis, h.sign))
                });
            let n = normal(&h);
            if !same || n.dot(to_sun) < 0.15 {
                continue;
            }
            let r = reference.green(x, y);
            if r < 0.02 {
                continue;
            }
            let p = o + d * h.t;
            let Some(texel) = cap.texel_at((p - eye).dot(forward)) else {
                continue;
            };
            let state = occluded(p, n, to_sun);
            // A texel (and the depth bias, along the light) spreads over the surface by 1/cos of
            // the light's incidence along the light's direction in the surface (a), not across
            // it (b).
            let a = (to_sun - n * n.dot(to_sun))
                .try_normalize()
                .unwrap_or(n.any_orthonormal_vector());
            let b = n.cross(a);
            let reach = (cap.normal_bias * std::f64::consts::SQRT_2 + 2.0).max(5.0) * texel;
            let (ra, rb) = (
                (reach + cap.depth_bias) / n.dot(to_sun) + 0.03,
                reach + 0.03,
            );
            let decidable = (0..24).all(|k| {
                let (t, f) = if k < 16 {
                    (std::f64::consts::TAU * f64::from(k) / 16.0, 1.0)
                } else {
                    (std::f64::consts::TAU * f64::from(k - 16) / 8.0, 0.5)
                };
                let q = p + (a * (ra * t.cos()) + b * (rb * t.sin())) * f;
                on_face(q, &h) && occluded(q, n, to_sun) == state
            });
            if !decidable {
                continue;
            }
            let ratio = cap.green(x, y) / r;
            tally.compared += 1;
            if state {
                tally.shadowed += 1;
                let pole = BOXES.len() - 1;
                if ray_box(p + n * 1e-6, to_sun, &BOXES[pole]).is_some() {
                    tally.by_pole += 1;
                }
            }
            let ok = if state { ratio < 0.25 } else { ratio > 0.75 };
            if !ok {
                tally.wrong.push((x, y, state, ratio));
            }
        }
    }
    tally
}

/// Where the PNG `name` goes: in `SHADOW_ALIASING_BEVY_IMAGES`, if it is set.
fn image_path(name: &str) -> Option<std::path::PathBuf> {
    let dir = std::env::var_os("SHADOW_ALIASING_BEVY_IMAGES")?;
    Some(std::path::Path::new(&dir).join(format!("{name}.png")))
}

fn save(name: &str, cap: &Capture) {
    let Some(path) = image_path(name) else {
        return;
    };
    image::save_buffer(&path, &cap.pixels, W, H, image::ExtendedColorType::Rgba8)
        .unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
}

/// The part of the image around the near boxes' shadows (`CROP`: x, y, width, height), enlarged
/// `ZOOM` times with each pixel kept square (no filtering), so that texels show as they are drawn.
const CROP: (u32, u32, u32, u32) = (220, 140, 200, 150);
const ZOOM: u32 = 3;

fn save_crop(name: &str, cap: &Capture) {
    let Some(path) = image_path(name) else {
        return;
    };
    let full = image::RgbaImage::from_raw(W, H, cap.pixels.clone()).expect("W × H RGBA8");
    let (x, y, w, h) = CROP;
    let crop = image::imageops::crop_imm(&full, x, y, w, h).to_image();
    let big = image::imageops::resize(
        &crop,
        w * ZOOM,
        h * ZOOM,
        image::imageops::FilterType::Nearest,
    );
    big.save(&path)
        .unwrap_or_else(|e| panic!("writing {}: {e}", path.display()));
}

#[test]
fn bevy_and_replaced_cascades_render_exact_shadows_and_replacements_measure_lower() {
    let start = Instant::now();
    let mut h = harness(true, RES);
    let reference = render(&mut h, None);
    save("reference", &reference);
    let cam = Eye::new();
    let configs: [(&str, Option<Replace>); 6] = [
        ("bevy", None),
        (
            "focused",
            Some(Replace {
                fit: Fit::Focused(WarpRule::Uniform),
                splits: Splits::Bevy,
                depth_range: None,
            }),
        ),
        (
            "stable",
            Some(Replace {
                fit: Fit::Stable,
                splits: Splits::Bevy,
                depth_range: None,
            }),
        ),
        (
            "equal_error",
            Some(Replace {
                fit: Fit::Focused(WarpRule::Uniform),
                splits: Splits::EqualError { k: 4 },
                depth_range: None,
            }),
        ),
        (
            "lispsm_equal_error",
            Some(Replace {
                fit: Fit::Focused(WarpRule::Lispsm),
                splits: Splits::EqualError { k: 4 },
                depth_range: None,
            }),
        ),
        (
            "practical_sdsm",
            Some(Replace {
                fit: Fit::Focused(WarpRule::Uniform),
                splits: Splits::Scheme {
                    scheme: SplitScheme::Practical { lambda: 0.5 },
                    k: 4,
                },
                // The receivers' visible depth range (here from the scene: the nearest ground
                // point seen and the ground's far end), as a depth-buffer reduction gives it.
                depth_range: Some((9.0, 175.0)),
            }),
        ),
    ];
    let mut bevy_error = None;
    println!(
        "{:<18} {:>9} {:>9} {:>8} {:>6} {:>5}  per-cascade max error (px) / texel (world)",
        "cascades", "max err", "vs Bevy", "compared", "shadow", "pole"
    );
    for (name, replace) in configs {
        let mode = replace.map_or(CascadeMode::Measure, CascadeMode::Replace);
        let cap = render(&mut h, Some(mode));
        save(name, &cap);
        let errors = cap
            .errors
            .clone()
            .expect("the camera's cascades were measured");
        assert_eq!(errors.error, None);
        let want_source = if name == "bevy" {
            CascadeSource::Bevy
        } else {
            CascadeSource::ShadowAliasing
        };
        assert_eq!(errors.source, want_source, "{name}");
        assert_eq!(
            (errors.map_resolution, errors.image_height),
            (RES as u32, H)
        );
        let max = errors.max_error_pixels().unwrap();
        let bevy = *bevy_error.get_or_insert(max);
        let tally = compare(&cap, &reference, &cam);
        let per: Vec<String> = errors
            .cascades
            .iter()
            .zip(&cap.texels)
            .map(|(e, t)| match e {
                Some(e) => format!("{:.3}/{t:.4}", e.max_error_pixels),
                None => format!("-/{t:.4}"),
            })
            .collect();
        println!(
            "{name:<18} {max:>9.3} {:>8.2}x {:>8} {:>6} {:>5}  {}",
            bevy / max,
            tally.compared,
            tally.shadowed,
            tally.by_pole,
            per.join("  ")
        );
        for w in tally.wrong.iter().take(10) {
            println!(
                "  {name}: pixel ({}, {}) exact shadow {} rendered ratio {:.3}",
                w.0, w.1, w.2, w.3
            );
        }
        assert!(
            tally.wrong.is_empty(),
            "{name}: {} of {} compared pixels disagree with the ray cast",
            tally.wrong.len(),
            tally.compared
        );
        assert!(
            tally.compared > 10_000 && tally.shadowed > 500,
            "{name}: {tally:?}"
        );
        assert!(
            tally.by_pole > 100,
            "{name}: the pole's shadow must be seen: {tally:?}"
        );
        // Stable cascades are not focused (the slice's bounding sphere, as Bevy's cover the
        // slice's diagonal): within a few per cent of Bevy's; every focused one below it.
        match name {
            "bevy" => {}
            "stable" => assert!(max < 1.05 * bevy, "{name}: {max} px vs Bevy's {bevy} px"),
            _ => assert!(max < bevy, "{name}: {max} px is not below Bevy's {bevy} px"),
        }
    }
    println!("render test: {:.1} s", start.elapsed().as_secs_f64());
}

#[test]
fn without_depth_clip_control_warped_maps_are_refused_and_orthographic_ones_stay_exact() {
    // Bevy's emulation of unclipped depth writes the undivided clip z: drawn with it, the
    // LiSPSM cascades disagreed with the ray cast at 29923 of 38801 compared pixels.
    let mut h = harness(false, RES);
    let reference = render(&mut h, None);
    let cam = Eye::new();
    let bevy = render(&mut h, Some(CascadeMode::Measure));
    let warped = render(
        &mut h,
        Some(CascadeMode::Replace(Replace {
            fit: Fit::Focused(WarpRule::Lispsm),
            splits: Splits::EqualError { k: 4 },
            depth_range: None,
        })),
    );
    let state = h.app.world().get::<ReplacedCascades>(h.light).unwrap();
    let e = &state.errors[&h.camera];
    assert!(
        e.contains("DEPTH_CLIP_CONTROL") && e.contains("Fit::Stable"),
        "{e}"
    );
    assert_eq!(warped.errors.as_ref().unwrap().source, CascadeSource::Bevy);
    assert!(
        warped.pixels == bevy.pixels,
        "Bevy's cascades are drawn instead"
    );
    let ortho = render(
        &mut h,
        Some(CascadeMode::Replace(Replace {
            fit: Fit::Focused(WarpRule::Uniform),
            splits: Splits::EqualError { k: 4 },
            depth_range: None,
        })),
    );
    assert_eq!(
        ortho.errors.as_ref().unwrap().source,
        CascadeSource::ShadowAliasing
    );
    for (name, cap) in [("bevy", &bevy), ("equal_error", &ortho)] {
        let tally = compare(cap, &reference, &cam);
        assert!(
            tally.wrong.is_empty() && tally.by_pole > 100,
            "{name} with emulated unclipped depth: {tally:?}"
        );
    }
}

#[test]
fn small_maps_show_the_difference_and_both_stay_exact() {
    // 512² maps (a sixteenth of Bevy's default texels): Bevy's cascades and the plugin's
    // equal-error ones, each checked against the ray cast like the 2048² ones (the band left
    // out scales with the texel). The crops are docs/bevy.md's screenshot pair.
    const SMALL: usize = 512;
    let mut h = harness(true, SMALL);
    let reference = render(&mut h, None);
    let cam = Eye::new();
    let mut errors = Vec::new();
    for (name, mode) in [
        ("bevy_512", CascadeMode::Measure),
        (
            "equal_error_512",
            CascadeMode::Replace(Replace {
                fit: Fit::Focused(WarpRule::Uniform),
                splits: Splits::EqualError { k: 4 },
                depth_range: None,
            }),
        ),
    ] {
        let cap = render(&mut h, Some(mode));
        save_crop(name, &cap);
        let e = cap
            .errors
            .clone()
            .expect("the camera's cascades were measured");
        assert_eq!((e.map_resolution, e.image_height), (SMALL as u32, H));
        let max = e.max_error_pixels().unwrap();
        let tally = compare(&cap, &reference, &cam);
        println!(
            "{name}: max error {max:.3} px, compared {}, shadowed {}, pole {}",
            tally.compared, tally.shadowed, tally.by_pole
        );
        assert!(
            tally.wrong.is_empty(),
            "{name}: {} of {} compared pixels disagree with the ray cast: {:?}",
            tally.wrong.len(),
            tally.compared,
            &tally.wrong[..tally.wrong.len().min(10)]
        );
        assert!(
            tally.compared > 10_000 && tally.shadowed > 200 && tally.by_pole > 100,
            "{name}: {tally:?}"
        );
        errors.push(max);
    }
    assert!(
        errors[1] < errors[0],
        "equal-error {} px is not below Bevy's {} px at {SMALL}²",
        errors[1],
        errors[0]
    );
}

/// How far from a box's footprint a ground pixel counts as near contact (world units).
const CONTACT: f64 = 2.0;

/// Exactly shadowed ground pixels within [`CONTACT`] of the footprint of a box standing on the
/// ground (its shadow's contact), and those of them drawn lit (over 0.75 of the reference):
/// detached shadow.
fn detached(cap: &Capture, reference: &Capture, cam: &Eye) -> (usize, usize) {
    let to_sun = -DVec3::from_array(sun_dir().as_dvec3().to_array()).normalize();
    let (mut near, mut lit) = (0, 0);
    for y in (0..H).step_by(STEP as usize) {
        for x in (0..W).step_by(STEP as usize) {
            let (o, d) = cam.ray(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let Some(h) = first_hit(o, d) else { continue };
            // The ground's top face, seen whole by the pixel.
            if (h.bx, h.axis, h.sign) != (0, 1, 1.0) {
                continue;
            }
            let whole = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)]
                .iter()
                .all(|&(a, b)| {
                    let (o, d) = cam.ray(f64::from(x) + a, f64::from(y) + b);
                    first_hit(o, d).is_some_and(|g| (g.bx, g.axis, g.sign) == (0, 1, 1.0))
                });
            let r = reference.green(x, y);
            if !whole || r < 0.02 {
                continue;
            }
            let p = o + d * h.t;
            if !on_face(p, &h) || !occluded(p, DVec3::Y, to_sun) {
                continue;
            }
            let contact = BOXES[1..].iter().any(|b| {
                let dx = (b.min[0] - p.x).max(p.x - b.max[0]).max(0.0);
                let dz = (b.min[2] - p.z).max(p.z - b.max[2]).max(0.0);
                b.min[1] == 0.0 && dx.hypot(dz) < CONTACT
            });
            if !contact {
                continue;
            }
            near += 1;
            if cap.green(x, y) / r > 0.75 {
                lit += 1;
            }
        }
    }
    (near, lit)
}

#[test]
fn automatic_bias_has_no_acne_and_fewer_detached_shadows_than_bevys_default() {
    // The plugin's equal-error cascades drawn twice with Bevy's 2 × 2 hardware PCF: with
    // Bevy's default bias (the automatic bias off) and with the crate's bias for those maps.
    let mut h = harness(true, RES);
    let reference = render(&mut h, None);
    let cam = Eye::new();
    let mode = CascadeMode::Replace(Replace {
        fit: Fit::Focused(WarpRule::Uniform),
        splits: Splits::EqualError { k: 4 },
        depth_range: None,
    });
    let mut rows = Vec::new();
    for auto in [false, true] {
        h.app
            .world_mut()
            .resource_mut::<ShadowAliasingSettings>()
            .auto_bias = auto;
        let cap = render(&mut h, Some(mode.clone()));
        let tally = compare(&cap, &reference, &cam);
        let acne = tally.wrong.iter().filter(|w| !w.2).count();
        let missed = tally.wrong.iter().filter(|w| w.2).count();
        let (near, lit) = detached(&cap, &reference, &cam);
        let applied = h
            .app
            .world()
            .get::<ReplacedCascades>(h.light)
            .unwrap()
            .bias
            .clone();
        println!(
            "auto bias {auto}: normal bias {:.3}, depth bias {:.3}; compared {}, acne {acne}, \
             missed {missed}; near contact {near}, drawn lit {lit}; {applied:?}",
            cap.normal_bias, cap.depth_bias, tally.compared
        );
        if auto {
            let a = applied.expect("the bias was set").expect("derived");
            assert_eq!(f64::from(a.normal_bias), cap.normal_bias);
            assert_eq!((a.depth_bias, cap.depth_bias), (0.0, 0.0));
            assert_eq!(a.pcf_radius, 0.5, "Hardware2x2: one bilinear comparison");
            assert_eq!(a.needed.len(), 4);
        } else {
            assert!(applied.is_none());
            assert_eq!(
                (cap.normal_bias as f32, cap.depth_bias as f32),
                (
                    DirectionalLight::DEFAULT_SHADOW_NORMAL_BIAS,
                    DirectionalLight::DEFAULT_SHADOW_DEPTH_BIAS
                ),
                "the automatic bias off leaves Bevy's default"
            );
        }
        assert!(tally.compared > 10_000 && near > 200, "{tally:?}, {near}");
        rows.push((acne, missed, near, lit));
    }
    let (bevy, auto) = (rows[0], rows[1]);
    assert_eq!(auto.0, 0, "acne with the automatic bias");
    assert_eq!(auto.1, 0, "missed shadows with the automatic bias");
    assert!(
        auto.3 < bevy.3,
        "detached: {} pixels with the automatic bias, {} with Bevy's default",
        auto.3,
        bevy.3
    );
}
