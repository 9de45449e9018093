"""The fast path of the element-wise closed forms (branch-free domain checks and the library's
unchecked twins over blocks, split over threads) against the validated element-by-element path
(`_native._set_fast_path(False)`, the crate's checked closed forms, which `eval` also answers):
the same numbers bit for bit and the same errors, at domain edges, for large arrays split over
threads, with and without the wider vectors (`_native._set_wide_simd`), and for a bad element
deep in a large array."""
import contextlib
import math
import zlib

import numpy as np
import pytest

import shadow_aliasing as sa
from shadow_aliasing import _native

HALF_PI = math.pi / 2
# Values at and around every edge of the domains: zeros, signs, subnormals, overflow, NaN, ∞.
SPECIAL = [0.0, -0.0, -1.0, 5e-324, 1e-310, 2.2250738585072014e-308, 1e-300, 1e300, 1e308,
           1.7976931348623157e308, math.inf, -math.inf, math.nan]


def _pick(rng, n, valid, special_rate=0.15):
    """`valid` values, with a fraction replaced by SPECIAL ones."""
    out = np.array(valid, dtype=np.float64)
    mask = rng.random(n) < special_rate
    out[mask] = rng.choice(SPECIAL, mask.sum())
    return out


def _edge_args(name, rng, n):
    """Arguments of `name` for n elements: mostly valid, with exact boundaries and SPECIAL values."""
    near = _pick(rng, n, 10.0 ** rng.uniform(-3, 3, n))
    far = _pick(rng, n, np.where(rng.random(n) < 0.1, near, near * 10.0 ** rng.uniform(0, 6, n)))
    th = _pick(rng, n, rng.choice([HALF_PI, np.nextafter(HALF_PI, 0), 1e-300, 1e-160, 0.5,
                                   math.pi / 4], n) * (rng.random(n) < 0.3)
               + rng.uniform(1e-3, 1.5, n) * (rng.random(n) >= 0.3))
    lispsm = near + np.sqrt(np.abs(near * far))
    np_ = _pick(rng, n, np.select(
        [rng.random(n) < 0.15, rng.random(n) < 0.15, rng.random(n) < 0.2],
        [near, lispsm, np.inf], near * 10.0 ** rng.uniform(-0.5, 5, n)))
    t = rng.random(n)
    z = _pick(rng, n, np.select([t < 0.1, t < 0.2, t < 0.25, t < 0.3],
                                [near, far, near * (1 - 1e-16), far * (1 + 1e-16)],
                                near + (far - near) * rng.random(n)), 0.1)
    res = lambda: _pick(rng, n, 10.0 ** rng.uniform(-2, 4, n), 0.05)  # noqa: E731
    alpha = _pick(rng, n, np.where(rng.random(n) < 0.1, 1.0, 1.0 + 10.0 ** rng.uniform(-3, 6, n)))
    if name == "mx":
        return [near, far, np_, z, res(), res()]
    if name == "mz":
        return [near, far, th, np_, z, res(), res()]
    if name == "max_mx":
        return [near, far, np_, res(), res()]
    if name == "max_mz":
        return [near, far, th, np_, res(), res()]
    if name == "storage_factor":
        return [near, far, th, np_]
    if name == "n_prime_lispsm":
        return [near, far]
    if name == "n_prime_from_eta":
        eta = _pick(rng, n, np.where(rng.random(n) < 0.3,
                                     rng.choice([-1.0, 1.0, 0.0, -1.0 + 1e-16, 1.0 + 1e-16], n),
                                     rng.uniform(-1, 1, n)))
        return [near, far, eta]
    if name == "eta_from_n_prime":
        return [near, far, np_]
    if name == "distribution_g":
        n_warp = _pick(rng, n, np.where(rng.random(n) < 0.2, rng.choice([1.0, np.inf], n),
                                        10.0 ** rng.uniform(-0.5, 6, n)))
        zg = _pick(rng, n, np.where(rng.random(n) < 0.2, rng.choice([1.0, 0.0], n) + alpha
                                    * (rng.random(n) < 0.5), 1.0 + (alpha - 1.0) * rng.random(n)),
                   0.1)
        return [alpha, n_warp, zg]
    # Zhang's λ and a tilted light's n′: any value > 0 (below near too) or ∞.
    zl = np.where(rng.random(n) < 0.25, _pick(rng, n, near * 10.0 ** rng.uniform(-3, 0, n)), np_)
    # Light angles at and beyond both ends of [0, π/2], and inside.
    g = _pick(rng, n, np.where(rng.random(n) < 0.3,
                               rng.choice([0.0, -0.0, 5e-324, 1e-300, HALF_PI,
                                           np.nextafter(HALF_PI, 4), -1e-300], n),
                               rng.uniform(0, HALF_PI, n)), 0.1)
    if name == "tsm_eta":
        lam = _pick(rng, n, 10.0 ** rng.uniform(-3, 3, n))
        frac = np.where(rng.random(n) < 0.2, rng.choice([0.0, 1e-12, 0.25, 1.0, 1.2], n),
                        rng.random(n))
        d = _pick(rng, n, lam * frac)
        # ξ: the ends of (−1, 1), the unwarped line 1 − 2δ′/λ (exact at δ′/λ = 1/4), above it.
        xi = _pick(rng, n, np.select(
            [rng.random(n) < 0.15, rng.random(n) < 0.15, rng.random(n) < 0.1],
            [rng.choice([-1.0, 1.0, -1.0 + 1e-16, 1.0 - 1e-16], n), 1.0 - 2.0 * frac,
             rng.uniform(1.0 - 2.0 * frac, 1.0)],
            -1.0 + (2.0 - 2.0 * frac) * rng.random(n)))
        return [lam, d, xi]
    if name in ("zhang_eq_local", "zhang_ep_local"):
        return [near, far, th, zl, z]
    if name == "gamma_lim":
        return [near, far, th]
    if name in ("zhang_eq", "zhang_ep"):
        # y on and just beyond the side planes (the check's relative slack is 1e-12), inside.
        h = z * np.tan(th)
        y = _pick(rng, n, np.select(
            [t < 0.1, t < 0.2, t < 0.25, t < 0.3, t < 0.35],
            [h, -h, h * (1 + 1e-12), -h * (1 + 3e-12), 0.0], h * rng.uniform(-1, 1, n)), 0.1)
        return [near, far, th, zl, g, y, z]
    if name == "tilted_mz":
        return [near, far, th, zl, g, z, res(), res()]
    if name == "subdivided_max_error":
        # k: powers of two up to 16 (square roots) and beyond, other whole numbers, the ends of
        # [1, 10⁶], fractions and values outside; ξ at and beyond ±1.
        k = np.where(rng.random(n) < 0.5, rng.integers(1, 40, n).astype(np.float64),
                     rng.choice([0.0, 1.0, 16.0, 32.0, 1e6, 1e6 + 1, 2.5, 1.0 - 1e-16, -2.0,
                                 math.nan, math.inf], n))
        eta = _pick(rng, n, np.where(rng.random(n) < 0.3,
                                     rng.choice([-1.0, 1.0, 0.0, -1.0 - 1e-15, 1.0 + 1e-15], n),
                                     rng.uniform(-1, 1, n)))
        return [alpha, k, eta, th, res(), res()]
    raise KeyError(name)


FAST_FORMS = ["mx", "mz", "max_mx", "max_mz", "storage_factor", "n_prime_lispsm",
              "n_prime_from_eta", "eta_from_n_prime", "distribution_g", "tsm_eta",
              "zhang_eq_local", "zhang_ep_local", "gamma_lim", "zhang_eq", "zhang_ep", "tilted_mz",
              "subdivided_max_error"]


def _outcome(f, args):
    try:
        return ("value", np.float64(f(*args)).tobytes())
    except ValueError as e:
        return ("error", str(e))


@contextlib.contextmanager
def _hook(setter, value):
    """Runs the body with a test hook (`_native._set_fast_path`, `_set_wide_simd`) at `value`,
    then restores the previous setting."""
    previous = setter(value)
    try:
        yield
    finally:
        setter(previous)


@pytest.fixture
def validated_path():
    """Runs the body with the fast path off, then restores it."""
    with _hook(_native._set_fast_path, False):
        yield


def _both_paths(f, args):
    assert _native._set_fast_path(True) is True
    fast = f(*args)
    with _hook(_native._set_fast_path, False):
        slow = f(*args)
    return fast, slow


@pytest.mark.parametrize("name", FAST_FORMS)
def test_fast_path_agrees_with_validated_path_at_domain_edges(name):
    # One element per call, so that the fast path alone decides each element (a block holding a
    # refused element would be recomputed by the validated path and hide a wrong admission).
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    f = getattr(sa, name)
    with np.errstate(all="ignore"):
        cols = _edge_args(name, rng, 1500)
    outcomes = {"value": 0, "error": 0}
    assert _native._set_fast_path(True) is True
    for i in range(cols[0].size):
        args = [float(c[i]) for c in cols]
        fast = _outcome(f, args)
        with _hook(_native._set_fast_path, False):
            slow = _outcome(f, args)
        assert fast == slow, (name, args)
        outcomes[fast[0]] += 1
        if fast[0] == "value":
            v = np.frombuffer(fast[1])[0]
            assert not math.isnan(v), (name, args)
    # The generator reaches both sides of the domain.
    assert outcomes["value"] > 100 and outcomes["error"] > 100, outcomes


def _wide_and_baseline(f, args):
    """f(*args) with the fast kernels' wider vectors (AVX2 where the processor has it), with the
    baseline target's, and on the validated path."""
    assert _native._set_wide_simd(True) is True
    with _hook(_native._set_wide_simd, False):
        baseline = f(*args)
    wide, slow = _both_paths(f, args)
    return wide, baseline, slow


@pytest.mark.parametrize("name", FAST_FORMS)
def test_wide_vectors_agree_with_baseline_at_domain_edges(name):
    # The edge arguments the validated form accepts, as one array of whole blocks (512 elements),
    # which the fast kernel computes in one vector loop: with AVX2 and with SSE2 the same bits as
    # the validated path. (One element per call, as above, runs the scalar tail loop instead.)
    rng = np.random.default_rng(zlib.crc32(b"wide " + name.encode()))
    f = getattr(sa, name)
    with np.errstate(all="ignore"):
        cols = _edge_args(name, rng, 1500)
    with _hook(_native._set_fast_path, False):
        accepted = [i for i in range(cols[0].size)
                    if _outcome(f, [float(c[i]) for c in cols])[0] == "value"]
    assert len(accepted) > 100, len(accepted)
    take = np.resize(np.array(accepted), 4 * 512)
    wide, baseline, slow = _wide_and_baseline(f, [c[take] for c in cols])
    assert wide.tobytes() == slow.tobytes() and baseline.tobytes() == slow.tobytes()
    assert not np.isnan(wide).any()


@pytest.mark.parametrize("name", FAST_FORMS)
def test_large_array_over_threads_equals_small_calls(name):
    # 300 000 elements: many blocks, split over the threads; valid arguments only.
    rng = np.random.default_rng(7)
    n = 300_000
    near = 10.0 ** rng.uniform(-2, 2, n)
    far = near * 10.0 ** rng.uniform(0.1, 5, n)
    th = rng.uniform(0.05, 1.5, n)
    np_ = np.where(rng.random(n) < 0.2, np.inf, near * 10.0 ** rng.uniform(0, 4, n))
    z = near + (far - near) * rng.random(n)
    alpha = far / near
    lam = 10.0 ** rng.uniform(-2, 2, n)
    frac = rng.uniform(0.01, 0.99, n)
    zl = np.where(rng.random(n) < 0.2, np.inf, near * 10.0 ** rng.uniform(-2, 3, n))
    g = rng.uniform(0, HALF_PI, n)
    y = z * np.tan(th) * rng.uniform(-1, 1, n)
    args = {
        "mx": [near, far, np_, z, 3.0, near],
        "mz": [near, far, th, np_, z, far, 2.0],
        "max_mx": [near, far, np_],
        "max_mz": [near, far, th, np_],
        "storage_factor": [near, far, th, np_],
        "n_prime_lispsm": [near, far],
        "n_prime_from_eta": [near, far, rng.uniform(-1, 1, n)],
        "eta_from_n_prime": [near, far, np_],
        "distribution_g": [alpha, np.where(np_ == np.inf, np.inf, np_ / near),
                           1.0 + (alpha - 1.0) * rng.random(n)],
        "tsm_eta": [lam, lam * frac, -1.0 + (2.0 - 2.0 * frac) * rng.uniform(0.01, 0.99, n)],
        "zhang_eq_local": [near, far, th, zl, z],
        "zhang_ep_local": [near, far, 0.3, zl, z],
        "gamma_lim": [near, far, th],
        "zhang_eq": [near, far, th, zl, g, y, z],
        "zhang_ep": [near, far, th, zl, g, y, z],
        "tilted_mz": [near, far, th, zl, np.maximum(g, 1e-3), z, 2.0, far],
        "subdivided_max_error": [alpha, rng.integers(1, 40, n).astype(np.float64),
                                 rng.uniform(-1, 1, n), th, 3.0, far],
    }[name]
    f = getattr(sa, name)
    big = f(*args)
    assert big.shape == (n,) and big.dtype == np.float64 and np.isfinite(big).mean() > 0.7
    # Slices of 1000 run on one thread (below the parallel threshold).
    pieces = np.concatenate([
        f(*[a[s:s + 1000] if isinstance(a, np.ndarray) else a for a in args])
        for s in range(0, n, 1000)])
    np.testing.assert_array_equal(big, pieces)
    wide, baseline, slow = _wide_and_baseline(f, args)
    assert wide.tobytes() == slow.tobytes() and baseline.tobytes() == slow.tobytes()
    # Element 123 456 by itself.
    i = 123_456
    one = f(*[float(a[i]) if isinstance(a, np.ndarray) else a for a in args])
    assert big[i] == one or (np.isinf(big[i]) and np.isinf(one))


def test_one_theta_equals_theta_array():
    # tan θ is taken once per run of equal θ: the same numbers as an array of the same θ.
    rng = np.random.default_rng(3)
    near = rng.uniform(0.1, 10, 50_000)
    far = near * rng.uniform(2, 1000, near.size)
    a = sa.storage_factor(near, far, 0.7, np.inf)
    b = sa.storage_factor(near, far, np.full(near.size, 0.7), np.inf)
    np.testing.assert_array_equal(a, b)
    # Lloyd 2006 Eq 12, unwarped: (f/n − 1)/(2 tan θ) · f/n, by NumPy.
    np.testing.assert_allclose(a, (far / near - 1) / (2 * np.tan(0.7)) * far / near, rtol=1e-13)


@pytest.mark.parametrize("name, bad, message", [
    ("storage_factor", (3, 0.5),
     "n_prime must be at least near for a light overhead (got n_prime=0.5, near=1)"),
    ("storage_factor", (2, HALF_PI), "half_fov must lie in (0, 1.5707963267948966) "
                                     "(got 1.5707963267948966)"),
    ("mx", (3, 1000.0), "z must lie in [near, far] = [1, 100] (got 1000)"),
    ("n_prime_lispsm", (1, math.nan), "far must be a finite number (got NaN)"),
    ("tsm_eta", (1, 10.0), "delta_prime must lie in (0, 10) (got 10)"),
    ("tsm_eta", (2, 0.9), "no solution: no centre of projection above the top line maps the "
                          "focus point (delta_prime=3) of a trapezoid of height lambda=10 to the "
                          "line xi=0.9: without warping it already lies at 0.4, and a centre "
                          "above the top line only moves it towards the base (-1)"),
    ("zhang_eq_local", (4, 1000.0), "z must lie in [1, 100] (got 1000)"),
    ("zhang_ep_local", (2, 0.0), "half_fov must lie in (0, 1.5707963267948966) (got 0)"),
    ("gamma_lim", (2, 1e-320), "half_fov is too small: tan θ must be a normal f64, at least "
                               "2.2250738585072014e-308 (got half_fov=1e-320)"),
    ("zhang_eq", (4, 2.0), "light_angle must lie in [0, 1.5707963267948966] (got 2)"),
    ("zhang_ep", (5, 40.0), "y must lie in the view frustum, |y| ≤ z tan(half_fov) = "
                            "27.315124492189526 (got 40)"),
    ("subdivided_max_error", (1, 2.5), "k must be a whole number of at least 1 (got 2.5)"),
    ("subdivided_max_error", (3, 1.6), "half_fov must lie in (0, 1.5707963267948966) (got 1.6)"),
    ("tilted_mz", (4, 0.0), "light_angle must be greater than 0 for Barroso's m_z, which "
                            "measures texels along the view axis and is infinite when light and "
                            "view are parallel (got 0)"),
])
def test_bad_element_deep_in_a_large_array(name, bad, message):
    n = 1_000_000
    base = {"storage_factor": [1.0, 100.0, 0.5, 11.0], "mx": [1.0, 100.0, 11.0, 50.0],
            "n_prime_lispsm": [1.0, 100.0], "tsm_eta": [10.0, 3.0, -0.6],
            "zhang_eq_local": [1.0, 100.0, 0.5, 11.0, 50.0],
            "zhang_ep_local": [1.0, 100.0, 0.5, 0.3, 50.0], "gamma_lim": [1.0, 100.0, 0.5],
            "zhang_eq": [1.0, 100.0, 0.5, 11.0, 1.0, 0.0, 50.0],
            "zhang_ep": [1.0, 100.0, 0.5, np.inf, 1.0, 10.0, 50.0],
            "tilted_mz": [1.0, 100.0, 0.5, 11.0, 1.0, 50.0],
            "subdivided_max_error": [100.0, 4.0, 0.0, 0.5]}[name]
    args = [np.full(n, v) for v in base]
    k, v = bad
    args[k][777_777] = v
    args[k][900_001] = v  # a later one, in another thread's part: not the one reported
    f = getattr(sa, name)
    for fast in (True, False):
        with _hook(_native._set_fast_path, fast), pytest.raises(ValueError) as e:
            f(*args)
        assert str(e.value) == message + " (at index (777777,))"
    # The same text for the element alone, without the index.
    with pytest.raises(ValueError) as e:
        f(*[float(a[777_777]) for a in args])
    assert str(e.value) == message
    # In two dimensions, the index is NumPy's multi-index.
    with pytest.raises(ValueError) as e:
        f(*[a.reshape(1000, 1000) for a in args])
    assert str(e.value) == message + " (at index (777, 777))"
