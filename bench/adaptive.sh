#!/usr/bin/env bash
# bench/adaptive.sh [SCENE...]: time to the benchmark's target relMSE (bench/lib.sh) with and
# without adaptive sampling (issue 17), at the reference's resolution (bench/references/*.json),
# sobol sampler, all cores. Uniform: spp in steps of 2^(1/4) until the relMSE against the
# reference is below the target; adaptive: --noise-threshold in steps of 2^(-1/8) from 0.5 (spp
# capped at 4x the uniform spp that met the target, --min-spp MIN_SPP, default 8) until the
# target is met; --target-error TARGET: one render (what a user runs; met or not, its true relMSE
# is printed); then --target-error in steps of 2^(-1/8) from TARGET until the true relMSE meets
# the target (the allocation's own time to target, as the threshold's: tuned against the
# reference). Each row: the first run meeting the target, its spp (mean for adaptive) and render
# seconds. Prints a Markdown table; renders run one at a time, so a loaded machine slows all.
set -euo pipefail
cd "$(dirname "$0")/.."
source bench/lib.sh
build_dir=${BUILD_DIR:-build}
min_spp=${MIN_SPP:-8}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(cornell-glass bunny-sky cornell-box)

run() {  # run OUT.exr FLAGS...: prints "relMSE render_seconds summary"
  local out=$1; shift
  local summary
  summary=$("$build_dir/candela" render "$scene" $res -o "$out" --stats "$out.json" "$@" 2>&1 | tail -1)
  echo "$("$build_dir/candela_relmse" "$out" "$ref") $(field "$out.json" render_seconds) $summary"
}
meets() { awk -v e="$1" -v g="$goal" 'BEGIN { exit !(e < g) }'; }
spp_mean() { sed -n 's/.*spp mean \([0-9.]*\).*/\1/p' <<<"$1"; }

echo "| scene | target relMSE | uniform: spp, s | threshold: value, mean spp, s | speed-up | --target-error TARGET: mean spp, relMSE, s | --target-error tuned: value, mean spp, s | speed-up |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for name in "${scenes[@]}"; do
  scene=$(scene_file "$name")
  ref=$(reference_file "$name")
  goal=${bench_target[$name]}
  res="--resolution $(grep -o '"resolution": \[[0-9]*, [0-9]*\]' "$(reference_record "$name")" | grep -o '[0-9]\+' | paste -sd x)"
  uniform="> 4096" uniform_s="" uniform_spp=4096
  for k in $(seq 8 48); do
    s=$(awk -v k="$k" 'BEGIN { printf "%d", 2 ^ (k / 4) + 0.5 }')
    read -r e t _ <<<"$(run "$work/u.exr" --spp "$s")"
    echo "bench/adaptive: $name uniform $s spp: relMSE $e, ${t}s" >&2
    if meets "$e"; then uniform="$s" uniform_s=$t uniform_spp=$s; break; fi
  done
  adaptive="not met" adaptive_s=""
  for k in $(seq 0 80); do
    th=$(awk -v k="$k" 'BEGIN { printf "%.4g", 0.5 * 2 ^ (-k / 8) }')
    line=$(run "$work/a.exr" --spp $((4 * uniform_spp)) --noise-threshold "$th" --min-spp "$min_spp")
    read -r e t _ <<<"$line"
    echo "bench/adaptive: $name threshold $th: relMSE $e, ${t}s, $(spp_mean "$line") spp" >&2
    if meets "$e"; then adaptive="$th, $(spp_mean "$line")" adaptive_s=$t; break; fi
  done
  line=$(run "$work/t.exr" --spp $((4 * uniform_spp)) --target-error "$goal")
  read -r e t _ <<<"$line"
  once="$(spp_mean "$line"), $e, $t"
  tuned="not met" tuned_s=""
  for k in $(seq 0 40); do
    te=$(awk -v g="$goal" -v k="$k" 'BEGIN { printf "%.4g", g * 2 ^ (-k / 8) }')
    line=$(run "$work/t.exr" --spp $((4 * uniform_spp)) --target-error "$te")
    read -r e t _ <<<"$line"
    echo "bench/adaptive: $name --target-error $te: relMSE $e, ${t}s, $(spp_mean "$line") spp" >&2
    if meets "$e"; then tuned="$te, $(spp_mean "$line")" tuned_s=$t; break; fi
  done
  ratio() { [ -n "$2" ] && [ -n "$uniform_s" ] && awk -v u="$uniform_s" -v a="$2" 'BEGIN { printf "%.2fx", u / a }' || echo n/a; }
  echo "| $name | $goal | $uniform, $uniform_s | $adaptive, $adaptive_s | $(ratio x "$adaptive_s") | $once | $tuned, $tuned_s | $(ratio x "$tuned_s") |"
done
