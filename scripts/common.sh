# Shared by scripts/run.sh, test.sh, slope_study.sh and fos_history.sh: bootstrap and configure.
# Usage: source scripts/common.sh; configure_build BUILD_DIR [cmake args...]
set -euo pipefail
RAINSLIDE_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# Installs the dependencies (idempotent) and sets KOKKOS_PREFIX.
bootstrap() {
    KOKKOS_PREFIX=$("$RAINSLIDE_ROOT/scripts/bootstrap.sh" | tail -n 1)
    export KOKKOS_PREFIX
}

# configure_build BUILD_DIR [extra cmake arguments]
configure_build() {
    local build_dir=$1
    shift
    cmake -S "$RAINSLIDE_ROOT" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_PREFIX_PATH="$KOKKOS_PREFIX" "$@" >"$build_dir.configure.log" 2>&1 ||
        { cat "$build_dir.configure.log" >&2; exit 1; }
}

# Builds the Release rainslide CLI (OpenMP default backend) into
# RAINSLIDE_BUILD_DIR (default build/release) and sets RAINSLIDE_BIN.
build_release() {
    BUILD_DIR="${RAINSLIDE_BUILD_DIR:-$RAINSLIDE_ROOT/build/release}"
    mkdir -p "$(dirname "$BUILD_DIR")"
    configure_build "$BUILD_DIR" -DRAINSLIDE_BACKEND=OpenMP \
        -DRAINSLIDE_ENABLE_TESTS=OFF -DRAINSLIDE_ENABLE_BENCH=OFF
    cmake --build "$BUILD_DIR" -j"$(nproc)" --target rainslide >"$BUILD_DIR.build.log" 2>&1 ||
        { tail -n 60 "$BUILD_DIR.build.log" >&2; exit 1; }
    RAINSLIDE_BIN="$BUILD_DIR/rainslide"
    export OMP_PROC_BIND="${OMP_PROC_BIND:-spread}" OMP_PLACES="${OMP_PLACES:-threads}"
}

# Debian's Python (h5py, numpy, matplotlib from the bootstrap's packages).
PYTHON=/usr/bin/python3
