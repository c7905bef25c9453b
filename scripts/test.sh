#!/usr/bin/env bash
# Builds candela and its tests, then runs every test with ctest. Extra arguments go to ctest
# (e.g. -L unit, -R Sphere).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" "$@"
