#!/usr/bin/python3
"""Compare a Liakopoulos run with the OpenGeoSys reference (verification.md §1).

Usage: liakopoulos.py RESULTS_DIR [--reference DIR] [--stage drainage]
Reads RESULTS_DIR/particles.h5, writes the comparison into the "verification"
section of RESULTS_DIR/metrics.json (atomically) and prints a table.

Metrics per reference time (5, 10, 20, 40, 80, 120 min):
  max_error_pa    max over material points of |p_w - p_ref(y0)|, with p_ref the
                  reference profile interpolated at the point's initial height;
  relative_error  max_error_pa / |p_ref(top)| (the issue's tolerance: 5 %);
  outflow_m_per_s Darcy flux n S (v_w - v_s) out of the bottom, from the points
                  of the bottom cell, against the reference (tolerance 10 %);
  settlement_m    top settlement against the reference u_y(top).
Errors in the input give one line "liakopoulos: error: ..." and exit code 2.
"""
import argparse
import csv
import json
import os
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_REFERENCE = os.path.normpath(os.path.join(HERE, "..", "..", "tests", "data", "reference"))
TIMES_MIN = [5, 10, 20, 40, 80, 120]
REFERENCE_FILES = ("liakopoulos_pressure_profiles.csv", "liakopoulos_outflow.csv")


def fail(message):
    print(f"liakopoulos: error: {message}", file=sys.stderr)
    sys.exit(2)


def read_reference(folder):
    profiles = {}
    with open(os.path.join(folder, "liakopoulos_pressure_profiles.csv")) as f:
        for row in csv.DictReader(f):
            t = int(row["time_min"])
            profiles.setdefault(t, []).append(
                (float(row["height_m"]), float(row["pw_Pa"]), float(row["uy_m"]) if row["uy_m"] not in ("", "nan") else np.nan))
    outflow = {}
    with open(os.path.join(folder, "liakopoulos_outflow.csv")) as f:
        for row in csv.DictReader(f):
            outflow[int(row["time_min"])] = float(row["outflow_darcy_flux_m_per_s"])
    return {t: np.array(sorted(v)) for t, v in profiles.items()}, outflow


def snapshot_at(h5, stage, stage_time):
    best, best_dt = None, 1e300
    for key, g in h5["snapshots"].items():
        name = g.attrs["stage"]
        name = name.decode() if isinstance(name, bytes) else str(name)
        if name != stage:
            continue
        dt = abs(g.attrs["stage_time_s"] - stage_time)
        if dt < best_dt:
            best, best_dt = g, dt
    if best is None:
        fail(f"no snapshot of stage '{stage}' (see --stage)")
    if best_dt > 1.0:
        fail(f"no snapshot of stage '{stage}' at {stage_time} s (nearest {best_dt} s away)")
    return best


def compare(results, reference, stage, cell_size):
    profiles, outflow_ref = read_reference(reference)
    out = {}
    with h5py.File(os.path.join(results, "particles.h5"), "r") as h5:
        for t in TIMES_MIN:
            g = snapshot_at(h5, stage, 60.0 * t)
            x = g["x"][:]
            u = g["displacement"][:]
            y0 = x[:, 1] - u[:, 1]
            p = g["pore_pressure"][:]
            ref = profiles[t]
            p_ref = np.interp(y0, ref[:, 0], ref[:, 1])
            top = abs(ref[-1, 1])
            err = np.abs(p - p_ref)
            # Cell means against the reference at the cells' mean height.
            h = cell_size
            cells = np.floor(y0 / h + 1e-9).astype(int)
            cell_err = 0.0
            for c in np.unique(cells):
                sel = cells == c
                cell_err = max(cell_err, abs(p[sel].mean() - np.interp(y0[sel].mean(), ref[:, 0], ref[:, 1])))
            # Darcy flux out of the bottom cell: n S (v_w - v_s), downward positive.
            bottom = y0 < h
            n = g["porosity"][:]
            S = g["saturation"][:]
            q = -(n * S * (g["water_velocity"][:, 1] - g["velocity"][:, 1]))[bottom].mean()
            top_points = y0 > y0.max() - 1e-9 - 0.5 * h
            settlement = -u[top_points, 1].mean()
            ref_u = ref[-1, 2]
            entry = {
                "time_min": t,
                "max_error_pa": float(err.max()),
                "top_suction_ref_pa": float(top),
                "relative_error": float(err.max() / top),
                "cell_max_error_pa": float(cell_err),
                "cell_relative_error": float(cell_err / top),
                "outflow_m_per_s": float(q),
                "outflow_ref_m_per_s": outflow_ref.get(t, float("nan")),
                "outflow_relative_error": float(abs(q - outflow_ref[t]) / outflow_ref[t]) if t in outflow_ref else None,
                "settlement_m": float(settlement),
                "settlement_ref_m": None if np.isnan(ref_u) else float(-ref_u),
            }
            out[str(t)] = entry
    return out


def write_metrics(results, section):
    path = os.path.join(results, "metrics.json")
    try:
        with open(path) as f:
            metrics = json.load(f)
        metrics["verification"] = section
        fd, tmp = tempfile.mkstemp(dir=results, prefix=".metrics.", suffix=".json")
        with os.fdopen(fd, "w") as f:
            json.dump(metrics, f, indent=2)
        os.replace(tmp, path)
    except (OSError, ValueError) as error:
        fail(f"cannot update {path}: {error}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results")
    parser.add_argument("--reference", default=DEFAULT_REFERENCE)
    parser.add_argument("--stage", default="drainage")
    parser.add_argument("--cell-size", type=float, default=None, help="m (default: from metrics.json)")
    args = parser.parse_args()
    if args.cell_size is not None and not args.cell_size > 0.0:
        parser.error(f"--cell-size must be > 0 m, got {args.cell_size:g}")
    if not os.path.isdir(args.results):
        fail(f"{args.results}: results folder not found")
    metrics_path = os.path.join(args.results, "metrics.json")
    try:
        with open(metrics_path) as f:
            metrics = json.load(f)
    except (OSError, ValueError) as error:
        fail(f"cannot read {metrics_path}: {error}")
    cell_size = args.cell_size
    if cell_size is None:
        cell_size = metrics.get("cell_size_m") if isinstance(metrics, dict) else None
        if not isinstance(cell_size, (int, float)) or not cell_size > 0.0:
            fail(f"{metrics_path}: no positive 'cell_size_m' (or pass --cell-size)")
    for name in REFERENCE_FILES:
        if not os.path.isfile(os.path.join(args.reference, name)):
            fail(f"{os.path.join(args.reference, name)}: reference file not found")
    h5_path = os.path.join(args.results, "particles.h5")
    if not os.path.isfile(h5_path):
        fail(f"{h5_path}: file not found")
    try:
        per_time = compare(args.results, args.reference, args.stage, cell_size)
    except (OSError, KeyError, ValueError) as error:
        fail(f"cannot compare {h5_path} with the reference in {args.reference}: {type(error).__name__}: {error}")
    worst = max(e["relative_error"] for e in per_time.values())
    worst_cell = max(e["cell_relative_error"] for e in per_time.values())
    worst_q = max(e["outflow_relative_error"] for e in per_time.values())
    write_metrics(args.results, {"kind": "liakopoulos", "per_time": per_time,
                                 "relative_error_max": worst, "cell_relative_error_max": worst_cell,
                                 "outflow_relative_error_max": worst_q})
    print(f"{'t min':>6} {'max err Pa':>11} {'rel':>7} {'cell rel':>8} {'outflow':>10} {'ref':>10} {'rel':>6} {'settl mm':>9} {'ref mm':>7}")
    for e in per_time.values():
        ref_s = e["settlement_ref_m"]
        print(f"{e['time_min']:6d} {e['max_error_pa']:11.1f} {e['relative_error']:7.3f} {e['cell_relative_error']:8.3f} {e['outflow_m_per_s']:10.3e} "
              f"{e['outflow_ref_m_per_s']:10.3e} {e['outflow_relative_error']:6.3f} {1e3*e['settlement_m']:9.3f} "
              f"{'' if ref_s is None else f'{1e3*ref_s:7.3f}'}")
    print(f"max relative p_w error {worst:.3f} points, {worst_cell:.3f} cell means (tolerance 0.05), max outflow error {worst_q:.3f} (tolerance 0.10)")


if __name__ == "__main__":
    sys.exit(main())
