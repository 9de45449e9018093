"""sa.plan, the crate's planner: its choice against a brute force over the candidates through
sa.frame (the texels of a target by hand), the plan's scheme rebuilt by sa.frame from
``frame_kwargs`` with the planned error, the command line's ``plan --json``, monotonicity,
determinism, and the argument checks."""
import json
import math
import os
import subprocess

import numpy as np
import pytest

import shadow_aliasing as sa

VIEW = np.eye(4)
CAM = dict(near=1.0, far=400.0, half_fov=0.5236)
LIGHT = [0.3, -0.8, -0.4]
GROUND = [[-50.0, -5.0, -100.0], [50.0, 0.0, 0.0]]
TOWER = [[-10.0, 0.0, -60.0], [10.0, 20.0, -40.0]]
SCENE = dict(receivers=[GROUND], casters=[GROUND, TOWER])
H = 1080


def _plan(**kw):
    args = dict(SCENE, image_height=H)
    args.update(kw)
    return sa.plan(VIEW, CAM["near"], CAM["far"], CAM["half_fov"], LIGHT, **args)


def _by_hand(maps, target):
    """Whole texels for the target: each axis ceil(M H / E); and the error they give."""
    texels, worst = 0, 0.0
    for mx, mz in maps:
        rs, rt = math.ceil(mx * H / target), math.ceil(mz * H / target)
        texels += rs * rt
        worst = max(worst, mx * H / rs, mz * H / rt)
    return texels, worst


def test_target_choice_is_the_brute_force_over_sa_frame():
    p = _plan(max_error=1.0)
    assert len(p["candidates"]) == 129
    best = None
    for i, c in enumerate(p["candidates"]):
        try:
            f = sa.frame(VIEW, CAM["near"], CAM["far"], CAM["half_fov"], LIGHT, **SCENE,
                         image_height=H, **c["frame_kwargs"])
        except ValueError:
            assert "error" in c, c["scheme"]
            continue
        maps = list(zip(f["max_mx"], f["max_mz"]))
        if c["frame_kwargs"]["scheme"] == "clipmap":
            # Levels of 16384 texels, its LOD bias chosen for the target; texels are pages.
            e = max(max(mx, mz) * H / 16384 for mx, mz in maps)
            assert c["max_error_pixels"] == pytest.approx(e, rel=1e-12) and e <= 1.0
            t = c["texels"]
            assert t % (128 * 128) == 0 and c["maps"] == len(maps)
            if best is None or (t, e) < best[:2]:
                best = (t, e, i)
            continue
        t, e = _by_hand(maps, 1.0)
        assert (c["texels"], c["maps"]) == (t, len(maps)), c["scheme"]
        assert c["max_error_pixels"] == pytest.approx(e, rel=1e-12)
        if best is None or (t, e) < best[:2]:
            best = (t, e, i)
    t, e, i = best
    assert p["scheme"] == p["candidates"][i]["scheme"]
    assert p["texels"] == t
    assert p["max_error_pixels"] == pytest.approx(e, rel=1e-12)


def test_the_plans_scheme_rebuilt_by_sa_frame_gives_its_error():
    for kw in [dict(max_error=0.5), dict(budget_texels=1 << 24, max_maps=4),
               dict(max_error=2.0, rounding="power_of_two")]:
        p = _plan(**kw)
        f = sa.frame(VIEW, CAM["near"], CAM["far"], CAM["half_fov"], LIGHT, **SCENE,
                     image_height=H, **p["frame_kwargs"])
        res = p["resolutions"]
        assert res.shape == (len(f["max_mx"]), 2)
        err = max(max(mx * H / rs, mz * H / rt)
                  for mx, mz, (rs, rt) in zip(f["max_mx"], f["max_mz"], res))
        assert err == pytest.approx(p["max_error_pixels"], rel=1e-12)
        if p["frame_kwargs"]["scheme"] == "clipmap":
            assert p["texels"] % (128 * 128) == 0  # pages, not whole levels
        else:
            assert int(np.prod(res, axis=1).sum()) == p["texels"]
        if "rounding" in kw:
            assert all(v & (v - 1) == 0 for v in res.ravel())


def test_matches_the_command_line():
    exe = os.environ.get("SHADOW_ALIASING_BIN")
    if not exe:
        pytest.skip("SHADOW_ALIASING_BIN not set (.ci/run sets it to the built command line)")
    box = lambda b: ",".join(repr(float(v)) for v in (*b[0], *b[1]))  # noqa: E731
    out = subprocess.run(
        [exe, "plan", "--near", "1", "--far", "400", "--half-fov", "0.5236", "--light-dir",
         "0.3,-0.8,-0.4", "--receivers=" + box(GROUND), "--casters=" + box(GROUND),
         "--casters=" + box(TOWER), "--image-height", str(H), "--max-error", "1", "--json"],
        check=True, capture_output=True, text=True).stdout
    cli = json.loads(out)
    p = _plan(max_error=1.0)
    assert cli["warp_args"] == p["warp_args"]
    assert cli["texels"] == p["texels"]
    assert cli["max_error_pixels"] == p["max_error_pixels"]
    assert cli["resolutions"] == p["resolutions"].tolist()


def test_monotone_and_deterministic():
    last = None
    for e in [0.5, 1.0, 2.0, 4.0]:
        t = _plan(max_error=e)["texels"]
        assert last is None or t <= last
        last = t
    a, b = _plan(max_error=1.0), _plan(max_error=1.0)
    assert a["candidates"] == b["candidates"]
    assert a["resolutions"].tolist() == b["resolutions"].tolist()


@pytest.mark.parametrize("kw, exc, name", [
    (dict(), ValueError, "max_error"),
    (dict(max_error=1.0, budget_texels=10), ValueError, "max_error"),
    (dict(max_error=1.0, max_maps=2), ValueError, "max_maps"),
    (dict(max_error=0.0), ValueError, "max_error"),
    (dict(max_error="1"), TypeError, "max_error"),
    (dict(budget_texels=0), ValueError, "budget_texels"),
    (dict(budget_texels=1.5), TypeError, "budget_texels"),
    (dict(budget_texels=100, max_maps=0), ValueError, "max_maps"),
    (dict(max_error=1.0, rounding="odd"), ValueError, "rounding"),
    (dict(max_error=1.0, rounding=0), ValueError, "rounding"),
    (dict(max_error=1.0, rounding=1.5), TypeError, "rounding"),
    (dict(max_error=1.0, image_height=0), ValueError, "image_height"),
    (dict(max_error=1.0, depth_range=(5.0, 2.0)), ValueError, "depth_range"),
])
def test_bad_arguments_are_named(kw, exc, name):
    with pytest.raises(exc, match=name):
        _plan(**kw)


def test_bad_light_is_named():
    with pytest.raises(ValueError, match="light_dir"):
        sa.plan(VIEW, 1.0, 400.0, 0.5236, [0.0, 0.0, 0.0], image_height=H, max_error=1.0)


def _clipmap(**kw):
    args = dict(SCENE, image_height=H)
    args.update(kw)
    return sa.plan_clipmap(VIEW, CAM["near"], CAM["far"], CAM["half_fov"], LIGHT, **args)


def test_plan_clipmap_levels_by_hand_and_rebuilt_by_sa_frame():
    """Each level's error bound is t H / (2 z tan θ) at its depths' ends with t = 2 · 2^(i+2)
    unit / R (level i's square has half-width 2^(i+2) units, twice the radius it covers), by
    hand; sa.frame with its frame_kwargs builds
    the same levels with the same largest error."""
    t = math.tan(CAM["half_fov"])
    for kw in [dict(), dict(lod_bias=-1.5), dict(pool=2000), dict(max_error=2.0)]:
        p = _clipmap(**kw)
        levels = p["levels"]
        assert [l["level"] for l in levels] == list(range(p["first_level"], p["last_level"] + 1))
        assert p["pages"] == sum(l["pages"] for l in levels)
        for l in levels:
            texel = 2 * 2.0 ** (l["level"] + 2) * 0.01 / 16384
            assert l["texel"] == pytest.approx(texel, rel=1e-15)
            a, b = l["depths"]
            assert l["error_bound"] == pytest.approx(
                (texel * H / (2 * b * t), texel * H / (2 * a * t)), rel=1e-12)
        f = sa.frame(VIEW, CAM["near"], CAM["far"], CAM["half_fov"], LIGHT, **SCENE,
                     image_height=H, **p["frame_kwargs"])
        assert [v for v in f["clipmap_level"]] == [l["level"] for l in levels
                                                   if l["max_error_pixels"] is not None]
        assert max(f["max_error_pixels"]) == p["max_error_pixels"]
        if "pool" in kw:
            assert p["pages"] <= kw["pool"]
        if "max_error" in kw:
            assert p["max_error_pixels"] <= kw["max_error"]
        if "lod_bias" in kw:
            assert p["lod_bias"] == kw["lod_bias"]


@pytest.mark.parametrize("kw, exc, name", [
    (dict(pool=10, max_error=1.0), ValueError, "max_error"),
    (dict(lod_bias=-1.0, pool=10), ValueError, "pool"),
    (dict(pool=0), ValueError, "pool"),
    (dict(max_error=-1.0), ValueError, "max_error"),
    (dict(max_error=0.01), ValueError, "max_error"),
    (dict(levels=(6, 8)), ValueError, "levels"),
    (dict(levels=3), ValueError, "levels"),
    (dict(levels="ab"), TypeError, "levels"),
    (dict(page_texels=100), ValueError, "page_texels"),
    (dict(lod_bias="x"), TypeError, "lod_bias"),
])
def test_plan_clipmap_bad_arguments_name_themselves(kw, exc, name):
    with pytest.raises(exc) as e:
        _clipmap(**kw)
    assert name in str(e.value), str(e.value)
