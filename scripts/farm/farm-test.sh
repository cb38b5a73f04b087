#!/usr/bin/env bash
# `make farm-test`: the Slurm path of a distributed render, end to end on
# this machine. Installs Slurm and MUNGE from Debian's packages (what is
# missing), writes a single-host cluster (controller and one node on
# localhost, the node's real CPUs and memory from `slurmd -C`) under
# output/farm-test/, starts munged, slurmctld and slurmd directly (root, no
# systemd), submits a TASKS-task array through slurm-render.sh, waits for the
# merge job and compares the merged image with a single-process
# `pathtracer render --spp SPP` byte for byte. Prints the wall times of the
# array and the merge. The daemons it started are stopped on any exit; an
# earlier run's daemons (by their pid files here) are stopped before it
# starts, so it can be run again. Settings (environment):
#   SCENE [testcases/smallpt.txt] SPP [64] TASKS [4] WIDTH [160] HEIGHT [120]
#   FARM_CPUS [1: CPUs per task] FARM_TIMEOUT [600 s] FARM_PORT [6817: slurmctld;
#   slurmd gets the next]
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$(pwd)

scene=${SCENE:-testcases/smallpt.txt}
spp=${SPP:-64}
tasks=${TASKS:-4}
width=${WIDTH:-160}
height=${HEIGHT:-120}
cpus=${FARM_CPUS:-1}
timeout=${FARM_TIMEOUT:-600}
port=${FARM_PORT:-6817}
bin=${PATHTRACER:-$root/target/release/pathtracer}
work=$root/output/farm-test
name=$(basename "${scene%.*}")

log() { echo "farm-test: $*"; }
die() { echo "farm-test: FAILED: $*" >&2; exit 1; }

# --- packages -------------------------------------------------------------
needed=()
for pkg in munge slurmctld slurmd slurm-client; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || needed+=("$pkg")
done
if ((${#needed[@]} > 0)); then
    log "installing ${needed[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q
    apt-get install -y -q --no-install-recommends "${needed[@]}"
fi
[[ -x $bin ]] || die "no renderer at $bin (make build)"

# --- stop what an earlier run left, then lay out the working folder -------
# Stops the daemon NAME whose pid file is F, if that pid still is NAME (a
# stale file's pid may belong to another process by now).
stop_pidfile() {
    local f=$1 name=$2 pid
    [[ -f $f ]] || return 0
    pid=$(cat "$f")
    if [[ $pid =~ ^[0-9]+$ && $(cat "/proc/$pid/comm" 2>/dev/null) == "$name" ]]; then
        kill "$pid" 2>/dev/null || true
        for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
        if kill -0 "$pid" 2>/dev/null; then kill -9 "$pid" 2>/dev/null || true; fi
    fi
    rm -f "$f"
}
for d in slurmd slurmctld munged; do stop_pidfile "$work/run/$d.pid" "$d"; done
rm -rf "$work"
mkdir -p "$work"/{run,log,munge,state,spool,render}
# munged wants its key private and its socket folder open to all.
chmod 0700 "$work"/{log,munge,state,spool}
chmod 0755 "$work" "$work/run"

# --- munge: a key of its own, its own socket ------------------------------
key=$work/munge/munge.key
socket=$work/run/munge.socket
mungekey --create --keyfile="$key"
chmod 0600 "$key"

# --- slurm.conf ------------------------------------------------------------
host=$(hostname -s)
node_line=$(slurmd -C | head -n 1)
[[ $node_line == NodeName=* ]] || die "slurmd -C printed: $node_line"
node_line=${node_line/NodeName=* CPUs=/NodeName=$host NodeAddr=127.0.0.1 CPUs=}
conf=$work/slurm.conf
cat >"$conf" <<CONF
# Single-host cluster of make farm-test (scripts/farm/farm-test.sh), made anew each run.
ClusterName=farmtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/run/slurmctld.pid
SlurmdPidFile=$work/run/slurmd.pid
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MinJobAge=3600
DependencyParameters=kill_invalid_depend
SchedulerParameters=sched_min_interval=0
$node_line State=UNKNOWN
PartitionName=farm Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$conf

# --- daemons ---------------------------------------------------------------
started=()
cleanup() {
    local rc=$?
    if ((rc != 0)); then
        for f in "$work"/log/slurmctld.log "$work"/log/slurmd.log "$work"/render/logs/*.log; do
            [[ -f $f ]] && { echo "--- tail of $f" >&2; tail -n 15 "$f" >&2; }
        done
    fi
    for d in slurmd slurmctld munged; do stop_pidfile "$work/run/$d.pid" "$d"; done
    for pid in "${started[@]}"; do
        kill "$pid" 2>/dev/null || true
    done
    wait 2>/dev/null || true
    ((rc == 0)) || echo "farm-test: daemons stopped; logs in $work/log" >&2
    exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

munged --foreground --force --key-file="$key" --socket="$socket" \
    --pid-file="$work/run/munged.pid" \
    --seed-file="$work/munge/munged.seed" >"$work/log/munged.out" 2>&1 &
started+=($!)
for _ in $(seq 100); do [[ -S $socket ]] && break; sleep 0.1; done
[[ -S $socket ]] || die "munged did not start (see $work/log/munged.out)"

slurmctld -D -c -f "$conf" >"$work/log/slurmctld.out" 2>&1 &
started+=($!)
for _ in $(seq 100); do scontrol ping 2>/dev/null | grep -q UP && break; sleep 0.2; done
scontrol ping | grep -q UP || die "slurmctld did not start"
slurmd -D -f "$conf" -N "$host" >"$work/log/slurmd.out" 2>&1 &
started+=($!)
for _ in $(seq 150); do
    state=$(sinfo -h -n "$host" -o %T 2>/dev/null || true)
    [[ $state == idle ]] && break
    sleep 0.2
done
[[ $state == idle ]] || die "node $host is '$state', not idle"
log "cluster up: $(sinfo -h -N -o '%N %c CPUs %m MB %T')"

# --- the single-process reference -------------------------------------------
size=(--width "$width" --height "$height")
reference=$work/single.pfm
t0=$(date +%s.%N)
"$bin" render "$scene" --spp "$spp" "${size[@]}" -o "$reference" --quiet
t1=$(date +%s.%N)
single=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.2f", b - a }')

# --- the farm render ---------------------------------------------------------
out=$work/render
merged=$out/$name.pfm
submitted=$(date +%s.%N)
ids=$(scripts/farm/slurm-render.sh "$scene" "$spp" "$tasks" --out "$out" --image "$merged" \
    --cpus "$cpus" --time 00:10:00 --merge-time 00:05:00 -- "${size[@]}")
echo "$ids"
array_id=$(awk '$1 == "array" { sub(":", "", $3); print $3 }' <<<"$ids")
merge_id=$(awk '$1 == "merge" { sub(":", "", $3); print $3 }' <<<"$ids")
[[ -n $array_id && -n $merge_id ]] || die "no job ids from slurm-render.sh"

job_state() { scontrol show job -o "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | head -n 1 | cut -d= -f2; }
deadline=$((SECONDS + timeout))
while :; do
    state=$(job_state "$merge_id")
    case $state in
    COMPLETED) break ;;
    FAILED | CANCELLED | TIMEOUT | NODE_FAIL | OUT_OF_MEMORY | BOOT_FAIL | DEADLINE | PREEMPTED)
        die "merge job $merge_id ended $state; array: $(squeue -h -j "$array_id" -t all -o '%i %T' | tr '\n' ' ')" ;;
    esac
    ((SECONDS < deadline)) || die "merge job $merge_id still '$state' after ${timeout}s"
    sleep 0.5
done
finished=$(date +%s.%N)

# --- the verdict -------------------------------------------------------------
cmp "$merged" "$reference" || die "merged $merged differs from single-process $reference"
log "merged image is byte for byte the single-process render ($merged)"
# Wall times from the lines task.sh and merge.sh print (first task start to
# last task end; the merge's own run), and from submission to the merge's end.
cat "$out"/logs/task-*.log "$out"/logs/merge.log | awk -v single="$single" -v sub0="$submitted" -v fin="$finished" '
    /^farm: task / {
        for (i = 1; i <= NF; i++) {
            split($i, kv, "=")
            if (kv[1] == "start" && (first == "" || kv[2] < first)) first = kv[2]
            if (kv[1] == "end" && kv[2] > last) last = kv[2]
            if (kv[1] == "seconds") busy += kv[2]
        }
        n++
    }
    /^farm: merge / { for (i = 1; i <= NF; i++) { split($i, kv, "="); if (kv[1] == "seconds") merge = kv[2] } }
    END {
        printf "farm-test: array of %d tasks: %.2f s wall (first start to last end), %.2f s of task time\n", n, last - first, busy
        printf "farm-test: merge: %.2f s; submission to merged image: %.2f s; single process: %.2f s\n", merge, fin - sub0, single
    }'
log "passed"
