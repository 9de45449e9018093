#!/usr/bin/env python3
"""NumPy reference of the hemisphere sweep of S̄ (issue 5's "ten times faster than NumPy" target).

The same computation as `shadow-aliasing sweep --near 1 --far 1000 --half-fov 0.5235987755982988
--warp lispsm-sin` (src/scheme/sweep.rs, src/maps/warp.rs, src/measure/mod.rs), vectorised over
all directions at once, one NumPy array operation per step, no Python loop over directions:

1. directions: D = (cos el sin az, sin el, cos el cos az) towards the light, light travels −D;
   el_i = i (π/2)/(E − 1) for i = 0..E (both ends), az_j = j 2π/A for j = 0..A (2π excluded);
2. light space with the view direction −Z as the warp axis (y = −L, z = axis ⊥ y, x = y × z,
   with the crate's fallback to eye up when the axis is parallel to the light);
3. the eight frustum corners in light space, their extent Δ along the warp axis, sin γ;
4. n′ = (n + √(f n))/sin γ (the 1/sin γ rule; unwarped when sin γ = 0 or the quotient overflows),
   ρ = 1/n′;
5. the fitted warp's rows (Lloyd 2006 §4 in ρ form, src/maps/warp.rs `warp_matrix`) composed with
   the light-space rotation: the 4 × 4 shadow matrix of every direction;
6. the measurement at the eight vertices from the exact derivatives of s and t (src/measure):
   m_x = h_w² |G_t⊥| / (|D| z tan θ), m_z = h_w² / (|G_t⊥| z tan θ), S̄ = max m_x · max m_z.

Usage:

    python3 benches/reference/sweep_numpy.py                 # time 90 × 360 and 360 × 1440
    python3 benches/reference/sweep_numpy.py --csv 90 360    # print the CSV the CLI prints

Timing: median of repeated runs of the whole vectorised sweep (directions to S̄), in-process,
after one warm-up run, single process (NumPy's element-wise operations use one core). The
directions are processed in blocks of --chunk (4096 by default) so that the (chunk, 8)
temporaries stay in cache: on this machine that is 1.5–2× faster at 360 × 1440 than one block.
"""
import argparse
import sys
import time

import numpy as np

NEAR, FAR, HALF_FOV, ASPECT = 1.0, 1000.0, np.pi / 6.0, 1.0
PARALLEL_TOLERANCE = 1e-12


def corners(near, far, half_fov, aspect):
    t = np.tan(half_fov)
    out = []
    for d in (near, far):
        h = d * t
        w = h * aspect
        out += [(-w, -h, -d), (w, -h, -d), (w, h, -d), (-w, h, -d)]
    return np.array(out)  # (8, 3)


def grid(elevations, azimuths):
    el = np.arange(elevations) * (np.pi / 2 / (elevations - 1)) if elevations > 1 else np.array([np.pi / 2])
    az = np.arange(azimuths) * (2 * np.pi / azimuths)
    return np.repeat(el, azimuths), np.tile(az, elevations)


def sweep(el, az, near=NEAR, far=FAR, half_fov=HALF_FOV, aspect=ASPECT):
    """S̄ of the lispsm-sin map for every direction (el[i], az[i])."""
    c = corners(near, far, half_fov, aspect)
    t = np.tan(half_fov)
    se, ce = np.sin(el), np.cos(el)
    sa, ca = np.sin(az), np.cos(az)
    # Towards the light (unit): y of light space; light travels L = −y.
    y = np.stack([ce * sa, se, ce * ca], axis=1)
    y /= np.linalg.norm(y, axis=1, keepdims=True)
    L = -y
    # Warp axis a = −Z projected perpendicular to y, with the crate's fallback.
    a = np.array([0.0, 0.0, -1.0])
    z = a - (y @ a)[:, None] * y
    par = np.linalg.norm(z, axis=1) < PARALLEL_TOLERANCE
    if par.any():
        zy = np.array([0.0, 1.0, 0.0]) - y[:, 1:2] * y
        zx = np.array([1.0, 0.0, 0.0]) - y[:, 0:1] * y
        fb = np.where((np.linalg.norm(zy, axis=1) < 0.5)[:, None], zx, zy)
        z = np.where(par[:, None], fb, z)
    z /= np.linalg.norm(z, axis=1, keepdims=True)
    x = np.cross(y, z)
    x /= np.linalg.norm(x, axis=1, keepdims=True)
    z = np.cross(x, y)
    # Corners in light space, (N, 8).
    qx, qy, qz = x @ c.T, y @ c.T, z @ c.T
    z0 = qz.min(axis=1)
    delta = qz.max(axis=1) - z0
    # sin γ = |a × L| = √(Lx² + Ly²) for a = −Z.
    sin_g = np.minimum(np.hypot(L[:, 0], L[:, 1]), 1.0)
    with np.errstate(divide="ignore", over="ignore"):
        n_prime = (near + np.sqrt(far * near)) / sin_g
        rho = np.where(np.isfinite(n_prime) & (n_prime > 0), 1.0 / n_prime, 0.0)
    # Fit u = x/w, v = y/w.
    w = 1.0 + rho[:, None] * (qz - z0[:, None])
    u, v = qx / w, qy / w
    u0, u1 = u.min(axis=1), u.max(axis=1)
    v0, v1 = v.min(axis=1), v.max(axis=1)
    extent = far * (1.0 + t * (1.0 + aspect))
    u_h, u_m = 0.5 * (u1 - u0), 0.5 * (u1 + u0)
    v_h, v_m = np.maximum(0.5 * (v1 - v0), 1e-9 * extent), 0.5 * (v1 + v0)
    aa = 1.0 - rho * z0
    k = 2.0 / delta + rho
    # Rows of W (light space → clip), W·R with R the rotation with rows x, y, z:
    # row0 = (1/u_h, 0, −u_m ρ/u_h | −u_m a/u_h), row1 = (0, 0, k | −1 − k z0),
    # row3 = (0, 0, ρ | a). The depth row is not measured.
    r0 = x / u_h[:, None] - (u_m * rho / u_h)[:, None] * z
    r0w = -u_m * aa / u_h
    r1 = k[:, None] * z
    r1w = -1.0 - k * z0
    r3 = rho[:, None] * z
    r3w = aa
    # Measurement at the vertices, component by component on (N, 8) arrays.
    cx, cy, cz = c[:, 0], c[:, 1], c[:, 2]

    def at_corners(r, rw):
        return np.outer(r[:, 0], cx) + np.outer(r[:, 1], cy) + np.outer(r[:, 2], cz) + rw[:, None]

    hx, hy, hw = at_corners(r0, r0w), at_corners(r1, r1w), at_corners(r3, r3w)
    gs = [hw * r0[:, i : i + 1] - hx * r3[:, i : i + 1] for i in range(3)]
    gt = [hw * r1[:, i : i + 1] - hy * r3[:, i : i + 1] for i in range(3)]
    lx, ly, lz = L[:, 0:1], L[:, 1:2], L[:, 2:3]
    d = (
        (gs[1] * gt[2] - gs[2] * gt[1]) * lx
        + (gs[2] * gt[0] - gs[0] * gt[2]) * ly
        + (gs[0] * gt[1] - gs[1] * gt[0]) * lz
    )
    gtl = gt[0] * lx + gt[1] * ly + gt[2] * lz
    gtp = np.sqrt(gt[0] * gt[0] + gt[1] * gt[1] + gt[2] * gt[2] - gtl * gtl)
    depth_t = -cz * t
    w2 = hw * hw
    mx = w2 * gtp / (np.abs(d) * depth_t)
    mz = w2 / (gtp * depth_t)
    return mx.max(axis=1) * mz.max(axis=1)


def sweep_chunked(el, az, chunk):
    """`sweep` over blocks of `chunk` directions, so the (chunk, 8) temporaries stay in cache."""
    out = np.empty(len(el))
    for i in range(0, len(el), chunk):
        out[i : i + chunk] = sweep(el[i : i + chunk], az[i : i + chunk])
    return out


def time_it(elevations, azimuths, repeats, chunk):
    el, az = grid(elevations, azimuths)
    sweep_chunked(el, az, chunk)  # warm-up
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        s = sweep_chunked(el, az, chunk)
        times.append(time.perf_counter() - t0)
    assert np.isfinite(s).all() and (s > 0).all()
    return float(np.median(times)), float(np.min(times))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--csv", nargs=2, type=int, metavar=("ELEVATIONS", "AZIMUTHS"))
    p.add_argument("--repeats", type=int, default=21)
    p.add_argument("--chunk", type=int, default=4096, help="directions per vectorised block")
    args = p.parse_args()
    if args.csv:
        el, az = grid(*args.csv)
        s = sweep_chunked(el, az, args.chunk)
        out = sys.stdout
        out.write("elevation,azimuth,storage_factor\n")
        for e, a, v in zip(el, az, s):
            out.write(f"{float(e)!r},{float(a)!r},{float(v)!r}\n")
        return
    print(f"numpy {np.__version__}, f/n = {FAR / NEAR:g}, half fov 30°, lispsm-sin, chunk {args.chunk}")
    for e, a, r in [(90, 360, args.repeats), (360, 1440, max(3, args.repeats // 4))]:
        med, best = time_it(e, a, r, args.chunk)
        print(f"{e} x {a}: median {med * 1e3:.2f} ms, best {best * 1e3:.2f} ms ({r} runs)")


if __name__ == "__main__":
    main()
