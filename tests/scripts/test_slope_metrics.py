"""Tests of scripts/slope_metrics.py (and smoke tests of slope_figures/slope_summary).

Run: /usr/bin/python3 -m unittest discover -s tests/scripts -p 'test_*.py' -v
(from the repository root; or /usr/bin/python3 tests/scripts/test_slope_metrics.py).

A synthetic particles.h5 in the rainslide-particles-1 layout: a 20 m x 5 m block
of points at 0.5 m spacing (0.25 m^2 each), a "gravity" stage ending at run
time 1 s (displacement reset after it), then a "rainfall" stage with snapshots
at stage times 1..10 s. Scripted motion (stage time t):
  block 1, x0 in [14, 18), y0 in [3, 5) (32 points, 8 m^2): slides from t = 4,
      u_x = 0.3 (t - 3) m, eps_p_bar = 0.2  -> first failure at t = 4, 8 m^2;
  growth, x0 in [13, 14), y0 in [3, 5) (8 points, 2 m^2): joins block 1 from
      t = 6 with the same displacement (linked to it: no new slide by default,
      an "area jump" with jump_rate 1 m^2/s);
  block 2, x0 in [2, 5), y0 in [3, 5) (24 points, 6 m^2): slides from t = 7,
      u_x = 0.2 m, eps 0.3, far from block 1 -> a detached slide at t = 7;
  a lone point at (5.25, 0.25) moves 1 m from t = 2 (0.25 m^2: ignored);
  a 3 x 3 block at x0 in [8, 9.5), y0 in [0, 1.5) is removed (status 0) and
      moved 2 m from t = 3 (ignored: not active);
  three points with eps 0.5 but u = 0.05 m (not sliding).
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
sys.path.insert(0, SCRIPTS)
import slope_metrics as sm  # noqa: E402

PYTHON = sys.executable or "/usr/bin/python3"
SPACING = 0.5


def _box(x0, xlo, xhi, ylo, yhi):
    return (x0[:, 0] >= xlo) & (x0[:, 0] < xhi) & (x0[:, 1] >= ylo) & (x0[:, 1] < yhi)


def make_run(folder, two_stage=True, two_phase=True, probes=True):
    """Writes particles.h5, metrics.json (and probes.csv) of the synthetic run into folder."""
    os.makedirs(folder, exist_ok=True)
    gx, gy = np.meshgrid(np.arange(40) * SPACING + 0.25, np.arange(10) * SPACING + 0.25,
                         indexing="ij")
    x_init = np.column_stack([gx.ravel(), gy.ravel()])
    n = len(x_init)
    ids = np.arange(n, dtype=np.int32)
    block1 = _box(x_init, 14, 18, 3, 5)
    growth = _box(x_init, 13, 14, 3, 5)
    block2 = _box(x_init, 2, 5, 3, 5)
    lone = np.isclose(x_init[:, 0], 5.25) & np.isclose(x_init[:, 1], 0.25)
    removed = _box(x_init, 8, 9.5, 0, 1.5)
    strained = _box(x_init, 10, 11.5, 0, 0.5)
    settle = np.array([0.0, -0.01])
    x_start = x_init + (settle if two_stage else 0.0)  # positions at the rainfall start

    def state(t):
        """(x, eps, status) at rainfall stage time t."""
        u = np.zeros((n, 2))
        eps = np.zeros(n)
        status = np.ones(n, dtype=np.int32)
        if t >= 4:
            u[block1, 0] = 0.3 * (t - 3)
            eps[block1] = 0.2
        if t >= 6:
            u[growth, 0] = 0.3 * (t - 3)
            eps[growth] = 0.2
        if t >= 7:
            u[block2, 0] = 0.2
            eps[block2] = 0.3
        if t >= 2:
            u[lone, 0] = 1.0
        if t >= 3:
            u[removed, 0] = 2.0
            status[removed] = 0
        u[strained, 0] = 0.05
        eps[strained] = 0.5
        return x_start + u, eps, status

    snaps = []  # (stage, stage_time, time, x, displacement, eps, status)
    offset = 0.0
    if two_stage:
        for ts in (0.5, 1.0):
            x = x_init + settle * ts
            snaps.append(("gravity", ts, ts, x, x - x_init, np.zeros(n), np.ones(n, dtype=np.int32)))
        offset = 1.0
    for t in range(1, 11):
        x, eps, status = state(float(t))
        # Displacement since the last reset: the rainfall start (two stages) or the run start.
        snaps.append(("rainfall" if two_stage else "collapse", float(t), offset + t, x,
                      x - x_start if two_stage else x - x_init, eps, status))

    with h5py.File(os.path.join(folder, "particles.h5"), "w") as f:
        f.attrs["format"] = np.bytes_("rainslide-particles-1")
        f.attrs["snapshot_count"] = np.int64(len(snaps))
        g = f.create_group("snapshots")
        for k, (stage, ts, t, x, u, eps, status) in enumerate(snaps):
            s = g.create_group(f"{k:06d}")
            s.attrs["time_s"] = t
            s.attrs["stage"] = np.bytes_(stage)
            s.attrs["stage_time_s"] = ts
            s.attrs["step"] = np.int64(100 * k)
            s.attrs["n_points"] = np.int64(n)
            s["x"] = x
            s["displacement"] = u
            s["velocity"] = np.zeros((n, 2))
            stress = np.zeros((n, 4))
            stress[:, 1] = -2e4 * (5.0 - x_init[:, 1])
            stress[:, 2] = 5e3 * np.sin(x[:, 0] / 3.0)
            s["stress"] = stress
            s["strain"] = np.zeros((n, 4))
            s["plastic_shear_strain"] = eps
            s["volume"] = np.full(n, SPACING ** 2)
            s["mass"] = np.full(n, 2000 * SPACING ** 2)
            s["material"] = np.zeros(n, dtype=np.int32)
            s["id"] = ids
            s["status"] = status
            if two_phase:
                front = 5.0 - 0.4 * (ts if stage == "rainfall" else 0.0)
                pw = np.where(x_init[:, 1] > front, 0.0, -5e4)
                s["pore_pressure"] = pw
                s["saturation"] = np.where(pw >= 0, 1.0, 0.3)
                s["porosity"] = np.full(n, 0.3)
                vw = np.zeros((n, 2))
                vw[:, 1] = np.where(pw >= 0, -4e-2, 0.0)
                s["water_velocity"] = vw
                s["relative_permeability"] = np.where(pw >= 0, 1.0, 1e-4)
    stages = [{"name": "gravity", "type": "quasi_static", "duration_s": 1.0}] if two_stage else []
    stages.append({"name": "rainfall" if two_stage else "collapse", "type": "dynamic",
                   "duration_s": 10.0})
    with open(os.path.join(folder, "metrics.json"), "w") as f:
        json.dump({"case": "synthetic_slope", "status": "completed", "stages": stages}, f)
    if probes and two_stage:
        with open(os.path.join(folder, "probes.csv"), "w") as f:
            f.write("time_s,stage,name,point_id,x_m,y_m,u_x_m,u_y_m,v_x_m_per_s,v_y_m_per_s,"
                    "v_w_x_m_per_s,v_w_y_m_per_s,p_w_pa,S,eps_p_bar,K_m_per_s\n")
            for t in np.arange(0.0, 10.01, 0.5):
                for k, name in enumerate("ABCD"):
                    vw = 0.04 * np.sin(2 * np.pi * t / 4.0 + k)
                    f.write(f"{1.0 + t},rainfall,{name},{k},{4 + 4 * k},4.75,0,0,0,0,"
                            f"{0.3 * vw},{-vw},0,1,0,0.0441\n")
    return folder


#---------------------------------------------------------------------------#
class SlopeMetricsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = os.path.join(self.tmp.name, "run")

    def tearDown(self):
        self.tmp.cleanup()

    def analyse(self, toe_x=18.0, **opts):
        run = sm.Run(self.dir)
        try:
            return sm.public(sm.slope_metrics(run, toe_x, **opts))
        finally:
            run.close()

    def check_default_result(self, r, stage):
        self.assertEqual(r["stage"], stage)
        self.assertAlmostEqual(r["point_spacing_m"], 0.5)
        self.assertEqual(r["first_failure_time_s"], 4.0)
        series = dict(zip(r["series"]["time_s"], r["series"]["sliding_area_m2"]))
        self.assertEqual(series[1.0], 0.0)
        self.assertEqual(series[3.0], 0.0)  # lone point and removed block ignored
        self.assertAlmostEqual(series[4.0], 8.0)
        self.assertAlmostEqual(series[6.0], 10.0)
        self.assertAlmostEqual(series[10.0], 16.0)
        self.assertEqual(r["slide_times_s"], [4.0, 7.0])
        self.assertEqual(r["slides"][0]["reason"], "first failure")
        self.assertAlmostEqual(r["slides"][0]["new_area_m2"], 8.0)
        self.assertIn("detached group", r["slides"][1]["reason"])
        self.assertAlmostEqual(r["slides"][1]["detached_area_m2"], 6.0)
        self.assertEqual(r["slides"][1]["initial_x_range_m"], [2.25, 4.75])
        fin = r["final"]
        self.assertEqual(fin["n_groups"], 2)
        self.assertAlmostEqual(fin["max_x_sliding_m"], 17.75 + 2.1)
        self.assertAlmostEqual(fin["run_out_m"], 17.75 + 2.1 - 18.0)
        self.assertAlmostEqual(fin["max_displacement_m"], 2.1)  # removed points excluded

    def test_two_stage_run(self):
        make_run(self.dir)
        r = self.analyse()
        self.check_default_result(r, "rainfall")
        self.assertAlmostEqual(r["stage_start_time_s"], 1.0)
        self.assertIn("end of stage 'gravity'", r["definition"]["reference_state"])

    def test_rotated_model_mapped_back_by_frame(self):
        """The synthetic run built rotated by 30 deg and shifted: with --frame
        the metrics are those of the unrotated run."""
        make_run(self.dir)
        a = np.radians(30.0)
        rot = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
        with h5py.File(os.path.join(self.dir, "particles.h5"), "r+") as f:
            for snap in f["snapshots"].values():
                for name in ("x", "displacement", "velocity"):
                    if name in snap:
                        v = snap[name][()] @ rot.T + (np.array([5.0, -3.0]) if name == "x" else 0.0)
                        snap[name][...] = v
        run = sm.Run(self.dir, frame=sm.Frame.parse("30,5,-3"))
        try:
            r = sm.public(sm.slope_metrics(run, 18.0))
        finally:
            run.close()
        self.check_default_result(r, "rainfall")
        with self.assertRaises(sm.InputError):
            sm.Frame.parse("30,5")

    def make_run_with_wave_speed(self, wave_speed):
        """The synthetic run, its metrics.json recording the undrained wave speed."""
        make_run(self.dir)
        with open(os.path.join(self.dir, "metrics.json")) as f:
            metrics = json.load(f)
        metrics["time_step"] = {"final_max_wave_speed_m_per_s": wave_speed}
        with open(os.path.join(self.dir, "metrics.json"), "w") as f:
            json.dump(metrics, f)

    def test_pore_pressure_pulse_against_hydrostatic_plus_joukowsky(self):
        self.make_run_with_wave_speed(1000.0)
        # A point that does not move, 4.5 m below the top of its column;
        # saturated points seep at 0.04 m/s: momentum 1000 * 0.3 * 0.04.
        hydrostatic, joukowsky = 9810.0 * 4.5, 1000.0 * 12.0
        with h5py.File(os.path.join(self.dir, "particles.h5"), "r+") as f:
            snap = f["snapshots"][sorted(f["snapshots"].keys())[-1]]
            x = snap["x"][:]
            k = int(np.argmin(np.hypot(x[:, 0] - 6.25, x[:, 1] - 0.24)))
            p = snap["pore_pressure"][:]
            p[k] = 2.0 * (hydrostatic + joukowsky)
            snap["pore_pressure"][...] = p
        pulses = self.analyse()["pore_pressure_pulses"]
        self.assertAlmostEqual(pulses["largest"]["ratio"], 2.0, places=5)
        self.assertAlmostEqual(pulses["largest"]["hydrostatic_pa"], hydrostatic, places=3)
        self.assertAlmostEqual(pulses["largest"]["joukowsky_pa"], joukowsky, places=3)
        self.assertEqual(pulses["largest"]["time_s"], 10.0)

    def test_pressure_peak_follows_the_point_and_splits_total_pressure(self):
        self.make_run_with_wave_speed(1500.0)
        # The last two snapshots: one point's p_w rises 50 -> 200 kPa at an
        # unchanged effective stress (an undrained compression: B = 1) while
        # its solid slows from 0.5 to 0.45 m/s: rho_m = 2000 + 0.3 * 1000.
        wave = 2300.0 * 1500.0 * 0.05
        with h5py.File(os.path.join(self.dir, "particles.h5"), "r+") as f:
            names = sorted(f["snapshots"].keys())
            for name, p_w, v in ((names[-2], 5.0e4, 0.5), (names[-1], 2.0e5, 0.45)):
                snap = f["snapshots"][name]
                x = snap["x"][:]
                k = int(np.argmin(np.hypot(x[:, 0] - 6.25, x[:, 1] - 0.24)))
                p = snap["pore_pressure"][:]
                p[k] = p_w
                snap["pore_pressure"][...] = p
                S = snap["saturation"][:]
                S[k] = 1.0
                snap["saturation"][...] = S
                velocity = snap["velocity"][:]
                velocity[k] = (0.6 * v, -0.8 * v)
                snap["velocity"][...] = velocity
                point_id, sig_yy = int(snap["id"][k]), float(snap["stress"][k, 1])
        peak = self.analyse()["pressure_peak"]
        self.assertEqual(peak["point_id"], point_id)
        self.assertAlmostEqual(peak["peak"]["p_w_pa"], 2.0e5)
        self.assertAlmostEqual(peak["before"]["p_w_pa"], 5.0e4)
        self.assertAlmostEqual(peak["peak"]["effective_mean_pressure_pa"], -sig_yy / 3.0, places=3)
        self.assertAlmostEqual(peak["peak"]["total_mean_pressure_pa"], 2.0e5 - sig_yy / 3.0,
                               places=3)
        self.assertAlmostEqual(peak["skempton_b"], 1.0, places=6)
        self.assertAlmostEqual(peak["undrained_wave"]["pressure_pa"], wave, places=3)
        self.assertAlmostEqual(peak["undrained_wave"]["total_pressure_change_over_it"],
                               1.5e5 / wave, places=6)

    def test_single_stage_run_uses_x_minus_displacement(self):
        make_run(self.dir, two_stage=False, two_phase=False)
        r = self.analyse()
        self.check_default_result(r, "collapse")
        self.assertAlmostEqual(r["stage_start_time_s"], 0.0)

    def test_stage_start_from_metrics_json_without_stage_time(self):
        make_run(self.dir)
        with h5py.File(os.path.join(self.dir, "particles.h5"), "r+") as f:
            for g in f["snapshots"].values():
                del g.attrs["stage_time_s"]
        r = self.analyse()
        self.check_default_result(r, "rainfall")
        self.assertEqual(r["stage_start_source"], "metrics.json (durations of the earlier stages)")

    def test_area_jump_rule(self):
        make_run(self.dir)
        r = self.analyse(jump_rate_m2_per_s=1.0)
        self.assertEqual(r["slide_times_s"], [4.0, 6.0, 7.0])
        self.assertEqual(r["slides"][1]["reason"], "area jump")
        self.assertAlmostEqual(r["slides"][1]["new_area_m2"], 2.0)

    def test_connected_groups(self):
        xy = np.array([[0, 0], [0.5, 0], [1.0, 0], [3, 0], [3.4, 0.3], [10, 10]], dtype=float)
        lab = sm.connected_groups(xy, 0.6)
        self.assertEqual(len(set(lab[:3])), 1)
        self.assertEqual(lab[3], lab[4])
        self.assertEqual(len(set(lab)), 3)
        # A long chain (label propagation must cross it).
        chain = np.column_stack([np.arange(500) * 0.3, np.zeros(500)])
        self.assertEqual(len(set(sm.connected_groups(chain[::-1], 0.35))), 1)

    def test_cli_writes_metrics_json(self):
        make_run(self.dir)
        out = subprocess.run([PYTHON, os.path.join(SCRIPTS, "slope_metrics.py"), self.dir,
                              "--toe-x", "18"], capture_output=True, text=True)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertIn("first failure at t = 4.0 s", out.stdout)
        with open(os.path.join(self.dir, "metrics.json")) as f:
            data = json.load(f)
        self.assertEqual(data["case"], "synthetic_slope")  # other keys kept
        self.assertEqual(data["slope"]["slide_times_s"], [4.0, 7.0])
        self.assertFalse(os.path.exists(os.path.join(self.dir, "metrics.json.partial")))

    def test_missing_inputs_give_one_line_and_exit_2(self):
        make_run(self.dir)
        os.remove(os.path.join(self.dir, "metrics.json"))
        cases = [("slope_metrics.py", [self.dir], "metrics.json: file not found"),
                 ("slope_metrics.py", [os.path.join(self.tmp.name, "nowhere")], "not found"),
                 ("slope_summary.py", [self.dir, "--out", os.path.join(self.tmp.name, "s.png")],
                  "metrics.json: file not found"),
                 ("slope_metrics.py", [self.dir, "--no-write", "--stage", "drying"],
                  "no snapshot of stage 'drying'")]
        for script, args, message in cases:
            out = subprocess.run([PYTHON, os.path.join(SCRIPTS, script)] + args,
                                 capture_output=True, text=True)
            self.assertEqual(out.returncode, 2, out.stderr)
            self.assertEqual(len(out.stderr.strip().splitlines()), 1, out.stderr)
            self.assertIn(message, out.stderr)
        os.remove(os.path.join(self.dir, "particles.h5"))
        out = subprocess.run([PYTHON, os.path.join(SCRIPTS, "slope_figures.py"), self.dir],
                             capture_output=True, text=True)
        self.assertEqual(out.returncode, 2)
        self.assertIn("particles.h5: file not found", out.stderr)
        self.assertEqual(len(out.stderr.strip().splitlines()), 1, out.stderr)

    def test_figures_and_summary_smoke(self):
        make_run(self.dir)
        figs = os.path.join(self.tmp.name, "figs")
        out = subprocess.run([PYTHON, os.path.join(SCRIPTS, "slope_figures.py"), self.dir,
                              "--out", figs, "--times", "2,5,8", "--toe-x", "18"],
                             capture_output=True, text=True)
        self.assertEqual(out.returncode, 0, out.stderr)
        for name in ("fig7_pw_epsp.png", "fig8_shear_stress.png", "fig9_vw_over_K.png",
                     "final_state.png"):
            path = os.path.join(figs, name)
            self.assertTrue(os.path.isfile(path), name)
            self.assertLess(os.path.getsize(path), 400 * 1024, name)
        png = os.path.join(self.tmp.name, "summary.png")
        table = os.path.join(self.tmp.name, "summary.md")
        out = subprocess.run([PYTHON, os.path.join(SCRIPTS, "slope_summary.py"), self.dir,
                              "--out", png, "--table", table, "--toe-x", "18"],
                             capture_output=True, text=True)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertTrue(os.path.isfile(png))
        with open(table) as f:
            rows = f.read().splitlines()
        self.assertEqual(len(rows), 3)  # header, rule, one case
        cells = [c.strip() for c in rows[2].strip("|").split("|")]
        self.assertEqual(cells[1], "4.00")  # first failure
        self.assertEqual(cells[2], "7")     # the detached slide

    def test_study_panel_smoke_and_bad_input(self):
        make_run(self.dir)
        png = os.path.join(self.tmp.name, "panel.png")
        out = subprocess.run([PYTHON, os.path.join(SCRIPTS, "study_panel.py"), png,
                              f"base={self.dir}", f"rotated={self.dir}",
                              "--frame", "rotated=0,0,0"], capture_output=True, text=True)
        self.assertEqual(out.returncode, 0, out.stderr)
        self.assertTrue(os.path.isfile(png))
        out = subprocess.run([PYTHON, os.path.join(SCRIPTS, "study_panel.py"), png,
                              self.dir], capture_output=True, text=True)
        self.assertEqual(out.returncode, 2)
        self.assertIn("study_panel: error: runs: expected LABEL=VALUE", out.stderr)


if __name__ == "__main__":
    unittest.main()
