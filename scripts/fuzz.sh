#!/usr/bin/env bash
# Fuzzes the case reader and `rainslide check` (mpm::checkCase) with libFuzzer
# under AddressSanitizer and UndefinedBehaviorSanitizer for MINUTES (default 10):
#   scripts/fuzz.sh [MINUTES]
# Installs clang and libFuzzer (Debian packages clang, libclang-rt-14-dev) if
# missing, builds tests/fuzz/fuzz_case_check into build/fuzz (clang, no Kokkos),
# seeds a run-time corpus (build/fuzz/corpus) with every case file of the
# repository and tests/fuzz/corpus/, and fuzzes with one job; crashes, timeouts
# and out-of-memory inputs go to build/fuzz/findings/. Prints the executions,
# the coverage and each finding with the first lines of its report, and exits
# 1 if there is a finding. Not part of scripts/test.sh (minutes, not seconds);
# the inputs of tests/fuzz/corpus/ are replayed there (FuzzCorpus.*).
# Environment: RAINSLIDE_FUZZ_BUILD_DIR (default build/fuzz).
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
MINUTES=${1:-10}
if ! [[ "$MINUTES" =~ ^[0-9]+$ ]] || [ "$MINUTES" -lt 1 ]; then
    echo "usage: scripts/fuzz.sh [MINUTES]   (a whole number >= 1, default 10)" >&2
    exit 2
fi
BUILD_DIR="${RAINSLIDE_FUZZ_BUILD_DIR:-$ROOT/build/fuzz}"
log() { echo "[fuzz] $*" >&2; }

# --- 1. clang and libFuzzer (idempotent) --------------------------------------
source "$ROOT/scripts/apt_packages.sh"
install_debian_packages "clang and libFuzzer" clang libclang-rt-14-dev cmake
if ! dpkg-query -W -f='${Status}' libtomlplusplus-dev 2>/dev/null | grep -q "install ok installed"; then
    "$ROOT/scripts/bootstrap.sh" >/dev/null # toml++ and the rest of the project's packages
fi

# --- 2. build (its own folder, clang, no Kokkos) -------------------------------
mkdir -p "$BUILD_DIR"
cmake -S "$ROOT" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ -DRAINSLIDE_ENABLE_FUZZ=ON >"$BUILD_DIR/configure.log" 2>&1 ||
    { cat "$BUILD_DIR/configure.log" >&2; exit 1; }
log "building fuzz_case_check in $BUILD_DIR"
cmake --build "$BUILD_DIR" -j2 --target fuzz_case_check >"$BUILD_DIR/build.log" 2>&1 ||
    { tail -n 60 "$BUILD_DIR/build.log" >&2; exit 1; }
FUZZER="$BUILD_DIR/tests/fuzz/fuzz_case_check"
# The run uses a copy: a rebuild during the run changes neither its jobs
# (fork mode starts the binary anew for each) nor the replay of its findings.
RUN_FUZZER="$BUILD_DIR/fuzz_case_check.run"
cp "$FUZZER" "$RUN_FUZZER"

# --- 3. corpus, findings ------------------------------------------------------
CORPUS="$BUILD_DIR/corpus"   # kept between runs: each run starts where the last ended
FINDINGS="$BUILD_DIR/findings"
SCRATCH="$BUILD_DIR/tmp"     # TMPDIR of the fuzzer: its case folders
mkdir -p "$CORPUS"
if [ -d "$FINDINGS" ] && [ -n "$(ls -A "$FINDINGS")" ]; then
    rm -rf "$FINDINGS.previous"
    mv "$FINDINGS" "$FINDINGS.previous"
    log "findings of the previous run moved to $FINDINGS.previous"
fi
rm -rf "$FINDINGS" "$SCRATCH"
mkdir -p "$FINDINGS" "$SCRATCH"
seeds=0
for f in "$ROOT"/cases/*.toml "$ROOT"/cases/shared/*.toml "$ROOT"/tests/data/*.toml \
    "$ROOT"/tests/data/bad_cases/*.toml "$ROOT"/tests/fuzz/corpus/*.toml; do
    [ -f "$f" ] || continue
    # Named by content (as libFuzzer names its inputs): no duplicates.
    cp "$f" "$CORPUS/$(sha1sum "$f" | cut -c1-40)"
    seeds=$((seeds + 1))
done
log "seeded $CORPUS with $seeds case files ($(ls "$CORPUS" | wc -l) inputs in the corpus)"

# --- 4. fuzz ------------------------------------------------------------------
LOG="$BUILD_DIR/fuzz.log"
OPTIONS=(-max_total_time=$((MINUTES * 60)) -timeout=10 -rss_limit_mb=2048 -max_len=65536
    -dict="$ROOT/tests/fuzz/case.dict" -artifact_prefix="$FINDINGS/" -print_final_stats=1)
log "fuzzing for $MINUTES min (log: $LOG)"
# -fork=1: one job, restarted after a finding, so the run goes on to its end.
# UBSan reports abort (-fno-sanitize-recover) and print their stack.
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
export ASAN_OPTIONS="detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
status=0
(cd "$BUILD_DIR" && TMPDIR="$SCRATCH" "$RUN_FUZZER" "${OPTIONS[@]}" -fork=1 -ignore_crashes=1 \
    -ignore_timeouts=1 -ignore_ooms=1 "$CORPUS") >"$LOG" 2>&1 || status=$?
rm -rf "$SCRATCH"

# --- 5. summary ---------------------------------------------------------------
# Fork mode prints "#RUNS: cov: C ft: F corp: N exec/s: E oom/timeout/crash: a/b/c time: Ts".
last=$(grep -E '^#[0-9]+: cov: ' "$LOG" | tail -n 1 || true)
if [ -n "$last" ]; then
    execs=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last")
    cov=$(sed -E 's/.* cov: ([0-9]+).*/\1/' <<<"$last")
    ft=$(sed -E 's/.* ft: ([0-9]+).*/\1/' <<<"$last")
    corp=$(sed -E 's/.* corp: ([0-9]+).*/\1/' <<<"$last")
    secs=$(sed -E 's/.* time: ([0-9]+)s.*/\1/' <<<"$last")
    echo "executions: $execs in ${secs}s ($((execs / (secs > 0 ? secs : 1))) exec/s)"
    echo "coverage: cov $cov, ft $ft, corpus $corp inputs ($CORPUS)"
else
    echo "no statistics in $LOG (exit status $status):"
    tail -n 30 "$LOG"
fi
findings=()
for f in "$FINDINGS"/*; do
    [ -f "$f" ] && findings+=("$f")
done
echo "findings: ${#findings[@]} (in $FINDINGS)"
for f in "${findings[@]}"; do
    echo "--- $(basename "$f") ($(stat -c %s "$f") bytes)"
    # Replay it with the binary of the run: the error line and the first
    # frames of the report outside libFuzzer, the sanitizers and libc.
    mkdir -p "$SCRATCH"
    report=$(cd "$BUILD_DIR" && TMPDIR="$SCRATCH" timeout 60 "$RUN_FUZZER" -timeout=10 \
        -rss_limit_mb=2048 "$f" 2>&1 || true)
    rm -rf "$SCRATCH"
    summary=$(grep -E 'Assertion|runtime error|ERROR: |escaped|ALARM|out-of-memory|[Tt]imeout' <<<"$report" |
        grep -v -E 'ERROR: libFuzzer: deadly signal' | head -n 3 || true)
    frames=$(grep -E '^ +#[0-9]+ ' <<<"$report" |
        grep -v -E '__sanitizer|fuzzer::|libc\.so|nptl/|stdlib/|assert/|signal/|__libc_|_start|__asan|__ubsan|in main ' |
        head -n 6 | sed -E 's/^ +#[0-9]+ 0x[0-9a-f]+ in /    /' | cut -c1-200 || true)
    if [ -z "$summary$frames" ]; then
        echo "    (no report on replay)"
    else
        [ -n "$summary" ] && echo "$summary" | cut -c1-300
        [ -n "$frames" ] && echo "$frames"
    fi
done
if [ "${#findings[@]}" -gt 0 ]; then
    exit 1
fi
if [ -z "$last" ]; then
    exit 1
fi
exit 0
