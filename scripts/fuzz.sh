#!/usr/bin/env bash
# Builds the libFuzzer targets (scripts/build-sanitize.sh) and fuzzes each for a while:
#   scripts/fuzz.sh [--smoke SECONDS | --long SECONDS] [TARGET...]
# --smoke (default 30 s per target; CI runs 10 s); --long is for the recorded runs in
# docs/RELIABILITY.md. Targets: scene obj ply hdr exr pbrt nvdb (default: all). Each target first runs
# every input in fuzz/regressions/TARGET/ (inputs that once crashed it), then fuzzes from its
# seeds (the repository's scenes, meshes, images and bad inputs) and its working corpus, which
# grows in BUILD_DIR/fuzz-corpus/TARGET/ from run to run. A crash, a hang (an input taking over
# 10 s), a leak, a sanitizer report or an allocation over 2.5 GiB fails the target; the input is
# saved under BUILD_DIR/fuzz-artifacts/TARGET/. Prints executions, speed and coverage per target
# and exits 1 if any target failed.
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=30
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --smoke|--long) seconds="$2"; shift 2 ;;
    -h|--help) sed -n '2,/^set -e/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "fuzz: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
all_targets=(scene obj ply hdr exr pbrt nvdb)
[ ${#targets[@]} -eq 0 ] && targets=("${all_targets[@]}")
for t in "${targets[@]}"; do
  [[ " ${all_targets[*]} " == *" $t "* ]] || { echo "fuzz: unknown target $t; expected one of: ${all_targets[*]}" >&2; exit 2; }
done

export BUILD_DIR="${BUILD_DIR:-build-sanitize}"
build_targets=(candela_fuzz_image_seeds)
for t in "${targets[@]}"; do build_targets+=("candela_fuzz_$t"); done
scripts/build-sanitize.sh "${build_targets[@]}"

# seed_files TARGET: the repository files that seed it (scenes/ and tests/data/, the bad-input
# corpus included), one per line. Files over 64 KiB are left out: libFuzzer sizes its inputs after
# the largest seed, and big inputs only slow it down.
seed_files() {
  local patterns
  case "$1" in
    scene) patterns=(-name '*.json') ;;
    obj) patterns=(-iname '*.obj') ;;
    ply) patterns=(-iname '*.ply' -o -iname '*.ply.gz') ;;
    hdr) patterns=(-iname '*.hdr') ;;
    exr) patterns=(-iname '*.exr') ;;
    pbrt) patterns=(-iname '*.pbrt') ;;
    nvdb) patterns=(-iname '*.nvdb') ;;
  esac
  find scenes tests/data -type f \( "${patterns[@]}" \) -size -65k | sort
}

fuzz_dir="$BUILD_DIR/fuzz"
image_seeds="$BUILD_DIR/fuzz-seeds/images"
rm -rf "$image_seeds"
"$fuzz_dir/candela_fuzz_image_seeds" "$image_seeds"

failed=()
summary=()
for t in "${targets[@]}"; do
  binary="$fuzz_dir/candela_fuzz_$t"
  seeds="$BUILD_DIR/fuzz-seeds/$t"
  corpus="$BUILD_DIR/fuzz-corpus/$t"
  artifacts="$BUILD_DIR/fuzz-artifacts/$t/"
  log="$BUILD_DIR/fuzz-logs/$t.log"
  rm -rf "$seeds"
  mkdir -p "$seeds" "$corpus" "$artifacts" "$(dirname "$log")"
  seed_files "$t" | while read -r f; do cp "$f" "$seeds/$(echo "$f" | tr '/' '_')"; done
  case "$t" in hdr|exr) cp "$image_seeds"/*."$t" "$seeds/" ;; esac
  # The NanoVDB fixtures are kept gzip-compressed (tests/data/vdb/README.md); inflated, they are
  # 0.3 to 2.4 MB, so only those under 1 MB seed the target.
  if [ "$t" = nvdb ]; then
    for f in tests/data/vdb/*.nvdb.gz; do
      out="$seeds/$(basename "$f" .gz)"
      gzip -dc "$f" >"$out"
      [ "$(stat -c %s "$out")" -lt 1048576 ] || rm "$out"
    done
  fi
  limits=(-timeout=10 -rss_limit_mb=2560 -malloc_limit_mb=1024)
  dict=()
  [ -f "fuzz/$t.dict" ] && dict=("-dict=fuzz/$t.dict")

  echo "fuzz: $t: regression inputs" >&2
  regressions="fuzz/regressions/$t"
  if ! "$binary" -runs=0 "${limits[@]}" "$regressions" >"$log" 2>&1; then
    echo "fuzz: $t: a regression input fails again; log: $log" >&2
    tail -n 40 "$log" >&2
    failed+=("$t")
    continue
  fi

  echo "fuzz: $t: fuzzing for $seconds s" >&2
  status=0
  "$binary" -max_total_time="$seconds" -print_final_stats=1 -artifact_prefix="$artifacts" "${limits[@]}" \
    "${dict[@]}" "$corpus" "$seeds" "$regressions" >"$log" 2>&1 || status=$?
  # The last status line ("#N DONE cov: C ft: F corp: U/S ...") and libFuzzer's final stats.
  last=$(grep -E '^#[0-9]+' "$log" | tail -n 1 || true)
  cov=$(sed -nE 's/.* cov: ([0-9]+).*/\1/p' <<<"$last")
  ft=$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$last")
  corp=$(sed -nE 's/.* corp: ([0-9]+)\/([0-9a-zA-Z]+).*/\1 (\2)/p' <<<"$last")
  execs=$(sed -nE 's/^stat::number_of_executed_units: *([0-9]+)/\1/p' "$log")
  speed=$(sed -nE 's/^stat::average_exec_per_sec: *([0-9]+)/\1/p' "$log")
  rss=$(sed -nE 's/^stat::peak_rss_mb: *([0-9]+)/\1/p' "$log")
  summary+=("$(printf '%-6s %12s %9s %7s %7s %14s %8s  %s' "$t" "${execs:-?}" "${speed:-?}" "${cov:-?}" "${ft:-?}" \
    "${corp:-?}" "${rss:-?}" "$([ $status -eq 0 ] && echo ok || echo FAILED)")")
  if [ $status -ne 0 ]; then
    echo "fuzz: $t: FAILED (exit $status); input saved in $artifacts; log: $log" >&2
    grep -E '^(==[0-9]+==ERROR|SUMMARY|fuzz: invariant|.*runtime error|.*Test unit written)' "$log" >&2 || tail -n 40 "$log" >&2
    failed+=("$t")
  fi
done

echo
printf '%-6s %12s %9s %7s %7s %14s %8s  %s\n' target executions exec/s cov ft "corpus (size)" "rss MB" result
for line in "${summary[@]}"; do echo "$line"; done
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: failed: ${failed[*]}" >&2
  exit 1
fi
