"""A closed form that is positive and proportional to res_image/res_s (or /res_t) raises
ValueError naming both resolutions when they scale its value below f64's normal range, never
returns 0 or a subnormal (issue 21, item 8: ``sa.mx(1, 100, 11, 10, 1e-300, 1e300)`` was 0.0 for
1.8e-600). The same on the fast path (SIMD blocks, which admit only a normal value for these
forms) and the validated one, for one number and for an element deep in a large array.

Expected values by hand at unit resolutions, near 1, far 100, n' = 11, z = 10, theta = pi/4 (Lloyd
2006 Eq 7-10, Lloyd 2005 Eq 7, Barroso Eq 12 overhead = Lloyd's m_z)."""
import contextlib
import math
import re

import numpy as np
import pytest

import shadow_aliasing as sa
from shadow_aliasing import _native

Q = math.pi / 4
MX = 100 * 20 / (10 * 110)                 # f (n' + z - n) / (z (n' + f - n))
MZ = 99 / 2 * 400 / (10 * 11 * 110)        # (f - n)/(2 tan) (n' + z - n)^2 / (z n' (n' + f - n))
MAX_MX = 100 * 11 / 110                    # f n' / (n (n' + f - n))
MAX_MZ = 99 / 2 * 110 / (100 * 11)         # far plane at n' = n + sqrt(f n) = 11
EQ7 = 2 * 9 / 2 / math.sqrt(10)            # k (a^(1/k) - 1)/(2 tan) / a^(1/2k), a = 100, k = 2

# name, function, the arguments before the resolutions, the map resolution's name, unit value.
FORMS = [
    ("mx", sa.mx, (1.0, 100.0, 11.0, 10.0), "res_s", "m_x", MX),
    ("max_mx", sa.max_mx, (1.0, 100.0, 11.0), "res_s", "m_x", MAX_MX),
    ("mz", sa.mz, (1.0, 100.0, Q, 11.0, 10.0), "res_t", "m_z", MZ),
    ("max_mz", sa.max_mz, (1.0, 100.0, Q, 11.0), "res_t", "M_z", MAX_MZ),
    ("tilted_mz", sa.tilted_mz, (1.0, 100.0, Q, 11.0, math.pi / 2, 10.0), "res_t", "m_z", MZ),
    ("subdivided_max_error", sa.subdivided_max_error, (100.0, 2.0, 0.0, Q), "res_s", "m_max",
     EQ7),
]
IDS = [f[0] for f in FORMS]


@contextlib.contextmanager
def fast_path(enabled):
    previous = _native._set_fast_path(enabled)
    try:
        yield
    finally:
        _native._set_fast_path(previous)


def _estimate(message):
    """The 'about 1.818e-600' of a message, as log10."""
    m = re.search(r"about (\d\.\d{3})e(-?\d+)", message)
    assert m, message
    return math.log10(float(m.group(1))) + int(m.group(2))


@pytest.mark.parametrize("fast", [True, False])
@pytest.mark.parametrize("name,f,args,res,what,unit", FORMS, ids=IDS)
def test_one_number_that_underflows_is_refused(fast, name, f, args, res, what, unit):
    with fast_path(fast), pytest.raises(ValueError) as e:
        f(*args, res_image=1e-300, **{res: 1e300})
    msg = str(e.value)
    assert f"res_image and {res} make {what} underflow f64" in msg, msg
    assert f"res_image/{res} (res_image=1e-300, {res}=1e300)" in msg, msg
    assert "returned as 0" in msg, msg
    assert f"evaluate it at res_image={res}=1" in msg, msg
    assert abs(_estimate(msg) - (math.log10(unit) - 600)) < 2.5e-4, msg


@pytest.mark.parametrize("fast", [True, False])
@pytest.mark.parametrize("name,f,args,res,what,unit", FORMS, ids=IDS)
def test_a_subnormal_is_refused_and_a_small_normal_answered(fast, name, f, args, res, what, unit):
    with fast_path(fast):
        # unit · 1e-310: subnormal, digits lost.
        with pytest.raises(ValueError, match="res_image") as e:
            f(*args, res_image=1e-300, **{res: 1e10})
        assert "the subnormal" in str(e.value)
        assert abs(_estimate(str(e.value)) - (math.log10(unit) - 310)) < 2.5e-4
        # unit · 1e-305 is a normal number: answered.
        v = f(*args, res_image=1e-300, **{res: 1e5})
        assert v == pytest.approx(unit * 1e-305, rel=1e-12)


@pytest.mark.parametrize("name,f,args,res,what,unit", FORMS, ids=IDS)
def test_an_element_deep_in_an_array(name, f, args, res, what, unit):
    """Blocks of normal values go through the fast kernels; the one element whose resolutions
    make it 0 sends its block to the validated form, which raises with its index. The same
    message with the fast path off; the values of the array without it equal the validated
    path's bit for bit."""
    n = 20_000
    ri = np.full(n, 2.0)
    ri[12_345] = 1e-300
    rm = np.full(n, 3.0)
    rm[12_345] = 1e300
    messages = []
    for fast in (True, False):
        with fast_path(fast), pytest.raises(ValueError) as e:
            f(*args, res_image=ri, **{res: rm})
        messages.append(str(e.value))
    assert messages[0] == messages[1]
    assert messages[0].endswith("(at index (12345,))"), messages[0]
    assert f"res_image and {res} make {what} underflow f64" in messages[0]
    ri[12_345], rm[12_345] = 2.0, 3.0
    with fast_path(True):
        a = f(*args, res_image=ri, **{res: rm})
    with fast_path(False):
        b = f(*args, res_image=ri, **{res: rm})
    assert a.tobytes() == b.tobytes()
    assert a[0] == pytest.approx(unit * 2 / 3, rel=1e-12)
