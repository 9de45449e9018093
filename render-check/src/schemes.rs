//! The set-ups (camera and light) and the schemes, built as a renderer builds them.
//!
//! The scene is in world space. Every scheme is built by the crate's world-space frame API
//! ([`shadow_aliasing::frame`]) from the camera's world → eye matrix `V`, the light's world
//! direction and the scene's receiver and caster boxes. Each map's matrix `S` (eye → light clip;
//! the frame's world → light clip is `S V`) is used with eye-space vertices (the GPU gets
//! eye-space positions, transformed in `f64`).

use crate::faults::Fault;
pub use crate::options::Options;
use crate::scene::{Camera, Scene};
use glam::{DMat4, DVec3};
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::frame::{
    frame, Aabb, Bound, Camera as FrameCamera, CascadeSplits, ClipmapOptions, CullVolume,
    FrameInput, FrameScheme, GpuShadowMap, LevelChoice,
};
use shadow_aliasing::maps::faces::{Face, FaceWarp};
use shadow_aliasing::maps::{ClipDepth, TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::ViewFrustum;

/// The schemes compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scheme {
    /// The tight orthographic map.
    Uniform,
    /// LiSPSM with n′ from 1/sin γ.
    Lispsm,
    /// The crate's minimax n′.
    Minimax,
    /// Trapezoidal shadow maps (80 % rule).
    Tsm,
    /// 4 z-partitions, LiSPSM each (practical split, λ = 0.75).
    Cascades,
    /// 4 stable cascades (bounding spheres, snapped to texels).
    StableCascades,
    /// Face partitions (LiSPSM per face, k = 1).
    Faces,
    /// 4 z-partitions as [`Scheme::Cascades`], each reaching [`BLEND_OVERLAP`] of its depth into
    /// the next: cross-faded over that band by the crate's `sa_cascaded_visibility`.
    BlendedCascades,
    /// A clipmap ([`ClipmapOptions::UNREAL`]'s levels and LOD bias, the scene's map resolution):
    /// the level picked by the crate's `sa_clipmap_level`.
    Clipmap,
    /// Perspective shadow maps' parameter (Stamminger & Drettakis 2002; Lloyd 2006 §4.1:
    /// n′ = n, the body's nearest eye depth): the crate's `WarpRule::Psm`, one map.
    Psm,
}

impl Scheme {
    /// All schemes, in the order of the gallery.
    pub const ALL: [Scheme; 10] = [
        Scheme::Uniform,
        Scheme::Lispsm,
        Scheme::Minimax,
        Scheme::Tsm,
        Scheme::Cascades,
        Scheme::StableCascades,
        Scheme::Faces,
        Scheme::BlendedCascades,
        Scheme::Clipmap,
        Scheme::Psm,
    ];
    /// The name in images' titles.
    pub fn label(self) -> &'static str {
        match self {
            Scheme::Uniform => "uniform",
            Scheme::Lispsm => "LiSPSM, n′ = (n + √(f n))/sin γ",
            Scheme::Minimax => "minimax n′",
            Scheme::Tsm => "TSM (80 % rule)",
            Scheme::Cascades => "4 cascades, LiSPSM each",
            Scheme::StableCascades => "4 stable cascades",
            Scheme::Faces => "face partitions (LiSPSM, k = 1)",
            Scheme::BlendedCascades => "4 cascades, LiSPSM, cross-faded over 25 %",
            Scheme::Clipmap => "clipmap (Unreal's levels)",
            Scheme::Psm => "PSM, n′ = n",
        }
    }
    /// The name in summary.json.
    pub fn name(self) -> &'static str {
        match self {
            Scheme::Uniform => "uniform",
            Scheme::Lispsm => "lispsm",
            Scheme::Minimax => "minimax",
            Scheme::Tsm => "tsm",
            Scheme::Cascades => "cascades4_lispsm",
            Scheme::StableCascades => "stable_cascades4",
            Scheme::Faces => "face_partitions",
            Scheme::BlendedCascades => "cascades4_blend",
            Scheme::Clipmap => "clipmap",
            Scheme::Psm => "psm",
        }
    }
}

/// The built-in set-ups built so that every scheme's worst body point is on screen (the level
/// camera: each map's error depends on the eye depth alone and is largest on the near plane,
/// where the ground shows): there `frame_error_ratio_worst_visible` must be measured, and a
/// null is a violation ([`crate::targets::violations`]), not a check that silently did not run.
pub const WORST_POINT_ON_SCREEN: [&str; 2] = ["level_overhead", "level_side"];

/// The built-in set-ups that do not run [`Scheme::Psm`]: `front_5`, the light from in front
/// (γ = 175°). Lloyd 2006 §4.4 has PSM revert to the orthographic map with the light in front
/// of or behind the viewer; the crate's `WarpRule::Psm` keeps n′ = n at every direction, and at
/// γ = 175° its map's texels far from the camera are so large that, on a correct crate, fewer
/// than half of the shadowed pixels are decidable and the GPU's `f32` texel coordinates move by
/// too little over the derivatives' steps for the paper's comparison (12) to hold its 99th
/// percentile (docs/rendered.md, "Schemes").
pub const PSM_SKIPPED: [&str; 1] = ["front_5"];

/// The schemes a set-up named `setup` runs: [`Scheme::ALL`], less [`Scheme::Psm`] in the set-ups
/// of [`PSM_SKIPPED`] (a scene file runs all).
pub fn schemes_for(setup: &str) -> Vec<Scheme> {
    Scheme::ALL
        .into_iter()
        .filter(|&s| s != Scheme::Psm || !PSM_SKIPPED.contains(&setup))
        .collect()
}

/// How the fragment picks its map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Select {
    /// One map.
    Single,
    /// By eye depth, in the parts' `[near, far)`.
    Depth,
    /// By the frustum face the point's light ray passes (Lloyd 2005 §4; see the shader).
    Faces,
    /// By the clipmap level at the eye depth (`sa_clipmap_level`, [`Built::clipmap`]).
    Clipmap,
}

/// One map: its eye → light clip matrix (OpenGL depth, as built), the same map with depth
/// [0, 1], the record the GPU takes, how the shader selects it, what the frame reported for it
/// and its culling volumes.
#[derive(Debug, Clone, Copy)]
pub struct Map {
    /// As built (eye → light clip, OpenGL depth): what the measurement takes.
    pub built: DMat4,
    /// The same map, eye → light clip with depth [0, 1]: what the analysis looks up with.
    pub gpu: DMat4,
    /// The record uploaded (`FrameMap::gpu_relative` for the build's origin and clip-depth
    /// convention; its matrix, split and face faulted where a fault changes them): the shader's
    /// map, selected and looked up by the crate's WGSL module.
    pub record: GpuShadowMap,
    /// The record with the bias values for a PCF kernel of radius 1 (`FrameMap::
    /// gpu_relative_with_pcf`, or `gpu_with_pcf` on the plain path), its matrix, split, band
    /// and face the uploaded record's (faults included): the shader-path checks' r = 1 pass
    /// ([`crate::paths`]).
    pub record_pcf1: GpuShadowMap,
    /// `FrameMap::casters_volume`: what culling draws into the map.
    pub casters: CullVolume,
    /// `FrameMap::receivers_volume` (the cull-tight fault cuts the casters' volume by it).
    pub receivers: CullVolume,
    /// −1 for a depth range, else the face (bottom, right, top, left, near, far).
    pub region: i32,
    /// The texels per side render-check asked the map for: [`Options::resolutions`]' entry for
    /// its slot, else the case's resolution (not read from the crate).
    pub res: u32,
    /// Depth range covered.
    pub near: f64,
    /// Depth range covered.
    pub far: f64,
    /// What the frame reported for this map (`FrameMap`'s numbers), kept as reported when a
    /// fault changes the matrix.
    pub reported: Reported,
}

/// A map's numbers as the frame reported them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reported {
    /// `FrameMap::max_error_pixels`: max(M_x, M_z) · image height / map resolution.
    pub max_error_pixels: f64,
    /// `FrameMap::max_mx` (unit resolutions).
    pub max_mx: f64,
    /// `FrameMap::max_mz` (unit resolutions).
    pub max_mz: f64,
    /// The warp's n′ (infinite for an orthographic map).
    pub n_prime: f64,
    /// `FrameMap::texel_world`.
    pub texel_world: f64,
    /// `FrameMap::storage_factor` (S̄ = M_x M_z, unit resolutions).
    pub storage_factor: f64,
    /// `FrameMap::blend`.
    pub blend: (f64, f64),
}

/// Which objects each map draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Cull {
    /// Every object into every map.
    Off,
    /// An object only into the maps whose casters' volume it may meet
    /// (`CullVolume::intersects_aabb`).
    Casters,
    /// A fault: the casters' volume cut by the receivers' volume (the view slice), which drops
    /// the casters outside the view.
    Tight,
}

impl Map {
    /// Whether the world box `min`..`max` is drawn into this map under `cull`.
    pub fn draws(&self, min: DVec3, max: DVec3, cull: Cull) -> bool {
        let Ok(b) = Aabb::new(min, max) else {
            return true;
        };
        match cull {
            Cull::Off => true,
            Cull::Casters => self.casters.intersects_aabb(&b),
            Cull::Tight => self.casters.intersects_aabb(&b) && self.receivers.intersects_aabb(&b),
        }
    }
}

/// A scheme built for one frame.
#[derive(Debug, Clone)]
pub struct Built {
    /// The maps.
    pub maps: Vec<Map>,
    /// The upload origin: vertex positions go to the GPU relative to it (the camera's position).
    pub origin: DVec3,
    /// Added to a relative position (in `f32`) before a map's matrix: 0 on the relative path;
    /// the origin for the plain world matrix (a fault).
    pub offset: DVec3,
    /// How fragments choose.
    pub select: Select,
    /// Each map's focus body as the frame returned it (`FrameMap::body`, eye space): where the
    /// reported maximum error lies (docs/rendered.md).
    pub bodies: Vec<Vec<DVec3>>,
    /// Clipmaps: the level choice's offset (`LevelChoice::offset`) and the first and the last
    /// map's level; zero for the other schemes.
    pub clipmap: [f64; 3],
    /// The fault `blend-ignored`: the shader shades a cascade by its first map alone inside the
    /// blend band.
    pub one_map_in_band: bool,
    /// The cascades' split planes as the paper places them ([`crate::papers::practical_planes`]
    /// over the camera's near and far, computed here, not by the crate); empty for a scheme not
    /// selected by depth.
    pub planes: Vec<f64>,
    /// Whether the frame was asked to rely on depth clamp ([`Options::depth_clamp`]).
    pub depth_clamp: bool,
    /// The blend bands the requested overlap makes ([`crate::papers::blend_bands`], computed
    /// here, not `FrameMap::blend`); empty for a scheme that requests none.
    pub bands: Vec<(f64, f64)>,
}

/// The camera's frustum and matrices.
#[derive(Debug, Clone, Copy)]
pub struct View {
    /// World → eye.
    pub world_to_eye: DMat4,
    /// Eye → clip (wgpu: depth [0, 1], NDC y up).
    pub proj: DMat4,
    /// The validated frustum.
    pub frustum: ViewFrustum,
    /// Unit light direction (travel), eye space.
    pub light_eye: DVec3,
    /// Unit light direction, world space.
    pub light_world: DVec3,
    /// The camera's position, world space: the upload origin.
    pub origin: DVec3,
    /// The image's height, pixels (the frame's `image_height`: a clipmap's level choice).
    pub image_height: u32,
}

impl View {
    /// The view of `camera` with a `width × height` image.
    ///
    /// # Errors
    /// The crate's error for an invalid frustum.
    pub fn new(
        camera: &Camera,
        light_world: DVec3,
        width: u32,
        height: u32,
    ) -> Result<Self, String> {
        let aspect = f64::from(width) / f64::from(height);
        let half = 0.5 * camera.fov_y_deg.to_radians();
        let frustum = ViewFrustum::with_aspect(camera.near, camera.far, half, aspect)
            .map_err(|e| e.to_string())?;
        let world_to_eye = glam::dcamera::rh::view::look_at_mat4(
            DVec3::from_array(camera.eye),
            DVec3::from_array(camera.target),
            DVec3::from_array(camera.up),
        );
        let proj = glam::dcamera::rh::proj::directx::perspective(
            2.0 * half,
            aspect,
            camera.near,
            camera.far,
        );
        let light_world = light_world.normalize();
        Ok(Self {
            world_to_eye,
            proj,
            frustum,
            light_eye: world_to_eye.transform_vector3(light_world).normalize(),
            light_world,
            origin: DVec3::from_array(camera.eye),
            image_height: height,
        })
    }

    /// near, far, tan θ, tan θ · aspect.
    pub fn frustum_params(&self) -> [f64; 4] {
        let t = self.frustum.tan_half_fov();
        [
            self.frustum.near(),
            self.frustum.far(),
            t,
            t * self.frustum.aspect(),
        ]
    }
}

fn face_id(f: Face) -> i32 {
    match f {
        Face::Bottom => 0,
        Face::Right => 1,
        Face::Top => 2,
        Face::Left => 3,
        Face::Near => 4,
        Face::Far => 5,
    }
}

/// The cascades' split scheme (practical, λ = 0.75) and count, for both cascade schemes.
const CASCADE_SPLIT: SplitScheme = SplitScheme::Practical {
    lambda: CASCADE_LAMBDA,
};
/// The practical split's λ (the logarithmic part) of both cascade schemes.
pub const CASCADE_LAMBDA: f64 = 0.75;
pub const CASCADES: usize = 4;
/// [`Scheme::BlendedCascades`]: each cascade but the last reaches this fraction of its own depth
/// into the next (`CascadeSplits::Scheme`'s overlap), the band cross-faded.
pub const BLEND_OVERLAP: f64 = 0.25;

/// The split planes of the cascades (practical, λ = 0.75, 4 partitions: the frame schemes' own).
pub fn splits(view: &ViewFrustum) -> Result<shadow_aliasing::analytic::partition::Splits, String> {
    z_splits(view.near(), view.far(), CASCADES, CASCADE_SPLIT).map_err(|e| e.to_string())
}

/// The scene's bounds for the frame API: receivers are the drawn ground square (zero thickness)
/// and every box, merged by the frame into one bounding box; casters are the boxes (the tower
/// outside the view included). A rotated box is given as its world-space bounding box (the
/// frame takes axis-aligned boxes, or one polytope for the receivers).
fn bounds(scene: &Scene) -> Result<(Vec<Aabb>, Vec<Aabb>), String> {
    let aabb = |min: DVec3, max: DVec3| Aabb::new(min, max).map_err(|e| e.to_string());
    let casters = scene
        .boxes
        .iter()
        .map(|b| {
            let (min, max) = b.world_bounds();
            aabb(min, max)
        })
        .collect::<Result<Vec<_>, String>>()?;
    let c = DVec3::from_array(scene.camera.eye);
    let e = scene.ground_half_extent;
    let ground = aabb(
        DVec3::new(c.x - e, scene.ground_y, c.z - e),
        DVec3::new(c.x + e, scene.ground_y, c.z + e),
    )?;
    let mut receivers = vec![ground];
    receivers.extend_from_slice(&casters);
    Ok((receivers, casters))
}

/// The frame API's scheme for `scheme_` (the fault `overlap-dropped` asks the blended cascades
/// for no overlap).
fn frame_scheme(
    scheme_: Scheme,
    view: &ViewFrustum,
    res: u32,
    fault: Option<Fault>,
    split: SplitScheme,
) -> FrameScheme<'static> {
    let practical = CascadeSplits::Scheme {
        scheme: split,
        k: CASCADES,
        overlap: 0.0,
    };
    match scheme_ {
        Scheme::Uniform => FrameScheme::Single(WarpRule::Uniform),
        Scheme::Lispsm => FrameScheme::Single(WarpRule::Lispsm),
        Scheme::Minimax => FrameScheme::Single(WarpRule::Minimax),
        Scheme::Tsm => FrameScheme::Tsm(TsmOptions {
            focus: crate::papers::TSM_FOCUS_SHARE * (view.far() - view.near()),
            search: TsmSearch::EightyPercent,
        }),
        Scheme::Cascades => FrameScheme::Cascades {
            splits: practical,
            rule: WarpRule::Lispsm,
        },
        Scheme::StableCascades => FrameScheme::Stable(practical),
        Scheme::Faces => FrameScheme::Faces {
            rule: FaceWarp::Lispsm,
            k: 1,
        },
        Scheme::BlendedCascades => FrameScheme::Cascades {
            splits: CascadeSplits::Scheme {
                scheme: split,
                k: CASCADES,
                overlap: if fault == Some(Fault::OverlapDropped) {
                    0.0
                } else {
                    BLEND_OVERLAP
                },
            },
            rule: WarpRule::Lispsm,
        },
        Scheme::Clipmap => FrameScheme::Clipmap(clipmap_options(res)),
        Scheme::Psm => FrameScheme::Single(WarpRule::Psm),
    }
}

/// Unreal's clipmap layout ([`ClipmapOptions::UNREAL`]: levels 6 to 22 of radius 2^(i+1) cm,
/// LOD bias −0.5) with pages of 128 texels where `res` holds at least two of them, else the
/// largest that divides it into at least two.
pub fn clipmap_options(res: u32) -> ClipmapOptions {
    let page = (1..=ClipmapOptions::UNREAL.page_texels)
        .rev()
        .find(|&p| res.is_multiple_of(p) && res / p >= 2)
        .unwrap_or(1);
    ClipmapOptions {
        page_texels: page,
        ..ClipmapOptions::UNREAL
    }
}

/// Builds `scheme` for `view`, `res` texels per map side, through the crate's world-space frame
/// API ([`shadow_aliasing::frame::frame`]): each map is focused on the receivers in view, its
/// depth range reaches every caster that can shadow them, and the GPU renders with the frame's
/// own matrix in depth \[0, 1\]. `fault` injects one deliberate fault ([`Fault`], the check that
/// the targets can fail) into the frame's input, its matrices or the maps' selection; `options`
/// are the frame options beyond the defaults ([`Options`], [`crate::options`];
/// `Options::default()` for the built-in set-ups).
///
/// # Errors
/// The crate's error, as text; a frame with no map (the scene out of view) is an error here.
pub fn build(
    scheme_: Scheme,
    view: &View,
    scene: &Scene,
    res: u32,
    fault: Option<Fault>,
    clip_depth: ClipDepth,
    options: &Options,
) -> Result<Built, String> {
    let e = |e: shadow_aliasing::Error| format!("{}: {e}", scheme_.name());
    let origin = view.origin;
    let plain = fault == Some(Fault::PlainWorld);
    // What a relative position, as the GPU holds it, is in world space: origin + position.
    let rel_to_eye = view.world_to_eye * DMat4::from_translation(origin);
    let fr = &view.frustum;
    let (receivers, boxes) = bounds(scene)?;
    let camera = FrameCamera::new(
        view.world_to_eye,
        fr.near(),
        fr.far(),
        fr.half_fov(),
        fr.aspect(),
    )
    .map_err(e)?;
    let light = Fault::frame_light(fault, view.light_world);
    let input = FrameInput::new(camera, light, res, view.image_height)
        .receivers(if Fault::keeps_receivers(fault) {
            Bound::Boxes(&receivers)
        } else {
            Bound::Unbounded
        })
        .casters(if Fault::keeps_casters(fault) {
            Bound::Boxes(&boxes)
        } else {
            Bound::Unbounded
        })
        .depth_clamp(options.depth_clamp)
        .scheme(frame_scheme(scheme_, fr, res, fault, options.split()));
    let input = match &options.resolutions {
        Some(each) => input.map_resolutions(each),
        None => input,
    };
    let mut f = frame(&input).map_err(e)?;
    // A fault in the crate's rule: the frame built again with the faulted rule's n′.
    let faulted_rule = f
        .maps()
        .iter()
        .next()
        .and_then(|m| Fault::psm_rule(fault, scheme_, m.body()));
    if let Some(rule) = faulted_rule {
        f = frame(&input.scheme(FrameScheme::Single(rule?))).map_err(e)?;
    }
    if f.is_empty() {
        return Err(format!(
            "{}: the frame built no map ({:?})",
            scheme_.name(),
            f.focus()
        ));
    }
    // A fault reported honestly scales the frame's reported error with the map.
    let honest = Fault::reported_factor(fault, scheme_);
    // Each built map's slot: its requested resolution.
    let slot_res: Vec<u32> = f
        .slots()
        .iter()
        .enumerate()
        .filter(|(_, m)| m.is_some())
        .map(|(i, _)| {
            options
                .resolutions
                .as_ref()
                .and_then(|r| r.get(i).copied())
                .unwrap_or(res)
        })
        .collect();
    let mut maps: Vec<Map> = f
        .maps()
        .iter()
        .zip(&slot_res)
        .map(|(m, &map_res)| {
            let clean = m.shadow.matrix();
            let mut record = if plain {
                m.gpu(clip_depth)
            } else {
                m.gpu_relative(Fault::upload_origin(fault, origin), clip_depth)
            };
            let pcf1 = if plain {
                m.gpu_with_pcf(clip_depth, 1.0)
            } else {
                m.gpu_relative_with_pcf(Fault::upload_origin(fault, origin), clip_depth, 1.0)
            }
            .map_err(e)?;
            let blend = Fault::blend(fault, m.blend);
            record.blend = [blend.0 as f32, blend.1 as f32];
            let (built, gpu) = match fault.and_then(|x| x.matrix(scheme_, m, clean, view)) {
                Some(b) => {
                    record.world_to_clip = (clip_depth.convert(&b) * rel_to_eye)
                        .as_mat4()
                        .to_cols_array_2d();
                    (b, Fault::gpu_matrix(b))
                }
                None => (clean, m.shadow.with_clip_depth(ClipDepth::ZeroToOne)),
            };
            Ok(Map {
                built,
                gpu,
                record,
                record_pcf1: pcf1,
                casters: *m.casters_volume(),
                receivers: *m.receivers_volume(),
                region: m.face.map_or(-1, face_id),
                res: map_res,
                near: m.split.0,
                far: m.split.1,
                reported: Reported {
                    max_error_pixels: m.max_error_pixels * honest,
                    max_mx: m.max_mx * honest,
                    max_mz: m.max_mz * honest,
                    n_prime: m.shadow.n_prime().value(),
                    texel_world: m.texel_world * honest,
                    storage_factor: m.storage_factor * honest * honest,
                    blend,
                },
            })
        })
        .collect::<Result<_, String>>()?;
    if Fault::selection(fault, scheme_, &mut maps) {
        // The shader selects by the record: give it the faulted ranges and faces.
        for m in &mut maps {
            m.record.split = [m.near as f32, m.far as f32];
            m.record.face = u32::try_from(m.region).unwrap_or(GpuShadowMap::NO_FACE);
        }
    }
    for m in &mut maps {
        // The r = 1 record: the uploaded record's matrix, ranges and face, its own bias values.
        let r = &mut m.record_pcf1;
        r.world_to_clip = m.record.world_to_clip;
        r.split = m.record.split;
        r.blend = m.record.blend;
        r.face = m.record.face;
        Fault::record_bias(fault, &mut m.record);
        Fault::record_bias(fault, r);
    }
    let select = match scheme_ {
        Scheme::Cascades | Scheme::StableCascades | Scheme::BlendedCascades => Select::Depth,
        Scheme::Faces => Select::Faces,
        Scheme::Clipmap => Select::Clipmap,
        _ => Select::Single,
    };
    let clipmap = if scheme_ == Scheme::Clipmap {
        clipmap_choice(&f, view, res)?
    } else {
        [0.0; 3]
    };
    let bodies = f.maps().iter().map(|m| m.body().to_vec()).collect();
    let planes = if select == Select::Depth {
        crate::papers::practical_planes(fr.near(), fr.far(), CASCADES, options.lambda())
    } else {
        Vec::new()
    };
    let bands = if scheme_ == Scheme::BlendedCascades {
        crate::papers::blend_bands(&planes, BLEND_OVERLAP)
    } else {
        Vec::new()
    };
    Ok(Built {
        depth_clamp: options.depth_clamp,
        planes,
        bands,
        maps,
        origin,
        offset: if plain { origin } else { DVec3::ZERO },
        select,
        bodies,
        clipmap,
        one_map_in_band: Fault::shades_one_map(fault),
    })
}

/// The shader's clipmap level choice: `LevelChoice::offset` and the first and the last map's
/// level. The shader's slot is the level less the first map's, so the maps must be one per
/// level, finest first, with no level missing.
///
/// # Errors
/// The crate's error; a level missing among the maps.
fn clipmap_choice(
    f: &shadow_aliasing::frame::Frame,
    view: &View,
    res: u32,
) -> Result<[f64; 3], String> {
    let choice = LevelChoice::new(&view.frustum, view.image_height, res, &clipmap_options(res))
        .map_err(|e| format!("clipmap: {e}"))?;
    let levels: Vec<Option<i32>> = f.maps().iter().map(|m| m.clipmap_level).collect();
    let first = levels
        .first()
        .copied()
        .flatten()
        .ok_or("clipmap: no level")?;
    for (i, l) in levels.iter().enumerate() {
        if *l != Some(first + i as i32) {
            return Err(format!(
                "clipmap: the maps' levels {levels:?} are not one per level from {first}: the \
                 shader's slot (level − {first}) would name the wrong map"
            ));
        }
    }
    Ok([
        choice.offset,
        f64::from(first),
        f64::from(first + levels.len() as i32 - 1),
    ])
}

/// A named camera and light.
#[derive(Debug, Clone)]
pub struct Setup {
    /// Name in summary.json.
    pub name: String,
    /// The scene with this camera and light.
    pub scene: Scene,
}

fn rotate_toward(v: DVec3, u: DVec3, deg: f64) -> DVec3 {
    let a = deg.to_radians();
    (v * a.cos() + u * a.sin()).normalize()
}

/// The set-ups: seven of the built-in scene and the thin-caster scene. With `v` the view
/// direction and `u` the camera's up (both unit, orthogonal), γ the angle between view and light:
///
/// - `overhead`: light straight down;
/// - `tilted_45`: 45° elevation, travelling forward and to the right;
/// - `behind_5`: γ = 5°, the light from behind the viewer (`L = cos5° v − sin5° u`);
/// - `front_5`: γ = 175°, the light from in front, towards the viewer (the camera pitched up 3°
///   so that this light still comes from above: 8° elevation);
/// - `grazing_10`: 10° elevation, across the view;
/// - `parallel_1`: γ = 1°, the light from behind, 1° from parallel to the view direction;
/// - `level_overhead`: Lloyd 2006's overhead case (γ = 90°): the camera level, 0.896 n tan θ
///   above the ground (so the ground meets the near plane 0.896 of the way down the screen, just
///   below a row of pixel centres at 180, 240 and 480 rows), the light straight down; every
///   map's focus body then has the frustum's (or its slice's) footprint, and the rendered M_x,
///   M_z over the ground are compared with Eq 7–10 (`analysis`);
/// - `level_side`: `level_overhead`'s camera with the light 45° high from the side (travelling
///   along +X, perpendicular to the view: γ = 90° again, but not straight down), so that each
///   map's error depends on the eye depth alone and its worst body point, on the near plane, is
///   the nearest visible ground (the two-sided `frame_error_ratio_worst_visible`);
///
/// and `thin_casters`, the thin-caster scene ([`Scene::thin_casters`], also
/// `render-check/scenes/thin_casters.json`) under its own 20° sun, and `far_1e5`, the same scene
/// moved 10⁵ from the world origin ([`FAR_OFFSET`]): drawn through the relative upload path it
/// meets every target as at the origin, and the plain `f32` world matrix fails there (the fault
/// suite's `plain-world`).
pub fn setups() -> Vec<Setup> {
    let base = Scene::builtin();
    let cam = base.camera;
    let dir = |c: &Camera| (DVec3::from_array(c.target) - DVec3::from_array(c.eye)).normalize();
    let up_of = |c: &Camera| {
        let f = dir(c);
        let r = f.cross(DVec3::from_array(c.up)).normalize();
        r.cross(f)
    };
    let mut out = Vec::new();
    let mut push = |name: &str, camera: Camera, l: DVec3| {
        let mut s = base.clone();
        s.camera = camera;
        s.light_dir = l.to_array();
        out.push(Setup {
            name: name.into(),
            scene: s,
        });
    };
    let (v, u) = (dir(&cam), up_of(&cam));
    let elev = |deg: f64, h: DVec3| {
        let a = deg.to_radians();
        (DVec3::NEG_Y * a.sin() + h.normalize() * a.cos()).normalize()
    };
    push("overhead", cam, DVec3::NEG_Y);
    push("tilted_45", cam, elev(45.0, DVec3::new(0.5, 0.0, -1.0)));
    push("behind_5", cam, rotate_toward(v, -u, 5.0));
    let mut up_cam = cam;
    up_cam.target = [0.0, 6.0 + 40.0 * 3f64.to_radians().tan(), -40.0];
    let (v2, u2) = (dir(&up_cam), up_of(&up_cam));
    push("front_5", up_cam, rotate_toward(-v2, -u2, 5.0));
    push("grazing_10", cam, elev(10.0, DVec3::new(1.0, 0.0, -0.3)));
    push("parallel_1", cam, rotate_toward(v, -u, 1.0));
    let mut level = cam;
    let h = 0.896 * cam.near * (0.5 * cam.fov_y_deg).to_radians().tan();
    level.eye = [0.0, h, 0.0];
    level.target = [0.0, h, -40.0];
    push("level_overhead", level, DVec3::NEG_Y);
    let level_side = (level, elev(45.0, DVec3::X));
    out.push(Setup {
        name: "thin_casters".into(),
        scene: Scene::thin_casters(),
    });
    out.push(Setup {
        name: "far_1e5".into(),
        scene: Scene::thin_casters().translated(FAR_OFFSET),
    });
    let tilted = out[1].scene.translated(FAR_TILTED_OFFSET);
    out.push(Setup {
        name: "far_tilted".into(),
        scene: tilted,
    });
    let mut side = base.clone();
    side.camera = level_side.0;
    side.light_dir = level_side.1.to_array();
    out.push(Setup {
        name: "level_side".into(),
        scene: side,
    });
    out
}

/// The offset of the set-up `far_1e5` from the thin-caster scene: 10⁵ from the world origin,
/// horizontally, by amounts `f32` cannot hold (its camera, 60 000.3 and −80 000.7 from the
/// origin there, is 0.0008 and 0.0031 from the nearest `f32`s).
pub const FAR_OFFSET: DVec3 = DVec3::new(60_000.3, 0.0, -80_000.7);

/// The offset of the set-up `far_tilted` (`tilted_45`'s camera and light) from the built-in
/// scene: 1.2·10⁵ from the world origin, horizontally, by amounts `f32` cannot hold.
pub const FAR_TILTED_OFFSET: DVec3 = DVec3::new(-90_000.37, 0.0, 80_000.61);
