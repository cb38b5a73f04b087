#!/usr/bin/env bash
# Submits a distributed render of SCENE at SPP samples per pixel to Slurm:
# a job array of TASKS tasks (task i renders samples [i*SPP/TASKS,
# (i+1)*SPP/TASKS) of every pixel into OUT/parts/part-000i.exr, through
# slurm-task.sbatch and task.sh) and a merge job that runs once all of them
# succeeded (--dependency=afterok, slurm-merge.sbatch and merge.sh) and
# writes the image. Prints the two job ids; returns at once.
#
#   scripts/farm/slurm-render.sh testcases/smallpt.txt 1024 16 [options] [-- RENDER_ARGS...]
#
# Options (defaults in brackets):
#   --out DIR          parts, logs and image [output/farm/<scene name>]
#   --image FILE       the merged image, .bmp/.png/.pfm/.exr [DIR/<scene name>.bmp]
#   --partition P      Slurm partition [the cluster's default]
#   --time T           time limit of each render task [01:00:00]
#   --cpus C           CPUs per render task, also its render threads [4]
#   --merge-time T     time limit of the merge job [00:15:00]
# RENDER_ARGS go to every task's `pathtracer render` (e.g. --seed 7 --width
# 640 --height 480) and must not be --spp/-o. Other sbatch settings (account,
# QOS, memory) come from sbatch's own SBATCH_* environment variables. This
# checkout, the scene and DIR must be on a file system the compute nodes
# share, and target/release/pathtracer built for them (or $PATHTRACER set).
# Old parts in DIR/parts are deleted first, so that a part of an earlier run
# can never be merged into this one.
set -euo pipefail

usage() {
    sed -n '2,/^set -euo/p' "${BASH_SOURCE[0]}" | sed '$d; s/^# \{0,1\}//' >&2
    exit 2
}

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
[[ $# -ge 3 ]] || usage
scene=$1 spp=$2 tasks=$3
shift 3
out="" image="" partition="" time_limit=01:00:00 cpus=4 merge_time=00:15:00
while [[ $# -gt 0 ]]; do
    case $1 in
    --out) out=$2; shift 2 ;;
    --image) image=$2; shift 2 ;;
    --partition) partition=$2; shift 2 ;;
    --time) time_limit=$2; shift 2 ;;
    --cpus) cpus=$2; shift 2 ;;
    --merge-time) merge_time=$2; shift 2 ;;
    --) shift; break ;;
    *) echo "$0: unknown option $1" >&2; usage ;;
    esac
done
render_args=("$@")

for n in "$spp" "$tasks" "$cpus"; do
    [[ $n =~ ^[0-9]+$ ]] || { echo "$0: not a whole number: $n" >&2; exit 2; }
done
if ((tasks < 1 || tasks > spp || cpus < 1)); then
    echo "$0: need 1 <= TASKS <= SPP and CPUS >= 1" >&2
    exit 2
fi
[[ -f $scene ]] || { echo "$0: no such scene: $scene" >&2; exit 2; }
for a in "${render_args[@]}"; do
    case $a in
    --spp | -o | --samples | --film | --threads)
        echo "$0: $a is set by the farm scripts, not in RENDER_ARGS" >&2
        exit 2
        ;;
    esac
done

abs() { (cd "$(dirname "$1")" && printf '%s/%s\n' "$(pwd)" "$(basename "$1")"); }
name=$(basename "${scene%.*}")
scene=$(abs "$scene")
out=${out:-$root/output/farm/$name}
mkdir -p "$out/parts" "$out/logs"
out=$(cd "$out" && pwd)
image=${image:-$out/$name.bmp}
mkdir -p "$(dirname "$image")"
image=$(abs "$image")
rm -f "$out"/parts/part-*.exr

common=(--parsable --export=ALL --chdir="$root")
[[ -n $partition ]] && common+=(--partition="$partition")

export FARM_ROOT=$root
array_id=$(sbatch "${common[@]}" \
    --job-name="pt-$name" --array="0-$((tasks - 1))" \
    --cpus-per-task="$cpus" --time="$time_limit" \
    --output="$out/logs/task-%a.log" \
    "$root/scripts/farm/slurm-task.sbatch" "$scene" "$spp" "$tasks" "$out" -- "${render_args[@]}")
array_id=${array_id%%;*}
merge_id=$(sbatch "${common[@]}" \
    --job-name="pt-$name-merge" --dependency="afterok:$array_id" \
    --time="$merge_time" \
    --output="$out/logs/merge.log" \
    "$root/scripts/farm/slurm-merge.sbatch" "$out" "$tasks" "$image")
merge_id=${merge_id%%;*}

echo "array job $array_id: $tasks tasks of $scene at $spp spp, logs in $out/logs"
echo "merge job $merge_id: $image once array $array_id has succeeded"
