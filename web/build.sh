#!/usr/bin/env bash
# Builds the explorer page's program, BUILD_DIR/web/explorer-shell.html (docs/explorer.md):
#   1. the physics to WebAssembly (web/build-wasm.sh, Debian's emscripten),
#   2. the app bundled with esbuild (three.js; npm ci from web/package-lock.json when the
#      install step has not put the packages in place),
#   3. both inlined into the page by web/make_explorer.py.
# `bookspin explore SCENE… -o OUT` (found beside the shell: BUILD_DIR/bookspin) then writes the
# scenes into it: OUT/explorer.html.
# Usage: web/build.sh BUILD_DIR
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
[ $# -eq 1 ] || { echo "usage: web/build.sh BUILD_DIR" >&2; exit 2; }
mkdir -p "$1"; build="$(cd "$1" && pwd)"
work="$build/web"
"$here/build-wasm.sh" "$work"
if [ ! -x "$here/node_modules/.bin/esbuild" ] || [ "$here/package-lock.json" -nt "$here/node_modules/.package-lock.json" ]; then
  (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
fi
"$here/node_modules/.bin/esbuild" "$here/src/main.js" --bundle --format=iife --minify \
  --target=es2020 --log-level=warning --outfile="$work/explorer.bundle.js"
python3 "$here/make_explorer.py" "$here/src/index.html" "$work/bookspin_physics.js" \
  "$work/explorer.bundle.js" "$work/explorer-shell.html"
