#!/usr/bin/env bash
# Time per kernel of one benchmark of rainslide_bench (bench/kernel_timer.cpp
# loaded as a Kokkos Tools library): a Markdown table of each kernel's share,
# time per call and calls, on standard error.
#
# Usage (from the repository root):
#   bench/kernel_profile.sh [build_dir] [filter] [threads]
#     build_dir  CMake build directory holding bench/rainslide_bench
#                (default: build/test)
#     filter     --benchmark_filter (default: the slope's rainfall step on
#                Serial, run_slope_unsaturated/Serial/)
#     threads    --kokkos-threads (default 1)
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${1:-$root/build/test}
filter=${2:-run_slope_unsaturated/Serial/}
threads=${3:-1}
binary="$build_dir/bench/rainslide_bench"
[ -x "$binary" ] || { echo "error: $binary not found (build rainslide_bench)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
g++ -O2 -shared -fPIC "$root/bench/kernel_timer.cpp" -o "$work/libkernel_timer.so"
KOKKOS_PROFILE_LIBRARY="$work/libkernel_timer.so" "$binary" \
    --kokkos-threads="$threads" --benchmark_filter="$filter" \
    --benchmark_min_time="${BENCH_MIN_TIME:-2}" 2>&1 >/dev/null |
    sed -n '/^kernel time/,$p' >&2
