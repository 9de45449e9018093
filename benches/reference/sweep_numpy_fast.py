#!/usr/bin/env python3
"""The fastest vectorised NumPy hemisphere sweep of S̄ we could write (issue 13), for comparison with
`shadow-aliasing sweep --near 1 --far 1000 --half-fov 0.5235987755982988 --warp lispsm`.

Two forms, both checked against the crate's own output (`--check FILE.npy`):

* ``full`` (default): the same pipeline as the crate and as benches/reference/sweep_numpy.py
  (light space, the eight corners, the 1/sin γ n′, the fitted map's rows, the exact-derivative
  measurement m_x = h_w² |G_t⊥| / (|D| z tan θ), m_z = h_w² / (|G_t⊥| z tan θ) at the eight
  vertices), vectorised better than that reference:
  - sines and cosines of the grid's 1-D axes only (E + A of each, not E·A), broadcast;
  - the light-space basis in closed form per component, no `np.cross`/`np.linalg.norm`
    (x = y × z of two orthonormal vectors is unit);
  - the directions in blocks of whole elevation rows (at most 4 096 directions: two rows of
    1 440, the fastest block tried) so that every
    (block, 8) temporary stays in cache, with the block's arrays reused through ``out=``;
  - the matrix rows' products at the corners shared (h_w = ρ q_z + a is the fit's w).
* ``reduced``: the measurement above simplified by hand for this single fitted map:
  G_t = (k + ρ) z (so G_t · L = 0 and |G_t⊥| = k + ρ), D = (k + ρ) w / u_h, hence
  m_x = w u_h / (z tan θ) and m_z = w² / ((k + ρ) z tan θ) at each vertex, with w = 1 + ρ (q_z − z₀).
  A specialisation no general tool would make (it holds for this map, not for any matrix), the
  least NumPy work that still computes each direction's map; the crate does the general
  measurement.

Usage:

    python3 benches/reference/sweep_numpy_fast.py                      # time 360 × 1440, both forms
    python3 benches/reference/sweep_numpy_fast.py --check sweep.npy     # compare with the crate
    python3 benches/reference/sweep_numpy_fast.py --once 360 1440       # one timed run, in ms

Timing: in-process, after one warm-up run, median of repeated runs of the whole sweep (grid to S̄),
one core (NumPy's element-wise operations are single-threaded).
"""
import argparse
import time

import numpy as np

NEAR, FAR, HALF_FOV, ASPECT = 1.0, 1000.0, np.pi / 6.0, 1.0
PARALLEL_TOLERANCE = 1e-12


def axes(elevations, azimuths):
    """The crate's grid: el_i = i (π/2)/(E − 1) (E = 1: π/2), az_j = j 2π/A."""
    if elevations > 1:
        el = np.arange(elevations) * (np.pi / 2 / (elevations - 1))
    else:
        el = np.array([np.pi / 2])
    return el, np.arange(azimuths) * (2 * np.pi / azimuths)


def corners(near, far, half_fov, aspect):
    t = np.tan(half_fov)
    out = []
    for d in (near, far):
        h = d * t
        w = h * aspect
        out += [(-w, -h, -d), (w, -h, -d), (w, h, -d), (-w, h, -d)]
    return np.array(out).T.copy()[:, :, None]  # (3, 8, 1)


def basis(se, ce, sa, ca):
    """Light space per direction: y towards the light, z the view axis −Z made perpendicular
    to y (the crate's fallback when parallel), x = y × z; each a tuple of three (n,) arrays."""
    y0, y1, y2 = ce * sa, se * np.ones_like(sa), ce * ca
    # z = a − (y·a) y with a = (0, 0, −1), y·a = −y2.
    z0, z1, z2 = y2 * y0, y2 * y1, y2 * y2 - 1.0
    nz = np.sqrt(z0 * z0 + z1 * z1 + z2 * z2)
    par = nz < PARALLEL_TOLERANCE
    if par.any():
        # (0, 1, 0) − y1 y, or (1, 0, 0) − y0 y when that is short.
        fy = (-y1 * y0, 1.0 - y1 * y1, -y1 * y2)
        fx = (1.0 - y0 * y0, -y0 * y1, -y0 * y2)
        short = np.sqrt(fy[0] ** 2 + fy[1] ** 2 + fy[2] ** 2) < 0.5
        fb = [np.where(short, a, b) for a, b in zip(fx, fy)]
        z0, z1, z2 = (np.where(par, f, z) for f, z in zip(fb, (z0, z1, z2)))
        nz = np.sqrt(z0 * z0 + z1 * z1 + z2 * z2)
    inv = 1.0 / nz
    z0, z1, z2 = z0 * inv, z1 * inv, z2 * inv
    x0, x1, x2 = y1 * z2 - y2 * z1, y2 * z0 - y0 * z2, y0 * z1 - y1 * z0
    nx = 1.0 / np.sqrt(x0 * x0 + x1 * x1 + x2 * x2)
    x0, x1, x2 = x0 * nx, x1 * nx, x2 * nx
    # z = x × y, as the crate re-orthogonalises.
    z0, z1, z2 = x1 * y2 - x2 * y1, x2 * y0 - x0 * y2, x0 * y1 - x1 * y0
    return (x0, x1, x2), (y0, y1, y2), (z0, z1, z2)


def at(v, c):
    """v · c for every corner and direction: (8, n), corner-major, so that every NumPy inner
    loop runs over the n directions (with (n, 8) the inner loops are 8 long and their overhead
    dominates)."""
    return c[0] * v[0] + c[1] * v[1] + c[2] * v[2]


def block(se, ce, sa, ca, c, reduced, near=NEAR, far=FAR, half_fov=HALF_FOV, aspect=ASPECT):
    t = np.tan(half_fov)
    x, y, z = basis(se, ce, sa, ca)
    qx, qy, qz = at(x, c), at(y, c), at(z, c)
    zmin = qz.min(axis=0)
    delta = qz.max(axis=0) - zmin
    # L = −y; sin γ = |a × L| = √(Lx² + Ly²).
    sin_g = np.minimum(np.hypot(y[0], y[1]), 1.0)
    with np.errstate(divide="ignore", over="ignore"):
        n_prime = (near + np.sqrt(far * near)) / sin_g
        rho = np.where(np.isfinite(n_prime) & (n_prime > 0), 1.0 / n_prime, 0.0)
    # w = 1 + ρ (q_z − z₀): the fit's divisor and the matrix's h_w at the corners.
    w = qz - zmin
    w *= rho
    w += 1.0
    iw = 1.0 / w
    u = qx * iw
    v = np.multiply(qy, iw, out=qy)
    u0, u1 = u.min(axis=0), u.max(axis=0)
    v0, v1 = v.min(axis=0), v.max(axis=0)
    extent = far * (1.0 + t * (1.0 + aspect))
    u_h, u_m = 0.5 * (u1 - u0), 0.5 * (u1 + u0)
    v_h = np.maximum(0.5 * (v1 - v0), 1e-9 * extent)
    k = 2.0 / delta + rho
    depth_t = -c[2] * t  # (8, 1)
    if reduced:
        mx = w * (u_h / depth_t)
        mz = (w * w) * (1.0 / ((k + rho) * depth_t))
        return mx.max(axis=0) * mz.max(axis=0)
    aa = 1.0 - rho * zmin
    # Rows of W·R (the depth row is not measured): r0 = (x − u_m ρ z)/u_h | −u_m a/u_h,
    # r1 = k z | −1 − k z₀, r3 = ρ z | a.
    iuh = 1.0 / u_h
    r0 = [(xi - (u_m * rho) * zi) * iuh for xi, zi in zip(x, z)]
    r1 = [k * zi for zi in z]
    r3 = [rho * zi for zi in z]
    hx = at(r0, c)
    hx += -u_m * aa * iuh
    hy = np.multiply(qz, k, out=qz)
    hy += -1.0 - k * zmin
    hw = w
    gs = [hw * r0[i] - hx * r3[i] for i in range(3)]
    gt = [hw * r1[i] - hy * r3[i] for i in range(3)]
    lx, ly, lz = (-yi for yi in y)
    d = (gs[1] * gt[2] - gs[2] * gt[1]) * lx
    d += (gs[2] * gt[0] - gs[0] * gt[2]) * ly
    d += (gs[0] * gt[1] - gs[1] * gt[0]) * lz
    gtl = gt[0] * lx + gt[1] * ly + gt[2] * lz
    gtp = gt[0] * gt[0] + gt[1] * gt[1] + gt[2] * gt[2] - gtl * gtl
    np.sqrt(gtp, out=gtp)
    w2 = hw * hw
    mx = w2 * gtp / (np.abs(d) * depth_t)
    mz = w2 / (gtp * depth_t)
    return mx.max(axis=0) * mz.max(axis=0)


def sweep(elevations, azimuths, reduced=False, block_dirs=4096):
    """S̄ of every direction, shape (E, A), row i elevation i."""
    el, az = axes(elevations, azimuths)
    c = corners(NEAR, FAR, HALF_FOV, ASPECT)
    se, ce = np.sin(el), np.cos(el)
    sa, ca = np.sin(az), np.cos(az)
    rows = max(1, block_dirs // azimuths)
    out = np.empty((elevations, azimuths))
    for i in range(0, elevations, rows):
        r = slice(i, min(i + rows, elevations))
        m = r.stop - r.start
        s = block(
            np.repeat(se[r], azimuths),
            np.repeat(ce[r], azimuths),
            np.tile(sa, m),
            np.tile(ca, m),
            c,
            reduced,
        )
        out[r] = s.reshape(m, azimuths)
    return out


def time_it(elevations, azimuths, reduced, repeats):
    sweep(elevations, azimuths, reduced)  # warm-up
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        s = sweep(elevations, azimuths, reduced)
        times.append(time.perf_counter() - t0)
    assert np.isfinite(s).all() and (s > 0).all()
    return times


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--check", metavar="NPY", help="compare with the crate's `sweep --format npy`")
    p.add_argument("--once", nargs=2, type=int, metavar=("E", "A"), help="print one run's ms")
    p.add_argument("--reduced", action="store_true", help="the hand-reduced measurement")
    p.add_argument("--repeats", type=int, default=11)
    args = p.parse_args()
    if args.check:
        want = np.load(args.check)
        worst = 0.0
        for reduced in (False, True):
            got = sweep(*want.shape, reduced)
            rel = float(np.max(np.abs(got - want) / np.abs(want)))
            worst = max(worst, rel)
            print(f"{'reduced' if reduced else 'full'}: max relative difference {rel:.2e}")
        raise SystemExit(0 if worst <= 1e-9 else 1)
    if args.once:
        t0 = time.perf_counter()
        sweep(*args.once, args.reduced)
        print(f"{(time.perf_counter() - t0) * 1e3:.3f}")
        return
    print(f"numpy {np.__version__}, f/n = {FAR / NEAR:g}, half fov 30°, lispsm (1/sin γ)")
    for reduced in (False, True):
        ts = time_it(360, 1440, reduced, args.repeats)
        name = "reduced" if reduced else "full"
        print(f"360 x 1440 {name}: median {np.median(ts) * 1e3:.1f} ms, best {min(ts) * 1e3:.1f} ms")


if __name__ == "__main__":
    main()
