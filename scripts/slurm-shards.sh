#!/usr/bin/env bash
#SBATCH --job-name=candela-shards
#SBATCH --array=1-8
#SBATCH --cpus-per-task=16
#SBATCH --time=04:00:00
#SBATCH --requeue
#SBATCH --output=candela-%x-%a.log
# Renders one scene on a Slurm cluster as a job array of N shards, then merges the parts into the
# images one `candela render` would write, bit for bit (docs/CLUSTER.md). On the login node, in
# the folder the parts and images should go to:
#
#   SHARDS=8 scripts/slurm-shards.sh SCENE OUTPUT... [-- RENDER FLAGS...]
#   SHARDS=64 scripts/slurm-shards.sh scenes/cornell-box/scene.json cbox.exr cbox.png -- --spp 4096
#
# submits this script as a job array (--array=1-N, overriding the line above), whose task I runs
#   candela render SCENE --shard I/N -o part-I.ckpt
# and a merge job (afterok: it starts once every task has succeeded) that runs
#   candela merge part-1.ckpt ... part-N.ckpt -o OUTPUT...
# The scene and the files it names must be readable from every node (a shared file system), and
# every task must be given the same flags. A task that is stopped (Slurm's SIGTERM at the time
# limit or on preemption) writes its part file; requeued, it resumes from it. CANDELA names the
# program (default: candela on the PATH); sbatch options (partition, account) go in SBATCH_*
# variables or in the lines above.
set -euo pipefail

candela=${CANDELA:-candela}
shards=${SHARDS:-8}
scene=${1:?usage: SHARDS=N $0 SCENE OUTPUT... [-- RENDER FLAGS...]}
shift
outputs=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    outputs+=("$1")
    shift
done
[ $# -gt 0 ] && shift  # the "--"
[ ${#outputs[@]} -gt 0 ] || { echo "$0: give at least one OUTPUT image" >&2; exit 2; }

if [ -n "${SLURM_ARRAY_TASK_ID:-}" ]; then
    # One task of the array: render part I of N, continuing its part file if a stopped run of
    # this task left one.
    i=$SLURM_ARRAY_TASK_ID
    part="part-$i.ckpt"
    resume=()
    [ -f "$part" ] && resume=(--resume "$part")
    exec "$candela" render "$scene" --shard "$i/$shards" -o "$part" --checkpoint-every 600 \
        --threads "${SLURM_CPUS_PER_TASK:-0}" "${resume[@]}" "$@"
else
    # On the login node: submit the array, then the merge (a job of its own, not an array: a
    # wrapped command line) to start once every task has succeeded.
    array=$(sbatch --parsable --array="1-$shards" --export="ALL,SHARDS=$shards" "$0" "$scene" "${outputs[@]}" -- "$@")
    array=${array%%;*}  # "jobid;cluster" on multi-cluster sites
    merge_command=("$candela" merge)
    for ((i = 1; i <= shards; ++i)); do merge_command+=("part-$i.ckpt"); done
    for out in "${outputs[@]}"; do merge_command+=(-o "$out"); done
    merge=$(sbatch --parsable --job-name=candela-merge --dependency="afterok:$array" --output=candela-merge-%j.log \
        --wrap="$(printf '%q ' "${merge_command[@]}")")
    echo "submitted job array $array ($shards shards) and merge job ${merge%%;*}"
fi
