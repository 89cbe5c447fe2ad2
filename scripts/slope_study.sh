#!/usr/bin/env bash
# The whole slope study (docs/slope-study.md): runs every slope case into
# results/<case>/, draws each case's figures and the summary across cases
# (results/slope_summary.png and the table results/slope_summary.md).
#   scripts/slope_study.sh             all cases (the refined base case last;
#                                      slope_base_paper_dt, the paper's time
#                                      step, only when named in SLOPE_CASES)
#   SLOPE_CASES="slope_base slope_phi30" scripts/slope_study.sh
# Extra arguments go to every `rainslide run` (e.g. --threads 2).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

cases=${SLOPE_CASES:-"slope_total_stress slope_base slope_base_sudden slope_phi15 slope_phi30 slope_cr001 slope_cr5 slope_rain_surface slope_base_fine"}
for case in $cases; do
    [ -f "$RAINSLIDE_ROOT/cases/$case.toml" ] ||
        { echo "slope_study: error: no case file cases/$case.toml (SLOPE_CASES names cases/<name>.toml)" >&2; exit 2; }
done
bootstrap
build_release
cd "$RAINSLIDE_ROOT"
dirs=()
for case in $cases; do
    echo "== $case" >&2
    "$RAINSLIDE_BIN" run "cases/$case.toml" --out "results/$case" --quiet "$@"
    times=()
    [ "$case" = slope_total_stress ] && times=(--times 0.5,2.0)
    "$PYTHON" scripts/slope_figures.py "results/$case" "${times[@]}"
    dirs+=("results/$case")
done
"$PYTHON" scripts/slope_summary.py "${dirs[@]}" --out results/slope_summary.png \
    --table results/slope_summary.md
echo "summary: results/slope_summary.png, results/slope_summary.md" >&2
