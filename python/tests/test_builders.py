"""Builders, the measurement of any 4×4 matrix, and the sweep."""
import math

import numpy as np
import pytest

import shadow_aliasing as sa

VIEW = (1.0, 100.0, math.radians(30))
OVERHEAD = [0.0, -1.0, 0.0]


def test_warp_every_rule_returns_a_4x4_that_maps_the_frustum_into_the_map():
    t = math.tan(VIEW[2])
    corners = [(sx * d * t, sy * d * t, -d, 1.0) for d in (VIEW[0], VIEW[1]) for sx in (-1, 1) for sy in (-1, 1)]
    light = [0.3, -0.8, -0.4]
    for rule in sa.WARP_RULES:
        kw = {"eta": 0.2} if rule == "eta" else {}
        m = sa.warp(*VIEW, light, rule, **kw)
        assert m.shape == (4, 4) and m.dtype == np.float64, rule
        for c in corners:
            h = m @ np.array(c)
            assert h[3] > 0, rule
            assert np.all(np.abs(h[:3] / h[3]) <= 1 + 1e-9), rule


def test_lispsm_overhead_measures_lloyd_eq_12():
    # The built matrix, measured from its derivatives, against the closed form.
    m = sa.warp(*VIEW, OVERHEAD, "lispsm")
    mx_, mz_, s = sa.frustum_max(m, OVERHEAD, *VIEW)
    want = sa.storage_factor(*VIEW, sa.n_prime_lispsm(VIEW[0], VIEW[1]))
    assert s == pytest.approx(want, rel=1e-9)
    assert mx_ * mz_ == pytest.approx(s, rel=1e-15)
    assert sa.n_prime_for(*VIEW, OVERHEAD, "lispsm") == pytest.approx(11.0, rel=1e-12)


def test_uniform_overhead_point_error_is_lloyd_eq_7_8():
    m = sa.warp(*VIEW, OVERHEAD, "uniform")
    z = np.array([1.0, 10.0, 50.0, 100.0])
    pts = np.stack([np.zeros_like(z), np.zeros_like(z), -z], axis=1)
    e = sa.point_error(m, OVERHEAD, pts, *VIEW)
    assert e.shape == (4, 2)
    np.testing.assert_allclose(e[:, 0], sa.mx(1.0, 100.0, np.inf, z), rtol=1e-9)
    np.testing.assert_allclose(e[:, 1], sa.mz(*VIEW, np.inf, z), rtol=1e-9)


def test_clip_depth_zero_to_one_is_row_average():
    a = sa.warp(*VIEW, OVERHEAD, "psm")
    b = sa.warp(*VIEW, OVERHEAD, "psm", clip_depth="zero_to_one")
    np.testing.assert_allclose(b[2], 0.5 * (a[2] + a[3]), rtol=1e-15)
    np.testing.assert_array_equal(b[[0, 1, 3]], a[[0, 1, 3]])


def test_clip_depth_reversed_is_one_minus_zero_to_one():
    a = sa.warp(*VIEW, OVERHEAD, "psm")
    b = sa.warp(*VIEW, OVERHEAD, "psm", clip_depth="reversed")
    np.testing.assert_allclose(b[2], 0.5 * (a[3] - a[2]), rtol=1e-15)
    np.testing.assert_array_equal(b[[0, 1, 3]], a[[0, 1, 3]])
    # The frustum's corners: depth 1 at the end nearest the light, 0 at the farthest.
    near, far, half_fov = VIEW
    t = np.tan(half_fov)
    corners = np.array(
        [[sx * z * t, sy * z * t, -z, 1.0] for z in (near, far) for sx in (-1, 1) for sy in (-1, 1)]
    )
    za, zb = corners @ a.T, corners @ b.T
    np.testing.assert_allclose(zb[:, 2] / zb[:, 3], 0.5 * (1.0 - za[:, 2] / za[:, 3]), atol=1e-12)
    assert zb[:, 2].max() / zb[zb[:, 2].argmax(), 3] <= 1.0 + 1e-9
    with pytest.raises(ValueError, match="clip_depth"):
        sa.warp(*VIEW, OVERHEAD, "psm", clip_depth="reverse")


def test_cascades_zp_w_overhead_is_lloyd_eq_18():
    k = 4
    ms = sa.cascades(*VIEW, OVERHEAD, k, "self_similar", "lispsm")
    assert ms.shape == (k, 4, 4)
    total = sa.frustum_max(ms, OVERHEAD, *VIEW)
    # Each cascade measured over its own sub-frustum.
    planes = sa.z_partition(VIEW[0], VIEW[1], k, "self_similar")
    s = sum(sa.frustum_max(ms[i], OVERHEAD, planes[i], planes[i + 1], VIEW[2])[2] for i in range(k))
    want = sa.scheme_storage_factor("zp_w", "overhead", *VIEW, k)
    assert s == pytest.approx(want, rel=1e-9)
    assert total.shape == (k, 3)


def test_faces_and_tsm():
    ms, names = sa.faces(*VIEW, [0.0, -0.2, -1.0], 2)
    assert ms.shape == (len(names), 4, 4) and set(names) <= {"bottom", "right", "top", "left", "near"}
    m = sa.tsm(*VIEW, [0.0, -1.0, -0.3])
    assert m.shape == (4, 4) and np.isfinite(m).all()


def test_builder_errors():
    with pytest.raises(ValueError, match="rule must be one of"):
        sa.warp(*VIEW, OVERHEAD, "lisp")
    with pytest.raises(ValueError, match="eta is missing"):
        sa.warp(*VIEW, OVERHEAD, "eta")
    with pytest.raises(ValueError, match="eta is only used"):
        sa.warp(*VIEW, OVERHEAD, "psm", eta=0.2)
    with pytest.raises(ValueError, match="light_dir"):
        sa.warp(*VIEW, [0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="shape"):
        sa.warp(*VIEW, [0.0, -1.0])
    with pytest.raises(ValueError, match="matrix must have finite entries"):
        sa.frustum_max(np.full((4, 4), np.nan), OVERHEAD, *VIEW)
    with pytest.raises(ValueError, match="matrix must have shape"):
        sa.frustum_max(np.eye(3), OVERHEAD, *VIEW)


def test_sweep_shape_zenith_and_measurement():
    s = sa.sweep(1.0, 1000.0, math.pi / 6, "lispsm", elevations=9, azimuths=16)
    assert s.shape == (9, 16) and s.dtype == np.float64 and np.isfinite(s).all()
    el, az = sa.sweep_angles(9, 16)
    # Any cell: the single map built for that direction, measured.
    for i, j in [(0, 0), (3, 5), (8, 11)]:
        d = np.array([math.cos(el[i]) * math.sin(az[j]), math.sin(el[i]), math.cos(el[i]) * math.cos(az[j])])
        m = sa.warp(1.0, 1000.0, math.pi / 6, -d, "lispsm")
        assert s[i, j] == pytest.approx(sa.frustum_max(m, -d, 1.0, 1000.0, math.pi / 6)[2], rel=1e-9)
    with pytest.raises(ValueError, match="elevations"):
        sa.sweep(1.0, 1000.0, 0.5, elevations=0)
