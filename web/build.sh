#!/usr/bin/env bash
# Builds the WebAssembly module of shadow-aliasing-web and copies it into the npm package
# (web/npm/shadow_aliasing.wasm). docs/web.md, "Building".
#
# rustup has no wasm32 standard library here; Debian's rustc-web builds one from rust-web-src
# (`-Zbuild-std`, allowed on a stable compiler by RUSTC_BOOTSTRAP=1), linked by LLVM's wasm-ld
# (Debian's /usr/bin/rust-lld is a dangling link). Only this build uses that compiler: rustup's
# stays first on PATH for everything else. Its own target directory keeps the two compilers'
# products apart. Needs: apt-get install rustc-web cargo-web rust-web-src lld.
set -euo pipefail
cd "$(dirname "$0")/.."
for f in /usr/bin/rustc /usr/bin/cargo /usr/bin/wasm-ld-14; do
  if [ ! -x "$f" ]; then
    echo "web/build.sh: $f is missing: apt-get install -y rustc-web cargo-web rust-web-src lld" >&2
    exit 1
  fi
done
target_dir="${SAW_TARGET_DIR:-$PWD/target/web}"
RUSTC=/usr/bin/rustc RUSTC_BOOTSTRAP=1 \
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER=/usr/bin/wasm-ld-14 \
  CARGO_PROFILE_RELEASE_PANIC=abort CARGO_PROFILE_RELEASE_LTO=true \
  CARGO_PROFILE_RELEASE_CODEGEN_UNITS=1 CARGO_PROFILE_RELEASE_OPT_LEVEL=3 \
  CARGO_TARGET_DIR="$target_dir" \
  /usr/bin/cargo build --locked --release -p shadow-aliasing-web \
  -Zbuild-std=std,panic_abort --target wasm32-unknown-unknown
cp "$target_dir/wasm32-unknown-unknown/release/shadow_aliasing_web.wasm" web/npm/shadow_aliasing.wasm
ls -l web/npm/shadow_aliasing.wasm
