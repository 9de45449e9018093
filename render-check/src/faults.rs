//! Deliberate faults (`render-check --fault NAME`, `render-check --self-test`): each changes what
//! the frame returns, or how the renderer uses it, in one way a real bug could, so that the
//! targets ([`crate::targets`]) can be seen to fail. A fault is applied where render-check builds
//! the frame ([`crate::schemes::build`]): to the frame's input (the casters, the light), to each
//! map's matrix (both the matrix the measurement takes and the GPU's, so that the two stay
//! consistent and only the frame's own reported numbers, the ray cast and the coverage can tell),
//! to the split ranges and faces the shader selects maps by, to how the maps are uploaded (the
//! plain world matrix in place of the relative path), to what is drawn into them (culling), or
//! to how the shader cross-fades cascades over their blend band.

mod warp;

pub use warp::n_prime_scaled;

use crate::schemes::{Map, Scheme, View};
use glam::{DMat4, DVec3, DVec4};
use shadow_aliasing::frame::FrameMap;
use shadow_aliasing::maps::ClipDepth;

/// One deliberate fault.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fault {
    /// Every map's matrix scaled by 1.01 about the map centre (clip x and y × 1.01).
    MatrixScale,
    /// Every map's light depth shifted by two texels' worth: the scene moved 2 × the frame's
    /// `texel_world` along the light (away from it) before the matrix.
    DepthShift,
    /// Every warped map's n′ doubled, the map refitted to its focus body (s and t tight, the
    /// depth range kept).
    NPrimeDouble,
    /// The casters left out of the frame (its depth range fitted to the focus body alone).
    NoCasters,
    /// The frame built for a light rotated by 0.5° (the scene lit by the true light).
    LightRotated,
    /// Cascade selection off by one: a fragment in split i takes map i + 1 (the last split keeps
    /// the last map).
    CascadeOffByOne,
    /// Stable cascades not snapped: each map's square centred on its bounding sphere exactly.
    Unsnapped,
    /// Face partitions: every map given to the wrong face (each face's maps labelled with the
    /// next face present, cyclically).
    WrongFace,
    /// The plain `f32` world matrix (`FrameMap::gpu`, world positions in `f32`) in place of the
    /// relative upload path: only set-ups far from the world origin can tell.
    PlainWorld,
    /// Culling too tight: each map draws only the objects that may meet its casters' volume cut
    /// by its receivers' volume (the view slice), so casters outside the view are dropped.
    CullTight,
    /// The blend band ignored: inside a cascade's band the shader shades with the band's first
    /// map alone (its visibility, not the cross-fade `sa_cascaded_visibility` computes).
    BlendIgnored,
    /// LiSPSM's n′ without its 1/sin γ (`WarpRule::Lispsm`'s maps: n′ × sin γ, refitted to the
    /// body as [`Fault::NPrimeDouble`]).
    LispsmNoSin,
    /// TSM's focus line sent to ξ = −0.8 instead of Martin & Tan's −0.6 (n′ scaled by the ratio
    /// of the two η).
    TsmFocus,
    /// The blend bands 1.5 × as wide as the overlap makes them (`FrameMap::blend` and the
    /// records alike, the band's start kept).
    BlendWide,
    /// The blended cascades built with no overlap (the request dropped).
    OverlapDropped,
    /// The upload origin rounded through `f32` (an API taking the camera as `Vec3`): the records
    /// relative to the rounded origin, the vertices to the true one.
    OriginF32,
    /// Every split but the last ends 3 % past its map's slice (the records' split ranges; the
    /// maps unchanged).
    SplitsPast,
    /// The reversed-depth comparison of the crate's WGSL module made strict (`>` for `>=`).
    ReversedStrict,
    /// The records' depth bias (constant and slope-scaled) and normal offset halved.
    BiasHalved,
    /// The PCF kernel of the crate's `sa_visibility` reaching 2r texels for a radius r (the taps
    /// −2r..2r; the bias still for r).
    PcfRadiusDoubled,
    /// The normal offset twice too large, in the crate's Rust and WGSL alike: the records'
    /// `normal_offset` and the per-point offset (`sa_local_normal_offset`, and the `f64`
    /// `normal_offset_at` render-check models the lookup with) doubled.
    NormalOffsetDoubled,
    /// The uniform map 1.2 × as wide as its focus body (its extent along s and t, about the map
    /// centre), honestly reported: the frame's M_x, M_z, `max_error_pixels` and `texel_world`
    /// × 1.2 with it, so that only a measurement against the paper can tell.
    UniformWide,
    /// PSM's n′ doubled in the crate's rule (`WarpRule::Psm` giving 2 n for n): the frame built
    /// by the crate with the n′ of 2 n_B ([`Fault::psm_rule`]), so that everything the frame
    /// reports (n′, M_x, M_z, `max_error_pixels`, the records' bias) follows the doubled n′ as
    /// a bug in the rule would make it; only a measurement of the map against PSM's n′ from
    /// the paper can tell.
    PsmNPrimeDouble,
    /// The receivers left out of the frame (`Bound::Unbounded`): every map's focus body the
    /// whole view slice instead of its part the receivers' box holds, and everything the frame
    /// reports following it, as a focus body that lost its clip would make it.
    ReceiversUnbounded,
}

/// How far from the world origin a set-up's camera must be for [`Fault::PlainWorld`] to apply
/// (the self-test runs it only there; nearer, the plain matrix loses nothing measurable).
pub const FAR_FROM_ORIGIN: f64 = 1e4;

/// clip x, y scale of [`Fault::MatrixScale`].
const SCALE: f64 = 1.01;
/// The rotation of [`Fault::LightRotated`], degrees.
const LIGHT_DEG: f64 = 0.5;
/// The depth shift of [`Fault::DepthShift`], in the frame's world-space texel edges.
const DEPTH_TEXELS: f64 = 2.0;
/// [`Fault::BlendWide`]'s factor.
const BLEND_WIDE: f64 = 1.5;
/// [`Fault::SplitsPast`]'s factor on each split's far end.
const SPLITS_PAST: f64 = 1.03;
/// [`Fault::UniformWide`]'s factor on the uniform map's extent.
const UNIFORM_WIDE: f64 = 1.2;
/// [`Fault::TsmFocus`]'s ξ (Martin & Tan's is −0.6).
const TSM_XI: f64 = -0.8;

/// OpenGL depth → depth [0, 1] (`ShadowMatrix::with_clip_depth`: row 2 becomes (row 2 + row 3)/2).
const GL_TO_01: DMat4 = DMat4::from_cols(
    DVec4::new(1.0, 0.0, 0.0, 0.0),
    DVec4::new(0.0, 1.0, 0.0, 0.0),
    DVec4::new(0.0, 0.0, 0.5, 0.0),
    DVec4::new(0.0, 0.0, 0.5, 1.0),
);

impl Fault {
    /// Every fault, in the order of the self-test.
    pub const ALL: [Fault; 24] = [
        Fault::MatrixScale,
        Fault::DepthShift,
        Fault::NPrimeDouble,
        Fault::NoCasters,
        Fault::LightRotated,
        Fault::CascadeOffByOne,
        Fault::Unsnapped,
        Fault::WrongFace,
        Fault::PlainWorld,
        Fault::CullTight,
        Fault::BlendIgnored,
        Fault::LispsmNoSin,
        Fault::TsmFocus,
        Fault::BlendWide,
        Fault::OverlapDropped,
        Fault::OriginF32,
        Fault::SplitsPast,
        Fault::ReversedStrict,
        Fault::BiasHalved,
        Fault::PcfRadiusDoubled,
        Fault::NormalOffsetDoubled,
        Fault::UniformWide,
        Fault::PsmNPrimeDouble,
        Fault::ReceiversUnbounded,
    ];

    /// The name `--fault` takes.
    pub fn name(self) -> &'static str {
        match self {
            Fault::MatrixScale => "matrix-scale",
            Fault::DepthShift => "depth-shift",
            Fault::NPrimeDouble => "n-prime-x2",
            Fault::NoCasters => "no-casters",
            Fault::LightRotated => "light-rotated",
            Fault::CascadeOffByOne => "cascade-off-by-one",
            Fault::Unsnapped => "unsnapped",
            Fault::WrongFace => "wrong-face",
            Fault::PlainWorld => "plain-world",
            Fault::CullTight => "cull-tight",
            Fault::BlendIgnored => "blend-ignored",
            Fault::LispsmNoSin => "lispsm-no-sin",
            Fault::TsmFocus => "tsm-focus-0.8",
            Fault::BlendWide => "blend-wide",
            Fault::OverlapDropped => "overlap-dropped",
            Fault::OriginF32 => "origin-f32",
            Fault::SplitsPast => "splits-past",
            Fault::ReversedStrict => "reversed-strict",
            Fault::BiasHalved => "bias-halved",
            Fault::PcfRadiusDoubled => "pcf-radius-x2",
            Fault::NormalOffsetDoubled => "normal-offset-x2",
            Fault::UniformWide => "uniform-wide",
            Fault::PsmNPrimeDouble => "psm-n-prime-x2",
            Fault::ReceiversUnbounded => "receivers-unbounded",
        }
    }

    /// One line for `--help` and the docs.
    pub fn describe(self) -> &'static str {
        match self {
            Fault::MatrixScale => "every matrix scaled by 1.01 about the map centre",
            Fault::DepthShift => "light depth shifted by two texels' worth (2 texel_world)",
            Fault::NPrimeDouble => "n' x 2 in every warped map (refitted to its body)",
            Fault::NoCasters => "casters left out of the depth range",
            Fault::LightRotated => "the frame built for the light rotated 0.5 deg",
            Fault::CascadeOffByOne => "cascade selection off by one",
            Fault::Unsnapped => "stable cascades not snapped to texels",
            Fault::WrongFace => "face partitions: every map given to the wrong face",
            Fault::PlainWorld => "the plain f32 world matrix in place of the relative upload path",
            Fault::CullTight => "culling too tight: casters' volume cut to the view slice",
            Fault::BlendIgnored => "the blend band ignored: one map shades the band",
            Fault::LispsmNoSin => "LiSPSM's n' without its 1/sin gamma",
            Fault::TsmFocus => "TSM's focus line at xi = -0.8 instead of -0.6",
            Fault::BlendWide => "blend bands 1.5 x as wide as the overlap makes them",
            Fault::OverlapDropped => "the blended cascades' overlap dropped (no band)",
            Fault::OriginF32 => "the upload origin rounded through f32",
            Fault::SplitsPast => "every split but the last 3 % past its map",
            Fault::ReversedStrict => "the reversed-depth comparison strict (> for >=)",
            Fault::BiasHalved => "the records' depth bias and normal offset halved",
            Fault::PcfRadiusDoubled => "the PCF kernel's taps reaching 2r for a radius r",
            Fault::NormalOffsetDoubled => "the normal offset (record and per point) doubled",
            Fault::UniformWide => "the uniform map 1.2 x too wide, its error reported x 1.2",
            Fault::PsmNPrimeDouble => "PSM's n' x 2 in the crate's rule (reported with it)",
            Fault::ReceiversUnbounded => {
                "receivers left out: each focus body the whole view slice (reported with it)"
            }
        }
    }

    /// The fault named `s`.
    ///
    /// # Errors
    /// An unknown name, with the list of names.
    pub fn parse(s: &str) -> Result<Fault, String> {
        Fault::ALL
            .into_iter()
            .find(|f| f.name() == s)
            .ok_or_else(|| {
                let names: Vec<&str> = Fault::ALL.iter().map(|f| f.name()).collect();
                format!("--fault: unknown fault {s:?}; one of {}", names.join(", "))
            })
    }

    /// Whether the fault can change `scheme` at all (the self-test runs only those).
    pub fn applies_to(self, scheme: Scheme) -> bool {
        match self {
            Fault::NPrimeDouble => !matches!(
                scheme,
                Scheme::Uniform | Scheme::StableCascades | Scheme::Clipmap
            ),
            Fault::CascadeOffByOne => matches!(
                scheme,
                Scheme::Cascades | Scheme::StableCascades | Scheme::BlendedCascades
            ),
            Fault::Unsnapped => scheme == Scheme::StableCascades,
            Fault::WrongFace => scheme == Scheme::Faces,
            Fault::BlendIgnored | Fault::BlendWide | Fault::OverlapDropped => {
                scheme == Scheme::BlendedCascades
            }
            Fault::LispsmNoSin => matches!(
                scheme,
                Scheme::Lispsm | Scheme::Cascades | Scheme::BlendedCascades
            ),
            Fault::TsmFocus => scheme == Scheme::Tsm,
            Fault::UniformWide => scheme == Scheme::Uniform,
            Fault::PsmNPrimeDouble => scheme == Scheme::Psm,
            Fault::SplitsPast => matches!(
                scheme,
                Scheme::Cascades | Scheme::StableCascades | Scheme::BlendedCascades
            ),
            _ => true,
        }
    }

    /// Whether the fault can change a case of `scene` at all: the plain world matrix only far
    /// from the world origin ([`FAR_FROM_ORIGIN`]).
    pub fn applies_to_scene(self, scene: &crate::scene::Scene) -> bool {
        let eye = DVec3::from_array(scene.camera.eye);
        match self {
            Fault::PlainWorld => eye.length() >= FAR_FROM_ORIGIN,
            // Only a camera f32 cannot hold can tell.
            Fault::OriginF32 => eye.as_vec3().as_dvec3() != eye,
            _ => true,
        }
    }

    /// Whether the fault can change a case drawn with `clip_depth`: the strict reversed
    /// comparison only in reversed depth.
    pub fn applies_to_depth(self, clip_depth: ClipDepth) -> bool {
        self != Fault::ReversedStrict || clip_depth == ClipDepth::Reversed
    }

    /// Whether the fault changes the crate's WGSL module (a case under it runs on its own
    /// device, [`Fault::shader_source`]).
    pub fn changes_shader(self) -> bool {
        matches!(
            self,
            Fault::ReversedStrict | Fault::PcfRadiusDoubled | Fault::NormalOffsetDoubled
        )
    }

    /// Whether only the shader-path checks ([`crate::paths`]) use what the fault changes (the
    /// self-test runs it only on their cases).
    pub fn paths_only(self) -> bool {
        matches!(
            self,
            Fault::BiasHalved | Fault::PcfRadiusDoubled | Fault::NormalOffsetDoubled
        )
    }

    /// The shaders' source under `fault`: [`crate::gpu::shader_source`], with the crate's
    /// reversed-depth comparison made strict for [`Fault::ReversedStrict`], the PCF kernel's
    /// reach doubled for [`Fault::PcfRadiusDoubled`], the per-point normal offset doubled for
    /// [`Fault::NormalOffsetDoubled`].
    ///
    /// # Errors
    /// The text to change not found in the crate's module (the fault could not be applied).
    pub fn shader_source(fault: Option<Fault>) -> Result<String, String> {
        let module = shadow_aliasing::frame::SHADOW_WGSL;
        let (from, to) = match fault {
            Some(Fault::ReversedStrict) => ("return d >= stored;", "return d > stored;"),
            Some(Fault::PcfRadiusDoubled) => ("let k = max(r, 0);", "let k = 2 * max(r, 0);"),
            // sa_local_normal_offset's result (its only `return o;`).
            Some(Fault::NormalOffsetDoubled) => ("    return o;\n}", "    return 2.0 * o;\n}"),
            _ => return Ok(crate::gpu::shader_source()),
        };
        if module.matches(from).count() != 1 {
            return Err(format!(
                "{}: the crate's WGSL module has not exactly one `{from}` to change",
                fault.map_or("", |f| f.name())
            ));
        }
        Ok(crate::gpu::shader_source_with(
            &module.replacen(from, to, 1),
        ))
    }

    /// The bias values of a record under `fault`: depth bias and normal offset halved
    /// ([`Fault::BiasHalved`]), the normal offset doubled ([`Fault::NormalOffsetDoubled`]).
    pub fn record_bias(fault: Option<Fault>, r: &mut shadow_aliasing::frame::GpuShadowMap) {
        match fault {
            Some(Fault::BiasHalved) => {
                r.constant_depth *= 0.5;
                r.slope_scaled_depth *= 0.5;
                r.normal_offset *= 0.5;
            }
            Some(Fault::NormalOffsetDoubled) => r.normal_offset *= 2.0,
            _ => {}
        }
    }

    /// The factor of the per-point normal offset (`normal_offset_at`, `sa_local_normal_offset`)
    /// under `fault`: 2 for [`Fault::NormalOffsetDoubled`], else 1.
    pub fn local_offset_factor(fault: Option<Fault>) -> f64 {
        if fault == Some(Fault::NormalOffsetDoubled) {
            2.0
        } else {
            1.0
        }
    }

    /// The upload origin the records are made relative to: the camera's position, rounded
    /// through `f32` under [`Fault::OriginF32`].
    pub fn upload_origin(fault: Option<Fault>, origin: DVec3) -> DVec3 {
        if fault == Some(Fault::OriginF32) {
            origin.as_vec3().as_dvec3()
        } else {
            origin
        }
    }

    /// A map's blend band as the frame reports it and the record carries it: 1.5 × as wide under
    /// [`Fault::BlendWide`].
    pub fn blend(fault: Option<Fault>, (b, e): (f64, f64)) -> (f64, f64) {
        if fault == Some(Fault::BlendWide) && e > b {
            (b, b + BLEND_WIDE * (e - b))
        } else {
            (b, e)
        }
    }

    /// How the maps are culled when `cull` asks for culling.
    pub fn cull(fault: Option<Fault>, cull: bool) -> crate::schemes::Cull {
        use crate::schemes::Cull;
        match (cull, fault) {
            (_, Some(Fault::CullTight)) => Cull::Tight,
            (true, _) => Cull::Casters,
            (false, _) => Cull::Off,
        }
    }

    /// Whether the shader shades a cascade by its first map alone inside the blend band.
    pub fn shades_one_map(fault: Option<Fault>) -> bool {
        fault == Some(Fault::BlendIgnored)
    }

    /// Whether the frame is built with the scene's receivers (all but
    /// [`Fault::ReceiversUnbounded`]).
    pub fn keeps_receivers(fault: Option<Fault>) -> bool {
        fault != Some(Fault::ReceiversUnbounded)
    }

    /// Whether the frame is given the casters.
    pub fn keeps_casters(fault: Option<Fault>) -> bool {
        fault != Some(Fault::NoCasters)
    }

    /// The light the frame is built for (unit, world space), given the scene's `light`.
    pub fn frame_light(fault: Option<Fault>, light: DVec3) -> DVec3 {
        if fault != Some(Fault::LightRotated) {
            return light;
        }
        let axis = light.cross(DVec3::Y);
        let axis = if axis.length() < 1e-6 {
            DVec3::X
        } else {
            axis.normalize()
        };
        glam::DQuat::from_axis_angle(axis, LIGHT_DEG.to_radians()) * light
    }

    /// The faulted OpenGL-depth matrix of `map` (its frame map `fm`, as built `built`), or
    /// `None` when this fault leaves the matrix alone.
    pub fn matrix(self, scheme: Scheme, fm: &FrameMap, built: DMat4, view: &View) -> Option<DMat4> {
        if !self.applies_to(scheme) {
            return None;
        }
        match self {
            Fault::LispsmNoSin => {
                n_prime_scaled(built, fm.body(), crate::papers::sin_gamma(view.light_eye))
            }
            Fault::TsmFocus => {
                let axis = crate::papers::warp_axis(view.light_eye)?;
                let body = fm.body();
                let a: Vec<f64> = body.iter().map(|v| axis.dot(*v)).collect();
                let lo = a.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = a.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                let n_b = body.iter().map(|v| -v.z).fold(f64::INFINITY, f64::min);
                let f_b = body.iter().map(|v| -v.z).fold(f64::NEG_INFINITY, f64::max);
                let fr = &view.frustum;
                let focus = crate::papers::tsm_focus_point((n_b, f_b), (fr.near(), fr.far()));
                let (lambda, delta) = (hi - lo, axis.dot(focus) - lo);
                let k = crate::papers::tsm_eta(lambda, delta, TSM_XI)
                    / crate::papers::tsm_eta(lambda, delta, -0.6);
                (k.is_finite() && k > 0.0)
                    .then(|| n_prime_scaled(built, body, k))
                    .flatten()
            }
            Fault::MatrixScale => Some(DMat4::from_scale(DVec3::new(SCALE, SCALE, 1.0)) * built),
            Fault::UniformWide => Some(
                DMat4::from_scale(DVec3::new(1.0 / UNIFORM_WIDE, 1.0 / UNIFORM_WIDE, 1.0)) * built,
            ),
            Fault::DepthShift => Some(
                built * DMat4::from_translation(view.light_eye * (DEPTH_TEXELS * fm.texel_world)),
            ),
            Fault::NPrimeDouble => n_prime_scaled(built, fm.body(), 2.0),
            Fault::Unsnapped => {
                let (c, _) = shadow_aliasing::maps::cascades::bounding_sphere(
                    &view.frustum,
                    fm.split.0,
                    fm.split.1,
                )
                .ok()?;
                let h = built * DVec4::new(0.0, 0.0, -c, 1.0);
                let (x, y) = (h.x / h.w, h.y / h.w);
                Some(
                    DMat4::from_cols(DVec4::X, DVec4::Y, DVec4::Z, DVec4::new(-x, -y, 0.0, 1.0))
                        * built,
                )
            }
            _ => None,
        }
    }

    /// The factor on the frame's reported error (M_x, M_z, `max_error_pixels`, `texel_world`)
    /// of a map of `scheme`: 1 but where the fault changes the map and reports it honestly.
    pub fn reported_factor(fault: Option<Fault>, scheme: Scheme) -> f64 {
        match fault {
            Some(f @ Fault::UniformWide) if f.applies_to(scheme) => UNIFORM_WIDE,
            _ => 1.0,
        }
    }

    /// The GPU's matrix (depth [0, 1]) of a faulted OpenGL-depth matrix.
    pub fn gpu_matrix(built: DMat4) -> DMat4 {
        GL_TO_01 * built
    }

    /// The rule the crate's frame is built with again for a map of `scheme` focused on `body`
    /// (eye space) under `fault`, or `None` to keep the scheme's own: for
    /// [`Fault::PsmNPrimeDouble`], Lloyd 2006 Eq 11's η whose n′ is 2 n_B for the body's eye
    /// depths `[n_B, f_B]` (α = f_B/n_B: n(√α + 1)/(η√α + 1) = 2n at η = (√α − 1)/(2√α)), which
    /// the crate's `WarpRule::Eta` applies to the body's depth range as `WarpRule::Psm` applies
    /// n′ = n_B to it.
    ///
    /// # Errors
    /// A body without depth (α ≤ 1: no η > 0 gives 2 n_B).
    pub fn psm_rule(
        fault: Option<Fault>,
        scheme: Scheme,
        body: &[DVec3],
    ) -> Option<Result<shadow_aliasing::maps::WarpRule, String>> {
        if fault != Some(Fault::PsmNPrimeDouble) || scheme != Scheme::Psm {
            return None;
        }
        let n_b = body.iter().map(|v| -v.z).fold(f64::INFINITY, f64::min);
        let f_b = body.iter().map(|v| -v.z).fold(f64::NEG_INFINITY, f64::max);
        let ra = (f_b / n_b).sqrt();
        let eta = (ra - 1.0) / (2.0 * ra);
        Some(if eta > 0.0 && eta <= 1.0 {
            Ok(shadow_aliasing::maps::WarpRule::Eta(eta))
        } else {
            Err(format!(
                "psm-n-prime-x2: the body's eye depths [{n_b}, {f_b}] give no η for 2 n_B"
            ))
        })
    }

    /// Changes how the renderer selects the maps of `scheme` (split ranges, faces), where the
    /// fault applies to the scheme ([`Fault::applies_to`]); whether it did.
    pub fn selection(fault: Option<Fault>, scheme: Scheme, maps: &mut [Map]) -> bool {
        if !fault.is_some_and(|f| f.applies_to(scheme)) {
            return false;
        }
        match fault {
            Some(Fault::CascadeOffByOne) => {
                // The shader takes the first map whose far exceeds the fragment's depth: each
                // map given the previous one's range takes the fragments of the split before it.
                for i in (0..maps.len()).rev() {
                    let (near, far) = if i == 0 {
                        (maps[0].near, maps[0].near)
                    } else {
                        (maps[i - 1].near, maps[i - 1].far)
                    };
                    maps[i].near = near;
                    maps[i].far = far;
                }
                if let Some(last) = maps.last_mut() {
                    last.far = f64::INFINITY;
                }
                true
            }
            Some(Fault::SplitsPast) => {
                let n = maps.len();
                for i in 0..n.saturating_sub(1) {
                    maps[i].far *= SPLITS_PAST;
                    maps[i + 1].near = maps[i].far;
                }
                n > 1
            }
            Some(Fault::WrongFace) => {
                let mut faces: Vec<i32> = maps.iter().map(|m| m.region).collect();
                faces.sort_unstable();
                faces.dedup();
                for m in maps.iter_mut() {
                    let k = faces.iter().position(|&f| f == m.region).unwrap_or(0);
                    m.region = faces[(k + 1) % faces.len()];
                }
                true
            }
            _ => false,
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// `scheme` built for the second built-in set-up (`tilted_45`) at 320 × 240, 1024² texels,
    /// depth \[0, 1\], the default options, with `fault` injected.
    pub(crate) fn built(scheme: Scheme, fault: Option<Fault>) -> crate::schemes::Built {
        let setup = &crate::schemes::setups()[1];
        let view = View::new(&setup.scene.camera, setup.scene.light(), 320, 240).unwrap();
        let zo = shadow_aliasing::maps::ClipDepth::ZeroToOne;
        let options = crate::schemes::Options::default();
        crate::schemes::build(scheme, &view, &setup.scene, 1024, fault, zo, &options).unwrap()
    }

    /// Every map given to the wrong face: no map keeps its face, and the records the shader
    /// selects by carry the wrong faces.
    #[test]
    fn wrong_face_moves_every_map() {
        let clean = built(Scheme::Faces, None);
        let wrong = built(Scheme::Faces, Some(Fault::WrongFace));
        let faces: std::collections::BTreeSet<i32> = clean.maps.iter().map(|m| m.region).collect();
        assert!(faces.len() >= 2, "{faces:?}");
        for (a, b) in clean.maps.iter().zip(&wrong.maps) {
            assert_eq!(a.record.face, a.region as u32);
            assert_ne!(a.region, b.region);
            assert_eq!(b.record.face, b.region as u32);
        }
    }

    /// PSM's n′ doubled in the crate's rule: the crate's own frame with twice the n′ of the
    /// clean one (read back from the matrix as in `n_prime_doubled_on_frame_maps`, and as the
    /// frame reports it), on the same body, its reported maxima following the map.
    #[test]
    fn psm_n_prime_doubled_in_the_rule() {
        let clean = built(Scheme::Psm, None);
        let f = built(Scheme::Psm, Some(Fault::PsmNPrimeDouble));
        assert_eq!(clean.bodies, f.bodies);
        let body = &clean.bodies[0];
        let n_b = body.iter().map(|v| -v.z).fold(f64::INFINITY, f64::min);
        let read = |mat: DMat4| {
            let w = mat.row(3);
            let axis = w.truncate().normalize();
            let (mut zlo, mut zhi, mut wlo, mut whi) =
                (f64::INFINITY, f64::MIN, f64::INFINITY, 0.0f64);
            for p in body {
                let (z, ww) = (axis.dot(*p), w.dot(p.extend(1.0)));
                (zlo, zhi, wlo, whi) = (zlo.min(z), zhi.max(z), wlo.min(ww), whi.max(ww));
            }
            (zhi - zlo) / (whi / wlo - 1.0)
        };
        let (a, b) = (&clean.maps[0], &f.maps[0]);
        assert!(
            (read(a.built) / n_b - 1.0).abs() < 1e-6,
            "{} {n_b}",
            read(a.built)
        );
        assert!(
            (read(b.built) / (2.0 * n_b) - 1.0).abs() < 1e-6,
            "{}",
            read(b.built)
        );
        assert!((b.reported.n_prime / (2.0 * a.reported.n_prime) - 1.0).abs() < 1e-9);
        assert!((b.reported.max_mz / a.reported.max_mz - 1.0).abs() > 1e-3);
        // Only PSM's rule: the other schemes are built as without the fault.
        let l = |fault| built(Scheme::Lispsm, fault).maps[0].built;
        assert_eq!(l(None), l(Some(Fault::PsmNPrimeDouble)));
    }

    /// `cascade-off-by-one` changes the cascades' selection only: a single map, the face
    /// partitions and the clipmap keep their split ranges and records (the whole binary applies
    /// a fault to every scheme; it gave the uniform map the range (n, ∞), which the level
    /// set-up's Eq 7–10 then read as the map's depth range: `lloyd_rel_diff` 1.0).
    #[test]
    fn cascade_off_by_one_leaves_other_schemes_alone() {
        for scheme in [Scheme::Uniform, Scheme::Psm, Scheme::Faces, Scheme::Clipmap] {
            let (clean, f) = (
                built(scheme, None),
                built(scheme, Some(Fault::CascadeOffByOne)),
            );
            for (a, c) in clean.maps.iter().zip(&f.maps) {
                assert_eq!((a.near, a.far, a.region), (c.near, c.far, c.region));
                assert_eq!(a.record, c.record, "{}", scheme.name());
            }
        }
        let clean = built(Scheme::Cascades, None);
        let f = built(Scheme::Cascades, Some(Fault::CascadeOffByOne));
        assert_eq!(f.maps[1].near, clean.maps[0].near);
        assert_eq!(f.maps[1].far, clean.maps[0].far);
    }

    #[test]
    fn names_parse_back() {
        for f in Fault::ALL {
            assert_eq!(Fault::parse(f.name()), Ok(f));
        }
        let e = Fault::parse("nope").unwrap_err();
        assert!(e.contains("nope") && e.contains("matrix-scale"), "{e}");
    }
}
