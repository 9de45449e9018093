"""The closed forms: agreement with the crate's `eval` JSON and with hand values from the papers,
broadcasting and dtype rules, and errors."""
import json
import math
import os
import subprocess

import numpy as np
import pytest

import shadow_aliasing as sa


# Hand values (expected numbers computed here from the printed equations, not by the crate).
def test_storage_factor_lispsm_hand_value():
    # Lloyd 2006 Eq 12, n′ ≤ n′_LSPSM: S̄ = (f/n − 1)/(2 tan θ); f/n = 100, θ = 45°: 99/2.
    assert sa.storage_factor(1.0, 100.0, math.pi / 4, 11.0) == pytest.approx(49.5, rel=1e-14)
    # Unwarped: times f/n.
    assert sa.storage_factor(1.0, 100.0, math.pi / 4, np.inf) == pytest.approx(4950.0, rel=1e-14)


def test_n_prime_lispsm_and_eta_hand_values():
    assert sa.n_prime_lispsm(1.0, 100.0) == pytest.approx(11.0, rel=1e-15)
    # Eq 11: η = 0 is LiSPSM, η = 1 PSM (n′ = n), η = −1 unwarped.
    np.testing.assert_allclose(sa.n_prime_from_eta(1.0, 100.0, [0.0, 1.0]), [11.0, 1.0], rtol=1e-14)
    assert sa.n_prime_from_eta(1.0, 100.0, -1.0) == np.inf


def test_mx_hand_value():
    # Eq 7: f (n′ + z − n)/(z (n′ + f − n)) = 100 · (11 + 50 − 1)/(50 · 110).
    assert sa.mx(1.0, 100.0, 11.0, 50.0) == pytest.approx(100 * 60 / (50 * 110), rel=1e-14)
    assert sa.mx(1.0, 100.0, 11.0, 50.0, res_image=2.0, res_s=4.0) == pytest.approx(
        0.5 * 100 * 60 / (50 * 110), rel=1e-14)


def test_tsm_eta_hand_value():
    # η = λ δ′ (1 + ξ)/(λ (1 − ξ) − 2 δ′) with λ = 1, δ′ = 0.2, ξ = −0.6: 0.08/1.2.
    assert sa.tsm_eta(1.0, 0.2, -0.6) == pytest.approx(0.08 / 1.2, rel=1e-14)


def test_z_partition_hand_values():
    np.testing.assert_allclose(sa.z_partition(1.0, 100.0, 2, "self_similar"), [1.0, 10.0, 100.0], rtol=1e-14)
    np.testing.assert_allclose(sa.z_partition(1.0, 101.0, 2, "uniform"), [1.0, 51.0, 101.0], rtol=1e-14)
    got = sa.z_partition(1.0, 100.0, 2, "practical", lambda_=[0.0, 1.0])
    np.testing.assert_allclose(got, [[1.0, 50.5, 100.0], [1.0, 10.0, 100.0]], rtol=1e-14)


def test_optimal_scheme_hand_value():
    # Lloyd 2006 App. C: ln α/(2 tan θ).
    v = sa.scheme_storage_factor("optimal", "overhead", 1.0, 100.0, math.pi / 4, 1)
    assert v == pytest.approx(math.log(100.0) / 2.0, rel=1e-14)


def test_allocate_texels_hand_value():
    # Eq 6: r_si = r_s e_i / Σ e_j.
    np.testing.assert_allclose(sa.allocate_texels([1.0, 2.0], 9.0), [3.0, 6.0], rtol=1e-14)


# Agreement with the command line's eval (the same crate, through JSON).
REQUESTS = [
    ("mx", dict(near=1, far=100, n_prime=7, z=30, res_image=2, res_s=3)),
    ("mz", dict(near=1, far=100, half_fov=0.5, n_prime=7, z=30, res_image=2, res_t=3)),
    ("max_mx", dict(near=1, far=100, n_prime=20)),
    ("max_mz", dict(near=1, far=100, half_fov=0.5, n_prime=20)),
    ("storage_factor", dict(near=0.5, far=300, half_fov=0.7, n_prime=90)),
    ("critical_resolution", dict(near=1, far=100, half_fov=0.5, n_prime=20, budget=4e6)),
    ("n_prime_lispsm", dict(near=2, far=50)),
    ("n_prime_from_eta", dict(near=1, far=100, eta=0.3)),
    ("eta_from_n_prime", dict(near=1, far=100, n_prime=30)),
    ("distribution_g", dict(alpha=100, n_warp=5, z=20)),
    ("subdivided_max_error", dict(alpha=100, k=3, eta=0.2, half_fov=0.5)),
    ("z_partition", dict(near=1, far=100, k=3, scheme="adaptive", light_angle=0.4, ratio=2)),
    ("scheme_storage_factor", dict(scheme="zp_w", light="overhead", near=1, far=100, half_fov=0.5, k=3)),
    ("tilted_mz", dict(near=1, far=100, half_fov=0.5, n_prime=5, light_angle=0.7, z=40)),
    ("generalized_n_prime", dict(near=1, far=100, half_fov=0.5, light_angle=0.3, falloff="zhang")),
    ("gamma_lim", dict(near=1, far=100, half_fov=0.5)),
    ("tsm_eta", dict(**{"lambda": 2.0}, delta_prime=0.3, xi=-0.6)),
    ("zhang_eq", dict(near=1, far=100, half_fov=0.5, **{"lambda": 8.0}, light_angle=0.9, y=3, z=20)),
    ("zhang_ep", dict(near=1, far=100, half_fov=0.5, **{"lambda": 8.0}, light_angle=0.9, y=3, z=20)),
    ("zhang_eq_local", dict(near=1, far=100, half_fov=0.5, **{"lambda": 8.0}, z=20)),
    ("zhang_ep_local", dict(near=1, far=100, half_fov=0.5, **{"lambda": 8.0}, z=20)),
]


def _python_value(q, args):
    kw = {("lambda_" if k == "lambda" else k): v for k, v in args.items()}
    return getattr(sa, q)(**kw)


def _cli():
    exe = os.environ.get("SHADOW_ALIASING_BIN")
    if not exe:
        pytest.skip("SHADOW_ALIASING_BIN not set (.ci/run sets it to the built command line)")
    return exe


def test_every_quantity_agrees_with_eval_json():
    exe = _cli()
    body = json.dumps([dict(quantity=q, **a) for q, a in REQUESTS])
    out = subprocess.run([exe, "eval"], input=body, capture_output=True, text=True, check=True)
    answers = json.loads(out.stdout)
    assert len(answers) == len(REQUESTS)
    for (q, a), ans in zip(REQUESTS, answers):
        want = np.asarray(ans["value"], dtype=np.float64)
        got = np.asarray(_python_value(q, a))
        # The same f64 computation: bit for bit.
        np.testing.assert_array_equal(got, want, err_msg=q)


def test_error_messages_agree_with_eval_json():
    exe = _cli()
    req = dict(quantity="n_prime_lispsm", near=2, far=1)
    out = subprocess.run([exe, "eval"], input=json.dumps(req), capture_output=True, text=True)
    want = json.loads(out.stdout)["error"]
    with pytest.raises(ValueError) as e:
        sa.n_prime_lispsm(2.0, 1.0)
    assert str(e.value) == want == "far must be greater than near (got near=2, far=1)"


def test_every_contract_quantity_is_bound():
    assert {q for q, _ in REQUESTS} | {"allocate_texels"} <= set(sa.__all__)
    assert len({q for q, _ in REQUESTS} | {"allocate_texels"}) == 22


# Broadcasting and dtypes.
def test_broadcasting_matches_elementwise_calls():
    near = np.array([[1.0], [2.0]])          # (2, 1)
    far = np.array([50.0, 100.0, 200.0])      # (3,)
    got = sa.storage_factor(near, far, 0.5, np.inf)
    assert got.shape == (2, 3) and got.dtype == np.float64
    for i in range(2):
        for j in range(3):
            assert got[i, j] == sa.storage_factor(float(near[i, 0]), float(far[j]), 0.5, np.inf)


def test_non_contiguous_and_transposed_inputs():
    far = np.linspace(10.0, 100.0, 12).reshape(3, 4)
    a = sa.n_prime_lispsm(1.0, far.T)
    np.testing.assert_array_equal(a, sa.n_prime_lispsm(1.0, np.ascontiguousarray(far.T)))
    b = sa.n_prime_lispsm(1.0, far[:, ::2])
    np.testing.assert_array_equal(b, sa.n_prime_lispsm(1.0, np.ascontiguousarray(far[:, ::2])))


def test_dtypes_int_float32_zero_d():
    a = sa.n_prime_lispsm(np.array([1, 4]), np.array([100, 64], dtype=np.int32))
    np.testing.assert_allclose(a, [11.0, 20.0], rtol=1e-15)
    assert a.dtype == np.float64
    b = sa.n_prime_lispsm(np.float32(1.0), np.array([100.0], dtype=np.float32))
    assert b.dtype == np.float64 and b.shape == (1,)
    c = sa.n_prime_lispsm(np.array(1.0), np.array(100.0))
    assert isinstance(c, np.float64) and c == 11.0
    assert isinstance(sa.n_prime_lispsm(1, 100), np.float64)
    # k as an integer array broadcasts with the floats.
    ks = sa.subdivided_max_error(100.0, np.array([1, 2, 4]), 0.0, 0.5)
    assert ks.shape == (3,)
    assert ks[1] == sa.subdivided_max_error(100.0, 2, 0.0, 0.5)


def test_large_parallel_call_equals_serial_values():
    far = np.linspace(2.0, 1000.0, 100_000)
    big = sa.n_prime_lispsm(1.0, far)
    assert big.shape == (100_000,)
    for i in (0, 12_345, 50_000, 99_999):
        assert big[i] == sa.n_prime_lispsm(1.0, float(far[i]))


def test_shape_mismatch_raises():
    with pytest.raises(ValueError, match="cannot be broadcast"):
        sa.storage_factor([1.0, 2.0], [10.0, 20.0, 30.0], 0.5, np.inf)


def test_refused_dtypes():
    with pytest.raises(TypeError):
        sa.n_prime_lispsm(np.array([1 + 1j]), 100.0)
    with pytest.raises(TypeError):
        sa.n_prime_lispsm(True, 100.0)
    with pytest.raises((TypeError, ValueError)):
        sa.n_prime_lispsm("one", 100.0)


# Bad input: ValueError with the crate's message, never NaN.
@pytest.mark.parametrize("call, message", [
    (lambda: sa.storage_factor(1.0, 100.0, 0.5, 0.5), "n_prime must be at least near"),
    (lambda: sa.storage_factor(1.0, 100.0, 2.0, 11.0), "half_fov must lie in"),
    (lambda: sa.mx(1.0, 100.0, 11.0, 200.0), "z must lie in [near, far]"),
    (lambda: sa.n_prime_lispsm(np.nan, 100.0), "near must be a finite number"),
    (lambda: sa.storage_factor(1.0, 100.0, 0.5, -1.0), "n_prime must be greater than 0"),
    (lambda: sa.zhang_eq_local(1.0, 100.0, 0.5, -2.0, 20.0), "lambda must be greater than 0"),
    (lambda: sa.subdivided_max_error(100.0, 2.5, 0.0, 0.5), "k must be a whole number"),
    (lambda: sa.subdivided_max_error(100.0, 2, 1.5, 0.5), "eta must lie in"),
    (lambda: sa.scheme_storage_factor("zp", "sideways", 1.0, 100.0, 0.5, 2), "light must be one of"),
    (lambda: sa.z_partition(1.0, 100.0, 2, "practical"), "lambda_ is missing"),
    (lambda: sa.tsm_eta(1.0, 0.2, 0.9), "no solution"),
])
def test_bad_input_raises_value_error(call, message):
    with pytest.raises(ValueError) as e:
        call()
    assert message in str(e.value)


def test_error_names_the_element():
    with pytest.raises(ValueError) as e:
        sa.n_prime_lispsm(1.0, [10.0, 20.0, 0.5, np.nan])
    # The first failing element in C order.
    assert str(e.value) == "far must be greater than near (got near=1, far=0.5) (at index (2,))"


def _stub_docstrings():
    import ast
    path = os.path.join(os.path.dirname(sa.__file__), "__init__.pyi")
    if not os.path.exists(path):
        path = os.path.join(os.path.dirname(__file__), "..", "shadow_aliasing", "__init__.pyi")
    tree = ast.parse(open(path, encoding="utf-8").read())
    return {f.name: ast.get_docstring(f) for f in tree.body if isinstance(f, ast.FunctionDef)}


@pytest.mark.parametrize("name", sorted({q for q, _ in REQUESTS} | {"allocate_texels"}))
def test_stub_and_docstring_carry_formula_and_equation(name):
    stub = _stub_docstrings()[name]
    doc = getattr(sa, name).__doc__
    for text in (stub, doc):
        # A formula (an equals sign) and the paper's equation or section.
        assert "=" in text, (name, text)
        assert any(w in text for w in ("Eq", "§", "App.")), (name, text)
