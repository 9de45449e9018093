//! `plan`: the crate's planner (`shadow_aliasing::plan`), the cheapest shadow set-up for a target
//! error or the least error for a texel budget, with every candidate's figures.

use crate::args;
use crate::closed::choice;
use crate::frame::{clipmap_options, depth_clamp_arg, frame_err, with_scene};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{CascadeSplits, FrameInput, FrameScheme};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::plan::allocate::Rounding;
use shadow_aliasing::plan::candidates::{
    face_rule_name, label, rule_name, splits_name, warp_args, CLIPMAP_RESOLUTION,
};
use shadow_aliasing::plan::clipmap::{
    clipmap_for_error, clipmap_for_pool, plan_clipmap as plan_levels, ClipmapPlan,
};
use shadow_aliasing::plan::{plan as plan_frame, Goal, Plan};

type Any<'py> = Bound<'py, PyAny>;

/// The maps a budget's scheme may have when `max_maps` is not given (the command line's default).
const DEFAULT_MAX_MAPS: usize = 8;

/// `rounding`: "whole" (the default), "power_of_two", or a whole number of texels (a tile).
pub(crate) fn rounding(ob: Option<&Any<'_>>) -> PyResult<Rounding> {
    let Some(ob) = ob.filter(|o| !o.is_none()) else {
        return Ok(Rounding::Whole);
    };
    if let Ok(s) = ob.extract::<String>() {
        return Ok(match choice("rounding", &s, &["whole", "power_of_two"])? {
            "whole" => Rounding::Whole,
            _ => Rounding::PowerOfTwo,
        });
    }
    let tile = args::whole("rounding", ob, u64::from(u32::MAX)).map_err(|e| {
        if e.is_instance_of::<PyTypeError>(ob.py()) {
            PyTypeError::new_err(format!(
                "rounding must be \"whole\", \"power_of_two\" or a whole number of texels (got {})",
                args::kind(ob)
            ))
        } else {
            e
        }
    })?;
    match u32::try_from(tile) {
        Ok(t) if t >= 1 => Ok(Rounding::Multiple(t)),
        _ => Err(PyValueError::new_err(format!(
            "rounding must be a tile of at least 1 texel (got {tile})"
        ))),
    }
}

/// `sa.frame`'s keyword arguments that build `s`.
fn frame_kwargs<'py>(py: Python<'py>, s: &FrameScheme<'_>) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let splits = |d: &Bound<'py, PyDict>, sp: &CascadeSplits<'_>| -> PyResult<()> {
        let (name, k) = splits_name(sp);
        d.set_item("partition", name.replace('-', "_"))?;
        d.set_item("k", k)?;
        if let CascadeSplits::Scheme {
            scheme: SplitScheme::Practical { lambda },
            ..
        } = sp
        {
            d.set_item("lambda_", *lambda)?;
        }
        Ok(())
    };
    match s {
        FrameScheme::Single(r) => {
            d.set_item("scheme", "single")?;
            d.set_item("rule", rule_name(*r))?;
            if let WarpRule::Tsm { focus } = r {
                d.set_item("focus", *focus)?;
            }
        }
        FrameScheme::Tsm(o) => {
            d.set_item("scheme", "tsm")?;
            d.set_item("focus", o.focus)?;
        }
        FrameScheme::Cascades { splits: sp, rule } => {
            d.set_item("scheme", "cascades")?;
            d.set_item("rule", rule_name(*rule))?;
            splits(&d, sp)?;
        }
        FrameScheme::Stable(sp) => {
            d.set_item("scheme", "stable")?;
            splits(&d, sp)?;
        }
        FrameScheme::Faces { rule, k } => {
            d.set_item("scheme", "faces")?;
            d.set_item("rule", face_rule_name(*rule))?;
            d.set_item("k", *k)?;
        }
        FrameScheme::Clipmap(o) => {
            d.set_item("scheme", "clipmap")?;
            d.set_item("lod_bias", o.lod_bias)?;
            d.set_item("levels", (o.first_level, o.last_level))?;
            d.set_item("level_unit", o.unit)?;
            d.set_item("page_texels", o.page_texels)?;
            d.set_item("map_resolution", CLIPMAP_RESOLUTION)?;
        }
        #[allow(unreachable_patterns)]
        _ => d.set_item("scheme", label(s))?,
    }
    Ok(d)
}

/// A candidate's or the plan's scheme entries: its label, `sa.frame`'s keywords, `warp`'s flags.
pub(crate) fn scheme_entries(
    d: &Bound<'_, PyDict>,
    s: &FrameScheme<'_>,
    image_height: u32,
) -> PyResult<()> {
    d.set_item("scheme", label(s))?;
    d.set_item("frame_kwargs", frame_kwargs(d.py(), s)?)?;
    d.set_item("warp_args", warp_args(s, image_height))?;
    Ok(())
}

/// The cheapest shadow set-up for a target error, or the least error within a texel budget (the
/// crate's ``shadow_aliasing::plan::plan``): every candidate — a single map with each warp rule,
/// TSM, cascades k = 2…8 with each split scheme (equal-error included) unwarped and LiSPSM,
/// stable cascades, face partitions, the clipmap (its LOD bias chosen for the goal, levels of
/// 16384 texels, texels its pages × 128²) — built for the scene and measured over its focus body.
///
/// The scene as ``sa.frame`` takes it: ``view`` (4, 4) world → eye, ``near``, ``far``,
/// ``half_fov``, ``light_dir``, ``aspect``, ``receivers``, ``casters``, ``depth_range``,
/// ``depth_clamp``, ``map_resolution``; ``image_height``: errors are in these pixels per texel.
/// The goal: ``max_error`` (pixels per texel; the fewest texels that meet it) or
/// ``budget_texels`` with ``max_maps`` (default 8; the least error within the budget).
/// ``rounding``: each map's resolutions "whole" (default), "power_of_two", or multiples of a tile.
///
/// Returns a dict: ``scheme`` (its name), ``frame_kwargs`` (``sa.frame``'s keywords that build
/// it), ``warp_args`` (the command line's ``warp`` flags), ``resolutions`` (m, 2) ``[res_s,
/// res_t]`` per map in the frame's order, ``max_error_pixels``, ``texels``, ``focus``, and
/// ``candidates``: a list of dicts with the same ``scheme``, ``frame_kwargs``, ``warp_args`` and
/// either ``maps``, ``texels``, ``max_error_pixels``, ``storage_factor`` or ``error`` (why it is
/// not a plan). The GIL is released while it is planned.
#[pyfunction]
#[pyo3(signature = (view, near, far, half_fov, light_dir, *, image_height, max_error=None,
    budget_texels=None, max_maps=None, rounding=None, aspect=1.0, receivers=None, casters=None,
    depth_range=None, depth_clamp=false, map_resolution=2048))]
#[allow(clippy::too_many_arguments)]
pub fn plan<'py>(
    py: Python<'py>,
    view: &Any<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::image_height)] image_height: u32,
    max_error: Option<&Any<'py>>,
    budget_texels: Option<&Any<'py>>,
    max_maps: Option<&Any<'py>>,
    rounding: Option<&Any<'py>>,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
    receivers: Option<&Any<'py>>,
    casters: Option<&Any<'py>>,
    depth_range: Option<&Any<'py>>,
    #[pyo3(from_py_with = depth_clamp_arg)] depth_clamp: bool,
    #[pyo3(from_py_with = args::map_resolution)] map_resolution: u32,
) -> PyResult<Bound<'py, PyDict>> {
    let (camera, light, receivers, casters, depth_range) = crate::frame::scene(
        view,
        (near, far, half_fov, aspect),
        light_dir,
        [receivers, casters, depth_range],
    )?;
    let max_error = max_error
        .filter(|v| !v.is_none())
        .map(|v| args::real("max_error", v))
        .transpose()?;
    let budget = budget_texels
        .filter(|v| !v.is_none())
        .map(|v| args::whole("budget_texels", v, u64::MAX))
        .transpose()?;
    let max_maps = max_maps
        .filter(|v| !v.is_none())
        .map(|v| args::whole("max_maps", v, u64::MAX))
        .transpose()?;
    let goal = match (max_error, budget, max_maps) {
        (Some(e), None, None) => Goal::MaxError(e),
        (Some(_), None, Some(_)) => {
            return Err(PyValueError::new_err(
                "max_maps is only used with budget_texels: drop it, or give budget_texels \
                 instead of max_error",
            ))
        }
        (None, Some(t), m) => Goal::Budget {
            texels: t,
            max_maps: m.map_or(DEFAULT_MAX_MAPS, |m| {
                usize::try_from(m).unwrap_or(usize::MAX)
            }),
        },
        (Some(_), Some(_), _) => {
            return Err(PyValueError::new_err(
                "max_error and budget_texels are alternatives: give one",
            ))
        }
        (None, None, _) => {
            return Err(PyValueError::new_err(
                "max_error or budget_texels is needed: max_error=PX for the fewest texels \
                 within PX, or budget_texels=N (with max_maps) for the least error within N",
            ))
        }
    };
    let rounding = self::rounding(rounding)?;
    // On a thread of its own, Ctrl-C seen while it runs (a plan over thousands of caster boxes
    // takes seconds).
    let p = crate::interrupt::off_thread(py, move || {
        let input =
            FrameInput::new(camera, light, map_resolution, image_height).depth_clamp(depth_clamp);
        let input = with_scene(input, receivers.as_deref(), casters.as_deref(), depth_range);
        plan_frame(&input, goal, rounding)
    })?
    .map_err(|e| frame_err(e, false))?;
    result(py, &p, image_height)
}

/// The plan as a dict.
fn result<'py>(py: Python<'py>, p: &Plan, image_height: u32) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    scheme_entries(&d, &p.scheme(), image_height)?;
    let res: Vec<i64> = p
        .resolutions
        .iter()
        .flat_map(|r| [r.res_s as i64, r.res_t as i64])
        .collect();
    let res = numpy::PyArrayMethods::reshape(
        &numpy::PyArray1::from_vec(py, res),
        [p.resolutions.len(), 2],
    )?;
    d.set_item("resolutions", res)?;
    d.set_item("max_error_pixels", p.max_error_pixels)?;
    d.set_item("texels", p.texels)?;
    d.set_item("focus", p.frame.focus().name())?;
    let rows = PyList::empty(py);
    for c in &p.candidates {
        let r = PyDict::new(py);
        scheme_entries(&r, &c.scheme, image_height)?;
        match &c.outcome {
            Ok(m) => {
                r.set_item("maps", m.maps)?;
                r.set_item("texels", m.texels)?;
                r.set_item("max_error_pixels", m.max_error_pixels)?;
                r.set_item("storage_factor", m.storage_factor)?;
            }
            Err(e) => r.set_item("error", e.to_string())?,
        }
        rows.append(r)?;
    }
    d.set_item("candidates", rows)?;
    Ok(d)
}

/// A clipmap's levels for the scene (the crate's ``shadow_aliasing::plan::clipmap``): the first
/// and last level the visible depths need, each level's depths, error bound, texel, measured
/// error and pages, and the LOD bias, as given (``lod_bias``), or the least whose pages fit
/// ``pool`` pages, or the one with the fewest pages whose measured error is at most
/// ``max_error`` pixels (alternatives). The scene as ``sa.frame`` takes it; ``map_resolution``
/// (default 16384) is the levels' texels a side; ``levels``, ``level_unit``, ``page_texels`` as
/// ``sa.frame``'s clipmap.
///
/// Returns a dict: ``lod_bias`` (the bias asked for: the one to give ``sa.frame``),
/// ``bias_in_effect``, ``first_level``, ``last_level``, ``pages``, ``max_error_pixels``,
/// ``frame_kwargs`` (``sa.frame``'s keywords that build it) and ``levels``: a list of dicts
/// ``level``, ``depths`` (a, b), ``error_bound`` (least, largest), ``texel``,
/// ``max_error_pixels`` (None where its body is empty), ``pages``. The GIL is released.
#[pyfunction]
#[pyo3(signature = (view, near, far, half_fov, light_dir, *, image_height, aspect=1.0,
    receivers=None, casters=None, depth_range=None, depth_clamp=false, map_resolution=16384,
    lod_bias=None, levels=None, level_unit=None, page_texels=None, pool=None, max_error=None))]
#[allow(clippy::too_many_arguments)]
pub fn plan_clipmap<'py>(
    py: Python<'py>,
    view: &Any<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::image_height)] image_height: u32,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
    receivers: Option<&Any<'py>>,
    casters: Option<&Any<'py>>,
    depth_range: Option<&Any<'py>>,
    #[pyo3(from_py_with = depth_clamp_arg)] depth_clamp: bool,
    #[pyo3(from_py_with = args::map_resolution)] map_resolution: u32,
    lod_bias: Option<&Any<'py>>,
    levels: Option<&Any<'py>>,
    level_unit: Option<&Any<'py>>,
    page_texels: Option<&Any<'py>>,
    pool: Option<&Any<'py>>,
    max_error: Option<&Any<'py>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (camera, light, receivers, casters, depth_range) = crate::frame::scene(
        view,
        (near, far, half_fov, aspect),
        light_dir,
        [receivers, casters, depth_range],
    )?;
    let bias_given = lod_bias.is_some_and(|v| !v.is_none());
    let opts = clipmap_options(lod_bias, levels, level_unit, page_texels)?.options;
    let pool = pool
        .filter(|v| !v.is_none())
        .map(|v| args::whole("pool", v, u64::MAX))
        .transpose()?;
    let max_error = max_error
        .filter(|v| !v.is_none())
        .map(|v| args::real("max_error", v))
        .transpose()?;
    if usize::from(bias_given) + usize::from(pool.is_some()) + usize::from(max_error.is_some()) > 1
    {
        return Err(PyValueError::new_err(
            "lod_bias, pool and max_error are alternatives (the bias given, or chosen for a \
             page pool or a target error): give one",
        ));
    }
    // On a thread of its own, Ctrl-C seen while it runs.
    let p = crate::interrupt::off_thread(py, move || {
        let input =
            FrameInput::new(camera, light, map_resolution, image_height).depth_clamp(depth_clamp);
        let input = with_scene(input, receivers.as_deref(), casters.as_deref(), depth_range);
        match (pool, max_error) {
            (Some(n), _) => clipmap_for_pool(&input, &opts, n),
            (_, Some(e)) => clipmap_for_error(&input, &opts, e),
            _ => plan_levels(&input, &opts),
        }
    })?
    .map_err(|e| frame_err(e, false))?;
    clipmap_result(py, &p, map_resolution)
}

/// A clipmap plan as a dict.
fn clipmap_result<'py>(
    py: Python<'py>,
    p: &ClipmapPlan,
    map_resolution: u32,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let o = p.choice.options;
    let (first, last) = p.level_range();
    d.set_item("lod_bias", o.lod_bias)?;
    d.set_item("bias_in_effect", p.choice.bias)?;
    d.set_item("first_level", first)?;
    d.set_item("last_level", last)?;
    d.set_item("pages", p.pages())?;
    d.set_item("max_error_pixels", p.max_error_pixels())?;
    let kw = PyDict::new(py);
    kw.set_item("scheme", "clipmap")?;
    kw.set_item("lod_bias", o.lod_bias)?;
    kw.set_item("levels", (o.first_level, o.last_level))?;
    kw.set_item("level_unit", o.unit)?;
    kw.set_item("page_texels", o.page_texels)?;
    kw.set_item("map_resolution", map_resolution)?;
    d.set_item("frame_kwargs", kw)?;
    let rows = PyList::empty(py);
    for l in p.levels() {
        let r = PyDict::new(py);
        r.set_item("level", l.level)?;
        r.set_item("depths", l.depths)?;
        r.set_item("error_bound", l.error_bound)?;
        r.set_item("texel", l.texel)?;
        r.set_item("max_error_pixels", l.max_error_pixels)?;
        r.set_item("pages", l.pages)?;
        rows.append(r)?;
    }
    d.set_item("levels", rows)?;
    Ok(d)
}
