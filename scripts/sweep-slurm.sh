#!/usr/bin/env bash
# Submits a `bookspin sweep` as a Slurm job array: one task per shard (the task's
# SLURM_ARRAY_TASK_ID is K in --shard K/N, counting from 0), then a merge job that starts
# when every shard succeeded (--dependency=afterok) and writes DIR/<scene>-sweep.csv and .png.
#
# usage: scripts/sweep-slurm.sh SCENE [sweep options] --shards N -o DIR
#   sweep options: --vary, --measure, --set, -j (threads per task; also --cpus-per-task)
#   DIR must be on a filesystem every node sees; it holds the shard CSVs
#   (DIR/<scene>-sweep.shard-K-of-N.csv), the job scripts and the Slurm logs. Keep one sweep
#   per DIR: the merge job merges DIR/*-sweep.shard-*-of-N.csv.
# environment: BOOKSPIN (the binary; default: bookspin on PATH, else build/bookspin of this
#   checkout), SBATCH (default: sbatch), and sbatch's own SBATCH_* variables (partition, time).
# prints: "shards: JOBID" and "merge: JOBID" (the merge job's id last).
set -euo pipefail

usage() {
  echo "usage: $0 SCENE [sweep options] --shards N -o DIR" >&2
  exit 2
}

here=$(cd "$(dirname "$0")/.." && pwd)
bookspin=${BOOKSPIN:-$(command -v bookspin || echo "$here/build/bookspin")}
sbatch=${SBATCH:-sbatch}
[ -x "$bookspin" ] || { echo "$0: no bookspin binary at '$bookspin' (set BOOKSPIN)" >&2; exit 2; }
bookspin=$(cd "$(dirname "$bookspin")" && pwd)/$(basename "$bookspin")

shards=""
out=""
cpus=1
pass=()
while [ $# -gt 0 ]; do
  case "$1" in
    --shards) [ $# -ge 2 ] || usage; shards=$2; shift 2 ;;
    --shards=*) shards=${1#--shards=}; shift ;;
    -o|--out) [ $# -ge 2 ] || usage; out=$2; shift 2 ;;
    --out=*) out=${1#--out=}; shift ;;
    --shard|--shard=*|--merge|--merge=*)
      echo "$0: $1 is set by the script (one shard per array task)" >&2; exit 2 ;;
    -j|--jobs) [ $# -ge 2 ] || usage; cpus=$2; pass+=("$1" "$2"); shift 2 ;;
    *) pass+=("$1"); shift ;;
  esac
done
[ ${#pass[@]} -ge 1 ] || usage
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "$0: --shards N needs a positive integer" >&2; exit 2; }
[ -n "$out" ] || { echo "$0: -o DIR is required" >&2; exit 2; }
[[ "$cpus" =~ ^[1-9][0-9]*$ ]] || cpus=1
# The scene path as the jobs will see it (they run in this directory, but be explicit).
case "${pass[0]}" in /*) ;; *) [ -e "${pass[0]}" ] && pass[0]=$PWD/${pass[0]} ;; esac
mkdir -p "$out"
out=$(cd "$out" && pwd)

quoted=$(printf ' %q' "${pass[@]}")
cat > "$out/sweep-shard.sbatch" <<JOB
#!/usr/bin/env bash
set -euo pipefail
exec $(printf '%q' "$bookspin") sweep$quoted --shard "\$SLURM_ARRAY_TASK_ID/$shards" -o $(printf '%q' "$out")
JOB
cat > "$out/sweep-merge.sbatch" <<JOB
#!/usr/bin/env bash
set -euo pipefail
shopt -s nullglob
files=($(printf '%q' "$out")/*-sweep.shard-*-of-$shards.csv)
exec $(printf '%q' "$bookspin") sweep --merge "\${files[@]}" -o $(printf '%q' "$out")
JOB
chmod +x "$out/sweep-shard.sbatch" "$out/sweep-merge.sbatch"

array=$("$sbatch" --parsable --job-name=bookspin-sweep --array="0-$((shards - 1))" \
  --cpus-per-task="$cpus" --chdir="$PWD" --output="$out/slurm-%A_%a.out" \
  "$out/sweep-shard.sbatch")
array=${array%%;*}
merge=$("$sbatch" --parsable --job-name=bookspin-sweep-merge --dependency="afterok:$array" \
  --kill-on-invalid-dep=yes --chdir="$PWD" --output="$out/slurm-%j-merge.out" \
  "$out/sweep-merge.sbatch")
merge=${merge%%;*}
echo "shards: $array"
echo "merge: $merge"
