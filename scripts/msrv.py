#!/usr/bin/env python3
"""The least Rust version each of the README's commands needs, computed from the lock file.

For each build (the library alone, the README's main job, the README's test command) this takes
the packages `cargo tree` says that build compiles on this host, looks up each one's declared
`rust-version` in `cargo metadata`, and prints the greatest. With `--check` it also fails unless
README.md states those versions ("Rust X or newer" for the main job, "X for the tests") and
Cargo.toml's `rust-version` is at least the library's, so that neither can drift from the lock
file again (.ci/run calls it).

Usage: scripts/msrv.py [--check]
"""

import json
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# The builds the README promises, as `cargo tree` arguments.
BUILDS = {
    "library": ["-p", "shadow-aliasing", "--no-default-features", "-e", "normal,build"],
    "main job": ["-p", "shadow-aliasing", "--features", "cli", "-e", "normal,build"],
    "tests": ["--workspace", "--all-features", "-e", "normal,build,dev"],
}


def version_key(v: str) -> tuple:
    parts = [int(x) for x in v.split(".")]
    return tuple(parts + [0] * (3 - len(parts)))


def declared_versions() -> dict:
    out = subprocess.run(
        ["cargo", "metadata", "--locked", "--format-version", "1"],
        cwd=ROOT, check=True, capture_output=True, text=True,
    ).stdout
    return {
        (p["name"], p["version"]): p["rust_version"]
        for p in json.loads(out)["packages"]
        if p.get("rust_version")
    }


def least_rust(declared: dict, args: list) -> tuple:
    out = subprocess.run(
        ["cargo", "tree", "--locked", "--prefix", "none", "--format", "{p}", *args],
        cwd=ROOT, check=True, capture_output=True, text=True,
    ).stdout
    best = ("1.0", "(none)")
    for line in out.splitlines():
        fields = line.split()
        # Skip the workspace's own packages (printed with their path): the figure must come from
        # the dependencies, or Cargo.toml's rust-version would be checked against itself.
        if len(fields) < 2 or not fields[1].startswith("v") or "(/" in line:
            continue
        name, version = fields[0], fields[1][1:]
        rv = declared.get((name, version))
        if rv and version_key(rv) > version_key(best[0]):
            best = (rv, f"{name} {version}")
    return best


def short(v: str) -> str:
    """1.90.0 → 1.90, as the README writes it."""
    major, minor, *_ = v.split(".") + ["0"]
    return f"{major}.{minor}"


def main() -> int:
    declared = declared_versions()
    least = {build: least_rust(declared, args) for build, args in BUILDS.items()}
    for build, (rv, who) in least.items():
        print(f"{build}: Rust {short(rv)} (set by {who})")
    if "--check" not in sys.argv[1:]:
        return 0
    failures = []
    readme = (ROOT / "README.md").read_text()
    main_job, tests = short(least["main job"][0]), short(least["tests"][0])
    if f"Rust {main_job} or newer" not in readme:
        failures.append(f"README.md must say 'Rust {main_job} or newer' for the main job")
    if f"{tests} for the tests" not in readme:
        failures.append(f"README.md must say '{tests} for the tests'")
    cargo_toml = (ROOT / "Cargo.toml").read_text()
    stated = re.search(r'^rust-version\s*=\s*"([0-9.]+)"', cargo_toml, re.M)
    lib = least["library"][0]
    if not stated or version_key(stated.group(1)) < version_key(lib):
        failures.append(f"Cargo.toml's rust-version must be at least {short(lib)} (the library's)")
    for f in failures:
        print(f"scripts/msrv.py: {f}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
