#!/usr/bin/env python3
"""A stack of cameras: the storage factor S̄ of LiSPSM and of the uniform map over a grid of
light elevations and fields of view, built and measured in two calls over stacks.

    pip install ./python matplotlib
    python python/examples/camera_stack.py [OUT.png]

`warp` broadcasts its camera (near, far, half_fov: numbers or arrays) with the light directions
(..., 3), so a (elevations, fovs) grid of maps is one call; `frustum_max` measures the stack the
same way. With the light overhead (γ = 90°) LiSPSM's S̄ is Lloyd 2006 Eq 12 at
n′ = n + √(f n), which the script checks against `storage_factor`.
"""
from __future__ import annotations

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import numpy.typing as npt  # noqa: E402

import shadow_aliasing as sa  # noqa: E402

NEAR, FAR = 1.0, 500.0


def grid() -> tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """Light elevations (rows, radians above the horizon, the light ahead of the viewer) and
    half fields of view (columns); the light directions (rows, 1, 3) broadcast with the fovs."""
    elevation = np.radians(np.linspace(10.0, 90.0, 33))
    half_fov = np.radians(np.linspace(15.0, 45.0, 13))
    light = np.stack([np.zeros_like(elevation), -np.sin(elevation), -np.cos(elevation)], -1)
    return elevation, half_fov, light[:, None, :]


def run() -> dict[str, npt.NDArray[np.float64]]:
    elevation, half_fov, light = grid()
    out: dict[str, npt.NDArray[np.float64]] = {"elevation": elevation, "half_fov": half_fov}
    for rule in ("uniform", "lispsm"):
        m = sa.warp(NEAR, FAR, half_fov, light, rule)          # (33, 13, 4, 4)
        out[rule] = sa.frustum_max(m, light, NEAR, FAR, half_fov)[..., 2]   # S̄, (33, 13)
    # Overhead: Lloyd 2006 Eq 12 with LiSPSM's n′.
    eq12 = sa.storage_factor(NEAR, FAR, half_fov, sa.n_prime_lispsm(NEAR, FAR))
    out["eq12"] = np.asarray(eq12, dtype=np.float64)
    return out


def main(path: str = "camera_stack.png") -> None:
    r = run()
    assert np.allclose(r["lispsm"][-1], r["eq12"], rtol=1e-9), "overhead LiSPSM is Eq 12"
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True, sharey=True)
    lo = np.log10(min(r["uniform"].min(), r["lispsm"].min()))
    hi = np.log10(max(r["uniform"].max(), r["lispsm"].max()))
    for ax, rule, title in zip(axes, ("uniform", "lispsm"), ("uniform", "LiSPSM")):
        im = ax.pcolormesh(np.degrees(r["half_fov"]), np.degrees(r["elevation"]),
                           np.log10(r[rule]), vmin=lo, vmax=hi, shading="nearest",
                           cmap="viridis")
        ax.set_title(f"{title}, f/n = {FAR / NEAR:g}")
        ax.set_xlabel("half field of view θ (°)")
    axes[0].set_ylabel("light elevation (°; 90 = overhead)")
    fig.colorbar(im, ax=axes, label="log₁₀ storage factor S̄")
    fig.savefig(path, dpi=110)
    print(f"wrote {path}; overhead LiSPSM S̄ at θ = 30°: {r['lispsm'][-1, 6]:.6g} "
          f"(Eq 12: {r['eq12'][6]:.6g})")


if __name__ == "__main__":
    main(*sys.argv[1:])
