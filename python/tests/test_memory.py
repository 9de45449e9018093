"""Calls whose results do not fit in memory raise MemoryError before any work, never abort the
process, and the module works after it; error_image refuses a singular shadow matrix.

The memory tests run in a fresh interpreter whose address space is limited
(``resource.setrlimit(RLIMIT_AS)``) to what it uses after a first call plus a margin: an
allocation beyond it fails as it would on a machine without the memory. Before the fix,
``error_image`` allocated its points and per-pixel results with Rust's infallible allocation,
and the process aborted (SIGABRT, "memory allocation of … bytes failed")."""
import json
import subprocess
import sys

import numpy as np
import pytest

import shadow_aliasing as sa

GIB = 1 << 30

SCRIPT = r"""
import json, resource, sys
import numpy as np
import shadow_aliasing as sa

def vm_size():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmSize:"):
                return int(line.split()[1]) * 1024

shadow = sa.warp(1.0, 100.0, 0.5, [0, -1, 0], "lispsm")
# Every thread started and the module's code paged in before the limit is measured.
sa.error_image(np.full((64, 64), 0.5), np.eye(4), np.eye(4), shadow)
sa.sweep(1.0, 100.0, 0.5, "lispsm", elevations=8, azimuths=8)
margin = int(sys.argv[2])
resource.setrlimit(resource.RLIMIT_AS, (vm_size() + margin, resource.RLIM_INFINITY))
try:
    if sys.argv[1] == "error_image":
        side = int(sys.argv[3])
        sa.error_image(np.broadcast_to(0.5, (side, side)), np.eye(4), np.eye(4), shadow,
                       return_jacobian=sys.argv[4] == "jacobian")
    else:
        sa.sweep(1.0, 100.0, 0.5, "lispsm", elevations=4096, azimuths=4096)
    outcome = "returned"
except MemoryError as e:
    outcome = "MemoryError: " + str(e)
# max_mx(1, 100, 11) = f n'/(n (n' + f - n)) = 100·11/110 = 10: the module still works.
print(json.dumps({"outcome": outcome, "after": float(sa.max_mx(1.0, 100.0, 11.0)) == 10.0}))
# The checks are done: leave without the interpreter's teardown, which under the limit can fail
# to allocate a thread's storage and abort ("cannot allocate memory for thread-local data"),
# after the call under test has raised and the module has worked again.
sys.stdout.flush()
import os
os._exit(0)
"""


def run_limited(tmp_path, *args):
    run = subprocess.run([sys.executable, "-c", SCRIPT, *map(str, args)], capture_output=True,
                         text=True, timeout=300, cwd=tmp_path)
    assert run.returncode == 0, (run.returncode, run.stderr[-2000:])
    return json.loads(run.stdout.strip().splitlines()[-1])


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc/self/status")
@pytest.mark.parametrize("side, margin, jacobian", [
    # 16384² pixels: the depth's copy (2 GiB) fits in 3 GiB, the error image (2 GiB more) not.
    (16384, 3 * GIB, "error"),
    # 8192²: depth and error (0.5 GiB each) fit in 2 GiB, the Jacobians (2 GiB more) not.
    (8192, 2 * GIB, "jacobian"),
])
def test_error_image_too_large_raises_memory_error(tmp_path, side, margin, jacobian):
    r = run_limited(tmp_path, "error_image", margin, side, jacobian)
    assert r["outcome"].startswith("MemoryError"), r
    assert "does not fit in memory" in r["outcome"], r
    assert r["after"], r


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc/self/status")
def test_sweep_too_large_raises_memory_error(tmp_path):
    # 4096 × 4096 directions (the limit, 2²⁴): a 128 MiB result in a 64 MiB margin.
    r = run_limited(tmp_path, "sweep", 64 << 20)
    assert r["outcome"].startswith("MemoryError"), r
    assert "(4096, 4096)" in r["outcome"], r
    assert r["after"], r


SHADOW = sa.warp(1.0, 100.0, 0.5, [0, -1, 0], "lispsm")


@pytest.mark.parametrize("matrix", [
    np.zeros((4, 4)),
    # A zero row (depth) or a repeated row: determinant 0 by hand.
    np.diag([1.0, 1.0, 0.0, 1.0]),
    np.array([[1.0, 0, 0, 0], [1.0, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
])
def test_error_image_refuses_a_singular_shadow_matrix(matrix):
    with pytest.raises(ValueError, match=r"shadow_matrix must be invertible \(its determinant is 0"):
        sa.error_image(np.full((4, 4), 0.5), np.eye(4), np.eye(4), matrix)


def test_error_image_names_the_singular_map_of_a_stack():
    stack = np.stack([SHADOW, SHADOW, np.zeros((4, 4))])
    with pytest.raises(ValueError, match=r"shadow_matrix must be invertible .* at map 2\)"):
        sa.error_image(np.full((4, 4), 0.5), np.eye(4), np.eye(4), stack)
