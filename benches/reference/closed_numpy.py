#!/usr/bin/env python3
"""NumPy references of the element-wise closed forms, for python/bench.py: the light-overhead
errors and storage factor (Lloyd 2006 Eq 7–12), n′_LSPSM, η ↔ n′ (Eq 11, App. B) and Lloyd 2005's
g(z) (Eq 3).

Each has the same formula and the same domain checks as the bindings (src/analytic/, src/
frustum.rs), vectorised with one NumPy operation per step and no Python loop. The first,
`storage_factor`:

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


def _arrays(*args):
    return np.broadcast_arrays(*(np.asarray(a, dtype=np.float64) for a in args))


def _near_far_ok(n, f):
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        return np.isfinite(n) & (n > 0) & np.isfinite(f) & (f > n) & np.isfinite(f / n)


def _view_ok(n, f, th):
    """The frustum's domain (src/frustum.rs): near/far, θ ∈ (0, π/2); tan θ returned."""
    t = np.tan(th)
    ok = _near_far_ok(n, f) & (th > 0) & (th < np.pi / 2)
    return ok, t


def _finite_or_raise(out, what):
    if not np.isfinite(out).all():
        raise ValueError(f"{what} is not finite")
    return out


def mz(near, far, half_fov, n_prime, z, res_image=1.0, res_t=1.0):
    """Lloyd 2006 Eq 8: (res_image/res_t)(f − n)/(2 tan θ) (n′ + z − n)²/(z n′ (n′ + f − n)),
    1/z for n′ = ∞, with the bindings' domain checks."""
    n, f, th, npr, zz, ri, rt = _arrays(near, far, half_fov, n_prime, z, res_image, res_t)
    ok, t = _view_ok(n, f, th)
    ok &= (npr >= n) & np.isfinite(zz) & (zz >= n) & (zz <= f)
    ok &= np.isfinite(ri) & (ri > 0) & np.isfinite(rt) & (rt > 0)
    if not ok.all():
        raise ValueError("argument outside the domain")
    with np.errstate(invalid="ignore"):
        zp = npr + zz - n
        shape = np.where(np.isinf(npr), 1.0 / zz, (zp / (npr + f - n)) * (zp / npr) / zz)
    return _finite_or_raise(ri / rt * (f - n) / (2.0 * t) * shape, "m_z")


def max_mx(near, far, n_prime, res_image=1.0, res_s=1.0):
    """Lloyd 2006 Eq 9: m_x at z = near."""
    return mx(near, far, n_prime, near, res_image, res_s)


def max_mz(near, far, half_fov, n_prime, res_image=1.0, res_t=1.0):
    """Lloyd 2006 Eq 10, the far-plane branch up to n′_LSPSM = n + √(f n), the near-plane above."""
    n, f, th, npr, ri, rt = _arrays(near, far, half_fov, n_prime, res_image, res_t)
    ok, t = _view_ok(n, f, th)
    ok &= (npr >= n) & np.isfinite(ri) & (ri > 0) & np.isfinite(rt) & (rt > 0)
    if not ok.all():
        raise ValueError("argument outside the domain")
    lispsm = n + np.sqrt(f) * np.sqrt(n)
    with np.errstate(invalid="ignore"):
        shape = np.where(npr <= lispsm, (npr + f - n) / f / npr, npr / (npr + f - n) / n)
    shape = np.where(np.isinf(npr), 1.0 / n, shape)
    return _finite_or_raise(ri / rt * (f - n) / (2.0 * t) * shape, "M_z")


def n_prime_lispsm(near, far):
    """n′ = n + √(f n) (Lloyd 2006 §4.1)."""
    n, f = _arrays(near, far)
    if not _near_far_ok(n, f).all():
        raise ValueError("argument outside the domain")
    return _finite_or_raise(n + np.sqrt(f) * np.sqrt(n), "n_prime")


def n_prime_from_eta(near, far, eta):
    """Lloyd 2006 Eq 11; ∞ for η = −1."""
    n, f, e = _arrays(near, far, eta)
    if not (_near_far_ok(n, f) & (e >= -1) & (e <= 1)).all():
        raise ValueError("argument outside the domain")
    a = f / n
    ra = np.sqrt(a)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        below = n * ((ra + 1 - e * (a - 1)) / (e + 1))
        below = np.where((e == -1) | ~np.isfinite(below), np.inf, below)
        above = n * ((ra + 1) / (e * ra + 1))
    out = np.where(e <= 0, below, above)
    if not np.isfinite(out[e > 0]).all():
        raise ValueError("n_prime is not finite")
    return out


def eta_from_n_prime(near, far, n_prime):
    """Lloyd 2006 App. B, the inverse of Eq 11; −1 for n′ = ∞."""
    n, f, npr = _arrays(near, far, n_prime)
    if not (_near_far_ok(n, f) & (npr >= n)).all():
        raise ValueError("argument outside the domain")
    a = f / n
    ra = np.sqrt(a)
    nu = npr / n
    with np.errstate(invalid="ignore"):
        eta = np.where(nu >= 1 + ra, (ra + 1 - nu) / (nu + a - 1), (ra + 1 - nu) / (nu * ra))
    return np.where(np.isfinite(nu), np.clip(eta, -1, 1), -1.0)


def distribution_g(alpha, n_warp, z):
    """Lloyd 2005 Eq 3: g(z) = (z − 1 + n)²/(z n (n + α − 1)), 1/z for n = ∞."""
    a, nw, zz = _arrays(alpha, n_warp, z)
    ok = np.isfinite(a) & (a > 1) & (nw >= 1) & np.isfinite(zz) & (zz >= 1) & (zz <= a)
    if not ok.all():
        raise ValueError("argument outside the domain")
    with np.errstate(invalid="ignore"):
        zp = zz - 1 + nw
        g = np.where(np.isinf(nw), 1 / zz, (zp / (nw + a - 1)) * (zp / nw) / zz)
    return _finite_or_raise(g, "g")
