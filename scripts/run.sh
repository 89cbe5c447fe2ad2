#!/usr/bin/env bash
# Bootstraps, builds rainslide (Release, OpenMP) and runs it.
#   scripts/run.sh                       runs the default case, a rainfall-
#                                        induced collapse of the paper's slope
#                                        (cases/slope_collapse.toml), prints
#                                        its verdict and draws its figures
#   scripts/run.sh run cases/X.toml ...  passes the arguments to the rainslide CLI
#   scripts/run.sh check cases/X.toml
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

bootstrap
build_release
cd "$RAINSLIDE_ROOT"
if [ $# -gt 0 ]; then
    exec "$RAINSLIDE_BIN" "$@"
fi
"$RAINSLIDE_BIN" run cases/slope_collapse.toml --out results/slope_collapse
"$PYTHON" scripts/slope_figures.py results/slope_collapse
echo "figures: results/slope_collapse/figures/"
