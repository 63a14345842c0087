#!/usr/bin/env bash
# Starts a single-node Slurm (slurmctld + slurmd + munged, as the current user, configured
# in a temporary directory), runs a 6-point sweep as 3 shards through
# scripts/sweep-slurm.sh, waits for the merge job and checks that the merged CSV equals a
# one-process sweep byte for byte. The daemons are always stopped.
# Exit 77 (ctest SKIP_RETURN_CODE) when Slurm cannot start here, except with CI=true, where
# that is a failure (1).
# usage: slurm_sweep_test.sh BOOKSPIN_BINARY SOURCE_DIR
set -uo pipefail

bookspin=$1
source_dir=$2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/bookspin-slurm.XXXXXX")
chmod 700 "$tmp"
pids=()

stop_daemons() {
  local pid
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null
    wait "$pid" 2>/dev/null
  done
  pids=()
}
cleanup() {
  stop_daemons
  if [ "${KEEP_SLURM_TMP:-}" = 1 ]; then echo "kept $tmp"; else rm -rf "$tmp"; fi
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP  # so that the EXIT trap stops the daemons

logs() {
  local f
  for f in "$tmp"/munged.log "$tmp"/slurmctld.log "$tmp"/slurmd.log "$tmp"/out/slurm-*.out; do
    [ -f "$f" ] && { echo "--- $f (last 20 lines)"; tail -n 20 "$f"; }
  done
}
# Slurm could not start: skip, or fail under CI.
cannot_start() {
  echo "slurm_sweep_test: Slurm cannot start here: $1"
  logs
  if [ "${CI:-}" = true ]; then echo "FAILED (CI=true: Slurm must start)"; exit 1; fi
  echo "SKIPPED: single-node Slurm unavailable (install slurm-wlm and munge; see scripts/install-deps.sh)"
  exit 77
}
fail() {
  echo "slurm_sweep_test: FAILED: $1"
  logs
  exit 1
}

for tool in munged mungekey slurmctld slurmd sbatch squeue sinfo; do
  command -v "$tool" >/dev/null || cannot_start "'$tool' not found"
done

# Ports of our own, so that a Slurm already on this machine (or a parallel run) is not hit.
base=$((20000 + ($$ % 20000)))
ctld_port=$base
slurmd_port=$((base + 1))
user=$(id -un)

mungekey --create --keyfile="$tmp/munge.key" >/dev/null 2>&1 ||
  cannot_start "mungekey --create failed"
chmod 600 "$tmp/munge.key"
munged --foreground --force --key-file="$tmp/munge.key" --socket="$tmp/munge.socket" \
  --pid-file="$tmp/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munge.seed" \
  >>"$tmp/munged.log" 2>&1 &
pids+=($!)
for _ in $(seq 50); do [ -S "$tmp/munge.socket" ] && break; sleep 0.1; done
[ -S "$tmp/munge.socket" ] || cannot_start "munged did not open its socket"

mkdir -p "$tmp/state" "$tmp/spool" "$tmp/out"
cat > "$tmp/slurm.conf" <<CONF
ClusterName=bookspintest
SlurmctldHost=localhost
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$tmp/munge.socket
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SwitchType=switch/none
ReturnToService=2
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName=localhost NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf

slurmctld -D -c -f "$SLURM_CONF" >>"$tmp/slurmctld.log" 2>&1 &
pids+=($!)
slurmd -D -N localhost -f "$SLURM_CONF" >>"$tmp/slurmd.log" 2>&1 &
pids+=($!)
up=""
for _ in $(seq 100); do
  state=$(sinfo -h -n localhost -o %T 2>/dev/null)
  case "$state" in idle*|mixed*|allocated*) up=1; break ;; esac
  sleep 0.3
done
[ -n "$up" ] || cannot_start "the node did not become idle (sinfo: '${state:-no answer}')"

# The sweep: 3 × 2 = 6 points, 3 shards of 2, short runs.
scene=$source_dir/scenes/exact-unstable-x.toml
args=(--set 'model.kind="rigid-quaternion"' --set 'model.integrator="rk4"' --set time.frames=120
      --vary 'initial.angular_velocity[1]=1e-4:1e-2:3:log' --vary 'time.dt=0.01:0.02:2'
      --measure first_flip,flip_period,energy_drift,orientation_error,diverged_at -j 1)
"$bookspin" sweep "$scene" "${args[@]}" -o "$tmp/one" >/dev/null || fail "the one-process sweep failed"

submitted=$(BOOKSPIN=$bookspin "$source_dir/scripts/sweep-slurm.sh" "$scene" "${args[@]}" \
  --shards 3 -o "$tmp/out") || fail "sweep-slurm.sh failed: $submitted"
echo "$submitted"
merge_job=$(echo "$submitted" | sed -n 's/^merge: //p')
[ -n "$merge_job" ] || fail "sweep-slurm.sh printed no merge job"

merged=$tmp/out/exact-unstable-x-sweep.csv
for _ in $(seq 600); do
  # Done when the merge job has left the queue (finished, failed, or cancelled because a
  # shard failed: --kill-on-invalid-dep).
  [ -z "$(squeue -h -j "$merge_job" 2>/dev/null)" ] && break
  sleep 0.2
done
[ -f "$merged" ] || fail "no merged CSV (merge job $merge_job; squeue: $(squeue -h 2>&1))"
for k in 0 1 2; do
  [ -f "$tmp/out/exact-unstable-x-sweep.shard-$k-of-3.csv" ] || fail "shard $k is missing"
done
[ -f "$tmp/out/exact-unstable-x-sweep.png" ] || fail "no merged plot"
cmp "$tmp/one/exact-unstable-x-sweep.csv" "$merged" || fail "merged CSV differs from the one-process sweep"
[ "$(wc -l < "$merged")" -eq 7 ] || fail "merged CSV should have a header and 6 rows"
echo "slurm_sweep_test: merged CSV of 3 Slurm array tasks equals the one-process sweep"
exit 0
