#!/usr/bin/env bash
# Renders every scene given: BOOKSPIN OUT_DIR SCENE... . Scenes run in parallel where cores
# allow (one scene per two cores; each scene gets those two for rendering, PNG compression
# and encoding). Stops with a non-zero status if any scene fails.
set -euo pipefail
bookspin=$1 out=$2
shift 2
cores=$(nproc)
parallel=$(( cores / 2 > 0 ? cores / 2 : 1 ))
jobs=$(( cores / parallel ))
echo "render-all: ${#@} scenes, $parallel at a time, --jobs $jobs each"
printf '%s\n' "$@" | xargs -P "$parallel" -I{} "$bookspin" render {} -o "$out" --jobs "$jobs"
echo "render-all: done; clips in $out/"
