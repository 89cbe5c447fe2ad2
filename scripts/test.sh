#!/usr/bin/env bash
# Bootstraps, builds everything (Release) and runs the whole test suite:
# unit and regression tests on Serial and on OpenMP with 1 and 2 threads,
# CLI and bad-input tests, the format check and a benchmark smoke run.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

bootstrap
BUILD_DIR="${RAINSLIDE_TEST_BUILD_DIR:-$RAINSLIDE_ROOT/build/test}"
mkdir -p "$(dirname "$BUILD_DIR")"
configure_build "$BUILD_DIR" -DRAINSLIDE_ENABLE_TESTS=ON -DRAINSLIDE_ENABLE_BENCH=ON
echo "[test] building in $BUILD_DIR" >&2
cmake --build "$BUILD_DIR" -j"$(nproc)" >"$BUILD_DIR.build.log" 2>&1 ||
    { tail -n 80 "$BUILD_DIR.build.log" >&2; exit 1; }
cd "$BUILD_DIR"
exec ctest --output-on-failure --timeout 1500 "$@"
