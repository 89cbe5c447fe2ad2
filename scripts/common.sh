# Shared by scripts/run.sh and scripts/test.sh: bootstrap and configure.
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
