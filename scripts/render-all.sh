#!/usr/bin/env bash
# Renders every scene given: BOOKSPIN OUT_DIR SCENE... . Scenes run in parallel where cores
# allow (one scene per two cores; each scene gets those two for rendering, PNG compression
# and encoding). Then plots each scene's diagnostics (OUT_DIR/<scene>-plot.png) and writes
# the gallery OUT_DIR/index.html. Stops with a non-zero status if any scene fails.
set -euo pipefail
bookspin=$1 out=$2
shift 2
cores=$(nproc)
parallel=$(( cores / 2 > 0 ? cores / 2 : 1 ))
jobs=$(( cores / parallel ))
echo "render-all: ${#@} scenes, $parallel at a time, --jobs $jobs each"
printf '%s\n' "$@" | xargs -P "$parallel" -I{} "$bookspin" render {} -o "$out" --jobs "$jobs"
echo "render-all: plotting"
printf '%s\n' "$@" | xargs -P "$cores" -I{} "$bookspin" plot {} -o "$out"
"$bookspin" gallery "$out" "$@"
echo "render-all: done; clips in $out/, gallery $out/index.html"
