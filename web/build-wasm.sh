#!/usr/bin/env bash
# Compiles src/physics and web/bindings.cpp with Debian's emscripten into one JavaScript file
# holding the WebAssembly (-sSINGLE_FILE=1, -sMODULARIZE): OUT/bookspin_physics.js; with it the
# judge (web/judge_bindings.cpp) and the fit (web/fit_bindings.cpp: src/fit with Ceres, minizip
# and zlib built from Debian's source by web/build-wasm-deps.sh into OUT/deps/prefix).
# Usage: web/build-wasm.sh OUT_DIR   (objects cached in OUT_DIR/obj, rebuilt when newer)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
mkdir -p "${1:-$root/build/web}"
out="$(cd "${1:-$root/build/web}" && pwd)"
mkdir -p "$out/obj"
command -v em++ >/dev/null || { echo "build-wasm: em++ not found (apt-get install emscripten)" >&2; exit 3; }
# Debian's em++ finds its acorn module through NODE_PATH.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
# Debian's ccache in front of emscripten's clang where it is installed: unchanged files are not
# compiled again, in this build tree or a clone elsewhere (docs/performance.md, "CI").
if command -v ccache >/dev/null && [ -z "${EM_COMPILER_WRAPPER:-}" ]; then
  export EM_COMPILER_WRAPPER=ccache CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
fi
# Eigen and Boost.Math are header-only: reach Debian's copies without the host's /usr/include
# (whose libc headers would shadow emscripten's).
mkdir -p "$out/include"
ln -sfn /usr/include/boost "$out/include/boost"
"$here/build-wasm-deps.sh" "$out"
prefix="$out/deps/prefix"
flags=(-std=c++20 -O3 -DNDEBUG -I"$root/src" -I/usr/include/eigen3 -isystem "$out/include"
       -Wall -Wextra -fexceptions)
# The fit's files: Ceres's headers with its miniglog, minizip's as libminizip-dev has them.
fit_flags=(-DBOOKSPIN_MINIGLOG -isystem "$prefix/include" -isystem "$prefix/include/ceres/internal/miniglog"
           -isystem "$prefix/include/minizip")
objs=()
pids=()
# The physics whole; of analysis and clip only the two pure-Eigen files the page measures and
# draws with (the flip detector, the trilinear cage), which include nothing but src/physics;
# for the "Judge a motion" panel, the conformance kit's pure files (the judgement, the motion
# CSV's parser, the exact motion and the scenario file) and the writers of common they use
# (numbers, CSV, JSON, errors): no I/O, no engine, no scene reader (docs/architecture.md).
pure=("$root/src/analysis/motion.cpp" "$root/src/analysis/judgement.cpp" "$root/src/analysis/scenario_file.cpp"
      "$root/src/jobs/motion_csv.cpp" "$root/src/jobs/exact_motion.cpp"
      "$root/src/clip/body_drawing.cpp")
for name in errors number_text csv_writer json_writer json_string text_lines text_file version file_name; do
  pure+=("$root/src/common/$name.cpp")
done
# The one version (VERSION, docs/flipcheck.md "Versions"), on its one file as
# src/common/CMakeLists.txt compiles it: the page shows it and its judgements record it.
version="$(sed -n 's/^version \([0-9]*\.[0-9]*\.[0-9]*\)$/\1/p' "$root/VERSION")"
[ -n "$version" ] || { echo "build-wasm: VERSION has no line \"version MAJOR.MINOR.PATCH\"" >&2; exit 1; }
# For the "Phone-toss lab" panel: the fit stage whole (the recording's reader, the flights, the
# fit, its tables, each toss's chart data and scene values: its report): no chart drawn, no
# file written.
fit_sources=("$root"/src/fit/*.cpp "$here/fit_bindings.cpp")
for src in "$root"/src/physics/*.cpp "${pure[@]}" "$here/bindings.cpp" "$here/judge_bindings.cpp" "${fit_sources[@]}"; do
  obj="$out/obj/$(basename "${src%.cpp}").o"
  objs+=("$obj")
  extra=()
  case " ${fit_sources[*]} " in *" $src "*) extra=("${fit_flags[@]}");; esac
  # The file-name rule's utf8proc, built by build-wasm-deps.sh.
  [ "$src" = "$root/src/common/file_name.cpp" ] && extra=(-DUTF8PROC_STATIC -isystem "$prefix/include")
  stale=0
  if [ "$src" = "$root/src/common/version.cpp" ]; then
    extra=(-DBOOKSPIN_VERSION="\"$version\"")
    [ "$root/VERSION" -nt "$obj" ] && stale=1
  fi
  if [ "$stale" = 1 ] || [ ! -f "$obj" ] || [ "$src" -nt "$obj" ] || [ "$out/deps/inputs.sha256" -nt "$obj" ] || [ -n "$(find "$root/src/physics" "$root/src/analysis/motion.hpp" "$root/src/clip/body_drawing.hpp" "$root/src/analysis/judgement.hpp" "$root/src/analysis/scenario_file.hpp" "$root/src/jobs" "$root/src/common" "$root/src/fit" "$root/src/scene/limits.hpp" "$here/body_spec.hpp" "$here/guarded.hpp" "$here/judgement_value.hpp" \
       -name '*.hpp' -newer "$obj" -print -quit)" ]; then
    em++ "${flags[@]}" "${extra[@]}" -c "$src" -o "$obj" &
    pids+=($!)
    # two compilers at a time
    if [ ${#pids[@]} -ge "${JOBS:-2}" ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
  fi
done
for p in "${pids[@]}"; do wait "$p"; done
em++ -O3 -fexceptions --bind "${objs[@]}" "$prefix/lib/libceres.a" "$prefix/lib/libminizip.a" \
  "$prefix/lib/libz.a" "$prefix/lib/libutf8proc.a" -o "$out/bookspin_physics.js" \
  -sSINGLE_FILE=1 -sMODULARIZE=1 -sEXPORT_NAME=BookspinPhysics -sALLOW_MEMORY_GROWTH=1 \
  -sENVIRONMENT=web,worker,node -sDISABLE_EXCEPTION_CATCHING=0
echo "build-wasm: $out/bookspin_physics.js ($(stat -c %s "$out/bookspin_physics.js") bytes)"
