"""python/examples run as a researcher runs them (a fresh interpreter, matplotlib's Agg backend),
each writing its figure; their numbers are checked against values derived independently."""
import importlib.util
import os
import subprocess
import sys

import numpy as np
import pytest

import shadow_aliasing as sa

EXAMPLES = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "examples")
SCRIPTS = sorted(f for f in os.listdir(EXAMPLES) if f.endswith(".py"))

pytest.importorskip("matplotlib", reason="the examples draw with matplotlib (pip install matplotlib)")


def _load(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(EXAMPLES, name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_three_uses_have_an_example():
    assert {"camera_stack.py", "cascade_planning.py", "captured_frame.py"} <= set(SCRIPTS)


@pytest.mark.parametrize("script", SCRIPTS)
def test_each_example_runs_and_writes_its_figure(script, tmp_path):
    out = tmp_path / (script[:-3] + ".png")
    run = subprocess.run([sys.executable, os.path.join(EXAMPLES, script), str(out)],
                         capture_output=True, text=True, timeout=600, cwd=tmp_path,
                         env={**os.environ, "MPLBACKEND": "Agg"})
    assert run.returncode == 0, run.stderr[-3000:]
    assert out.stat().st_size > 20_000, out.stat().st_size  # a drawn figure, not an empty one
    assert open(out, "rb").read(8) == b"\x89PNG\r\n\x1a\n"
    assert f"wrote {out}" in run.stdout


def test_camera_stack_is_each_camera_built_alone_and_eq12_overhead():
    ex = _load("camera_stack")
    r = ex.run()
    elevation, half_fov, light = ex.grid()
    for i, j in [(0, 0), (10, 4), (32, 12)]:
        m = sa.warp(ex.NEAR, ex.FAR, float(half_fov[j]), light[i, 0], "lispsm")
        assert r["lispsm"][i, j] == sa.frustum_max(m, light[i, 0], ex.NEAR, ex.FAR,
                                                   float(half_fov[j]))[2]
    # Overhead: S̄ = (f/n − 1)/(2 tan θ) · n′² f/(n (n′ + f − n)²), n′ = n + √(f n) (Eq 12).
    n, f = ex.NEAR, ex.FAR
    npr = n + np.sqrt(f * n)
    eq12 = (f / n - 1) / (2 * np.tan(half_fov)) * npr**2 * f / (n * (npr + f - n) ** 2)
    np.testing.assert_allclose(r["lispsm"][-1], eq12, rtol=1e-9)


def test_cascade_planning_planes_and_equal_errors():
    ex = _load("cascade_planning")
    plans = ex.run()
    # Lloyd 2006 Eq 15: z_i = n (f/n)^(i/k); every plane of a built map is one of them.
    log = ex.NEAR * (ex.FAR / ex.NEAR) ** (np.arange(ex.K + 1) / ex.K)
    planes = np.unique(plans["log (Lloyd 2006 Eq 15)"]["split"])
    assert all(np.isclose(z, log, rtol=1e-12).any() for z in planes), planes
    equal = plans["equal error"]["error"]
    np.testing.assert_allclose(equal, equal.max(), rtol=1e-3)
    # Equal errors are the least largest error of the plans tried.
    assert equal.max() <= min(p["error"].max() for p in plans.values()) * (1 + 1e-9)


def test_captured_frame_normals_from_depth_agree_with_the_true_ones():
    ex = _load("captured_frame")
    cap = ex.synthetic()
    error, jac = ex.run(cap)
    seen = np.isfinite(error)
    assert seen.mean() > 0.3 and np.isnan(jac[~seen]).all()
    # On the ground (away from the boxes and the cascades' edges) the reconstructed normal is
    # the ground's: the error with the true normal given is the same.
    up = np.broadcast_to([0.0, 1.0, 0.0], error.shape + (3,))
    given = sa.error_image(cap["depth"], cap["projection"], cap["view"], cap["shadow_matrix"],
                           map_resolution=1024, normals=up)
    rows = slice(ex.H - 20, ex.H)  # the bottom rows: ground only
    np.testing.assert_allclose(error[rows], given[rows], rtol=1e-6)
