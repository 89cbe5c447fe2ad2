#!/usr/bin/python3
"""Speed-versus-error study of rainslide on the two verification columns.

Usage (from the repository root, after `scripts/run.sh check cases/terzaghi.toml`
has built build/release/rainslide):

    /usr/bin/python3 scripts/speed_vs_error.py [--binary PATH] [--out DIR]
        [--problems terzaghi,liakopoulos] [--reuse] [--report-only]

Generates variants of cases/terzaghi.toml and cases/liakopoulos.toml (cell
size, points per cell, water bulk modulus K_w, Courant number, inertia
scaling), runs them one at a time with the serial backend, scores each run with
scripts/verification/{terzaghi,liakopoulos}.py, and writes

    DIR/runs/<id>/{case.toml,metrics.json,particles.h5}   one folder per run
    DIR/runs.json, DIR/runs.csv                           every run
    DIR/tables.md                                         the tables of docs/speed-vs-error.md
    docs/speed-vs-error.png                               error vs wall time with the Pareto
                                                          fronts; Terzaghi error vs cell size

DIR defaults to results/speed_vs_error. --reuse keeps the runs whose folder
already holds a scored metrics.json for the same case text; --report-only
redraws the tables and figures from DIR/runs.json without running anything.

Error measures (smaller is better):
  Terzaghi     error = cell-mean relative L2 error of p_w, maximum over the five
               Tv snapshots, against the series solution of the *physical*
               problem (the K_w of cases/terzaghi.toml, 2e9 Pa). The
               verification script's own l2_error_cell_max / l2_error_max use
               the run's K_w (numerical error only); both are recorded.
  Liakopoulos  error = max(cell_relative_error_max, outflow_relative_error_max)
               against the OpenGeoSys reference (relative_error_max, the
               point-wise one, is recorded too).
"""
import argparse
import json
import math
import os
import re
import resource
import subprocess
import sys
import time
import tomllib

import numpy as np

from rainslide_tools.speed_vs_error_cases import (ROOT, VERIFY, liakopoulos_case, liakopoulos_plan,
                                                  load_module, terzaghi_case, terzaghi_physics, terzaghi_plan)
from rainslide_tools.speed_vs_error_report import fmt, write_outputs

PYTHON = "/usr/bin/python3"
PROBLEMS = ("terzaghi", "liakopoulos")


def fail(message):
    print(f"speed_vs_error: error: {message}", file=sys.stderr)
    sys.exit(2)

# --------------------------------------------------------------------------- #
# Running and scoring.


def terzaghi_physical_error(run_dir, case_text, reference_case):
    """Cell-mean and point-wise relative L2 errors (max over the snapshots)
    against the series solution with the reference case's K_w."""
    import h5py
    tz = load_module("terzaghi_verification", os.path.join(VERIFY, "terzaghi.py"))
    case = tomllib.loads(case_text)
    ref = terzaghi_physics(reference_case)
    run = terzaghi_physics(case)
    h = case["grid"]["cell_size_m"]
    duration = case["stages"][0]["duration_s"]
    H, y_top, p0, c_v = run["H"], run["y_top"], ref["p0"], ref["c_v"]
    cell_errs, point_errs = [], []
    with h5py.File(os.path.join(run_dir, "particles.h5"), "r") as f:
        for g in f["snapshots"].values():
            t = float(g.attrs["stage_time_s"])
            Tv = (t - 0.5 * run["t_ramp"]) * c_v / H ** 2
            if Tv <= 0.0 or t >= duration - 1e-9:
                continue
            x, u, p = g["x"][:], g["displacement"][:], g["pore_pressure"][:]
            z = y_top - (x[:, 1] - u[:, 1])
            exact = p0 * tz.series_ratio(z, H, Tv)
            point_errs.append(math.sqrt(np.sum((p - exact) ** 2) / np.sum(exact ** 2)))
            cells = np.floor(z / h + 1e-9).astype(int)
            num = den = 0.0
            for c in np.unique(cells):
                sel = cells == c
                e = p0 * tz.series_ratio(np.array([z[sel].mean()]), H, Tv)[0]
                num += (p[sel].mean() - e) ** 2
                den += e * e
            cell_errs.append(math.sqrt(num / den))
    return max(cell_errs), max(point_errs)


def geostatic_info(metrics):
    geo = [st for st in metrics.get("stages", []) if st["name"] == "geostatic"]
    if not geo:
        return {}
    return {"geostatic_end_s": geo[0].get("duration_s"), "geostatic_converged": geo[0].get("converged"),
            "geostatic_ke_ratio": geo[0].get("ke_ratio")}


def run_one(binary, out_root, spec, case_text, reference_case, reuse):
    run_dir = os.path.join(out_root, "runs", spec["id"])
    case_path = os.path.join(run_dir, "case.toml")
    metrics_path = os.path.join(run_dir, "metrics.json")
    record = {"id": spec["id"], "problem": spec["problem"], "study": spec["study"], "groups": spec["groups"],
              **spec["params"], "case_file": os.path.relpath(case_path, ROOT)}
    previous = reuse.get(spec["id"]) if reuse else None
    if previous and previous.get("status") == "completed" and os.path.exists(metrics_path) \
            and os.path.exists(case_path):
        with open(case_path) as f:
            same = f.read() == case_text
        with open(metrics_path) as f:
            m = json.load(f)
        scored = "verification" in m
        if same and scored:
            previous.update(geostatic_info(m))
            previous["groups"] = spec["groups"]
            previous["study"] = spec["study"]
            previous.update(spec["params"])
            previous["reused"] = True
            return previous
    os.makedirs(run_dir, exist_ok=True)
    for name in ("metrics.json", "particles.h5", "particles.xdmf"):
        if os.path.exists(os.path.join(run_dir, name)):
            os.remove(os.path.join(run_dir, name))
    with open(case_path, "w") as f:
        f.write(case_text)
    cmd = [binary, "run", os.path.abspath(case_path), "--out", os.path.abspath(run_dir),
           "--backend", "serial", "--threads", "1", "--quiet"]
    record["command"] = " ".join(cmd)
    # The machine may be shared: a run whose process wall time exceeds its CPU
    # time by more than 30 % (it waited for a core) is repeated once, and the
    # faster attempt is kept. process_wall_s / cpu_s is recorded.
    attempts = []
    for attempt in range(2):
        load = os.getloadavg()[0]
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        proc = subprocess.run(cmd, capture_output=True, text=True, cwd=ROOT)
        wall = time.perf_counter() - t0
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        metrics = None
        if proc.returncode == 0 and os.path.exists(metrics_path):
            with open(metrics_path) as f:
                metrics = json.load(f)
        attempts.append({"process_wall_s": wall, "cpu_s": cpu, "load_average_1min_before": load,
                         "wall_s": None if metrics is None else metrics["wall_s"]})
        if metrics is None or wall <= 1.3 * cpu:
            break
        if attempt == 0:
            with open(metrics_path + ".attempt0", "w") as f:
                json.dump(metrics, f)
    if len(attempts) == 2 and attempts[1]["wall_s"] is not None and attempts[0]["wall_s"] < attempts[1]["wall_s"]:
        os.replace(metrics_path + ".attempt0", metrics_path)     # the first attempt was faster
        best = attempts[0]
    else:
        best = attempts[-1]
    if os.path.exists(metrics_path + ".attempt0"):
        os.remove(metrics_path + ".attempt0")
    record.update({k: best[k] for k in ("process_wall_s", "cpu_s", "load_average_1min_before")})
    record["attempts"] = attempts
    record["returncode"] = proc.returncode
    if proc.returncode != 0 or not os.path.exists(metrics_path):
        record["status"] = "failed"
        record["output"] = (proc.stdout + proc.stderr)[-3000:]
        return record
    script = os.path.join(VERIFY, f"{spec['problem']}.py")
    ver = subprocess.run([PYTHON, script, run_dir], capture_output=True, text=True, cwd=ROOT)
    if ver.returncode != 0:
        record["status"] = "verification_failed"
        record["output"] = (proc.stdout + proc.stderr + ver.stdout + ver.stderr)[-3000:]
        return record
    with open(metrics_path) as f:
        m = json.load(f)
    v = m["verification"]
    record.update({"status": m.get("status", "?"), "wall_s": m["wall_s"], "steps": m["steps"],
                   "dt_s": m["dt_s"], "mp_updates_per_s": m["mp_updates_per_s"],
                   "n_particles": m["n_particles"], "backend": m.get("backend"),
                   "threads": m.get("threads"), "simulated_time_s": m.get("simulated_time_s"),
                   "stage_steps": {s["name"]: s["steps"] for s in m.get("stages", [])},
                   "stage_durations_s": {s["name"]: s.get("duration_s") for s in m.get("stages", [])}})
    if spec["problem"] == "terzaghi":
        phys_cell, phys_point = terzaghi_physical_error(run_dir, case_text, reference_case)
        record.update({"l2_error_max": v["l2_error_max"], "l2_error_cell_max": v["l2_error_cell_max"],
                       "l2_error_cell_max_vs_ref_kw": phys_cell, "l2_error_max_vs_ref_kw": phys_point,
                       "error": phys_cell})
    else:
        record.update({"relative_error_max": v["relative_error_max"],
                       "cell_relative_error_max": v["cell_relative_error_max"],
                       "outflow_relative_error_max": v["outflow_relative_error_max"],
                       "settlement_120min_m": v["per_time"]["120"]["settlement_m"],
                       "settlement_120min_ref_m": v["per_time"]["120"]["settlement_ref_m"],
                       "settlement_120min_relative_error": abs(v["per_time"]["120"]["settlement_m"]
                                                               / v["per_time"]["120"]["settlement_ref_m"] - 1.0),
                       "error": max(v["cell_relative_error_max"], v["outflow_relative_error_max"])})
        record.update(geostatic_info(m))
    if record["status"] != "completed":
        record["output"] = (proc.stdout + proc.stderr)[-3000:]
    return record


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--binary", default=os.path.join(ROOT, "build", "release", "rainslide"),
                    help="rainslide executable (default: build/release/rainslide, built by scripts/run.sh)")
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "speed_vs_error"))
    ap.add_argument("--problems", default="terzaghi,liakopoulos")
    ap.add_argument("--png", default=os.path.join(ROOT, "docs", "speed-vs-error.png"))
    ap.add_argument("--reuse", action="store_true", help="keep scored runs of an earlier sweep with the same case text")
    ap.add_argument("--report-only", action="store_true", help="only redraw tables and figures from runs.json")
    ap.add_argument("--only", default=None, help="run only the runs whose id matches this regular expression "
                    "(with --reuse the other runs of runs.json are kept in the outputs)")
    ap.add_argument("--rerun", default=None, help="with --reuse: run again the runs whose id matches this "
                    "regular expression (e.g. to re-time runs that shared the machine)")
    ap.add_argument("--dry-run", action="store_true", help="write the case files and list the runs only")
    args = ap.parse_args()
    problems = [p.strip() for p in args.problems.split(",") if p.strip()]
    unknown = [p for p in problems if p not in PROBLEMS]
    if unknown or not problems:
        fail(f"--problems: expected a comma-separated list of {', '.join(PROBLEMS)}, got '{args.problems}'")
    for option, pattern in (("--only", args.only), ("--rerun", args.rerun)):
        try:
            re.compile(pattern or "")
        except re.error as error:
            fail(f"{option}: not a regular expression ('{pattern}': {error})")
    out_root = os.path.abspath(args.out)
    try:
        os.makedirs(out_root, exist_ok=True)
    except OSError as error:
        fail(f"{out_root}: cannot create the output folder ({error})")

    if args.report_only:
        runs_json = os.path.join(out_root, "runs.json")
        try:
            with open(runs_json) as f:
                data = json.load(f)
            runs, meta = data["runs"], data["meta"]
        except (OSError, ValueError) as error:
            fail(f"cannot read {runs_json} ({error}); run the sweep first")
        except (KeyError, TypeError):
            fail(f"{runs_json}: no 'runs' and 'meta' (not written by speed_vs_error.py)")
        write_outputs(out_root, runs, meta, args.png)
        return 0

    binary = os.path.abspath(args.binary)
    if not args.dry_run and not os.access(binary, os.X_OK):
        fail(f"{binary}: not an executable; build it with `scripts/run.sh check cases/terzaghi.toml` "
             f"or pass --binary")
    bases = {}
    for p in problems:
        with open(os.path.join(ROOT, "cases", f"{p}.toml")) as f:
            bases[p] = f.read()
    plan = []
    if "terzaghi" in problems:
        plan += [(s, terzaghi_case(bases["terzaghi"], s["params"])) for s in terzaghi_plan()]
    if "liakopoulos" in problems:
        plan += [(s, liakopoulos_case(bases["liakopoulos"], s["params"])) for s in liakopoulos_plan()]
    full_plan = plan
    if args.only:
        plan = [(s, t) for s, t in plan if re.search(args.only, s["id"])]
    if args.dry_run:
        for s, text in plan:
            d = os.path.join(out_root, "runs", s["id"])
            os.makedirs(d, exist_ok=True)
            with open(os.path.join(d, "case.toml"), "w") as f:
                f.write(text)
            print(s["id"])
        print(f"{len(plan)} runs")
        return 0

    reference = {p: tomllib.loads(t) for p, t in bases.items()}
    git = subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"], capture_output=True, text=True).stdout.strip()
    import hashlib
    with open(binary, "rb") as f:
        sha = hashlib.sha256(f.read()).hexdigest()
    meta = {"binary": binary, "binary_sha256": sha,
            "binary_mtime": time.strftime("%Y-%m-%d %H:%M:%S", time.gmtime(os.path.getmtime(binary))),
            "git_head_at_sweep": git, "machine_cores": os.cpu_count(), "backend": "serial",
            "threads": 1, "started": time.strftime("%Y-%m-%d %H:%M:%S %Z")}
    previous = {}
    earlier = []
    if args.reuse and os.path.exists(os.path.join(out_root, "runs.json")):
        with open(os.path.join(out_root, "runs.json")) as f:
            old = json.load(f)
        previous = {r["id"]: r for r in old["runs"]}
        earlier = old["meta"].get("invocations", [])
    records = []
    t_start = time.perf_counter()
    for i, (spec, text) in enumerate(plan):
        again = args.rerun and re.search(args.rerun, spec["id"])
        r = run_one(binary, out_root, spec, text, reference[spec["problem"]], {} if again else previous)
        records.append(r)
        err = r.get("error")
        print(f"[{i + 1}/{len(plan)}] {r['id']}: {r.get('status')}, "
              f"error {fmt(err, '.5f')}, wall {fmt(r.get('wall_s'), '.2f')} s"
              f"{' (reused)' if r.get('reused') else ''}", flush=True)
        if r.get("status") != "completed":
            print(r.get("output", ""), flush=True)
        meta["sweep_wall_s"] = time.perf_counter() - t_start
        # Keep runs.json current so that an interrupted sweep can be resumed with --reuse.
        with open(os.path.join(out_root, "runs.json"), "w") as f:
            json.dump({"meta": meta, "runs": records}, f, indent=2)
    meta["sweep_wall_s"] = time.perf_counter() - t_start
    executed = sum(1 for r in records if not r.get("reused"))
    if args.only and previous:
        done = {r["id"] for r in records}
        order = [s["id"] for s, _ in full_plan]
        records += [r for i, r in previous.items() if i not in done]
        records.sort(key=lambda r: order.index(r["id"]) if r["id"] in order else len(order))
    meta["finished"] = time.strftime("%Y-%m-%d %H:%M:%S %Z")
    meta["invocations"] = earlier + [{"started": meta["started"], "wall_s": meta["sweep_wall_s"],
                                      "runs_executed": executed, "runs_reused": len(records) - executed}]
    meta["sweep_wall_s_total"] = sum(i["wall_s"] for i in meta["invocations"])
    write_outputs(out_root, records, meta, args.png)
    print(f"sweep wall time {meta['sweep_wall_s']:.0f} s; {out_root}/runs.json, runs.csv, tables.md; {args.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
