#!/usr/bin/env bash
# Builds the explorer page's program, BUILD_DIR/web/explorer-shell.html (docs/explorer.md):
#   1. the physics to WebAssembly (web/build-wasm.sh, Debian's emscripten),
#   2. the app bundled with esbuild (three.js; npm ci from web/package-lock.json when the
#      install step has not put the packages in place),
#   3. both inlined into the page by web/make_explorer.py;
#   4. beside it, the JavaScript engines (cannon-es, Rapier, Jolt, Havok: web/src/engines/) as a second
#      bundle, BUILD_DIR/web/explorer-engines.js, which only `bookspin explore --engines` writes
#      into the page (the WebAssembly of Rapier and Jolt is inlined in their packages, base64;
#      Havok's by esbuild), packed by web/pack_engines.py (gzip, base64) for the page to inflate;
#      the physics' WebAssembly is packed likewise by web/make_explorer.py (web/src/packed.js).
# `bookspin explore SCENE… -o OUT` (found beside the shell: BUILD_DIR/bookspin) then writes the
# scenes into it: OUT/explorer.html.
# One caller at a time (a lock in BUILD_DIR/web). Nothing to do, nothing done: BUILD_DIR/web/inputs.sha256 holds the hash of every input (these
# scripts, web/*.cpp and *.hpp, web/src/, package.json and its lockfile, src/physics/, src/common/,
# src/analysis/, src/fit/ and the few files of src/jobs/, src/products/ and src/scene/ the page
# compiles), written
# after a build; while it matches and the shell is there, the script rebuilds and rewrites
# nothing.
# Usage: web/build.sh BUILD_DIR
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
[ $# -eq 1 ] || { echo "usage: web/build.sh BUILD_DIR" >&2; exit 2; }
mkdir -p "$1"; build="$(cd "$1" && pwd)"
work="$build/web"
root="$(dirname "$here")"
stamp="$work/inputs.sha256"
# One build at a time per BUILD_DIR: the browser tests call this script at once from a fresh
# build tree, and two em++ runs writing the same .wasm break each other. The second waits,
# then finds the first's build up to date.
mkdir -p "$work"
exec 9>"$work/.build.lock"
flock 9
inputs=$(cd "$root" && find web/build.sh web/build-wasm.sh web/build-wasm-deps.sh web/make_explorer.py web/pack_engines.py \
           web/*.cpp web/*.hpp web/src web/package.json web/package-lock.json src/physics \
           src/common src/analysis src/jobs/motion_csv.* src/jobs/exact_motion.* src/fit \
           src/scene/limits.hpp -type f -print0 |
         sort -z | xargs -0 sha256sum | sha256sum | cut -d ' ' -f 1)
if [ -f "$work/explorer-shell.html" ] && [ -f "$work/explorer-engines.js" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$inputs" ]; then
  echo "web: up to date: $work/explorer-shell.html"
  exit 0
fi
rm -f "$stamp"
"$here/build-wasm.sh" "$work"
if [ ! -x "$here/node_modules/.bin/esbuild" ] || [ "$here/package-lock.json" -nt "$here/node_modules/.package-lock.json" ]; then
  (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)
fi
"$here/node_modules/.bin/esbuild" "$here/src/main.js" --bundle --format=iife --minify \
  --target=es2020 --log-level=warning --outfile="$work/explorer.bundle.js"
# The engines' bundle: the node branch of Jolt's loader (import("node:module")) stays unbundled
# and never runs in a browser; Havok's .wasm is inlined as bytes (the binary loader).
"$here/node_modules/.bin/esbuild" "$here/src/engines/index.js" --bundle --format=iife --minify \
  --target=es2020 --external:'node:*' --loader:.wasm=binary --log-level=warning \
  --outfile="$work/explorer-engines.bundle.js"
# Packed (gzip, its WebAssembly as bytes, base64) for the page to inflate as it starts.
python3 "$here/pack_engines.py" "$work/explorer-engines.bundle.js" "$work/explorer-engines.js"
python3 "$here/make_explorer.py" "$here/src/index.html" "$work/bookspin_physics.js" \
  "$work/explorer.bundle.js" "$work/explorer-shell.html"
echo "$inputs" > "$stamp"
