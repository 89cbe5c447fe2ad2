"""Tests of scripts/region_history.py on the synthetic run of test_slope_metrics.py.

Block 1 of that run (x0 in [14, 18), y0 in [3, 5): 32 points) starts to slide at
stage time 4 s (u_x = 0.3 (t - 3) m, eps_p_bar 0.2); the wetting front
y = 5 - 0.4 t (p_w = 0 above it, -50 kPa below) passes its rows at y0 = 4.75,
4.25, 3.75 and 3.25 m at 0.625, 1.875, 3.125 and 4.375 s.
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from test_slope_metrics import PYTHON, SCRIPTS, make_run  # noqa: E402

SCRIPT = os.path.join(SCRIPTS, "region_history.py")
BLOCK_1 = ["--x-range", "14", "17.9", "--y-range", "2.9", "4.9"]


def run_script(*args):
    return subprocess.run([PYTHON, SCRIPT, *args], capture_output=True, text=True)


class RegionHistoryTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.run_dir = make_run(os.path.join(cls.tmp.name, "run"))

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def history(self, *args):
        result = run_script(self.run_dir, *BLOCK_1, "--json", *args)
        self.assertEqual(result.returncode, 0, result.stderr)
        return json.loads(result.stdout)[0]

    def test_follows_the_block_from_the_stage_start(self):
        h = self.history()
        self.assertEqual(h["points"], 32)
        self.assertEqual(h["yield_onset_s"], 4.0)
        rows = {r["t_s"]: r for r in h["rows"]}
        self.assertEqual(sorted(rows), [float(t) for t in range(1, 11)])
        self.assertAlmostEqual(rows[3.0]["u_max_m"], 0.0)
        self.assertAlmostEqual(rows[5.0]["u_max_m"], 0.6)
        self.assertAlmostEqual(rows[5.0]["u_median_m"], 0.6)
        self.assertEqual(rows[3.0]["yielded"], 0)
        self.assertEqual(rows[4.0]["yielded"], 32)
        self.assertAlmostEqual(rows[4.0]["eps_p_max"], 0.2)
        # One row of four wetted at 1 s, three at 4 s, all at 5 s.
        self.assertAlmostEqual(rows[1.0]["p_w_mean_pa"], -37.5e3)
        self.assertAlmostEqual(rows[4.0]["p_w_mean_pa"], -12.5e3)
        self.assertAlmostEqual(rows[5.0]["p_w_max_pa"], 0.0)

    def test_thresholds_and_interval(self):
        self.assertIsNone(self.history("--yield-strain", "0.25")["yield_onset_s"])
        self.assertIsNone(self.history("--yield-points", "33")["yield_onset_s"])
        times = [r["t_s"] for r in self.history("--every-s", "2.5")["rows"]]
        self.assertEqual(times, [5.0, 10.0])

    def test_markdown_names_the_run_and_its_onset(self):
        result = run_script(self.run_dir, *BLOCK_1)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("| 5 | 60.00 | 60.000 | 0.00 | 0.0 | 0.200 | 32 |", result.stdout)
        self.assertIn("run: 32 points, yield onset 4 s", result.stdout)

    def test_bad_input_exits_2(self):
        empty = run_script(self.run_dir, "--x-range", "100", "101")
        self.assertEqual(empty.returncode, 2)
        self.assertIn("no point starts the last stage", empty.stderr)
        missing = run_script(os.path.join(self.tmp.name, "absent"), *BLOCK_1)
        self.assertEqual(missing.returncode, 2)
        self.assertIn("particles.h5", missing.stderr)
        self.assertEqual(run_script(self.run_dir, *BLOCK_1, "--every-s", "0").returncode, 2)


if __name__ == "__main__":
    unittest.main()
