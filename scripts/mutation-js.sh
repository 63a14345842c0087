#!/usr/bin/env bash
# Stryker (npm's @stryker-mutator/core, its command runner) on the explorer page's JavaScript
# that changed since 9f74334 and that node's tests reach (scripts/stryker.config.json names the
# lines): each mutant run against tests/web/*_test.mjs, the score and every survivor printed,
# the JSON report in build/stryker/mutation-report.json. Not part of `make test` (about 100 s on
# 2 cores; docs/explorer.md, "Mutation testing" has the last score measured).
# Stryker 8 (node 18 or later; Stryker 9 and 10 want node 22) and the page's three.js, which
# plots.js's import chain needs, are installed into BUILD/stryker from the npm registry once.
# With --npm: the npm package's ES module instead (npm/package/index.mjs, its lines changed
# since 9f74334: scripts/stryker-npm.config.json), each mutant run against tests/npm/index_test.mjs
# on the WebAssembly npm/build.sh made (BUILD/npm/package), one at a time; the report in
# build/stryker/npm-mutation-report.json (docs/flipcheck.md, "Mutation testing of the package").
# Usage: scripts/mutation-js.sh [--npm] [BUILD]
set -euo pipefail
config=scripts/stryker.config.json
if [ "${1:-}" = --npm ]; then
  config=scripts/stryker-npm.config.json
  shift
fi
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "${1:-$root/build}"
build="$(cd "${1:-$root/build}" && pwd)"
tool="$build/stryker"
three=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["dependencies"]["three"])' "$root/web/package.json")
if [ ! -x "$tool/node_modules/.bin/stryker" ] || [ ! -d "$tool/node_modules/three" ]; then
  mkdir -p "$tool"
  [ -f "$tool/package.json" ] || echo '{"name": "bookspin-stryker", "private": true}' > "$tool/package.json"
  (cd "$tool" && npm install --no-audit --no-fund --loglevel=error \
    "@stryker-mutator/core@8.7.1" "three@$three")
fi
cd "$root"
# The sandbox's web/node_modules: the tree's own where installed, else the one beside Stryker.
modules="$root/web/node_modules"
[ -d "$modules/three" ] || modules="$tool/node_modules"
if [ "$config" = scripts/stryker-npm.config.json ] && [ ! -f "$build/npm/package/flipcheck-wasm.cjs" ]; then
  echo "mutation-js.sh: $build/npm/package/flipcheck-wasm.cjs is not made (npm/build.sh $build)" >&2
  exit 1
fi
BOOKSPIN_WEB_MODULES="$modules" BOOKSPIN_NPM_PACKAGE="$build/npm/package" \
  "$tool/node_modules/.bin/stryker" run "$config"
