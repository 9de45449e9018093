//! `Controller`: the crate's error-budget controller (`shadow_aliasing::plan::Controller`), one
//! per light and camera, called every frame; and its maps' per-point error lens
//! (`FrameMap::error_lens_at`).
//!
//! A frame runs on a thread of its own (`crate::interrupt::off_thread`): the controller moves
//! there and back. Where Ctrl-C abandons a frame, the controller is lost with it and the next
//! frame starts afresh from the options (a cut).

use crate::args;
use crate::broadcast::{fmt_index, fmt_shape, to_python, values_of, FloatArg};
use crate::frame::{depth_clamp_arg, frame_err, with_scene};
use crate::interrupt::in_blocks;
use glam::DVec3;
use numpy::PyUntypedArrayMethods;
use pyo3::exceptions::{PyRuntimeError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use shadow_aliasing::analytic::partition::SplitScheme;
use shadow_aliasing::frame::{Camera, CascadeSplits, Frame, FrameInput, FrameScheme};
use shadow_aliasing::maps::WarpRule;
use shadow_aliasing::plan::candidates::{candidates, label};
use shadow_aliasing::plan::{Controller as Inner, ControllerOptions};
use shadow_aliasing::Error;

type Any<'py> = Bound<'py, PyAny>;

/// The crate's name of an option spelled as Python's keyword (the texel budget is
/// `budget_texels`, as `plan` names it).
fn option_err(e: Error) -> PyErr {
    match e {
        Error::InvalidArgument { name, reason } => {
            let py_name = if name == "max_texels" {
                "budget_texels"
            } else {
                name
            };
            PyValueError::new_err(format!(
                "{py_name} {}",
                reason.replace("max_texels", "budget_texels")
            ))
        }
        e => frame_err(e, false),
    }
}

/// Whether the scheme depends on each frame's camera or light (the TSM focus, the adaptive
/// splits' light angle): such a scheme cannot be one fixed candidate.
fn per_frame(s: &FrameScheme<'_>) -> Option<&'static str> {
    let adaptive = |sp: &CascadeSplits<'_>| {
        matches!(
            sp,
            CascadeSplits::Scheme {
                scheme: SplitScheme::Adaptive { .. },
                ..
            }
        )
    };
    match s {
        FrameScheme::Single(WarpRule::Tsm { .. }) | FrameScheme::Tsm(_) => {
            Some("its focus is half of each frame's depth range")
        }
        FrameScheme::Cascades { splits, .. } | FrameScheme::Stable(splits) if adaptive(splits) => {
            Some("its planes follow each frame's light angle")
        }
        _ => None,
    }
}

/// `candidates`: a list of scheme names as `plan` names them (its result's ``scheme`` and its
/// candidates' ``scheme``), or `None` for every candidate of each cut but the clipmap.
fn candidate_list(ob: Option<&Any<'_>>) -> PyResult<Option<Vec<FrameScheme<'static>>>> {
    let Some(ob) = ob.filter(|o| !o.is_none()) else {
        return Ok(None);
    };
    let not_a_list = || {
        PyTypeError::new_err(format!(
            "candidates must be a list of scheme names as plan names them, e.g. [\"single \
             uniform\", \"cascades log k=4 lispsm\"] (got {})",
            args::kind(ob)
        ))
    };
    if ob.is_instance_of::<PyString>() {
        return Err(not_a_list());
    }
    // Every scheme `plan` names, with the fixed ones' values (a camera and light that only the
    // per-frame schemes, refused below, would read).
    let camera = Camera::new(glam::DMat4::IDENTITY, 1.0, 100.0, 0.5, 1.0).map_err(err_internal)?;
    let all = candidates(&FrameInput::new(
        camera,
        DVec3::new(0.3, -0.8, -0.4),
        2048,
        1080,
    ));
    let names: Vec<String> = all.iter().map(label).collect();
    let mut chosen = Vec::new();
    for (i, item) in ob.try_iter().map_err(|_| not_a_list())?.enumerate() {
        let item = item?;
        let name: String = item.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "candidates[{i}] must be a scheme name, a string (got {})",
                args::kind(&item)
            ))
        })?;
        let Some(k) = names.iter().position(|n| *n == name) else {
            return Err(PyValueError::new_err(format!(
                "candidates[{i}] is not a scheme name of plan's candidates (got {name:?}); \
                 e.g. \"single uniform\", \"cascades practical k=3 uniform\", \"stable log \
                 k=4\", \"faces lispsm k=2\": the ``scheme`` of plan(...)[\"candidates\"]"
            )));
        };
        if let Some(why) = per_frame(&all[k]) {
            return Err(PyValueError::new_err(format!(
                "candidates[{i}] {name:?} cannot be a fixed candidate: {why}; give \
                 candidates=None to search it with every other scheme"
            )));
        }
        chosen.push(all[k]);
    }
    Ok(Some(chosen))
}

/// `shared_resolution`, by [`crate::frame::flag`].
fn shared_resolution_arg(ob: &Any<'_>) -> PyResult<bool> {
    crate::frame::flag("shared_resolution", ob)
}

/// An error of the crate where none is expected.
fn err_internal(e: Error) -> PyErr {
    PyRuntimeError::new_err(format!("internal error: {e}"))
}

/// `Option<&PyAny>` with `None` for Python's `None`.
fn given<'a, 'py>(ob: Option<&'a Any<'py>>) -> Option<&'a Any<'py>> {
    ob.filter(|o| !o.is_none())
}

/// One frame's decision, owned, brought back from the frame's thread.
struct Outcome {
    scheme: FrameScheme<'static>,
    resolution: u32,
    resolutions: Vec<u32>,
    frame: Box<Frame>,
    max_error_pixels: f64,
    texels: u64,
    meets_target: bool,
    within_budget: bool,
    switched: bool,
    cut: bool,
}

/// The last frame: its maps and the camera and image height they were measured for.
struct Last {
    frame: Box<Frame>,
    camera: Camera,
    image_height: u32,
}

/// The error-budget controller (the crate's ``shadow_aliasing::plan::Controller``): one per
/// light and camera, ``frame(...)`` every frame. It returns the cheapest set-up (a scheme and one
/// square resolution shared by its maps, or with ``shared_resolution=False`` each map's own)
/// whose measured largest error is at most ``max_error``
/// pixels (within ``budget_texels`` where given), else the least error that fits, and keeps it
/// from frame to frame so that it does not flicker (docs/planning.md, "An error budget per
/// frame").
///
/// The goal: ``max_error`` (pixels of the image per texel), ``budget_texels`` (every map
/// together, the sum of the maps' ``resolution²``), or both. The engine's constraints:
/// ``max_maps`` (default 65, the atlas's most), ``rounding`` ("power_of_two", the default,
/// "whole", or a tile of texels), ``max_resolution`` (default 8192), ``shared_resolution`` (True,
/// the default: every map at one resolution, as Bevy and three.js have it; False: each map sized
/// by its own error), ``candidates`` (scheme names as ``plan`` names them; None:
/// every candidate but the clipmap). Hysteresis: ``patience`` (frames, default 30), ``margin``
/// (default 0.9), ``neighbour_every`` (frames between the checks of a neighbouring scheme,
/// default 4; 0: never), ``retry_every`` (while the last search found nothing that meets
/// ``max_error``, every candidate is searched again every so many frames, default 30; 1: in
/// every frame that misses it); a cut (every candidate searched) when the eye moves more than
/// ``cut_move`` of the far distance (default 0.1), the view turns more than ``cut_turn`` radians
/// (default 15°) or the light more than ``cut_light`` (default 5°). Defaults are the crate's
/// ``ControllerOptions::new``.
#[pyclass(name = "Controller", module = "shadow_aliasing")]
pub struct Controller {
    /// `None` only after Ctrl-C abandoned a frame (rebuilt from `options` at the next one).
    inner: Option<Inner>,
    options: ControllerOptions,
    last: Option<Last>,
}

#[pymethods]
impl Controller {
    #[new]
    #[pyo3(signature = (*, max_error=None, budget_texels=None, max_maps=None, rounding=None,
        max_resolution=None, shared_resolution=true, candidates=None, patience=None,
        margin=None, neighbour_every=None, retry_every=None, cut_move=None, cut_turn=None,
        cut_light=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        max_error: Option<&Any<'_>>,
        budget_texels: Option<&Any<'_>>,
        max_maps: Option<&Any<'_>>,
        rounding: Option<&Any<'_>>,
        max_resolution: Option<&Any<'_>>,
        #[pyo3(from_py_with = shared_resolution_arg)] shared_resolution: bool,
        candidates: Option<&Any<'_>>,
        patience: Option<&Any<'_>>,
        margin: Option<&Any<'_>>,
        neighbour_every: Option<&Any<'_>>,
        retry_every: Option<&Any<'_>>,
        cut_move: Option<&Any<'_>>,
        cut_turn: Option<&Any<'_>>,
        cut_light: Option<&Any<'_>>,
    ) -> PyResult<Self> {
        let max_error = given(max_error)
            .map(|v| args::real("max_error", v))
            .transpose()?;
        let budget = given(budget_texels)
            .map(|v| args::whole("budget_texels", v, u64::MAX))
            .transpose()?;
        let mut o = match (max_error, budget) {
            (Some(e), b) => ControllerOptions {
                max_texels: b,
                ..ControllerOptions::new(e)
            },
            (None, Some(b)) => ControllerOptions::budget(b),
            (None, None) => {
                return Err(PyValueError::new_err(
                    "max_error or budget_texels is needed (or both): max_error=PX for the \
                     fewest texels within PX, budget_texels=N for the least error within N \
                     texels",
                ))
            }
        };
        let u32_arg = |name: &str, v: &Any<'_>| -> PyResult<u32> {
            // At most u32::MAX: the cast is exact.
            args::whole(name, v, u64::from(u32::MAX)).map(|v| v as u32)
        };
        if let Some(v) = given(max_maps) {
            // At most usize::MAX: the cast is exact.
            o.max_maps = args::whole("max_maps", v, usize::MAX as u64)? as usize;
        }
        if let Some(v) = given(rounding) {
            o.rounding = crate::plan::rounding(Some(v))?;
        }
        if let Some(v) = given(max_resolution) {
            o.max_resolution = u32_arg("max_resolution", v)?;
        }
        o.shared_resolution = shared_resolution;
        o.candidates = candidate_list(candidates)?;
        if let Some(v) = given(patience) {
            o.patience = u32_arg("patience", v)?;
        }
        if let Some(v) = given(neighbour_every) {
            o.neighbour_every = u32_arg("neighbour_every", v)?;
        }
        if let Some(v) = given(retry_every) {
            o.retry_every = u32_arg("retry_every", v)?;
        }
        for (slot, name, v) in [
            (&mut o.margin, "margin", margin),
            (&mut o.cut_move, "cut_move", cut_move),
            (&mut o.cut_turn, "cut_turn", cut_turn),
            (&mut o.cut_light, "cut_light", cut_light),
        ] {
            if let Some(v) = given(v) {
                *slot = args::real(name, v)?;
            }
        }
        let inner = Inner::new(o.clone()).map_err(option_err)?;
        Ok(Self {
            inner: Some(inner),
            options: o,
            last: None,
        })
    }

    /// This frame's set-up and maps (the crate's ``Controller::frame``). The scene as ``plan``
    /// takes it: ``view`` (4, 4) world → eye, ``near``, ``far``, ``half_fov``, ``light_dir``,
    /// ``aspect``, ``receivers``, ``casters``, ``depth_range``, ``depth_clamp``;
    /// ``image_height``: errors are in these pixels per texel. ``pcf_radius``, ``clip_depth`` and
    /// ``dtype`` shape the maps as ``frame``'s.
    ///
    /// Returns a dict: ``scheme`` (its name, as ``plan`` names it), ``frame_kwargs``,
    /// ``warp_args`` (as ``plan``'s), ``resolution`` (the largest map's, texels a side: every
    /// map's with a shared resolution), ``resolutions`` ((slots,) int64: each partition slot's
    /// texels a side in slot order, a slot without a map included: ``sa.frame(...,
    /// **frame_kwargs, map_resolutions=resolutions)`` builds the same maps bit for bit with
    /// ``shared_resolution=False``, ``map_resolution=resolution`` with a shared one, except
    /// equal-error cascades between cuts, which keep their cut's planes (``maps["split"]``:
    /// pass them as ``splits=``);
    /// ``resolutions[maps["slot"]]`` is ``maps["resolution"]``),
    /// ``max_error_pixels`` (the largest of the maps' measured errors), ``texels`` (the sum of
    /// the maps' resolution²),
    /// ``meets_target``, ``within_budget``, ``switched``, ``cut``, ``unchanged`` ((m,) bool: each
    /// map bit for bit the one its slot held in the last frame) and ``maps``: ``frame``'s dict
    /// of the maps. The GIL is released while the frame is built; after Ctrl-C the next frame is
    /// a cut.
    #[pyo3(signature = (view, near, far, half_fov, light_dir, *, image_height, aspect=1.0,
        receivers=None, casters=None, depth_range=None, depth_clamp=false, pcf_radius=0.0,
        clip_depth="neg_one_to_one", dtype=None))]
    #[allow(clippy::too_many_arguments)]
    fn frame<'py>(
        &mut self,
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
        #[pyo3(from_py_with = args::pcf_radius)] pcf_radius: f64,
        #[pyo3(from_py_with = args::clip_depth)] clip_depth: &str,
        dtype: Option<&Any<'py>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let (camera, light, receivers, casters, depth_range) = crate::frame::scene(
            view,
            (near, far, half_fov, aspect),
            light_dir,
            [receivers, casters, depth_range],
        )?;
        let depth = crate::builders::clip_depth(clip_depth)?;
        let f32_out = crate::out::dtype(dtype)?;
        // Checked before the frame, which would otherwise be taken and lost with the error.
        if !(pcf_radius.is_finite() && pcf_radius >= 0.0) {
            return Err(PyValueError::new_err(format!(
                "pcf_radius must be finite and ≥ 0 texels (got {pcf_radius}); use 0 for a \
                 single lookup"
            )));
        }
        let mut inner = match self.inner.take() {
            Some(c) => c,
            None => Inner::new(self.options.clone()).map_err(option_err)?,
        };
        // On a thread of its own, Ctrl-C seen while it runs (a cut over thousands of caster
        // boxes takes seconds).
        let (inner, outcome) = crate::interrupt::off_thread(py, move || {
            // The map resolution is the controller's choice: the input's is ignored.
            let input = FrameInput::new(camera, light, 1, image_height).depth_clamp(depth_clamp);
            let input = with_scene(input, receivers.as_deref(), casters.as_deref(), depth_range);
            let outcome = inner.frame(&input).map(|d| Outcome {
                scheme: d.scheme,
                resolution: d.resolution,
                resolutions: d.resolutions.to_vec(),
                frame: Box::new(*d.frame),
                max_error_pixels: d.max_error_pixels,
                texels: d.texels,
                meets_target: d.meets_target,
                within_budget: d.within_budget,
                switched: d.switched,
                cut: d.cut,
            });
            (inner, outcome)
        })?;
        self.inner = Some(inner);
        let o = outcome.map_err(|e| frame_err(e, false))?;
        let d = PyDict::new(py);
        crate::plan::scheme_entries(&d, &o.scheme, image_height)?;
        d.set_item("resolution", o.resolution)?;
        let each: Vec<i64> = o.resolutions.iter().map(|&r| i64::from(r)).collect();
        d.set_item("resolutions", numpy::PyArray1::from_vec(py, each))?;
        d.set_item("max_error_pixels", o.max_error_pixels)?;
        d.set_item("texels", o.texels)?;
        d.set_item("meets_target", o.meets_target)?;
        d.set_item("within_budget", o.within_budget)?;
        d.set_item("switched", o.switched)?;
        d.set_item("cut", o.cut)?;
        let unchanged: Vec<bool> = o.frame.maps().iter().map(|m| m.unchanged()).collect();
        d.set_item("unchanged", numpy::PyArray1::from_vec(py, unchanged))?;
        d.set_item(
            "maps",
            crate::frame::result(py, &o.frame, depth, f32_out, pcf_radius)?,
        )?;
        self.last = Some(Last {
            frame: o.frame,
            camera,
            image_height,
        });
        Ok(d)
    }

    /// Makes the next frame a cut (every candidate searched): for what the controller does not
    /// watch, such as a change of the receivers' or casters' bounds.
    fn cut(&mut self) {
        if let Some(c) = self.inner.as_mut() {
            c.cut();
        }
    }

    /// The error lens of the last frame's maps (the crate's ``FrameMap::error_lens_at``, the WGSL
    /// module's ``sa_error_lens``): at world points ``points`` (..., 3) with surface normals
    /// ``normals`` (the same shape, any length), the size of the map's shadow texel in pixels of
    /// the frame's image on that surface, the surface's projection factor included (a surface at
    /// grazing light gets a large value, whichever way it faces). The map is ``map_index`` (...)
    /// (whole numbers, −1 for none) or, without it, the first map whose square (|x/w|, |y/w| ≤ 1,
    /// w > 0) holds the point: the near cascade where cascades overlap, as ``error_image``
    /// chooses. Returns (...) float64: ``inf`` where the surface is edge-on to the light, ``fill``
    /// (default NaN) where there is no lens: no map, a point not in front of the camera or behind
    /// the map's centre of projection. ``RuntimeError`` before the first frame.
    #[pyo3(signature = (points, normals, *, map_index=None,
        fill=f64::NAN))]
    fn error_lens<'py>(
        &self,
        py: Python<'py>,
        points: &Any<'py>,
        normals: &Any<'py>,
        map_index: Option<&Any<'py>>,
        #[pyo3(from_py_with = args::fill)] fill: f64,
    ) -> PyResult<Any<'py>> {
        let Some(last) = &self.last else {
            return Err(PyRuntimeError::new_err(
                "error_lens needs a frame: call frame(...) first",
            ));
        };
        let (ps, pv) = array("points", points)?;
        if ps.last() != Some(&3) {
            return Err(PyValueError::new_err(format!(
                "points must have shape (..., 3) (got {})",
                fmt_shape(&ps)
            )));
        }
        let (ns, nv) = array("normals", normals)?;
        if ns != ps {
            return Err(PyValueError::new_err(format!(
                "normals must have points' shape {} (got {})",
                fmt_shape(&ps),
                fmt_shape(&ns)
            )));
        }
        let out_shape = ps[..ps.len() - 1].to_vec();
        let n = pv.len() / 3;
        let maps = last.frame.maps();
        let index = match given(map_index) {
            None => None,
            Some(ob) => {
                let (s, v) = array("map_index", ob)?;
                if s != out_shape {
                    return Err(PyValueError::new_err(format!(
                        "map_index must have shape {} (points' shape without its last axis) \
                         (got {})",
                        fmt_shape(&out_shape),
                        fmt_shape(&s)
                    )));
                }
                if let Some((i, k)) = v
                    .iter()
                    .enumerate()
                    .find(|(_, &k)| k.fract() != 0.0 || k < -1.0 || k >= maps.len() as f64)
                {
                    return Err(PyValueError::new_err(format!(
                        "map_index must hold whole numbers from -1 (no map) to {} (got {k} at \
                         index {})",
                        maps.len() as i64 - 1,
                        fmt_index(i, &out_shape)
                    )));
                }
                Some(v)
            }
        };
        for (name, v) in [("points", &pv), ("normals", &nv)] {
            if let Some(i) = v.iter().position(|x| !x.is_finite()) {
                return Err(PyValueError::new_err(format!(
                    "{name} must be finite (got {} at index {})",
                    v[i],
                    fmt_index(i, &ps)
                )));
            }
        }
        if let Some(i) = nv.chunks_exact(3).position(|c| c.iter().all(|&x| x == 0.0)) {
            return Err(PyValueError::new_err(format!(
                "normals must be non-zero vectors (got [0, 0, 0] at index {})",
                fmt_index(i, &out_shape)
            )));
        }
        let world_to_eye = last.camera.world_to_eye();
        let lens = |i: usize| -> f64 {
            let p = DVec3::from_slice(&pv[3 * i..3 * i + 3]);
            let nrm = DVec3::from_slice(&nv[3 * i..3 * i + 3]);
            if world_to_eye.transform_point3(p).z >= 0.0 {
                return fill;
            }
            let in_front = |m: &glam::DMat4| (*m * p.extend(1.0)).w > 0.0;
            let covers = |m: &glam::DMat4| {
                let c = *m * p.extend(1.0);
                c.w > 0.0 && c.x.abs() <= c.w && c.y.abs() <= c.w
            };
            let map = match &index {
                // Whole, in [-1, m): exact.
                Some(ix) if ix[i] < 0.0 => return fill,
                Some(ix) => &maps[ix[i] as usize],
                None => match maps.iter().find(|m| covers(&m.world_to_clip)) {
                    Some(m) => m,
                    None => return fill,
                },
            };
            if !in_front(&map.world_to_clip) {
                return fill;
            }
            // In front of the camera and of the map's centre of projection, finite, with a
            // non-zero normal: the only lens left without a value is a surface edge-on to the
            // light (a texel covers an unbounded strip of it).
            map.error_lens_at(p, nrm, &last.camera, last.image_height)
                .unwrap_or(f64::INFINITY)
        };
        let mut out = Vec::new();
        out.try_reserve_exact(n).map_err(|_| {
            pyo3::exceptions::PyMemoryError::new_err(format!(
                "error_lens: a result of shape {} does not fit in memory",
                fmt_shape(&out_shape)
            ))
        })?;
        // Blocks of about 20 ms, Ctrl-C seen between them.
        in_blocks(py, n, 1 << 14, |r| {
            out.extend(r.map(lens));
            None::<()>
        })?;
        to_python(py, out_shape, out)
    }
}

/// An array argument's shape and values (C order); a number is refused, naming the argument.
fn array(name: &str, ob: &Any<'_>) -> PyResult<(Vec<usize>, Vec<f64>)> {
    match FloatArg::extract(name, ob)? {
        FloatArg::Number(_) => Err(PyValueError::new_err(format!(
            "{name} must be an array (got a number)"
        ))),
        FloatArg::Array(a) => Ok((a.shape().to_vec(), values_of(&a)?)),
    }
}
