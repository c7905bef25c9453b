#!/usr/bin/env bash
# The benchmark (bench/README.md): renders the fixed scene set and writes Markdown tables of
# speed (wall time, startup, samples/s, rays/s by kind, peak memory), error against the converged
# references (relMSE at the benchmark spp, time to reach a target relMSE) and the raw-traversal
# bound (Embree alone on candela's own rays, and candela's end-to-end rays/s as a fraction of it).
#
#   bench/run.sh [--runs N] [--threads N] [--scenes a,b,...] [--record] [--no-bound]
#                [--no-target] [--build-dir DIR] [--no-build] [--work DIR] [--smoke]
#                [-- EXTRA CANDELA RENDER FLAGS]
#
# --runs: timed renders per scene, the table shows medians (default 3). --threads: render
# threads, 0 = all cores (default). --record: also append the tables to bench/RESULTS.md.
# --smoke: the ctest run (cornell-box and bunny-sky at twice the reference resolution, 2 spp,
# one run, a short bound), which must finish in seconds. Everything after -- goes to every `candela render`
# (e.g. -- --sampler sobol). Builds Release first unless --no-build. Timings need a quiet machine.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/lib.sh

usage() {
  sed -n '7,9p' "$0" | sed 's/^#  */usage: /' >&2
  exit 2
}

runs=3 threads=0 record=0 smoke=0 build=1 bound=1 target=1 build_dir=build work_dir="" scenes_arg="" extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --threads) threads="$2"; shift 2 ;;
    --scenes) scenes_arg="$2"; shift 2 ;;
    --record) record=1; shift ;;
    --no-bound) bound=0; shift ;;
    --no-target) target=0; shift ;;
    --build-dir) build_dir="$2"; shift 2 ;;
    --no-build) build=0; shift ;;
    --work) work_dir="$2"; shift 2 ;;
    --smoke) smoke=1; shift ;;
    --) shift; extra=("$@"); break ;;
    *) usage ;;
  esac
done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || { echo "bench: --runs: expected an integer >= 1, got $runs" >&2; exit 2; }
[[ "$threads" =~ ^[0-9]+$ ]] || { echo "bench: --threads: expected an integer >= 0, got $threads" >&2; exit 2; }
[ -n "$work_dir" ] || work_dir="$build_dir/bench-work"

if [ "$smoke" = 1 ]; then
  scenes=(cornell-box bunny-sky)
  runs=1
elif [ -n "$scenes_arg" ]; then
  IFS=, read -r -a scenes <<<"$scenes_arg"
else
  scenes=("${bench_all_scenes[@]}")
fi
for s in "${scenes[@]}"; do
  [ -n "${bench_spp[$s]:-}" ] || { echo "bench: unknown scene $s; expected one of: ${bench_all_scenes[*]}" >&2; exit 2; }
done

if [ "$build" = 1 ]; then
  BUILD_DIR="$build_dir" scripts/build.sh candela_cli candela_relmse candela_make_mesh candela_record_rays \
    candela_trace_bound >/dev/null
fi
candela="$build_dir/candela"
for tool in "$candela" "$build_dir/candela_relmse" "$build_dir/candela_make_mesh"; do
  [ -x "$tool" ] || { echo "bench: $tool is missing (build it, or drop --no-build)" >&2; exit 1; }
done
out="$work_dir/out"
mkdir -p "$out"
rm -f "$out"/*

# Renders scene $1 at $2 spp; the stats JSON goes to $3, the image to $3 with .exr; prints the
# wall time of the whole command. Extra render flags follow in $4...
render() {
  local scene="$1" spp="$2" stats="$3" start
  shift 3
  start=$(now)
  if ! "$candela" render "$scene" --spp "$spp" --threads "$threads" -o "${stats%.json}.exr" --stats "$stats" \
    "$@" ${extra[@]+"${extra[@]}"} 2>"${stats%.json}.log"; then
    echo "bench: candela failed on $scene:" >&2
    cat "${stats%.json}.log" >&2
    exit 1
  fi
  calc "$(now) - $start"
}

# relMSE of image $1 against the reference of scene $2, or "n/a".
relmse_of() {
  local ref
  ref=$(reference_file "$2")
  if [ -f "$ref" ]; then "$build_dir/candela_relmse" "$1" "$ref"; else echo n/a; fi
}

date=$(date -u +%Y-%m-%d)
commit=$(commit_id)
machine="$(cpu_model), $(nproc) cores"
perf_rows=() error_rows=() bound_rows=() notes=()
declare -A e2e_rays  # scene -> candela's median end-to-end Mrays/s, for the bound table
used_threads=""

for name in "${scenes[@]}"; do
  if ! prepare_scene "$name"; then
    perf_rows+=("| $name | skipped: input not found (see the note below) | | | | | | | | | |")
    error_rows+=("| $name | skipped | | | | | |")
    notes+=("$name: skipped, $dragon_asset not found (CANDELA_ASSETS overrides the assets folder)")
    continue
  fi
  scene=$(scene_file "$name")
  spp=${bench_spp[$name]}
  res_flags=()
  ref=$(reference_file "$name")
  if [ "$smoke" = 1 ]; then
    # Twice the reference resolution (so the comparison downsamples), 2 spp.
    read -r w h <<<"$(scene_resolution "$scene")"
    res_flags=(--resolution "$((2 * w / ref_factor))x$((2 * h / ref_factor))")
    spp=2
    [ -f "$ref" ] || { echo "bench: smoke run: $ref is missing" >&2; exit 1; }
  fi
  if [ -f "$(reference_record "$name")" ] && ! grep -q "\"scene_sha256_16\": \"$(scene_hash "$name")\"" "$(reference_record "$name")"; then
    notes+=("$name: bench/scenes/$name.json changed since its reference was rendered: run bench/make-references.sh $name")
  fi
  echo "bench: $name: $runs x $spp spp" >&2

  walls=() renders=() startups=() loads=() builds=() rss=() order=()
  for r in $(seq "$runs"); do
    st="$out/$name-run$r.json"
    walls+=("$(render "$scene" "$spp" "$st" ${res_flags[@]+"${res_flags[@]}"})")
    renders+=("$(field "$st" render_seconds)")
    startups+=("$(field "$st" startup_seconds)")
    loads+=("$(field "$st" load_seconds)")
    builds+=("$(field "$st" build_seconds)")
    rss+=("$(field "$st" peak_rss_bytes)")
    order+=("$(field "$st" render_seconds) $r")
  done
  # The run with the median render time gives the ray counts and the image for relMSE.
  mid=$(printf '%s\n' "${order[@]}" | sort -g | awk -v n="$runs" 'NR == int((n + 1) / 2) {print $2}')
  st="$out/$name-run$mid.json"
  t=$(median "${renders[@]}")
  used_threads=$(field "$st" threads)
  e2e_rays[$name]=$(calc "$(field "$st" total) / $t / 1e6")
  perf_rows+=("$(awk -v n="$name" -v w="$(field "$st" width)" -v h="$(field "$st" height)" -v spp="$spp" \
    -v th="$used_threads" -v wall="$(median "${walls[@]}")" -v su="$(median "${startups[@]}")" \
    -v ld="$(median "${loads[@]}")" -v bd="$(median "${builds[@]}")" -v t="$t" -v s="$(field "$st" samples)" \
    -v rt="$(field "$st" total)" -v rc="$(field "$st" camera)" -v rb="$(field "$st" bounce)" \
    -v rs="$(field "$st" shadow)" -v mem="$(median "${rss[@]}")" \
    'BEGIN { printf "| %s | %sx%s | %s | %s | %.2f | %.2f (%.2f / %.2f) | %.2f | %.3f | %.2f | %.2f / %.2f / %.2f | %.0f |",
             n, w, h, spp, th, wall, su, ld, bd, t, s / t / 1e6, rt / t / 1e6, rc / t / 1e6, rb / t / 1e6, rs / t / 1e6, mem / 1048576 }')")

  # Error against the reference: at the benchmark spp, then doubling spp from 1 until the
  # target is met (at most 4x the benchmark spp).
  rel=$(relmse_of "${st%.json}.exr" "$name")
  floor=$(grep -o '"relmse_floor": [-0-9.e+]*' "$(reference_record "$name")" 2>/dev/null | awk '{print $2}' || true)
  goal=${bench_target[$name]}
  [ "$smoke" = 1 ] && goal=1e9  # met at 1 spp: runs the loop once
  reached="n/a" reached_s="n/a" estimate="n/a"
  if [ "$target" = 1 ] && [ -f "$ref" ]; then
    reached="> $((4 * spp))"
    for ((s = 1; s <= 4 * spp; s *= 2)); do
      ts="$out/$name-target$s.json"
      render "$scene" "$s" "$ts" ${res_flags[@]+"${res_flags[@]}"} >/dev/null
      e=$("$build_dir/candela_relmse" "${ts%.json}.exr" "$ref")
      if awk -v e="$e" -v g="$goal" 'BEGIN { exit !(e < g) }'; then
        ts_render=$(field "$ts" render_seconds)
        reached=$s reached_s=$(printf '%.2f' "$ts_render")
        # relMSE ~ 1/spp for independent samples: the time at which it would just meet the target.
        estimate=$(awk -v t="$ts_render" -v e="$e" -v g="$goal" 'BEGIN { printf "%.2f", t * e / g }')
        break
      fi
    done
  fi
  error_rows+=("| $name | ${floor:-n/a} | $rel | $goal | $reached | $reached_s | $estimate |")
done

# The raw-traversal bound, on the Cornell box and the dragon: record a few spp of candela's own
# rays, trace them through Embree alone (1 thread and the benchmark's thread count), and compare
# with candela's end-to-end rays/s at the same thread count.
if [ "$bound" = 1 ] && [ -x "$build_dir/candela_trace_bound" ] && [ -n "$used_threads" ]; then
  for name in cornell-box dragon; do
    [ -n "${e2e_rays[$name]:-}" ] || continue
    scene=$(scene_file "$name")
    rays="$work_dir/rays-$name.bin"
    rec_flags=(--spp 2) gb_flags=("--benchmark_repetitions=$runs" --benchmark_report_aggregates_only=true)
    [ "$smoke" = 1 ] && rec_flags=(--spp 1 --resolution 64x64) gb_flags=(--benchmark_min_time=0.01)
    echo "bench: $name: raw-traversal bound" >&2
    "$build_dir/candela_record_rays" "$scene" "$rays" "${rec_flags[@]}" >"$out/record-$name.log"
    thread_list=1
    [ "$used_threads" != 1 ] && thread_list="1,$used_threads"
    "$build_dir/candela_trace_bound" "$scene" "$rays" --threads "$thread_list" --summary "$out/bound-$name.txt" \
      "${gb_flags[@]}" >"$out/bound-$name.log" 2>&1 || { cat "$out/bound-$name.log" >&2; exit 1; }
    rm -f "$rays"
    b() { awk -v k="$1" -v t="$2" '$1 == k && $2 == t {printf "%.1f", $3}' "$out/bound-$name.txt"; }
    T=$used_threads
    mix=$(b mix "$T")
    bound_rows+=("| $name | $(b camera 1) / $(b camera "$T") | $(b bounce 1) / $(b bounce "$T") | $(b shadow 1) / $(b shadow "$T") | $(b mix 1) / $mix | $(b camera_stream "$T") / $(b bounce_stream "$T") / $(b shadow_stream "$T") | $(printf '%.2f' "${e2e_rays[$name]}") | $(awk -v e="${e2e_rays[$name]}" -v m="$mix" 'BEGIN { printf "%.0f%%", 100 * e / m }') |")
  done
fi

# The tables.
report="$work_dir/results.md"
{
  echo "### $date, commit $commit, $machine, $used_threads threads, median of $runs run(s)"
  echo
  [ ${#extra[@]} -gt 0 ] && echo "candela render flags: \`${extra[*]}\`" && echo
  echo "| scene | size | spp | threads | wall s | startup s (load / build) | render s | Msamples/s | Mrays/s | camera / bounce / shadow Mrays/s | peak RSS MiB |"
  echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
  printf '%s\n' "${perf_rows[@]}"
  echo
  echo "| scene | reference relMSE floor | relMSE at bench spp | target relMSE | spp to target | render s at that spp | est. s to target (1/spp) |"
  echo "| --- | --- | --- | --- | --- | --- | --- |"
  printf '%s\n' "${error_rows[@]}"
  if [ ${#bound_rows[@]} -gt 0 ]; then
    echo
    echo "Raw-traversal bound: candela's own rays (${rec_flags[*]}, recorded by candela_record_rays) through Embree alone"
    echo "(candela_trace_bound; Mrays/s, 1 thread / $used_threads threads; streams: rtcIntersect1M/rtcOccluded1M, $used_threads threads)."
    echo
    echo "| scene | camera | bounce | shadow | mix | streams camera / bounce / shadow | candela end-to-end Mrays/s | candela / mix bound |"
    echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
    printf '%s\n' "${bound_rows[@]}"
  fi
  if [ ${#notes[@]} -gt 0 ]; then
    echo
    printf -- '- %s\n' "${notes[@]}"
  fi
} >"$report"
cat "$report"

# A table without its rows is a broken harness, not a result.
for name in "${scenes[@]}"; do
  if [ "$(grep -c "^| $name |" "$report")" -lt 2 ]; then
    echo "bench: the report lacks the rows of $name" >&2
    exit 1
  fi
done
if [ "$record" = 1 ]; then
  { echo; cat "$report"; } >>bench/RESULTS.md
  echo "bench: appended to bench/RESULTS.md" >&2
fi
