#!/usr/bin/env bash
# slurm_map_test.sh [MAGNUS]: run a small S(Re, α) map as a Slurm job array on a one-node cluster started
# here, merge the shards, and check the merge equals the unsharded map bit for bit.
#   scripts/slurm_map_test.sh build/magnus          (ctest -L slurm runs it; needs root and
#                                                    scripts/setup.sh --slurm for munge and Slurm)
# It starts munged, slurmctld and slurmd as root from a fresh temporary directory (key, slurm.conf, state,
# spool, logs, pid files, sockets; free ports on 127.0.0.1), waits for the node to be idle, submits
#   magnus sweep cases/s_map.toml --reynolds 20:80:20 --spin-ratio 0:2:1 --shard K/N      (4 Re × 3 α)
# as `sbatch --array=1-N --wait` (N = 3 shards: rows {20, 80}, {40}, {60}), merges the shards with
# magnus merge, computes the same map in one process, and compares the two files with
# scripts/sweep_files_equal.py. It tears the daemons and any job left down on every exit path.
# The map: MAGNUS_SLURM_REYNOLDS, MAGNUS_SLURM_ALPHA, MAGNUS_SLURM_SHARDS. MAGNUS_SLURM_KEEP=1 keeps the
# temporary directory (it is kept anyway when the test fails, for its logs).
# Prints one line on failure ("slurm_map_test: FAILED: …") and exits 1.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
magnus="$(realpath -m "${1:-$here/build/magnus}")"
case_file="$here/cases/s_map.toml"
reynolds="${MAGNUS_SLURM_REYNOLDS:-20:80:20}"
alpha="${MAGNUS_SLURM_ALPHA:-0:2:1}"
shards="${MAGNUS_SLURM_SHARDS:-3}"
name="slurm_map_test"
tmp=""
pids=()     # the daemons this script started, in the order to stop them
marker=""   # MAGNUS_SLURM_TEST=<tmp>: in the environment of the daemons and the jobs, and nothing else
started="$EPOCHREALTIME"

fail() {
  echo "$name: FAILED: $*${tmp:+ (logs in $tmp)}" >&2
  exit 1
}
trap 'fail "line $LINENO: $BASH_COMMAND"' ERR
trap 'fail "interrupted by a signal"' INT TERM HUP

# COMMAND… marked, in the background, waited for: a signal to this script stops the wait at once.
in_background() {
  env "$marker" "$@" &
  wait $!
}

# Seconds from the $EPOCHREALTIME given to now, to 0.1 s.
seconds_since() {
  /usr/bin/python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.1f}')" "$1" "$EPOCHREALTIME"
}

# Processes with the marker in their environment: the daemons, slurmstepd and the jobs' tasks.
marked_pids() {
  local e p
  for e in /proc/[0-9]*/environ; do
    p="${e#/proc/}"; p="${p%/environ}"
    [ "$p" != "$$" ] && { tr '\0' '\n' <"$e"; } 2>/dev/null | grep -qxF "$marker" && echo "$p"
  done
  return 0
}

# Cancel what is queued, stop the daemons, then end any process of the test still alive.
teardown() {
  local status=$? p i
  trap - ERR
  set +e
  # Only our own slurmctld, through our own SLURM_CONF: before it started, scancel would reach the
  # machine's own Slurm (and "kill -0 0" always succeeds, so the pid alone is no guard).
  if [ ${#pids[@]} -ge 2 ] && [ -n "${SLURM_CONF:-}" ] && [ "$SLURM_CONF" = "$tmp/slurm.conf" ] &&
    kill -0 "${pids[1]}" 2>/dev/null; then
    scancel --quiet --user=root 2>/dev/null
    for i in $(seq 40); do [ -z "$(squeue -h -o %i 2>/dev/null)" ] && break; sleep 0.5; done
  fi
  for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null; done
  for i in $(seq 40); do
    local alive=0
    for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && alive=1; done
    [ $alive = 0 ] && break
    sleep 0.25
  done
  if [ -n "$marker" ]; then
    for p in "${pids[@]}" $(marked_pids); do kill -KILL "$p" 2>/dev/null; done
  fi
  if [ -n "$tmp" ] && [ $status -eq 0 ] && [ "${MAGNUS_SLURM_KEEP:-0}" != 1 ]; then rm -rf "$tmp"; fi
  exit $status
}
trap teardown EXIT

# ------------------------------------------------------------------ what the test needs
[ "$(id -u)" -eq 0 ] || fail "run as root: it starts munged, slurmctld and slurmd"
for c in munged munge unmunge slurmctld slurmd sbatch sinfo squeue scancel; do
  command -v "$c" >/dev/null || fail "$c not found: install munge and Slurm with scripts/setup.sh --slurm"
done
/usr/bin/python3 -c "import h5py" 2>/dev/null || fail "python3-h5py is missing (scripts/setup.sh installs it)"
[ -x "$magnus" ] || fail "no magnus at $magnus (build it, or give its path)"
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || fail "MAGNUS_SLURM_SHARDS '$shards': expected a whole number ≥ 1"

tmp="$(mktemp -d /tmp/magnus-slurm.XXXXXX)"
chmod 755 "$tmp"   # munged wants every directory above its socket searchable by all
marker="MAGNUS_SLURM_TEST=$tmp"
node="$(hostname -s)"
read -r ctld_port slurmd_port < <(/usr/bin/python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')

# ------------------------------------------------------------------ munge: a fresh key, its own socket
head -c 1024 /dev/urandom >"$tmp/munge.key"
chmod 0400 "$tmp/munge.key"
env "$marker" munged --foreground --key-file="$tmp/munge.key" --socket="$tmp/munge.socket" \
  --pid-file="$tmp/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munged.seed" \
  >"$tmp/munged.out" 2>&1 &
pids+=($!)
for i in $(seq 50); do
  munge -n -S "$tmp/munge.socket" 2>/dev/null | unmunge -S "$tmp/munge.socket" >/dev/null 2>&1 && break
  kill -0 "${pids[0]}" 2>/dev/null || fail "munged exited: $(tail -n 1 "$tmp/munged.out")"
  [ "$i" = 50 ] && fail "munged does not answer on $tmp/munge.socket"
  sleep 0.2
done

# ------------------------------------------------------------------ slurmctld and slurmd on localhost
mkdir -p "$tmp/state" "$tmp/spool"
# MinJobAge=6 (s a finished job is kept): sbatch --wait polls every 2 s instead of backing off to 32 s.
cat >"$tmp/slurm.conf" <<EOF
ClusterName=magnus-test
SlurmctldHost=$node(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
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
MailProg=/bin/true
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
ReturnToService=2
MinJobAge=6
NodeName=$node NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=1000 State=UNKNOWN
PartitionName=magnus Nodes=$node Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$tmp/slurm.conf"
env "$marker" slurmctld -D -i -f "$SLURM_CONF" >"$tmp/slurmctld.out" 2>&1 &
pids+=($!)
env "$marker" slurmd -D -N "$node" -f "$SLURM_CONF" >"$tmp/slurmd.out" 2>&1 &
pids+=($!)
for i in $(seq 120); do
  [ "$(sinfo -h -N -o %t 2>/dev/null)" = idle ] && break
  kill -0 "${pids[1]}" 2>/dev/null || fail "slurmctld exited: $(tail -n 1 "$tmp/slurmctld.out")"
  kill -0 "${pids[2]}" 2>/dev/null || fail "slurmd exited: $(tail -n 1 "$tmp/slurmd.out")"
  [ "$i" = 120 ] && fail "node $node not idle after 60 s (sinfo: $(sinfo -h -N -o %t 2>&1 | head -n 1))"
  sleep 0.5
done
cluster_s="$(seconds_since "$started")"

# ------------------------------------------------------------------ the map as a job array of shards
map=(sweep "$case_file" --reynolds "$reynolds" --spin-ratio "$alpha" -q)
cat >"$tmp/s_map.sbatch" <<EOF
#!/bin/bash
#SBATCH --job-name=s_map
#SBATCH --partition=magnus        # the README's job script, with this cluster's partition
#SBATCH --cpus-per-task=1
#SBATCH --mem=500M
#SBATCH --time=00:30:00
exec $(printf '%q ' "$magnus" "${map[@]}") \\
  --shard \${SLURM_ARRAY_TASK_ID}/\${SLURM_ARRAY_TASK_COUNT} -o "$tmp/s_map.\${SLURM_ARRAY_TASK_ID}.h5"
EOF
t0="$EPOCHREALTIME"
in_background timeout 600 sbatch --wait --parsable --array="1-$shards" --chdir="$tmp" \
  --output="$tmp/s_map.%a.log" "$tmp/s_map.sbatch" >"$tmp/sbatch.out" 2>&1 || {
  status=$?
  why="$(cat "$tmp"/s_map.*.log 2>/dev/null | grep -m 1 .)" || why="$(tail -n 1 "$tmp/sbatch.out")"
  fail "the job array failed (sbatch exit $status): $why"
}
array_s="$(seconds_since "$t0")"
job="$(head -n 1 "$tmp/sbatch.out")"
shard_files=()
for k in $(seq "$shards"); do
  [ -s "$tmp/s_map.$k.h5" ] || fail "task $k of job array $job wrote no $tmp/s_map.$k.h5"
  shard_files+=("$tmp/s_map.$k.h5")
done
"$magnus" merge "$tmp/s_map.h5" "${shard_files[@]}" >"$tmp/merge.out" 2>&1 ||
  fail "magnus merge: $(tail -n 1 "$tmp/merge.out")"

# ------------------------------------------------------------------ the same map in one process
t0="$EPOCHREALTIME"
in_background "$magnus" "${map[@]}" -o "$tmp/whole.h5" >"$tmp/whole.out" 2>&1 ||
  fail "unsharded sweep: $(tail -n 1 "$tmp/whole.out")"
whole_s="$(seconds_since "$t0")"

# ------------------------------------------------------------------ the merge is the unsharded map
check="$here/scripts/sweep_files_equal.py"
same="$(/usr/bin/python3 "$check" "$tmp/whole.h5" "$tmp/s_map.h5" 2>&1)" ||
  fail "merged shards ≠ unsharded map: $same"
# The comparison can fail: a shard alone is not the whole map.
if [ "$shards" -gt 1 ] && /usr/bin/python3 "$check" "$tmp/whole.h5" "$tmp/s_map.1.h5" >/dev/null 2>&1; then
  fail "sweep_files_equal.py finds shard 1 equal to the whole map: the check sees nothing"
fi
points="$(/usr/bin/python3 -c 'import h5py, sys; f = h5py.File(sys.argv[1]); print(len(f["/sweep/cl"]), "points,",
  len(f["/axes/reynolds"]), "Re ×", len(f["/axes/alpha"]), "α")' "$tmp/s_map.h5")"
echo "$name: passed: $points in $shards shards of job array $job on $node; merged $same"
echo "$name: wall times: cluster up ${cluster_s} s, job array ${array_s} s, unsharded map ${whole_s} s," \
     "whole test $(seconds_since "$started") s"
