#!/usr/bin/env bash
# Factor of safety against time through a case's last stage (the rainfall of
# the slope cases), with the wetting front: `rainslide fos --every-s`, then
# scripts/fos_history.py (fos_history.png, fos_history.md).
#   scripts/fos_history.sh CASE [rainslide fos options...]
#   e.g. scripts/fos_history.sh cases/slope_base.toml --every-s 5 \
#        --set grid.cell_size_m=1.0 --set 'grid.cells=[72,21]'
# Default: a search every 2.5 s into results/<case file name>_fos_history.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

if [ $# -lt 1 ]; then
    echo "usage: scripts/fos_history.sh CASE [rainslide fos options...]" >&2
    exit 2
fi
case_file=$1
shift
[ -f "$case_file" ] || { echo "fos_history: error: case file '$case_file' not found" >&2; exit 2; }
out="$RAINSLIDE_ROOT/results/$(basename "$case_file" .toml)_fos_history"
every=(--every-s 2.5)
for arg in "$@"; do
    [ "$arg" = "--every-s" ] && every=()
    [ "$arg" = "--out" ] && out=""
done
bootstrap
build_release
out_args=()
if [ -n "$out" ]; then out_args=(--out "$out"); fi
"$RAINSLIDE_BIN" fos "$case_file" "${every[@]}" "${out_args[@]}" "$@"
if [ -z "$out" ]; then
    # --out given: the folder is the argument after it.
    prev=""
    for arg in "$@"; do [ "$prev" = "--out" ] && out=$arg; prev=$arg; done
fi
"$PYTHON" "$RAINSLIDE_ROOT/scripts/fos_history.py" "$out"
