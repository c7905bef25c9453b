#!/usr/bin/env bash
# Configures and builds candela (Release) into build/. Extra arguments are build targets
# (default: everything, tests included). Warnings are errors when CI is set (below). BUILD_DIR picks
# another build folder (default build/); CMAKE_ARGS adds configure options.
set -euo pipefail
cd "$(dirname "$0")/.."
# CI: warnings are errors, and the test executables compile in unity batches (CMakeLists.txt,
# CANDELA_UNITY_BUILD), which halves their cold compile; an edit then recompiles its whole batch.
werror=OFF
unity=OFF
[ -n "${CI:-}" ] && werror=ON && unity=ON
build_dir="${BUILD_DIR:-build}"
# shellcheck disable=SC2086 # CMAKE_ARGS is a list of options
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCANDELA_WERROR="$werror" -DCANDELA_UNITY_BUILD="$unity" ${CMAKE_ARGS:-} >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build "$build_dir" -j "$(nproc)" "${targets[@]}"
