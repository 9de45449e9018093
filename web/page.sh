#!/usr/bin/env bash
# Builds the WebAssembly module (web/build.sh) and serves the live page on 127.0.0.1:
# open http://127.0.0.1:${1:-8000}/page/index.html (docs/web.md, "The live page").
set -euo pipefail
cd "$(dirname "$0")/.."
web/build.sh
exec node web/serve.mjs "${1:-8000}"
