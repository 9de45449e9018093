#!/usr/bin/env python3
"""NumPy references of the element-wise closed forms, for python/bench.py: the light-overhead
errors and storage factor (Lloyd 2006 Eq 7–12), n′_LSPSM, η ↔ n′ (Eq 11, App. B), Lloyd 2005's
g(z) (Eq 3) and subdivided maximum error (Eq 7), TSM's η (Martin–Tan §6.2), Zhang's E_q, E_p
(Eq 8, 9, 13, 14), Barroso's tilted m_z (Eq 10–12) and γ_lim (Eq 15).

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


def _view_ok_no_tan(n, f, th):
    """The frustum's domain as `_view_ok` checks it, for forms whose value needs no tan θ."""
    return _near_far_ok(n, f) & (th > 0) & (th < np.pi / 2)


def _point_ok(n, f, t, y, z):
    """near ≤ z ≤ far and |y| ≤ z tan θ (1 + 1e-12), as `point_in_view` (src/analytic/global.rs)."""
    return (np.isfinite(z) & (z >= n) & (z <= f) & np.isfinite(y)
            & (np.abs(y) <= z * t * (1.0 + 1e-12)))


def _angle_ok(g):
    return np.isfinite(g) & (g >= 0) & (g <= np.pi / 2)


def tsm_eta(lambda_, delta_prime, xi):
    """Martin–Tan §6.2: η = λ δ′ (1 + ξ)/(λ (1 − ξ) − 2 δ′), ∞ on the unwarped line, ValueError
    above it (no solution) and outside λ > 0, δ′ ∈ (0, λ), ξ ∈ (−1, 1)."""
    lam, d, xi = _arrays(lambda_, delta_prime, xi)
    ok = np.isfinite(lam) & (lam > 0) & (d > 0) & (d < lam) & (xi > -1) & (xi < 1)
    if not ok.all():
        raise ValueError("argument outside the domain")
    den = lam * (1.0 - xi) - 2.0 * d
    if (den < 0).any():
        raise ValueError("no solution: xi above the unwarped line")
    unwarped = den == 0
    with np.errstate(divide="ignore", invalid="ignore"):
        eta = lam * d * (1.0 + xi) / den
    if not (np.isfinite(eta[~unwarped]).all() and (eta[~unwarped] > 0).all()):
        raise ValueError("tsm_eta is not finite and positive")
    return np.where(unwarped, np.inf, eta)


def zhang_eq_local(near, far, half_fov, lambda_, z):
    """Zhang Eq 8: 2 f (z − n + λ)/((f − n + λ) z) for λ ≥ n, 2 n (z − n + λ)/(λ z) for λ < n,
    2 f/z for λ = ∞."""
    n, f, th, lam, zz = _arrays(near, far, half_fov, lambda_, z)
    ok = _view_ok_no_tan(n, f, th) & (lam > 0) & np.isfinite(zz) & (zz >= n) & (zz <= f)
    if not ok.all():
        raise ValueError("argument outside the domain")
    with np.errstate(invalid="ignore"):
        w = zz - n + lam
        far_bound = 2.0 * f * w / ((f - n + lam) * zz)
        near_bound = 2.0 * n * w / (lam * zz)
        out = np.where(np.isinf(lam), 2.0 * f / zz, np.where(lam >= n, far_bound, near_bound))
    return _finite_or_raise(out, "E_q")


def zhang_ep_local(near, far, half_fov, lambda_, z):
    """Zhang Eq 9: (f − n)(z − n + λ)²/((f − n + λ) λ tan φ z), (f − n)/(tan φ z) for λ = ∞."""
    n, f, th, lam, zz = _arrays(near, far, half_fov, lambda_, z)
    ok, t = _view_ok(n, f, th)
    ok &= (lam > 0) & np.isfinite(zz) & (zz >= n) & (zz <= f)
    if not ok.all():
        raise ValueError("argument outside the domain")
    unwarped = (f - n) / (t * zz)
    with np.errstate(invalid="ignore"):
        w = zz - n + lam
        out = np.where(np.isinf(lam), unwarped, unwarped * (w / lam) * (w / (f - n + lam)))
    return _finite_or_raise(out, "E_p")


def _zhang_parts(n, f, th, t, g, y, zz):
    """sin θ, cos θ, the branch θ ≥ φ, μ (Zhang Appendix, Barroso Eq 11) and z_w − λ."""
    s, c = np.sin(g), np.cos(g)
    upper = g >= th
    tc = t * c
    mu = np.where(upper, f * ((1.0 + n / f) * tc) + (f - n) * s, f * (2.0 * tc))
    offset = np.where(upper, (zz - n) * s + (n * t - y) * c, (zz - f) * s + (f * t - y) * c)
    return s, c, upper, mu, offset


def _zhang_point(near, far, half_fov, lambda_, light_angle, y, z):
    """The arguments of Zhang's global forms as arrays, checked as the bindings check them, and
    their parts: (n, f, tan φ, λ, z, sin θ, cos θ, μ, z_w − λ)."""
    n, f, th, lam, g, yy, zz = _arrays(near, far, half_fov, lambda_, light_angle, y, z)
    ok, t = _view_ok(n, f, th)
    ok &= (lam > 0) & _angle_ok(g) & _point_ok(n, f, t, yy, zz)
    if not ok.all():
        raise ValueError("argument outside the domain")
    s, c, _, mu, offset = _zhang_parts(n, f, th, t, g, yy, zz)
    return n, f, t, lam, zz, s, c, mu, offset


def zhang_eq(near, far, half_fov, lambda_, light_angle, y, z):
    """Zhang Eq 13: E_q = 2 tan φ_w z_w/(tan φ z), 2 f/z for λ = ∞, with tan φ_w the fitted
    warping frustum's (the crate's form, docs/errata.md)."""
    n, f, t, lam, zz, s, c, _, offset = _zhang_point(near, far, half_fov, lambda_,
                                                     light_angle, y, z)
    with np.errstate(invalid="ignore"):
        zw = lam + offset
        d = (f - n) * (s - t * c)
        tan_phi_w = np.maximum(n * t / (lam + np.maximum(-d, 0.0)),
                               f * t / (lam + np.maximum(d, 0.0)))
        out = np.where(np.isinf(lam), 2.0 * f / zz, 2.0 * tan_phi_w * zw / (t * zz))
    return _finite_or_raise(out, "E_q")


def zhang_ep(near, far, half_fov, lambda_, light_angle, y, z):
    """Zhang Eq 14: E_p = μ z_w²/(tan φ (λ + μ) λ z), μ/(tan φ z) for λ = ∞."""
    n, f, t, lam, zz, _, _, mu, offset = _zhang_point(near, far, half_fov, lambda_,
                                                      light_angle, y, z)
    _finite_or_raise(mu, "mu")
    unwarped = mu / (t * zz)
    with np.errstate(invalid="ignore"):
        zw = lam + offset
        out = np.where(np.isinf(lam), unwarped, unwarped * (zw / lam) * (zw / (lam + mu)))
    return _finite_or_raise(out, "E_p")


def tilted_mz(near, far, half_fov, n_prime, light_angle, z, res_image=1.0, res_t=1.0):
    """Barroso Eq 12: (res_image/res_t) μ ψ²/(2 tan φ n′ (n′ + μ) z sin γ), ψ the warp depth
    (Eq 10), μ (Eq 11); (res_image/res_t) μ/(2 tan φ z sin γ) for n′ = ∞; γ ∈ (0, π/2]."""
    n, f, th, npr, g, zz, ri, rt = _arrays(near, far, half_fov, n_prime, light_angle, z,
                                           res_image, res_t)
    ok, t = _view_ok(n, f, th)
    ok &= (npr > 0) & _angle_ok(g) & (g > 0) & np.isfinite(zz) & (zz >= n) & (zz <= f)
    ok &= np.isfinite(ri) & (ri > 0) & np.isfinite(rt) & (rt > 0)
    if not ok.all():
        raise ValueError("argument outside the domain")
    s, c = np.sin(g), np.cos(g)
    upper = g >= th
    tc = t * c
    mu = _finite_or_raise(
        np.where(upper, f * ((1.0 + n / f) * tc) + (f - n) * s, f * (2.0 * tc)), "mu")
    k = ri / rt / (2.0 * t) * mu / zz
    with np.errstate(invalid="ignore"):
        psi = npr + np.where(upper, n * tc + (zz - n) * s, f * tc + (zz - f) * s)
        perp = np.where(np.isinf(npr), k, k * (psi / npr) * (psi / (npr + mu)))
    return _finite_or_raise(perp / s, "m_z")


def gamma_lim(near, far, half_fov):
    """Barroso Eq 15: γ_lim = atan((f + n) tan φ/(f − n)), as atan((1 + n/f) tan φ/((f − n)/f))."""
    n, f, th = _arrays(near, far, half_fov)
    ok, t = _view_ok(n, f, th)
    if not ok.all():
        raise ValueError("argument outside the domain")
    return _finite_or_raise(np.arctan((1.0 + n / f) * t / ((f - n) / f)), "gamma_lim")


def subdivided_max_error(alpha, k, eta, half_fov, res_image=1.0, res_s=1.0):
    """Lloyd 2005 Eq 7: k (r_p/r_s) (α^{1/k} − 1)/(2 tan θ) · (1 + |ξ| (α^{1/2k} − 1))/α^{1/2k},
    with s − 1 = expm1(ln α / 2k) and α^{1/k} − 1 = (s − 1)(s + 1); k whole in [1, 10⁶]."""
    a, kk, e, th, rp, rs = _arrays(alpha, k, eta, half_fov, res_image, res_s)
    ok = np.isfinite(a) & (a > 1) & np.isfinite(kk) & (kk >= 1) & (kk <= 1e6)
    ok &= (np.mod(kk, 1.0) == 0) & (th > 0) & (th < np.pi / 2) & (e >= -1) & (e <= 1)
    ok &= np.isfinite(rp) & (rp > 0) & np.isfinite(rs) & (rs > 0)
    if not ok.all():
        raise ValueError("argument outside the domain")
    t = np.tan(th)
    s_m1 = np.expm1(np.log(a) * (0.5 / kk))
    rak = 1.0 + s_m1
    err = s_m1 * (s_m1 + 2.0) / rak
    q = kk * rp / (rs * (2.0 * t))
    return _finite_or_raise(q * err * (1.0 + np.abs(e) * (rak - 1.0)), "m_max")
