"""A resolution per map: sa.frame's ``map_resolutions`` and sa.Controller's
``shared_resolution=False``. Each map's error is measured again from its own matrix by central
differences in NumPy (test_controller.audit, never the crate's measurement) and scaled by its
own resolution; the controller's choice on a cut is checked against allocations made here by
hand from those measurements; the decision's ``resolutions`` rebuild its maps bit for bit; bad
input is refused by name."""
import math

import numpy as np
import pytest

import shadow_aliasing as sa
from test_controller import (ALLOWED, CAP, FAR, FRAMES, H, HALF_FOV, LIGHT, NEAR, SCENE, TARGET,
                             TILE, audit, controller, step, walk_view)

PRACTICAL = dict(scheme="cascades", rule="uniform", partition="practical", k=3, lambda_=0.5)


def products(maps):
    """Each map's largest error over its body at one texel a side (pixels × texels), from its
    matrix alone."""
    return np.array([audit(m, maps["light_dir_eye"], body, math.tan(HALF_FOV)).max() * H
                     for m, body in zip(maps["eye_to_clip"], maps["body"])])


def build(view, kw, **more):
    return sa.frame(view, NEAR, FAR, HALF_FOV, LIGHT, **SCENE, **kw, **more)


@pytest.mark.parametrize("kw, each", [
    (PRACTICAL, [2048, 512, 128]),
    (dict(scheme="stable", partition="log", k=3), [256, 1024, 4096]),
    (dict(scheme="single", rule="lispsm"), [700]),
    (dict(scheme="cascades", rule="uniform", partition="equal_error", k=3), [2048, 1024, 512]),
], ids=["cascades", "stable", "single", "equal_error"])
def test_each_map_has_its_own_resolution_and_its_error_scales_with_it(kw, each):
    f = build(walk_view(60), kw, map_resolutions=each)
    slots = f["slot"]
    assert 0 < len(slots) <= len(each)
    assert f["resolution"].dtype == np.int64
    assert np.array_equal(f["resolution"], np.array(each)[slots])
    # Each map's error, measured from its matrix alone, over its own resolution.
    fd = products(f) / f["resolution"]
    np.testing.assert_allclose(f["max_error_pixels"], fd, rtol=1e-5)


def least_tiles(view, kw):
    """Each map of scheme ``kw`` at the least multiple of TILE that meets TARGET, by hand: sized
    from its error at the cap, measured from its matrix, then raised a tile at a time while its
    own measurement misses (a stable map's snap moves a little with its resolution). The slot
    resolutions and the maps' texels, or None where a map needs more than the cap or the scheme
    more than 4 maps."""
    f = build(view, kw, map_resolution=CAP)
    if not 0 < len(f["slot"]) <= 4:
        return None
    slots = kw.get("k", 1)
    each = np.full(slots, TILE)
    each[f["slot"]] = TILE * np.ceil(products(f) / TARGET / TILE)
    while each.max() <= CAP:
        g = build(view, kw, map_resolutions=each.tolist())
        over = products(g) / each[g["slot"]] > TARGET
        if not over.any():
            return each, int((each[g["slot"]] ** 2).sum())
        each[g["slot"][over]] += TILE
    return None


def test_a_cut_gives_each_map_the_least_resolution_of_the_cheapest_scheme():
    view = walk_view(60)
    d = step(controller(shared_resolution=False), view)
    assert d["cut"] and d["meets_target"]
    by_hand = {name: least_tiles(view, kw) for name, kw in ALLOWED.items()}
    name, (each, texels) = min(((n, b) for n, b in by_hand.items() if b is not None),
                               key=lambda nb: nb[1][1])
    assert d["scheme"] == name
    assert d["texels"] == texels
    maps = d["maps"]
    assert np.array_equal(d["resolutions"][maps["slot"]], each[maps["slot"]])
    # Less than one shared resolution, which must be the largest map's for every map.
    shared = step(controller(), view)
    assert shared["meets_target"] and d["texels"] < shared["texels"]


def test_the_walk_with_a_resolution_per_map():
    """The scripted walk, with a cut every 40 frames: each map's own error, audited, within the
    target where the frame says so; texels the sum of the maps' squares; the decision's
    resolutions rebuilding its maps bit for bit; few switches; on each cut no map with a tile to
    spare."""
    c = controller(shared_resolution=False)
    shared = controller()
    switches = met = texels = shared_texels = 0
    frames = range(FRAMES)
    for i in frames:
        view = walk_view(i)
        if i % 40 == 0 and i > 0:
            c.cut()
        d = step(c, view)
        shared_texels += step(shared, view)["texels"]
        assert d["cut"] == (i % 40 == 0), i
        switches += d["switched"]
        maps = d["maps"]
        r = d["resolutions"]
        assert r.dtype == np.int64 and len(r) == ALLOWED[d["scheme"]].get("k", 1), i
        assert np.all(r % TILE == 0) and np.all((TILE <= r) & (r <= CAP)), (i, r)
        assert np.array_equal(maps["resolution"], r[maps["slot"]]), i
        assert d["resolution"] == maps["resolution"].max(), i
        assert d["texels"] == int((maps["resolution"] ** 2).sum()), i
        texels += d["texels"]
        fd = products(maps) / maps["resolution"]
        np.testing.assert_allclose(maps["max_error_pixels"], fd, rtol=1e-5, err_msg=str(i))
        assert d["max_error_pixels"] == maps["max_error_pixels"].max(), i
        assert not d["meets_target"] or fd.max() <= TARGET * (1 + 1e-5), (i, fd)
        met += d["meets_target"]
        # sa.frame with the decision's scheme and resolutions: the same maps, bit for bit.
        again = build(view, d["frame_kwargs"], map_resolutions=d["resolutions"])
        for key in ("slot", "resolution", "world_to_clip", "max_error_pixels"):
            assert np.array_equal(again[key], maps[key]), (i, key)
        if d["cut"] and d["meets_target"]:
            # No map meets the target a tile lower (measured from the lowered map's matrix).
            for j, slot in enumerate(maps["slot"]):
                if r[slot] == TILE:
                    continue
                lower = r.copy()
                lower[slot] -= TILE
                g = build(view, d["frame_kwargs"], map_resolutions=lower)
                k = list(g["slot"]).index(slot)
                assert products(g)[k] / lower[slot] > TARGET, (i, slot, lower)
    assert met >= len(frames) // 2, met
    # 22 here, 5 of them at the cuts (a fresh search sizes each map again).
    assert switches <= FRAMES // 10, switches
    # A resolution per map spends fewer texels than one shared by every map (0.41 here).
    assert texels < 0.5 * shared_texels, (texels, shared_texels)


def test_a_shared_resolution_gives_every_slot_the_same():
    d = step(controller(candidates=["stable log k=3"]), walk_view(60))
    assert np.array_equal(d["resolutions"], [d["resolution"]] * 3)
    assert np.array_equal(d["maps"]["resolution"], [d["resolution"]] * len(d["maps"]["slot"]))
    again = build(walk_view(60), d["frame_kwargs"], map_resolution=d["resolution"])
    assert np.array_equal(again["world_to_clip"], d["maps"]["world_to_clip"])


@pytest.mark.parametrize("kw, exc, name", [
    (dict(map_resolutions="512"), TypeError, r"map_resolutions"),
    (dict(map_resolutions=[512, "512", 512]), TypeError, r"map_resolutions"),
    (dict(map_resolutions=512), ValueError, r"map_resolutions must be a one-dimensional array"),
    (dict(map_resolutions=np.array([[512, 512, 512]])), ValueError,
     r"map_resolutions must be a one-dimensional array of numbers \(got shape \(1, 3\)\)"),
    (dict(map_resolutions=[512, 512.5, 512]), ValueError,
     r"map_resolutions must hold whole numbers .* \(got 512.5 at index 1\)"),
    (dict(map_resolutions=[512, 512, -4]), ValueError, r"map_resolutions .* at index 2"),
    (dict(map_resolutions=[512, 512, 2**32]), ValueError, r"map_resolutions .* at index 2"),
    (dict(map_resolutions=[512, math.nan, 512]), ValueError, r"map_resolutions .* at index 1"),
    (dict(map_resolutions=[512, 2, 512]), ValueError,
     r"map_resolutions must hold resolutions of at least 3"),
    (dict(map_resolutions=[512, 512]), ValueError, r"map_resolutions has 2 entries"),
    (dict(map_resolutions=[]), ValueError, r"map_resolutions has 0 entries"),
])
def test_bad_map_resolutions_are_refused_by_name(kw, exc, name):
    args = dict(PRACTICAL)
    args.update(kw)
    with pytest.raises(exc, match="^" + name):
        build(walk_view(60), args)


def test_a_clipmap_refuses_map_resolutions():
    with pytest.raises(ValueError, match="^map_resolutions cannot be used with a clipmap"):
        build(walk_view(60), dict(scheme="clipmap"), map_resolutions=[512] * 17)


def test_numpy_resolutions_are_taken():
    a = build(walk_view(60), PRACTICAL, map_resolutions=np.array([1024, 512, 256], np.uint16))
    b = build(walk_view(60), PRACTICAL, map_resolutions=(1024, 512, 256))
    assert np.array_equal(a["resolution"], [1024, 512, 256])
    assert np.array_equal(a["max_error_pixels"], b["max_error_pixels"])


@pytest.mark.parametrize("kw, exc, name", [
    (dict(shared_resolution=1), TypeError, "shared_resolution must be a bool"),
    (dict(shared_resolution=None), TypeError, "shared_resolution must be a bool"),
    (dict(shared_resolution="no"), TypeError, "shared_resolution must be a bool"),
])
def test_bad_shared_resolution_is_refused_by_name(kw, exc, name):
    with pytest.raises(exc, match="^" + name):
        controller(**kw)


def test_error_image_takes_each_maps_resolution():
    """sa.error_image with ``map_resolutions=frame(...)["resolution"]``: each pixel's error, at
    the map that covers it, against test_error_image's ray cast and central differences of
    pixel → texel at that map's own resolution."""
    from test_error_image import (FAR as FAR_I, H as HI, NEAR as NEAR_I, THETA, W as WI,
                                  ground_depth, look_at, perspective, pixel_ndc, texel_of_pixel)
    aspect = WI / HI
    proj = perspective(NEAR_I, FAR_I, THETA, aspect)
    view = look_at([0.0, 3.0, 0.0], [0.0, 0.0, -30.0])
    each = [2048, 512, 128]
    f = sa.frame(view, NEAR_I, FAR_I, THETA, [0.3, -1.0, 0.2], aspect=aspect, scheme="cascades",
                 k=3, partition="log", receivers=[[[-300, -1, -300], [300, 0, 300]]],
                 map_resolutions=each)
    ms, res = f["world_to_clip"], f["resolution"]
    assert np.array_equal(res, np.array(each)[f["slot"]])
    depth, ok = ground_depth(proj, view, HI, WI)
    err = sa.error_image(depth, proj, view, ms, map_resolutions=res)
    # The first map whose square holds each pixel's point, found here.
    xs, ys = pixel_ndc(HI, WI)
    c = np.stack([xs, ys, depth, np.ones_like(xs)], -1) @ np.linalg.inv(proj @ view).T
    p = np.concatenate([c[..., :3] / c[..., 3:], np.ones((HI, WI, 1))], -1)
    lc = np.einsum("mij,hwj->mhwi", ms, p)
    inside = (lc[..., 3] > 0) & (np.abs(lc[..., 0]) <= lc[..., 3]) & (np.abs(lc[..., 1]) <= lc[..., 3])
    first = np.where(inside.any(0), inside.argmax(0), -1)
    used = set()
    e = 1e-3
    for y, x in zip(*np.nonzero(ok & (first >= 0))):
        k = first[y, x]
        tex = texel_of_pixel(proj, view, ms[k], res[k])
        u, v = x + 0.5, y + 0.5
        j = np.column_stack([(tex(u + e, v) - tex(u - e, v)) / (2 * e),
                             (tex(u, v + e) - tex(u, v - e)) / (2 * e)])
        assert err[y, x] == pytest.approx(1 / np.linalg.svd(j, compute_uv=False)[-1], rel=1e-5)
        used.add(int(k))
    assert len(used) >= 2, used


@pytest.mark.parametrize("value, name", [
    ([1024, 1024], r"map_resolutions must hold one resolution per shadow matrix, 3 \(got 2\)"),
    ([1024, 0, 1024], r"map_resolutions must hold resolutions of at least 1 \(got 0 at index 1\)"),
    ([1024, 1.5, 1024], r"map_resolutions must hold whole numbers"),
    ("1024", r"map_resolutions"),
])
def test_error_image_refuses_bad_map_resolutions_by_name(value, name):
    f = build(walk_view(60), PRACTICAL)
    exc = TypeError if isinstance(value, str) else ValueError
    with pytest.raises(exc, match="^" + name):
        sa.error_image(np.full((4, 4), 0.5), np.eye(4), np.eye(4), f["world_to_clip"],
                       map_resolutions=value)
