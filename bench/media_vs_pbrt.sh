#!/usr/bin/env bash
# Time to equal error against pbrt-v4 on media scenes (issue 24), side by side in one run on this
# machine: both renderers render each pbrt-v4 scene file unchanged at the same spp, threads and
# resolution; each image's relMSE (candela_relmse) is measured against a reference rendered by
# pbrt-v4 at REF_SPP with another seed, and each renderer's efficiency is 1 / (relMSE x seconds)
# (relMSE falls as 1/time for an unbiased estimator, so the ratio of efficiencies is the ratio of
# times to any equal error). The reference's own noise adds the same floor to both.
#
#   bench/media_vs_pbrt.sh --pbrt PATH/pbrt [--spp N] [--ref-spp N | --ref-dir DIR] [--threads N]
#                          [--cpu] [--record] [--no-build] [--build-dir DIR] [--work DIR] SCENE.pbrt...
#
# Any pbrt-v4 scene works (media, hair, ...). --cpu measures each render's CPU seconds (user + system)
# instead of its wall time: on a machine shared with other work the wall time measures the other
# work too, while both renderers keep every thread busy, so their CPU seconds compare the work.
#
# --ref-dir DIR takes DIR/NAME.exr as the reference instead of rendering one (the pbrt-v4
# references of tests/data/pbrt-media/refs/, 1024 spp at seed 0).
#
# pbrt-v4 is not a dependency of candela: build it as ../shared/refs/pbrt-v4/README.md says. Wall
# times include loading the scene (small here). candela renders in spectral mode, as pbrt-v4 does.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/lib.sh

pbrt="" spp=64 ref_spp=1024 ref_dir="" threads=2 cpu=0 record=0 build=1 build_dir=build work_dir=""
scenes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --pbrt) pbrt="$2"; shift 2 ;;
    --spp) spp="$2"; shift 2 ;;
    --ref-spp) ref_spp="$2"; shift 2 ;;
    --ref-dir) ref_dir="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --cpu) cpu=1; shift ;;
    --record) record=1; shift ;;
    --no-build) build=0; shift ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --work) work_dir="$2"; shift 2 ;;
    -*) echo "media_vs_pbrt: unknown option $1" >&2; exit 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ -x "$pbrt" ] || { echo "media_vs_pbrt: give --pbrt PATH to a pbrt-v4 binary" >&2; exit 2; }
[ ${#scenes[@]} -gt 0 ] || { echo "media_vs_pbrt: give the pbrt-v4 scene files" >&2; exit 2; }
work_dir="${work_dir:-$build_dir/bench-work/media}"
mkdir -p "$work_dir"
if [ "$build" = 1 ]; then BUILD_DIR="$build_dir" scripts/build.sh candela_cli candela_relmse >/dev/null; fi
candela="$build_dir/candela"
relmse="$build_dir/candela_relmse"

# Seconds a command takes, wall clock (or CPU seconds with --cpu); its output goes to the log $1.
timed() {
  local log="$1"; shift
  local t0 t1
  if [ "$cpu" = 1 ]; then
    /usr/bin/time -f "%U %S" -o "$log.time" "$@" >"$log" 2>&1
    awk '{print $1 + $2}' "$log.time"
    return
  fi
  t0=$(now)
  "$@" >"$log" 2>&1
  t1=$(now)
  calc "$t1 - $t0"
}

unit=s
cpu_flag=""
[ "$cpu" = 1 ] && unit="CPU s" && cpu_flag=" --cpu"
table="| scene | spp | pbrt-v4 $unit | pbrt-v4 relMSE | candela $unit | candela relMSE | candela's time to pbrt-v4's error |
| --- | --- | --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .pbrt)
  dir=$(cd "$(dirname "$scene")" && pwd)
  out="$(cd "$work_dir" && pwd)/$name"
  ref="$out-ref.pfm"
  [ -n "$ref_dir" ] && ref="$(cd "$ref_dir" && pwd)/$name.exr"
  if [ ! -f "$ref" ]; then
    echo "media_vs_pbrt: $name: reference, pbrt-v4 at $ref_spp spp" >&2
    (cd "$dir" && "$pbrt" --nthreads "$threads" --spp "$ref_spp" --seed 100 --outfile "$ref" --quiet "$(basename "$scene")") \
      >"$out-ref.log" 2>&1
  fi
  tp=$(cd "$dir" && timed "$out-pbrt.log" "$pbrt" --nthreads "$threads" --spp "$spp" --seed 1 --outfile "$out-pbrt.pfm" --quiet "$(basename "$scene")")
  tc=$(timed "$out-candela.log" "$candela" render "$scene" --spectral --threads "$threads" --spp "$spp" --seed 1 -o "$out-candela.pfm")
  ep=$("$relmse" "$out-pbrt.pfm" "$ref")
  ec=$("$relmse" "$out-candela.pfm" "$ref")
  # Time for candela to reach pbrt-v4's error: its time scaled by its error over pbrt-v4's.
  ratio=$(calc "($tc * $ec) / ($tp * $ep)")
  table+=$'\n'"| $name | $spp | $(printf %.2f "$tp") | $(printf %.3g "$ep") | $(printf %.2f "$tc") | $(printf %.3g "$ec") | $(printf %.2f "$ratio") x |"
done
echo "$table"
if [ "$record" = 1 ]; then
  {
    echo
    echo "### Against pbrt-v4, commit $(commit_id), $(date -u +%Y-%m-%d), $(cpu_model), $threads threads"
    echo
    if [ -n "$ref_dir" ]; then
      echo "bench/media_vs_pbrt.sh --spp $spp$cpu_flag --ref-dir $ref_dir (references: pbrt-v4's, 1024 spp, seed 0)"
    else
      echo "bench/media_vs_pbrt.sh --spp $spp$cpu_flag --ref-spp $ref_spp (reference: pbrt-v4, seed 100)"
    fi
    echo
    echo "$table"
  } >>bench/RESULTS.md
fi
