#!/usr/bin/env bash
# Every figure of `make figures` into OUT: the sweeps, the engines' accuracy report, the
# phone-toss lab's fit of the sample recording, every scene rendered and plotted
# (scripts/render-all.sh), the conformance kit's league table, the explorer page (where
# emscripten and npm are installed), then the gallery OUT/index.html, in that order, so that
# the one gallery written at the end shows and links them all (docs/outputs.md).
#
# Usage: scripts/figures.sh BUILD_DIR OUT [--quick]
#   --quick: the same commands on the same scenes and sweeps, each made small (a few frames at
#   160×96, three points per swept key, two time steps, one flip): what the figures test
#   (tests/figures/) runs to check the page `make figures` writes, in about a minute.
set -euo pipefail
[ $# -ge 2 ] && [ $# -le 3 ] || { echo "usage: scripts/figures.sh BUILD_DIR OUT [--quick]" >&2; exit 2; }
build=$1 out=$2 quick=${3:-}
[ -z "$quick" ] || [ "$quick" = --quick ] || { echo "figures: unknown option $quick" >&2; exit 2; }
root="$(cd "$(dirname "$0")/.." && pwd)"
bookspin="$build/bookspin"
cd "$root"

# Nothing changed, nothing done: OUT/.logs/figures.stamp holds the hash of every input of this
# script (the program, these scripts, the scenes, sweeps and recordings, the sources the
# explorer page is built from, the npm lockfile, the tools found, --quick) and the listing of
# every file under OUT but its logs (path, size, modification time) as the last whole run left
# them. While both match, the script runs nothing and writes nothing: each product would find
# itself up to date, but one process each, about 60 of them, took 13 s on the 2-core machine.
stamp="$out/.logs/figures.stamp"
inputs_hash() {
  { sha256sum "$bookspin"
    find scripts scenes sweeps recordings src web -path web/node_modules -prune -o -type f -print0 |
      sort -z | xargs -0 sha256sum
    command -v node npm em++ || true
    node --version 2>/dev/null || true
    echo "quick=$quick"; } | sha256sum | cut -d ' ' -f 1
}
listing() { find "$out" -path "$out/.logs" -prune -o -type f -printf '%P %s %T@\n' | LC_ALL=C sort; }
hash=$(inputs_hash)
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$(echo "$hash"; listing)" ]; then
  echo "figures: up to date: nothing changed since the last run ($stamp)"
  exit 0
fi
rm -f "$stamp"

# Each stage's seconds, printed as it ends and together at the end (docs/performance-build.md,
# "The first make figures").
stage_start=$(date +%s) stage_table=()
stage_done() {
  local now; now=$(date +%s)
  stage_table+=("$(printf '%-44s %5d s' "$1" $((now - stage_start)))")
  echo "figures: $1: $((now - stage_start)) s"
  stage_start=$now
}

# In the background from the start, one after the other: the explorer page's program
# (WebAssembly: Ceres, minizip and zlib, then the physics; the app's bundles), then the npm
# package flipcheck whose reader the league's JavaScript engines read each scenario with
# (npm/build.sh into BUILD/npm-figures, which no test reads while it is rebuilt; it links the
# page's up-to-date objects of the files both compile, so only its bindings compile). Beside them run
# the sweeps, the engines' accuracy, the fit and the renders; the league, the page and the
# gallery that links both come once the background is done (docs/performance-build.md, "The first
# make figures"). Each build's exit status lands in OUT/.logs/<name>.exit.
web_pid=
mkdir -p "$out/.logs"
js_engines=
if command -v node >/dev/null && node web/flipcheck-engines.mjs --check >/dev/null &&
   command -v em++ >/dev/null && command -v npm >/dev/null; then
  js_engines=1
fi
rm -f "$out/.logs/web-build.exit" "$out/.logs/npm-build.exit"
if command -v em++ >/dev/null && command -v npm >/dev/null; then
  (
    status=0
    bash web/build.sh "$build" > "$out/.logs/web-build.log" 2>&1 || status=$?
    echo "$status" > "$out/.logs/web-build.exit"
    if [ -n "$js_engines" ]; then
      status=0
      bash npm/build.sh "$build" "$build/npm-figures" > "$out/.logs/npm-build.log" 2>&1 || status=$?
      echo "$status" > "$out/.logs/npm-build.exit"
    fi
  ) &
  web_pid=$!
fi

# The swept points: full, or three per key with --quick.
points() { if [ -n "$quick" ]; then echo 3; else echo "$1"; fi; }
frames=() duration=()
dts=(0.03333333333333333 0.016666666666666666 0.008333333333333333 0.004 0.002 0.001 0.0005 0.00025)
flips=()
if [ -n "$quick" ]; then
  frames=(--set time.frames=4) duration=(--set time.duration=2)
  dts=(0.03333333333333333 0.016666666666666666)
  flips=(--flips 1)
  export RENDER_ARGS='--frames 3 --set render.width=160 --set render.height=96 --set render.preset="ultrafast"'
  export PLOT_ARGS='--set time.frames=3 --width 640 --height 400'
fi

"$bookspin" sweep sweeps/flip-time-vs-perturbation.toml "${frames[@]}" \
  --vary "initial.angular_velocity[1]=1e-6:1e-2:$(points 20):log" \
  --measure first_flip,flip_period,energy_drift,orientation_error -o "$out"
"$bookspin" sweep sweeps/t-handle-flip-time-vs-perturbation.toml "${frames[@]}" \
  --vary "initial.angular_velocity[0]=1e-6:1e-2:$(points 20):log" \
  --measure first_flip,flip_period,energy_drift,orientation_error -o "$out"
for f in sweeps/when-to-normalize*.toml; do
  "$bookspin" sweep "$f" "${duration[@]}" --vary "time.dt=0.0020833333333333333:0.125:$(points 7):log" \
    --vary "model.normalize_every=1:10000:$(points 9):log" \
    --measure orientation_error,diverged_at -o "$out"
done
"$bookspin" sweep sweeps/tennis-racket-twist.toml "${duration[@]}" \
  --vary "initial.angular_velocity[0]=1e-3:3:$(points 25):log" --measure twist,flip_period -o "$out"
stage_done "sweeps"
"$bookspin" accuracy sweeps/engines-energy-vs-dt.toml "${flips[@]}" \
  --methods engines,rigid-quaternion:rk4,rigid-quaternion:implicit-midpoint,rigid-quaternion:splitting4 \
  --dt "${dts[@]}" -o "$out"
stage_done "engines' accuracy"
# The phone-toss lab (docs/phone-lab.md) on the sample recording (recordings/README.md): the
# fit's CSVs, a chart, a scene and a clip of each toss (the book drawn, 640×360; --quick: in
# real time), which the gallery shows and the explorer page below opens (?scene=<recording>-toss1).
recording=phone-on-book-synthetic
fit_quick=()
[ -z "$quick" ] || fit_quick=(--slow-motion 1)
"$bookspin" fit "recordings/$recording" --render --scene "recordings/$recording.toml" \
  "${fit_quick[@]}" -o "$out"
tosses=("$out/$recording"-toss[0-9]*.toml)
stage_done "phone-toss fit and its clips"
# Every scene rendered and plotted; the gallery comes last, once the league and the page it
# links are there.
GALLERY=0 bash scripts/render-all.sh "$bookspin" "$out" scenes/*.toml
stage_done "renders and plots"
[ -z "$web_pid" ] || wait "$web_pid"
stage_done "waiting for the page's WebAssembly and the npm package"
# The conformance kit's league table (docs/flipcheck.md): the scenarios exported, the
# JavaScript engines run on them under node (where web/node_modules is installed), then every
# method and mode bookspin has judged beside them: OUT/flipcheck-league.html, which the gallery
# links. --quick: two methods (the scenarios as they are: seconds).
league_methods=all
[ -z "$quick" ] || league_methods=rigid-quaternion:rk4,mujoco:rk4
"$bookspin" flipcheck export scenes/flipcheck/*.toml -o "$out/flipcheck"
motions=("$out"/flipcheck/*-exact.csv)
# The engines' step is cached (its manifest: the scenarios, the lockfile, the adapters, the
# engines run): with nothing changed it writes nothing. --quick: two of the eleven engine modes
# (the test of every one is Flipcheck.JavaScriptEnginesUnderNode).
engines_quick=()
[ -z "$quick" ] || engines_quick=(--only cannon-es,babylonjs-havok)
# The runner checks every package it imports (--check: one line naming the missing ones); it
# reads each scenario with the npm package flipcheck's reader, built in the background above.
if [ -n "$js_engines" ]; then
  if [ "$(cat "$out/.logs/npm-build.exit" 2>/dev/null)" != 0 ]; then
    echo "figures: the npm package's build failed ($out/.logs/npm-build.log):" >&2
    tail -n 20 "$out/.logs/npm-build.log" >&2
    exit 1
  fi
  node web/flipcheck-engines.mjs --flipcheck "$build/npm-figures/package" "${engines_quick[@]}" \
    "$out/flipcheck/motions" "$out"/flipcheck/*.json
  motions+=("$out"/flipcheck/motions/*.csv)
else
  echo "figures: no node, emscripten or not every npm package of the engines (above; scripts/install-deps.sh): the league table without the JavaScript engines"
fi
"$bookspin" flipcheck league scenes/flipcheck/*.toml --motions "${motions[@]}" \
  --methods "$league_methods" -o "$out"
stage_done "league (the JavaScript engines included)"
if [ -z "$web_pid" ]; then
  echo "figures: no emscripten or npm: $out/explorer.html not made (scripts/install-deps.sh)"
elif [ "$(cat "$out/.logs/web-build.exit" 2>/dev/null)" = 0 ]; then
  tail -n 1 "$out/.logs/web-build.log"
  "$bookspin" explore --engines scenes/*.toml scenes/flipcheck/*.toml sweeps/*.toml "${tosses[@]}" -o "$out"
  stage_done "explorer page"
else
  echo "figures: the explorer page's build failed ($out/.logs/web-build.log):" >&2
  tail -n 20 "$out/.logs/web-build.log" >&2
  exit 1
fi
# The gallery over every scene (render-all.sh stopped the script if one had failed) and the sweeps.
"$bookspin" gallery "$out" scenes/*.toml sweeps/*.toml
stage_done "the gallery"
echo "figures: the stages' seconds"
printf '  %s\n' "${stage_table[@]}"
{ echo "$hash"; listing; } > "$stamp.tmp" && mv "$stamp.tmp" "$stamp"
