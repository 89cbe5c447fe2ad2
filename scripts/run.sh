#!/usr/bin/env bash
# Bootstraps, builds rainslide (Release, OpenMP) and runs it.
#   scripts/run.sh                       runs the default case
#   scripts/run.sh run cases/X.toml ...  passes the arguments to the rainslide CLI
#   scripts/run.sh check cases/X.toml
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

bootstrap
BUILD_DIR="${RAINSLIDE_BUILD_DIR:-$RAINSLIDE_ROOT/build/release}"
mkdir -p "$(dirname "$BUILD_DIR")"
configure_build "$BUILD_DIR" -DRAINSLIDE_BACKEND=OpenMP \
    -DRAINSLIDE_ENABLE_TESTS=OFF -DRAINSLIDE_ENABLE_BENCH=OFF
cmake --build "$BUILD_DIR" -j"$(nproc)" --target rainslide >"$BUILD_DIR.build.log" 2>&1 ||
    { tail -n 60 "$BUILD_DIR.build.log" >&2; exit 1; }

if [ $# -eq 0 ]; then
    set -- run "cases/dry_slope.toml"
fi
export OMP_PROC_BIND="${OMP_PROC_BIND:-spread}" OMP_PLACES="${OMP_PLACES:-threads}"
cd "$RAINSLIDE_ROOT"
exec "$BUILD_DIR/rainslide" "$@"
