#!/usr/bin/env bash
# Renders the benchmark's converged references once (bench/README.md, "References"):
#
#   bench/make-references.sh [--build-dir DIR] [--no-build] [--spp N]
#                            [--candela BIN --commit ID] [SCENE ...]
#
# Default: all scenes, each at its ref_spp from bench/lib.sh; --spp overrides it, for trying the
# script out. --candela renders with another build (e.g. of a clean commit, from `git archive`),
# whose commit --commit names for the record.
#
# Each reference is rendered at 1/4 of the benchmark resolution with a box filter (so it is, in
# expectation, exactly the box-downsampled full-resolution image), as two independent halves of
# ref_spp/2 samples with seeds 1001 and 2002 (the benchmark renders use seed 0). Their mean goes
# to bench/references/NAME.exr as half-float EXR; NAME.json records the command, spp, commit,
# date, render time and the reference's own expected relMSE (relMSE(A, B) / 4), which the
# benchmark's targets must stay well above. Runs at low priority (nice): about 15 minutes for
# the first five scenes on a quiet 2-core machine (35 minutes while others compiled), and 12
# minutes more for cornell-glass (on a busy machine).
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/lib.sh

build_dir=build build=1 scenes=() spp_override="" candela="" commit=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build_dir="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    --spp) spp_override="$2"; shift 2 ;;
    --candela) candela="$2"; shift 2 ;;
    --commit) commit="$2"; shift 2 ;;
    -*) echo "usage: bench/make-references.sh [--build-dir DIR] [--no-build] [--spp N] [--candela BIN --commit ID] [SCENE ...]" >&2
        exit 2 ;;
    *) scenes+=("$1"); shift ;;
  esac
done
[ ${#scenes[@]} -eq 0 ] && scenes=("${bench_all_scenes[@]}")
for s in "${scenes[@]}"; do
  [ -n "$spp_override" ] && ref_spp[$s]=$spp_override
  [ -n "${ref_spp[$s]:-}" ] || { echo "make-references: unknown scene $s; expected one of: ${bench_all_scenes[*]}" >&2; exit 2; }
done
if [ -n "$candela" ] && [ -z "$commit" ]; then
  echo "make-references: --candela needs --commit (the commit that binary was built from)" >&2
  exit 2
fi
[ -z "$candela" ] && candela="$build_dir/candela" commit=$(commit_id)
work_dir="$build_dir/bench-work"
mkdir -p "$work_dir" bench/references
if [ "$build" = 1 ]; then
  BUILD_DIR="$build_dir" scripts/build.sh candela_cli candela_make_reference candela_make_mesh >/dev/null
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

for name in "${scenes[@]}"; do
  prepare_scene "$name" || continue
  scene=$(scene_file "$name")
  read -r w h <<<"$(scene_resolution "$scene")"
  rw=$((w / ref_factor)) rh=$((h / ref_factor)) half=$((ref_spp[$name] / 2))
  cmd="candela render ${scene/#$build_dir/BUILD} --resolution ${rw}x${rh} --spp $half --threads 0"
  case "$name" in
    dragon) inputs="dragon_vrip.ply (gzip -dc of CANDELA_ASSETS/meshes/stanford-dragon/dragon_vrip.ply.gz)" ;;
    displaced-sphere) inputs="displaced-sphere.ply (candela_make_mesh --triangles $sphere_triangles)" ;;
    *) inputs="the files bench/scenes/$name.json names" ;;
  esac
  echo "make-references: $name: ${rw}x${rh}, 2 x $half spp" >&2
  start=$(now)
  for seed in 1001 2002; do
    nice -n 10 "$candela" render "$scene" --resolution "${rw}x${rh}" --spp "$half" --threads 0 \
      --seed "$seed" -o "$tmp/$seed.exr" 2>/dev/null
  done
  seconds=$(calc "$(now) - $start")
  floor=$("$build_dir/candela_make_reference" "$(reference_file "$name")" "$tmp/1001.exr" "$tmp/2002.exr")
  cat >"$(reference_record "$name")" <<JSON
{
  "scene": "bench/scenes/$name.json",
  "scene_sha256_16": "$(scene_hash "$name")",
  "inputs": "$inputs",
  "resolution": [$rw, $rh],
  "spp": ${ref_spp[$name]},
  "halves": "2 renders of $half spp, seeds 1001 and 2002, averaged by candela_make_reference",
  "command": "$cmd --seed {1001,2002}",
  "commit": "$commit",
  "date": "$(date -u +%Y-%m-%d)",
  "machine": "$(cpu_model), $(nproc) cores",
  "seconds": $(printf '%.1f' "$seconds"),
  "relmse_floor": $floor
}
JSON
  echo "make-references: $name: relMSE floor $floor, $(printf '%.0f' "$seconds") s, $(stat -c %s "$(reference_file "$name")") bytes" >&2
done
