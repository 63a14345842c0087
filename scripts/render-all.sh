#!/usr/bin/env bash
# Renders every scene given: BOOKSPIN OUT_DIR SCENE... . Then plots each scene's diagnostics
# (OUT_DIR/<scene>-plot.png) and writes the gallery OUT_DIR/index.html. A scene whose
# outputs are up to date (OUT_DIR/<scene>/manifest.json) is not rendered again. While it
# runs, one line per finished scene ("[3/14] fig05-…: rendered, 41 s"); at the end one table
# (scene, frames, seconds, CPU seconds of the render with all its threads, its peak resident
# memory, status), the total time, CPU time and the disk space under OUT_DIR; the same table
# in OUT_DIR/.logs/summary.tsv. Each render's own output goes to OUT_DIR/.logs/<scene>.log,
# its CPU time and peak memory (GNU time) to OUT_DIR/.logs/<scene>.time. Stops with a non-zero status if any
# scene fails. GALLERY_EXTRA (environment): more scene files the gallery lists (the sweeps,
# run before); GALLERY=0: no gallery (scripts/figures.sh writes it after the league and the
# explorer page it links); RENDER_ARGS and PLOT_ARGS: more arguments for every render and every
# plot (scripts/figures.sh --quick: a few small frames).
#
# How the cores are shared: one render keeps about two cores busy even with --jobs 1 (the
# simulation and GL on one thread, llvmpipe's rasterizer, the encoder and a PNG worker
# overlap), and a render's own threads wait on each other now and then. So scenes run side
# by side, one per two cores but never fewer than two where there are two cores, and each
# gets an equal share of the cores through --jobs (which caps llvmpipe, x264 and the PNG
# workers alike). On the 2-core reference machine two scenes at --jobs 1 finished 7% sooner
# than one after the other at --jobs 2.
set -euo pipefail
RENDER_ARGS=${RENDER_ARGS:-} PLOT_ARGS=${PLOT_ARGS:-}
bookspin=$1 out=$2
shift 2
cores=$(nproc)
parallel=$(( cores >= 2 ? (cores / 2 > 2 ? cores / 2 : 2) : 1 ))
parallel=$(( parallel < $# ? parallel : ($# > 0 ? $# : 1) ))
jobs=$(( cores / parallel > 0 ? cores / parallel : 1 ))
logs="$out/.logs"
mkdir -p "$logs"
rm -f "$logs"/*.status "$logs/done"
echo 0 > "$logs/done"
start=$(date +%s.%N)
echo "render-all: $# scenes, $parallel at a time, --jobs $jobs each"

# "diverged at t = 12.3" from a render's warning ("simulation diverged at t = 12.3; …"), or
# "diverged at t = 4.5 (panel 'x')" for a comparison ("panel 'x' diverged at t = 4.5; …"):
# the first one.
diverged() {
  local status tile
  status=$(grep -o 'diverged at t = [^;]*' "$1" | head -n 1 | sed 's/ (when it was rendered)//')
  tile=$(grep -o "panel '[^']*' diverged" "$1" | head -n 1 | sed "s/ diverged//")
  echo "$status${tile:+ ($tile)}"
}

# One scene: render it under GNU time (user + system CPU seconds, peak resident KiB), classify
# the result from the render's output and exit status, write OUT/.logs/<stem>.status
# ("frames<TAB>status<TAB>seconds<TAB>cpu<TAB>peak MiB") and print the progress line.
render_one() {
  local scene=$1 total=$2 stem log t0 rc=0 status frames seconds name done cpu peak
  stem=$(basename "$scene" .toml)
  log="$logs/$stem.log"
  t0=$(date +%s.%N)
  # shellcheck disable=SC2086  # RENDER_ARGS: words, split
  /usr/bin/time -f '%U %S %M' -o "$logs/$stem.time" \
    "$bookspin" render "$scene" -o "$out" --jobs "$jobs" ${RENDER_ARGS:-} > "$log" 2>&1 || rc=$?
  seconds=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  # The last line: GNU time puts "Command exited with non-zero status" before it on a failure.
  read -r cpu peak < <(tail -n 1 "$logs/$stem.time" |
                       awk '{ printf "%.1f %.0f\n", $1 + $2, $3 / 1024 }')
  frames=$(sed -n 's/^rendered: .* (\([0-9]*\) frames)$/\1/p' "$log" | tail -n 1)
  if [ "$rc" -ne 0 ]; then
    reason=$(grep -E 'bookspin: (error|internal error):' "$log" | tail -n 1 |
             sed 's/^bookspin: \(internal \)*error: //' | cut -c 1-60)
    status="failed: ${reason:-exit status $rc}"
  elif grep -q '^up to date: ' "$log"; then
    status="up to date"
    # The divergence of the earlier render, repeated from the manifest.
    grep -q 'diverged at t = ' "$log" && status="up to date, $(diverged "$log")"
    name=$(sed -n 's/^up to date: //p' "$log" | tail -n 1)
    frames=$(sed -n 's/^ *"frames": \([0-9]*\),$/\1/p' "$out/$name/manifest.json" 2>/dev/null |
             head -n 1)
  elif grep -q 'diverged at t = ' "$log"; then
    status=$(diverged "$log")
  else
    status="rendered"
  fi
  printf '%s\t%s\t%s\t%s\t%s\n' "${frames:--}" "$status" "$seconds" "${cpu:--}" "${peak:--}" \
    > "$logs/$stem.status"
  {
    flock 9
    done=$(( $(cat "$logs/done") + 1 ))
    echo "$done" > "$logs/done"
    printf '[%d/%d] %s: %s, %s s\n' "$done" "$total" "$stem" "$status" "$seconds"
  } 9> "$logs/lock"
}
export -f render_one diverged
export bookspin out jobs logs RENDER_ARGS PLOT_ARGS

printf '%s\n' "$@" | xargs -P "$parallel" -I{} bash -c 'render_one "$1" "$2"' _ {} "$#"

# Plots and the gallery over the scenes that rendered (a bad scene would fail them all).
ok=()
for scene in "$@"; do
  grep -q $'\tfailed' "$logs/$(basename "$scene" .toml).status" || ok+=("$scene")
done
failed=0
echo "render-all: plotting"
printf '%s\n' "${ok[@]}" |
  xargs -P "$cores" -I{} sh -c '"$0" plot "$1" -o "$2" ${PLOT_ARGS:-} > /dev/null' "$bookspin" {} "$out" ||
  { echo "render-all: some plots failed"; failed=1; }
# shellcheck disable=SC2086  # GALLERY_EXTRA: more scene files for the page (sweeps), split
if [ "${GALLERY:-1}" != 0 ]; then
  "$bookspin" gallery "$out" "${ok[@]}" ${GALLERY_EXTRA:-} || { echo "render-all: the gallery failed"; failed=1; }
fi

printf '\n%-36s %7s %8s %8s %8s  %s\n' scene frames seconds cpu-s peak-MiB status
printf 'scene\tframes\tseconds\tcpu_seconds\tpeak_rss_mib\tstatus\n' > "$logs/summary.tsv"
cpu_total=0
for scene in "$@"; do
  stem=$(basename "$scene" .toml)
  IFS=$'\t' read -r frames status seconds cpu peak < "$logs/$stem.status"
  printf '%-36s %7s %8s %8s %8s  %s\n' "$stem" "$frames" "$seconds" "$cpu" "$peak" "$status"
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$stem" "$frames" "$seconds" "$cpu" "$peak" "$status" \
    >> "$logs/summary.tsv"
  [ "$cpu" = - ] || cpu_total=$(awk -v a="$cpu_total" -v b="$cpu" 'BEGIN { printf "%.1f", a + b }')
  case $status in failed*) failed=1 ;; esac
done
total=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.0f", b - a }')
printf 'render-all: %d scenes in %d min %d s, %s CPU-s of renders; %s under %s/\n' "$#" \
  $(( total / 60 )) $(( total % 60 )) "$cpu_total" "$(du -sh "$out" | cut -f 1)" "$out"
echo "render-all: clips in $out/, gallery $out/index.html, logs in $logs/"
exit "$failed"
