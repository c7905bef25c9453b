#!/usr/bin/env bash
# How candela's time grows (bench/README.md, "Scaling"): render threads (1 vs all cores),
# resolution and spp on the Cornell box, and triangle count (generated displaced spheres of 1k
# to 10M triangles: load, BVH build and render time, peak memory and bytes per triangle).
#
#   bench/scaling.sh [--runs N] [--record] [--build-dir DIR] [--no-build] [--work DIR]
#
# Times are medians of --runs renders (default 3). --record appends the tables to
# bench/RESULTS.md. About 3 minutes on a quiet 2-core machine; timings need a quiet machine.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/lib.sh

runs=3 record=0 build=1 build_dir=build work_dir=""
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --record) record=1; shift ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    --work) work_dir="$2"; shift 2 ;;
    *) echo "usage: bench/scaling.sh [--runs N] [--record] [--build-dir DIR] [--no-build] [--work DIR]" >&2; exit 2 ;;
  esac
done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || { echo "scaling: --runs: expected an integer >= 1, got $runs" >&2; exit 2; }
[ -n "$work_dir" ] || work_dir="$build_dir/bench-work"
[ "$build" = 1 ] && BUILD_DIR="$build_dir" scripts/build.sh candela_cli candela_make_mesh >/dev/null
out="$work_dir/scaling"
mkdir -p "$out"
rm -f "$out"/*.json "$out"/*.exr "$out"/*.log

# Renders scene $1 --runs times with the remaining flags; leaves the median run's stats in
# $out/last.json (by render time) and the medians of load, build, startup and render seconds and
# of peak RSS in the globals m_load m_build m_startup m_render m_rss.
measure() {
  local scene="$1" r st order=() loads=() builds=() startups=() renders=() rss=()
  shift
  for r in $(seq "$runs"); do
    st="$out/run$r.json"
    if ! "$build_dir/candela" render "$scene" -o "$out/run$r.exr" --stats "$st" "$@" 2>"$out/run$r.log"; then
      cat "$out/run$r.log" >&2
      exit 1
    fi
    loads+=("$(field "$st" load_seconds)") builds+=("$(field "$st" build_seconds)")
    startups+=("$(field "$st" startup_seconds)") renders+=("$(field "$st" render_seconds)")
    rss+=("$(field "$st" peak_rss_bytes)") order+=("$(field "$st" render_seconds) $r")
  done
  r=$(printf '%s\n' "${order[@]}" | sort -g | awk -v n="$runs" 'NR == int((n + 1) / 2) {print $2}')
  cp "$out/run$r.json" "$out/last.json"
  m_load=$(median "${loads[@]}") m_build=$(median "${builds[@]}") m_startup=$(median "${startups[@]}")
  m_render=$(median "${renders[@]}") m_rss=$(median "${rss[@]}")
}

cornell=bench/scenes/cornell-box.json
report="$work_dir/scaling.md"
{
  echo "### Scaling: $(date -u +%Y-%m-%d), commit $(commit_id), $(cpu_model), $(nproc) cores, median of $runs run(s)"
  echo
  echo "Threads (Cornell box 512x512, 16 spp; render time only):"
  echo
  echo "| threads | render s | Mrays/s | speedup |"
  echo "| --- | --- | --- | --- |"
  echo "scaling: threads" >&2
  t1=""
  for th in 1 $(nproc); do
    measure "$cornell" --spp 16 --threads "$th"
    [ -z "$t1" ] && t1=$m_render
    awk -v th="$th" -v t="$m_render" -v r="$(field "$out/last.json" total)" -v t1="$t1" \
      'BEGIN { printf "| %d | %.2f | %.2f | %.2f |\n", th, t, r / t / 1e6, t1 / t }'
  done
  echo
  echo "Resolution and spp (Cornell box, all cores): time per sample should stay flat."
  echo
  echo "| size | spp | render s | ns per sample | Mrays/s |"
  echo "| --- | --- | --- | --- | --- |"
  echo "scaling: resolution and spp" >&2
  for case in "128 16" "256 16" "512 16" "1024 16" "512 4" "512 64"; do
    read -r side spp <<<"$case"
    measure "$cornell" --spp "$spp" --resolution "${side}x${side}"
    awk -v s="$side" -v spp="$spp" -v t="$m_render" -v n="$(field "$out/last.json" samples)" \
      -v r="$(field "$out/last.json" total)" \
      'BEGIN { printf "| %dx%d | %d | %.2f | %.0f | %.2f |\n", s, s, spp, t, t / n * 1e9, r / t / 1e6 }'
  done
  echo
  echo "Triangle count (bench/scenes/displaced-sphere.json with a generated mesh, 256x256, 4 spp, all"
  echo "cores). Load: parsing the binary PLY; build: Embree BVH (and the light tables, negligible here);"
  echo "bytes/triangle: peak RSS above the 1k-triangle run, per triangle added (scene data, Embree's"
  echo "copy and BVH, and the PLY file's bytes while it is parsed)."
  echo
  echo "| triangles | PLY MB | load s | load MB/s | build s | Mtris/s built | render s | startup s | peak RSS MiB | bytes/triangle |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  echo "scaling: triangle count" >&2
  base_rss="" base_tris=""
  for n in 1000 10000 100000 1000000 10000000; do
    dir="$work_dir/sphere-$n"
    mkdir -p "$dir"
    make_sphere_mesh "$n" "$dir/displaced-sphere.ply"
    cp bench/scenes/displaced-sphere.json "$dir/"
    tris=$(grep -a -m1 '^element face' "$dir/displaced-sphere.ply" | awk '{print $3}')
    bytes=$(stat -c %s "$dir/displaced-sphere.ply")
    measure "$dir/displaced-sphere.json" --spp 4 --resolution 256x256
    [ -z "$base_rss" ] && base_rss=$m_rss base_tris=$tris
    awk -v n="$tris" -v b="$bytes" -v l="$m_load" -v bd="$m_build" -v t="$m_render" -v su="$m_startup" \
      -v m="$m_rss" -v m0="$base_rss" -v n0="$base_tris" \
      'BEGIN { per = n > n0 ? sprintf("%.0f", (m - m0) / (n - n0)) : "(base)";
               printf "| %d | %.1f | %.3f | %.0f | %.3f | %.2f | %.2f | %.2f | %.0f | %s |\n",
                      n, b / 1e6, l, b / 1e6 / l, bd, n / bd / 1e6, t, su, m / 1048576, per }'
  done
} >"$report"
cat "$report"
if [ "$record" = 1 ]; then
  { echo; cat "$report"; } >>bench/RESULTS.md
  echo "scaling: appended to bench/RESULTS.md" >&2
fi
