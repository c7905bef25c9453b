#!/usr/bin/env bash
# MPI against one process (bench/README.md, "MPI"): the Cornell box rendered by
# `candela --threads C` and by `mpirun -np N candela --threads T` with N x T = C, alternating the
# two so that a change in the machine's load hits both alike; also 3 and 4 ranks oversubscribed
# (more rank threads than cores: the overheads, not the speed, are what they show). Per setting:
# the median wall time of the whole command, its render time (sampling only), the efficiency
# (one process's render time over MPI's: 100% = as fast), the startup overhead (wall minus
# render), the passes and the bytes rank 0 received and sent per pixel and pass.
#
#   bench/mpi_scaling.sh [--runs N] [--spp "64 256"] [--record] [--build-dir DIR] [--no-build]
#                        [-- EXTRA MPIRUN FLAGS]
#
# Flags after -- go to mpirun (e.g. -- --mca pml ob1: on a machine without a fast network, Open
# MPI's default UCX layer alone takes ~0.2 s of MPI_Init).
#
# Needs Open MPI (scripts/setup.sh installs it); timings need a quiet machine.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/lib.sh

runs=5 spps="64 256" record=0 build=1 build_dir=build mpirun_flags=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --spp) spps="$2"; shift 2 ;;
    --record) record=1; shift ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    --) shift; mpirun_flags=("$@"); break ;;
    *) echo "usage: bench/mpi_scaling.sh [--runs N] [--spp \"64 256\"] [--record] [--build-dir DIR] [--no-build]" >&2; exit 2 ;;
  esac
done
command -v mpirun >/dev/null || { echo "mpi_scaling: mpirun not found (scripts/setup.sh installs Open MPI)" >&2; exit 2; }
[ "$build" = 1 ] && BUILD_DIR="$build_dir" scripts/build.sh candela_cli >/dev/null
[ "$(id -u)" -eq 0 ] && export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cores=$(nproc)
out="$build_dir/bench-work/mpi"
mkdir -p "$out"
scene=scenes/cornell-box/scene.json
pixels=$((512 * 512))

# One run of setting $1 ("1xC" alone, or "NxT" under mpirun) at spp $2: appends "wall render passes
# to_rank0 from_rank0" to $out/$1-$2.txt.
run_once() {
  local setting="$1" spp="$2" n t start end st="$out/stats.json"
  n="${setting%x*}" t="${setting#*x}"
  rm -f "$st"
  start=$(now)
  if [ "$setting" = "alone" ]; then
    "$build_dir/candela" render "$scene" --spp "$spp" --threads "$cores" -o "$out/img.exr" --stats "$st" 2>>"$out/log"
  else
    mpirun "${mpirun_flags[@]}" --oversubscribe -np "$n" "$build_dir/candela" render "$scene" --spp "$spp" --threads "$t" \
      -o "$out/img.exr" --stats "$st" 2>>"$out/log"
  fi
  end=$(now)
  echo "$(calc "$end - $start") $(field "$st" render_seconds) $(field "$st" passes) $(field "$st" mpi_bytes_to_rank0) $(field "$st" mpi_bytes_from_rank0)" \
    >>"$out/$setting-$spp.txt"
}

settings=("alone" "2x1" "3x1" "4x1")
[ "$cores" -ge 4 ] && settings+=("$((cores / 2))x2")
table="$out/table.md"
{
  echo "MPI against one process, Cornell box 512x512 ($(commit_id), $(cpu_model), $cores cores, medians of $runs alternating runs${mpirun_flags[*]:+, mpirun ${mpirun_flags[*]}}):"
  echo
  echo "| spp | ranks x threads | wall s | render s | efficiency (render) | efficiency (wall) | startup s | passes | to rank 0 B/px/pass | from rank 0 B/px/pass |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
} >"$table"
for spp in $spps; do
  for s in "${settings[@]}"; do rm -f "$out/$s-$spp.txt"; done
  for r in $(seq "$runs"); do
    for s in "${settings[@]}"; do run_once "$s" "$spp"; done
  done
  base_render="" base_wall=""
  for s in "${settings[@]}"; do
    f="$out/$s-$spp.txt"
    wall=$(median $(awk '{print $1}' "$f"))
    render=$(median $(awk '{print $2}' "$f"))
    passes=$(median $(awk '{print $3}' "$f"))
    [ "$s" = "alone" ] && base_render="$render" base_wall="$wall"
    label="$s"
    [ "$s" = "alone" ] && label="1 process x $cores"
    if [ "$s" = "alone" ]; then
      to="-" from="-"
    else
      to=$(calc "$(median $(awk '{print $4}' "$f")) / $pixels / $passes")
      from=$(calc "$(median $(awk '{print $5}' "$f")) / $pixels / $passes")
    fi
    printf '| %s | %s | %.2f | %.2f | %.1f%% | %.1f%% | %.2f | %s | %s | %s |\n' "$spp" "$label" "$wall" "$render" \
      "$(calc "100 * $base_render / $render")" "$(calc "100 * $base_wall / $wall")" "$(calc "$wall - $render")" \
      "$passes" "$to" "$from" >>"$table"
  done
done
cat "$table"
if [ "$record" = 1 ]; then
  { echo; cat "$table"; } >>bench/RESULTS.md
fi
