#!/usr/bin/env bash
# Builds OUT/explorer.html, one self-contained file (docs/explorer.md):
#   1. the physics to WebAssembly (web/build-wasm.sh, Debian's emscripten),
#   2. the app bundled with esbuild (three.js; npm ci from web/package-lock.json),
#   3. each scene's settings and the book's faces from bookspin-explorer-data,
#   4. all inlined by web/make_explorer.py.
# Usage: web/build.sh BUILD_DIR OUT_DIR SCENE...   (BUILD_DIR holds bookspin-explorer-data)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "$1" && pwd)"; shift
mkdir -p "$1"; out="$(cd "$1" && pwd)"; shift
work="$build/web"
"$here/build-wasm.sh" "$work"
if [ ! -x "$here/node_modules/.bin/esbuild" ] || [ "$here/package-lock.json" -nt "$here/node_modules/.package-lock.json" ]; then
  (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
fi
"$here/node_modules/.bin/esbuild" "$here/src/main.js" --bundle --format=iife --minify \
  --target=es2020 --log-level=warning --outfile="$work/explorer.bundle.js"
"$build/bookspin-explorer-data" "$work/data" "$@"
python3 "$here/make_explorer.py" "$here/src/index.html" "$work/data" \
  "$work/bookspin_physics.js" "$work/explorer.bundle.js" "$out/explorer.html"
