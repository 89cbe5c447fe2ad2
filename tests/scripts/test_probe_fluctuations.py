"""Tests of scripts/probe_fluctuations.py on a synthetic probes.csv.

Probe "ringing" rings about a steady state: p_w = 10 kPa + 2 kPa sin(2 pi t /
T) and v_x = 3 mm/s + 1 mm/s cos(2 pi t / T), T = 5.5 ms, sampled every 0.5 ms
(11 rows a period) for 1 s of the last stage, its plastic strain growing by
1e-3; a window of 3 periods (33 rows) holds its running mean at the steady
state exactly. Probe "steady" holds p_w = -5 kPa and v = (0, 2) mm/s. Rows of
an earlier stage, far off both, must not count.
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from test_slope_metrics import PYTHON, SCRIPTS  # noqa: E402

SCRIPT = os.path.join(SCRIPTS, "probe_fluctuations.py")
ROWS_PER_PERIOD = 11
WINDOW = ["--window-s", "0.0165"]  # 3 periods
COLUMNS = ["time_s", "stage", "name", "point_id", "x_m", "y_m", "u_x_m", "u_y_m",
           "v_x_m_per_s", "v_y_m_per_s", "eps_p_bar", "p_w_pa", "S",
           "v_w_x_m_per_s", "v_w_y_m_per_s", "K_m_per_s"]


def row(t, stage, name, p_w, v_x, v_y, eps_p):
    values = {c: 0.0 for c in COLUMNS}
    values.update(time_s=t, stage=stage, name=name, point_id=1, p_w_pa=p_w,
                  v_x_m_per_s=v_x, v_y_m_per_s=v_y, eps_p_bar=eps_p, S=1.0)
    return values


def write_probes(path):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        for k in range(10):  # an earlier stage, far off
            writer.writerow(row(0.1 * k, "gravity", "ringing", 1e6, 1.0, 1.0, 0.5))
        for k in range(2001):
            t = 5.0 + 0.0005 * k
            phase = 2.0 * math.pi * k / ROWS_PER_PERIOD
            writer.writerow(row(t, "rainfall", "ringing", 10e3 + 2e3 * math.sin(phase),
                                3e-3 + 1e-3 * math.cos(phase), 0.0, 1e-3 * (t - 5.0)))
            writer.writerow(row(t, "rainfall", "steady", -5e3, 0.0, 2e-3, 0.0))


class ProbeFluctuationsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.run_dir = os.path.join(cls.tmp.name, "run")
        os.makedirs(cls.run_dir)
        write_probes(os.path.join(cls.run_dir, "probes.csv"))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def stats(self, *args):
        result = subprocess.run([PYTHON, SCRIPT, self.run_dir, "--json", *args],
                                capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        return next(iter(json.loads(result.stdout).values()))

    def test_ringing_about_its_running_mean(self):
        s = self.stats(*WINDOW)["ringing"]
        self.assertEqual(s["rows"], 2001)
        self.assertAlmostEqual(s["interval_s"], 0.0005)
        # 2001 rows are 181 periods and 10 rows: the mean is off by the
        # partial period's sum.
        partial = sum(math.sin(2 * math.pi * k / ROWS_PER_PERIOD) for k in range(10))
        self.assertAlmostEqual(s["p_w_mean_pa"], 10e3 + 2e3 * partial / 2001, delta=1e-6)
        # The 1,969 rows a full window covers are 179 whole periods: the
        # sine's RMS (amplitude / sqrt 2) and its largest sample.
        largest = max(abs(math.sin(2 * math.pi * k / ROWS_PER_PERIOD))
                      for k in range(ROWS_PER_PERIOD))
        self.assertAlmostEqual(s["p_w_fluctuation_rms_pa"], 2e3 / math.sqrt(2), delta=1e-6)
        self.assertAlmostEqual(s["p_w_fluctuation_max_pa"], 2e3 * largest, delta=1e-6)
        self.assertAlmostEqual(s["velocity_fluctuation_rms_m_per_s"],
                               1e-3 / math.sqrt(2), delta=1e-12)
        self.assertAlmostEqual(s["eps_p_growth"], 1e-3)

    def test_a_steady_point_does_not_fluctuate(self):
        s = self.stats(*WINDOW)["steady"]
        self.assertAlmostEqual(s["p_w_mean_pa"], -5e3)
        self.assertAlmostEqual(s["p_w_fluctuation_rms_pa"], 0.0, places=6)
        self.assertAlmostEqual(s["velocity_fluctuation_rms_m_per_s"], 0.0, places=9)
        self.assertAlmostEqual(s["speed_mean_m_per_s"], 2e-3)
        self.assertEqual(s["eps_p_growth"], 0.0)

    def test_a_window_as_long_as_the_record_leaves_no_fluctuation_measure(self):
        s = self.stats("--window-s", "2.0")["ringing"]
        self.assertIsNone(s["p_w_fluctuation_rms_pa"])
        self.assertIsNone(s["velocity_fluctuation_rms_m_per_s"])

    def test_bad_input_is_refused(self):
        bad = subprocess.run([PYTHON, SCRIPT, self.run_dir, "--window-s", "0"],
                             capture_output=True, text=True)
        self.assertNotEqual(bad.returncode, 0)
        self.assertIn("--window-s", bad.stderr)
        empty = os.path.join(self.tmp.name, "empty.csv")
        with open(empty, "w") as f:
            f.write(",".join(COLUMNS) + "\n")
        result = subprocess.run([PYTHON, SCRIPT, empty], capture_output=True, text=True)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("no probe rows", result.stderr)
        missing = subprocess.run([PYTHON, SCRIPT, os.path.join(self.tmp.name, "none")],
                                 capture_output=True, text=True)
        self.assertNotEqual(missing.returncode, 0)
        self.assertIn("cannot read", missing.stderr)
        other = os.path.join(self.tmp.name, "other.csv")
        with open(other, "w") as f:
            f.write("time_s,stage,name\n1,rainfall,A\n")
        result = subprocess.run([PYTHON, SCRIPT, other], capture_output=True, text=True)
        self.assertNotEqual(result.returncode, 0)
        self.assertIn("no column(s) eps_p_bar, p_w_pa", result.stderr)
        self.assertNotIn("Traceback", result.stderr)


if __name__ == "__main__":
    unittest.main()
