#!/usr/bin/env bash
# The merge step of a distributed render: adds up the TASKS films
# OUT/parts/part-0000.exr ... that `task.sh` wrote into one IMAGE
# (bmp/png/pfm/exr) with `pathtracer merge`, which checks that they belong
# to one scene and settings, do not overlap and cover every sample.
# Slurm's merge job and the Kubernetes merge Job call it; by hand:
#
#   scripts/farm/merge.sh output/farm/smallpt 4 output/farm/smallpt/smallpt.bmp
#
# --wait SECONDS first waits up to that long for all parts to appear (the
# Kubernetes merge Job, which has no job dependencies; the renderer writes
# files atomically, so a part that exists is complete). Without it a missing
# part is an error at once. The renderer is found as in `task.sh`.
# Prints one line `farm: merge of TASKS parts start=T0 end=T1 seconds=S`.
set -euo pipefail

usage() {
    echo "usage: $0 [--wait SECONDS] OUT TASKS IMAGE" >&2
    exit 2
}

wait_for=0
if [[ ${1:-} == --wait ]]; then
    [[ $# -ge 2 ]] || usage
    wait_for=$2
    shift 2
fi
[[ $# -eq 3 ]] || usage
out=$1 tasks=$2 image=$3
for n in "$tasks" "$wait_for"; do
    [[ $n =~ ^[0-9]+$ ]] || { echo "$0: not a whole number: $n" >&2; exit 2; }
done
((tasks >= 1)) || { echo "$0: TASKS must be at least 1" >&2; exit 2; }

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin=${PATHTRACER:-}
if [[ -z $bin ]]; then
    if [[ -x $root/target/release/pathtracer ]]; then
        bin=$root/target/release/pathtracer
    else
        bin=pathtracer
    fi
fi

parts=()
for ((i = 0; i < tasks; i++)); do
    parts+=("$out/parts/part-$(printf %04d "$i").exr")
done

missing() {
    local p
    for p in "${parts[@]}"; do
        [[ -f $p ]] || { echo "$p"; return 0; }
    done
    return 1
}
deadline=$((SECONDS + wait_for))
while first_missing=$(missing); do
    if ((SECONDS >= deadline)); then
        echo "$0: part missing: $first_missing" >&2
        exit 1
    fi
    sleep 5
done

mkdir -p "$(dirname "$image")"
t0=$(date +%s.%N)
"$bin" merge "${parts[@]}" -o "$image"
t1=$(date +%s.%N)
awk -v n="$tasks" -v t0="$t0" -v t1="$t1" \
    'BEGIN { printf "farm: merge of %d parts start=%s end=%s seconds=%.2f\n", n, t0, t1, t1 - t0 }'
