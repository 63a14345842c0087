#!/usr/bin/env bash
# Runs `bookspin inertia` over every model of Debian's assimp-testmodels package that the mesh
# reader accepts by its name (OBJ, STL, glTF, GLB) and prints one verdict a file: "accepted"
# with the volume, or "refused" with bookspin's one line. Ends with the counts. Any exit
# status other than 0 (accepted) or 2 (bad input) is a bug: listed as CRASH, and the script
# exits 1. Skips (exit 0, with a message) where the package is not installed.
#   scripts/check-testmodels.sh [BOOKSPIN]   (default build/bookspin)
set -uo pipefail
cd "$(dirname "$0")/.."
bookspin=${1:-build/bookspin}
models=/usr/share/assimp/models
if ! dpkg -s assimp-testmodels >/dev/null 2>&1 || [ ! -d "$models" ]; then
  echo "check-testmodels: skipped: the assimp-testmodels package is not installed" \
       "(apt-get install assimp-testmodels)"
  exit 0
fi
if [ ! -x "$bookspin" ]; then
  echo "check-testmodels: $bookspin not found; build it first (cmake --build build --target bookspin)" >&2
  exit 2
fi
errors=$(mktemp)
trap 'rm -f "$errors"' EXIT
accepted=0 refused=0 crashed=0
while IFS= read -r -d '' file; do
  name=${file#"$models"/}
  json=$("$bookspin" inertia --json "$file" 2>"$errors")
  status=$?
  out=$(cat "$errors")
  case $status in
    0)
      accepted=$((accepted + 1))
      volume=$(printf '%s' "$json" | sed -n 's/^{"volume": \([^,]*\),.*/\1/p')
      printf 'accepted  %s  volume %s%s\n' "$name" "$volume" "${out:+  ($(printf '%s' "$out" | tr '\n' ' '))}"
      ;;
    2)
      refused=$((refused + 1))
      printf 'refused   %s  %s\n' "$name" "${out#bookspin: error: "$file": }"
      ;;
    *)
      crashed=$((crashed + 1))
      printf 'CRASH     %s  exit %d: %s\n' "$name" "$status" "$out"
      ;;
  esac
done < <(find "$models" -type f \( -iname '*.obj' -o -iname '*.stl' -o -iname '*.gltf' \
                                    -o -iname '*.glb' \) -print0 | sort -z)
echo "check-testmodels: $((accepted + refused + crashed)) files: $accepted accepted," \
     "$refused refused, $crashed crashed"
[ "$crashed" -eq 0 ]
