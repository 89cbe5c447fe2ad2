"""Tests of scripts/fos_history.py and scripts/study_table.py on synthetic results.

fos_history: two searched states of a column of points at x = 7.5 m, y = 0.25 ..
4.75 m (top 4.75 m): at t = 0 every p_w is -50 kPa (front depth 0), at t = 5 s the
points with y >= 2.25 m are at 0 (front 2.5 m below the top). FS 1.2 then 0.95;
the second search's mechanism moved the points of x0 in [40, 44] by 1 m.
study_table: slides starting at x 50-56, then 45-49 (upslope of all: retrogressive),
then 52-53 (not), then 30-31 (retrogressive); eps_p_bar 0.02 at the toe of the cut
after stage 1 (cohesion 20 - 250 x 0.02 = 15 kPa).
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.normpath(os.path.join(HERE, "..", "..", "scripts"))
PYTHON = sys.executable or "/usr/bin/python3"


def write_snapshots(path, snapshots):
    """snapshots: list of (attrs, {field: array})."""
    with h5py.File(path, "w") as f:
        group = f.create_group("snapshots")
        for k, (attrs, fields) in enumerate(snapshots):
            snap = group.create_group(f"{k:06d}")
            for key, value in attrs.items():
                snap.attrs[key] = value
            for key, value in fields.items():
                snap.create_dataset(key, data=value)


def run_script(name, *args):
    return subprocess.run([PYTHON, os.path.join(SCRIPTS, name), *args],
                          capture_output=True, text=True,
                          env=dict(os.environ, MPLBACKEND="Agg"))


class FosHistoryTest(unittest.TestCase):
    def make_history(self, folder):
        y = np.arange(0.25, 5.0, 0.5)
        x = np.stack([np.full_like(y, 7.5), y], axis=1)
        dry = np.full_like(y, -50.0e3)
        wet = np.where(y >= 2.25, 0.0, -50.0e3)
        write_snapshots(os.path.join(folder, "states.h5"), [
            ({"stage_time_s": 0.0, "time_s": 4.0}, {"x": x, "pore_pressure": dry}),
            ({"stage_time_s": 5.0, "time_s": 9.0}, {"x": x, "pore_pressure": wet})])
        rows = []
        for t, fs in ((0.0, 1.2), (5.0, 0.95)):
            name = f"t_{t:07.2f}"
            os.makedirs(os.path.join(folder, name))
            fos = {"factor_of_safety": fs}
            if t > 0:
                x0 = np.array([[40.0, 1.0], [44.0, 2.0], [10.0, 3.0]])
                u = np.array([[1.0, 0.0], [1.0, 0.0], [0.01, 0.0]])
                write_snapshots(os.path.join(folder, name, "mechanism.h5"),
                                [({"stage_time_s": 1.0}, {"x": x0 + u, "displacement": u})])
                fos["mechanism"] = {"hdf5": "mechanism.h5", "factor": 0.96}
            with open(os.path.join(folder, name, "fos.json"), "w") as f:
                json.dump(fos, f)
            rows.append({"stage_time_s": t, "factor_of_safety": fs,
                         "bracket": [fs - 0.01, fs + 0.01], "folder": name, "wall_s": 3.0})
        with open(os.path.join(folder, "fos_history.json"), "w") as f:
            json.dump({"case": "synthetic", "rows": rows}, f)

    def test_table_front_depth_mechanism_and_first_drop(self):
        with tempfile.TemporaryDirectory() as folder:
            self.make_history(folder)
            result = run_script("fos_history.py", folder, "--columns", "7.5")
            self.assertEqual(result.returncode, 0, result.stderr)
            lines = result.stdout.splitlines()
            self.assertTrue(lines[2].startswith("| 0.00 | 1.200 |"), lines[2])
            self.assertIn("| 0.00 | none |", lines[2])
            self.assertIn("| 2.50 | x 40.0-44.0, y >= 1.0 |", lines[3])
            self.assertIn("FS first below 1 at t = 5.00 s", result.stdout)
            self.assertTrue(os.path.isfile(os.path.join(folder, "fos_history.png")))

    def test_other_histories_on_the_same_plot(self):
        with tempfile.TemporaryDirectory() as folder, \
                tempfile.TemporaryDirectory() as variant:
            self.make_history(folder)
            rows = [{"stage_time_s": 0.0, "factor_of_safety": 1.5},
                    {"stage_time_s": 5.0, "factor_of_safety": None}]
            with open(os.path.join(variant, "fos_history.json"), "w") as f:
                json.dump({"case": "variant", "rows": rows}, f)
            out = os.path.join(folder, "both.png")
            result = run_script("fos_history.py", folder, "--columns", "7.5",
                                "--with", variant, "--out", out)
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertTrue(os.path.isfile(out))
            # A row without its time is named, before any figure is drawn.
            rows[1].pop("stage_time_s")
            with open(os.path.join(variant, "fos_history.json"), "w") as f:
                json.dump({"case": "variant", "rows": rows}, f)
            os.remove(out)
            result = run_script("fos_history.py", folder, "--with", variant,
                                "--out", out)
            self.assertEqual(result.returncode, 2)
            self.assertIn("rows[1].stage_time_s: expected a number of seconds, found None",
                          result.stderr)
            self.assertFalse(os.path.exists(out))

    def test_missing_history_exits_2(self):
        with tempfile.TemporaryDirectory() as folder:
            result = run_script("fos_history.py", folder)
            self.assertEqual(result.returncode, 2)
            self.assertIn("fos_history: error:", result.stderr)


class StudyTableTest(unittest.TestCase):
    def test_retrogressive_onsets_and_initial_softening(self):
        with tempfile.TemporaryDirectory() as folder:
            slides = [{"time_s": t, "initial_x_range_m": r}
                      for t, r in ((10.0, [50.0, 56.0]), (12.0, [45.0, 49.0]),
                                   (14.0, [52.0, 53.0]), (16.0, [30.0, 31.0]))]
            metrics = {"case": "synthetic", "stages": [{"name": "gravity"}, {"name": "rain"}],
                       "slope": {"slides": slides, "max_run_out_m": 3.0,
                                 "final": {"sliding_area_m2": 42.0}}}
            with open(os.path.join(folder, "metrics.json"), "w") as f:
                json.dump(metrics, f)
            x = np.array([[56.0, 1.2], [54.5, 5.0], [15.0, 19.0], [30.0, 10.0]])
            eps = np.array([0.02, 0.0, 0.001, 0.5])
            write_snapshots(os.path.join(folder, "particles.h5"), [
                ({"stage": "gravity"}, {"x": x, "plastic_shear_strain": eps}),
                ({"stage": "rain"}, {"x": x, "plastic_shear_strain": 2 * eps})])
            result = run_script("study_table.py", folder)
            self.assertEqual(result.returncode, 0, result.stderr)
            row = result.stdout.splitlines()[2]
            self.assertIn("| 10.00 at x 50.0-56.0 | 4 | 2 | 42.0 | 3.0 |", row)
            self.assertIn("0.0200 (15.0) | 0.0000 (20.0) | 0.0010 (19.8) |", row)

            # With the FS history of a folder of the same name under --fos-root.
            fos_root = os.path.join(folder, "fos")
            os.makedirs(os.path.join(fos_root, os.path.basename(folder)))
            FosHistoryTest().make_history(os.path.join(fos_root, os.path.basename(folder)))
            result = run_script("study_table.py", folder, "--fos-root", fos_root)
            self.assertEqual(result.returncode, 0, result.stderr)
            lines = result.stdout.splitlines()
            self.assertTrue(lines[0].endswith("| FS at 0 / 5 s |"), lines[0])
            self.assertTrue(lines[2].endswith("| 1.20 / 0.95 |"), lines[2])


if __name__ == "__main__":
    unittest.main()
