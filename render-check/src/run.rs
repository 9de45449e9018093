//! One case (set-up × scheme) end to end, the shimmer test, and summary.json.

use crate::analysis::{analyse, pixel_point, Analysis, Measured};
use crate::faults::Fault;
use crate::gpu::{FrameInput, Gpu, Lookup};
use crate::scene::{Mesh, Scene, FACING};
use crate::schemes::{build, Built, Options, Scheme, Select, View};
use glam::{DMat4, DVec3};
use serde::Serialize;
use shadow_aliasing::frame::GpuShadowMap;
use shadow_aliasing::maps::ClipDepth;
use std::ops::Range;

/// One row of summary.json (docs/rendered.md lists the fields; [`crate::targets`] the limits).
#[derive(Debug, Clone, Serialize)]
pub struct CaseSummary {
    /// Set-up name.
    pub setup: String,
    /// Scheme name.
    pub scheme: String,
    /// Screen width, pixels.
    pub width: u32,
    /// Screen height, pixels.
    pub height: u32,
    /// Texels along each side of each map.
    pub map_resolution: u32,
    /// Texels of all the scheme's maps together.
    pub map_texels: u64,
    /// What the analysis measured (flattened into the row).
    #[serde(flatten)]
    pub measured: Measured,
    /// Fraction of sampled shadow-edge points whose state changed between frames (cascade
    /// schemes).
    pub shimmer_changed_fraction: Option<f64>,
    /// The shadow-edge points the shimmer test followed (cascade schemes).
    pub shimmer_points: Option<usize>,
    /// How far fixed world points move between shimmer frames in each stable map from a whole
    /// number of texels, the largest ([`crate::snap`]; stable cascades).
    pub stable_grid_texels: Option<f64>,
    /// The records' clip-depth convention: "zero_to_one" or "reversed".
    pub clip_depth: &'static str,
    /// Each map's geometry against render-check's own reconstruction ([`crate::geometry`]).
    #[serde(flatten)]
    pub geometry: crate::geometry::Geometry,
    /// The lens overlay the GPU drew against the library's Rust ramp ([`crate::overlay`]).
    #[serde(flatten)]
    pub overlay: crate::overlay::OverlayCheck,
    /// The shader paths checked ([`crate::paths`]; `None` outside [`crate::paths::CASES`]).
    pub paths: Option<Vec<crate::paths::PathSummary>>,
}

/// summary.json.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// The adapter.
    pub device: String,
    /// Every case.
    pub cases: Vec<CaseSummary>,
    /// The option cases of the set-ups run ([`crate::options`]; CPU only).
    pub options: Vec<crate::options::OptionSummary>,
}

/// Sizes of a run.
#[derive(Debug, Clone, Copy)]
pub struct Sizes {
    /// Screen width.
    pub width: u32,
    /// Screen height.
    pub height: u32,
    /// Map resolution (per map), overriding the scene's when set.
    pub res: Option<u32>,
    /// Frames of the shimmer test.
    pub frames: usize,
    /// Sample points of the shimmer test (at most).
    pub shimmer_points: usize,
    /// One deliberate fault injected into every frame built ([`crate::faults::Fault`]; the check
    /// that the targets can fail), or none.
    pub fault: Option<crate::faults::Fault>,
    /// How the maps are uploaded, culled and looked up.
    pub render: Render,
}

/// How a run uploads, culls and looks up the maps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Render {
    /// The records' clip-depth convention: [`ClipDepth::ZeroToOne`] (the shadow pass compares
    /// less, the lookup less-equal) or [`ClipDepth::Reversed`] (greater-equal both).
    pub clip_depth: ClipDepth,
    /// Second-depth maps with the hand-set rasterizer bias, or first-surface maps with the
    /// crate's normal offset.
    pub lookup: Lookup,
    /// Whether each object is drawn only into the maps whose casters' volume it may meet.
    pub cull: bool,
}

impl Render {
    /// What `render-check` does unless told otherwise: depth [0, 1], second-depth maps, culling.
    pub const DEFAULT: Render = Render {
        clip_depth: ClipDepth::ZeroToOne,
        lookup: Lookup::SecondDepth,
        cull: true,
    };
}

/// A case's full result.
pub struct CaseResult {
    /// The summary row.
    pub summary: CaseSummary,
    /// The analysis (heat-map data).
    pub analysis: Analysis,
    /// Shaded colour.
    pub color: Vec<[u8; 4]>,
    /// The error lens drawn over the shaded colour by the GPU.
    pub overlay: Vec<[u8; 4]>,
    /// Diagnostics: excluded pixels, interior and edge-band sizes.
    pub diagnostics: String,
}

/// The mesh as uploaded: positions relative to the upload origin (the `f64` difference, rounded
/// once to `f32` on upload), world-space normals.
pub struct UploadMesh {
    /// Triangle vertices relative to the origin.
    pub positions: Vec<DVec3>,
    /// Each vertex's surface normal, world space.
    pub normals: Vec<DVec3>,
}

impl UploadMesh {
    /// `mesh` relative to `origin`.
    pub fn new(mesh: &Mesh, origin: DVec3) -> Self {
        Self {
            positions: mesh.positions.iter().map(|&p| p - origin).collect(),
            normals: mesh
                .surface
                .iter()
                .map(|&s| mesh.surfaces[s as usize].normal)
                .collect(),
        }
    }
}

fn mode(s: Select) -> u32 {
    match s {
        Select::Single => 0,
        Select::Depth => 1,
        Select::Faces => 2,
        Select::Clipmap => 3,
    }
}

/// Per map, the vertex ranges of the objects drawn into it.
pub fn draws(built: &Built, mesh: &Mesh, sizes: Sizes) -> Vec<Vec<Range<u32>>> {
    let cull = Fault::cull(sizes.fault, sizes.render.cull);
    built
        .maps
        .iter()
        .map(|m| {
            mesh.objects
                .iter()
                .filter(|o| m.draws(o.min, o.max, cull))
                .map(|o| o.vertices.clone())
                .collect()
        })
        .collect()
}

/// One frame's upload: the records, the draws and the mesh.
pub struct Upload {
    records: Vec<GpuShadowMap>,
    draws: Vec<Vec<Range<u32>>>,
    mesh: UploadMesh,
}

impl Upload {
    /// The upload of `built` with `mesh`.
    pub fn new(built: &Built, mesh: &Mesh, sizes: Sizes) -> Self {
        Self {
            records: built.maps.iter().map(|m| m.record).collect(),
            draws: draws(built, mesh, sizes),
            mesh: UploadMesh::new(mesh, built.origin),
        }
    }

    /// The GPU's frame.
    pub fn input<'a>(
        &'a self,
        view: &View,
        mesh: &'a Mesh,
        built: &Built,
        res: u32,
        sizes: Sizes,
    ) -> FrameInput<'a> {
        let rel_to_eye = view.world_to_eye * DMat4::from_translation(built.origin);
        FrameInput {
            positions: &self.mesh.positions,
            normals: &self.mesh.normals,
            surface: &mesh.surface,
            rel_to_clip: view.proj * rel_to_eye,
            rel_to_eye,
            light: view.light_world,
            light_eye: view.light_eye,
            mode: mode(built.select),
            clipmap: built.clipmap,
            one_map_in_band: built.one_map_in_band,
            frustum: view.frustum_params(),
            maps: &self.records,
            draws: &self.draws,
            offset: built.offset,
            lookup: sizes.render.lookup,
            res,
            width: sizes.width,
            height: sizes.height,
        }
    }
}

/// The clip-depth convention of the case of set-up number `setup` (in its list) and `scheme` in
/// a run that does not ask for one: reversed depth where their indices' sum is even, depth
/// [0, 1] elsewhere, so that every set-up and every scheme is drawn in both conventions at no
/// extra cost.
pub fn case_clip_depth(setup: usize, scheme: Scheme) -> ClipDepth {
    let k = Scheme::ALL.iter().position(|&s| s == scheme).unwrap_or(0);
    if (setup + k).is_multiple_of(2) {
        ClipDepth::Reversed
    } else {
        ClipDepth::ZeroToOne
    }
}

/// Renders and analyses one case.
///
/// # Errors
/// Building, rendering or an empty analysis.
pub fn run_case(
    gpu: &Gpu,
    setup: &str,
    scene: &Scene,
    scheme: Scheme,
    sizes: Sizes,
) -> Result<CaseResult, String> {
    let res = sizes.res.unwrap_or(scene.map_resolution);
    let view = View::new(&scene.camera, scene.light(), sizes.width, sizes.height)?;
    let mesh = Mesh::build(scene);
    let built = build(
        scheme,
        &view,
        scene,
        res,
        sizes.fault,
        sizes.render.clip_depth,
        &Options::default(),
    )?;
    let geometry = crate::geometry::measure(scheme, &view, scene, &built, res);
    let up = Upload::new(&built, &mesh, sizes);
    let out = gpu.render(&up.input(&view, &mesh, &built, res, sizes))?;
    let a = analyse(
        &out,
        &view,
        scene,
        &mesh,
        &built,
        (scheme, sizes.render.lookup),
        res,
        sizes.width,
        sizes.height,
    )
    .map_err(|e| format!("{setup}/{}: {e}", scheme.name()))?;
    let diagnostics = format!(
        "visible {}, not compared {}, band mismatches {:.4}",
        a.measured.visible_pixels,
        a.measured.pixels_not_compared,
        a.measured.band_mismatch_fraction
    );
    Ok(CaseResult {
        summary: CaseSummary {
            setup: setup.into(),
            scheme: scheme.name().into(),
            width: sizes.width,
            height: sizes.height,
            map_resolution: res,
            map_texels: built.maps.len() as u64 * u64::from(res) * u64::from(res),
            measured: a.measured.clone(),
            shimmer_changed_fraction: None,
            shimmer_points: None,
            stable_grid_texels: None,
            clip_depth: if sizes.render.clip_depth == ClipDepth::Reversed {
                "reversed"
            } else {
                "zero_to_one"
            },
            geometry,
            overlay: crate::overlay::check(&out, built.maps.len()),
            paths: None,
        },
        color: out.color,
        overlay: out.overlay,
        analysis: a,
        diagnostics,
    })
}

/// The camera of shimmer frame `i`: translated by `i` sub-texel steps (0.37 of a texel of the
/// first stable cascade, along a fixed horizontal direction) and turned by `i` × 0.05° about the
/// vertical.
pub fn moved(scene: &Scene, i: usize, step: f64) -> Scene {
    let mut s = scene.clone();
    let c = &mut s.camera;
    let d = DVec3::new(1.0, 0.0, -0.6).normalize() * step * i as f64;
    let eye = DVec3::from_array(c.eye) + d;
    let target = DVec3::from_array(c.target) + d;
    let yaw = glam::DQuat::from_rotation_y((0.05 * i as f64).to_radians());
    let f = yaw * (target - eye);
    c.eye = eye.to_array();
    c.target = (eye + f).to_array();
    s
}

/// The shimmer test's camera step ([`moved`]): 0.37 of a texel of the first stable cascade of
/// `view` at `res` texels, 2 R res/(res − 2) / res for the first split's bounding sphere of
/// radius R.
///
/// # Errors
/// The splits or the sphere (the crate's error).
pub fn shimmer_step(view: &View, res: u32) -> Result<f64, String> {
    let sp = crate::schemes::splits(&view.frustum)?;
    let (a, b) = sp.range(0);
    let (_, r) = shadow_aliasing::maps::cascades::bounding_sphere(&view.frustum, a, b)
        .map_err(|e| e.to_string())?;
    Ok(0.37 * 2.0 * r / f64::from(res - 2))
}

/// The shimmer test's result.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Shimmer {
    /// The fraction of (point, consecutive frame pair) whose state changed; NaN where no point
    /// was looked up in both frames of any pair.
    pub changed_fraction: f64,
    /// The shadow-edge points followed: those looked up in both frames of at least one pair.
    pub points: usize,
    /// Stable cascades: the moves of the shadow-edge points (fixed world points) between
    /// consecutive frames in each map, from whole texels, the largest ([`crate::snap`]); NaN
    /// where no map pairs; `None` for the other schemes.
    pub grid_texels: Option<f64>,
}

/// The shimmer test: the fraction of sampled world points on shadow edges whose lit/shadow
/// state, looked up in the rendered maps of each frame (read back, the shader's lookup in f64),
/// changes between consecutive frames. Points are taken from frame 0's visible pixels on
/// surfaces facing the light within 3 pixels of a pixel of the same surface whose exact
/// occlusion differs: shadow boundaries on receivers, which can flip, and no silhouette (a face
/// turned away beside a lit one), which cannot. They are counted in a frame pair only when looked
/// up in both frames (inside the view frustum and in the selected map). A test that can follow
/// no point (every lookup outside its map: the fault `cascade-off-by-one` under the overhead
/// light) reports 0 points and a NaN fraction, which the targets count, not an error that would
/// drop the case's other measurements.
///
/// # Errors
/// Building or rendering; no shadow edge on a receiver in view.
pub fn shimmer(gpu: &Gpu, scene: &Scene, scheme: Scheme, sizes: Sizes) -> Result<Shimmer, String> {
    let res = sizes.res.unwrap_or(scene.map_resolution);
    let mesh = Mesh::build(scene);
    let view0 = View::new(&scene.camera, scene.light(), sizes.width, sizes.height)?;
    let step = shimmer_step(&view0, res)?;
    // Sample points from frame 0.
    let depth_conv = sizes.render.clip_depth;
    let built0 = build(
        scheme,
        &view0,
        scene,
        res,
        sizes.fault,
        depth_conv,
        &Options::default(),
    )?;
    let up0 = Upload::new(&built0, &mesh, sizes);
    let out0 = gpu.render(&up0.input(&view0, &mesh, &built0, res, sizes))?;
    let points = edge_points(&out0, &view0, scene, &mesh, sizes)?;
    let mut prev: Option<Vec<Option<bool>>> = None;
    let mut prev_frame: Option<(View, Built)> = None;
    let mut grid = (scheme == Scheme::StableCascades).then_some(0.0f64);
    let world: Vec<DVec3> = points.iter().map(|&(p, _)| p).collect();
    let (mut changed, mut counted) = (0usize, 0usize);
    let mut followed = vec![false; points.len()];
    for i in 0..sizes.frames {
        let s = moved(scene, i, step);
        let view = View::new(&s.camera, s.light(), sizes.width, sizes.height)?;
        let built = build(
            scheme,
            &view,
            &s,
            res,
            sizes.fault,
            depth_conv,
            &Options::default(),
        )?;
        let up = Upload::new(&built, &mesh, sizes);
        let depth = gpu.render_maps(&up.input(&view, &mesh, &built, res, sizes))?;
        let states: Vec<Option<bool>> = points
            .iter()
            .map(|&(p, n)| lookup(&view, &built, &depth, res, sizes.render, p, n))
            .collect();
        if let Some(prev) = &prev {
            for ((a, b), f) in prev.iter().zip(&states).zip(&mut followed) {
                if let (Some(a), Some(b)) = (a, b) {
                    counted += 1;
                    *f = true;
                    if a != b {
                        changed += 1;
                    }
                }
            }
        }
        prev = Some(states);
        if let Some(g) = &mut grid {
            if let Some((pv, pb)) = &prev_frame {
                let d = crate::snap::grid_offset_texels((pv, pb), (&view, &built), &world);
                *g = if g.is_nan() || d.is_nan() {
                    f64::NAN
                } else {
                    g.max(d)
                };
            }
            prev_frame = Some((view, built));
        }
    }
    Ok(Shimmer {
        grid_texels: grid,
        // 0/0 is NaN: nothing followed is no pass.
        changed_fraction: changed as f64 / counted as f64,
        points: followed.iter().filter(|&&f| f).count(),
    })
}

/// World points (with normals) of frame 0's visible pixels on surfaces facing the light within
/// 3 pixels of a pixel of the same surface whose exact occlusion differs, at most
/// `sizes.shimmer_points`, evenly thinned.
fn edge_points(
    out: &crate::gpu::FrameOutput,
    view: &View,
    scene: &Scene,
    mesh: &Mesh,
    sizes: Sizes,
) -> Result<Vec<(DVec3, DVec3)>, String> {
    let (w, h) = (sizes.width as usize, sizes.height as usize);
    let inv = view.world_to_eye.inverse();
    // Per pixel: (surface id, occluded) on surfaces facing the light.
    let mut state: Vec<Option<(u32, bool)>> = vec![None; w * h];
    let mut pts = vec![None; w * h];
    for y in 0..h {
        for x in 0..w {
            let i = y * w + x;
            if out.id[i] == 0 {
                continue;
            }
            let surf = mesh.surfaces[(out.id[i] - 1) as usize];
            if surf.normal.dot(-view.light_world) <= FACING {
                continue;
            }
            let ne = view.world_to_eye.transform_vector3(surf.normal);
            let p0 = view.world_to_eye.transform_point3(surf.point);
            let Some(p) = pixel_point(view, sizes.width, sizes.height, x, y, ne, p0) else {
                continue;
            };
            let pw = inv.transform_point3(p);
            let occ = crate::scene::ray_occluded(scene, pw, surf.normal, view.light_world);
            state[i] = Some((out.id[i], occ));
            pts[i] = Some((pw, surf.normal));
        }
    }
    let mut out_pts = Vec::new();
    for y in 3..h.saturating_sub(3) {
        for x in 3..w.saturating_sub(3) {
            let i = y * w + x;
            let Some((id, occ)) = state[i] else { continue };
            let edge = (0..7).any(|dy| {
                (0..7).any(|dx| {
                    state[(y + dy - 3) * w + (x + dx - 3)].is_some_and(|o| o.0 == id && o.1 != occ)
                })
            });
            if edge {
                if let Some(p) = pts[i] {
                    out_pts.push(p);
                }
            }
        }
    }
    if out_pts.is_empty() {
        return Err("shimmer: no shadow edge on a receiver in view".into());
    }
    let stride = out_pts.len().div_ceil(sizes.shimmer_points.max(1));
    Ok(out_pts.into_iter().step_by(stride).collect())
}

/// [`run_case`], for the cascade schemes the shimmer test ([`shimmer`]), and in the cases of
/// [`crate::paths::CASES`] the shader paths ([`crate::paths::check`]), with their results in the
/// summary: everything `render-check` measures for one case.
///
/// # Errors
/// As [`run_case`] and [`shimmer`].
pub fn run_full(
    gpu: &Gpu,
    setup: &str,
    scene: &Scene,
    scheme: Scheme,
    sizes: Sizes,
) -> Result<CaseResult, String> {
    let mut r = run_case(gpu, setup, scene, scheme, sizes)?;
    if matches!(scheme, Scheme::Cascades | Scheme::StableCascades) {
        let s = shimmer(gpu, scene, scheme, sizes)
            .map_err(|e| format!("{setup}/{}: {e}", scheme.name()))?;
        r.summary.shimmer_changed_fraction = Some(s.changed_fraction);
        r.summary.shimmer_points = Some(s.points);
        r.summary.stable_grid_texels = s.grid_texels;
    }
    if crate::paths::applies(setup, scheme) {
        let t = std::time::Instant::now();
        let p = crate::paths::check(gpu, scene, scheme, sizes)
            .map_err(|e| format!("{setup}/{}: {e}", scheme.name()))?;
        if std::env::var_os("RENDER_CHECK_DEBUG").is_some() {
            eprintln!(
                "{setup}/{}: shader paths in {:.2} s",
                scheme.name(),
                t.elapsed().as_secs_f64()
            );
        }
        r.summary.paths = Some(p);
    }
    Ok(r)
}

/// The shader's lookup of a world point in the read-back maps (f64: the normal offset of
/// first-surface maps, the clip-depth convention's comparison), or `None` outside the view
/// frustum or every map.
fn lookup(
    view: &View,
    built: &Built,
    depth: &[f32],
    res: u32,
    render: Render,
    pw: DVec3,
    nw: DVec3,
) -> Option<bool> {
    let p = view.world_to_eye.transform_point3(pw);
    if !view.frustum.contains(p, 0.0) {
        return None;
    }
    let z = -p.z;
    let part = match built.select {
        Select::Single => 0,
        Select::Depth => built
            .maps
            .iter()
            .position(|m| z < m.far)
            .unwrap_or(built.maps.len() - 1),
        Select::Faces | Select::Clipmap => return None,
    };
    let map = &built.maps[part];
    let offset = match render.lookup {
        Lookup::SecondDepth => 0.0,
        Lookup::FirstSurface => crate::shadows::first_surface_offset(
            &(map.gpu * view.world_to_eye),
            res,
            pw,
            nw,
            view.light_world,
            f64::from(map.record.normal_offset),
        ),
    };
    let q = view.world_to_eye.transform_point3(pw + nw * offset);
    let h = map.gpu * q.extend(1.0);
    if h.w <= 0.0 {
        return None;
    }
    let (s, t) = ((h.x / h.w + 1.0) * 0.5, (h.y / h.w + 1.0) * 0.5);
    if !(0.0..1.0).contains(&s) || !(0.0..1.0).contains(&t) {
        return None;
    }
    let r = f64::from(res);
    let (ix, iy) = ((s * r).floor() as usize, ((1.0 - t) * r).floor() as usize);
    let stored = f64::from(depth[part * (res * res) as usize + iy * res as usize + ix]);
    // Depth [0, 1] of `map.gpu`; reversed depth is 1 minus it.
    let d = (h.z / h.w).clamp(0.0, 1.0);
    let lit = if render.clip_depth == ClipDepth::Reversed {
        1.0 - d >= stored
    } else {
        d <= stored
    };
    let facing = nw.dot(-view.light_world) > FACING;
    Some(facing && lit)
}
