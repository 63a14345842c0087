#!/usr/bin/env bash
# Builds the scene-parser fuzzer with clang and runs it: first every saved regression input,
# then RUNS fresh executions (default 1,000,000) from a seed corpus of scenes/ and
# tests/bad_scenes/. A crash leaves its input in build-fuzz/crash-*; copy it into
# tests/fuzz/regressions/ so that every later run replays it.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-1000000}
cmake -S . -B build-fuzz -DBOOKSPIN_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz --target scene_fuzzer -j "$(nproc)"
corpus=build-fuzz/corpus
rm -rf "$corpus" && mkdir -p "$corpus"
cp scenes/*.toml "$corpus"/
cp tests/bad_scenes/*.toml "$corpus"/ 2>/dev/null || true
regressions=$(find tests/fuzz/regressions -type f ! -name README.md)
if [ -n "$regressions" ]; then
  echo "fuzz: replaying $(echo "$regressions" | wc -l) regression inputs"
  # shellcheck disable=SC2086
  build-fuzz/tests/fuzz/scene_fuzzer $regressions
fi
echo "fuzz: $runs executions"
cd build-fuzz && ./tests/fuzz/scene_fuzzer -runs="$runs" -max_len=4096 -print_final_stats=1 corpus 2>&1 | tail -15
