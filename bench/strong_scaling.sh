#!/usr/bin/env bash
# Strong scaling of the benchmark suite: the same problems at 1 and 2 OpenMP
# threads (Serial runs once, it does not depend on the thread count).
#
# Usage (from the repository root):
#   bench/strong_scaling.sh [build_dir] [benchmark_filter]
#     build_dir         CMake build directory holding bench/rainslide_bench
#                       (default: build)
#     benchmark_filter  Google Benchmark regex, e.g. 'cells_high:65/' or '^p2g/'
#                       (default: all)
# Environment: BENCH_REPETITIONS (default 5), BENCH_MIN_TIME in s (default 0.5),
#   BENCH_RUN_TAG: run in pieces (e.g. one kernel at a time on a shared
#   machine): each tagged call keeps the raw files of the other tags and the
#   table covers all of them. Without a tag, old raw files are removed first.
# Repetitions are randomly interleaved across benchmarks, so a burst of load
# from other processes spreads over many benchmarks instead of spoiling the
# medians of one; still, run on an otherwise idle machine.
# Writes bench/results/raw_nt{1,2}[_<tag>].json (Google Benchmark output) and
# bench/results/strong_scaling.json, and prints a Markdown table on stdout
# (benchmark progress goes to stderr).
set -euo pipefail

build_dir=${1:-build}
filter=${2:-.}
repetitions=${BENCH_REPETITIONS:-5}
min_time=${BENCH_MIN_TIME:-0.5}

bench_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
binary="$build_dir/bench/rainslide_bench"
if [ ! -x "$binary" ]; then
    echo "error: $binary not found; build it with" >&2
    echo "  cmake --build $build_dir --target rainslide_bench" >&2
    exit 1
fi
python=/usr/bin/python3
[ -x "$python" ] || python=python3
results="$bench_dir/results"
mkdir -p "$results"
tag=${BENCH_RUN_TAG:-}
suffix=${tag:+_$tag}
[ -n "$tag" ] || rm -f "$results"/raw_nt*.json

# Timing settings: one thread per core, threads spread over the cores.
export OMP_PROC_BIND=spread OMP_PLACES=threads

# Benchmark names (one per line) matching a filter, for the given threads.
list_benchmarks() {
    "$binary" --kokkos-threads="$1" --benchmark_list_tests=true \
        --benchmark_filter="$filter" | grep -E '^[a-z0-9_]+/(Serial|OpenMP)/' || true
}

for nt in 1 2; do
    run_filter=$filter
    if [ "$nt" -gt 1 ]; then
        # Only the OpenMP benchmarks, as an exact-name alternation.
        names=$(list_benchmarks "$nt" | grep '/OpenMP/' | paste -sd '|' - || true)
        if [ -z "$names" ]; then
            echo "note: no OpenMP benchmark matches '$filter'; skipping $nt threads" >&2
            continue
        fi
        run_filter="^($names)\$"
    fi
    out="$results/raw_nt$nt$suffix.json"
    echo "== $nt thread(s): $binary --kokkos-threads=$nt (filter '$filter')" >&2
    "$binary" --kokkos-threads="$nt" \
        --benchmark_filter="$run_filter" \
        --benchmark_repetitions="$repetitions" \
        --benchmark_report_aggregates_only=true \
        --benchmark_enable_random_interleaving=true \
        --benchmark_min_time="$min_time" \
        --benchmark_out="$out" --benchmark_out_format=json >&2
done

shopt -s nullglob
raw_files=("$results"/raw_nt*.json)
if [ ${#raw_files[@]} -eq 0 ]; then
    echo "error: no benchmark matched '$filter'" >&2
    exit 1
fi
"$python" "$bench_dir/strong_scaling_report.py" \
    --output "$results/strong_scaling.json" \
    --repetitions "$repetitions" --min-time "$min_time" --filter "$filter" \
    "${raw_files[@]}"
