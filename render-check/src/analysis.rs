//! What is measured on the read-back frame (docs/rendered.md, "What is measured"):
//!
//! 1. the rendered Jacobian (exact derivatives of the texel image, [`crate::perspective`])
//!    against `measure::surface_footprint`;
//! 2. every visible pixel's rendered shadow against the exact ray cast, except within a band of
//!    the true boundary measured in shadow-map texels (docs/rendered.md, "Shadow correctness");
//! 3. coverage: every visible pixel inside the clip volume of the map the shader selected;
//! 4. the rendered perspective error against the frame's reported M_x, M_z, and, in Lloyd 2006's
//!    overhead case, against its Eq 7–10;
//! 5. cascades' cross-fade: in each blend band, the weights the shader applied against the
//!    frame's `blend` at the pixel's exact depth, and the shaded visibility against the weighted
//!    pair of both maps' lookups;
//! 6. the error lens the GPU drew (the crate's `sa_error_lens`) against the pixels one texel step
//!    spans by the rendered Jacobian, and its perspective part against the frame's reported
//!    maximum ([`crate::lens`]);
//! 7. the GPU's texel position of each pixel against the exact point's under the map's matrix in
//!    `f64`;
//! 8. LiSPSM's and TSM's warps fitted from the GPU's texel coordinates ([`crate::warpfit`])
//!    against the papers' n′ and 80 % line ([`crate::papers`]);
//! 9. each pixel's map against the paper's split planes and the requested blend bands
//!    ([`crate::blend`]).

use crate::blend::{band_at, band_maps, blend_agrees, in_band, paper_part};
use crate::gpu::{FrameOutput, Lookup};
use crate::lloyd_level::lloyd_applies;
use crate::paper_error::PaperErrors;
use crate::perspective::{centred, one_sided, perspective_error};
use crate::ratios::{frame_ratios, lens_ratios};
use crate::scene::{ray_occluded, Mesh, Scene, FACING};
use crate::schemes::{Built, Scheme, View};
use crate::shadows::{debug_pixel, shadow_verdict, MapGeom};
use crate::warpfit::{warp_fits, warp_measures};
use glam::{DMat2, DVec2, DVec3};
use serde::Serialize;
use shadow_aliasing::measure::{surface_footprint, Footprint, Grids};

/// Surfaces nearly edge-on to the light (|n·L| below this) are left out of the perspective-error
/// maxima: dividing out their projection factor amplifies the GPU's rounding without bound.
pub const EDGE_ON_LIGHT: f64 = 0.05;

/// A rendered maximum counts as reaching the reported one when the body's worst point is within
/// this many pixel widths of a visible pixel's surface point.
pub(crate) const VISIBLE_PIXELS: f64 = 3.0;

/// A frame's numbers (the fields of summary.json that the analysis measures; docs/rendered.md,
/// "What is measured").
#[derive(Debug, Clone, Serialize)]
pub struct Measured {
    /// Visible pixels (not sky).
    pub visible_pixels: usize,
    /// Pixels whose rendered and predicted Jacobians were compared.
    pub pixels_compared: usize,
    /// Visible pixels not compared: no two same-surface, same-map neighbours along an axis (a
    /// discontinuity; counted, never differenced across), or no prediction.
    pub pixels_not_compared: usize,
    /// Median of ‖J_rendered − J_predicted‖_F / ‖J_predicted‖_F.
    pub median_rel_diff: f64,
    /// 99th percentile of the same.
    pub p99_rel_diff: f64,
    /// Largest rendered error (pixels per texel, 1/σ_min of the rendered J) over compared pixels
    /// facing the light.
    pub max_rendered_error: f64,
    /// Largest predicted error over the same pixels.
    pub max_predicted_error: f64,
    /// Visible pixels facing the light that the exact ray cast shadows.
    pub shadow_pixels: usize,
    /// Of those, the ones compared (outside the texel band of the boundary).
    pub shadow_pixels_checked: usize,
    /// Visible pixels facing the light that the exact ray cast lights.
    pub lit_pixels: usize,
    /// Of those, the ones compared.
    pub lit_pixels_checked: usize,
    /// Compared pixels in exact shadow rendered lit.
    pub shadow_misses: usize,
    /// Compared pixels exactly lit rendered in shadow.
    pub false_shadows: usize,
    /// Mismatching fraction of the pixels facing the light that were not compared (the band).
    pub band_mismatch_fraction: f64,
    /// Visible pixels outside the clip volume (x, y or depth) of the map the shader selected.
    pub uncovered_pixels: usize,
    /// The largest ratio, over maps and over x and z, of the rendered perspective error's maximum
    /// to the frame's reported maximum (M_x, M_z in pixels per texel).
    pub frame_error_ratio: f64,
    /// The smallest such ratio where the body's worst point is visible (`None` where it is not).
    pub frame_error_ratio_worst_visible: Option<f64>,
    /// Lloyd 2006's overhead case: the largest relative difference between the rendered m_x, m_z
    /// of a ground pixel and Eq 7–8 at its depth, and between the rendered maxima and Eq 9–10
    /// (maps whose near end is the camera's near plane). `None` where the case does not apply.
    pub lloyd_rel_diff: Option<f64>,
    /// Visible pixels in a blend band (the frame's `blend` at the pixel's exact view depth, or
    /// the shader's pick cross-fading two maps); `None` for a frame with no band.
    pub blend_pixels: Option<usize>,
    /// Of those, the pixels whose cross-fade is wrong: weights off the frame's by more than
    /// [`BLEND_WEIGHT_TOLERANCE`](crate::blend::BLEND_WEIGHT_TOLERANCE), or a shaded visibility
    /// off the weighted pair of the two maps' lookups by more than
    /// [`BLEND_VALUE_TOLERANCE`](crate::blend::BLEND_VALUE_TOLERANCE); `None` for a frame with no
    /// band.
    pub blend_mismatches: Option<usize>,
    /// Pixels whose GPU lens was compared with the rendered Jacobian's (every pixel with a
    /// rendered Jacobian, on a surface at least [`EDGE_ON_LIGHT`] from edge-on to the light).
    pub lens_pixels_compared: usize,
    /// Median over those pixels of |lens / rendered lens − 1| (the rendered lens: the larger
    /// singular value of the inverse rendered Jacobian, [`crate::lens::pixels_per_texel`]).
    pub lens_median_rel_diff: f64,
    /// 99th percentile of the same.
    pub lens_p99_rel_diff: f64,
    /// The largest GPU lens over the visible pixels on surfaces at least [`EDGE_ON_LIGHT`] from
    /// edge-on to the light (pixels; the projection factor included).
    pub max_lens: f64,
    /// The largest ratio, over maps, of the largest GPU lens with the projection factor 1 over
    /// the map's visible pixels to the map's reported `max_error_pixels` times the map's largest
    /// rendered texel shear (`max_texel_shear`: a sheared texel's extent exceeds both of Lloyd's
    /// widths).
    pub lens_frame_ratio: f64,
    /// The smallest ratio of the same lens to `max_error_pixels` (no shear: the texel's extent is
    /// at least each of Lloyd's widths) over the maps whose worst body vertex is visible (`None`
    /// where no map's is).
    pub lens_frame_ratio_worst_visible: Option<f64>,
    /// The largest texel shear over the maps' compared pixels: the texel's largest extent on Π
    /// (from the GPU's texel coordinates) over the larger of Lloyd's widths there
    /// ([`crate::perspective::texel_shear`]).
    pub max_texel_shear: f64,
    /// The GPU's texel position of each pixel against the exact point's (`f64`) under the map's
    /// matrix, texels: the 99th percentile over the visible pixels in a map.
    pub texel_position_p99: f64,
    /// The largest of the same.
    pub texel_position_max: f64,
    /// LiSPSM's maps (`WarpRule::Lispsm`) and PSM's (`WarpRule::Psm`): the largest relative
    /// difference, over the maps, of w's far/near ratio along the warp axis fitted from the
    /// GPU's texel coordinates ([`crate::warpfit`]) from `1 + Δ/n′` with n′ from the paper
    /// ([`crate::papers`]); `None` for the other schemes.
    pub warp_rel_diff: Option<f64>,
    /// TSM: the fraction of the map, from its top line, up to the focus line, fitted from the
    /// GPU's texel coordinates (Martin & Tan: 0.8); `None` for the other schemes.
    pub tsm_focus_fraction: Option<f64>,
    /// Cascades: visible pixels looked up in another map than the split planes computed from the
    /// paper ([`crate::papers::practical_planes`], with the requested blend bands) name at the
    /// pixel's exact depth (pixels within 10⁻⁴ of a plane left out); `None` for the other
    /// schemes.
    pub split_mismatches: Option<usize>,
    /// The rendered m_x, m_z against the paper's map at each compared pixel
    /// ([`crate::paper_error`]): (99th percentile, largest) of the relative difference; `None`
    /// for a scheme whose maps no paper fixes.
    pub paper_error_rel_diff: Option<(f64, f64)>,
    /// The frame's reported M_x, M_z against Lloyd 2006 §4.4's maxima of the paper's maps:
    /// the largest relative difference over the maps; `None` as above.
    pub paper_frame_rel_diff: Option<f64>,
    /// The minimax map: S̄ at its n′ over the least S̄ of the paper's maps (`None` elsewhere).
    pub minimax_storage_ratio: Option<f64>,
}

/// Per-pixel results (for the heat maps) and the case's numbers.
pub struct Analysis {
    /// The numbers.
    pub measured: Measured,
    /// Rendered error per pixel (NaN where not compared).
    pub rendered_error: Vec<f64>,
    /// Predicted error per pixel (NaN where not compared).
    pub predicted_error: Vec<f64>,
    /// The GPU's lens per pixel (pixels; NaN for the sky, +∞ edge-on to the light, NaN where the
    /// GPU flagged the pixel otherwise).
    pub lens: Vec<f64>,
    /// The GPU's lens with the projection factor 1 per pixel (NaN where it has none).
    pub perspective_lens: Vec<f64>,
}

/// The exact eye-space point seen through pixel `(x, y)` on the plane `(n, p0)` (eye space), or
/// `None` when the ray is parallel to the plane or the point is behind the eye.
pub fn pixel_point(
    view: &View,
    w: u32,
    h: u32,
    x: usize,
    y: usize,
    n: DVec3,
    p0: DVec3,
) -> Option<DVec3> {
    let [_, _, t, ta] = view.frustum_params();
    let xn = 2.0 * (x as f64 + 0.5) / f64::from(w) - 1.0;
    let yn = 1.0 - 2.0 * (y as f64 + 0.5) / f64::from(h);
    let d = DVec3::new(xn * ta, yn * t, -1.0);
    let den = n.dot(d);
    if den.abs() < 1e-12 {
        return None;
    }
    let s = n.dot(p0) / den;
    (s > 0.0).then_some(d * s)
}

/// The exact state of a visible pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Class {
    /// Sky.
    Sky,
    /// Facing the light, not occluded.
    Lit,
    /// Facing the light, occluded (a cast shadow).
    Shadow,
    /// Turned away from the light (or edge-on): dark whatever the map.
    Away,
}

/// What the first pass finds at one pixel.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Pixel {
    pub(crate) class: Class,
    /// Exact eye-space point.
    pub(crate) p: DVec3,
    /// Eye-space unit normal.
    n: DVec3,
    /// The map the shader selected (`usize::MAX` when it named none of the built maps).
    pub(crate) part: usize,
    predicted: Option<Footprint>,
    /// The verdict the lookup must give (in shadow: `true`), where the shadow comparison decides
    /// this pixel (every texel ray it may read gives one exact verdict; in a blend band, both its
    /// maps give the same); `None` in the band left out.
    verdict: Option<bool>,
    /// Whether every map of the pixel's blend band by the frame (`blend::band_maps`) holds its exact
    /// point in its clip volume (true outside a band).
    band_covered: bool,
}

const SKY: Pixel = Pixel {
    class: Class::Sky,
    p: DVec3::ZERO,
    n: DVec3::ZERO,
    part: usize::MAX,
    predicted: None,
    verdict: None,
    band_covered: true,
};

/// The first pass over rows `rows` (exact points, classes, predictions, the texel band).
#[allow(clippy::too_many_arguments)] // the frame's inputs, each needed once
fn first_pass(
    out: &FrameOutput,
    view: &View,
    scene: &Scene,
    mesh: &Mesh,
    built: &Built,
    lookup: Lookup,
    grids: Grids,
    (width, height, res): (u32, u32, u32),
    rows: std::ops::Range<usize>,
) -> Vec<Pixel> {
    let w = width as usize;
    let eye_to_world = view.world_to_eye.inverse();
    let maps: Vec<MapGeom> = built
        .maps
        .iter()
        .map(|m| {
            let wc = m.gpu * view.world_to_eye;
            MapGeom {
                world_to_clip: wc,
                clip_to_world: wc.inverse(),
                normal_offset: match lookup {
                    Lookup::SecondDepth => None,
                    Lookup::FirstSurface => Some(f64::from(m.record.normal_offset)),
                },
            }
        })
        .collect();
    let mut px = Vec::with_capacity(rows.len() * w);
    for y in rows {
        for x in 0..w {
            let i = y * w + x;
            let id = out.id[i];
            if id == 0 {
                px.push(SKY);
                continue;
            }
            let surf = mesh.surfaces[(id - 1) as usize];
            let ne = view.world_to_eye.transform_vector3(surf.normal);
            let pe0 = view.world_to_eye.transform_point3(surf.point);
            let Some(p) = pixel_point(view, width, height, x, y, ne, pe0) else {
                px.push(SKY);
                continue;
            };
            let k = out.texel[i][2];
            let part = if k >= 0.0 && (k as usize) < built.maps.len() {
                k as usize
            } else {
                usize::MAX
            };
            let predicted = built
                .maps
                .get(part)
                .and_then(|m| surface_footprint(&view.proj, &m.built, grids, p, ne).ok());
            let pw = eye_to_world.transform_point3(p);
            let facing = surf.normal.dot(-view.light_world) > FACING;
            // The shader's map, and in a blend band both of the band's maps.
            let mut used = band_maps(built, -p.z);
            let band_covered = used
                .iter()
                .all(|&k| clip_covers(&maps[k], pw, f64::from(res)));
            if !used.contains(&part) {
                used.push(part);
            }
            let (class, verdict) = if facing {
                let occ = ray_occluded(scene, pw, surf.normal, view.light_world);
                let mut verdicts = used.iter().map(|&k| {
                    maps.get(k).and_then(|m| {
                        shadow_verdict(scene, m, f64::from(res), pw, surf.normal, view.light_world)
                    })
                });
                let first = verdicts.next().flatten();
                let verdict = first.filter(|&v| verdicts.all(|x| x == Some(v)));
                (if occ { Class::Shadow } else { Class::Lit }, verdict)
            } else {
                (Class::Away, None)
            };
            px.push(Pixel {
                class,
                p,
                n: ne,
                part,
                predicted,
                verdict,
                band_covered,
            });
        }
    }
    px
}

/// The widest stencil step, pixels: the three samples of a derivative are at most this far
/// apart on each side (centred) or 2 × this on one side.
pub const STENCIL: isize = 4;

/// The rendered Jacobian at pixel `i` from exact three-sample derivatives along the row and the
/// column ([`crate::perspective`]), or `None` when an axis has no two neighbours on the pixel's
/// surface and map.
fn rendered_jacobian(out: &FrameOutput, w: usize, h: usize, i: usize) -> Option<DMat2> {
    let (x, y) = ((i % w) as isize, (i / w) as isize);
    let same = |dx: isize, dy: isize| {
        let (xx, yy) = (x + dx, y + dy);
        if xx < 0 || yy < 0 || xx >= w as isize || yy >= h as isize {
            return None;
        }
        let j = yy as usize * w + xx as usize;
        (out.id[j] == out.id[i] && out.texel[j][2] == out.texel[i][2]).then_some(j)
    };
    let t = |j: usize| DVec2::new(f64::from(out.texel[j][0]), f64::from(out.texel[j][1]));
    // The widest step (up to STENCIL pixels) whose samples lie on the pixel's surface and map:
    // the formulas are exact at any step, and a wider one divides the GPU's f32 rounding by it.
    let axis = |dx: isize, dy: isize| -> Option<DVec2> {
        for k in (1..=STENCIL).rev() {
            if let (Some(m), Some(p)) = (same(-k * dx, -k * dy), same(k * dx, k * dy)) {
                return Some(centred(t(m), t(i), t(p)) / k as f64);
            }
        }
        for k in (1..=STENCIL).rev() {
            if let (Some(p1), Some(p2)) = (same(k * dx, k * dy), same(2 * k * dx, 2 * k * dy)) {
                return Some(one_sided(t(i), t(p1), t(p2), true) / k as f64);
            }
            if let (Some(m1), Some(m2)) = (same(-k * dx, -k * dy), same(-2 * k * dx, -2 * k * dy)) {
                return Some(one_sided(t(i), t(m1), t(m2), false) / k as f64);
            }
        }
        None
    };
    Some(DMat2::from_cols(axis(1, 0)?, axis(0, 1)?))
}

fn rel_diff(a: DMat2, b: DMat2) -> f64 {
    let n = |m: DMat2| (m.x_axis.length_squared() + m.y_axis.length_squared()).sqrt();
    n(a - b) / n(b)
}

fn error_of(j: DMat2) -> f64 {
    Footprint {
        jacobian: j,
        pixel: DVec2::ZERO,
        texel: DVec2::ZERO,
    }
    .error()
    .unwrap_or(f64::INFINITY)
}

fn percentile(sorted: &[f64], q: f64) -> f64 {
    if sorted.is_empty() {
        return f64::NAN;
    }
    let i = ((sorted.len() - 1) as f64 * q).round() as usize;
    sorted[i]
}

/// How far outside the clip volume (texels along s and t; depth) the GPU's `f32` position of a
/// pixel may fall and still count as covered: a receiver on the focus body's boundary (the
/// ground under an overhead light is all at depth 1) lands there within a few `f32` ulps.
pub const COVERAGE_TOLERANCE: (f64, f64) = (1e-3, 1e-6);

/// Whether the world point `pw`'s exact (`f64`) light clip position in `map` lies in its clip
/// volume, to [`COVERAGE_TOLERANCE`]: a blend band's second map, which the shader's texel output
/// does not hold.
fn clip_covers(map: &MapGeom, pw: DVec3, res: f64) -> bool {
    let h = map.world_to_clip * pw.extend(1.0);
    if h.w <= 0.0 {
        return false;
    }
    let (et, ed) = COVERAGE_TOLERANCE;
    let inside = |v: f64, hi: f64, e: f64| (-e..=hi + e).contains(&v);
    inside((h.x / h.w + 1.0) * 0.5 * res, res, et)
        && inside((h.y / h.w + 1.0) * 0.5 * res, res, et)
        && inside(h.z / h.w, 1.0, ed)
}

/// Whether the pixel's light clip position in the map it selected lies in the clip volume: x, y
/// within the map (texel coordinates in [0, res]) and depth in [0, 1], to
/// [`COVERAGE_TOLERANCE`].
fn covered(out: &FrameOutput, i: usize, res: f64) -> bool {
    let [s, t, _, _] = out.texel[i];
    let d = out.depth[i];
    let (et, ed) = COVERAGE_TOLERANCE;
    let inside = |v: f32, hi: f64, e: f64| (-e..=hi + e).contains(&f64::from(v));
    inside(s, res, et) && inside(t, res, et) && inside(d, 1.0, ed)
}

/// Analyses one frame of `scheme`.
///
/// # Errors
/// When nothing could be compared (an empty result is not a success).
#[allow(clippy::too_many_arguments)] // the frame, its inputs and its sizes, each needed once
pub fn analyse(
    out: &FrameOutput,
    view: &View,
    scene: &Scene,
    mesh: &Mesh,
    built: &Built,
    (scheme, lookup): (Scheme, Lookup),
    res: u32,
    width: u32,
    height: u32,
) -> Result<Analysis, String> {
    let (w, h) = (width as usize, height as usize);
    let grids = Grids::new(width, height, res, res).map_err(|e| e.to_string())?;
    // The first pass (a ray cast and its texel band per pixel) in two halves.
    let sizes = (width, height, res);
    let mid = h / 2;
    let px: Vec<Pixel> = std::thread::scope(|sc| {
        let a =
            sc.spawn(|| first_pass(out, view, scene, mesh, built, lookup, grids, sizes, 0..mid));
        let b = first_pass(out, view, scene, mesh, built, lookup, grids, sizes, mid..h);
        let mut a = a.join().expect("first pass");
        a.extend(b);
        a
    });
    let n = w * h;
    let nmaps = built.maps.len();
    let mut rels = Vec::new();
    let mut rendered_error = vec![f64::NAN; n];
    let mut predicted_error = vec![f64::NAN; n];
    let (mut visible, mut not_compared) = (0usize, 0usize);
    let (mut max_r, mut max_p) = (0.0f64, 0.0f64);
    // Per map: the rendered maxima of m_x, m_z.
    let mut rendered_m = vec![(0.0f64, 0.0f64); nmaps];
    // Lloyd's overhead case.
    let lloyd = lloyd_applies(view, built, scheme);
    let mut lloyd_diff = 0.0f64;
    let mut ground_m = vec![(0.0f64, 0.0f64); nmaps];
    let (mut shadow, mut shadow_checked, mut lit, mut lit_checked) = (0, 0, 0, 0);
    let (mut misses, mut falses, mut band, mut band_mis, mut uncovered) = (0, 0, 0, 0, 0);
    let blended = !built.bands.is_empty();
    let (mut blend_px, mut blend_mis) = (0usize, 0usize);
    let mut lens_rels = Vec::new();
    let mut lens = vec![f64::NAN; n];
    let mut perspective_lens = vec![f64::NAN; n];
    let mut max_lens = 0.0f64;
    // Per map: the largest GPU lens with the projection factor 1.
    let mut lens_m = vec![0.0f64; nmaps];
    // Per map: the largest rendered texel shear on Π (`perspective::texel_shear`).
    let mut shear_m = vec![1.0f64; nmaps];
    // Per map: the largest GPU lens (projection factor included; printed with
    // RENDER_CHECK_DEBUG).
    let mut lens_full_m = vec![0.0f64; nmaps];
    let debug = std::env::var_os("RENDER_CHECK_DEBUG").is_some();
    let mut positions = Vec::new();
    let mut fits = warp_fits(view, built, scheme);
    let mut split_mis = 0usize;
    let mut paper = PaperErrors::new(view, built, scheme, height, res);
    for (i, q) in px.iter().enumerate() {
        if q.class == Class::Sky {
            continue;
        }
        visible += 1;
        if let Some(m) = built.maps.get(q.part) {
            let hc = m.gpu * q.p.extend(1.0);
            if hc.w > 0.0 {
                let r = f64::from(res);
                let ds = (hc.x / hc.w + 1.0) * 0.5 * r - f64::from(out.texel[i][0]);
                let dt = (hc.y / hc.w + 1.0) * 0.5 * r - f64::from(out.texel[i][1]);
                positions.push(ds.hypot(dt));
            }
            if let Some(Some(f)) = fits.get_mut(q.part) {
                let r = f64::from(res);
                f.add(
                    q.p,
                    f64::from(out.texel[i][0]) / r,
                    f64::from(out.texel[i][1]) / r,
                );
            }
        }
        if let Some(expected) = paper_part(built, -q.p.z) {
            if expected != q.part {
                split_mis += 1;
                if debug && split_mis < 6 {
                    eprintln!(
                        "  split mismatch ({}, {}) depth {}: map {} where the planes name {expected}",
                        i % w,
                        i / w,
                        -q.p.z,
                        q.part
                    );
                }
            }
        }
        if blended && in_band(out, i, q.part, built, -q.p.z) {
            blend_px += 1;
            if !blend_agrees(out, i, q.part, built, -q.p.z) {
                blend_mis += 1;
                if debug && blend_mis < 6 {
                    eprintln!(
                        "  blend mismatch ({}, {}) depth {}: part {} blend {:?} shaded {} frame's band {:?}",
                        i % w,
                        i / w,
                        -q.p.z,
                        q.part,
                        out.blend[i],
                        out.texel[i][3],
                        band_at(built, -q.p.z)
                    );
                }
            }
        }
        if q.part == usize::MAX || !covered(out, i, f64::from(res)) || !q.band_covered {
            uncovered += 1;
            if debug && uncovered < 6 {
                eprintln!(
                    "  uncovered ({}, {}): texel {:?} depth {} surface {}",
                    i % w,
                    i / w,
                    out.texel[i],
                    out.depth[i],
                    out.id[i] - 1
                );
            }
        }
        // Shadows.
        let rendered_lit = out.texel[i][3] > 0.5;
        match q.class {
            Class::Lit | Class::Shadow => {
                let exact_lit = q.class == Class::Lit;
                if exact_lit {
                    lit += 1;
                } else {
                    shadow += 1;
                }
                if let Some(in_shadow) = q.verdict {
                    // Compared with the verdict of the texel rays it reads (the pixel's own
                    // state where they agree with it, the texel's where the boundary passes
                    // between the pixel and the texel's centre).
                    if exact_lit {
                        lit_checked += 1;
                    } else {
                        shadow_checked += 1;
                    }
                    misses += usize::from(in_shadow && rendered_lit);
                    falses += usize::from(!in_shadow && !rendered_lit);
                    if debug && in_shadow == rendered_lit {
                        eprintln!(
                            "  shadow mismatch at ({}, {}) eye {:?}: surface {} exact_lit {exact_lit} verdict in shadow {in_shadow} part {} texel {:?}",
                            i % w, i / w, q.p, out.id[i] - 1, q.part, out.texel[i]
                        );
                        debug_pixel(scene, view, built, res, q.p, q.n, q.part);
                    }
                } else {
                    band += 1;
                    band_mis += usize::from(exact_lit != rendered_lit);
                }
            }
            _ => {}
        }
        // The lens.
        let jr = rendered_jacobian(out, w, h, i);
        let off_edge = q.n.dot(view.light_eye).abs() >= EDGE_ON_LIGHT;
        lens[i] = match out.lens[i][0] {
            v if v >= 3.0e38 => f64::INFINITY,
            v if v > 0.0 => f64::from(v),
            _ => f64::NAN,
        };
        if off_edge {
            if let Some(v) = crate::lens::gpu_lens(out, i) {
                max_lens = max_lens.max(v);
                if let Some(m) = lens_full_m.get_mut(q.part) {
                    *m = m.max(v);
                }
            }
            if let Some(reference) = jr.and_then(crate::lens::pixels_per_texel) {
                lens_rels.push(crate::lens::rel_diff(out, i, reference));
            }
        }
        if let Some(v) = crate::lens::gpu_perspective_lens(out, i) {
            perspective_lens[i] = v;
            if let Some(m) = lens_m.get_mut(q.part) {
                *m = m.max(v);
            }
        }
        // Jacobians.
        let (Some(fp), Some(jr)) = (q.predicted, jr) else {
            not_compared += 1;
            continue;
        };
        let r = rel_diff(jr, fp.jacobian);
        if !r.is_finite() {
            not_compared += 1;
            continue;
        }
        rels.push(r);
        let (er, ep) = (error_of(jr), error_of(fp.jacobian));
        rendered_error[i] = er;
        predicted_error[i] = ep;
        // The maxima over surfaces the light can reach (a face turned away or edge-on is dark
        // whatever its texels; edge-on, its texels are unbounded).
        if q.class != Class::Away && er.is_finite() && ep.is_finite() {
            max_r = max_r.max(er);
            max_p = max_p.max(ep);
        }
        // The perspective error, projection factor divided out.
        if q.n.dot(view.light_eye).abs() >= EDGE_ON_LIGHT {
            if let Some((mx, mz, sh)) = perspective_error(view, width, height, jr, q.p, q.n) {
                let m = &mut rendered_m[q.part];
                *m = (m.0.max(mx), m.1.max(mz));
                shear_m[q.part] = shear_m[q.part].max(sh);
                paper.add(q.part, q.p, (mx, mz));
                if let (Some(l), 1) = (&lloyd, out.id[i]) {
                    let d = l.pixel_diff(q.part, -q.p.z, mx, mz, width, height, res);
                    if debug && d > 0.005 {
                        eprintln!(
                            "  lloyd ({}, {}) z {} m {mx} {mz} diff {d}",
                            i % w,
                            i / w,
                            -q.p.z
                        );
                    }
                    lloyd_diff = lloyd_diff.max(d);
                    let g = &mut ground_m[q.part];
                    *g = (g.0.max(mx), g.1.max(mz));
                }
            }
        }
    }
    if rels.is_empty() {
        return Err("no pixel could be compared (empty frame?)".into());
    }
    if lens_rels.is_empty() {
        return Err("no pixel's lens could be compared (empty frame?)".into());
    }
    rels.sort_by(f64::total_cmp);
    lens_rels.sort_by(f64::total_cmp);
    positions.sort_by(f64::total_cmp);
    let (warp_diff, tsm_focus) = warp_measures(view, built, scheme, &fits, debug);
    let (ratio, worst) = frame_ratios(&px, view, built, &rendered_m, (width, height, res));
    let (lens_ratio, lens_worst) =
        lens_ratios(&px, view, built, (&lens_m, &shear_m), (width, height));
    if debug {
        for (k, map) in built.maps.iter().enumerate() {
            eprintln!(
                "  map {k}: largest lens {:.6} px, with the projection factor 1 {:.6} px, reported max_error_pixels {:.6}",
                lens_full_m[k], lens_m[k], map.reported.max_error_pixels
            );
        }
    }
    if let Some(l) = &lloyd {
        lloyd_diff = lloyd_diff.max(l.maxima_diff(&ground_m, width, height, res));
    }
    let measured = Measured {
        visible_pixels: visible,
        pixels_compared: rels.len(),
        pixels_not_compared: not_compared,
        median_rel_diff: percentile(&rels, 0.5),
        p99_rel_diff: percentile(&rels, 0.99),
        max_rendered_error: max_r,
        max_predicted_error: max_p,
        shadow_pixels: shadow,
        shadow_pixels_checked: shadow_checked,
        lit_pixels: lit,
        lit_pixels_checked: lit_checked,
        shadow_misses: misses,
        false_shadows: falses,
        band_mismatch_fraction: if band > 0 {
            band_mis as f64 / band as f64
        } else {
            0.0
        },
        uncovered_pixels: uncovered,
        frame_error_ratio: ratio,
        frame_error_ratio_worst_visible: worst,
        lloyd_rel_diff: lloyd.map(|_| lloyd_diff),
        blend_pixels: blended.then_some(blend_px),
        blend_mismatches: blended.then_some(blend_mis),
        lens_pixels_compared: lens_rels.len(),
        lens_median_rel_diff: percentile(&lens_rels, 0.5),
        lens_p99_rel_diff: percentile(&lens_rels, 0.99),
        max_lens,
        lens_frame_ratio: lens_ratio,
        lens_frame_ratio_worst_visible: lens_worst,
        max_texel_shear: shear_m.iter().copied().fold(1.0, f64::max),
        texel_position_p99: percentile(&positions, 0.99),
        texel_position_max: positions.last().copied().unwrap_or(f64::NAN),
        warp_rel_diff: warp_diff,
        tsm_focus_fraction: tsm_focus,
        split_mismatches: (!built.planes.is_empty()).then_some(split_mis),
        paper_error_rel_diff: paper.pixel_diffs(),
        paper_frame_rel_diff: paper.frame_diff(built),
        minimax_storage_ratio: paper.storage_ratio(),
    };
    Ok(Analysis {
        measured,
        rendered_error,
        predicted_error,
        lens,
        perspective_lens,
    })
}
