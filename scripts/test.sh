#!/usr/bin/env bash
# The README's test command: every workspace member's tests (the library with all its features,
# the Python bindings' crate, render-check), then the Python package's pytest suite in a fresh
# virtual environment, on a fresh machine included. This is what CI's test step runs.
#
# render-check renders with wgpu on Vulkan; a machine without a Vulkan driver gets Debian's
# software rasterizer (lavapipe, package mesa-vulkan-drivers) first. render-check's tests fail,
# naming that package, when no adapter is found; they never skip. The Python step needs python3
# with venv and pip, and PyPI (maturin, numpy, pytest; mypy for the stub checks, matplotlib for
# the examples, which python/tests/test_examples.py runs).
#
# Arguments are passed to `cargo test` (e.g. a test name filter).
set -euo pipefail
cd "$(dirname "$0")/.."

have_vulkan_icd() {
  local d
  for d in /usr/share/vulkan/icd.d /etc/vulkan/icd.d /usr/local/share/vulkan/icd.d; do
    if compgen -G "$d/*.json" >/dev/null; then
      return 0
    fi
  done
  return 1
}

if ! have_vulkan_icd; then
  echo "scripts/test.sh: no Vulkan driver (ICD) found; installing mesa-vulkan-drivers (lavapipe)"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
  fi
  $sudo apt-get update
  $sudo apt-get install -y mesa-vulkan-drivers
fi

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Mesa's window-system code prints "error: XDG_RUNTIME_DIR is invalid or not set" once per
# Vulkan instance when the variable names no directory (headless machines, CI). Give it a private
# one; nothing is written there.
if [ -z "${XDG_RUNTIME_DIR:-}" ] || [ ! -d "$XDG_RUNTIME_DIR" ]; then
  export XDG_RUNTIME_DIR="$scratch/xdg"
  mkdir -m 700 "$XDG_RUNTIME_DIR"
fi

echo "== cargo test --workspace --all-features"
cargo test --locked --workspace --all-features "$@"

echo "== Python package (python/): pip install into a fresh venv, pytest"
# The command line built by the tests above answers the eval-agreement tests.
cargo build --locked --features cli --bin shadow-aliasing
python3 -m venv "$scratch/venv"
"$scratch/venv/bin/python" -m pip install --quiet --upgrade pip
"$scratch/venv/bin/python" -m pip install --quiet ./python pytest numpy mypy matplotlib
echo "== Python stubs: stubtest against the installed module, mypy --strict on the stubs and examples"
# From the scratch directory, so that the module imported is the installed one (with its
# compiled extension), never the source tree python/shadow_aliasing.
allowlist="$PWD/python/stubtest-allowlist.txt"
(cd "$scratch" && "$scratch/venv/bin/python" -m mypy.stubtest shadow_aliasing --allowlist "$allowlist")
"$scratch/venv/bin/python" -m mypy --strict --cache-dir "$scratch/mypy-cache" \
  python/shadow_aliasing/__init__.pyi python/examples
SHADOW_ALIASING_BIN="$PWD/target/debug/shadow-aliasing" "$scratch/venv/bin/python" -m pytest -q python/tests
