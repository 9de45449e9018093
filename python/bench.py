#!/usr/bin/env python3
"""Times the Python bindings against NumPy, in one run (docs/python.md reports the numbers).

1. Every element-wise closed form with a NumPy reference, 1M elements, every argument an array
   (random, inside the domain; n′ and Zhang's λ = ∞ for every 7th element), against
   benches/reference/closed_numpy.py (the same formula and domain checks in NumPy); the forms
   with tan θ also with θ one number.
2. The 360 × 1440 hemisphere sweep of the lispsm (1/sin γ) map, f/n = 1000, half fov 30°,
   against benches/reference/sweep_numpy.py (vectorised, blocks of 4096 directions).

Each pair is checked to agree (relative 1e-12, sweep 1e-9) before it is timed. Best and median
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


def compare(label, ours, theirs, args, repeats, rtol=1e-12):
    a = ours(*args)
    b = theirs(*args)
    both = np.isfinite(b)
    assert np.array_equal(np.isinf(a), np.isinf(b)), label
    assert np.allclose(a[both], b[both], rtol=rtol, atol=0), (label, np.max(np.abs(a / b - 1)))
    rs, rm = timed(lambda: ours(*args), repeats)
    ns, nm = timed(lambda: theirs(*args), repeats)
    print(f"| {label} | {rs * 1e3:.2f} ms ({rm * 1e3:.2f}) | {ns * 1e3:.2f} ms ({nm * 1e3:.2f}) "
          f"| {ns / rs:.1f}x |", flush=True)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--repeats", type=int, default=11)
    args = p.parse_args()
    r = args.repeats
    print(f"numpy {np.__version__}, {os.cpu_count()} cores, load average "
          f"{' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print("| call, 1M elements | bindings best (median) | NumPy best (median) | ratio |")
    print("|---|---|---|---|")

    rng = np.random.default_rng(1)
    n = 1_000_000
    near = rng.uniform(0.1, 10.0, n)
    far = near * rng.uniform(1.5, 1000.0, n)
    half_fov = rng.uniform(0.1, 1.4, n)
    n_prime = near * rng.uniform(1.0, 100.0, n)
    n_prime[::7] = np.inf
    z = near + (far - near) * rng.uniform(0.0, 1.0, n)
    eta = rng.uniform(-1.0, 1.0, n)
    alpha = far / near
    n_warp = n_prime / near
    zg = 1.0 + (alpha - 1.0) * rng.uniform(0.0, 1.0, n)
    # TSM: height λ, focus δ′ ∈ (0, λ), ξ ∈ (−1, 1) below the unwarped line 1 − 2δ′/λ.
    lam = rng.uniform(0.1, 100.0, n)
    frac = rng.uniform(0.01, 0.99, n)
    delta = lam * frac
    xi = -1.0 + (2.0 - 2.0 * frac) * rng.uniform(0.01, 0.99, n)
    # Zhang's λ: any λ > 0 (below near too), ∞ for every 7th; light angles in [0, π/2] (tilted
    # m_z: > 0); y across the frustum's vertical section at z, for θ an array and θ = 0.5.
    zl = near * 10.0 ** rng.uniform(-1.0, 2.0, n)
    zl[::7] = np.inf
    light = rng.uniform(0.0, np.pi / 2, n)
    light_pos = rng.uniform(0.01, np.pi / 2, n)
    u = rng.uniform(-1.0, 1.0, n)
    y = z * np.tan(half_fov) * u
    y_one = z * np.tan(0.5) * u
    k = rng.integers(1, 17, n).astype(np.float64)
    c = closed_numpy
    for label, ours, theirs, a in [
        ("`mx`", sa.mx, c.mx, (near, far, n_prime, z)),
        ("`max_mx`", sa.max_mx, c.max_mx, (near, far, n_prime)),
        ("`n_prime_lispsm`", sa.n_prime_lispsm, c.n_prime_lispsm, (near, far)),
        ("`n_prime_from_eta`", sa.n_prime_from_eta, c.n_prime_from_eta, (near, far, eta)),
        ("`eta_from_n_prime`", sa.eta_from_n_prime, c.eta_from_n_prime, (near, far, n_prime)),
        ("`distribution_g`", sa.distribution_g, c.distribution_g, (alpha, n_warp, zg)),
        ("`mz`", sa.mz, c.mz, (near, far, half_fov, n_prime, z)),
        ("`max_mz`", sa.max_mz, c.max_mz, (near, far, half_fov, n_prime)),
        ("`storage_factor`", sa.storage_factor, c.storage_factor, (near, far, half_fov, n_prime)),
        ("`mz`, θ one number", sa.mz, c.mz, (near, far, 0.5, n_prime, z)),
        ("`max_mz`, θ one number", sa.max_mz, c.max_mz, (near, far, 0.5, n_prime)),
        ("`storage_factor`, θ one number", sa.storage_factor, c.storage_factor,
         (near, far, 0.5, n_prime)),
        ("`tsm_eta`", sa.tsm_eta, c.tsm_eta, (lam, delta, xi)),
        ("`zhang_eq_local`", sa.zhang_eq_local, c.zhang_eq_local, (near, far, half_fov, zl, z)),
        ("`zhang_ep_local`", sa.zhang_ep_local, c.zhang_ep_local, (near, far, half_fov, zl, z)),
        ("`zhang_ep_local`, θ one number", sa.zhang_ep_local, c.zhang_ep_local,
         (near, far, 0.5, zl, z)),
        ("`subdivided_max_error`", sa.subdivided_max_error, c.subdivided_max_error,
         (alpha, k, eta, half_fov)),
        ("`subdivided_max_error`, θ one number", sa.subdivided_max_error,
         c.subdivided_max_error, (alpha, k, eta, 0.5)),
        ("`gamma_lim`", sa.gamma_lim, c.gamma_lim, (near, far, half_fov)),
        ("`gamma_lim`, θ one number", sa.gamma_lim, c.gamma_lim, (near, far, 0.5)),
        ("`zhang_eq`", sa.zhang_eq, c.zhang_eq, (near, far, half_fov, zl, light, y, z)),
        ("`zhang_eq`, θ one number", sa.zhang_eq, c.zhang_eq,
         (near, far, 0.5, zl, light, y_one, z)),
        ("`zhang_ep`", sa.zhang_ep, c.zhang_ep, (near, far, half_fov, zl, light, y, z)),
        ("`zhang_ep`, θ one number", sa.zhang_ep, c.zhang_ep,
         (near, far, 0.5, zl, light, y_one, z)),
        ("`tilted_mz`", sa.tilted_mz, c.tilted_mz, (near, far, half_fov, n_prime, light_pos, z)),
        ("`tilted_mz`, θ one number", sa.tilted_mz, c.tilted_mz,
         (near, far, 0.5, n_prime, light_pos, z)),
    ]:
        compare(label, ours, theirs, a, r)
    t = np.empty(n)
    ts, tm = timed(lambda: np.tan(half_fov, out=t), r)
    print(f"(NumPy's np.tan alone, 1M elements: {ts * 1e3:.2f} ms; f64::tan (libm) is the "
          f"bindings' tan)")

    e, az = 360, 1440
    el_flat, az_flat = sweep_numpy.grid(e, az)
    s_rust = sa.sweep(1.0, 1000.0, np.pi / 6, "lispsm", elevations=e, azimuths=az)
    s_np = sweep_numpy.sweep_chunked(el_flat, az_flat, 4096).reshape(e, az)
    assert np.allclose(s_rust, s_np, rtol=1e-9, atol=0), np.max(np.abs(s_rust / s_np - 1))
    sweep_repeats = max(3, r // 2)
    rs, rm = timed(lambda: sa.sweep(1.0, 1000.0, np.pi / 6, "lispsm", elevations=e, azimuths=az),
                   sweep_repeats)
    ns, nm = timed(lambda: sweep_numpy.sweep_chunked(el_flat, az_flat, 4096), sweep_repeats)
    print(f"| `sweep` {e} x {az} | {rs * 1e3:.2f} ms ({rm * 1e3:.2f}) | "
          f"{ns * 1e3:.2f} ms ({nm * 1e3:.2f}) | {ns / rs:.1f}x |")


if __name__ == "__main__":
    main()
