#!/usr/bin/env bash
# One task of a distributed render: renders task I's share of the pixel
# samples 0..SPP of SCENE (task I of TASKS gets [I*SPP/TASKS, (I+1)*SPP/TASKS))
# into the film OUT/parts/part-NNNN.exr, which `merge.sh` later adds up.
# Slurm's sbatch file and the Kubernetes Job call it; it runs by hand too:
#
#   scripts/farm/task.sh --index 2 testcases/smallpt.txt 64 4 output/farm/smallpt -- --width 160 --height 120
#
# The index is --index, else $SLURM_ARRAY_TASK_ID (Slurm job arrays), else
# $JOB_COMPLETION_INDEX (Kubernetes Indexed Jobs). Everything after `--` is
# passed to `pathtracer render` and must be the same for every task (seed,
# size, look...). Render threads: $FARM_THREADS, else $SLURM_CPUS_PER_TASK,
# else the renderer's default (all cores). The renderer is $PATHTRACER, else
# target/release/pathtracer of this checkout, else `pathtracer` on PATH.
# Prints one line `farm: task I samples A..B start=T0 end=T1 seconds=S`.
set -euo pipefail

usage() {
    echo "usage: $0 [--index I] SCENE SPP TASKS OUT [-- RENDER_ARGS...]" >&2
    exit 2
}

index=""
if [[ ${1:-} == --index ]]; then
    [[ $# -ge 2 ]] || usage
    index=$2
    shift 2
fi
[[ $# -ge 4 ]] || usage
scene=$1 spp=$2 tasks=$3 out=$4
shift 4
if [[ $# -gt 0 ]]; then
    [[ $1 == -- ]] || usage
    shift
fi
index=${index:-${SLURM_ARRAY_TASK_ID:-${JOB_COMPLETION_INDEX:-}}}
if [[ -z $index ]]; then
    echo "$0: no task index (--index, SLURM_ARRAY_TASK_ID or JOB_COMPLETION_INDEX)" >&2
    exit 2
fi
for n in "$spp" "$tasks" "$index"; do
    [[ $n =~ ^[0-9]+$ ]] || { echo "$0: not a whole number: $n" >&2; exit 2; }
done
if ((tasks < 1 || tasks > spp || index >= tasks)); then
    echo "$0: need 1 <= TASKS <= SPP and INDEX < TASKS (got SPP=$spp TASKS=$tasks INDEX=$index)" >&2
    exit 2
fi

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${PATHTRACER:-}
if [[ -z $bin ]]; then
    if [[ -x $root/target/release/pathtracer ]]; then
        bin=$root/target/release/pathtracer
    else
        bin=pathtracer
    fi
fi

first=$((index * spp / tasks))
end=$(((index + 1) * spp / tasks))
threads=${FARM_THREADS:-${SLURM_CPUS_PER_TASK:-}}
thread_args=()
[[ -n $threads ]] && thread_args=(--threads "$threads")

mkdir -p "$out/parts"
film=$out/parts/part-$(printf %04d "$index").exr
t0=$(date +%s.%N)
"$bin" render "$scene" --samples "$first..$end" --film "$film" "${thread_args[@]}" "$@"
t1=$(date +%s.%N)
awk -v i="$index" -v a="$first" -v b="$end" -v t0="$t0" -v t1="$t1" \
    'BEGIN { printf "farm: task %d samples %d..%d start=%s end=%s seconds=%.2f\n", i, a, b, t0, t1, t1 - t0 }'
