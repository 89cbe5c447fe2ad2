#!/usr/bin/env bash
# Installs everything rainslide needs on a fresh Debian 12 machine:
#   - Debian packages (compiler tools, Eigen, HDF5, GoogleTest, Google Benchmark,
#     toml++, CLI11, nlohmann-json, Python plotting);
#   - Kokkos 3.4.01 with Serial + OpenMP, built from the Debian *source* package
#     `trilinos` into a cache prefix outside the source tree.
# Idempotent: a second run checks and returns in seconds.
# Prints the Kokkos prefix on its last line of stdout (for scripts that need it).
set -euo pipefail
if [ $# -gt 0 ]; then
    echo "usage: scripts/bootstrap.sh   (no arguments; RAINSLIDE_CACHE sets the Kokkos cache folder)" >&2
    exit 2
fi

KOKKOS_VERSION=3.4.01
CACHE_DIR="${RAINSLIDE_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/rainslide}"
KOKKOS_PREFIX="$CACHE_DIR/kokkos-$KOKKOS_VERSION-serial-openmp"

log() { echo "[bootstrap] $*" >&2; }
source "$(dirname "${BASH_SOURCE[0]}")/apt_packages.sh"

# --- 1. Debian packages -----------------------------------------------------
PACKAGES=(
    build-essential cmake clang-format ca-certificates
    libeigen3-dev libhdf5-dev libgtest-dev libbenchmark-dev
    libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
    python3 python3-numpy python3-matplotlib python3-h5py
)
install_debian_packages "Debian packages" "${PACKAGES[@]}"

# --- 2. Kokkos 3.4.01 (Serial + OpenMP) from the trilinos source package ------
if [ -f "$KOKKOS_PREFIX/lib/cmake/Kokkos/KokkosConfig.cmake" ] ||
    [ -f "$KOKKOS_PREFIX/lib64/cmake/Kokkos/KokkosConfig.cmake" ]; then
    log "Kokkos $KOKKOS_VERSION found in $KOKKOS_PREFIX"
    echo "$KOKKOS_PREFIX"
    exit 0
fi

SRC_CACHE="$CACHE_DIR/src"
mkdir -p "$SRC_CACHE"
orig=$(ls "$SRC_CACHE"/trilinos_*.orig.tar.* 2>/dev/null | head -n 1 || true)
if [ -z "$orig" ]; then
    log "downloading the Debian source package 'trilinos' (about 166 MB)"
    # A private apt configuration: the machine's own sources, switched to deb-src.
    # Nothing system-wide changes and no archive host name is written anywhere.
    APT_DIR="$CACHE_DIR/apt-src"
    rm -rf "$APT_DIR"
    mkdir -p "$APT_DIR/sources.list.d" "$APT_DIR/lists/partial"
    found_sources=0
    for f in /etc/apt/sources.list.d/*.sources; do
        [ -f "$f" ] || continue
        sed 's/^Types:.*/Types: deb-src/' "$f" >"$APT_DIR/sources.list.d/$(basename "$f")"
        found_sources=1
    done
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
        [ -f "$f" ] || continue
        grep -E '^\s*deb\s' "$f" | sed -E 's/^\s*deb\s/deb-src /' \
            >>"$APT_DIR/sources.list.d/from-list.list" || true
        found_sources=1
    done
    if [ "$found_sources" = 0 ]; then
        log "error: no apt sources found in /etc/apt; cannot locate the 'trilinos' source package"
        exit 1
    fi
    APT_OPTS=(-o Dir::Etc::SourceList=/dev/null -o "Dir::Etc::SourceParts=$APT_DIR/sources.list.d"
        -o "Dir::State::Lists=$APT_DIR/lists")
    apt-get "${APT_OPTS[@]}" update -qq >&2
    dl_dir=$(mktemp -d "$SRC_CACHE/dl.XXXXXX")
    (cd "$dl_dir" && apt-get "${APT_OPTS[@]}" source --download-only -qq trilinos >&2)
    dsc=$(ls "$dl_dir"/trilinos_*.dsc | head -n 1)
    tarball=$(ls "$dl_dir"/trilinos_*.orig.tar.* | head -n 1)
    # Verify the tarball against the SHA-256 listed in the .dsc.
    expected=$(awk '/^Checksums-Sha256:/{f=1;next} /^[^ ]/{f=0} f' "$dsc" |
        awk -v n="$(basename "$tarball")" '$3==n{print $1}')
    actual=$(sha256sum "$tarball" | awk '{print $1}')
    if [ -z "$expected" ] || [ "$expected" != "$actual" ]; then
        log "error: SHA-256 of $(basename "$tarball") is $actual, the .dsc lists '$expected'"
        exit 1
    fi
    log "checksum ok ($actual)"
    mv "$tarball" "$SRC_CACHE/"
    cp "$dsc" "$SRC_CACHE/"
    rm -rf "$dl_dir"
    orig=$(ls "$SRC_CACHE"/trilinos_*.orig.tar.* | head -n 1)
fi

log "building Kokkos $KOKKOS_VERSION (Serial + OpenMP) into $KOKKOS_PREFIX"
work=$(mktemp -d "$CACHE_DIR/kokkos-build.XXXXXX")
# Extract only the Kokkos folder of the Trilinos source tree.
tar xzf "$orig" -C "$work" --wildcards --no-wildcards-match-slash '*/packages/kokkos'
src=$(echo "$work"/*/packages/kokkos)
cmake -S "$src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_INSTALL_PREFIX="$KOKKOS_PREFIX.tmp" \
    -DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_OPENMP=ON \
    -DCMAKE_CXX_STANDARD=17 -DKokkos_ENABLE_TESTS=OFF \
    -DKokkos_ENABLE_COMPILER_WARNINGS=OFF >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log" >&2; exit 1; }
cmake --build "$work/build" -j"$(nproc)" --target install >"$work/build.log" 2>&1 ||
    { tail -n 50 "$work/build.log" >&2; exit 1; }
# Install into a temporary prefix and rename, so an interrupted build never
# leaves a half-installed Kokkos that a later run would take as complete.
rm -rf "$KOKKOS_PREFIX"
mv "$KOKKOS_PREFIX.tmp" "$KOKKOS_PREFIX"
rm -rf "$work" "$CACHE_DIR"/kokkos-build.*
log "Kokkos installed in $KOKKOS_PREFIX"
echo "$KOKKOS_PREFIX"
