//! Clipmaps, as Unreal 5's virtual shadow maps lay them out for a directional light
//! ([`FrameScheme::Clipmap`](super::FrameScheme::Clipmap), issue 24 item 4).
//!
//! # The levels
//!
//! Level i is an orthographic map of `map_resolution` texels per side (Unreal: 16 384, 128 × 128
//! pages of 128² texels). Its square, in a world-fixed light space, has half-width
//! `2^{i+2} · unit` and covers the disc of radius `2^{i+1} · unit` around the camera. The radius
//! doubles per level. The square is centred on the camera, snapped to whole pages, so the page
//! grid is fixed in the world. Unreal's `VirtualShadowMapClipmap.cpp` sets the same sizes:
//! `GetLevelRadius(Level) = 2^(Level+1)` and `HalfLevelDim = 2 · RawLevelRadius`, in
//! centimetres. It snaps coarser, to the radius (a quarter of the level, 32 pages). That choice
//! moves the square less often but leaves the page grid and the page counts unchanged.
//!
//! # The level choice ([`LevelChoice`])
//!
//! The shader picks, at eye depth z, the coarsest level whose texel is no coarser than `2^b`
//! pixels, b the LOD bias. Every finer level meets the bound too, but it costs more pages. The
//! issue's "finest level whose texel is no coarser than a pixel" means this level: read
//! literally, the finest such level would always be the first. A pixel at depth z is
//! `w(z) = 2 z tan θ / H` wide (θ the half vertical field of view, H the image's height), and
//! level i's texel is `t_i = 2^{i+3} · unit / R`. So
//!
//! ```text
//! level(z) = clamp(⌊log₂ z + L⌋, first_level, last_level),  L = b + log₂(tan θ · R / (4 · unit · H))
//! ```
//!
//! and at depths where no clamp applies the level's error, `t_i / w(z)`, lies in
//! `(2^{b−1}, 2^b]`. Each level must also cover what it is chosen for. A point at depth z lies
//! within `k z` of the camera, `k = √(1 + tan²θ (1 + aspect²))` (the frustum's corner ray). Level
//! `⌊log₂ z + log₂(k/unit)⌋` covers that distance, so L is raised to at least `log₂(k / unit)`.
//! This is Unreal's clamp of its total LOD bias at 0, in the crate's terms. Above that bound
//! the effective bias ([`LevelChoice::bias`]) is larger than the one asked for.
//!
//! Each level is a map of the frame ([`FrameMap`](super::FrameMap)). Its focus body is B cut to
//! the depths where the level is chosen (its `split`). Its error, culling volumes and bias are
//! those of any other map. Its depth range covers B and the casters, snapped to whole texels, as
//! a stable cascade's is. `FrameMap::clipmap_level` names the level.

use super::input::ClipmapOptions;
use super::output::Focus;
use super::{Built, Ctx, Frame, Slice};
use crate::analytic::partition::MAX_PARTITIONS;
use crate::error::{fmt_num, Error, Result};
use crate::frustum::ViewFrustum;

/// The shader's level choice for a camera, an image and a clipmap (module docs): `level(z) =
/// clamp(⌊log₂ z + offset⌋, first_level, last_level)` at eye depth z.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LevelChoice {
    /// L of `level(z) = clamp(⌊log₂ z + L⌋, first_level, last_level)`.
    pub offset: f64,
    /// The finest level.
    pub first_level: i32,
    /// The coarsest level.
    pub last_level: i32,
    /// The LOD bias in effect: the one asked for, or larger where the levels could not cover
    /// what they are chosen for with it (module docs). Unclamped levels' errors lie in
    /// `(2^{bias−1}, 2^bias]` pixels.
    pub bias: f64,
    /// The clipmap's layout.
    pub options: ClipmapOptions,
    /// The levels' texels per side.
    pub resolution: u32,
    /// tan θ of the camera.
    pub tan_half_fov: f64,
    /// The image's height in pixels.
    pub image_height: u32,
}

impl LevelChoice {
    /// The level choice for the camera `view`, an image `image_height` pixels high and levels of
    /// `resolution` texels laid out as `options`.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `image_height` (0), `map_resolution` (< 3), or a field of
    /// [`ClipmapOptions`] out of its domain.
    pub fn new(
        view: &ViewFrustum,
        image_height: u32,
        resolution: u32,
        options: &ClipmapOptions,
    ) -> Result<Self> {
        if image_height == 0 {
            return Err(Error::invalid("image_height", "must be at least 1 pixel"));
        }
        if resolution < 3 {
            return Err(Error::invalid(
                "map_resolution",
                format!("must be at least 3 texels (got {resolution})"),
            ));
        }
        options.check(resolution)?;
        let t = view.tan_half_fov();
        let a = view.aspect();
        let matched =
            (t * f64::from(resolution) / (4.0 * options.unit * f64::from(image_height))).log2();
        let covered = ((1.0 + t * t * (1.0 + a * a)).sqrt() / options.unit).log2();
        let offset = (options.lod_bias + matched).max(covered);
        Ok(Self {
            offset,
            first_level: options.first_level,
            last_level: options.last_level,
            bias: offset - matched,
            options: *options,
            resolution,
            tan_half_fov: t,
            image_height,
        })
    }

    /// The level the shader picks at eye depth `depth` > 0 (the WGSL function of docs/planning.md
    /// computes the same in `f32`).
    #[must_use]
    pub fn level(&self, depth: f64) -> i32 {
        let l = (depth.log2() + self.offset).floor();
        // Clamped in f64 first: a depth of 0 or +∞ gives ∓∞, which `as` would saturate anyway.
        l.clamp(f64::from(self.first_level), f64::from(self.last_level)) as i32
    }

    /// The depth from which `level` is chosen when no clamp applies, `2^{level − offset}`.
    #[must_use]
    pub fn level_start(&self, level: i32) -> f64 {
        (f64::from(level) - self.offset).exp2()
    }

    /// Level `level`'s texel edge, world units: `2 · half_width / resolution`.
    #[must_use]
    pub fn texel(&self, level: i32) -> f64 {
        2.0 * self.options.half_width(level) / f64::from(self.resolution)
    }

    /// Level `level`'s page edge, world units.
    #[must_use]
    pub fn page(&self, level: i32) -> f64 {
        self.texel(level) * f64::from(self.options.page_texels)
    }

    /// The error of level `level` at eye depth `depth`, in pixels: its texel over the pixel's
    /// width there, `t_i H / (2 z tan θ)`; M_x and M_z of the level's map at that depth (an
    /// orthographic map's texel, measured across the light, against a pixel measured across the
    /// view, Lloyd 2006 Eq 7–8).
    #[must_use]
    pub fn error_at(&self, level: i32, depth: f64) -> f64 {
        self.texel(level) * f64::from(self.image_height) / (2.0 * depth * self.tan_half_fov)
    }

    /// The deepest eye depth that `last_level` covers: the largest `f64` z that
    /// [`LevelChoice::levels_needed`] accepts as the visible far depth. That is
    /// [`LevelChoice::level_start`]`(last_level + 1)`, found among the floats themselves (a
    /// bisection on their bits), since `log₂` and `exp2` round: a far plane at this depth or
    /// nearer is covered. 0 when no positive depth is covered, `f64::MAX` when every finite
    /// one is.
    #[must_use]
    pub fn deepest_covered(&self) -> f64 {
        let limit = f64::from(self.last_level) + 1.0;
        let covers = |z: f64| z.log2() + self.offset <= limit;
        // Positive floats are ordered as their bits: bisect between one covered and one not.
        let (mut ok, mut bad) = (0u64, f64::INFINITY.to_bits());
        if covers(f64::MAX) {
            return f64::MAX;
        }
        while bad - ok > 1 {
            let mid = ok + (bad - ok) / 2;
            if covers(f64::from_bits(mid)) {
                ok = mid;
            } else {
                bad = mid;
            }
        }
        f64::from_bits(ok)
    }

    /// The first and last level the visible depths `[z_near, z_far]` need.
    ///
    /// # Errors
    /// [`Error::InvalidArgument`] naming `last_level` when the farthest depth needs a coarser
    /// level than the last (no level would cover it), with the level that would.
    pub fn levels_needed(&self, z_near: f64, z_far: f64) -> Result<(i32, i32)> {
        let top = z_far.log2() + self.offset;
        if top > f64::from(self.last_level) + 1.0 {
            let needed = top.ceil() - 1.0;
            // Cutting the far depth helps only where it would stay beyond the near one.
            let deepest = self.deepest_covered();
            let cut = if deepest > z_near {
                format!(
                    ", or cut the visible depths to {} (depth_range or far)",
                    fmt_num(deepest)
                )
            } else {
                String::new()
            };
            return Err(Error::invalid(
                "last_level",
                format!(
                    "is {} but the visible depth {} needs level {needed} (radius {}): raise \
                     last_level to {needed}{cut}",
                    self.last_level,
                    fmt_num(z_far),
                    fmt_num(self.options.unit * (needed + 1.0).exp2()),
                ),
            ));
        }
        let first = self.level(z_near);
        let last = ((top.ceil() - 1.0) as i32).clamp(first, self.last_level);
        Ok((first, last))
    }

    /// The depths where `level` is chosen within `[z_near, z_far]`, for `level` in
    /// [`LevelChoice::levels_needed`]'s range.
    #[must_use]
    pub fn level_depths(&self, level: i32, z_near: f64, z_far: f64) -> (f64, f64) {
        let a = if level <= self.first_level {
            z_near
        } else {
            self.level_start(level).max(z_near)
        };
        (a, self.level_start(level + 1).min(z_far))
    }
}

impl Ctx<'_, '_> {
    /// The clipmap's levels over the visible depths `[zn, zf]` into `out`, finest first, one
    /// slot per level needed (`None` where B has no volume at its depths).
    pub(super) fn clipmap_into(
        &self,
        opts: ClipmapOptions,
        (zn, zf): (f64, f64),
        out: &mut Frame,
    ) -> Result<()> {
        super::input::check_resolutions(self.input, 0)?;
        let choice = LevelChoice::new(
            self.view,
            self.input.image_height,
            self.input.map_resolution,
            &opts,
        )?;
        let (first, last) = choice.levels_needed(zn, zf)?;
        let count = (last - first + 1) as usize;
        if count > MAX_PARTITIONS {
            return Err(Error::invalid(
                "depth_range",
                format!(
                    "needs {count} clipmap levels ({first} to {last}), more than the frame's \
                     {MAX_PARTITIONS} maps: cut the visible depths (depth_range), raise \
                     first_level, or raise lod_bias"
                ),
            ));
        }
        let camera = self.input.camera.eye_to_world.w_axis.truncate();
        for level in first..=last {
            let (a, b) = choice.level_depths(level, zn, zf);
            let s = Slice {
                cover: (a, b),
                split: (a, b),
                blend: (b, b),
                res: self.input.map_resolution,
            };
            let body = self.body(a, b, &[])?;
            out.push_with(|dst| {
                if body.focus == Focus::Empty || body.n == 0 {
                    return Ok(Built::None(Focus::Empty));
                }
                let square = (camera, opts.half_width(level), choice.page(level));
                let built = self.square_map(&s, &body, square, dst)?;
                if let (Built::Map, Some(m)) = (&built, dst) {
                    m.clipmap_level = Some(level);
                }
                Ok(built)
            })?;
        }
        out.settle();
        Ok(())
    }
}
