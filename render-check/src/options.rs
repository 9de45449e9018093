//! The option cases (docs/rendered.md, "What is measured", 17): frame options that no built-in
//! set-up asks for, each built through the crate's frame API for a built-in set-up and held, on
//! the CPU (no rendering), to the independent measurements that apply to it:
//!
//! - **Split rules other than the set-ups' practical λ = 0.75** (`SplitScheme::Uniform`,
//!   `SplitScheme::SelfSimilar`, `Practical { λ = 0.5 }`): render-check places its own planes by
//!   the paper's formula for the same λ ([`crate::papers::practical_planes`]; λ = 0 uniform,
//!   λ = 1 logarithmic), each map's split range against them (`split_rel_diff`) and each map's
//!   body against B rebuilt over them (`body_rel_diff`, [`crate::geometry`]).
//! - **Per-map resolutions** (`FrameInput::map_resolutions`): the texel and bias measurements
//!   of [`crate::geometry`] take each map's resolution from what render-check asked for its slot
//!   ([`crate::schemes::Map::res`]), so a map built at another resolution fails
//!   `texel_world_ratio` and the bias ratios.
//! - **`depth_clamp`**: the map's depth over the rebuilt B must span \[0, 1\] exactly
//!   (`depth_clamp_fill`): the casters are left to the device's clamp.
//! - **`receivers_volume`** is measured in every case, built-in ones included
//!   (`receivers_volume_rel_diff`, [`crate::volumes::volume_distance`]).
//! - **`storage_factor`**: the reported S̄ against M_x M_z of the paper's map (Lloyd 2006 §4.2,
//!   §4.4) over each body, with the reported M_x and M_z (`paper_frame_rel_diff`, as measured in
//!   the rendered cases).

use crate::faults::Fault;
use crate::geometry::Geometry;
use crate::paper_error::PaperErrors;
use crate::schemes::{build, setups, Built, Scheme, View};
use serde::Serialize;
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::maps::ClipDepth;

/// Frame options beyond the set-ups' defaults, each exercised by an option case
/// (docs/rendered.md, "What is measured", 17).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Options {
    /// The cascades' split λ (`None`: [`crate::schemes::CASCADE_LAMBDA`]): 0 asks the crate for
    /// `SplitScheme::Uniform`, 1 for `SplitScheme::SelfSimilar`, else `Practical { lambda }`;
    /// render-check places its own planes with the paper's formula for the same λ.
    pub lambda: Option<f64>,
    /// Each slot's texels per side (`FrameInput::map_resolutions`); `None`: every map at the
    /// case's resolution.
    pub resolutions: Option<Vec<u32>>,
    /// `FrameInput::depth_clamp`: the map's depth covers B alone.
    pub depth_clamp: bool,
    /// The camera's far plane moved here (`None`: the set-up's): far beyond the receivers, so
    /// that B's depth range `[n_B, f_B]` ends well before the slice's far plane and the papers'
    /// n′ ([`crate::paper_error::paper_n_prime`], at B's own n_B, f_B) differ from the n′ of
    /// the slice's planes.
    pub far: Option<f64>,
    /// The image (width, height) of the case (`None`: the run's): a small image makes the
    /// clipmap's level follow its LOD rule, not the coverage bound
    /// ([`crate::geometry::clipmap_offset`]).
    pub screen: Option<(u32, u32)>,
}

impl Options {
    /// The split λ asked for.
    pub fn lambda(&self) -> f64 {
        self.lambda.unwrap_or(crate::schemes::CASCADE_LAMBDA)
    }

    /// The crate's split scheme for [`Options::lambda`].
    pub(crate) fn split(&self) -> SplitScheme {
        match self.lambda() {
            0.0 => SplitScheme::Uniform,
            1.0 => SplitScheme::SelfSimilar,
            lambda => SplitScheme::Practical { lambda },
        }
    }
}

/// One option case: a built-in set-up and scheme with frame options beyond the defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct OptionCase {
    /// The case's name (what it exercises).
    pub name: &'static str,
    /// The built-in set-up.
    pub setup: &'static str,
    /// The scheme.
    pub scheme: Scheme,
    /// The options.
    pub options: Options,
}

/// The far plane of the `receivers_inside_*` cases: the built-in scene's receivers (its ground
/// drawn 260 units about the camera) end well before it.
pub const RECEIVERS_INSIDE_FAR: f64 = 1000.0;

/// The image of the `clipmap_lod_bound` case (80 × 60): at 1024² texels the clipmap's LOD rule,
/// not the coverage bound, sets its level offset ([`crate::geometry::clipmap_offset`]).
pub const LOD_SCREEN: (u32, u32) = (80, 60);

/// Every option case the plain run measures.
pub fn cases() -> Vec<OptionCase> {
    let case = |name, setup, scheme, options| OptionCase {
        name,
        setup,
        scheme,
        options,
    };
    let lambda = |l: f64| Options {
        lambda: Some(l),
        ..Options::default()
    };
    let resolutions = |r: &[u32]| Options {
        resolutions: Some(r.to_vec()),
        ..Options::default()
    };
    let clamp = Options {
        depth_clamp: true,
        ..Options::default()
    };
    let far = Options {
        far: Some(RECEIVERS_INSIDE_FAR),
        ..Options::default()
    };
    let small = Options {
        screen: Some(LOD_SCREEN),
        ..Options::default()
    };
    vec![
        case("splits_uniform", "tilted_45", Scheme::Cascades, lambda(0.0)),
        case(
            "splits_logarithmic",
            "grazing_10",
            Scheme::Cascades,
            lambda(1.0),
        ),
        case(
            "splits_practical_0.5",
            "front_5",
            Scheme::BlendedCascades,
            lambda(0.5),
        ),
        case(
            "splits_logarithmic_stable",
            "overhead",
            Scheme::StableCascades,
            lambda(1.0),
        ),
        case(
            "resolutions_cascades",
            "tilted_45",
            Scheme::Cascades,
            resolutions(&[2048, 1024, 512, 256]),
        ),
        case(
            "resolutions_stable",
            "behind_5",
            Scheme::StableCascades,
            resolutions(&[256, 512, 1024, 2048]),
        ),
        case(
            "resolutions_single",
            "grazing_10",
            Scheme::Lispsm,
            resolutions(&[512]),
        ),
        case(
            "depth_clamp_lispsm",
            "tilted_45",
            Scheme::Lispsm,
            clamp.clone(),
        ),
        case(
            "depth_clamp_uniform",
            "behind_5",
            Scheme::Uniform,
            clamp.clone(),
        ),
        case(
            "depth_clamp_tsm",
            "thin_casters",
            Scheme::Tsm,
            clamp.clone(),
        ),
        case(
            "depth_clamp_cascades",
            "front_5",
            Scheme::Cascades,
            clamp.clone(),
        ),
        case(
            "depth_clamp_faces",
            "tilted_45",
            Scheme::Faces,
            clamp.clone(),
        ),
        case("depth_clamp_clipmap", "parallel_1", Scheme::Clipmap, clamp),
        case(
            "receivers_inside_lispsm",
            "tilted_45",
            Scheme::Lispsm,
            far.clone(),
        ),
        case(
            "receivers_inside_cascades",
            "behind_5",
            Scheme::Cascades,
            far,
        ),
        case("clipmap_lod_bound", "overhead", Scheme::Clipmap, small),
    ]
}

/// What the plain run reports for one option case (summary.json's `options`).
#[derive(Debug, Clone, Serialize)]
pub struct OptionSummary {
    /// [`OptionCase::name`].
    pub name: String,
    /// The set-up.
    pub setup: String,
    /// The scheme's name.
    pub scheme: String,
    /// The geometry measurements ([`crate::geometry`]), each map at its own resolution.
    #[serde(flatten)]
    pub geometry: Geometry,
    /// The reported M_x, M_z and S̄ against the paper's map over each body, the largest relative
    /// difference; `None` for a scheme no paper fixes.
    pub paper_frame_rel_diff: Option<f64>,
}

/// Builds and measures `case` at `width × height` (depth \[0, 1\]) with `fault` injected.
///
/// # Errors
/// An unknown set-up, or the crate's error.
pub fn measure(
    case: &OptionCase,
    width: u32,
    height: u32,
    fault: Option<Fault>,
) -> Result<OptionSummary, String> {
    let s = setups()
        .into_iter()
        .find(|s| s.name == case.setup)
        .ok_or_else(|| format!("option case {}: no set-up {}", case.name, case.setup))?;
    let mut scene = s.scene;
    if let Some(far) = case.options.far {
        scene.camera.far = far;
    }
    let (width, height) = case.options.screen.unwrap_or((width, height));
    let view = View::new(&scene.camera, scene.light(), width, height)?;
    let res = scene.map_resolution;
    let built = build(
        case.scheme,
        &view,
        &scene,
        res,
        fault,
        ClipDepth::ZeroToOne,
        &case.options,
    )
    .map_err(|e| format!("option case {}: {e}", case.name))?;
    Ok(summarise(case, &view, &scene, &built, height, res))
}

/// The measurements of `built` (the case's frame, perhaps edited as a faulty crate would make
/// it) for `case`.
pub fn summarise(
    case: &OptionCase,
    view: &View,
    scene: &crate::scene::Scene,
    built: &Built,
    height: u32,
    res: u32,
) -> OptionSummary {
    let geometry = crate::geometry::measure(case.scheme, view, scene, built, res);
    let paper = PaperErrors::new(view, built, case.scheme, height, res);
    OptionSummary {
        name: case.name.to_string(),
        setup: case.setup.to_string(),
        scheme: case.scheme.name().to_string(),
        geometry,
        paper_frame_rel_diff: paper.frame_diff(built),
    }
}

/// Each map's split range `[near, far)` against render-check's planes `z_i, z_{i+1}` (the
/// window whose start lies nearest the map's near end, in ln z: a slice with no receiver builds
/// no map), the largest relative difference; `None` where the scheme has no planes. More maps
/// than windows, or a range that is not a number, reads 1.
pub fn split_rel_diff(built: &Built) -> Option<f64> {
    if built.planes.is_empty() {
        return None;
    }
    if built.maps.len() + 1 > built.planes.len() {
        return Some(1.0);
    }
    let d = built
        .maps
        .iter()
        .map(|m| {
            built
                .planes
                .windows(2)
                .min_by(|x, y| {
                    let off = |w: &[f64]| (m.near / w[0]).ln().abs();
                    off(x).total_cmp(&off(y))
                })
                .map_or(1.0, |w| {
                    (m.near / w[0] - 1.0).abs().max((m.far / w[1] - 1.0).abs())
                })
        })
        .fold(0.0f64, |a, x| if x.is_nan() { 1.0 } else { a.max(x) });
    Some(d)
}

/// The targets `o` violates: the geometry targets (the split planes among them) and the paper's
/// figures.
pub fn violations(o: &OptionSummary) -> Vec<String> {
    let mut v = crate::targets::geometry_violations(&o.geometry);
    let mut at_most = |name: &str, got: Option<f64>, limit: f64| {
        if let Some(x) = got {
            if x.is_nan() || x > limit {
                v.push(format!("{name} = {x:.4e}, limit ≤ {limit:e}"));
            }
        }
    };
    at_most(
        "paper_frame_rel_diff (reported M_x, M_z against the paper's map's §4.4 maxima)",
        o.paper_frame_rel_diff,
        crate::targets::PAPER_FRAME_REL_DIFF,
    );
    v
}
