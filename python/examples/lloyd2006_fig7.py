#!/usr/bin/env python3
"""Redraws Lloyd et al. 2006 Fig 7 (the storage factor over the hemisphere of light directions,
uniform against LiSPSM, f/n = 1000, half fov 30°) from the Python API, with matplotlib.

    pip install ./python matplotlib
    python python/examples/lloyd2006_fig7.py [OUT.png]

Each panel is log10 S̄ over elevation (rows, 0 at the horizon to 90° overhead) and azimuth
(columns, 0 = light behind the viewer, 180° = in front), as `shadow_aliasing.sweep` returns it.
"""
from __future__ import annotations

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import shadow_aliasing as sa  # noqa: E402

NEAR, FAR, HALF_FOV = 1.0, 1000.0, np.pi / 6


def main(out: str = "lloyd2006_fig7.png") -> None:
    el, az = sa.sweep_angles(91, 360)
    panels = [("uniform", "Uniform (n′ = ∞)"), ("lispsm", "LiSPSM, n′ = (n + √(fn))/sin γ")]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    grids = [sa.sweep(NEAR, FAR, HALF_FOV, rule, elevations=91, azimuths=360) for rule, _ in panels]
    lo = min(np.log10(g).min() for g in grids)
    hi = max(np.log10(g).max() for g in grids)
    for ax, g, (_, title) in zip(axes, grids, panels):
        im = ax.pcolormesh(np.degrees(az), np.degrees(el), np.log10(g), vmin=lo, vmax=hi,
                           shading="nearest", cmap="viridis")
        ax.set_title(title)
        ax.set_xlabel("azimuth (°; 0 = light behind the viewer)")
        ax.set_ylabel("elevation (°; 90 = overhead)")
    fig.colorbar(im, ax=axes, label="log10 storage factor S̄")
    fig.suptitle("Lloyd et al. 2006 Fig 7: S̄ over light directions, f/n = 1000, θ = 30°")
    fig.savefig(out, dpi=110)
    print(f"wrote {out}; S̄ max uniform {grids[0].max():.4g}, LiSPSM {grids[1].max():.4g}")


if __name__ == "__main__":
    main(*sys.argv[1:])
