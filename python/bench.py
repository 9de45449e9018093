#!/usr/bin/env python3
"""Times the Python bindings against NumPy, in one run (docs/python.md reports the numbers).

1. A 1M-element closed-form call: ``storage_factor`` over arrays of near, far, half_fov, n′
   against benches/reference/closed_numpy.py (the same formula and domain checks in NumPy).
2. The 360 × 1440 hemisphere sweep of the lispsm (1/sin γ) map, f/n = 1000, half fov 30°,
   against benches/reference/sweep_numpy.py (vectorised, blocks of 4096 directions).

Both pairs are checked to agree (relative 1e-12 and 1e-9) before they are timed. Best and median
of repeated runs after a warm-up; the bindings use all cores (rayon), NumPy one.

    python python/bench.py [--repeats N]
"""
import argparse
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
# The installed package, not the source folder python/shadow_aliasing (which lacks _native).
sys.path = [p for p in sys.path if os.path.abspath(p or ".") != HERE]
import shadow_aliasing as sa  # noqa: E402

sys.path.append(os.path.join(HERE, "..", "benches", "reference"))
import closed_numpy  # noqa: E402
import sweep_numpy  # noqa: E402


def timed(f, repeats):
    f()
    ts = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        ts.append(time.perf_counter() - t0)
    return min(ts), float(np.median(ts))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--repeats", type=int, default=11)
    args = p.parse_args()
    print(f"numpy {np.__version__}, {os.cpu_count()} cores")

    rng = np.random.default_rng(1)
    n = 1_000_000
    near = rng.uniform(0.1, 10.0, n)
    far = near * rng.uniform(1.5, 1000.0, n)
    half_fov = rng.uniform(0.1, 1.4, n)
    n_prime = near * rng.uniform(1.0, 100.0, n)
    n_prime[::7] = np.inf
    a = sa.storage_factor(near, far, half_fov, n_prime)
    b = closed_numpy.storage_factor(near, far, half_fov, n_prime)
    assert np.allclose(a, b, rtol=1e-12, atol=0), np.max(np.abs(a / b - 1))
    rs, rm = timed(lambda: sa.storage_factor(near, far, half_fov, n_prime), args.repeats)
    ns, nm = timed(lambda: closed_numpy.storage_factor(near, far, half_fov, n_prime), args.repeats)
    print(f"storage_factor, 1M elements: bindings best {rs * 1e3:.2f} ms (median {rm * 1e3:.2f}), "
          f"numpy best {ns * 1e3:.2f} ms (median {nm * 1e3:.2f}): {ns / rs:.1f}x")

    z = near + (far - near) * rng.uniform(0.0, 1.0, n)
    a = sa.mx(near, far, n_prime, z)
    b = closed_numpy.mx(near, far, n_prime, z)
    assert np.allclose(a, b, rtol=1e-12, atol=0), np.max(np.abs(a / b - 1))
    rs, rm = timed(lambda: sa.mx(near, far, n_prime, z), args.repeats)
    ns, nm = timed(lambda: closed_numpy.mx(near, far, n_prime, z), args.repeats)
    print(f"mx, 1M elements: bindings best {rs * 1e3:.2f} ms (median {rm * 1e3:.2f}), "
          f"numpy best {ns * 1e3:.2f} ms (median {nm * 1e3:.2f}): {ns / rs:.1f}x")

    e, az = 360, 1440
    el_flat, az_flat = sweep_numpy.grid(e, az)
    s_rust = sa.sweep(1.0, 1000.0, np.pi / 6, "lispsm", elevations=e, azimuths=az)
    s_np = sweep_numpy.sweep_chunked(el_flat, az_flat, 4096).reshape(e, az)
    assert np.allclose(s_rust, s_np, rtol=1e-9, atol=0), np.max(np.abs(s_rust / s_np - 1))
    sweep_repeats = max(3, args.repeats // 2)
    rs, rm = timed(lambda: sa.sweep(1.0, 1000.0, np.pi / 6, "lispsm", elevations=e, azimuths=az),
                   sweep_repeats)
    ns, nm = timed(lambda: sweep_numpy.sweep_chunked(el_flat, az_flat, 4096), sweep_repeats)
    print(f"sweep {e} x {az}: bindings best {rs * 1e3:.2f} ms (median {rm * 1e3:.2f}), "
          f"numpy best {ns * 1e3:.2f} ms (median {nm * 1e3:.2f}): {ns / rs:.1f}x")


if __name__ == "__main__":
    main()
