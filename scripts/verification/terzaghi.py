#!/usr/bin/python3
"""Compare a Terzaghi consolidation run with the series solution (verification.md §2).

Usage: terzaghi.py RESULTS_DIR
Reads the case file named in RESULTS_DIR/metrics.json (case_file) for the
geometry, material, water and load, and RESULTS_DIR/particles.h5 for p_w.
Writes the "verification" section of RESULTS_DIR/metrics.json (atomically):
  l2_error[Tv]      relative L2 error of p_w over material points
                    sqrt(sum (p - p_exact(z))^2 / sum p_exact(z)^2);
  l2_error_max      its maximum over the Tv values;
  l2_error_cell[Tv] the same with cell means of p_w against the solution at
                    the cell's mean depth (the scheme's p_w is piecewise
                    constant per cell in a one-cell-wide column);
  degree_of_consolidation[Tv] U = 1 - mean p / p0 against the series.
Errors in the input give one line "terzaghi: error: ..." and exit code 2.
"""
import argparse
import json
import math
import os
import sys
import tempfile
import tomllib

import h5py
import numpy as np


def series_ratio(z, H, Tv, terms=200):
    m = np.arange(terms)
    M = 0.5 * math.pi * (2 * m + 1)
    return np.sum((2.0 / M)[None, :] * np.sin(np.outer(z / H, M)) * np.exp(-M * M * Tv)[None, :], axis=1)


def degree(Tv, terms=200):
    m = np.arange(terms)
    M = 0.5 * math.pi * (2 * m + 1)
    return 1.0 - float(np.sum(2.0 / (M * M) * np.exp(-M * M * Tv)))


def consolidation_parameters(case):
    """c_v, H, y_top, the load ramp t_ramp and the initial excess pressure p0
    (Skempton's B with compressible water) of a Terzaghi case (a dict of its
    TOML); speed_vs_error.py uses it too."""
    mat = case["materials"][0]
    water = case.get("water", {})
    K_w = water.get("bulk_modulus_pa", 2.2e9)
    rho_w = water.get("density_kg_per_m3", 1000.0)
    mu = water.get("viscosity_pa_s", 1.0e-3)
    E, nu, n, k = mat["youngs_modulus_pa"], mat["poisson_ratio"], mat["porosity"], mat["permeability_m2"]
    E_c = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    m_v = 1.0 / E_c
    K = k * rho_w * 9.81 / mu
    c_v = K / (rho_w * 9.81 * (m_v + n / K_w))
    polygon = np.array(case["bodies"][0]["polygon_m"])
    load = case["stages"][0]["loads"][0]
    ramp = load.get("time_function", [[0.0, 1.0]])
    return {"c_v": c_v, "H": polygon[:, 1].max() - polygon[:, 1].min(), "y_top": polygon[:, 1].max(),
            "t_ramp": ramp[-1][0] if len(ramp) > 1 else 0.0,
            "p0": abs(load["traction_pa"][1]) * m_v / (m_v + n / K_w)}


def fail(message):
    print(f"terzaghi: error: {message}", file=sys.stderr)
    sys.exit(2)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", help="results folder of a Terzaghi run")
    results = parser.parse_args().results
    if not os.path.isdir(results):
        fail(f"{results}: results folder not found")
    metrics_path = os.path.join(results, "metrics.json")
    try:
        with open(metrics_path) as f:
            metrics = json.load(f)
    except (OSError, ValueError) as error:
        fail(f"cannot read {metrics_path}: {error}")
    case_file = metrics.get("case_file") if isinstance(metrics, dict) else None
    if not isinstance(case_file, str):
        fail(f"{metrics_path}: no 'case_file' (not written by rainslide run?)")
    try:
        with open(case_file, "rb") as f:
            case = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as error:
        fail(f"cannot read the case file {case_file} (named in {metrics_path}): {error}")
    try:
        phys = consolidation_parameters(case)
        h = case["grid"]["cell_size_m"]
        duration = case["stages"][0]["duration_s"]
    except (KeyError, IndexError, TypeError) as error:
        fail(f"{case_file}: not a Terzaghi case (no {error})")
    c_v, H, y_top, t_ramp, p0 = phys["c_v"], phys["H"], phys["y_top"], phys["t_ramp"], phys["p0"]

    out = {"kind": "terzaghi", "c_v_m2_per_s": c_v, "p0_pa": p0, "cells_over_height": round(H / h),
           "l2_error": {}, "l2_error_cell": {}, "degree_of_consolidation": {}}
    h5_path = os.path.join(results, "particles.h5")
    if not os.path.isfile(h5_path):
        fail(f"{h5_path}: file not found")
    try:
        with h5py.File(h5_path, "r") as h5:
            for g in h5["snapshots"].values():
                t = float(g.attrs["stage_time_s"])
                Tv = (t - 0.5 * t_ramp) * c_v / H ** 2
                if Tv <= 0.0 or t >= duration - 1e-9:
                    continue
                x, u, p = g["x"][:], g["displacement"][:], g["pore_pressure"][:]
                z = y_top - (x[:, 1] - u[:, 1])
                exact = p0 * series_ratio(z, H, Tv)
                l2 = math.sqrt(np.sum((p - exact) ** 2) / np.sum(exact ** 2))
                cells = np.floor(z / h + 1e-9).astype(int)
                num, den = 0.0, 0.0
                for c in np.unique(cells):
                    sel = cells == c
                    e = p0 * series_ratio(np.array([z[sel].mean()]), H, Tv)[0]
                    num += (p[sel].mean() - e) ** 2
                    den += e * e
                key = f"{Tv:.3g}"
                out["l2_error"][key] = l2
                out["l2_error_cell"][key] = math.sqrt(num / den)
                out["degree_of_consolidation"][key] = {"mpm": 1.0 - p.mean() / p0, "exact": degree(Tv)}
    except (OSError, KeyError) as error:
        fail(f"cannot read {h5_path}: {error}")
    if not out["l2_error"]:
        fail(f"{h5_path}: no snapshot inside the consolidation stage")
    out["l2_error_max"] = max(out["l2_error"].values())
    out["l2_error_cell_max"] = max(out["l2_error_cell"].values())
    metrics["verification"] = out
    try:
        fd, tmp = tempfile.mkstemp(dir=results, prefix=".metrics.", suffix=".json")
        with os.fdopen(fd, "w") as f:
            json.dump(metrics, f, indent=2)
        os.replace(tmp, metrics_path)
    except OSError as error:
        fail(f"cannot write {metrics_path}: {error}")
    print(f"Terzaghi, {out['cells_over_height']} cells, c_v = {c_v:.4g} m^2/s, p0 = {p0:.1f} Pa")
    print(f"{'Tv':>6} {'L2 points':>10} {'L2 cells':>9} {'U mpm':>7} {'U exact':>8}")
    for key in out["l2_error"]:
        U = out["degree_of_consolidation"][key]
        print(f"{key:>6} {out['l2_error'][key]:10.4f} {out['l2_error_cell'][key]:9.4f} {U['mpm']:7.4f} {U['exact']:8.4f}")
    print(f"l2_error_max {out['l2_error_max']:.4f}, l2_error_cell_max {out['l2_error_cell_max']:.4f}")


if __name__ == "__main__":
    main()
