#!/usr/bin/env python3
"""Issue 13's comparison, side by side in one run: the whole `shadow-aliasing sweep` process
(`--format npy --output`, and CSV to a file) against NumPy computing the same sweep in-process
(benches/reference/sweep_numpy_fast.py, both forms, and the older benches/reference/sweep_numpy.py).

    cargo build --release --features cli
    python3 -m venv /tmp/np && /tmp/np/bin/pip install numpy
    /tmp/np/bin/python benches/sweep_vs_numpy.py [--rounds 15] [--elevations 360 --azimuths 1440]

Each round runs every contender once, in turn (so a change in the machine's load hits all of
them alike); the medians and minima over the rounds are printed, with the load average before
and after and the core count. The crate's process time is wall-clock from spawn to exit
(time.perf_counter around subprocess.run), its startup, thread pool and file writing included;
NumPy's is the sweep alone, grid to S̄, after a warm-up, without Python's or NumPy's start-up.
First the crate's npy is checked against the NumPy forms (≤ 1e-9 relative).
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "benches" / "reference"))
import sweep_numpy  # noqa: E402
import sweep_numpy_fast  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--binary", default=str(ROOT / "target" / "release" / "shadow-aliasing"))
    p.add_argument("--rounds", type=int, default=15)
    p.add_argument("--elevations", type=int, default=360)
    p.add_argument("--azimuths", type=int, default=1440)
    p.add_argument("--no-old", action="store_true", help="leave out sweep_numpy.py (slow)")
    a = p.parse_args()
    e, az = a.elevations, a.azimuths
    tmp = Path(tempfile.mkdtemp(prefix="sweep_vs_numpy"))
    base = [a.binary, "sweep", "--near", "1", "--far", "1000", "--half-fov",
            repr(float(np.pi / 6)), "--warp", "lispsm", "--elevations", str(e),
            "--azimuths", str(az)]
    npy_cmd = base + ["--format", "npy", "--output", str(tmp / "s.npy")]
    csv_cmd = base + ["--output", str(tmp / "s.csv")]

    subprocess.run(npy_cmd, check=True)
    crate = np.load(tmp / "s.npy")
    assert crate.shape == (e, az) and crate.dtype == np.float64
    for reduced in (False, True):
        rel = np.max(np.abs(sweep_numpy_fast.sweep(e, az, reduced) - crate) / crate)
        assert rel <= 1e-9, rel
    el, azs = sweep_numpy.grid(e, az)
    rel_old = np.max(np.abs(sweep_numpy.sweep_chunked(el, azs, 4096) - crate.ravel()) / crate.ravel())
    assert rel_old <= 1e-9, rel_old

    def process(cmd):
        def run():
            t0 = time.perf_counter()
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
            return time.perf_counter() - t0
        return run

    def in_process(f):
        f()  # warm-up
        def run():
            t0 = time.perf_counter()
            f()
            return time.perf_counter() - t0
        return run

    contenders = {
        "crate process, --format npy --output": process(npy_cmd),
        "crate process, CSV --output": process(csv_cmd),
        "NumPy fast (full measurement), in process": in_process(
            lambda: sweep_numpy_fast.sweep(e, az, False)),
        "NumPy fast (reduced measurement), in process": in_process(
            lambda: sweep_numpy_fast.sweep(e, az, True)),
    }
    if not a.no_old:
        contenders["NumPy sweep_numpy.py (old reference), in process"] = in_process(
            lambda: sweep_numpy.sweep_chunked(el, azs, 4096))
    for run in contenders.values():
        run()  # warm-up (page cache, CPU frequency)
    load0 = os.getloadavg()
    times = {k: [] for k in contenders}
    for _ in range(a.rounds):
        for k, run in contenders.items():
            times[k].append(run())
    load1 = os.getloadavg()
    print(f"{e} x {az}, {a.rounds} rounds, numpy {np.__version__}, {os.cpu_count()} cores, "
          f"load average {load0[0]:.2f} before, {load1[0]:.2f} after")
    print(f"crate vs NumPy fast: max relative difference ≤ 1e-9 (old reference {rel_old:.1e})")
    med = {k: statistics.median(v) for k, v in times.items()}
    npy = med["crate process, --format npy --output"]
    for k, v in times.items():
        print(f"{k:52s} median {med[k] * 1e3:7.1f} ms  min {min(v) * 1e3:7.1f} ms  "
              f"{med[k] / npy:5.2f}× the npy process")


if __name__ == "__main__":
    main()
