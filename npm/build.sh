#!/usr/bin/env bash
# Makes the npm package `flipcheck` (docs/flipcheck.md, "In your engine's tests"):
# BUILD/npm/flipcheck-VERSION.tgz, by `npm pack` of BUILD/npm/package/, which holds
#   flipcheck-wasm.cjs   the judge and the exact motion compiled by Debian's emscripten, the
#                        WebAssembly inside (-sSINGLE_FILE): src/physics, the conformance kit's
#                        pure files as web/build-wasm.sh compiles them for the page, and
#                        npm/flipcheck_bindings.cpp
#   scenarios/*.json     the seven scenarios as `bookspin flipcheck export` writes them
#   index.mjs, index.d.ts, cli.mjs, files.mjs, README.md, package.json   from npm/package/
#   well_formed.js       the lone-surrogate check, the page's own (web/src/well_formed.js)
# Usage: npm/build.sh BUILD_DIR [OUT_DIR]   (needs BUILD_DIR/bookspin; OUT_DIR is BUILD/npm unless
# given, objects cached in OUT_DIR/obj, or copied from the page's up-to-date ones in
# BUILD_DIR/web/obj: scripts/figures.sh builds its own, which no test reads, after the page's)
# Exit 3 where em++ or npm is missing.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
build="$(cd "${1:?usage: npm/build.sh BUILD_DIR}" && pwd)"
mkdir -p "${2:-$build/npm}"
out="$(cd "${2:-$build/npm}" && pwd)"
command -v em++ >/dev/null || { echo "npm/build.sh: em++ not found (apt-get install emscripten)" >&2; exit 3; }
command -v npm >/dev/null || { echo "npm/build.sh: npm not found (scripts/install-deps.sh)" >&2; exit 3; }
[ -x "$build/bookspin" ] || { echo "npm/build.sh: $build/bookspin not built" >&2; exit 3; }
# The one version (VERSION, docs/flipcheck.md "Versions"): package.json's and the WebAssembly's.
version="$(sed -n 's/^version \([0-9]*\.[0-9]*\.[0-9]*\)$/\1/p' "$root/VERSION")"
[ -n "$version" ] || { echo "npm/build.sh: VERSION has no line \"version MAJOR.MINOR.PATCH\"" >&2; exit 1; }
# Boost reached through the page's build's include folder (web/build-wasm.sh), so that its
# compiler lines, and ccache's keys, are the page's: a file compiled for one is not compiled again.
include="$build/web/include"
mkdir -p "$out/obj" "$include"
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
if command -v ccache >/dev/null && [ -z "${EM_COMPILER_WRAPPER:-}" ]; then
  export EM_COMPILER_WRAPPER=ccache CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
fi
[ -L "$include/boost" ] || ln -sfn /usr/include/boost "$include/boost" 2>/dev/null || [ -L "$include/boost" ]
flags=(-std=c++20 -O3 -DNDEBUG -I"$root/src" -I/usr/include/eigen3 -isystem "$include"
       -Wall -Wextra -fexceptions)
# The same pure files the page's judge compiles (web/build-wasm.sh): no I/O, no engine, no scene
# reader, no fit.
sources=("$root"/src/physics/*.cpp "$root/src/analysis/motion.cpp" "$root/src/analysis/judgement.cpp" "$root/src/analysis/scenario_file.cpp"
         "$root/src/jobs/motion_csv.cpp" "$root/src/jobs/exact_motion.cpp" "$here/flipcheck_bindings.cpp")
for name in errors number_text csv_writer json_writer json_string text_lines version; do
  sources+=("$root/src/common/$name.cpp")
done
objs=()
pids=()
# stale OBJ SRC: OBJ is missing or older than SRC, than a header it may include, or (the version's
# file) than VERSION.
stale() {
  [ ! -f "$1" ] || [ "$2" -nt "$1" ] ||
    { [ "$2" = "$root/src/common/version.cpp" ] && [ "$root/VERSION" -nt "$1" ]; } ||
    [ -n "$(find "$root/src/physics" "$root/src/analysis" "$root/src/jobs" "$root/src/common" \
              "$root/web/guarded.hpp" "$root/web/judgement_value.hpp" -name '*.hpp' -newer "$1" -print -quit)" ]
}
# The page's program compiles every one of these files but the bindings with these very flags
# (web/build-wasm.sh, into BUILD/web/obj/): where its object is there and up to date it is
# copied, under the page build's lock, rather than compiled again (scripts/figures.sh builds the
# page just before this package).
page_obj_dir="$build/web/obj"
for src in "${sources[@]}"; do
  obj="$out/obj/$(basename "$(dirname "$src")")-$(basename "${src%.cpp}").o"
  objs+=("$obj")
  extra=()
  # The version on its one file, as src/common/CMakeLists.txt compiles it.
  if [ "$src" = "$root/src/common/version.cpp" ]; then
    extra=(-DBOOKSPIN_VERSION="\"$version\"")
  fi
  stale "$obj" "$src" || continue
  page_obj="$page_obj_dir/$(basename "${src%.cpp}").o"
  if [ "$src" != "$here/flipcheck_bindings.cpp" ] && ! stale "$page_obj" "$src" &&
     flock "$build/web/.build.lock" cp -p "$page_obj" "$obj" && ! stale "$obj" "$src"; then
    continue
  fi
  em++ "${flags[@]}" "${extra[@]}" -c "$src" -o "$obj" &
  pids+=($!)
  if [ ${#pids[@]} -ge "${JOBS:-2}" ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
done
for p in "${pids[@]}"; do wait "$p"; done
package="$out/package"
rm -rf "$package" "$out/export"
mkdir -p "$package/scenarios"
em++ -O3 -fexceptions --bind "${objs[@]}" -o "$package/flipcheck-wasm.cjs" \
  -sSINGLE_FILE=1 -sMODULARIZE=1 -sEXPORT_NAME=FlipcheckWasm -sALLOW_MEMORY_GROWTH=1 \
  -sENVIRONMENT=node -sDISABLE_EXCEPTION_CATCHING=0
# The scenarios as the command line exports them (their JSON only: the exact motion is computed).
"$build/bookspin" flipcheck export "$root"/scenes/flipcheck/*.toml -o "$out/export" >/dev/null
cp "$out/export"/*.json "$package/scenarios/"
for f in index.mjs index.d.ts cli.mjs files.mjs README.md; do cp "$here/package/$f" "$package/"; done
# The page's lone-surrogate check, one module for both (docs/architecture.md, "The npm package").
cp "$root/web/src/well_formed.js" "$package/"
sed "s/@VERSION@/$version/" "$here/package/package.json.in" >"$package/package.json"
rm -f "$out"/flipcheck-*.tgz
(cd "$package" && npm pack --pack-destination "$out" --silent >/dev/null)
tgz="$out/flipcheck-$version.tgz"
[ -f "$tgz" ] || { echo "npm/build.sh: npm pack made no $tgz" >&2; exit 1; }
echo "npm/build.sh: $tgz ($(stat -c %s "$tgz") bytes)"
