//! Shadow-matrix builders and the measurement of any 4×4 matrix (the hemisphere sweep: `sweep`).
//!
//! Matrices cross the boundary as NumPy (row-major) 4×4 float64 arrays `M` with
//! `clip = M @ (x, y, z, 1)`: eye space (right-handed, looking down −Z, Y up) → light clip space.

use crate::args;
use crate::broadcast::{buffer, fmt_shape, to_python, value_error, values_of, FloatArg};
use crate::closed::choice;
use glam::{DMat4, DVec3};
use numpy::PyUntypedArrayMethods;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyList;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::maps::cascades::cascades as build_cascades;
use shadow_aliasing::maps::faces::{face_partitions, FaceWarp};
use shadow_aliasing::maps::{
    self, ClipDepth, Falloff, ShadowMatrix, TsmOptions, TsmSearch, WarpRule,
};
use shadow_aliasing::measure::{
    frustum_max as measure_frustum_max, point_error as measure_point_error, ShadowMap,
};
use shadow_aliasing::scheme::ADAPTIVE_RATIO;
use shadow_aliasing::{Error, LightAngle, Resolutions, ViewFrustum};

type Any<'py> = Bound<'py, PyAny>;

/// The warp rules by name, as the command line spells them (`--warp`).
pub const WARP_RULES: &[&str] = &[
    "uniform",
    "eta",
    "psm",
    "lispsm",
    "lispsm-fixed",
    "barroso",
    "barroso-zhang",
    "minimax",
    "minimax-mz",
    "tsm",
    "lispsm-reference",
    "filament",
    "ogre",
    "ogre-ortho",
];

pub fn err(e: Error) -> PyErr {
    value_error(&e)
}

pub fn view_of(near: f64, far: f64, half_fov: f64, aspect: f64) -> PyResult<ViewFrustum> {
    ViewFrustum::with_aspect(near, far, half_fov, aspect).map_err(err)
}

/// A 3-vector from any sequence or array of three real numbers.
pub(crate) fn vec3<'py>(name: &str, ob: &Any<'py>) -> PyResult<DVec3> {
    let v = values(name, ob, &[3])?;
    Ok(DVec3::new(v[0], v[1], v[2]))
}

/// The values of an array argument of exactly `shape`, C order.
pub(crate) fn values<'py>(name: &str, ob: &Any<'py>, shape: &[usize]) -> PyResult<Vec<f64>> {
    match FloatArg::extract(name, ob)? {
        FloatArg::Number(_) => Err(PyValueError::new_err(format!(
            "{name} must be an array of shape {} (got a number)",
            fmt_shape(shape)
        ))),
        FloatArg::Array(a) => {
            if a.shape() != shape {
                return Err(PyValueError::new_err(format!(
                    "{name} must be an array of shape {} (got shape {})",
                    fmt_shape(shape),
                    fmt_shape(a.shape())
                )));
            }
            values_of(&a)
        }
    }
}

/// Row-major 16 values → glam's column-major matrix.
pub(crate) fn from_rows(v: &[f64]) -> DMat4 {
    DMat4::from_cols_array(&std::array::from_fn(|k| v[(k % 4) * 4 + k / 4]))
}

/// glam's matrix → row-major 16 values.
pub(crate) fn to_rows(m: &DMat4) -> [f64; 16] {
    let c = m.to_cols_array();
    std::array::from_fn(|k| c[(k % 4) * 4 + k / 4])
}

pub(crate) fn clip_depth(name: &str) -> PyResult<ClipDepth> {
    Ok(
        match choice(
            "clip_depth",
            name,
            &["neg_one_to_one", "zero_to_one", "reversed"],
        )? {
            "neg_one_to_one" => ClipDepth::NegOneToOne,
            "zero_to_one" => ClipDepth::ZeroToOne,
            _ => ClipDepth::Reversed,
        },
    )
}

/// Several matrices as an (m, 4, 4) array.
pub(crate) fn stack<'py>(py: Python<'py>, ms: &[DMat4]) -> PyResult<Any<'py>> {
    let mut v = Vec::with_capacity(16 * ms.len());
    for m in ms {
        v.extend_from_slice(&to_rows(m));
    }
    to_python(py, vec![ms.len(), 4, 4], v)
}

fn one_matrix<'py>(py: Python<'py>, m: &DMat4) -> PyResult<Any<'py>> {
    to_python(py, vec![4, 4], to_rows(m).to_vec())
}

/// `light_dir` of the builders: one direction (3,) → `None`, or a stack (..., 3) → its leading
/// shape; with the values, C order.
fn light_dirs(ob: &Any<'_>) -> PyResult<(Option<Vec<usize>>, Vec<f64>)> {
    let (shape, v) = shape_of("light_dir", ob)?;
    match shape.split_last() {
        Some((3, [])) => Ok((None, v)),
        Some((3, lead)) => Ok((Some(lead.to_vec()), v)),
        _ => Err(PyValueError::new_err(format!(
            "light_dir must have shape (3,) or (..., 3) (got {})",
            fmt_shape(&shape)
        ))),
    }
}

/// `f` at each light direction of `dirs` (C order, 3 values each), `width` values per direction,
/// without the GIL and over all cores; the first direction (in C order) that fails raises its
/// error with its index in `lead`.
fn per_light<F>(
    py: Python<'_>,
    lead: &[usize],
    dirs: &[f64],
    width: usize,
    f: F,
) -> PyResult<Vec<f64>>
where
    F: Fn(DVec3, &mut [f64]) -> Result<(), Error> + Sync,
{
    use rayon::prelude::*;
    let n = dirs.len() / 3;
    let shape = [lead, &[width]].concat();
    let mut out = buffer(n * width, &shape)?;
    out.resize(n * width, 0.0);
    let failed: Option<(usize, Error)> = py.detach(|| {
        out.par_chunks_mut(width * 256)
            .zip(dirs.par_chunks(3 * 256))
            .enumerate()
            .find_map_first(|(block, (o, d))| {
                for (j, (oo, dd)) in o.chunks_exact_mut(width).zip(d.chunks_exact(3)).enumerate() {
                    if let Err(e) = f(DVec3::new(dd[0], dd[1], dd[2]), oo) {
                        return Some((block * 256 + j, e));
                    }
                }
                None
            })
    });
    match failed {
        Some((i, e)) => Err(PyValueError::new_err(format!(
            "{e} (light_dir at index {})",
            crate::broadcast::fmt_index(i, lead)
        ))),
        None => Ok(out),
    }
}

/// The parameters of the named rules, as keyword arguments.
#[derive(Clone, Copy, Default)]
pub struct RuleParams {
    pub eta: Option<f64>,
    pub focus: Option<f64>,
    pub near_hint: Option<f64>,
    pub far_hint: Option<f64>,
    pub shadow_distance: Option<f64>,
}

/// The library's rule for a name, checking that every parameter given is one the rule uses
/// (the command line's checks and defaults).
pub fn rule(view: &ViewFrustum, name: &str, p: RuleParams) -> PyResult<WarpRule> {
    let spelled = name.replace('_', "-");
    let spelled = if spelled == "lispsm-sin" {
        "lispsm".to_string()
    } else {
        spelled
    };
    let name = choice("rule", &spelled, WARP_RULES)?;
    let only = |given: bool, arg: &str, owner: &str| -> PyResult<()> {
        if given && name != owner {
            Err(PyValueError::new_err(format!(
                "{arg} is only used by rule \"{owner}\""
            )))
        } else {
            Ok(())
        }
    };
    only(p.eta.is_some(), "eta", "eta")?;
    only(p.focus.is_some(), "focus", "tsm")?;
    only(p.near_hint.is_some(), "near_hint", "filament")?;
    only(p.far_hint.is_some(), "far_hint", "filament")?;
    only(p.shadow_distance.is_some(), "shadow_distance", "ogre-ortho")?;
    Ok(match name {
        "uniform" => WarpRule::Uniform,
        "eta" => WarpRule::Eta(p.eta.ok_or_else(|| {
            PyValueError::new_err("eta is missing: rule \"eta\" needs eta in [-1, 1]")
        })?),
        "psm" => WarpRule::Psm,
        "lispsm" => WarpRule::Lispsm,
        "lispsm-fixed" => WarpRule::LispsmFixed,
        "barroso" => WarpRule::Barroso(Falloff::Barroso),
        "barroso-zhang" => WarpRule::Barroso(Falloff::Zhang),
        "minimax" => WarpRule::Minimax,
        "minimax-mz" => WarpRule::MinimaxMz,
        "tsm" => WarpRule::Tsm {
            focus: p.focus.unwrap_or(0.5 * (view.far() - view.near())),
        },
        "lispsm-reference" => WarpRule::LispsmReference,
        "filament" => match (p.near_hint, p.far_hint) {
            (Some(near_hint), Some(far_hint)) => WarpRule::FilamentHints {
                near_hint,
                far_hint,
            },
            (None, None) => WarpRule::Filament,
            _ => {
                return Err(PyValueError::new_err(
                    "near_hint and far_hint are given together (rule \"filament\")",
                ))
            }
        },
        "ogre" => WarpRule::Ogre,
        _ => WarpRule::OgreOrtho {
            shadow_distance: p.shadow_distance.unwrap_or(300.0 * view.near()),
        },
    })
}

/// One shadow map fitted to the whole view frustum, its n′ chosen by `rule` (a name as the
/// command line's ``--warp`` spells it: "uniform", "eta" (with ``eta``), "psm", "lispsm"
/// (n′ = (n + √(f n))/sin γ, Wimmer et al. 2004, Lloyd 2006 §4.1), "lispsm-fixed", "barroso",
/// "barroso-zhang" (Barroso Eq 13–18), "minimax" (the default: least S̄ = M_x M_z), "minimax-mz",
/// "tsm" (Martin–Tan's 80 % rule, ``focus`` default (f − n)/2), "lispsm-reference", "filament"
/// (optionally ``near_hint``, ``far_hint``), "ogre", "ogre-ortho" (``shadow_distance``, default
/// 300 near)). The warp is Lloyd 2006 §4's perspective along the light-space axis (Fig 3).
///
/// light_dir: the direction light travels, eye space. Returns the 4×4 float64 matrix eye → light
/// clip space (``clip_depth`` "neg_one_to_one", OpenGL, "zero_to_one", Vulkan/D3D, or "reversed",
/// 1 nearest the light and 0 farthest, Bevy's cascades).
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, rule="minimax", *, eta=None, focus=None,
    near_hint=None, far_hint=None, shadow_distance=None, clip_depth="neg_one_to_one", aspect=1.0))]
#[allow(clippy::too_many_arguments)]
pub fn warp<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::rule)] rule: &str,
    #[pyo3(from_py_with = args::eta)] eta: Option<f64>,
    #[pyo3(from_py_with = args::focus)] focus: Option<f64>,
    #[pyo3(from_py_with = args::near_hint)] near_hint: Option<f64>,
    #[pyo3(from_py_with = args::far_hint)] far_hint: Option<f64>,
    #[pyo3(from_py_with = args::shadow_distance)] shadow_distance: Option<f64>,
    #[pyo3(from_py_with = args::clip_depth)] clip_depth: &str,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
) -> PyResult<Any<'py>> {
    let view = view_of(near, far, half_fov, aspect)?;
    let (lead, dirs) = light_dirs(light_dir)?;
    let r = self::rule(
        &view,
        rule,
        RuleParams {
            eta,
            focus,
            near_hint,
            far_hint,
            shadow_distance,
        },
    )?;
    let depth = self::clip_depth(clip_depth)?;
    match lead {
        None => {
            let l = DVec3::new(dirs[0], dirs[1], dirs[2]);
            let s: ShadowMatrix = py.detach(|| maps::warp(&view, l, r)).map_err(err)?;
            one_matrix(py, &s.with_clip_depth(depth))
        }
        Some(lead) => {
            let out = per_light(py, &lead, &dirs, 16, |l, o| {
                let s = maps::warp(&view, l, r)?;
                o.copy_from_slice(&to_rows(&s.with_clip_depth(depth)));
                Ok(())
            })?;
            to_python(py, [&lead[..], &[4, 4]].concat(), out)
        }
    }
}

/// The n′ the rule chooses for this camera and light (``inf`` for an unwarped map); the same
/// rules and keywords as :func:`warp`.
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, rule="minimax", *, eta=None, focus=None,
    near_hint=None, far_hint=None, shadow_distance=None, aspect=1.0))]
#[allow(clippy::too_many_arguments)]
pub fn n_prime_for<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::rule)] rule: &str,
    #[pyo3(from_py_with = args::eta)] eta: Option<f64>,
    #[pyo3(from_py_with = args::focus)] focus: Option<f64>,
    #[pyo3(from_py_with = args::near_hint)] near_hint: Option<f64>,
    #[pyo3(from_py_with = args::far_hint)] far_hint: Option<f64>,
    #[pyo3(from_py_with = args::shadow_distance)] shadow_distance: Option<f64>,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
) -> PyResult<Any<'py>> {
    let view = view_of(near, far, half_fov, aspect)?;
    let (lead, dirs) = light_dirs(light_dir)?;
    let r = self::rule(
        &view,
        rule,
        RuleParams {
            eta,
            focus,
            near_hint,
            far_hint,
            shadow_distance,
        },
    )?;
    match lead {
        None => {
            let l = DVec3::new(dirs[0], dirs[1], dirs[2]);
            to_python(
                py,
                vec![],
                vec![maps::n_prime_for(&view, l, r).map_err(err)?.value()],
            )
        }
        Some(lead) => {
            let out = per_light(py, &lead, &dirs, 1, |l, o| {
                o[0] = maps::n_prime_for(&view, l, r)?.value();
                Ok(())
            })?;
            to_python(py, lead, out)
        }
    }
}

pub(crate) fn split_scheme(
    name: &str,
    lambda_: Option<f64>,
    light_dir: DVec3,
) -> PyResult<SplitScheme> {
    let name = choice(
        "partition",
        name,
        &["self_similar", "log", "uniform", "practical", "adaptive"],
    )?;
    if lambda_.is_some() && name != "practical" {
        return Err(PyValueError::new_err(format!(
            "lambda_ is not an argument of partition \"{name}\" (only of partition \"practical\")"
        )));
    }
    Ok(match name {
        "self_similar" | "log" => SplitScheme::SelfSimilar,
        "uniform" => SplitScheme::Uniform,
        "practical" => SplitScheme::Practical {
            lambda: lambda_.ok_or_else(|| {
                PyValueError::new_err("lambda_ is missing (partition \"practical\" needs it)")
            })?,
        },
        _ => SplitScheme::Adaptive {
            light_angle: LightAngle::from_light_dir(light_dir)
                .map_err(err)?
                .radians(),
            ratio: ADAPTIVE_RATIO,
        },
    })
}

/// k z-partitions (cascades) of the view frustum, each with its own map fitted by `rule`
/// (as in :func:`warp`). The split planes: ``partition`` "self_similar" (alias "log";
/// z_i = n (f/n)^{i/k}, Lloyd 2006 Eq 15, 16), "uniform", "practical" (``lambda_`` ∈ [0, 1])
/// or "adaptive" (Barroso Eq 19, γ from the light, α = 2). ``overlap`` ∈ [0, 1) widens each
/// partition's far end by that fraction of its depth. Returns a (k, 4, 4) float64 array, near to
/// far; :func:`z_partition` gives the planes.
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, k, partition="self_similar", rule="minimax",
    *, lambda_=None, overlap=0.0, eta=None, focus=None, clip_depth="neg_one_to_one", aspect=1.0))]
#[allow(clippy::too_many_arguments)]
pub fn cascades<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::k)] k: usize,
    #[pyo3(from_py_with = args::partition)] partition: &str,
    #[pyo3(from_py_with = args::rule)] rule: &str,
    #[pyo3(from_py_with = args::lambda_)] lambda_: Option<f64>,
    #[pyo3(from_py_with = args::overlap)] overlap: f64,
    #[pyo3(from_py_with = args::eta)] eta: Option<f64>,
    #[pyo3(from_py_with = args::focus)] focus: Option<f64>,
    #[pyo3(from_py_with = args::clip_depth)] clip_depth: &str,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
) -> PyResult<Any<'py>> {
    let view = view_of(near, far, half_fov, aspect)?;
    let l = vec3("light_dir", light_dir)?;
    let r = self::rule(
        &view,
        rule,
        RuleParams {
            eta,
            focus,
            ..RuleParams::default()
        },
    )?;
    let s = split_scheme(partition, lambda_, l)?;
    let depth = self::clip_depth(clip_depth)?;
    let splits = z_splits(near, far, k, s).map_err(err)?;
    let c = build_cascades(&view, l, &splits, r, overlap).map_err(err)?;
    let ms: Vec<DMat4> = c.iter().map(|p| p.shadow.with_clip_depth(depth)).collect();
    stack(py, &ms)
}

/// Face partitions (Lloyd 2006 §5.1): one map per visible face of the view frustum, each side
/// face z-partitioned k times (self-similar planes), warped by ``warp`` "uniform", "psm" or
/// "lispsm" (n′ = d_n + √(d_n d_f) of its face, which reproduces Lloyd 2006 Eq 19, 21).
/// Returns ``(matrices, faces)``: an (m, 4, 4) float64 array and the face of each ("bottom",
/// "right", "top", "left", "near").
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, k=1, warp="lispsm", *,
    clip_depth="neg_one_to_one", aspect=1.0))]
#[allow(clippy::too_many_arguments)]
pub fn faces<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::k)] k: usize,
    #[pyo3(from_py_with = args::warp)] warp: &str,
    #[pyo3(from_py_with = args::clip_depth)] clip_depth: &str,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
) -> PyResult<(Any<'py>, Bound<'py, PyList>)> {
    let view = view_of(near, far, half_fov, aspect)?;
    let l = vec3("light_dir", light_dir)?;
    let w = match choice("warp", warp, &["uniform", "psm", "lispsm"])? {
        "uniform" => FaceWarp::Uniform,
        "psm" => FaceWarp::Psm,
        _ => FaceWarp::Lispsm,
    };
    let depth = self::clip_depth(clip_depth)?;
    let fp = face_partitions(&view, l, w, k).map_err(err)?;
    let ms: Vec<DMat4> = fp.iter().map(|p| p.shadow.with_clip_depth(depth)).collect();
    let names: Vec<&str> = fp.iter().map(|p| p.face.name()).collect();
    Ok((stack(py, &ms)?, PyList::new(py, names)?))
}

/// The trapezoidal shadow map (Martin & Tan 2004): the focus point ``focus`` beyond the near
/// plane on the view axis (default (f − n)/2) is mapped to the 80 % line ξ = −0.6 (§6.2), or to
/// the line ``xi`` ∈ (−1, 1), or, with ``iterative`` = the map's texel lines along t, the line of
/// largest focus area (§6.2's iterative variant, searched fast as the crate's
/// ``TsmSearch::Iterative``: 33 sampled lines refined, which can miss a peak narrower than the
/// sampling step). Returns the 4×4 float64 matrix eye → light clip space.
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, focus=None, *, xi=None, iterative=None,
    clip_depth="neg_one_to_one", aspect=1.0))]
#[allow(clippy::too_many_arguments)]
pub fn tsm<'py>(
    py: Python<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::focus)] focus: Option<f64>,
    #[pyo3(from_py_with = args::xi)] xi: Option<f64>,
    #[pyo3(from_py_with = args::iterative)] iterative: Option<u32>,
    #[pyo3(from_py_with = args::clip_depth)] clip_depth: &str,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
) -> PyResult<Any<'py>> {
    let view = view_of(near, far, half_fov, aspect)?;
    let l = vec3("light_dir", light_dir)?;
    let search = tsm_search(xi, iterative)?;
    let opts = TsmOptions {
        focus: focus.unwrap_or(0.5 * (far - near)),
        search,
    };
    let depth = self::clip_depth(clip_depth)?;
    let m = maps::tsm(&view, l, opts).map_err(|e| match e {
        // The crate's name for what Python calls `iterative`.
        Error::InvalidArgument {
            name: "map_lines",
            reason,
        } => PyValueError::new_err(format!("iterative {reason}")),
        e => err(e),
    })?;
    one_matrix(py, &m.shadow.with_clip_depth(depth))
}

/// TSM's line rule from `xi` and `iterative` (alternatives; neither: the 80 % rule).
pub(crate) fn tsm_search(xi: Option<f64>, iterative: Option<u32>) -> PyResult<TsmSearch> {
    match (xi, iterative) {
        (None, None) => Ok(TsmSearch::EightyPercent),
        (Some(x), None) => Ok(TsmSearch::Line(x)),
        (None, Some(map_lines)) => Ok(TsmSearch::Iterative { map_lines }),
        _ => Err(PyValueError::new_err(
            "xi and iterative are alternatives: give at most one",
        )),
    }
}

/// The shape of `ob` if it is an array-like.
fn shape_of(name: &str, ob: &Any<'_>) -> PyResult<(Vec<usize>, Vec<f64>)> {
    match FloatArg::extract(name, ob)? {
        FloatArg::Number(_) => Err(PyValueError::new_err(format!(
            "{name} must be an array (got a number)"
        ))),
        FloatArg::Array(a) => Ok((a.shape().to_vec(), values_of(&a)?)),
    }
}

/// M_x, M_z and S̄ = M_x M_z of any shadow matrix over the view frustum, measured from the
/// exact derivatives of the projective map at the frustum's eight vertices (Lloyd 2006 §4.4):
///
///     m_x = w_ls / w_i,  m_z = w_lt / w_i,  w_i = 2 z tan θ / res_image  (unit resolutions)
///
/// matrix: (..., 4, 4) (row-major, clip = M @ (x, y, z, 1)); light_dir: (3,) or (..., 3), the
/// direction light travels. Returns (..., 3) float64: ``[M_x, M_z, S̄]`` for each matrix.
#[pyfunction]
#[pyo3(signature = (matrix, light_dir, near, far, half_fov, *, aspect=1.0))]
pub fn frustum_max<'py>(
    py: Python<'py>,
    matrix: &Any<'py>,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
) -> PyResult<Any<'py>> {
    let view = view_of(near, far, half_fov, aspect)?;
    let (ms, mv) = shape_of("matrix", matrix)?;
    if ms.len() < 2 || ms[ms.len() - 2..] != [4, 4] {
        return Err(PyValueError::new_err(format!(
            "matrix must have shape (4, 4) or (..., 4, 4) (got {})",
            fmt_shape(&ms)
        )));
    }
    let lead = &ms[..ms.len() - 2];
    let (ls, lv) = shape_of("light_dir", light_dir)?;
    let per_matrix = if ls == [3] {
        false
    } else if ls.len() == lead.len() + 1 && ls[..lead.len()] == *lead && ls[lead.len()] == 3 {
        true
    } else {
        let per = if lead.is_empty() {
            String::new()
        } else {
            format!(" or {}", fmt_shape(&[lead, &[3]].concat()))
        };
        return Err(PyValueError::new_err(format!(
            "light_dir must have shape (3,){per} for matrix of shape {} (got {})",
            fmt_shape(&ms),
            fmt_shape(&ls)
        )));
    };
    let count = mv.len() / 16;
    let out_shape = [lead, &[3]].concat();
    let mut out = buffer(3 * count, &out_shape)?;
    for i in 0..count {
        let m = from_rows(&mv[16 * i..16 * i + 16]);
        let o = if per_matrix { 3 * i } else { 0 };
        let l = DVec3::new(lv[o], lv[o + 1], lv[o + 2]);
        let r = ShadowMap::new(m, l)
            .and_then(|s| measure_frustum_max(&view, &s))
            .map_err(|e| {
                if lead.is_empty() {
                    err(e)
                } else {
                    PyValueError::new_err(format!(
                        "{e} (matrix at index {})",
                        crate::broadcast::fmt_index(i, lead)
                    ))
                }
            })?;
        out.extend_from_slice(&[r.max_mx, r.max_mz, r.storage_factor]);
    }
    to_python(py, out_shape, out)
}

/// The perspective aliasing error ``[m_x, m_z]`` of one shadow matrix at eye-space points
/// (depth −z > 0), from the exact derivatives of s and t: the light beam widths across and
/// along the map over the image beam width 2 z tan θ / res_image (Lloyd 2006 Eq 7, 8 for any
/// matrix). point: (3,) or (..., 3); returns (..., 2) float64.
#[pyfunction]
#[pyo3(signature = (matrix, light_dir, point, near, far, half_fov, *, res_image=1.0, res_s=1.0,
    res_t=1.0, aspect=1.0))]
#[allow(clippy::too_many_arguments)]
pub fn point_error<'py>(
    py: Python<'py>,
    matrix: &Any<'py>,
    light_dir: &Any<'py>,
    point: &Any<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    #[pyo3(from_py_with = args::res_image)] res_image: f64,
    #[pyo3(from_py_with = args::res_s)] res_s: f64,
    #[pyo3(from_py_with = args::res_t)] res_t: f64,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
) -> PyResult<Any<'py>> {
    let view = view_of(near, far, half_fov, aspect)?;
    let m = from_rows(&values("matrix", matrix, &[4, 4])?);
    let l = vec3("light_dir", light_dir)?;
    let shadow = ShadowMap::new(m, l).map_err(err)?;
    let res = Resolutions::new(res_image, res_s, res_t).map_err(err)?;
    let (ps, pv) = shape_of("point", point)?;
    if ps.last() != Some(&3) {
        return Err(PyValueError::new_err(format!(
            "point must have shape (3,) or (..., 3) (got {})",
            fmt_shape(&ps)
        )));
    }
    let lead = &ps[..ps.len() - 1];
    let out_shape = [lead, &[2]].concat();
    let mut out = buffer(pv.len() / 3 * 2, &out_shape)?;
    for (i, p) in pv.chunks_exact(3).enumerate() {
        let e = measure_point_error(&view, &shadow, DVec3::new(p[0], p[1], p[2]), res).map_err(
            |e| {
                if lead.is_empty() {
                    err(e)
                } else {
                    PyValueError::new_err(format!(
                        "{e} (point at index {})",
                        crate::broadcast::fmt_index(i, lead)
                    ))
                }
            },
        )?;
        out.extend_from_slice(&[e.mx, e.mz]);
    }
    to_python(py, out_shape, out)
}
