#!/usr/bin/env python3
"""Cascade planning for a scene: where to put the split planes of four cascades, judged by the
error each cascade's map leaves, with the crate's frame API (`shadow_aliasing.frame`).

    pip install ./python matplotlib
    python python/examples/cascade_planning.py [OUT.png]

The scene is a ground 400 × 400 (receivers) with a few buildings (casters), a camera 1.7 above
the ground looking ahead, and a low sun. For each split rule (Lloyd 2006's logarithmic planes,
uniform planes, the practical mix λ = 0.5 and 0.8, and equal-error splits) the frame builds one
LiSPSM-warped map per cascade, fitted to the cascade's slice of the visible scene, and measures
each map's largest perspective error in pixels (M_x, M_z over the map's focus body). The left
panel draws the planes, the right one each cascade's error: the plan with the lowest largest
error is the one to take.
"""
from __future__ import annotations

import sys
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import shadow_aliasing as sa  # noqa: E402

NEAR, FAR, HALF_FOV, ASPECT, K = 0.1, 300.0, np.radians(30.0), 16 / 9, 4
GROUND = [[[-200.0, -1.0, -200.0], [200.0, 0.0, 200.0]]]
BUILDINGS = [[[x - 4.0, 0.0, z - 4.0], [x + 4.0, h, z + 4.0]]
             for x, z, h in [(-12, -30, 18), (10, -60, 30), (-20, -110, 45), (25, -160, 25)]]
SUN = [0.45, -0.5, -0.35]            # low, ahead and to the right of the camera
# Plans: (label, frame keywords).
PLANS: list[tuple[str, dict[str, Any]]] = [
    ("log (Lloyd 2006 Eq 15)", {"partition": "log"}),
    ("uniform", {"partition": "uniform"}),
    ("practical λ = 0.5", {"partition": "practical", "lambda_": 0.5}),
    ("practical λ = 0.8", {"partition": "practical", "lambda_": 0.8}),
    ("equal error", {"partition": "equal_error"}),
]


def view_matrix() -> np.ndarray:
    """World → eye: the camera at (0, 1.7, 0) looking down −Z, pitched 5° down."""
    a = np.radians(5.0)
    pitch = np.array([[1, 0, 0, 0], [0, np.cos(a), np.sin(a), 0],
                      [0, -np.sin(a), np.cos(a), 0], [0, 0, 0, 1.0]])
    move = np.eye(4)
    move[1, 3] = -1.7
    return pitch @ move


def run() -> dict[str, dict[str, np.ndarray]]:
    plans = {}
    for label, kw in PLANS:
        f = sa.frame(view_matrix(), NEAR, FAR, HALF_FOV, SUN, aspect=ASPECT, receivers=GROUND,
                     casters=BUILDINGS + GROUND, scheme="cascades", rule="lispsm", k=K,
                     image_height=1080, map_resolution=2048, **kw)
        plans[label] = {"split": f["split"], "error": f["max_error_pixels"], "slot": f["slot"]}
    return plans


def main(path: str = "cascade_planning.png") -> None:
    plans = run()
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6), constrained_layout=True)
    styles = ["-o", "--s", "-.^", ":D", "-v"]
    for row, ((label, p), style) in enumerate(zip(plans.items(), styles)):
        planes = np.unique(p["split"].ravel())
        left.plot(planes, np.full_like(planes, row), style, label=label)
        right.plot(p["slot"] + 1, p["error"], style, label=label)
    left.set_xscale("log")
    left.set_yticks(range(len(plans)), list(plans), fontsize=8)
    left.set_xlabel("eye depth of the split planes (log)")
    left.set_title(f"{K} cascades, near {NEAR:g}, far {FAR:g}")
    right.set_yscale("log")
    right.set_xticks(range(1, K + 1))
    right.set_xlabel("cascade (near to far)")
    right.set_ylabel("largest error, pixels per texel (1080p, 2048² maps)")
    right.set_title("each cascade's measured error")
    right.legend(fontsize=8)
    fig.savefig(path, dpi=110)
    best = min(plans, key=lambda k: float(plans[k]["error"].max()))
    for label, p in plans.items():
        print(f"{label:24s} largest error {p['error'].max():8.3f} px  planes "
              + " ".join(f"{z:.4g}" for z in np.unique(p['split'].ravel())))
    print(f"wrote {path}; the plan with the lowest largest error: {best}")


if __name__ == "__main__":
    main(*sys.argv[1:])
