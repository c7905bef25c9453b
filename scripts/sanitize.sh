#!/usr/bin/env bash
# Builds the whole test suite with clang, AddressSanitizer (with LeakSanitizer) and
# UndefinedBehaviorSanitizer (scripts/build-sanitize.sh, into build-sanitize/; BUILD_DIR picks
# another folder) and runs it with ctest; extra arguments go to ctest (e.g. -L unit, -R Exr).
# A sanitizer report ends the test that triggered it with a failure. The same build holds the
# fuzz targets, whose regression inputs (fuzz/regressions/) run here as ctest tests too.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
export BUILD_DIR="${BUILD_DIR:-build-sanitize}"
scripts/build-sanitize.sh
# Static initialisation order problems are reported too; UB reports carry a stack trace.
export ASAN_OPTIONS="check_initialization_order=1:strict_init_order=1:detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)" "$@"
