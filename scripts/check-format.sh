#!/usr/bin/env bash
# Fails when a C++ file of src, tests, bench, examples, python, web or npm (the WebAssembly
# bindings) differs from what clang-format makes of it with the repository's .clang-format.
# Debian 12's clang-format 14 (scripts/install-deps.sh) is the reference: another version
# formats some constructs differently, so it is refused under CI=true and only warned about
# elsewhere.
# Usage: scripts/check-format.sh [--fix]
set -euo pipefail
cd "$(dirname "$0")/.."
tool=$(command -v clang-format-14 || command -v clang-format || true)
if [ -z "$tool" ]; then
  echo "check-format: clang-format is not installed (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
version=$("$tool" --version | sed -n 's/.*version \([0-9]*\)\..*/\1/p')
if [ "$version" != 14 ]; then
  echo "check-format: $tool is version $version, the reference is 14 (Debian 12)" >&2
  [ "${CI:-}" = true ] && exit 1
fi
mapfile -t files < <(git ls-files -- src tests bench examples python web npm |
  grep -E '\.(cpp|hpp|h|cc)$')
if [ "${1:-}" = --fix ]; then
  "$tool" -i "${files[@]}"
  exit 0
fi
"$tool" --dry-run --Werror "${files[@]}"
echo "check-format: ${#files[@]} files formatted"
