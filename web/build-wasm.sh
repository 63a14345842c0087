#!/usr/bin/env bash
# Compiles src/physics and web/bindings.cpp with Debian's emscripten into one JavaScript file
# holding the WebAssembly (-sSINGLE_FILE=1, -sMODULARIZE): OUT/bookspin_physics.js.
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
# Eigen and Boost.Math are header-only: reach Debian's copies without the host's /usr/include
# (whose libc headers would shadow emscripten's).
mkdir -p "$out/include"
ln -sfn /usr/include/boost "$out/include/boost"
flags=(-std=c++20 -O3 -DNDEBUG -I"$root/src" -I/usr/include/eigen3 -isystem "$out/include"
       -Wall -Wextra -fexceptions)
objs=()
pids=()
# The physics whole; of analysis and clip only the two pure-Eigen files the page measures and
# draws with (the flip detector, the trilinear cage), which include nothing but src/physics;
# for the "Judge a motion" panel, the conformance kit's pure files (the judgement, the motion
# CSV's parser, the exact motion and the scenario file) and the writers of common they use
# (numbers, CSV, JSON, errors): no I/O, no engine, no scene reader (docs/architecture.md).
pure=("$root/src/analysis/motion.cpp" "$root/src/analysis/judgement.cpp"
      "$root/src/jobs/motion_csv.cpp" "$root/src/jobs/exact_motion.cpp"
      "$root/src/clip/body_drawing.cpp")
for name in errors number_text csv_writer json_writer json_string text_lines; do
  pure+=("$root/src/common/$name.cpp")
done
for src in "$root"/src/physics/*.cpp "${pure[@]}" "$here/bindings.cpp" "$here/judge_bindings.cpp"; do
  obj="$out/obj/$(basename "${src%.cpp}").o"
  objs+=("$obj")
  if [ ! -f "$obj" ] || [ "$src" -nt "$obj" ] || [ -n "$(find "$root/src/physics" "$root/src/analysis/motion.hpp" "$root/src/clip/body_drawing.hpp" "$root/src/analysis/judgement.hpp" "$root/src/jobs" "$root/src/common" "$here/body_spec.hpp" \
       -name '*.hpp' -newer "$obj" -print -quit)" ]; then
    em++ "${flags[@]}" -c "$src" -o "$obj" &
    pids+=($!)
    # two compilers at a time
    if [ ${#pids[@]} -ge "${JOBS:-2}" ]; then wait "${pids[0]}"; pids=("${pids[@]:1}"); fi
  fi
done
for p in "${pids[@]}"; do wait "$p"; done
em++ -O3 -fexceptions --bind "${objs[@]}" -o "$out/bookspin_physics.js" \
  -sSINGLE_FILE=1 -sMODULARIZE=1 -sEXPORT_NAME=BookspinPhysics -sALLOW_MEMORY_GROWTH=1 \
  -sENVIRONMENT=web,worker,node -sDISABLE_EXCEPTION_CATCHING=0
echo "build-wasm: $out/bookspin_physics.js ($(stat -c %s "$out/bookspin_physics.js") bytes)"
