#!/usr/bin/env bash
# Our explicit two-phase step against the stand-in step of
# ../shared/bench/standin_two_phase_step.cpp (the speed yardstick), in the
# same run: nanoseconds per material-point step of each, and their ratio,
# at 1 and 2 OpenMP threads (and Serial), at three sizes:
#   slope  the base slope case's rainfall stage (4,698 points) against the
#          stand-in's slope-shaped body at refine 1 (~3.9k points);
#   34k    the unsaturated soil block (33,800 points) against refine 3.1623;
#   340k   the unsaturated soil block (339,488 points) against refine 10.
# Each pair runs back to back, BENCH_REPETITIONS times (default 3); the
# table gives medians. Run on an otherwise idle machine.
#
# Usage (from the repository root):
#   bench/standin_ratio.sh [build_dir] [sizes]
#     build_dir  CMake build directory holding bench/rainslide_bench
#                (default: build/test)
#     sizes      any of "slope 34k 340k" (default: all three)
# Environment: STANDIN_SOURCE (default ../shared/bench/standin_two_phase_step.cpp
#   beside the repository), BENCH_MIN_TIME (s, default 1).
# Writes bench/results/standin_ratio.json and prints a Markdown table.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${1:-$root/build/test}
sizes=${2:-slope 34k 340k}
repetitions=${BENCH_REPETITIONS:-3}
min_time=${BENCH_MIN_TIME:-1}
source_file=${STANDIN_SOURCE:-$root/../shared/bench/standin_two_phase_step.cpp}
binary="$build_dir/bench/rainslide_bench"
python=/usr/bin/python3

[ -x "$binary" ] || { echo "error: $binary not found (build rainslide_bench)" >&2; exit 1; }
[ -f "$source_file" ] || { echo "error: stand-in source $source_file not found" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The stand-in as its README builds it: one grid copy per thread (MODE=2).
g++ -O3 -march=native -fopenmp -DMODE=2 "$source_file" -o "$work/standin"

export OMP_PROC_BIND=spread OMP_PLACES=threads
declare -A refine=([slope]=1 [34k]=3.1623 [340k]=10)
declare -A steps=([slope]=4000 [34k]=400 [340k]=40)
declare -A ours=([slope]='run_slope_unsaturated/BACKEND/'
    [34k]='run_step_unsaturated/BACKEND/[a-z]+/cells_high:65/'
    [340k]='run_step_unsaturated/BACKEND/[a-z]+/cells_high:206/')

rows="$work/rows.tsv"
: >"$rows"
for rep in $(seq "$repetitions"); do
    for size in $sizes; do
        for threads in 1 2; do
            standin_ns=$(OMP_NUM_THREADS=$threads "$work/standin" "${refine[$size]}" \
                "${steps[$size]}" 1 | sed -n 's/.* \([0-9.]*\) ns\/MP-step.*/\1/p')
            backends="OpenMP"
            [ "$threads" = 1 ] && backends="Serial OpenMP"
            for backend in $backends; do
                filter=${ours[$size]/BACKEND/$backend}
                "$binary" --kokkos-threads="$threads" --benchmark_filter="$filter" \
                    --benchmark_min_time="$min_time" --benchmark_format=json \
                    >"$work/ours.json" 2>/dev/null
                ours_ns=$("$python" -c 'import json,sys
b=json.load(open(sys.argv[1]))["benchmarks"]
print(1e9/b[0]["items_per_second"] if b else "nan")' "$work/ours.json")
                printf '%s\t%s\t%s\t%s\t%s\n' "$size" "$backend" "$threads" \
                    "$standin_ns" "$ours_ns" >>"$rows"
            done
        done
    done
done

"$python" - "$rows" "$root/bench/results/standin_ratio.json" <<'EOF'
import json, statistics, sys
rows = [l.split("\t") for l in open(sys.argv[1]).read().splitlines()]
groups = {}
for size, backend, threads, standin, ours in rows:
    groups.setdefault((size, backend, int(threads)), []).append((float(standin), float(ours)))
out = []
print("| size | backend | threads | stand-in ns/MP-step | ours ns/MP-step | ours / stand-in |")
print("|---|---|--:|--:|--:|--:|")
for (size, backend, threads), pairs in groups.items():
    standin = statistics.median(p[0] for p in pairs)
    ours = statistics.median(p[1] for p in pairs)
    ratio = statistics.median(p[1] / p[0] for p in pairs)
    out.append(dict(size=size, backend=backend, threads=threads, standin_ns=standin,
                    ours_ns=ours, ratio=ratio, repetitions=len(pairs)))
    print(f"| {size} | {backend} | {threads} | {standin:.0f} | {ours:.0f} | {ratio:.2f} |")
json.dump(out, open(sys.argv[2], "w"), indent=1)
EOF
