#!/usr/bin/env python3
"""The predicted shadow-map error of a captured frame, pixel by pixel, with
`shadow_aliasing.error_image`: the depth buffer and the camera in, the error image out.

    pip install ./python matplotlib
    python python/examples/captured_frame.py [OUT.png] [CAPTURE.npz]

CAPTURE.npz, if given, holds a frame from a renderer: ``depth`` (H, W) as the GPU wrote it
(Vulkan/D3D/wgpu convention, row 0 at the top), ``projection`` and ``view`` (4, 4) and
``shadow_matrix`` ((4, 4) or (m, 4, 4), world → light clip). Without it the script makes one:
a ground and three boxes seen by a camera 4 units up, ray cast in NumPy, lit by a low sun with
three cascades from `frame`. Each pixel's error is 1/σ_min of the exact footprint Jacobian
(pixels per texel: above 1 a texel covers more than a pixel and shadow edges turn blocky).
"""
from __future__ import annotations

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import numpy.typing as npt  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402

import shadow_aliasing as sa  # noqa: E402

F64 = npt.NDArray[np.float64]
H, W = 270, 480
NEAR, FAR, HALF_FOV = 0.5, 200.0, np.radians(30.0)
BOXES = np.array([[[-6.0, 0.0, -22.0], [-2.0, 5.0, -18.0]],
                  [[3.0, 0.0, -40.0], [9.0, 9.0, -34.0]],
                  [[-14.0, 0.0, -75.0], [-4.0, 14.0, -65.0]]])
GROUND = np.array([[[-300.0, -1.0, -300.0], [300.0, 0.0, 300.0]]])


def perspective(near: float, far: float, half_fov: float, aspect: float) -> F64:
    """Right-handed, looking down −Z, depth z/w in [0, 1] (Vulkan, D3D, wgpu)."""
    t = np.tan(half_fov)
    return np.array([[1 / (aspect * t), 0, 0, 0], [0, 1 / t, 0, 0],
                     [0, 0, far / (near - far), far * near / (near - far)], [0, 0, -1.0, 0]])


def view_matrix() -> F64:
    """World → eye: the camera at (0, 4, 0) looking down −Z, pitched 8° down."""
    a = np.radians(8.0)
    pitch = np.array([[1, 0, 0, 0], [0, np.cos(a), np.sin(a), 0],
                      [0, -np.sin(a), np.cos(a), 0], [0, 0, 0, 1.0]])
    move = np.eye(4)
    move[1, 3] = -4.0
    return pitch @ move


def ray_cast(proj: F64, view: F64) -> F64:
    """The depth buffer of the ground (y = 0) and the boxes: nearest hit per pixel centre."""
    x = (np.arange(W) + 0.5) / W * 2 - 1
    y = 1 - (np.arange(H) + 0.5) / H * 2
    xs, ys = np.meshgrid(x, y)
    inv = np.linalg.inv(proj @ view)
    ends = []
    for z in (0.0, 0.5):
        c = np.stack([xs, ys, np.full_like(xs, z), np.ones_like(xs)], -1) @ inv.T
        ends.append(c[..., :3] / c[..., 3:])
    origin, d = ends[0], ends[1] - ends[0]
    t = np.full((H, W), np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        g = -origin[..., 1] / d[..., 1]
        t = np.where(g > 0, g, t)
        for lo, hi in BOXES:   # slab test
            t0, t1 = (lo - origin) / d, (hi - origin) / d
            near_t = np.nanmax(np.minimum(t0, t1), -1)
            far_t = np.nanmin(np.maximum(t0, t1), -1)
            hit = (near_t <= far_t) & (near_t > 0)
            t = np.where(hit & (near_t < t), near_t, t)
    p = origin + np.where(np.isfinite(t), t, 0.0)[..., None] * d
    c = np.concatenate([p, np.ones((H, W, 1))], -1) @ (proj @ view).T
    depth = c[..., 2] / c[..., 3]
    return np.where(np.isfinite(t) & (depth < 1.0), depth, 1.0)


def synthetic() -> dict[str, F64]:
    proj, view = perspective(NEAR, FAR, HALF_FOV, W / H), view_matrix()
    f = sa.frame(view, NEAR, FAR, HALF_FOV, [0.5, -0.45, -0.3], aspect=W / H,
                 receivers=GROUND, casters=np.concatenate([BOXES, GROUND]), scheme="cascades",
                 k=3, partition="practical", lambda_=0.8, image_height=H, map_resolution=1024)
    return {"depth": ray_cast(proj, view), "projection": proj, "view": view,
            "shadow_matrix": np.asarray(f["world_to_clip"], dtype=np.float64)}


def run(capture: dict[str, F64], resolution: int = 1024) -> tuple[F64, F64]:
    return sa.error_image(capture["depth"], capture["projection"], capture["view"],
                          capture["shadow_matrix"], map_resolution=resolution,
                          return_jacobian=True)


def main(path: str = "captured_frame.png", capture_file: str | None = None) -> None:
    capture = dict(np.load(capture_file)) if capture_file else synthetic()
    error, jac = run(capture)
    # How stretched each texel is on the screen: σ_max/σ_min of J (1: square on the screen).
    s = np.linalg.svd(np.nan_to_num(jac), compute_uv=False)
    with np.errstate(divide="ignore", invalid="ignore"):
        anisotropy = np.where(np.isfinite(error), s[..., 0] / s[..., 1], np.nan)
    fig, (a, b) = plt.subplots(1, 2, figsize=(13, 4.2), constrained_layout=True)
    im = a.imshow(error, norm=LogNorm(vmin=np.nanpercentile(error, 1),
                                      vmax=np.nanpercentile(error, 99)), cmap="magma")
    fig.colorbar(im, ax=a, label="error: pixels per texel (log)")
    a.set_title("predicted error of each pixel (blank: sky)")
    im2 = b.imshow(anisotropy, norm=LogNorm(vmin=1, vmax=np.nanpercentile(anisotropy, 99)),
                   cmap="viridis")
    fig.colorbar(im2, ax=b, label="texel anisotropy σ_max/σ_min (log)")
    b.set_title("how stretched a texel is on the screen")
    for ax in (a, b):
        ax.set_xticks([])
        ax.set_yticks([])
    fig.savefig(path, dpi=110)
    seen = np.isfinite(error)
    print(f"wrote {path}; {seen.mean():.0%} of the pixels have a prediction, median error "
          f"{np.median(error[seen]):.3g} px/texel, above 1 (blocky): {(error[seen] > 1).mean():.0%}")


if __name__ == "__main__":
    main(*sys.argv[1:])
