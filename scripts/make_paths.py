#!/usr/bin/env python3
"""Writes the camera paths of paths/ (docs/paths.md): five scripted paths, each 300 frames, over
one scene. Run from the repository root: `python3 scripts/make_paths.py`. Deterministic (no
randomness); numbers are rounded to 6 decimals so that the files are stable across platforms."""

import json
import math
import os

FRAMES = 300
IMAGE_HEIGHT = 1080
CAMERA = {"near": 0.1, "far": 300.0, "half_fov": 0.5236, "aspect": 1.7778}

# A ground 400 × 400 (its top at y = 0) and a few buildings on it.
GROUND = [-200.0, -1.0, -200.0, 200.0, 0.0, 200.0]
BUILDINGS = [
    [-8.0, 0.0, -40.0, -2.0, 6.0, -30.0],
    [4.0, 0.0, -90.0, 12.0, 15.0, -80.0],
    [-20.0, 0.0, -170.0, -5.0, 4.0, -150.0],
    [0.0, 0.0, -260.0, 30.0, 25.0, -240.0],
    [40.0, 0.0, 20.0, 60.0, 40.0, 40.0],
    [-70.0, 0.0, 60.0, -50.0, 12.0, 90.0],
]
SCENE = {"receivers": [GROUND] + BUILDINGS, "casters": BUILDINGS}
SUN = [0.3, -0.8, -0.4]


def r(v):
    return [round(x, 6) for x in v]


def walk_frame(i, z0=150.0, x=0.0):
    """Eye height 1.7, 0.9 units a frame along -z, looking ahead and slightly down."""
    z = z0 - 0.9 * i
    return {"eye": r([x, 1.7, z]), "target": r([x, 1.2, z - 10.0])}


def walk():
    return [walk_frame(i) for i in range(FRAMES)]


def flyover():
    """Climbs from 2 to 200 units (geometrically) while moving along -z, looking ahead and down."""
    out = []
    for i in range(FRAMES):
        t = i / (FRAMES - 1)
        h = 2.0 * 100.0 ** t
        z = 150.0 - 300.0 * t
        out.append({"eye": r([0.0, h, z]), "target": r([0.0, 0.0, z - 20.0 - 1.5 * h])})
    return out


def turn():
    """A full turn in place at eye height, 1.2° a frame, looking slightly down."""
    out = []
    for i in range(FRAMES):
        a = 2.0 * math.pi * i / FRAMES
        eye = [0.0, 1.7, 0.0]
        out.append({"eye": r(eye), "target": r([-10.0 * math.sin(a), 1.2, -10.0 * math.cos(a)])})
    return out


def sun_sweep():
    """A still camera; the sun rises in the east, culminates at 60° and sets in the west."""
    out = []
    for i in range(FRAMES):
        t = i / (FRAMES - 1)
        elevation = math.radians(10.0 + 50.0 * math.sin(math.pi * t))
        azimuth = math.pi * t  # 0: from +x (east), pi: from -x (west), over -z (south)
        towards_sun = [math.cos(azimuth) * math.cos(elevation), math.sin(elevation),
                       -math.sin(azimuth) * math.cos(elevation)]
        out.append({"eye": r([0.0, 1.7, 10.0]), "target": r([0.0, 1.2, 0.0]),
                    "light_dir": r([-c for c in towards_sun])})
    return out


def cut():
    """The walk's first 150 frames, then a jump to another street (x = 100), walking on."""
    return [walk_frame(i) if i < 150 else walk_frame(i - 150, z0=120.0, x=100.0)
            for i in range(FRAMES)]


PATHS = {
    "walk": ("A walk at eye height (1.7) along -z, 0.9 units a frame.", walk, True),
    "flyover": ("A fly-over climbing from 2 to 200 units along -z.", flyover, True),
    "turn": ("A full turn in place at eye height.", turn, True),
    "sun_sweep": ("A still camera under a day's sun: 10° to 60° and back to 10°, east to west.",
                  sun_sweep, False),
    "cut": ("The walk, cut at frame 150 to another street.", cut, True),
}


def main():
    os.makedirs("paths", exist_ok=True)
    for name, (description, make, constant_light) in PATHS.items():
        path = {"description": description, "image_height": IMAGE_HEIGHT, "camera": CAMERA,
                "scene": SCENE}
        if constant_light:
            path["light_dir"] = SUN
        path["frames"] = make()
        with open(os.path.join("paths", name + ".json"), "w", encoding="utf-8") as f:
            f.write("{\n")
            keys = list(path)
            for k in keys:
                end = ",\n" if k != keys[-1] else "\n"
                if k == "frames":
                    f.write('  "frames": [\n')
                    f.write(",\n".join("    " + json.dumps(x, ensure_ascii=False)
                                       for x in path[k]))
                    f.write("\n  ]" + end)
                else:
                    f.write("  " + json.dumps(k) + ": " + json.dumps(path[k], ensure_ascii=False)
                            + end)
            f.write("}\n")


if __name__ == "__main__":
    main()
