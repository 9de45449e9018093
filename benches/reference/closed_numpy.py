#!/usr/bin/env python3
"""NumPy reference of the light-overhead storage factor (Lloyd 2006 Eq 12), for python/bench.py.

The same formula and the same domain checks as `shadow_aliasing.storage_factor` (src/analytic/
overhead.rs, src/frustum.rs), vectorised with one NumPy operation per step and no Python loop:

    S̄ = (f/n − 1) / (2 tan θ)                                  n ≤ n′ ≤ n + √(f n)
    S̄ = (f/n − 1) / (2 tan θ) · n′² f / (n (n′ + f − n)²)      n′ > n + √(f n)
    S̄ = (f/n − 1) / (2 tan θ) · f / n                          n′ = ∞

Inputs outside the domain (non-finite, near ≤ 0, far ≤ near, half_fov ∉ (0, π/2), n′ < near or
NaN) raise ValueError, as the bindings do; so the comparison includes validation on both sides.
"""
import numpy as np


def storage_factor(near, far, half_fov, n_prime):
    n, f, th, npr = np.broadcast_arrays(
        np.asarray(near, dtype=np.float64),
        np.asarray(far, dtype=np.float64),
        np.asarray(half_fov, dtype=np.float64),
        np.asarray(n_prime, dtype=np.float64),
    )
    ok = (
        np.isfinite(n) & (n > 0) & np.isfinite(f) & (f > n)
        & (th > 0) & (th < np.pi / 2) & (npr >= n)
    )
    if not ok.all():
        raise ValueError("argument outside the domain")
    base = (f / n - 1.0) / (2.0 * np.tan(th))
    lispsm = n + np.sqrt(f) * np.sqrt(n)
    unwarped = np.isinf(npr)
    with np.errstate(invalid="ignore"):
        r = npr / (npr + f - n)
        factor = np.where(npr <= lispsm, 1.0, r * r * f / n)
    factor = np.where(unwarped, f / n, factor)
    out = base * factor
    if not np.isfinite(out).all():
        raise ValueError("storage factor is not finite")
    return out


def mx(near, far, n_prime, z, res_image=1.0, res_s=1.0):
    """Lloyd 2006 Eq 7 with the bindings' domain checks:
    m_x = (res_image/res_s) f (n′ + z − n)/(z (n′ + f − n)), (res_image/res_s) f/z for n′ = ∞."""
    n, f, npr, zz, ri, rs = np.broadcast_arrays(
        *(np.asarray(a, dtype=np.float64) for a in (near, far, n_prime, z, res_image, res_s))
    )
    ok = (
        np.isfinite(n) & (n > 0) & np.isfinite(f) & (f > n) & (npr >= n)
        & np.isfinite(zz) & (zz >= n) & (zz <= f)
        & np.isfinite(ri) & (ri > 0) & np.isfinite(rs) & (rs > 0)
    )
    if not ok.all():
        raise ValueError("argument outside the domain")
    with np.errstate(invalid="ignore"):
        shape = np.where(np.isinf(npr), f / zz, f / zz * ((npr + zz - n) / (npr + f - n)))
    out = ri / rs * shape
    if not np.isfinite(out).all():
        raise ValueError("m_x is not finite")
    return out
