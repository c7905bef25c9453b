#!/usr/bin/env bash
# The benchmark: renders each benchmark scene at a fixed spp several times and prints one
# Markdown table row per scene (median wall time of the render, samples/s, rays/s by kind), with
# the commit, machine and date, ready to append to bench/RESULTS.md.
#
#   bench/run.sh [--spp N] [--runs N] [--threads N]
#
# It builds Release first (scripts/build.sh). Benchmarks are not tests: nothing here is in ctest.
set -euo pipefail
cd "$(dirname "$0")/.."

spp=64 runs=3 threads=0
while [ $# -gt 0 ]; do
  case "$1" in
    --spp) spp="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    *) echo "usage: bench/run.sh [--spp N] [--runs N] [--threads N]" >&2; exit 2 ;;
  esac
done

scripts/build.sh candela_cli >/dev/null
scenes=(scenes/cornell-box/scene.json)

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD 2>/dev/null || commit="$commit+dirty"
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
machine="$cpu, $(nproc) cores"
date=$(date -u +%Y-%m-%d)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# A field of the flat JSON that `candela render --stats` writes.
field() { grep -o "\"$2\": [0-9.]*" "$1" | head -1 | awk '{print $2}'; }

echo "| date | commit | machine | scene | size | spp | threads | render s (median of $runs) | Msamples/s | Mrays/s | camera / bounce / shadow Mrays |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for scene in "${scenes[@]}"; do
  times=()
  for r in $(seq "$runs"); do
    build/candela render "$scene" --spp "$spp" --threads "$threads" -o "$tmp/out.exr" --stats "$tmp/stats$r.json" 2>/dev/null
    times+=("$(field "$tmp/stats$r.json" render_seconds) $r")
  done
  median_run=$(printf '%s\n' "${times[@]}" | sort -n | awk -v n="$runs" 'NR == int((n + 1) / 2) {print $2}')
  s="$tmp/stats$median_run.json"
  secs=$(field "$s" render_seconds)
  awk -v d="$date" -v c="$commit" -v m="$machine" -v sc="$(basename "$(dirname "$scene")")" \
      -v w="$(field "$s" width)" -v h="$(field "$s" height)" -v spp="$(field "$s" spp)" -v th="$(field "$s" threads)" \
      -v t="$secs" -v n="$(field "$s" samples)" -v rt="$(field "$s" total)" \
      -v rc="$(field "$s" camera)" -v rb="$(field "$s" bounce)" -v rs="$(field "$s" shadow)" \
      'BEGIN { printf "| %s | %s | %s | %s | %sx%s | %s | %s | %.2f | %.2f | %.2f | %.1f / %.1f / %.1f |\n",
               d, c, m, sc, w, h, spp, th, t, n / t / 1e6, rt / t / 1e6, rc / 1e6, rb / 1e6, rs / 1e6 }'
done
