#!/usr/bin/env bash
# Bootstraps, builds rainslide (Release, OpenMP) and runs it.
#   scripts/run.sh                       runs the default case, the slope
#                                        study's base case, and draws its figures
#   scripts/run.sh run cases/X.toml ...  passes the arguments to the rainslide CLI
#   scripts/run.sh check cases/X.toml
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

bootstrap
build_release
cd "$RAINSLIDE_ROOT"
if [ $# -gt 0 ]; then
    exec "$RAINSLIDE_BIN" "$@"
fi
"$RAINSLIDE_BIN" run cases/slope_base.toml --out results/slope_base
"$PYTHON" scripts/slope_figures.py results/slope_base
echo "figures: results/slope_base/figures/"
