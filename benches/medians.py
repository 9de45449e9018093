#!/usr/bin/env python3
"""Print the median of every criterion benchmark under target/criterion, in nanoseconds, and its
ratio to reference/dmat4_mul (the machine-independent unit of docs/performance.md).

    python3 benches/medians.py [TARGET_DIR]     # default: ./target

Reads <group>/<name>/new/estimates.json (criterion's own median estimate and its 95 % interval).
Standard library only.
"""
import json
import pathlib
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "target") / "criterion"
rows = []
for est in sorted(root.glob("*/*/new/estimates.json")):
    name = f"{est.parts[-4]}/{est.parts[-3]}"
    m = json.loads(est.read_text())["median"]
    ci = m["confidence_interval"]
    rows.append((name, m["point_estimate"], ci["lower_bound"], ci["upper_bound"]))
unit = next((r[1] for r in rows if r[0] == "reference/dmat4_mul"), None)


def fmt(ns):
    if ns >= 1e6:
        return f"{ns / 1e6:.3f} ms"
    if ns >= 1e3:
        return f"{ns / 1e3:.3f} µs"
    return f"{ns:.2f} ns"


print(f"{'benchmark':36} {'median':>12} {'95% interval':>26} {'× dmat4_mul':>12}")
for name, med, lo, hi in rows:
    ratio = f"{med / unit:.1f}" if unit else "-"
    print(f"{name:36} {fmt(med):>12} {fmt(lo):>12} – {fmt(hi):>11} {ratio:>12}")
