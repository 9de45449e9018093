//! A fingerprint of the frame API's outputs, for work that must not change any output bit (a
//! speed-up of the clipper or of the frame's bookkeeping): 20 000 random frames over every scheme,
//! measured and not, with fixed seeds, each output hashed bit for bit (every map's matrices,
//! figures, body, culling volumes, bias and GPU record; the frame's bookkeeping; each error's
//! message). Run it before and after the change and compare the printed hash:
//!
//! ```text
//! cargo run --release --example frame_fingerprint
//! ```
//!
//! The hash depends on the platform's floating-point library (`sin`, `powf`) and on the standard
//! library's `DefaultHasher`, so it is a tool printed for comparison on one machine, not a test.

use glam::{DMat4, DVec3, DVec4};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{
    frame_into, Aabb, Bound, Camera, CascadeSplits, ClipmapOptions, Frame, FrameInput, FrameScheme,
    WarpCentre,
};
use shadow_aliasing::maps::faces::FaceWarp;
use shadow_aliasing::maps::{ClipDepth, Falloff, TsmOptions, TsmSearch, WarpRule};
use std::collections::hash_map::DefaultHasher;
use std::hash::Hasher;

/// splitmix64: a fixed, dependency-free stream.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn vec(&mut self, s: f64) -> DVec3 {
        DVec3::new(self.range(-s, s), self.range(-s, s), self.range(-s, s))
    }
    fn aabb(&mut self, centre: DVec3, s: f64) -> Aabb {
        let c = centre + self.vec(s);
        let mut h = DVec3::new(self.range(0.0, s), self.range(0.0, s), self.range(0.0, s));
        // Sometimes flat (a ground plane of zero thickness).
        if self.below(8) == 0 {
            h.y = 0.0;
        }
        Aabb::new(c - h, c + h).unwrap()
    }
}

fn rule(r: &mut Rng) -> WarpRule {
    match r.below(14) {
        0 => WarpRule::Uniform,
        1 => WarpRule::Eta(r.range(-1.0, 1.0)),
        2 => WarpRule::Psm,
        3 => WarpRule::LispsmFixed,
        4 | 5 => WarpRule::Lispsm,
        6 => WarpRule::Barroso(Falloff::Barroso),
        7 => WarpRule::Barroso(Falloff::Zhang),
        8 => WarpRule::LispsmReference,
        9 => WarpRule::Filament,
        10 => WarpRule::Ogre,
        11 => WarpRule::Minimax,
        12 => WarpRule::MinimaxMz,
        _ => WarpRule::Tsm {
            focus: r.range(0.05, 0.9),
        },
    }
}

fn splits(r: &mut Rng) -> CascadeSplits<'static> {
    let k = 1 + r.below(5) as usize;
    let overlap = if r.below(2) == 0 {
        0.0
    } else {
        r.range(0.0, 0.3)
    };
    match r.below(4) {
        0 => CascadeSplits::Scheme {
            scheme: SplitScheme::Practical {
                lambda: r.range(0.0, 1.0),
            },
            k,
            overlap,
        },
        1 => CascadeSplits::Scheme {
            scheme: SplitScheme::Uniform,
            k,
            overlap,
        },
        2 => CascadeSplits::Scheme {
            scheme: SplitScheme::SelfSimilar,
            k,
            overlap,
        },
        _ => CascadeSplits::EqualError { k },
    }
}

fn scheme(r: &mut Rng) -> FrameScheme<'static> {
    match r.below(10) {
        0..=2 => FrameScheme::Single(rule(r)),
        3 | 4 => FrameScheme::Cascades {
            splits: splits(r),
            rule: rule(r),
        },
        5 => FrameScheme::Stable(splits(r)),
        6 => FrameScheme::Tsm(TsmOptions {
            focus: r.range(0.05, 0.9),
            search: TsmSearch::EightyPercent,
        }),
        7 | 8 => FrameScheme::Faces {
            rule: [FaceWarp::Uniform, FaceWarp::Psm, FaceWarp::Lispsm][r.below(3) as usize],
            k: 1 + r.below(3) as usize,
        },
        _ => FrameScheme::Clipmap(ClipmapOptions {
            first_level: 2,
            last_level: 14,
            lod_bias: -0.5,
            unit: 0.01,
            page_texels: 128,
        }),
    }
}

fn put(h: &mut DefaultHasher, v: f64) {
    h.write_u64(v.to_bits());
}

fn put_mat(h: &mut DefaultHasher, m: &DMat4) {
    m.to_cols_array().iter().for_each(|v| put(h, *v));
}

fn put_str(h: &mut DefaultHasher, s: &str) {
    h.write(s.as_bytes());
    h.write_u8(0xff);
}

/// Every output of a frame (or its error) into `h`.
fn hash_frame(h: &mut DefaultHasher, res: &shadow_aliasing::Result<()>, f: &Frame) -> usize {
    if let Err(e) = res {
        put_str(h, &e.to_string());
        return 0;
    }
    h.write_usize(f.len());
    put_str(h, f.focus().name());
    put_str(h, f.light_case().name());
    f.light_dir_eye().to_array().iter().for_each(|v| put(h, *v));
    put(h, f.storage_factor().unwrap_or(-1.0));
    for slot in f.slots() {
        let Some(m) = slot else {
            h.write_u8(0);
            continue;
        };
        h.write_u8(1);
        put_str(h, &format!("{:?}", m.shadow));
        put_mat(h, &m.world_to_clip);
        for v in [m.split.0, m.split.1, m.blend.0, m.blend.1, m.texel_world] {
            put(h, v);
        }
        for v in [m.max_mx, m.max_mz, m.storage_factor, m.max_error_pixels] {
            put(h, v);
        }
        put_str(h, m.focus.name());
        put_str(h, &format!("{:?} {:?}", m.face, m.clipmap_level));
        h.write_u8(u8::from(m.unchanged()));
        h.write_u8(u8::from(m.error().is_some()));
        for p in m.body() {
            p.to_array().iter().for_each(|v| put(h, *v));
        }
        for vol in [m.casters_volume(), m.receivers_volume()] {
            h.write_usize(vol.planes().len());
            for p in vol.planes() {
                p.to_array().iter().for_each(|v| put(h, *v));
            }
        }
        for d in ClipDepth::ALL {
            put_mat(h, &m.world_to_clip(d));
            h.write(&m.gpu(d).to_bytes());
            match m.bias(1.5, d) {
                Ok(b) => put_str(h, &format!("{b:?}")),
                Err(e) => put_str(h, &e.to_string()),
            }
        }
    }
    f.len()
}

fn main() {
    let mut r = Rng(0x5EED_F4A3_0023_0009);
    let mut h = DefaultHasher::new();
    let mut out = Frame::default();
    let (mut maps, mut errors) = (0usize, 0usize);
    for _ in 0..20_000 {
        // A camera somewhere looking somewhere (sometimes the previous one moved slightly, so
        // that `unchanged` is exercised through the reused `out`).
        let eye = r.vec(30.0);
        let target = eye + r.vec(1.0);
        let up = if r.below(2) == 0 {
            DVec3::Y
        } else {
            r.vec(1.0)
        };
        let Some(view) =
            (target != eye).then(|| glam::dcamera::rh::view::look_at_mat4(eye, target, up))
        else {
            continue;
        };
        if !view.is_finite() {
            continue;
        }
        let near = r.range(0.05, 2.0);
        let far = near * r.range(2.0, 2000.0);
        let Ok(cam) = Camera::new(
            view,
            near,
            far,
            r.range(0.2, 1.2),
            [1.0, 16.0 / 9.0, r.range(0.5, 3.0)][r.below(3) as usize],
        ) else {
            continue;
        };
        let light = match r.below(8) {
            0 => DVec3::NEG_Y,
            1 => (target - eye) * r.range(0.5, 2.0),
            _ => r.vec(1.0),
        };
        let centre = eye + (target - eye).normalize_or_zero() * r.range(0.0, far * 0.5);
        let size = r.range(1.0, far * 0.5);
        let rboxes: Vec<Aabb> = (0..1 + r.below(3)).map(|_| r.aabb(centre, size)).collect();
        let cboxes: Vec<Aabb> = (0..r.below(4)).map(|_| r.aabb(centre, size)).collect();
        let cube: Vec<DVec4> = {
            let b = r.aabb(centre, size);
            let (lo, hi) = (b.min, b.max);
            vec![
                DVec4::new(1.0, 0.0, 0.0, -hi.x),
                DVec4::new(-1.0, 0.0, 0.0, lo.x),
                DVec4::new(0.0, 1.0, 0.0, -hi.y),
                DVec4::new(0.0, -1.0, 0.0, lo.y),
                DVec4::new(0.0, 0.0, 1.0, -hi.z),
                DVec4::new(0.0, 0.0, -1.0, lo.z),
                DVec4::new(1.0, 1.0, 0.0, -(hi.x + hi.y) * 0.9 - 0.1 * (lo.x + lo.y)),
            ]
        };
        let receivers = match r.below(6) {
            0 => Bound::Unbounded,
            1 => Bound::Polytope(&cube),
            _ => Bound::Boxes(&rboxes),
        };
        let casters = match r.below(6) {
            0 => Bound::Unbounded,
            1 => Bound::Polytope(&cube),
            _ => Bound::Boxes(&cboxes),
        };
        let mut input = FrameInput::new(cam, light, [512, 2048, 4096][r.below(3) as usize], 1080)
            .receivers(receivers)
            .casters(casters)
            .depth_clamp(r.below(4) == 0)
            .scheme(scheme(&mut r))
            .centre(
                [WarpCentre::Rule, WarpCentre::Eye, WarpCentre::NearestVertex][r.below(3) as usize],
            )
            .measure(r.below(2) == 0);
        if r.below(5) == 0 {
            let a = r.range(near, far);
            input = input.depth_range(a, a + r.range(0.0, far));
        }
        let res = frame_into(&input, &mut out);
        errors += usize::from(res.is_err());
        maps += hash_frame(&mut h, &res, &out);
        // The same frame again: every map unchanged.
        if r.below(8) == 0 {
            let res = frame_into(&input, &mut out);
            maps += hash_frame(&mut h, &res, &out);
        }
    }
    println!(
        "frame outputs fingerprint: {:016x} ({maps} maps, {errors} errors)",
        h.finish()
    );
}
