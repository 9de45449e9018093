"""The error contract, argument by argument, for every public function: a wrong type raises
TypeError, a value outside the domain raises ValueError, and either names the argument in
str(e); no bad input gives another exception class (OverflowError, PanicException, …) or a NaN.

The functions and their arguments are read from the module (``inspect.signature`` of each
function in ``__all__``) and their kinds from the stubs (``__init__.pyi``); CALLS gives one valid
call per function, and CONTEXT the other arguments an argument needs to be used at all (``eta``
only with rule "eta", …). A function or argument missing from these tables fails the test."""
import ast
import inspect
import math
import os
import re
import subprocess
import sys

import numpy as np
import pytest

import shadow_aliasing as sa

VIEW = {"near": 1.0, "far": 100.0, "half_fov": 0.5}
LIGHT = [0.3, -1.0, 0.2]
M = sa.warp(1.0, 100.0, 0.5, LIGHT, "lispsm")

# One valid call per function (keyword arguments).
CALLS = {
    "mx": dict(near=1.0, far=100.0, n_prime=11.0, z=10.0),
    "mz": dict(VIEW, n_prime=11.0, z=10.0),
    "max_mx": dict(near=1.0, far=100.0, n_prime=11.0),
    "max_mz": dict(VIEW, n_prime=11.0),
    "storage_factor": dict(VIEW, n_prime=11.0),
    "critical_resolution": dict(VIEW, n_prime=11.0, budget=1e6),
    "n_prime_lispsm": dict(near=1.0, far=100.0),
    "n_prime_from_eta": dict(near=1.0, far=100.0, eta=0.2),
    "eta_from_n_prime": dict(near=1.0, far=100.0, n_prime=11.0),
    "distribution_g": dict(alpha=100.0, n_warp=11.0, z=10.0),
    "subdivided_max_error": dict(alpha=100.0, k=2, eta=0.2, half_fov=0.5),
    "allocate_texels": dict(errors=[1.0, 2.0, 3.0], total=1024.0),
    "z_partition": dict(near=1.0, far=100.0, k=3, scheme="uniform"),
    "scheme_storage_factor": dict(scheme="zp_w", light="overhead", k=3, **VIEW),
    "tilted_mz": dict(VIEW, n_prime=11.0, light_angle=0.7, z=10.0),
    "generalized_n_prime": dict(VIEW, light_angle=0.7, falloff="barroso"),
    "gamma_lim": dict(VIEW),
    "tsm_eta": dict(lambda_=1.0, delta_prime=0.2, xi=-0.6),
    "zhang_eq": dict(VIEW, lambda_=11.0, light_angle=0.7, y=0.5, z=10.0),
    "zhang_ep": dict(VIEW, lambda_=11.0, light_angle=0.7, y=0.5, z=10.0),
    "zhang_eq_local": dict(VIEW, lambda_=11.0, z=10.0),
    "zhang_ep_local": dict(VIEW, lambda_=11.0, z=10.0),
    "warp": dict(VIEW, light_dir=LIGHT),
    "n_prime_for": dict(VIEW, light_dir=LIGHT),
    "cascades": dict(VIEW, light_dir=LIGHT, k=3),
    "faces": dict(VIEW, light_dir=LIGHT),
    "tsm": dict(VIEW, light_dir=LIGHT),
    "frustum_max": dict(VIEW, matrix=M, light_dir=LIGHT),
    "point_error": dict(VIEW, matrix=M, light_dir=LIGHT, point=[0.0, 0.0, -10.0]),
    "frame": dict(VIEW, view=np.eye(4), light_dir=LIGHT),
    "plan": dict(VIEW, view=np.eye(4), light_dir=LIGHT, image_height=1080, max_error=2.0),
    "plan_clipmap": dict(VIEW, view=np.eye(4), light_dir=LIGHT, image_height=1080),
    # A wall at depth 0.9 of a Vulkan-style camera (near 1, far 100), world = eye space.
    "error_image": dict(depth=np.full((3, 4), 0.9), view=np.eye(4), shadow_matrix=M,
                        projection=np.array([[1 / math.tan(0.5), 0, 0, 0], [0, 1 / math.tan(0.5), 0, 0],
                                             [0, 0, -100 / 99, -100 / 99], [0, 0, -1.0, 0]])),
    "sweep_angles": dict(elevations=3, azimuths=4),
    "sweep": dict(VIEW, elevations=3, azimuths=4),
    # The controller's constructor and its methods (on a controller that has run one frame).
    "Controller": dict(max_error=2.0),
    "Controller.frame": dict(VIEW, view=np.eye(4), light_dir=LIGHT, image_height=1080),
    "Controller.error_lens": dict(points=[[0.0, -1.0, -10.0]], normals=[[0.0, 1.0, 0.0]]),
}
# The controller the methods are called on: two schemes, so that a frame takes milliseconds.
CONTROLLER = dict(max_error=2.0, candidates=["single uniform", "cascades log k=3 uniform"])

BEVY = dict(num_cascades=3, minimum_distance=1.0, maximum_distance=80.0,
            first_cascade_far_bound=5.0, overlap_proportion=0.2)

# The arguments an argument needs beside it to be used (so that its own check is reached).
_RULE_ARGS = {"eta": {"rule": "eta", "eta": 0.2}, "focus": {"rule": "tsm", "focus": 30.0},
              "near_hint": {"rule": "filament", "near_hint": 2.0, "far_hint": 50.0},
              "far_hint": {"rule": "filament", "near_hint": 2.0, "far_hint": 50.0},
              "shadow_distance": {"rule": "ogre-ortho", "shadow_distance": 300.0}}
CONTEXT = {
    "error_image": {"map_resolutions": {"map_resolutions": [1024]}},
    "warp": _RULE_ARGS,
    "n_prime_for": _RULE_ARGS,
    "cascades": {"eta": _RULE_ARGS["eta"], "focus": {"rule": "tsm", "focus": 1.0},
                 "lambda_": {"partition": "practical", "lambda_": 0.5}},
    "sweep": {**_RULE_ARGS, "lambda_": {"partition": "practical", "k": 2, "lambda_": 0.5}},
    "tsm": {"xi": {"xi": -0.2}, "iterative": {"iterative": 64}},
    "z_partition": {"lambda_": {"scheme": "practical", "lambda_": 0.5},
                    "light_angle": {"scheme": "adaptive", "light_angle": 1.0, "ratio": 2.0},
                    "ratio": {"scheme": "adaptive", "light_angle": 1.0, "ratio": 2.0}},
    "critical_resolution": {},
    "Controller.frame": {"casters": {"receivers": [[[-5.0, -2.0, -50.0], [5.0, 0.0, -2.0]]],
                                     "casters": [[[-1.0, 0.0, -20.0], [1.0, 3.0, -15.0]]]}},
    "plan": {"budget_texels": {"max_error": None, "budget_texels": 1 << 24},
             "max_maps": {"max_error": None, "budget_texels": 1 << 24, "max_maps": 4}},
    "frame": {**_RULE_ARGS,
              "k": {"scheme": "cascades", "partition": "log", "k": 2},
              "partition": {"scheme": "cascades", "partition": "log", "k": 2},
              "lambda_": {"scheme": "cascades", "partition": "practical", "k": 2, "lambda_": 0.5},
              "overlap": {"scheme": "cascades", "partition": "log", "k": 2, "overlap": 0.1},
              "splits": {"scheme": "cascades", "splits": [1.0, 10.0, 100.0]},
              "fractions": {"scheme": "cascades", "fractions": [0.1]},
              "bevy": {"scheme": "cascades", "bevy": BEVY},
              "xi": {"scheme": "tsm", "xi": -0.2},
              "iterative": {"scheme": "tsm", "iterative": 64},
              "receivers": {"receivers": [[[-5.0, -2.0, -50.0], [5.0, 0.0, -2.0]]]},
              "casters": {"receivers": [[[-5.0, -2.0, -50.0], [5.0, 0.0, -2.0]]],
                          "casters": [[[-1.0, 0.0, -20.0], [1.0, 3.0, -15.0]]]},
              "depth_range": {"depth_range": [2.0, 50.0]},
              "map_resolutions": {"map_resolutions": [512]},
              "lod_bias": {"scheme": "clipmap", "lod_bias": -1.0},
              "levels": {"scheme": "clipmap", "levels": [6, 22]},
              "level_unit": {"scheme": "clipmap", "level_unit": 0.01},
              "page_texels": {"scheme": "clipmap", "page_texels": 128}},
}

# Arguments where NaN is a value: error_image's fill (its default) marks pixels without a
# prediction. Any value is accepted there.
NAN_VALID = {("error_image", "fill"), ("Controller.error_lens", "fill")}
# Whole numbers whose domain reaches 2**40: plan's texel budget (a count of texels, not of maps
# or cells). Such a value is accepted or refused naming the argument.
HUGE_INT_VALID = {("plan", "budget_texels"), ("plan_clipmap", "pool"),
                  ("Controller", "budget_texels")}

RAGGED = [[1.0], [1.0, 2.0]]
# The crate's errors about a combination of valid values rather than one argument (a frustum
# whose map cannot be represented in f64, a focus no trapezoid reaches): they name no argument.
COMBINATION = ("degenerate geometry:", "no solution:", "no closed form:")


def _stubs():
    path = os.path.join(os.path.dirname(sa.__file__), "__init__.pyi")
    tree = ast.parse(open(path, encoding="utf-8").read())
    out = {}
    for f in tree.body:
        if isinstance(f, ast.FunctionDef):
            args = f.args.args + f.args.kwonlyargs
            out[f.name] = {a.arg: ast.unparse(a.annotation) for a in args}
        if isinstance(f, ast.ClassDef):
            # A class's __new__ under the class's name, its methods as "Class.method"; without
            # cls and self.
            for m in f.body:
                if isinstance(m, ast.FunctionDef):
                    args = m.args.args[1:] + m.args.kwonlyargs
                    name = f.name if m.name == "__new__" else f"{f.name}.{m.name}"
                    out[name] = {a.arg: ast.unparse(a.annotation) for a in args if a.annotation}
    return out


STUBS = _stubs()
METHODS = ["Controller.frame", "Controller.error_lens"]
FUNCTIONS = sorted([n for n in sa.__all__ if callable(getattr(sa, n))] + METHODS)


def _target(fn):
    """The public function, or the method of a fresh controller (after one frame for its
    ``error_lens``)."""
    if fn == "Controller.frame":
        return sa.Controller(**CONTROLLER).frame
    if fn == "Controller.error_lens":
        c = sa.Controller(**CONTROLLER)
        c.frame(**CALLS["Controller.frame"])
        return c.error_lens
    return getattr(sa, fn)


def _kind(annotation):
    """'str', 'int', 'float' (one number), 'array' (anything numpy.asarray takes) or 'out' (an
    existing array that receives the result)."""
    if annotation == "OutArray":
        return "out"
    if annotation == "DType":
        return "str"
    if annotation == "Optional[Sequence[str]]":
        return "names"
    if annotation in ("bool", "Literal[True]", "Literal[False]"):
        return "bool"
    if "BevySplits" in annotation:
        return "dict"
    if "Literal" in annotation or "str" in annotation or annotation == "ClipDepth":
        return "str"
    if "int" in annotation:
        return "int"
    if annotation in ("float", "Optional[float]"):
        return "float"
    return "array"


def _optional(fn, arg):
    p = inspect.signature(_target(fn)).parameters[arg]
    return p.default is None


def _out_cases(fn):
    """``out``: anything but a writeable ndarray of the result's shape and dtype is refused."""
    right = np.asarray(getattr(sa, fn)(**CALLS[fn]))
    frozen = np.zeros_like(right)
    frozen.flags.writeable = False
    yield from [("a str", "abc", TypeError), ("a ragged list", RAGGED, TypeError),
                ("a float", 1.5, TypeError), ("a list", right.tolist(), TypeError),
                ("float32", right.astype(np.float32), TypeError),
                ("int64", right.astype(np.int64), TypeError),
                ("a wrong shape", np.zeros(right.shape + (2,)), ValueError),
                ("read-only", frozen, ValueError)]


def _cases():
    for fn in FUNCTIONS:
        for arg in inspect.signature(_target(fn)).parameters:
            kind = _kind(STUBS[fn][arg])
            if kind == "out":
                for label, v, cls in _out_cases(fn):
                    yield pytest.param(fn, arg, v, cls, id=f"{fn}-{arg}-{label}")
                continue
            wrong = [("a str", "abc"), ("a ragged list", RAGGED)] if kind != "str" else \
                [("a float", 1.5), ("a list", ["uniform"])]
            if kind == "names":
                wrong = [("a str", "abc"), ("a float", 1.5), ("a list of floats", [1.5])]
            if kind in ("bool", "dict"):
                wrong.append(("a float", 1.5))
            if not _optional(fn, arg):
                wrong.append(("None", None))
            if kind == "float":
                wrong.append(("an array", np.array([1.0, 2.0])))
            for label, v in wrong:
                yield pytest.param(fn, arg, v, TypeError, id=f"{fn}-{arg}-{label}")
            if kind == "bool":
                bad = []
            elif kind == "dict":
                bad = [("empty", {}, True), ("unknown key", {**BEVY, "other": 1.0}, True)]
                bad += [(f"{key}={v}", {**BEVY, key: v}, True)
                        for key in BEVY for v in (math.nan, -1.0)]
                for key in BEVY:
                    yield pytest.param(fn, arg, {**BEVY, key: "abc"}, TypeError,
                                       id=f"{fn}-{arg}-{key}=abc")
            elif kind == "str":
                bad = [("unknown", "no-such-choice", True)]
            elif kind == "names":
                bad = [("unknown", ["no-such-choice"], True), ("empty", [], True)]
            elif kind == "int":
                bad = [("-1", -1, True), ("2**40", 2**40, (fn, arg) not in HUGE_INT_VALID),
                       ("2**70", 2**70, True), ("0", 0, False)]
            else:
                bad = [("nan", math.nan, True), ("-1", -1, False), ("2**40", 2**40, False),
                       ("inf", math.inf, False), ("-inf", -math.inf, False),
                       ("10**400", 10**400, False)]
                if kind == "array":
                    bad.append(("[1, nan]", [1.0, math.nan], True))
                if (fn, arg) in NAN_VALID:
                    bad = [(label, v, False) for label, v, _ in bad]
            for label, v, must in bad:
                yield pytest.param(fn, arg, v, ValueError if must else None,
                                   id=f"{fn}-{arg}-{label}")


def test_tables_cover_every_function_and_the_stubs_match():
    assert sorted(CALLS) == FUNCTIONS
    for fn in FUNCTIONS:
        params = list(inspect.signature(_target(fn)).parameters)
        assert list(STUBS[fn]) == params, fn
        required = [a for a, p in inspect.signature(_target(fn)).parameters.items()
                    if p.default is inspect.Parameter.empty]
        assert set(required) <= set(CALLS[fn]), fn
        for arg in CONTEXT.get(fn, {}):
            assert arg in params, (fn, arg)


def _names(arg):
    """The argument's name as messages spell it (the eval contract's ``lambda`` for ``lambda_``)."""
    return {arg, arg.rstrip("_")}


def _named(message, names):
    """Whether one of `names` is a word of `message` (``k`` in "k must …", not in "like")."""
    return any(re.search(rf"(?<![\w.]){re.escape(n)}(?!\w)", message) for n in names)


@pytest.mark.parametrize("fn, arg, value, expected", list(_cases()))
def test_every_argument_of_every_function(fn, arg, value, expected):
    kwargs = {**CALLS[fn], **CONTEXT.get(fn, {}).get(arg, {})}
    f = _target(fn)
    f(**kwargs)  # the call is valid before the argument is spoiled
    kwargs[arg] = value
    try:
        out = f(**kwargs)
    except (TypeError, ValueError) as e:
        # The class the contract gives: TypeError for a wrong type, ValueError for a value.
        want = expected or ValueError
        assert type(e) is want, f"{fn}({arg}={value!r}): {type(e).__name__}: {e}"
        if expected is None:
            # A value inside its own domain that the rest of the call cannot take: the crate
            # names the combination, or another argument of it (a matrix measured over a frustum
            # it was not built for).
            others = {n for p in inspect.signature(f).parameters for n in _names(p)}
            if str(e).startswith(COMBINATION) or _named(str(e), others):
                return
        assert _named(str(e), _names(arg)), \
            f"{fn}({arg}={value!r}): {arg!r} not in str(e): {e}"
        return
    assert expected is None, f"{fn}({arg}={value!r}) returned {out!r}, expected {expected}"
    # Accepted: the value lies in the domain, and the answer holds no NaN.
    values = out[0] if fn == "faces" else out
    if fn == "Controller":
        return  # a controller, no numbers
    if fn == "Controller.frame":
        out = {**out, **out.pop("maps")}
    if fn in ("frame", "plan", "plan_clipmap", "Controller.frame"):
        values = np.concatenate([np.ravel(v).astype(np.float64) for v in out.values()
                                 if isinstance(v, (np.ndarray, float))
                                 and np.asarray(v).dtype.kind in "fiu"])
        if kwargs.get("measure") is False:  # unmeasured errors are +inf, never NaN
            values = values[np.isfinite(values)]
    if fn == "Controller.error_lens" and not (arg == "fill" and not math.isnan(value)):
        values = values[~np.isnan(values)]  # fill (default NaN) where there is no lens
        assert values.size or arg == "map_index", (fn, arg, value, out)
    if fn == "error_image" and not (arg == "fill" and not math.isnan(value)):
        values = values[~np.isnan(values)]  # fill (default NaN) where there is no prediction
        assert values.size or arg in ("map_index", "background"), (fn, arg, value, out)
    assert not np.isnan(np.asarray(values, dtype=np.float64)).any(), (fn, arg, value, out)


# Shapes with more elements than memory holds, which cost NumPy nothing to describe: a broadcast
# view of one value (2**40 elements), and two arguments whose broadcast has 2**80. Each must raise
# MemoryError, as NumPy's own allocations do; before, the first aborted the interpreter
# ("memory allocation of 8796093022208 bytes failed") and the second raised an "internal error".
# In a fresh interpreter whose address space is capped at 64 GiB, so that no allocation of that
# size can succeed whatever the machine's overcommit policy.
HUGE = r"""
import resource, sys
resource.setrlimit(resource.RLIMIT_AS, (64 << 30, 64 << 30))
import numpy as np
import shadow_aliasing as sa
one = np.broadcast_to(np.ones(1), (2**40,))
wide = np.broadcast_to(np.ones((1, 1)), (2**40, 1))
tall = np.broadcast_to(np.full((1, 1), 10.0), (1, 2**40))
calls = {
    "closed form": lambda: sa.n_prime_lispsm(one, 1e3),
    "broadcast of two": lambda: sa.n_prime_lispsm(wide, tall),
    "critical_resolution": lambda: sa.critical_resolution(one, 1e3, 0.5, 11.0, 1e6),
    "point_error": lambda: sa.point_error(np.eye(4), [0.0, -1.0, 0.0],
                                          np.broadcast_to(np.ones(3), (2**40, 3)), 1.0, 10.0, 0.5),
    "frustum_max": lambda: sa.frustum_max(np.broadcast_to(np.eye(4), (2**40, 4, 4)),
                                          [0.0, -1.0, 0.0], 1.0, 10.0, 0.5),
    "allocate_texels": lambda: sa.allocate_texels(one, 100.0),
}
for name, call in calls.items():
    try:
        call()
        print(name, "returned")
    except BaseException as e:
        print(name, type(e).__name__, str(e)[:120])
"""


def test_shapes_beyond_memory_raise_memory_error(tmp_path):
    run = subprocess.run([sys.executable, "-c", HUGE], capture_output=True, text=True,
                         timeout=300, cwd=tmp_path)
    assert run.returncode == 0, run.stderr[-2000:]
    lines = run.stdout.strip().splitlines()
    assert len(lines) == 6, run.stdout
    for line in lines:
        assert " MemoryError " in line and "does not fit in memory" in line, line
