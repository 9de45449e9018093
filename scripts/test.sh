#!/usr/bin/env bash
# The README's test command: every workspace member's tests (the library with all its features,
# the Python bindings' crate, render-check), on a fresh machine included. render-check renders with
# wgpu on Vulkan; a machine without a Vulkan driver gets Debian's software rasterizer (lavapipe,
# package mesa-vulkan-drivers) first. render-check's tests fail, naming that package, when no
# adapter is found; they never skip.
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

cargo test --locked --workspace --all-features "$@"
