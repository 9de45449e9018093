"""sa.frame, the crate's world-space frame API: bit for bit against the command line's
``warp --json`` with a scene (the same frame API, camera at the world origin), against the
frustum-only builders where the module docs promise equality, and the argument checks."""
import json
import math
import os
import subprocess

import numpy as np
import pytest

import shadow_aliasing as sa

CAM = dict(near=1.0, far=100.0, half_fov=0.5)
LIGHT = [0.3, -1.0, 0.2]
GROUND = [[-50.0, -2.0, -100.0], [50.0, 0.0, -1.0]]
CRATE = [[-3.0, 0.0, -20.0], [3.0, 6.0, -14.0]]


def _cli():
    exe = os.environ.get("SHADOW_ALIASING_BIN")
    if not exe:
        pytest.skip("SHADOW_ALIASING_BIN not set (.ci/run sets it to the built command line)")
    return exe


def _box_flag(b):
    return ",".join(repr(float(v)) for v in (*b[0], *b[1]))


# (command-line flags beyond the camera and light, sa.frame's keyword arguments)
CASES = [
    (["--warp", "lispsm", "--receivers", _box_flag(GROUND), "--casters", _box_flag(CRATE)],
     dict(rule="lispsm", receivers=[GROUND], casters=[CRATE])),
    (["--warp", "minimax", "--receivers", _box_flag(GROUND), "--depth-range", "2,60"],
     dict(receivers=[GROUND], depth_range=(2.0, 60.0))),
    (["--warp", "uniform", "--receivers", _box_flag(GROUND), "--clip-depth", "zero-to-one"],
     dict(rule="uniform", receivers=[GROUND], clip_depth="zero_to_one")),
    (["--warp", "psm", "--receivers", _box_flag(GROUND), "--casters", _box_flag(CRATE),
      "--depth-clamp", "--clip-depth", "reversed"],
     dict(rule="psm", receivers=[GROUND], casters=[CRATE], depth_clamp=np.True_,
          clip_depth="reversed")),
    (["--warp", "tsm", "--focus", "20", "--receivers", _box_flag(GROUND)],
     dict(rule="tsm", focus=20.0, receivers=[GROUND])),
    (["--warp", "lispsm", "--partition", "log", "--k", "3", "--overlap", "0.1",
      "--receivers", _box_flag(GROUND)],
     dict(scheme="cascades", rule="lispsm", partition="log", k=3, overlap=0.1,
          receivers=[GROUND])),
    (["--warp", "minimax", "--partition", "practical", "--k", "4", "--lambda", "0.7",
      "--receivers", _box_flag(GROUND)],
     dict(scheme="cascades", partition="practical", k=4, lambda_=0.7, receivers=[GROUND])),
    (["--warp", "lispsm", "--partition", "adaptive", "--k", "3", "--receivers", _box_flag(GROUND)],
     dict(scheme="cascades", rule="lispsm", partition="adaptive", k=3, receivers=[GROUND])),
    (["--warp", "uniform", "--partition", "uniform", "--k", "2", "--receivers", _box_flag(GROUND)],
     dict(scheme="cascades", rule="uniform", partition="uniform", k=2, receivers=[GROUND])),
    (["--warp", "lispsm", "--splits", "1,5,20,100", "--receivers", _box_flag(GROUND)],
     dict(scheme="cascades", rule="lispsm", splits=[1.0, 5.0, 20.0, 100.0], receivers=[GROUND])),
    (["--warp", "minimax", "--fractions", "0.05,0.3", "--overlap", "0.2",
      "--receivers", _box_flag(GROUND)],
     dict(scheme="cascades", fractions=[0.05, 0.3], overlap=0.2, receivers=[GROUND])),
    (["--warp", "uniform", "--bevy", "4,1,5,80,0.2", "--receivers", _box_flag(GROUND)],
     dict(scheme="cascades", rule="uniform", receivers=[GROUND],
          bevy=dict(num_cascades=4, minimum_distance=1.0, first_cascade_far_bound=5.0,
                    maximum_distance=80.0, overlap_proportion=0.2))),
    (["--warp", "lispsm", "--partition", "equal-error", "--k", "3",
      "--receivers", _box_flag(GROUND)],
     dict(scheme="cascades", rule="lispsm", partition="equal_error", k=3, receivers=[GROUND])),
    (["--warp", "lispsm", "--partition", "faces", "--k", "2", "--receivers", _box_flag(GROUND)],
     dict(scheme="faces", rule="lispsm", k=2, receivers=[GROUND])),
    (["--warp", "psm", "--partition", "faces", "--receivers", _box_flag(GROUND)],
     dict(scheme="faces", rule="psm", receivers=[GROUND])),
    (["--warp", "uniform", "--lod-bias", "-1", "--partition", "clipmap", "--levels", "2,12",
      "--level-unit", "0.1", "--page-texels", "64", "--virtual-resolution", "2048",
      "--image-height", "2048", "--receivers", _box_flag(GROUND)],
     dict(scheme="clipmap", lod_bias=-1.0, levels=(2, 12), level_unit=0.1, page_texels=64,
          receivers=[GROUND])),
]


def _num(v):
    return float(v)  # "inf" (n′ of an unwarped map) as float("inf")


@pytest.mark.parametrize("flags, kwargs", CASES, ids=[" ".join(c[0][:2] + c[0][4:6]) for c in CASES])
def test_agrees_with_the_command_line_bit_for_bit(flags, kwargs):
    exe = _cli()
    cmd = [exe, "warp", "--near", "1", "--far", "100", "--half-fov", "0.5",
           "--light-dir", ",".join(map(str, LIGHT)), "--json", *flags]
    want = json.loads(subprocess.run(cmd, capture_output=True, text=True, check=True).stdout)
    got = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, map_resolution=2048, image_height=2048,
                   **kwargs)
    parts = want["partitions"]
    assert got["focus"] == want["focus"] and got["light"] == want["light"]
    assert len(parts) == len(got["max_mx"]) > 0
    for i, p in enumerate(parts):
        # The command line prints glam's column-major array: rows are its transpose.
        m = np.array(p["matrix"], dtype=np.float64).reshape(4, 4).T
        np.testing.assert_array_equal(got["eye_to_clip"][i], m)
        # The camera at the world origin: world → clip is eye → clip.
        np.testing.assert_array_equal(got["world_to_clip"][i], m)
        for key in ("max_mx", "max_mz", "storage_factor", "texel_world"):
            assert got[key][i] == p[key], key
        assert got["n_prime"][i] == _num(p["n_prime"])
        assert tuple(got["depth"][i]) == (p["near"], p["far"])
        assert tuple(got["split"][i]) == tuple(p["split"])
        assert tuple(got["blend"][i]) == tuple(p["blend"])
        assert got["face"][i] == p.get("face")
        assert got["clipmap_level"][i] == p.get("clipmap_level")
        assert len(got["body"][i]) == p["body_vertices"]
        # The map resolution equals the image height: the error in pixels is max(M_x, M_z).
        assert got["max_error_pixels"][i] == max(p["max_mx"], p["max_mz"])
    assert got["storage_factor"].sum() == pytest.approx(want["storage_factor"], rel=1e-15)


@pytest.mark.parametrize("rule", ["uniform", "psm", "lispsm", "minimax", "filament"])
@pytest.mark.parametrize("clip_depth", ["neg_one_to_one", "zero_to_one", "reversed"])
def test_without_a_scene_the_single_map_is_warp_bit_for_bit(rule, clip_depth):
    # Module docs of shadow_aliasing::frame: an unbounded receiver gives maps::warp's matrix.
    got = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, rule=rule, clip_depth=clip_depth)
    want = sa.warp(**CAM, light_dir=LIGHT, rule=rule, clip_depth=clip_depth)
    np.testing.assert_array_equal(got["eye_to_clip"][0], want)
    assert got["n_prime"][0] == sa.n_prime_for(**CAM, light_dir=LIGHT, rule=rule)


@pytest.mark.parametrize("partition", ["self_similar", "uniform", "practical"])
def test_without_a_scene_cascades_are_the_builders_bit_for_bit(partition):
    extra = {"lambda_": 0.5} if partition == "practical" else {}
    got = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, scheme="cascades", partition=partition,
                   k=3, rule="lispsm", overlap=0.1, **extra)
    want = sa.cascades(**CAM, light_dir=LIGHT, k=3, partition=partition, rule="lispsm",
                       overlap=0.1, **extra)
    np.testing.assert_array_equal(got["eye_to_clip"], want)
    np.testing.assert_array_equal(got["split"][:, 0],
                                  sa.z_partition(1.0, 100.0, 3, partition, **extra)[:-1])


def test_face_partitions_without_a_scene_are_the_builders():
    got = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, scheme="faces", k=2, rule="psm")
    mats, names = sa.faces(**CAM, light_dir=LIGHT, k=2, warp="psm")
    assert got["face"] == names
    # To the clipper's rounding (module docs).
    np.testing.assert_allclose(got["eye_to_clip"], mats, rtol=1e-9, atol=1e-12)


def _rigid(angle, t):
    """World → eye: a turn by `angle` about +Y after a translation by t."""
    c, s = math.cos(angle), math.sin(angle)
    r = np.array([[c, 0.0, s, 0.0], [0.0, 1.0, 0.0, 0.0], [-s, 0.0, c, 0.0], [0, 0, 0, 1.0]])
    tr = np.eye(4)
    tr[:3, 3] = t
    return r @ tr


def test_a_moved_camera_sees_the_same_maps_in_its_eye_space():
    # A quarter turn and a whole-number translation: world boxes map to eye boxes exactly.
    view = _rigid(math.pi / 2, [7.0, -3.0, 11.0])
    view[np.abs(view) < 1e-15] = 0.0
    view[np.abs(view - 1) < 1e-15] = 1.0
    view[np.abs(view + 1) < 1e-15] = -1.0
    inv = np.linalg.inv(view)

    def to_world(b):
        c = np.array(b)
        pts = (inv @ np.c_[c, np.ones(2)].T).T[:, :3]
        return [pts.min(0).tolist(), pts.max(0).tolist()]

    light_w = (inv[:3, :3] @ np.array(LIGHT)).tolist()
    eye = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, rule="lispsm", receivers=[GROUND],
                   casters=[CRATE])
    world = sa.frame(view, **CAM, light_dir=light_w, rule="lispsm",
                     receivers=[to_world(GROUND)], casters=[to_world(CRATE)])
    np.testing.assert_allclose(world["eye_to_clip"], eye["eye_to_clip"], rtol=1e-12, atol=1e-12)
    # World → clip is eye → clip after the view matrix.
    np.testing.assert_allclose(world["world_to_clip"][0], world["eye_to_clip"][0] @ view,
                               rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(world["light_dir_eye"], np.array(LIGHT) / np.linalg.norm(LIGHT),
                               rtol=1e-12, atol=1e-15)
    # The receivers' culling volume holds the focus body (eye-space vertices taken to world).
    planes = world["receivers_volume"][0]
    np.testing.assert_allclose(np.linalg.norm(planes[:, :3], axis=1), 1.0, rtol=1e-12)
    body_w = (inv @ np.c_[world["body"][0], np.ones(len(world["body"][0]))].T).T[:, :3]
    assert (body_w @ planes[:, :3].T + planes[:, 3] <= 1e-9).all()
    cast = world["casters_volume"][0]
    assert (body_w @ cast[:, :3].T + cast[:, 3] <= 1e-9).all()


def test_float32_matrices_are_the_float64_ones_rounded():
    f64 = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, receivers=[GROUND], scheme="cascades",
                   k=2, partition="log")
    for dt in (np.float32, "float32", np.dtype(np.float32)):
        f32 = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, receivers=[GROUND],
                       scheme="cascades", k=2, partition="log", dtype=dt)
        assert f32["world_to_clip"].dtype == np.float32
        np.testing.assert_array_equal(f32["world_to_clip"],
                                      f64["world_to_clip"].astype(np.float32))
        np.testing.assert_array_equal(f32["max_mx"], f64["max_mx"])


def test_stable_cascades_snap_to_whole_texels_as_the_camera_moves():
    # Stable cascades (world-fixed light space): moving the camera shifts each map's s, t by
    # whole texels, which is what keeps shadows from shimmering.
    res = 1024
    light = [0.3, -1.0, 0.2]
    kw = dict(**CAM, light_dir=light, scheme="stable", partition="log", k=2,
              map_resolution=res)
    a = sa.frame(_rigid(0.0, [0.0, 0.0, 0.0]), **kw)
    b = sa.frame(_rigid(0.0, [0.37, 0.0, -0.21]), **kw)
    assert len(a["world_to_clip"]) == len(b["world_to_clip"]) == 2
    for i in range(2):
        ma, mb = a["world_to_clip"][i], b["world_to_clip"][i]
        # The same orthographic scale, a translation of whole texels (2/res of clip each).
        np.testing.assert_array_equal(ma[:2, :3], mb[:2, :3])
        shift = (mb[:2, 3] - ma[:2, 3]) * res / 2
        np.testing.assert_allclose(shift, np.round(shift), atol=1e-6)


def test_tsm_scheme_maps_the_focus_body():
    r = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, scheme="tsm", receivers=[GROUND], xi=-0.5)
    assert r["focus"] == "body" and len(r["world_to_clip"]) == 1
    # Every body vertex lands in the map's clip square.
    body = r["body"][0]
    clip = (r["world_to_clip"][0] @ np.c_[body, np.ones(len(body))].T).T
    ndc = clip[:, :3] / clip[:, 3:]
    assert (np.abs(ndc) <= 1 + 1e-9).all()


def test_out_of_view_receivers_give_no_map():
    r = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, receivers=[[[0, 0, 5], [1, 1, 6]]])
    assert r["focus"] == "empty"
    assert r["world_to_clip"].shape == (0, 4, 4) and r["face"] == []


@pytest.mark.parametrize("kwargs, name", [
    (dict(view=np.diag([2.0, 1.0, 1.0, 1.0])), "view"),
    (dict(view=np.eye(3)), "view"),
    (dict(receivers=[[1.0, 2.0, 3.0]]), "receivers"),
    (dict(casters=[[[0, 0, 0], [-1, 0, 0]]]), "casters"),
    (dict(depth_range=(1.0, 2.0, 3.0)), "depth_range"),
    (dict(depth_range=(200.0, 300.0)), "depth_range"),
    (dict(light_dir=[0.0, 0.0, 0.0]), "light_dir"),
    (dict(map_resolution=2), "map_resolution"),
    (dict(scheme="cascades"), "k"),
    (dict(scheme="cascades", k=2, partition="log", splits=[1.0, 100.0]), "partition"),
    (dict(scheme="cascades", splits=[1.0, 0.5, 100.0]), "splits"),
    (dict(scheme="cascades", fractions=[1.5]), "fractions"),
    (dict(scheme="cascades", bevy=dict(num_cascades=2)), "bevy"),
    (dict(scheme="cascades", bevy=dict(num_cascades=2, minimum_distance=1.0,
                                       maximum_distance=50.0, first_cascade_far_bound=80.0,
                                       overlap_proportion=0.2)), "bevy"),
    (dict(scheme="cascades", k=2, partition="equal_error", overlap=0.1), "overlap"),
    (dict(overlap=0.1), "overlap"),
    (dict(k=2), "k"),
    (dict(scheme="stable", k=2, partition="log", rule="lispsm"), "rule"),
    (dict(scheme="faces", rule="minimax"), "rule"),
    (dict(scheme="tsm", xi=0.1, iterative=64), "xi"),
    (dict(xi=0.1), "xi"),
    (dict(dtype=np.int32), "dtype"),
    (dict(dtype="float16"), "dtype"),
    (dict(pcf_radius=-1.0), "pcf_radius"),
    (dict(measure=1), "measure"),
    (dict(scheme="clipmap", rule="lispsm"), "rule"),
    (dict(scheme="clipmap", k=2), "k"),
    (dict(lod_bias=-1.0), "lod_bias"),
    (dict(scheme="clipmap", levels=(9,)), "levels"),
    (dict(scheme="clipmap", levels="ab"), "levels"),
    (dict(scheme="clipmap", levels=(6, 8)), "levels"),
    (dict(scheme="clipmap", page_texels=100), "page_texels"),
    (dict(scheme="clipmap", lod_bias=float("nan")), "lod_bias"),
    (dict(scheme="clipmap", level_unit=0.0), "level_unit"),
])
def test_bad_arguments_name_themselves(kwargs, name):
    args = dict(view=np.eye(4), **CAM, light_dir=LIGHT)
    args.update(kwargs)
    with pytest.raises((ValueError, TypeError)) as e:
        sa.frame(**args)
    assert name in str(e.value), str(e.value)


def test_bias_values_follow_the_clip_depth_convention():
    # frame::bias: depth values are what to add to the receiver's depth, negative where depth
    # grows away from the light, positive for reversed depth; [0, 1] depth is half of [-1, 1].
    kw = dict(**CAM, light_dir=LIGHT, rule="lispsm", receivers=[GROUND])
    gl = sa.frame(np.eye(4), **kw)
    zo = sa.frame(np.eye(4), **kw, clip_depth="zero_to_one")
    rv = sa.frame(np.eye(4), **kw, clip_depth="reversed")
    assert (gl["slope_scaled_depth"] < 0).all() and (rv["slope_scaled_depth"] > 0).all()
    np.testing.assert_allclose(zo["slope_scaled_depth"], 0.5 * gl["slope_scaled_depth"], rtol=1e-12)
    np.testing.assert_array_equal(rv["slope_scaled_depth"], -zo["slope_scaled_depth"])
    # The texel's extents over B reach at least the largest edge at B's vertices.
    assert gl["texel_extent"].max() >= gl["texel_world"][0] * (1 - 1e-12)
    # A wider PCF kernel needs a larger normal offset; the matrices do not change.
    wide = sa.frame(np.eye(4), **kw, pcf_radius=2.0)
    assert wide["normal_offset"][0] > gl["normal_offset"][0] > 0
    np.testing.assert_array_equal(wide["world_to_clip"], gl["world_to_clip"])


def test_an_orthographic_map_has_one_texel_size():
    r = sa.frame(np.eye(4), **CAM, light_dir=LIGHT, rule="uniform", receivers=[GROUND])
    np.testing.assert_allclose(r["texel_extent"][0].max(), r["texel_world"][0], rtol=1e-9)


def test_unmeasured_frames_keep_the_matrices_and_report_no_bound():
    kw = dict(**CAM, light_dir=LIGHT, receivers=[GROUND], scheme="cascades", k=3, partition="log")
    a = sa.frame(np.eye(4), **kw)
    b = sa.frame(np.eye(4), **kw, measure=False)
    np.testing.assert_array_equal(a["world_to_clip"], b["world_to_clip"])
    assert np.isinf(b["max_mx"]).all() and np.isfinite(a["max_mx"]).all()
