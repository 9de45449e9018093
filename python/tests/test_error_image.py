"""sa.error_image: the predicted error of every pixel of a captured frame, against the crate's
own measurement (point_error, through the footprint identity |det J| m_x m_z = |f̂·L|) and
against an independent NumPy derivation (ray casting and finite differences)."""
import math

import numpy as np
import pytest

import shadow_aliasing as sa
from views import look_at

NEAR, FAR, THETA = 1.0, 100.0, 0.5
H, W = 24, 32
RES = 1024


def perspective(near, far, theta, aspect, gl=False):
    """A right-handed perspective (looking down −Z): Vulkan/D3D depth z/w ∈ [0, 1], or OpenGL's
    [−1, 1] with ``gl``."""
    t = math.tan(theta)
    p = np.zeros((4, 4))
    p[0, 0], p[1, 1], p[3, 2] = 1 / (aspect * t), 1 / t, -1.0
    if gl:
        p[2, 2], p[2, 3] = (far + near) / (near - far), 2 * far * near / (near - far)
    else:
        p[2, 2], p[2, 3] = far / (near - far), far * near / (near - far)
    return p


def pixel_ndc(h, w):
    """NDC (x, y) of every pixel centre, row 0 at the top."""
    x = (np.arange(w) + 0.5) / w * 2 - 1
    y = 1 - (np.arange(h) + 0.5) / h * 2
    return np.meshgrid(x, y)


def ground_depth(proj, view, h, w, gl=False):
    """The depth buffer of the plane y = 0 (1 where the ray misses it or passes the far
    plane): each pixel's ray cast against the plane, the hit projected."""
    xs, ys = pixel_ndc(h, w)
    inv = np.linalg.inv(proj @ view)
    def unproject(z):
        c = np.stack([xs, ys, np.full_like(xs, z), np.ones_like(xs)], -1) @ inv.T
        return c[..., :3] / c[..., 3:]
    a, b = unproject(-1.0 if gl else 0.0), unproject(0.99)
    s = a[..., 1] / (a[..., 1] - b[..., 1])
    hit = a + s[..., None] * (b - a)
    c = np.concatenate([hit, np.ones((h, w, 1))], -1) @ (proj @ view).T
    z = c[..., 2] / c[..., 3]
    d = (z + 1) / 2 if gl else z
    ok = (s > 0) & (c[..., 3] > 0) & (d >= 0) & (d < 1)
    return np.where(ok, d, 1.0), ok


def texel_of_pixel(proj, view, m, res):
    """(u, v) pixel coordinates → texel coordinates on the plane y = 0 (by ray casting)."""
    inv = np.linalg.inv(proj @ view)
    def f(u, v):
        x, y = 2 * u / W - 1, 1 - 2 * v / H
        a = inv @ [x, y, 0.0, 1.0]
        b = inv @ [x, y, 0.5, 1.0]
        a, b = a[:3] / a[3], b[:3] / b[3]
        p = a + a[1] / (a[1] - b[1]) * (b - a)
        c = m @ np.append(p, 1.0)
        return np.array([(c[0] / c[3] + 1) / 2 * res, (c[1] / c[3] + 1) / 2 * res])
    return f


def test_matches_an_independent_ray_cast_and_finite_differences():
    aspect = W / H
    proj = perspective(NEAR, FAR, THETA, aspect)
    view = look_at([0.0, 6.0, 0.0], [3.0, 0.0, -25.0])
    light = [0.4, -1.0, 0.3]
    f = sa.frame(view, NEAR, FAR, THETA, light, aspect=aspect, scheme="single", rule="lispsm",
                 receivers=[[[-200, -1, -200], [200, 0, 200]]])
    m = f["world_to_clip"][0]
    depth, ok = ground_depth(proj, view, H, W)
    assert ok.sum() > H * W // 3
    err, jac = sa.error_image(depth, proj, view, m, map_resolution=RES, return_jacobian=True)
    given = sa.error_image(depth, proj, view, m, map_resolution=RES,
                           normals=np.broadcast_to([0.0, 1.0, 0.0], (H, W, 3)))
    assert err.shape == (H, W) and jac.shape == (H, W, 2, 2)
    assert np.isnan(err[~ok]).all() and np.isnan(jac[~ok]).all()
    tex = texel_of_pixel(proj, view, m, RES)
    e = 1e-3
    for y, x in zip(*np.nonzero(ok)):
        u, v = x + 0.5, y + 0.5
        j = np.column_stack([(tex(u + e, v) - tex(u - e, v)) / (2 * e),
                             (tex(u, v + e) - tex(u, v - e)) / (2 * e)])
        want = 1 / np.linalg.svd(j, compute_uv=False)[-1]
        np.testing.assert_allclose(jac[y, x], j, rtol=1e-5, atol=1e-9 * np.abs(j).max())
        assert err[y, x] == pytest.approx(want, rel=1e-5)
        assert given[y, x] == pytest.approx(want, rel=1e-5)


def test_the_crates_point_error_through_the_footprint_identity():
    # A wall facing the camera (normal = the view axis f̂), world = eye space: for the crate's
    # symmetric camera |det J| m_x m_z = |f̂·L| with point_error at res_image = H (the module
    # docs of measure::footprint), for any light.
    aspect = W / H
    proj = perspective(NEAR, FAR, THETA, aspect)
    z_eye = -20.0
    c = proj @ [0.0, 0.0, z_eye, 1.0]
    depth = np.full((H, W), c[2] / c[3])
    xs, ys = pixel_ndc(H, W)
    t = math.tan(THETA)
    points = np.stack([xs * aspect * t * -z_eye, ys * t * -z_eye, np.full_like(xs, z_eye)], -1)
    for light in ([0.3, -1.0, -0.4], [0.0, -1.0, 0.0], [-0.6, -0.5, 0.8]):
        m = sa.warp(NEAR, FAR, THETA, light, "lispsm", aspect=aspect)
        err, jac = sa.error_image(depth, proj, np.eye(4), m, map_resolution=RES,
                                  return_jacobian=True)
        mx, mz = np.moveaxis(sa.point_error(m, light, points, NEAR, FAR, THETA, res_image=H,
                                            res_s=RES, res_t=RES, aspect=aspect), -1, 0)
        l = np.asarray(light) / np.linalg.norm(light)
        np.testing.assert_allclose(np.abs(np.linalg.det(jac)) * mx * mz, abs(l[2]), rtol=1e-7)
        with np.errstate(divide="ignore"):  # the light along the wall: J singular, error inf
            want = 1 / np.linalg.svd(jac, compute_uv=False)[..., -1]
        np.testing.assert_allclose(err, want, rtol=1e-12)


def test_opengl_depth_gives_the_same_image():
    aspect = W / H
    view = look_at([0.0, 4.0, 2.0], [-2.0, 0.0, -20.0])
    m = sa.frame(view, NEAR, FAR, THETA, [0.2, -1.0, 0.5], aspect=aspect)["world_to_clip"][0]
    d_vk, ok = ground_depth(perspective(NEAR, FAR, THETA, aspect), view, H, W)
    d_gl, ok_gl = ground_depth(perspective(NEAR, FAR, THETA, aspect, gl=True), view, H, W, gl=True)
    assert (ok == ok_gl).all()
    a = sa.error_image(d_vk, perspective(NEAR, FAR, THETA, aspect), view, m, fill=-1.0)
    b = sa.error_image(d_gl, perspective(NEAR, FAR, THETA, aspect, gl=True), view, m,
                       clip_depth="neg_one_to_one", fill=-1.0)
    assert (a[~ok] == -1.0).all()
    np.testing.assert_allclose(a, b, rtol=1e-6)


def test_cascades_pick_the_first_map_that_covers_the_point():
    aspect = W / H
    proj = perspective(NEAR, FAR, THETA, aspect)
    view = look_at([0.0, 3.0, 0.0], [0.0, 0.0, -30.0])
    f = sa.frame(view, NEAR, FAR, THETA, [0.3, -1.0, 0.2], aspect=aspect, scheme="cascades",
                 k=3, partition="log", receivers=[[[-300, -1, -300], [300, 0, 300]]])
    ms = f["world_to_clip"]
    depth, ok = ground_depth(proj, view, H, W)
    # Which map each pixel's point falls in, from the points NumPy recovers itself.
    xs, ys = pixel_ndc(H, W)
    c = np.stack([xs, ys, depth, np.ones_like(xs)], -1) @ np.linalg.inv(proj @ view).T
    p = np.concatenate([c[..., :3] / c[..., 3:], np.ones((H, W, 1))], -1)
    lc = np.einsum("mij,hwj->mhwi", ms, p)
    inside = (lc[..., 3] > 0) & (np.abs(lc[..., 0]) <= lc[..., 3]) & (np.abs(lc[..., 1]) <= lc[..., 3])
    first = np.where(inside.any(0), inside.argmax(0), -1)
    first[~ok] = -1
    assert len(set(first[ok])) >= 2  # more than one cascade is used
    picked = sa.error_image(depth, proj, view, ms)
    np.testing.assert_array_equal(picked, sa.error_image(depth, proj, view, ms, map_index=first))
    for k in range(len(ms)):
        one = sa.error_image(depth, proj, view, ms[k])
        np.testing.assert_array_equal(picked[first == k], one[first == k])


def test_out_and_fill():
    proj = perspective(NEAR, FAR, THETA, W / H)
    view = look_at([0.0, 5.0, 0.0], [0.0, 0.0, -20.0])
    m = sa.frame(view, NEAR, FAR, THETA, [0.3, -1.0, 0.2], aspect=W / H)["world_to_clip"][0]
    depth, ok = ground_depth(proj, view, H, W)
    out = np.empty((H, W))
    assert sa.error_image(depth, proj, view, m, fill=0.0, out=out) is out
    assert (out[~ok] == 0.0).all() and (out[ok] > 0).all()
    np.testing.assert_array_equal(out[ok], sa.error_image(depth, proj, view, m)[ok])


@pytest.mark.parametrize("kwargs, name", [
    (dict(depth=np.full(5, 0.5)), "depth"),
    (dict(depth=np.full((H, W), 20.0)), "depth"),
    (dict(depth=np.full((0, W), 0.5)), "depth"),
    (dict(projection=np.zeros((4, 4))), "projection"),
    (dict(projection=np.eye(3)), "projection"),
    (dict(view=np.full((4, 4), np.nan)), "view"),
    (dict(shadow_matrix=np.zeros((0, 4, 4))), "shadow_matrix"),
    (dict(shadow_matrix=np.full((4, 4), np.inf)), "shadow_matrix"),
    (dict(normals=np.ones((H, W))), "normals"),
    (dict(normals=np.zeros((H, W, 3))), "normals"),
    (dict(map_index=np.full((H, W), 1)), "map_index"),
    (dict(map_index=np.full((H, W), 0.5)), "map_index"),
    (dict(map_resolution=0), "map_resolution"),
    (dict(background=math.nan), "background"),
    (dict(clip_depth="opengl"), "clip_depth"),
])
def test_bad_input_names_the_argument(kwargs, name):
    proj = perspective(NEAR, FAR, THETA, W / H)
    view = look_at([0.0, 5.0, 0.0], [0.0, 0.0, -20.0])
    m = sa.frame(view, NEAR, FAR, THETA, [0.3, -1.0, 0.2], aspect=W / H)["world_to_clip"][0]
    depth, _ = ground_depth(proj, view, H, W)
    args = dict(depth=depth, projection=proj, view=view, shadow_matrix=m)
    args.update(kwargs)
    with pytest.raises(ValueError) as e:
        sa.error_image(**args)
    assert name in str(e.value), str(e.value)
    with pytest.raises(TypeError, match="return_jacobian"):
        sa.error_image(depth, proj, view, m, return_jacobian=1)
