#!/usr/bin/python3
"""End-to-end test: the CLI writes a slope run, the Python scripts read it.

Usage: e2e_slope_run.py RAINSLIDE_BINARY

Runs cases/slope_base.toml on 1 m cells (1 s of its gravity-and-suction
stage, 2 s of rainfall, snapshots every 0.5 s) into a temporary folder, then
scripts/slope_metrics.py and scripts/slope_figures.py over it, and checks
that what the C++ writer put into particles.h5 is what the C++ run reported
in metrics.json, read back through the scripts' own reader (slope_metrics.Run):
the snapshot count and times, the largest displacement of the final state,
the water stored at the end (water balance: n, S, V and p_w, whose share
p_w / K_w of 8e-6 the 1e-6 tolerance sees), and every field the scripts
read. Exit code 0 if all hold, 1 otherwise.
"""
import json
import math
import os
import subprocess
import sys
import tempfile
import tomllib

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SCRIPTS = os.path.join(ROOT, "scripts")
sys.path.insert(0, SCRIPTS)
import slope_metrics as sm  # noqa: E402

PYTHON = "/usr/bin/python3"
OVERRIDES = ["grid.cell_size_m=1.0", "grid.cells=[72,21]",
             "stages[0].duration_s=1.0", "stages[1].duration_s=2.0",
             "stages[1].snapshot_interval_s=0.5"]
# The fields slope_metrics.py and slope_figures.py read (Run.field names).
FIELDS = ["x", "displacement", "velocity", "stress", "plastic_shear_strain",
          "volume", "pore_pressure", "saturation", "porosity",
          "water_velocity", "id", "status"]

failures = []


def check(condition, what):
    print(("ok      " if condition else "FAILED  ") + what)
    if not condition:
        failures.append(what)


def close(a, b, rel, floor=0.0):
    """a and b agree to rel (relative) plus floor (absolute)."""
    return abs(a - b) <= rel * max(abs(a), abs(b)) + floor


def run(cmd):
    """Exit code and stdout of cmd (stderr, shown on failure, apart)."""
    done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          text=True, timeout=600)
    return done.returncode, done.stdout + done.stderr, done.stdout


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    binary = sys.argv[1]
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "run")
        cmd = [binary, "run", os.path.join(ROOT, "cases", "slope_base.toml"),
               "--out", out, "--threads", "1", "--quiet"]
        for o in OVERRIDES:
            cmd += ["--set", o]
        code, text, _ = run(cmd)
        # The shortened equilibrium stage does not converge: status
        # "unconverged", exit code 0 with a warning.
        check(code == 0, "rainslide run exits 0"
              + ("" if code == 0 else " (got %d)\n%s" % (code, text)))
        if code != 0:
            return 1
        with open(os.path.join(out, "metrics.json"), encoding="utf-8") as f:
            metrics = json.load(f)

        code, text, stdout = run([PYTHON, os.path.join(SCRIPTS, "slope_metrics.py"),
                                  out, "--json"])
        check(code == 0, "slope_metrics.py exits 0"
              + ("" if code == 0 else " (got %d)\n%s" % (code, text)))
        slope = json.loads(stdout) if code == 0 else {}
        code, text, _ = run([PYTHON, os.path.join(SCRIPTS, "slope_figures.py"), out,
                          "--times", "0.5,2.0"])
        check(code == 0, "slope_figures.py exits 0"
              + ("" if code == 0 else " (got %d)\n%s" % (code, text)))
        check(os.path.isfile(os.path.join(out, "figures", "final_state.png")),
              "slope_figures.py wrote final_state.png")

        reader = sm.Run(out)
        snaps = reader.snapshots
        check(len(snaps) == metrics["output"]["snapshots"],
              "HDF5 snapshots %d = metrics.json output.snapshots %d"
              % (len(snaps), metrics["output"]["snapshots"]))
        # The end of the first stage, then the rainfall every 0.5 s.
        stages = [(s.stage, round(s.stage_time_s, 9)) for s in snaps]
        expected = [("gravity_and_suction", 1.0)] + [("rainfall", t)
                                                      for t in (0.5, 1.0, 1.5, 2.0)]
        check(stages == expected, "snapshots (stage, stage time): %s" % stages)
        last = snaps[-1]
        check(close(last.time_s, metrics["simulated_time_s"], 1e-12),
              "last snapshot at the run's end, %.6f s" % last.time_s)
        missing = [name for name in FIELDS if not reader.has_field(last, name)]
        check(not missing, "particles.h5 holds every field the scripts read"
              + (" (missing: %s)" % missing if missing else ""))
        if missing:
            return 1

        active = reader.active(last)
        u = np.linalg.norm(reader.field(last, "displacement"), axis=1)
        u_max = float(np.max(u[active]))
        reported = metrics["deformation"]["max_displacement_m"]
        check(close(u_max, reported, 1e-9),
              "largest displacement: HDF5 %.9g m, metrics.json %.9g m" % (u_max, reported))
        final = slope.get("final", {})
        # slope_metrics writes 6 decimals.
        check(close(final.get("max_displacement_m", math.nan), reported, 0.0, 5e-7),
              "slope_metrics final max displacement %s m = metrics.json %.6g m"
              % (final.get("max_displacement_m"), reported))

        # The run's verdict (solver/output/mpm_failure_verdict.cpp) and
        # slope_metrics share their definitions: the same answer.
        verdict = metrics.get("verdict", {})
        check(verdict.get("failed") is False and slope.get("failed") is False,
              "verdict: no failure in the C++ run and in slope_metrics (%s, %s)"
              % (verdict.get("failed"), slope.get("failed")))
        series_max = max((slope.get("series") or {}).get("max_displacement_m") or [math.nan])
        check(close(verdict.get("max_displacement_m", math.nan), series_max, 0.0, 5e-7),
              "verdict largest displacement %s m = slope_metrics' largest over the "
              "snapshots %s m" % (verdict.get("max_displacement_m"), series_max))
        check(verdict.get("snapshots_analysed") == slope.get("snapshots_analysed"),
              "verdict and slope_metrics analyse the same %s snapshots"
              % slope.get("snapshots_analysed"))
        check(verdict.get("line", "").startswith("no failure:")
              and "rainslide fos" in verdict.get("line", ""),
              "verdict line points to rainslide fos: %s" % verdict.get("line"))

        # physics::pointWaterVolume: V n S (1 + p_w / K_w).
        with open(os.path.join(ROOT, "cases", "slope_base.toml"), "rb") as f:
            K_w = tomllib.load(f)["water"]["bulk_modulus_pa"]
        n = reader.field(last, "porosity")
        s = reader.field(last, "saturation")
        vol = reader.field(last, "volume")
        p_w = reader.field(last, "pore_pressure")
        stored = float(np.sum((vol * n * s * (1.0 + p_w / K_w))[active]))
        stored_end = metrics["water_balance"]["stored_end"]
        check(close(stored, stored_end, 1e-6),
              "water stored at the end: HDF5 sum V n S (1 + p_w/K_w) %.9g m3/m, water balance %.9g m3/m"
              % (stored, stored_end))

        reader.close()
    print("%d check(s) failed" % len(failures) if failures else "all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
