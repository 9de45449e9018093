//! `frame`: the crate's world-space frame API (`shadow_aliasing::frame`), one call per light per
//! frame, its maps returned as NumPy arrays.

use crate::args;
use crate::broadcast::{fmt_shape, to_python, values_of, FloatArg};
use crate::builders::{err, from_rows, rule, split_scheme, to_rows, tsm_search, vec3, RuleParams};
use crate::closed::choice;
use glam::{DMat4, DVec3};
use numpy::PyUntypedArrayMethods;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyList};
use shadow_aliasing::frame::{
    frame as build_frame, Aabb, Bias, Bound as SceneBound, Camera, CascadeSplits, ClipmapOptions,
    FrameInput, FrameScheme, WarpCentre,
};
use shadow_aliasing::maps::faces::FaceWarp;
use shadow_aliasing::maps::{ClipDepth, TsmOptions, WarpRule};
use shadow_aliasing::Error;

type Any<'py> = Bound<'py, PyAny>;

/// The keys of `bevy`, Bevy's `CascadeShadowConfigBuilder` fields.
const BEVY_KEYS: [&str; 5] = [
    "num_cascades",
    "minimum_distance",
    "maximum_distance",
    "first_cascade_far_bound",
    "overlap_proportion",
];

/// World-space boxes from an `(n, 2, 3)` array (each `[min, max]`), or `None` for no bound.
pub(crate) fn boxes(name: &'static str, ob: Option<&Any<'_>>) -> PyResult<Option<Vec<Aabb>>> {
    let Some(ob) = ob.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    let a = match FloatArg::extract(name, ob)? {
        FloatArg::Number(_) => {
            return Err(PyValueError::new_err(format!(
                "{name} must be an array of shape (n, 2, 3) of boxes [min, max] (got a number)"
            )))
        }
        FloatArg::Array(a) => a,
    };
    let shape = a.shape().to_vec();
    if !(shape.len() == 3 && shape[1] == 2 && shape[2] == 3) {
        return Err(PyValueError::new_err(format!(
            "{name} must be an array of shape (n, 2, 3) of boxes [min, max] (got shape {})",
            fmt_shape(&shape)
        )));
    }
    let v = values_of(&a)?;
    v.chunks_exact(6)
        .enumerate()
        .map(|(i, b)| {
            Aabb::new([b[0], b[1], b[2]], [b[3], b[4], b[5]]).map_err(|_| {
                PyValueError::new_err(format!(
                    "{name} boxes must be finite with min not above max (got min={:?}, max={:?} \
                     at index {i})",
                    &b[..3],
                    &b[3..]
                ))
            })
        })
        .collect::<PyResult<Vec<_>>>()
        .map(Some)
}

/// A one-dimensional array of real numbers (`splits`, `fractions`), or `None`.
fn list(name: &str, ob: Option<&Any<'_>>) -> PyResult<Option<Vec<f64>>> {
    let Some(ob) = ob.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    match FloatArg::extract(name, ob)? {
        FloatArg::Number(_) => Err(PyValueError::new_err(format!(
            "{name} must be a one-dimensional array of numbers (got a number)"
        ))),
        FloatArg::Array(a) if a.ndim() == 1 => values_of(&a).map(Some),
        FloatArg::Array(a) => Err(PyValueError::new_err(format!(
            "{name} must be a one-dimensional array of numbers (got shape {})",
            fmt_shape(a.shape())
        ))),
    }
}

/// `map_resolutions`: a one-dimensional array of whole numbers (each partition's texels a
/// side, in slot order), or `None`. Refused by [`list`] (a `TypeError` for what is not an
/// array of numbers, a `ValueError` for a number or an array of another shape) and here (a
/// `ValueError` for an entry that is not a whole number in `[0, 2**32)`), each naming
/// `map_resolutions`; the crate checks the count and the least resolution.
pub(crate) fn map_resolutions(ob: Option<&Any<'_>>) -> PyResult<Option<Vec<u32>>> {
    let Some(v) = list("map_resolutions", ob)? else {
        return Ok(None);
    };
    v.iter()
        .enumerate()
        .map(|(i, &r)| {
            if r.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&r) {
                // Whole, in range: the cast is exact.
                Ok(r as u32)
            } else {
                Err(PyValueError::new_err(format!(
                    "map_resolutions must hold whole numbers of texels from 0 to {} (got {r} at \
                     index {i}): one resolution per partition, in slot order",
                    u32::MAX
                )))
            }
        })
        .collect::<PyResult<Vec<_>>>()
        .map(Some)
}

/// `depth_range`: two numbers `(z_min, z_max)`, or `None`.
/// The scene of `frame`, `plan`, `plan_clipmap` and `Controller.frame`: the camera, the
/// light, the receivers' and casters' boxes, the depth range.
pub(crate) type Scene = (
    Camera,
    DVec3,
    Option<Vec<Aabb>>,
    Option<Vec<Aabb>>,
    Option<(f64, f64)>,
);

/// [`Scene`] from those functions' Python arguments (`(near, far, half_fov, aspect)`;
/// receivers, casters, depth range), each refused by its name.
pub(crate) fn scene<'py>(
    view: &Any<'py>,
    (near, far, half_fov, aspect): (f64, f64, f64, f64),
    light_dir: &Any<'py>,
    [receivers, casters, depth_range]: [Option<&Any<'py>>; 3],
) -> PyResult<Scene> {
    let view_m = from_rows(&crate::builders::values("view", view, &[4, 4])?);
    Ok((
        Camera::new(view_m, near, far, half_fov, aspect).map_err(|e| frame_err(e, false))?,
        vec3("light_dir", light_dir)?,
        boxes("receivers", receivers)?,
        boxes("casters", casters)?,
        pair("depth_range", depth_range)?,
    ))
}

pub(crate) fn pair(name: &str, ob: Option<&Any<'_>>) -> PyResult<Option<(f64, f64)>> {
    match list(name, ob)? {
        None => Ok(None),
        Some(v) if v.len() == 2 => Ok(Some((v[0], v[1]))),
        Some(v) => Err(PyValueError::new_err(format!(
            "{name} must hold two numbers (z_min, z_max) (got {})",
            v.len()
        ))),
    }
}

/// A bool (Python's or NumPy's); anything else is a `TypeError`.
pub(crate) fn flag(name: &str, ob: &Any<'_>) -> PyResult<bool> {
    let is_numpy_bool = ob.is_instance(&ob.py().import("numpy")?.getattr("bool_")?)?;
    if ob.is_instance_of::<PyBool>() || is_numpy_bool {
        return ob.is_truthy();
    }
    Err(PyTypeError::new_err(format!(
        "{name} must be a bool (got {})",
        args::kind(ob)
    )))
}

/// `depth_clamp`, by [`flag`].
pub(crate) fn depth_clamp_arg(ob: &Any<'_>) -> PyResult<bool> {
    flag("depth_clamp", ob)
}

/// `measure`, by [`flag`].
fn measure_arg(ob: &Any<'_>) -> PyResult<bool> {
    flag("measure", ob)
}

/// `bevy`: a mapping with Bevy's `CascadeShadowConfigBuilder` fields.
fn bevy_splits(ob: &Any<'_>) -> PyResult<CascadeSplits<'static>> {
    let d = ob.cast::<PyDict>().map_err(|_| {
        PyTypeError::new_err(format!(
            "bevy must be a dict with the keys {} (got {})",
            BEVY_KEYS.join(", "),
            args::kind(ob)
        ))
    })?;
    let mut v = [0.0; 5];
    for (slot, key) in v.iter_mut().zip(BEVY_KEYS) {
        let item = d.get_item(key)?.ok_or_else(|| {
            PyValueError::new_err(format!(
                "bevy must have the keys {} (missing {key})",
                BEVY_KEYS.join(", ")
            ))
        })?;
        *slot = args::real(&format!("bevy[{key:?}]"), &item)?;
    }
    for key in d.keys() {
        let k: String = key.str()?.extract()?;
        if !BEVY_KEYS.contains(&k.as_str()) {
            return Err(PyValueError::new_err(format!(
                "bevy has an unknown key {k:?} (the keys: {})",
                BEVY_KEYS.join(", ")
            )));
        }
    }
    let k = v[0];
    if !(k.fract() == 0.0 && (1.0..=16.0).contains(&k)) {
        return Err(PyValueError::new_err(format!(
            "bevy[\"num_cascades\"] must be a whole number in [1, 16] (got {k})"
        )));
    }
    Ok(CascadeSplits::Bevy {
        k: k as usize,
        minimum_distance: v[1],
        maximum_distance: v[2],
        first_far_bound: v[3],
        overlap_proportion: v[4],
    })
}

/// The frame's error for Python: the crate's names of `bevy`'s fields and of the view matrix
/// spelled as Python's arguments.
pub(crate) fn frame_err(e: Error, bevy: bool) -> PyErr {
    match e {
        Error::InvalidArgument { name, reason } => {
            let py_name = match name {
                "world_to_eye" => "view".to_string(),
                "light_dir_world" => "light_dir".to_string(),
                "minimum_distance" | "maximum_distance" | "overlap" | "k" if bevy => {
                    let key = match name {
                        "overlap" => "overlap_proportion",
                        "k" => "num_cascades",
                        n => n,
                    };
                    format!("bevy[{key:?}]")
                }
                "first_far_bound" => "bevy[\"first_cascade_far_bound\"]".to_string(),
                "planes" => "splits".to_string(),
                "map_lines" => "iterative".to_string(),
                // The clipmap's (FIRST, LAST) are one argument, `levels`; its `unit`, `level_unit`.
                "first_level" | "last_level" => format!("levels ({name})"),
                "unit" => "level_unit".to_string(),
                n => n.to_string(),
            };
            PyValueError::new_err(format!("{py_name} {reason}"))
        }
        e => err(e),
    }
}

/// The scheme's argument `name` given where the scheme does not use it.
fn unused(name: &str, scheme: &str) -> PyErr {
    PyValueError::new_err(format!(
        "{name} is not used by scheme \"{scheme}\": drop it"
    ))
}

/// The shadow maps of one frame in world space, fitted to the scene (the crate's
/// ``shadow_aliasing::frame``, bit for bit).
///
/// view: the camera's (4, 4) world → eye matrix (rigid, row-major, looking down −Z), with the
/// projection's ``near``, ``far``, ``half_fov`` (radians, vertical) and ``aspect``; light_dir: the
/// world direction light travels. ``receivers``, ``casters``: (n, 2, 3) boxes [min, max] (None:
/// unbounded); ``depth_range``: (z_min, z_max) of the visible receivers; ``depth_clamp``;
/// ``measure`` (False: no error measurement, errors +inf); ``map_resolution``, ``image_height``;
/// ``map_resolutions`` (None, or one whole number per partition in slot order: each map's own
/// texels a side, instead of ``map_resolution`` for all; equal-error splits place their planes
/// at ``map_resolution``, then build each map at its own; not with a clipmap, whose levels share
/// one); ``pcf_radius`` (texels, for the bias values).
///
/// scheme: "single" (``rule``, any of WARP_RULES, default "minimax", with its keywords),
/// "cascades" (``rule`` and ``partition`` with ``k`` — "self_similar"/"log", "uniform",
/// "practical" with ``lambda_``, "adaptive", "equal_error" — or ``splits`` [z0, …, zk], or
/// ``fractions``, or ``bevy`` {num_cascades, minimum_distance, maximum_distance,
/// first_cascade_far_bound, overlap_proportion}; ``overlap``), "stable" (the same splits),
/// "tsm" (``focus``, ``xi`` or ``iterative``), "faces" (``rule`` "uniform", "psm", "lispsm";
/// ``k``), "clipmap" (Unreal-style virtual shadow maps, levels of ``map_resolution`` texels
/// chosen for ``image_height``: ``lod_bias`` −0.5, ``levels`` (6, 22), ``level_unit`` 0.01,
/// ``page_texels`` 128 by default). An argument the scheme does not use is refused.
///
/// Returns a dict, one entry per built map along the first axis: ``world_to_clip`` and
/// ``eye_to_clip`` (m, 4, 4) in ``clip_depth``'s convention (float64, or float32 with
/// ``dtype=numpy.float32``), ``n_prime``, ``texel_world``, ``max_mx``, ``max_mz``,
/// ``storage_factor``, ``max_error_pixels``, ``normal_offset``, ``slope_scaled_depth``,
/// ``constant_depth`` (m,), ``resolution`` (m,) int64 (each map's texels a side),
/// ``texel_extent``, ``depth``, ``split``, ``blend`` (m, 2), ``slot``, ``map_focus``, ``face``,
/// ``clipmap_level`` (None except for a clipmap), ``body`` (eye-space vertices),
/// ``casters_volume`` and ``receivers_volume`` ((p, 4) world planes, inside where a x + b y + c z + d ≤ 0), and the
/// frame's ``focus``, ``light`` and ``light_dir_eye``. The GIL is released while it is built.
#[pyfunction]
#[pyo3(signature = (view, near, far, half_fov, light_dir, *, aspect=1.0, receivers=None,
    casters=None, depth_range=None, depth_clamp=false, measure=true, map_resolution=2048,
    image_height=2048, map_resolutions=None, pcf_radius=0.0,
    scheme="single", rule=None, k=None, partition=None, splits=None, fractions=None, bevy=None,
    lambda_=None, overlap=None, eta=None, focus=None, near_hint=None, far_hint=None,
    shadow_distance=None, xi=None, iterative=None, lod_bias=None, levels=None, level_unit=None,
    page_texels=None, centre="rule", clip_depth="neg_one_to_one", dtype=None))]
#[allow(clippy::too_many_arguments)]
pub fn frame<'py>(
    py: Python<'py>,
    view: &Any<'py>,
    #[pyo3(from_py_with = args::near)] near: f64,
    #[pyo3(from_py_with = args::far)] far: f64,
    #[pyo3(from_py_with = args::half_fov)] half_fov: f64,
    light_dir: &Any<'py>,
    #[pyo3(from_py_with = args::aspect)] aspect: f64,
    receivers: Option<&Any<'py>>,
    casters: Option<&Any<'py>>,
    depth_range: Option<&Any<'py>>,
    #[pyo3(from_py_with = depth_clamp_arg)] depth_clamp: bool,
    #[pyo3(from_py_with = measure_arg)] measure: bool,
    #[pyo3(from_py_with = args::map_resolution)] map_resolution: u32,
    #[pyo3(from_py_with = args::image_height)] image_height: u32,
    map_resolutions: Option<&Any<'py>>,
    #[pyo3(from_py_with = args::pcf_radius)] pcf_radius: f64,
    #[pyo3(from_py_with = args::scheme)] scheme: &str,
    rule: Option<&Any<'py>>,
    k: Option<&Any<'py>>,
    partition: Option<&Any<'py>>,
    splits: Option<&Any<'py>>,
    fractions: Option<&Any<'py>>,
    bevy: Option<&Any<'py>>,
    #[pyo3(from_py_with = args::lambda_)] lambda_: Option<f64>,
    #[pyo3(from_py_with = args::overlap_or_none)] overlap: Option<f64>,
    #[pyo3(from_py_with = args::eta)] eta: Option<f64>,
    #[pyo3(from_py_with = args::focus)] focus: Option<f64>,
    #[pyo3(from_py_with = args::near_hint)] near_hint: Option<f64>,
    #[pyo3(from_py_with = args::far_hint)] far_hint: Option<f64>,
    #[pyo3(from_py_with = args::shadow_distance)] shadow_distance: Option<f64>,
    #[pyo3(from_py_with = args::xi)] xi: Option<f64>,
    #[pyo3(from_py_with = args::iterative)] iterative: Option<u32>,
    lod_bias: Option<&Any<'py>>,
    levels: Option<&Any<'py>>,
    level_unit: Option<&Any<'py>>,
    page_texels: Option<&Any<'py>>,
    #[pyo3(from_py_with = args::centre)] centre: &str,
    #[pyo3(from_py_with = args::clip_depth)] clip_depth: &str,
    dtype: Option<&Any<'py>>,
) -> PyResult<Bound<'py, PyDict>> {
    // Every argument converted and checked before the frame is built.
    let (camera, light, receivers, casters, depth_range) = crate::frame::scene(
        view,
        (near, far, half_fov, aspect),
        light_dir,
        [receivers, casters, depth_range],
    )?;
    let rule_name = rule
        .filter(|r| !r.is_none())
        .map(|r| args::rule(r))
        .transpose()?;
    let k = k.filter(|v| !v.is_none()).map(|v| args::k(v)).transpose()?;
    let partition = partition
        .filter(|v| !v.is_none())
        .map(|v| args::partition(v))
        .transpose()?;
    let splits = list("splits", splits)?;
    let fractions = list("fractions", fractions)?;
    let each = self::map_resolutions(map_resolutions)?;
    let bevy = bevy.filter(|b| !b.is_none()).map(bevy_splits).transpose()?;
    let bevy_given = bevy.is_some();
    let depth = crate::builders::clip_depth(clip_depth)?;
    let f32_out = crate::out::dtype(dtype)?;
    let centre = match choice("centre", centre, &["rule", "eye", "nearest_vertex"])? {
        "rule" => WarpCentre::Rule,
        "eye" => WarpCentre::Eye,
        _ => WarpCentre::NearestVertex,
    };
    let scheme = choice(
        "scheme",
        scheme,
        &["single", "cascades", "stable", "tsm", "faces", "clipmap"],
    )?;
    let clip = clipmap_options(lod_bias, levels, level_unit, page_texels)?;
    let eye_light = camera.world_to_eye().transform_vector3(light);
    let rp = RuleParams {
        eta,
        focus,
        near_hint,
        far_hint,
        shadow_distance,
    };
    let cam_view = *camera.view();
    let warp_rule = |name: Option<&str>| -> PyResult<WarpRule> {
        self::rule(&cam_view, name.unwrap_or("minimax"), rp)
    };
    // The cascades' splits (cascades and stable).
    let cascade_splits = || -> PyResult<CascadeSplits<'_>> {
        let given = [splits.is_some(), fractions.is_some(), bevy.is_some()];
        if given.iter().filter(|g| **g).count() + usize::from(partition.is_some()) > 1 {
            return Err(PyValueError::new_err(
                "partition, splits, fractions and bevy are alternatives: give one",
            ));
        }
        if bevy.is_some() && overlap.is_some() {
            return Err(PyValueError::new_err(
                "overlap is not used with bevy, which has its own overlap_proportion: drop it",
            ));
        }
        if lambda_.is_some() && partition != Some("practical") {
            return Err(PyValueError::new_err(
                "lambda_ is only used by partition \"practical\"",
            ));
        }
        if k.is_some() && partition.is_none() {
            return Err(PyValueError::new_err(
                "k is only used with partition (splits, fractions and bevy give the count)",
            ));
        }
        let overlap_v = overlap.unwrap_or(0.0);
        if let Some(planes) = splits.as_deref() {
            return Ok(CascadeSplits::Distances {
                planes,
                overlap: overlap_v,
            });
        }
        if let Some(fr) = fractions.as_deref() {
            return Ok(CascadeSplits::Fractions {
                fractions: fr,
                overlap: overlap_v,
            });
        }
        if let Some(b) = bevy {
            return Ok(b);
        }
        let k = k.ok_or_else(|| {
            PyValueError::new_err(
                "k is missing: cascades need k with partition (or splits, fractions or bevy)",
            )
        })?;
        match partition.unwrap_or("self_similar") {
            "equal_error" => {
                if overlap.is_some() {
                    return Err(PyValueError::new_err(
                        "overlap is not used by partition \"equal_error\", whose maps cover \
                         exactly their splits: drop it",
                    ));
                }
                Ok(CascadeSplits::EqualError { k })
            }
            p => Ok(CascadeSplits::Scheme {
                scheme: split_scheme(p, lambda_, eye_light).map_err(|e| {
                    if e.to_string().contains("partition must be") {
                        PyValueError::new_err(format!("{} or \"equal_error\"", e.value(py)))
                    } else {
                        e
                    }
                })?,
                k,
                overlap: overlap_v,
            }),
        }
    };
    // The arguments each scheme does not use: given, they are refused by name.
    let refuse = |s: &str, given: &[(bool, &'static str)]| -> PyResult<()> {
        match given.iter().find(|(g, _)| *g) {
            Some((_, name)) => Err(unused(name, s)),
            None => Ok(()),
        }
    };
    let cascade_args = [
        (partition.is_some(), "partition"),
        (splits.is_some(), "splits"),
        (fractions.is_some(), "fractions"),
        (bevy.is_some(), "bevy"),
        (lambda_.is_some(), "lambda_"),
        (overlap.is_some(), "overlap"),
    ];
    let tsm_args = [(xi.is_some(), "xi"), (iterative.is_some(), "iterative")];
    let hint_args = [
        (eta.is_some(), "eta"),
        (near_hint.is_some(), "near_hint"),
        (far_hint.is_some(), "far_hint"),
        (shadow_distance.is_some(), "shadow_distance"),
    ];
    let clip_args = [(clip.given, "lod_bias, levels, level_unit or page_texels")];
    let (k_arg, rule_arg, focus_arg) = (
        [(k.is_some(), "k")],
        [(rule_name.is_some(), "rule")],
        [(focus.is_some(), "focus")],
    );
    let fs: FrameScheme<'_> = match scheme {
        "single" => {
            for given in [&cascade_args[..], &tsm_args, &k_arg, &clip_args] {
                refuse(scheme, given)?;
            }
            FrameScheme::Single(warp_rule(rule_name)?)
        }
        "cascades" => {
            refuse(scheme, &tsm_args)?;
            refuse(scheme, &clip_args)?;
            let r = warp_rule(rule_name)?;
            FrameScheme::Cascades {
                splits: cascade_splits()?,
                rule: r,
            }
        }
        "stable" => {
            for given in [&tsm_args[..], &rule_arg, &focus_arg, &hint_args, &clip_args] {
                refuse(scheme, given)?;
            }
            FrameScheme::Stable(cascade_splits()?)
        }
        "tsm" => {
            for given in [&cascade_args[..], &k_arg, &rule_arg, &hint_args, &clip_args] {
                refuse(scheme, given)?;
            }
            FrameScheme::Tsm(TsmOptions {
                focus: focus.unwrap_or(0.5 * (far - near)),
                search: tsm_search(xi, iterative)?,
            })
        }
        "clipmap" => {
            for given in [&cascade_args[..], &tsm_args, &k_arg, &focus_arg, &hint_args] {
                refuse(scheme, given)?;
            }
            if let Some(r) = rule_name.filter(|r| *r != "uniform") {
                return Err(PyValueError::new_err(format!(
                    "rule must be \"uniform\" for scheme \"clipmap\", whose levels are \
                     camera-centred orthographic squares (got \"{r}\"): drop it"
                )));
            }
            FrameScheme::Clipmap(clip.options)
        }
        _ => {
            for given in [
                &cascade_args[..],
                &tsm_args,
                &focus_arg,
                &hint_args,
                &clip_args,
            ] {
                refuse(scheme, given)?;
            }
            let rule = match choice(
                "rule",
                rule_name.unwrap_or("lispsm"),
                &["uniform", "psm", "lispsm"],
            )? {
                "uniform" => FaceWarp::Uniform,
                "psm" => FaceWarp::Psm,
                _ => FaceWarp::Lispsm,
            };
            FrameScheme::Faces {
                rule,
                k: k.unwrap_or(1),
            }
        }
    };
    // Built on a thread of its own, Ctrl-C seen while it runs (a frame over a million caster
    // boxes takes seconds); the thread owns copies of the split planes the scheme reads.
    let fs = rebind(fs, &[], &[]);
    let planes = splits.clone().unwrap_or_default();
    let fractions = fractions.clone().unwrap_or_default();
    let f = crate::interrupt::off_thread(py, move || {
        let input = FrameInput::new(camera, light, map_resolution, image_height)
            .scheme(rebind(fs, &planes, &fractions))
            .depth_clamp(depth_clamp)
            .measure(measure)
            .centre(centre);
        let input = match each.as_deref() {
            Some(each) => input.map_resolutions(each),
            None => input,
        };
        let input = with_scene(input, receivers.as_deref(), casters.as_deref(), depth_range);
        build_frame(&input)
    })?
    .map_err(|e| frame_err(e, bevy_given))?;
    result(py, &f, depth, f32_out, pcf_radius)
}

/// `s` reading its split planes from `planes` and its fractions from `fractions` (a copy of the
/// values it read before, or none while it only travels to the thread that builds the frame).
fn rebind<'b>(s: FrameScheme<'_>, planes: &'b [f64], fractions: &'b [f64]) -> FrameScheme<'b> {
    let splits = |c: CascadeSplits<'_>| -> CascadeSplits<'b> {
        match c {
            CascadeSplits::Distances { overlap, .. } => {
                CascadeSplits::Distances { planes, overlap }
            }
            CascadeSplits::Fractions { overlap, .. } => {
                CascadeSplits::Fractions { fractions, overlap }
            }
            CascadeSplits::Scheme { scheme, k, overlap } => {
                CascadeSplits::Scheme { scheme, k, overlap }
            }
            CascadeSplits::Bevy {
                k,
                minimum_distance,
                maximum_distance,
                first_far_bound,
                overlap_proportion,
            } => CascadeSplits::Bevy {
                k,
                minimum_distance,
                maximum_distance,
                first_far_bound,
                overlap_proportion,
            },
            CascadeSplits::EqualError { k } => CascadeSplits::EqualError { k },
        }
    };
    match s {
        FrameScheme::Single(r) => FrameScheme::Single(r),
        FrameScheme::Cascades { splits: c, rule } => FrameScheme::Cascades {
            splits: splits(c),
            rule,
        },
        FrameScheme::Stable(c) => FrameScheme::Stable(splits(c)),
        FrameScheme::Tsm(o) => FrameScheme::Tsm(o),
        FrameScheme::Faces { rule, k } => FrameScheme::Faces { rule, k },
        FrameScheme::Clipmap(o) => FrameScheme::Clipmap(o),
    }
}

/// `input` with the scene's receivers' and casters' boxes and depth range, where given.
pub(crate) fn with_scene<'a>(
    mut input: FrameInput<'a>,
    receivers: Option<&'a [Aabb]>,
    casters: Option<&'a [Aabb]>,
    depth_range: Option<(f64, f64)>,
) -> FrameInput<'a> {
    if let Some(b) = receivers {
        input = input.receivers(SceneBound::Boxes(b));
    }
    if let Some(b) = casters {
        input = input.casters(SceneBound::Boxes(b));
    }
    if let Some((a, b)) = depth_range {
        input = input.depth_range(a, b);
    }
    input
}

/// A clipmap's layout from the keywords (Unreal's defaults where `None`), and whether any was
/// given.
pub struct ClipArgs {
    pub options: ClipmapOptions,
    pub given: bool,
}

/// `lod_bias`, `levels` (FIRST, LAST), `level_unit`, `page_texels` over
/// [`ClipmapOptions::UNREAL`]; each checked by name (the library checks their domains).
pub fn clipmap_options<'py>(
    lod_bias: Option<&Any<'py>>,
    levels: Option<&Any<'py>>,
    level_unit: Option<&Any<'py>>,
    page_texels: Option<&Any<'py>>,
) -> PyResult<ClipArgs> {
    let some = |v: Option<&Any<'py>>| v.filter(|v| !v.is_none()).cloned();
    let (lod_bias, levels, level_unit, page_texels) = (
        some(lod_bias),
        some(levels),
        some(level_unit),
        some(page_texels),
    );
    let given =
        lod_bias.is_some() || levels.is_some() || level_unit.is_some() || page_texels.is_some();
    let mut o = ClipmapOptions::UNREAL;
    if let Some(v) = lod_bias {
        o.lod_bias = args::real("lod_bias", &v)?;
    }
    if let Some(v) = level_unit {
        o.unit = args::real("level_unit", &v)?;
    }
    if let Some(v) = page_texels {
        o.page_texels =
            u32::try_from(args::whole("page_texels", &v, u64::from(u32::MAX))?).unwrap_or(u32::MAX);
    }
    if let Some(pair) = list("levels", levels.as_ref())? {
        let whole = |v: f64| v.fract() == 0.0 && v.abs() <= 64.0;
        match pair.as_slice() {
            [f, l] if whole(*f) && whole(*l) => {
                (o.first_level, o.last_level) = (*f as i32, *l as i32);
            }
            _ => {
                return Err(PyValueError::new_err(format!(
                    "levels must be (FIRST, LAST), two whole numbers in [-64, 64] (got {pair:?}; \
                     Unreal (6, 22))"
                )))
            }
        }
    }
    Ok(ClipArgs { options: o, given })
}

/// The frame as a dict of arrays.
pub(crate) fn result<'py>(
    py: Python<'py>,
    f: &shadow_aliasing::frame::Frame,
    depth: ClipDepth,
    f32_out: bool,
    pcf_radius: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let maps: Vec<(usize, &shadow_aliasing::frame::FrameMap)> = f
        .slots()
        .iter()
        .enumerate()
        .filter_map(|(i, m)| m.as_ref().map(|m| (i, m)))
        .collect();
    let m = maps.len();
    let matrices = |g: &dyn Fn(&shadow_aliasing::frame::FrameMap) -> DMat4| -> PyResult<Any<'py>> {
        let mut v = Vec::with_capacity(16 * m);
        for (_, map) in &maps {
            v.extend_from_slice(&to_rows(&g(map)));
        }
        let a = to_python(py, vec![m, 4, 4], v)?;
        if f32_out {
            a.call_method1("astype", ("float32",))
        } else {
            Ok(a)
        }
    };
    let column = |g: &dyn Fn(&shadow_aliasing::frame::FrameMap) -> f64| -> PyResult<Any<'py>> {
        to_python(py, vec![m], maps.iter().map(|(_, x)| g(x)).collect())
    };
    let pairs =
        |g: &dyn Fn(&shadow_aliasing::frame::FrameMap) -> (f64, f64)| -> PyResult<Any<'py>> {
            to_python(
                py,
                vec![m, 2],
                maps.iter()
                    .flat_map(|(_, x)| {
                        let (a, b) = g(x);
                        [a, b]
                    })
                    .collect(),
            )
        };
    let planes = |vol: &shadow_aliasing::frame::CullVolume| -> PyResult<Any<'py>> {
        let p = vol.planes();
        to_python(
            py,
            vec![p.len(), 4],
            p.iter().flat_map(|q| q.to_array()).collect(),
        )
    };
    let d = PyDict::new(py);
    d.set_item("focus", f.focus().name())?;
    d.set_item("light", f.light_case().name())?;
    d.set_item(
        "light_dir_eye",
        to_python(py, vec![3], f.light_dir_eye().to_array().to_vec())?,
    )?;
    d.set_item("world_to_clip", matrices(&|x| x.world_to_clip(depth))?)?;
    d.set_item(
        "eye_to_clip",
        matrices(&|x| x.shadow.with_clip_depth(depth))?,
    )?;
    d.set_item("n_prime", column(&|x| x.shadow.n_prime().value())?)?;
    d.set_item("depth", pairs(&|x| (x.shadow.near(), x.shadow.far()))?)?;
    d.set_item("split", pairs(&|x| x.split)?)?;
    d.set_item("blend", pairs(&|x| x.blend)?)?;
    d.set_item("texel_world", column(&|x| x.texel_world)?)?;
    d.set_item("max_mx", column(&|x| x.max_mx)?)?;
    d.set_item("max_mz", column(&|x| x.max_mz)?)?;
    d.set_item("storage_factor", column(&|x| x.storage_factor)?)?;
    d.set_item("max_error_pixels", column(&|x| x.max_error_pixels)?)?;
    let biases = maps
        .iter()
        .map(|(_, x)| {
            x.bias(pcf_radius, depth).map_err(|e| match e {
                Error::InvalidArgument { name: "r", reason } => {
                    PyValueError::new_err(format!("pcf_radius {reason}"))
                }
                e => err(e),
            })
        })
        .collect::<PyResult<Vec<_>>>()?;
    let bias_column = |g: &dyn Fn(&Bias) -> f64| -> PyResult<Any<'py>> {
        to_python(py, vec![m], biases.iter().map(g).collect())
    };
    d.set_item("normal_offset", bias_column(&|b| b.normal_offset)?)?;
    d.set_item(
        "slope_scaled_depth",
        bias_column(&|b| b.slope_scaled_depth)?,
    )?;
    d.set_item("constant_depth", bias_column(&|b| b.constant_depth)?)?;
    d.set_item(
        "texel_extent",
        to_python(
            py,
            vec![m, 2],
            biases
                .iter()
                .flat_map(|b| [b.texel_extent.0, b.texel_extent.1])
                .collect(),
        )?,
    )?;
    let slot: Vec<i64> = maps.iter().map(|(i, _)| *i as i64).collect();
    d.set_item("slot", numpy::PyArray1::from_vec(py, slot))?;
    let resolution: Vec<i64> = maps
        .iter()
        .map(|(_, x)| i64::from(x.resolution()))
        .collect();
    d.set_item("resolution", numpy::PyArray1::from_vec(py, resolution))?;
    d.set_item(
        "map_focus",
        PyList::new(py, maps.iter().map(|(_, x)| x.focus.name()))?,
    )?;
    d.set_item(
        "face",
        PyList::new(py, maps.iter().map(|(_, x)| x.face.map(|f| f.name())))?,
    )?;
    d.set_item(
        "clipmap_level",
        PyList::new(py, maps.iter().map(|(_, x)| x.clipmap_level))?,
    )?;
    let mut bodies = Vec::with_capacity(m);
    let mut casters = Vec::with_capacity(m);
    let mut receivers = Vec::with_capacity(m);
    for (_, x) in &maps {
        let b = x.body();
        bodies.push(to_python(
            py,
            vec![b.len(), 3],
            b.iter().flat_map(|p: &DVec3| p.to_array()).collect(),
        )?);
        casters.push(planes(x.casters_volume())?);
        receivers.push(planes(x.receivers_volume())?);
    }
    d.set_item("body", PyList::new(py, bodies)?)?;
    d.set_item("casters_volume", PyList::new(py, casters)?)?;
    d.set_item("receivers_volume", PyList::new(py, receivers)?)?;
    Ok(d)
}
