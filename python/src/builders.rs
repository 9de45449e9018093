//! Shadow-matrix builders and the measurement of any 4×4 matrix (the hemisphere sweep: `sweep`).
//!
//! Matrices cross the boundary as NumPy (row-major) 4×4 float64 arrays `M` with
//! `clip = M @ (x, y, z, 1)`: eye space (right-handed, looking down −Z, Y up) → light clip space.

use crate::args;
use crate::broadcast::{fmt_shape, value_error, values_of, FloatArg};
use crate::closed::choice;
use crate::out::Out;
use crate::stacked::{each, lead_shape, message, Operand};
use glam::{DMat4, DVec3};
use numpy::PyUntypedArrayMethods;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyList;
use shadow_aliasing::analytic::partition::{z_splits, SplitScheme};
use shadow_aliasing::maps::cascades::cascades as build_cascades;
use shadow_aliasing::maps::faces::{face_partitions, FaceWarp};
use shadow_aliasing::maps::{self, ClipDepth, Falloff, TsmOptions, TsmSearch, WarpRule};
use shadow_aliasing::scheme::ADAPTIVE_RATIO;
use shadow_aliasing::{Error, LightAngle, ViewFrustum};

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

/// Several matrices as an (m, 4, 4) array, float32 if `f32`.
fn stack<'py>(py: Python<'py>, ms: &[DMat4], f32: bool) -> PyResult<Any<'py>> {
    let mut v = Vec::with_capacity(16 * ms.len());
    for m in ms {
        v.extend_from_slice(&to_rows(m));
    }
    Out::new(None, &[], f32)?.deliver(py, vec![ms.len(), 4, 4], v)
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
    Ok(rule_spec(name, p)?.at(view))
}

/// A rule's name checked with its parameters; the defaults that depend on the camera (TSM's
/// focus, OGRE's shadow distance) are filled in per camera by [`RuleSpec::at`].
#[derive(Clone, Copy)]
pub struct RuleSpec {
    name: &'static str,
    p: RuleParams,
}

/// [`RuleSpec`] for a name, checking that every parameter given is one the rule uses.
pub fn rule_spec(name: &str, p: RuleParams) -> PyResult<RuleSpec> {
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
    if name == "eta" && p.eta.is_none() {
        return Err(PyValueError::new_err(
            "eta is missing: rule \"eta\" needs eta in [-1, 1]",
        ));
    }
    if name == "filament" && p.near_hint.is_some() != p.far_hint.is_some() {
        return Err(PyValueError::new_err(
            "near_hint and far_hint are given together (rule \"filament\")",
        ));
    }
    Ok(RuleSpec { name, p })
}

impl RuleSpec {
    /// The library's rule for this camera.
    pub fn at(&self, view: &ViewFrustum) -> WarpRule {
        let p = self.p;
        match self.name {
            "uniform" => WarpRule::Uniform,
            "eta" => WarpRule::Eta(p.eta.unwrap_or(0.0)),
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
                _ => WarpRule::Filament,
            },
            "ogre" => WarpRule::Ogre,
            _ => WarpRule::OgreOrtho {
                shadow_distance: p.shadow_distance.unwrap_or(300.0 * view.near()),
            },
        }
    }
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
/// 1 nearest the light and 0 farthest, Bevy's cascades); float32 with ``dtype=numpy.float32``
/// (rounded once from float64), (..., 4, 4) for stacks.
///
/// Stacks: ``near``, ``far``, ``half_fov`` (each a number or an array) and ``light_dir`` ((3,) or
/// (..., 3)) broadcast as NumPy broadcasts (the light's last axis aside); the result has the
/// broadcast shape in front, each entry the one-camera call's value bit for bit, computed
/// without the GIL on all cores. ``out``: an array of the result's shape and dtype to write
/// into (returned).
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, rule="minimax", *, eta=None, focus=None,
    near_hint=None, far_hint=None, shadow_distance=None, clip_depth="neg_one_to_one", aspect=1.0,
    dtype=None, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn warp<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::rule)] rule: &str,
    #[pyo3(from_py_with = args::eta)] eta: Option<f64>,
    #[pyo3(from_py_with = args::focus)] focus: Option<f64>,
    #[pyo3(from_py_with = args::near_hint)] near_hint: Option<f64>,
    #[pyo3(from_py_with = args::far_hint)] far_hint: Option<f64>,
    #[pyo3(from_py_with = args::shadow_distance)] shadow_distance: Option<f64>,
    #[pyo3(from_py_with = args::clip_depth)] clip_depth: &str,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
    dtype: Option<&Any<'py>>,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let cam = Cameras::new(near, far, half_fov, light_dir)?;
    let spec = rule_spec(
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
    let f32 = crate::out::dtype(dtype)?;
    let shape = [&cam.lead[..], &[4, 4]].concat();
    let target = Out::new(out, &shape, f32)?;
    let v = cam.each(py, aspect, 16, message, |view, l, o| {
        let s = maps::warp(&view, l, spec.at(&view))?;
        o.copy_from_slice(&to_rows(&s.with_clip_depth(depth)));
        Ok(())
    })?;
    target.deliver(py, shape, v)
}

/// The n′ the rule chooses for this camera and light (``inf`` for an unwarped map); the same
/// rules and keywords as :func:`warp`; (...,) for stacks.
///
/// Stacks: ``near``, ``far``, ``half_fov`` (each a number or an array) and ``light_dir`` ((3,) or
/// (..., 3)) broadcast as NumPy broadcasts (the light's last axis aside); the result has the
/// broadcast shape in front, each entry the one-camera call's value bit for bit, computed
/// without the GIL on all cores. ``out``: an array of the result's shape and dtype to write
/// into (returned).
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, rule="minimax", *, eta=None, focus=None,
    near_hint=None, far_hint=None, shadow_distance=None, aspect=1.0, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn n_prime_for<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::rule)] rule: &str,
    #[pyo3(from_py_with = args::eta)] eta: Option<f64>,
    #[pyo3(from_py_with = args::focus)] focus: Option<f64>,
    #[pyo3(from_py_with = args::near_hint)] near_hint: Option<f64>,
    #[pyo3(from_py_with = args::far_hint)] far_hint: Option<f64>,
    #[pyo3(from_py_with = args::shadow_distance)] shadow_distance: Option<f64>,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let cam = Cameras::new(near, far, half_fov, light_dir)?;
    let spec = rule_spec(
        rule,
        RuleParams {
            eta,
            focus,
            near_hint,
            far_hint,
            shadow_distance,
        },
    )?;
    let target = Out::new(out, &cam.lead, false)?;
    let v = cam.each(py, aspect, 1, message, |view, l, o| {
        o[0] = maps::n_prime_for(&view, l, spec.at(&view))?.value();
        Ok(())
    })?;
    target.deliver(py, cam.lead.clone(), v)
}

/// The stacked camera arguments of the builders: near, far, half_fov and light_dir (..., 3).
struct Cameras {
    ops: [Operand; 4],
    lead: Vec<usize>,
}

impl Cameras {
    fn new(
        near: &Any<'_>,
        far: &Any<'_>,
        half_fov: &Any<'_>,
        light_dir: &Any<'_>,
    ) -> PyResult<Self> {
        let ops = [
            Operand::new("near", near, &[])?,
            Operand::new("far", far, &[])?,
            Operand::new("half_fov", half_fov, &[])?,
            Operand::new("light_dir", light_dir, &[3])?,
        ];
        let lead = lead_shape(&[&ops[0], &ops[1], &ops[2], &ops[3]])?;
        Ok(Self { ops, lead })
    }

    /// `f(view, light_dir, out)` per camera of the stack, `width` values each (see
    /// [`crate::stacked::each`]).
    fn each<F>(
        &self,
        py: Python<'_>,
        aspect: f64,
        width: usize,
        msg: fn(Error) -> String,
        f: F,
    ) -> PyResult<Vec<f64>>
    where
        F: Fn(ViewFrustum, DVec3, &mut [f64]) -> Result<(), Error> + Sync,
    {
        let [n, fa, h, l] = &self.ops;
        each(
            py,
            [n, fa, h, l],
            &self.lead,
            width,
            |[n, fa, h, l], o| {
                let view = ViewFrustum::with_aspect(n[0], fa[0], h[0], aspect)?;
                f(view, DVec3::new(l[0], l[1], l[2]), o)
            },
            msg,
        )
    }
}

pub(crate) fn split_scheme(
    name: &str,
    lambda_: Option<f64>,
    light_dir: DVec3,
) -> PyResult<SplitScheme> {
    split_spec(name, lambda_)?.at(light_dir).map_err(err)
}

/// A partition's name checked with `lambda_`; the adaptive planes' light angle is taken per
/// light by [`SplitSpec::at`].
#[derive(Clone, Copy)]
pub(crate) enum SplitSpec {
    Fixed(SplitScheme),
    Adaptive,
}

pub(crate) fn split_spec(name: &str, lambda_: Option<f64>) -> PyResult<SplitSpec> {
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
        "self_similar" | "log" => SplitSpec::Fixed(SplitScheme::SelfSimilar),
        "uniform" => SplitSpec::Fixed(SplitScheme::Uniform),
        "practical" => SplitSpec::Fixed(SplitScheme::Practical {
            lambda: lambda_.ok_or_else(|| {
                PyValueError::new_err("lambda_ is missing (partition \"practical\" needs it)")
            })?,
        }),
        _ => SplitSpec::Adaptive,
    })
}

impl SplitSpec {
    /// The split scheme for this light.
    pub(crate) fn at(&self, light_dir: DVec3) -> Result<SplitScheme, Error> {
        Ok(match *self {
            SplitSpec::Fixed(s) => s,
            SplitSpec::Adaptive => SplitScheme::Adaptive {
                light_angle: LightAngle::from_light_dir(light_dir)?.radians(),
                ratio: ADAPTIVE_RATIO,
            },
        })
    }
}

/// k z-partitions (cascades) of the view frustum, each with its own map fitted by `rule`
/// (as in :func:`warp`). The split planes: ``partition`` "self_similar" (alias "log";
/// z_i = n (f/n)^{i/k}, Lloyd 2006 Eq 15, 16), "uniform", "practical" (``lambda_`` ∈ [0, 1])
/// or "adaptive" (Barroso Eq 19, γ from the light, α = 2). ``overlap`` ∈ [0, 1) widens each
/// partition's far end by that fraction of its depth. Returns a (k, 4, 4) float64 array, near to
/// far ((..., k, 4, 4) for stacks; float32 with ``dtype=numpy.float32``); :func:`z_partition`
/// gives the planes.
///
/// Stacks: ``near``, ``far``, ``half_fov`` (each a number or an array) and ``light_dir`` ((3,) or
/// (..., 3)) broadcast as NumPy broadcasts (the light's last axis aside); the result has the
/// broadcast shape in front, each entry the one-camera call's value bit for bit, computed
/// without the GIL on all cores. ``out``: an array of the result's shape and dtype to write
/// into (returned).
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, k, partition="self_similar", rule="minimax",
    *, lambda_=None, overlap=0.0, eta=None, focus=None, clip_depth="neg_one_to_one", aspect=1.0,
    dtype=None, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn cascades<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
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
    dtype: Option<&Any<'py>>,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let cam = Cameras::new(near, far, half_fov, light_dir)?;
    let spec = rule_spec(
        rule,
        RuleParams {
            eta,
            focus,
            ..RuleParams::default()
        },
    )?;
    let splits_of = split_spec(partition, lambda_)?;
    // k's own check (1 to MAX_PARTITIONS) before k sizes the result.
    z_splits(1.0, 2.0, k, SplitScheme::Uniform).map_err(err)?;
    let depth = self::clip_depth(clip_depth)?;
    let f32 = crate::out::dtype(dtype)?;
    let shape = [&cam.lead[..], &[k, 4, 4]].concat();
    let target = Out::new(out, &shape, f32)?;
    let v = cam.each(py, aspect, 16 * k, message, |view, l, o| {
        let splits = z_splits(view.near(), view.far(), k, splits_of.at(l)?)?;
        let c = build_cascades(&view, l, &splits, spec.at(&view), overlap)?;
        if c.k() != k {
            return Err(Error::Degenerate(format!(
                "{} cascades built where {k} were asked for",
                c.k()
            )));
        }
        for (p, o) in c.iter().zip(o.chunks_exact_mut(16)) {
            o.copy_from_slice(&to_rows(&p.shadow.with_clip_depth(depth)));
        }
        Ok(())
    })?;
    target.deliver(py, shape, v)
}

/// Face partitions (Lloyd 2006 §5.1): one map per visible face of the view frustum, each side
/// face z-partitioned k times (self-similar planes), warped by ``warp`` "uniform", "psm" or
/// "lispsm" (n′ = d_n + √(d_n d_f) of its face, which reproduces Lloyd 2006 Eq 19, 21).
/// Returns ``(matrices, faces)``: an (m, 4, 4) float64 array and the face of each ("bottom",
/// "right", "top", "left", "near"); float32 matrices with ``dtype=numpy.float32``. (No stacks
/// and no ``out``: the number of maps depends on the light.)
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, k=1, warp="lispsm", *,
    clip_depth="neg_one_to_one", aspect=1.0, dtype=None))]
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
    dtype: Option<&Any<'py>>,
) -> PyResult<(Any<'py>, Bound<'py, PyList>)> {
    let f32 = crate::out::dtype(dtype)?;
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
    Ok((stack(py, &ms, f32)?, PyList::new(py, names)?))
}

/// The trapezoidal shadow map (Martin & Tan 2004): the focus point ``focus`` beyond the near
/// plane on the view axis (default (f − n)/2) is mapped to the 80 % line ξ = −0.6 (§6.2), or to
/// the line ``xi`` ∈ (−1, 1), or, with ``iterative`` = the map's texel lines along t, the line of
/// largest focus area (§6.2's iterative variant, searched fast as the crate's
/// ``TsmSearch::Iterative``: 33 sampled lines refined, which can miss a peak narrower than the
/// sampling step). Returns the 4×4 float64 matrix eye → light clip space ((..., 4, 4) for
/// stacks; float32 with ``dtype=numpy.float32``).
///
/// Stacks: ``near``, ``far``, ``half_fov`` (each a number or an array) and ``light_dir`` ((3,) or
/// (..., 3)) broadcast as NumPy broadcasts (the light's last axis aside); the result has the
/// broadcast shape in front, each entry the one-camera call's value bit for bit, computed
/// without the GIL on all cores. ``out``: an array of the result's shape and dtype to write
/// into (returned).
#[pyfunction]
#[pyo3(signature = (near, far, half_fov, light_dir, focus=None, *, xi=None, iterative=None,
    clip_depth="neg_one_to_one", aspect=1.0, dtype=None, out=None))]
#[allow(clippy::too_many_arguments)]
pub fn tsm<'py>(
    py: Python<'py>,
    near: &Any<'py>,
    far: &Any<'py>,
    half_fov: &Any<'py>,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::focus)] focus: Option<f64>,
    #[pyo3(from_py_with = args::xi)] xi: Option<f64>,
    #[pyo3(from_py_with = args::iterative)] iterative: Option<u32>,
    #[pyo3(from_py_with = args::clip_depth)] clip_depth: &str,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
    dtype: Option<&Any<'py>>,
    out: Option<&Any<'py>>,
) -> PyResult<Any<'py>> {
    let cam = Cameras::new(near, far, half_fov, light_dir)?;
    let search = tsm_search(xi, iterative)?;
    let depth = self::clip_depth(clip_depth)?;
    let f32 = crate::out::dtype(dtype)?;
    let shape = [&cam.lead[..], &[4, 4]].concat();
    let target = Out::new(out, &shape, f32)?;
    // The crate's name for what Python calls `iterative`.
    let msg: fn(Error) -> String = |e| match e {
        Error::InvalidArgument {
            name: "map_lines",
            reason,
        } => format!("iterative {reason}"),
        e => e.to_string(),
    };
    let v = cam.each(py, aspect, 16, msg, |view, l, o| {
        let opts = TsmOptions {
            focus: focus.unwrap_or(0.5 * (view.far() - view.near())),
            search,
        };
        let m = maps::tsm(&view, l, opts)?;
        o.copy_from_slice(&to_rows(&m.shadow.with_clip_depth(depth)));
        Ok(())
    })?;
    target.deliver(py, shape, v)
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
