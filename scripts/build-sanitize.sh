#!/usr/bin/env bash
# Configures and builds the clang build that the sanitizer tests and the fuzzers share
# (cmake/sanitizers.cmake: ASan + UBSan everywhere, libFuzzer instrumentation, the fuzz/ targets)
# into build-sanitize/ (BUILD_DIR picks another folder) through scripts/build.sh, so CI and
# CMAKE_ARGS work as there. Extra arguments are build targets (default: everything).
#
# Debug, so that CANDELA_DCHECK and assert() are on; the optimisation level is sanitizers.cmake's
# -O1. Warnings are shown but are not errors, even in CI: the GCC build (scripts/build.sh) is the
# warnings gate. clang 14 reads the same flags differently (its -Wdouble-promotion also flags
# every exact float-to-double initialisation, some twenty in the tests; its -Wshadow also flags
# lambda parameters named like a field), and a second definition of the same warnings would turn
# this job, whose point is what the sanitizers find at run time, into a compile failure.
set -euo pipefail
cd "$(dirname "$0")/.."
clangxx="$(command -v clang++)" || { echo "build-sanitize: clang++ not found (scripts/install-deps.sh installs it)" >&2; exit 1; }
export BUILD_DIR="${BUILD_DIR:-build-sanitize}"
export CMAKE_ARGS="-DCMAKE_CXX_COMPILER=$clangxx -DCMAKE_BUILD_TYPE=Debug -DCANDELA_SANITIZE=ON -DCANDELA_FUZZ=ON -DCANDELA_WERROR=OFF ${CMAKE_ARGS:-}"
exec scripts/build.sh "$@"
