#!/usr/bin/env bash
# A Release build without warnings, kept so (CI: .ci/run). Reads a build's log (make build's
# output, stdout and stderr) and fails, listing each, where the compiler warned: a line
# "FILE:LINE:COLUMN: warning: …" (GCC's and Clang's form; ccache replays a cached object's
# warnings, so a build from the cache is judged as a fresh one). The project builds with
# -Wall -Wextra (CMakeLists.txt); a warning is fixed at its cause, not silenced by a flag.
# Usage: scripts/check-build-warnings.sh BUILD_LOG
set -euo pipefail
log=${1:?usage: scripts/check-build-warnings.sh BUILD_LOG}
count=$(grep -c -E '^[^ ]+:[0-9]+:[0-9]+: warning: ' "$log" || true)
if [ "$count" -ne 0 ]; then
  echo "check-build-warnings: $count compiler warning(s) in the build (each with its context):"
  grep -E -B12 -A3 '^[^ ]+:[0-9]+:[0-9]+: warning: ' "$log" | grep -v '^gmake\|^make\[' || true
  exit 1
fi
echo "check-build-warnings: no compiler warning in $(grep -c -E 'Building CXX object' "$log" || true) compiled objects"
