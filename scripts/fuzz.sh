#!/usr/bin/env bash
# Builds the two fuzzers with clang and runs them. The scene parser: first every saved
# regression input, then RUNS fresh executions (default 1,000,000) from a seed corpus of
# scenes/ and tests/bad_scenes/. The mesh validation layer (mesh stage + body_from_mesh):
# MESH_RUNS executions (default 10,000; each writes a file for assimp, about 25 a second on the 2-core machine) from tests/fuzz/mesh_seeds
# and the bad meshes, with a fixed seed so that a run here repeats in CI. The exact motion
# (tests/fuzz/exact_fuzzer.cpp: any moments, ω0 and t give finite states or the true refusal):
# EXACT_RUNS executions (default 300,000) with a fixed seed, after the mesh layer on its core
# (both beside the scene parser). A crash leaves its
# input in build-fuzz/crash-*; copy it into tests/fuzz/regressions/ (scene) or
# tests/fuzz/mesh_seeds/ (mesh) so that every later run replays it; the exact motion's (it
# prints the moments, ω0 and t that broke the property) becomes a case of
# tests/physics/exact_horizon_test.cpp.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${RUNS:-1000000}
mesh_runs=${MESH_RUNS:-10000}
exact_runs=${EXACT_RUNS:-300000}
cmake -S . -B build-fuzz -DBOOKSPIN_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz --target scene_fuzzer mesh_fuzzer exact_fuzzer -j "$(nproc)"
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

# Mesh inputs: a format byte (even: OBJ, odd: STL) before the file's bytes.
mesh_corpus=build-fuzz/mesh-corpus
rm -rf "$mesh_corpus" && mkdir -p "$mesh_corpus"
cp tests/fuzz/mesh_seeds/* "$mesh_corpus"/
for f in tests/bad_meshes/*.obj tests/bad_meshes/*.stl; do
  [ -f "$f" ] || continue
  case "$f" in *.obj) byte='\x00' ;; *) byte='\x01' ;; esac
  { printf "$byte"; head -c 4096 "$f"; } > "$mesh_corpus/$(basename "$f")"
done
# The two fuzzers side by side (one process each: two cores in use where there are two), each
# into its log; the logs' ends printed in turn, and a crash of either fails the script.
scene_fuzz() {
  (cd build-fuzz && ./tests/fuzz/scene_fuzzer -runs="$runs" -max_len=4096 -print_final_stats=1 corpus)
}
mesh_fuzz() {
  (cd build-fuzz && LSAN_OPTIONS=suppressions=$PWD/../tests/fuzz/assimp_leaks.supp:print_suppressions=0 \
    ./tests/fuzz/mesh_fuzzer -runs="$mesh_runs" -seed=1 -max_len=4096 -print_final_stats=1 mesh-corpus)
}
# The exact motion's seeds: one input of each mode (raw doubles, a seeded draw); libFuzzer
# mutates from them.
exact_corpus=build-fuzz/exact-corpus
rm -rf "$exact_corpus" && mkdir -p "$exact_corpus"
printf '\x01\x52\x00\x00\x00\x00\x00\x00\x00' > "$exact_corpus/seeded"
python3 -c 'import struct,sys; sys.stdout.buffer.write(b"\0" + struct.pack("<10d", 1, 2, 3, 0.1, 1, 0.05, 0, 1e300, 1e12, -5))' \
  > "$exact_corpus/raw"
exact_fuzz() {
  (cd build-fuzz && ./tests/fuzz/exact_fuzzer -runs="$exact_runs" -seed=1 -max_len=128 -print_final_stats=1 exact-corpus)
}
echo "fuzz: $runs executions of the scene parser, $mesh_runs of the mesh layer then $exact_runs of the exact motion, side by side"
scene_fuzz > build-fuzz/scene-fuzz.log 2>&1 &
scene_pid=$!
rm -f build-fuzz/exact-fuzz.rc
(
  mesh_rc=0 exact_rc=0
  mesh_fuzz > build-fuzz/mesh-fuzz.log 2>&1 || mesh_rc=$?
  exact_fuzz > build-fuzz/exact-fuzz.log 2>&1 || exact_rc=$?
  echo "$exact_rc" > build-fuzz/exact-fuzz.rc
  exit "$mesh_rc"
) &
mesh_pid=$!
scene_rc=0 mesh_rc=0
wait "$scene_pid" || scene_rc=$?
wait "$mesh_pid" || mesh_rc=$?
exact_rc=$(cat build-fuzz/exact-fuzz.rc 2>/dev/null || echo 1)
echo "fuzz: the scene parser (exit $scene_rc):"
tail -15 build-fuzz/scene-fuzz.log
echo "fuzz: the mesh layer (exit $mesh_rc):"
tail -15 build-fuzz/mesh-fuzz.log
echo "fuzz: the exact motion (exit $exact_rc):"
tail -15 build-fuzz/exact-fuzz.log 2>/dev/null || true
[ "$scene_rc" -eq 0 ] && [ "$mesh_rc" -eq 0 ] && [ "$exact_rc" -eq 0 ]
