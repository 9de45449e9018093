#!/usr/bin/env python3
"""A/B of two builds of the bindings (docs/python.md, "Packaging: abi3"): both extension
modules loaded side by side in one process and timed alternately, the minimum CPU time of the
process over the rounds, so that a loaded machine hits both alike. Run with one thread, so that
idle workers' spinning does not count:

    RAYON_NUM_THREADS=1 python python/abi3_bench.py FULL.so ABI3.so [ROUNDS [NAMES]]

FULL.so, ABI3.so: lib_native.so of `cargo build --release -p shadow-aliasing-python` without and
with pyo3's abi3-py310 feature; NAMES: a comma-separated filter of the rows."""
import importlib.machinery, importlib.util, sys, time
import numpy as np

def load(tag, path):
    name = f"{tag}._native"
    loader = importlib.machinery.ExtensionFileLoader(name, path)
    spec = importlib.util.spec_from_file_location(name, path, loader=loader)
    m = importlib.util.module_from_spec(spec); loader.exec_module(m); return m

A = load("full", sys.argv[1]); B = load("abi3", sys.argv[2])
rng = np.random.default_rng(1); N = 1_000_000
n = rng.uniform(0.5, 2, N); f = n * rng.uniform(10, 1000, N); th = rng.uniform(0.2, 1.2, N)
npr = n + np.sqrt(f * n); z = n + (f - n) * rng.uniform(0, 1, N)
d = rng.normal(size=(20000, 3)); d[:, 1] = -np.abs(d[:, 1]) - 0.05
L = [0.3, -1.0, 0.2]
def loop_scalar(m):
    for _ in range(20000): m.n_prime_lispsm(1.0, 100.0)
def loop_warp(m):
    for _ in range(5000): m.warp(1.0, 100.0, 0.5, L, "lispsm")
def loop_frame(m):
    for _ in range(300): m.frame(np.eye(4), 0.1, 100.0, 0.5, L, scheme="cascades", k=4, partition="log")
W_ALL = {
  "mx 1M": lambda m: m.mx(n, f, npr, z),
  "mz 1M": lambda m: m.mz(n, f, th, npr, z),
  "storage_factor 1M": lambda m: m.storage_factor(n, f, th, npr),
  "zhang_eq 1M": lambda m: m.zhang_eq(n, f, th, npr, 0.7, 0.0, z),
  "critical_resolution 1M": lambda m: m.critical_resolution(n, f, th, npr, 1e6),
  "warp stack 2e4": lambda m: m.warp(1.0, 100.0, 0.5, d, "lispsm"),
  "sweep 90x360": lambda m: m.sweep(1.0, 1000.0, 0.5, "lispsm", elevations=90, azimuths=360),
  "2e4 scalar n_prime_lispsm": loop_scalar,
  "5e3 scalar warp": loop_warp,
  "300 frame (4 cascades)": loop_frame,
}
ONLY = sys.argv[4].split(",") if len(sys.argv) > 4 else None
W = {k: v for k, v in W_ALL.items() if ONLY is None or any(o in k for o in ONLY)}
for k, w in W.items():  # same values
    a, b = w(A), w(B)
    if a is not None: assert np.array_equal(a, b), k
rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 15
best = {k: [np.inf, np.inf] for k in W}
for r in range(rounds):
    for k, w in W.items():
        for i, m in ((0, A), (1, B)) if r % 2 == 0 else ((1, B), (0, A)):
            t = time.process_time(); w(m); best[k][i] = min(best[k][i], time.process_time() - t)
print("| call | full API | abi3-py310 | abi3 / full |")
print("|---|---|---|---|")
for k, (a, b) in best.items():
    print(f"| {k} | {a*1e3:.2f} ms | {b*1e3:.2f} ms | {b/a:.3f} |")
