#!/usr/bin/env bash
# Renders every scene given: BOOKSPIN OUT_DIR SCENE... . Then plots each scene's diagnostics
# (OUT_DIR/<scene>-plot.png) and writes the gallery OUT_DIR/index.html. Stops with a
# non-zero status if any scene fails.
#
# How the cores are shared: one render keeps about two cores busy even with --jobs 1 (the
# simulation and GL on one thread, llvmpipe's rasterizer, the encoder and a PNG worker
# overlap), and a render's own threads wait on each other now and then. So scenes run side
# by side, one per two cores but never fewer than two where there are two cores, and each
# gets an equal share of the cores through --jobs (which caps llvmpipe, x264 and the PNG
# workers alike). On the 2-core reference machine two scenes at --jobs 1 finished 7% sooner
# than one after the other at --jobs 2.
set -euo pipefail
bookspin=$1 out=$2
shift 2
cores=$(nproc)
parallel=$(( cores >= 2 ? (cores / 2 > 2 ? cores / 2 : 2) : 1 ))
parallel=$(( parallel < $# ? parallel : ($# > 0 ? $# : 1) ))
jobs=$(( cores / parallel > 0 ? cores / parallel : 1 ))
echo "render-all: ${#@} scenes, $parallel at a time, --jobs $jobs each"
printf '%s\n' "$@" | xargs -P "$parallel" -I{} "$bookspin" render {} -o "$out" --jobs "$jobs"
echo "render-all: plotting"
printf '%s\n' "$@" | xargs -P "$cores" -I{} "$bookspin" plot {} -o "$out"
"$bookspin" gallery "$out" "$@"
echo "render-all: done; clips in $out/, gallery $out/index.html"
