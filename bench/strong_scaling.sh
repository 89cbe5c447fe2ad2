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
#   BENCH_THREADS: OpenMP thread counts to run (default "1 2"; Serial runs
#   with 1).
# Each repetition is one process per thread count (benchmarks in random order
# within it); the table gives the median over the repetitions. Run on an
# otherwise idle machine: a second busy process on 2 cores ruins the 2-thread
# numbers.
# Writes bench/results/raw_nt<N>[_<tag>]_r<rep>.json (Google Benchmark output),
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
if [ -n "$tag" ]; then
    for nt in ${BENCH_THREADS:-1 2}; do
        rm -f "$results"/raw_nt"$nt"_"$tag"_r*.json
    done
else
    rm -f "$results"/raw_nt*.json
fi

# Timing settings: one thread per core, threads spread over the cores.
export OMP_PROC_BIND=spread OMP_PLACES=threads

# Names (one per line) of the kernel benchmarks, <kernel>/<backend>/<scatter>/
# ..., that match the filter (other benchmarks in the binary are skipped).
list_benchmarks() {
    "$binary" --kokkos-threads="$1" --benchmark_list_tests=true \
        --benchmark_filter="$filter" | grep -E '^[a-z0-9_]+/(Serial|OpenMP)/' || true
}

# Repetitions are separate processes alternating between the thread counts
# (1, 2, 1, 2, ...), so a drift of the (virtual) machine's speed hits both
# columns alike; the report takes the median over the processes.
for rep in $(seq 1 "$repetitions"); do
    for nt in ${BENCH_THREADS:-1 2}; do
        # Serial once (with 1 thread), OpenMP at every thread count.
        backends='/(Serial|OpenMP)/'
        [ "$nt" -gt 1 ] && backends='/OpenMP/'
        names=$(list_benchmarks "$nt" | grep -E "$backends" | paste -sd '|' - || true)
        if [ -z "$names" ]; then
            echo "note: no benchmark matches '$filter' at $nt thread(s)" >&2
            continue
        fi
        # Exact-name alternation.
        run_filter="^($names)\$"
        out="$results/raw_nt$nt${suffix}_r$rep.json"
        echo "== repetition $rep/$repetitions, $nt thread(s) (filter '$filter')" >&2
        "$binary" --kokkos-threads="$nt" \
            --benchmark_filter="$run_filter" \
            --benchmark_enable_random_interleaving=true \
            --benchmark_min_time="$min_time" \
            --benchmark_out="$out" --benchmark_out_format=json >&2
    done
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
