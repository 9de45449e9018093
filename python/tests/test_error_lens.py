"""Controller.error_lens, the crate's per-point error lens (``FrameMap::error_lens_at``, the WGSL
module's ``sa_error_lens``): the size of the map's texel in screen pixels on a surface, held to
its own measurement here by central differences in NumPy (the surface's texel coordinates
through the map's world → clip matrix and its pixel coordinates through the camera, no formula
of the crate); and ``error_image`` over a ray-cast depth buffer, which is the same quantity per
pixel (1/σ_min of the pixel → texel Jacobian), agreeing with it."""
import math

import numpy as np
import pytest

import shadow_aliasing as sa
from views import look

H, W = 180, 320
NEAR, FAR, HALF_FOV, ASPECT = 0.5, 200.0, math.radians(30.0), W / H
LIGHT = [0.3, -0.8, -0.4]
BOXES = np.array([
    [[-60.0, -1.0, -400.0], [60.0, 0.0, 60.0]],
    [[-8.0, 0.0, -40.0], [-2.0, 6.0, -30.0]],
    [[4.0, 0.0, -90.0], [12.0, 15.0, -80.0]],
])
SCHEMES = ["single uniform", "single lispsm", "cascades practical k=3 uniform",
           "cascades log k=4 lispsm", "stable log k=3", "faces lispsm k=2"]


VIEW = look([1.0, 6.0, 10.0], [0.15, -0.25, -1.0])


def controlled(scheme):
    c = sa.Controller(max_error=4.0, candidates=[scheme], max_maps=16)
    d = c.frame(VIEW, NEAR, FAR, HALF_FOV, LIGHT, aspect=ASPECT, image_height=H,
                receivers=BOXES[:1], casters=BOXES)
    return c, d


def ground_points():
    """The ground y = 0 ray cast through every pixel's centre: (H, W, 3) world points, NaN
    where the ray misses it (above the horizon or past the far plane)."""
    x = (np.arange(W) + 0.5) / W * 2 - 1
    y = 1 - (np.arange(H) + 0.5) / H * 2
    t = math.tan(HALF_FOV)
    rays = np.stack(np.broadcast_arrays(x[None, :] * ASPECT * t, y[:, None] * t, -1.0), -1)
    eye_to_world = np.linalg.inv(VIEW)
    dirs = rays @ eye_to_world[:3, :3].T
    eye = eye_to_world[:3, 3]
    s = -eye[1] / dirs[..., 1]
    p = eye + s[..., None] * dirs
    far = (p - eye) @ -eye_to_world[:3, 2] > FAR
    p[(s <= 0) | far] = np.nan
    return p


def measured_lens(m, resolution, p, n):
    """The lens at world point p with normal n for the world → clip matrix m, measured: the
    Jacobians of the texel coordinates (res (x/w + 1)/2, res (y/w + 1)/2) and of the pixel
    coordinates (H/(2 tan θ) (x, y)/(−z) in eye space) over the surface's plane, by central
    differences; the texel → pixel map is J_pixel J_texel⁻¹ and the lens its largest singular
    value (the most pixels a one-texel step on the surface covers)."""
    n = np.asarray(n, float) / np.linalg.norm(n)
    u = np.cross(n, [1.0, 0.0, 0.0] if abs(n[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(n, u)
    k = H / (2 * math.tan(HALF_FOV))

    def texel(q):
        h = m @ np.append(q, 1.0)
        return resolution * 0.5 * (h[:2] / h[3] + 1)

    def pixel(q):
        e = VIEW @ np.append(q, 1.0)
        return k * e[:2] / -e[2]

    step = 1e-5 * (1 + np.linalg.norm(p))

    def jac(f):
        return np.column_stack([(f(p + step * a) - f(p - step * a)) / (2 * step) for a in (u, v)])

    return np.linalg.norm(jac(pixel) @ np.linalg.inv(jac(texel)), 2)


def first_covering(world_to_clip, p):
    """The index of the first map whose square (|x/w|, |y/w| ≤ 1, w > 0) holds p, or −1."""
    for i, m in enumerate(world_to_clip):
        h = m @ np.append(p, 1.0)
        if h[3] > 0 and abs(h[0]) <= h[3] and abs(h[1]) <= h[3]:
            return i
    return -1


@pytest.mark.parametrize("scheme", SCHEMES)
def test_the_lens_is_the_measured_texel_in_pixels(scheme):
    c, d = controlled(scheme)
    maps = d["maps"]
    rng = np.random.default_rng(7)
    pts = ground_points().reshape(-1, 3)
    pts = pts[~np.isnan(pts[:, 0])]
    pts = pts[rng.choice(len(pts), 40, replace=False)]
    # Surfaces of every kind: the ground, and normals tilted up to 80° from it either way.
    normals = np.array([[0.0, 1.0, 0.0]] * 10 + list(rng.normal(size=(30, 3)) * [1, 0.3, 1]
                                                      + [0, 0.2, 0]))
    index = np.array([first_covering(maps["world_to_clip"], p) for p in pts])
    assert (index >= 0).sum() >= 30
    got = c.error_lens(pts, normals)
    assert got.shape == (40,)
    assert np.array_equal(np.isnan(got), index < 0)
    for p, n, i, g in zip(pts, normals, index, got):
        if i < 0:
            continue
        want = measured_lens(maps["world_to_clip"][i], d["resolution"], p, n)
        assert g == pytest.approx(want, rel=1e-6), (scheme, p, n, i)
    # The map chosen by index gives the same, and another map another value.
    assert np.array_equal(c.error_lens(pts, normals, map_index=index), got, equal_nan=True)
    if len(maps["slot"]) > 1:
        other = np.where(index == 0, 1, 0)
        p, n = pts[index >= 0][0], normals[index >= 0][0]
        j = other[index >= 0][0]
        assert c.error_lens(p[None], n[None], map_index=[j])[0] == pytest.approx(
            measured_lens(maps["world_to_clip"][j], d["resolution"], p, n), rel=1e-6)


def test_a_grazing_lit_surface_facing_the_camera_exceeds_the_frames_maximum():
    c, d = controlled("single uniform")
    l = np.array(LIGHT) / np.linalg.norm(LIGHT)
    p = ground_points()[150, 160]
    to_eye = np.linalg.inv(VIEW)[:3, 3] - p
    # Turned toward the camera and nearly edge-on to the light: the projection factor grows as
    # 1/(n · l); the measured texel on it with it.
    values = []
    for tilt in (0.5, 0.1, 0.02):
        n = np.cross(l, np.cross(to_eye, l))
        n = n / np.linalg.norm(n) + tilt * -l
        want = measured_lens(d["maps"]["world_to_clip"][0], d["resolution"], p, n)
        got = c.error_lens(p, n)
        assert got == pytest.approx(want, rel=1e-6)
        values.append(float(got))
    assert values[0] < values[1] < values[2]
    assert values[2] > 10 * d["max_error_pixels"]


def test_error_image_over_a_ray_cast_frame_is_the_lens():
    c, d = controlled("cascades practical k=3 uniform")
    p = ground_points()
    f = 1 / math.tan(HALF_FOV)
    proj = np.array([[f / ASPECT, 0, 0, 0], [0, f, 0, 0],
                     [0, 0, FAR / (NEAR - FAR), NEAR * FAR / (NEAR - FAR)], [0, 0, -1, 0]])
    eye = (VIEW[:3, :3] @ np.nan_to_num(p).reshape(-1, 3).T).T + VIEW[:3, 3]
    clip = eye @ proj[:, :3].T + proj[:, 3]
    depth = (clip[:, 2] / clip[:, 3]).reshape(H, W)
    depth[np.isnan(p[..., 0])] = 1.0
    up = np.broadcast_to([0.0, 1.0, 0.0], (H, W, 3))
    image = sa.error_image(depth, proj, VIEW, d["maps"]["world_to_clip"],
                           map_resolution=d["resolution"], normals=up)
    lens = c.error_lens(np.nan_to_num(p, nan=0.0), up)
    lens[np.isnan(p[..., 0])] = np.nan
    hit = ~np.isnan(image)
    assert hit.sum() > H * W // 3
    np.testing.assert_allclose(lens, image, rtol=1e-6, equal_nan=True)


def test_points_behind_the_camera_or_outside_every_map_get_fill():
    c, _ = controlled("single uniform")
    eye = np.linalg.inv(VIEW)[:3, 3]
    behind = eye + np.linalg.inv(VIEW)[:3, 2] * 5  # +z of the eye: behind it
    outside = [0.0, 0.0, 1e5]
    got = c.error_lens([behind, outside], [[0, 1, 0], [0, 1, 0]], fill=-1.0)
    assert got.tolist() == [-1.0, -1.0]
    # map_index −1: no map; a map given for a point behind the camera: no lens either.
    ground = ground_points()[150, 160]
    got = c.error_lens([ground, behind], [[0, 1, 0], [0, 1, 0]], map_index=[-1, 0])
    assert np.isnan(got).all()
    assert np.isfinite(c.error_lens([ground], [[0, 1, 0]], map_index=[0])).all()


def test_the_lens_arguments_are_refused_by_name():
    c = sa.Controller(max_error=2.0)
    with pytest.raises(RuntimeError, match="frame"):
        c.error_lens([[0.0, 0.0, -5.0]], [[0.0, 1.0, 0.0]])
    c, d = controlled("cascades practical k=3 uniform")
    good = np.array([[0.0, 0.0, -5.0]])
    up = np.array([[0.0, 1.0, 0.0]])
    for args, kw, exc, name in [
        ((np.zeros((2, 2)), up), {}, ValueError, "points"),
        ((good, np.zeros((2, 3))), {}, ValueError, "normals"),
        ((good, np.zeros((1, 3))), {}, ValueError, "normals"),
        ((np.array([[np.nan, 0.0, 0.0]]), up), {}, ValueError, "points"),
        ((good, np.array([[np.inf, 0.0, 0.0]])), {}, ValueError, "normals"),
        ((good, up), dict(map_index=[3]), ValueError, "map_index"),
        ((good, up), dict(map_index=[0.5]), ValueError, "map_index"),
        ((good, up), dict(map_index=[0, 1]), ValueError, "map_index"),
        ((1.0, up), {}, ValueError, "points"),
        (("x", up), {}, TypeError, "points"),
        ((good, up), dict(fill="x"), TypeError, "fill"),
    ]:
        with pytest.raises(exc, match="^" + name):
            c.error_lens(*args, **kw)
