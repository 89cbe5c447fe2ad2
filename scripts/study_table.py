#!/usr/bin/python3
"""Summary table of the slope study's controlled experiments.

Usage: study_table.py DIR [DIR ...] [--out MD] [--fos-root ROOT]

Each DIR is a results folder of a slope run analysed by slope_metrics.py
(metrics.json with its "slope" entry, and particles.h5). One row per run:
the first failure (time since the rain began, initial x range of the first
sliding points), the number of slide onsets, how many of them are
retrogressive (start upslope, at smaller x, of every earlier onset), the
final sliding area and run-out, and the state after stage 1 (the initial
state before the rain): the largest eps_p_bar within 1 m of the toe of the
cut (56.33, 1.0), the crest of the cut (54.47, 5.0) and the crest/slope
corner (15.0, 19.36), with the cohesion it leaves (c0 + H eps_p_bar, at
least c_r; the base soil's c0 = 20 kPa, H = -250 kPa, c_r = 0.1 kPa).
With --fos-root, a last column gives the factor of safety at each searched
time of ROOT/<basename of DIR>/fos_history.json (rainslide fos --every-s), or
"–" where there is none. Prints the Markdown table (and writes it to MD). Errors in the input give
one line "study_table: error: ..." and exit code 2.
"""
import argparse
import json
import os
import sys

import numpy as np

from rainslide_tools.slope_run import Frame

PLACES = (("toe of the cut", (56.3323, 1.0)), ("crest of the cut", (54.4671, 5.0)),
          ("crest/slope corner", (15.0, 19.3648)))
C0, H, C_R = 20.0e3, -250.0e3, 100.0
RADIUS_M = 1.0


def fail(message):
    print(f"study_table: error: {message}", file=sys.stderr)
    sys.exit(2)


def initial_state_strain(run_dir, first_stage, frame=None):
    """Largest eps_p_bar near each place at the end of stage 1 (positions
    mapped back to the case's frame when the model was rotated)."""
    import h5py

    path = os.path.join(run_dir, "particles.h5")
    try:
        with h5py.File(path, "r") as f:
            snaps = f["snapshots"]
            names = [n for n in sorted(snaps.keys())
                     if snaps[n].attrs["stage"] in (first_stage, first_stage.encode())]
            if not names:
                fail(f"{path}: no snapshot of stage '{first_stage}'")
            last = snaps[names[-1]]
            x = last["x"][:]
            if frame is not None:
                x = frame.to_case(x, shift=True)
            eps = last["plastic_shear_strain"][:]
    except (OSError, KeyError) as error:
        fail(f"cannot read {path}: {error}")
    values = []
    for _, (px, py) in PLACES:
        near = np.hypot(x[:, 0] - px, x[:, 1] - py) <= RADIUS_M
        values.append(float(eps[near].max()) if near.any() else float("nan"))
    return values


def fos_history(fos_root, run_dir):
    """[(stage time, FS)] of the run's FS history (empty if there is none)."""
    path = os.path.join(fos_root, os.path.basename(os.path.normpath(run_dir)), "fos_history.json")
    if not os.path.isfile(path):
        return []
    try:
        with open(path) as f:
            rows = json.load(f)["rows"]
        found = [(r["stage_time_s"], r["factor_of_safety"]) for r in rows
                 if r.get("status", "found") == "found"]
    except (OSError, ValueError, KeyError, TypeError) as error:
        fail(f"cannot read {path}: {error}")
    return found


def fos_column(histories):
    """Header and cells: 'FS at t1 / t2 ... s' when every history has those
    times (the cells list the factors), else 't: FS' pairs in each cell."""
    times = {tuple(t for t, _ in h) for h in histories if h}
    if len(times) == 1:
        common = times.pop()
        head = "FS at " + " / ".join(f"{t:g}" for t in common) + " s"
        return head, [" / ".join(f"{fs:.2f}" for _, fs in h) if h else "–" for h in histories]
    return "FS (time s: FS)", [", ".join(f"{t:g}: {fs:.2f}" for t, fs in h) if h else "–"
                               for h in histories]


def row(run_dir):
    try:
        with open(os.path.join(run_dir, "metrics.json")) as f:
            metrics = json.load(f)
    except (OSError, ValueError) as error:
        fail(f"cannot read {run_dir}/metrics.json: {error}")
    slope = metrics.get("slope")
    if not isinstance(slope, dict):
        fail(f"{run_dir}/metrics.json: no 'slope' entry (run slope_metrics.py first)")
    stages = metrics.get("stages") or [{}]
    first_stage = stages[0].get("name", "")
    slides = slope.get("slides") or []
    retrogressive = 0
    for k, slide in enumerate(slides[1:], start=1):
        earlier = min(s["initial_x_range_m"][0] for s in slides[:k])
        if slide["initial_x_range_m"][1] < earlier:
            retrogressive += 1
    first = slides[0] if slides else None
    final = slope.get("final", {})
    frame = Frame(*slope["frame"]) if slope.get("frame") else None
    eps = initial_state_strain(run_dir, first_stage, frame)
    return {
        "case": metrics.get("case", os.path.basename(run_dir)),
        "first": (f"{first['time_s']:.2f} at x {first['initial_x_range_m'][0]:.1f}-"
                  f"{first['initial_x_range_m'][1]:.1f}" if first else "none"),
        "onsets": len(slides),
        "retrogressive": retrogressive,
        "area": final.get("sliding_area_m2", 0.0) or 0.0,
        "run_out": slope.get("max_run_out_m"),
        "eps": eps,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dirs", nargs="+")
    parser.add_argument("--out", default=None)
    parser.add_argument("--fos-root", default=None,
                        help="folder of the runs' FS histories (one subfolder per DIR name)")
    args = parser.parse_args()
    if args.fos_root and not os.path.isdir(args.fos_root):
        fail(f"--fos-root: {args.fos_root}: folder not found")
    rows = [row(d) for d in args.dirs]
    if args.fos_root:
        fos_head, fos_cells = fos_column([fos_history(args.fos_root, d) for d in args.dirs])
        for r, cell in zip(rows, fos_cells):
            r["fos"] = cell
    head = ["case", "first failure (s, initial x m)", "slide onsets",
            "retrogressive onsets", "final sliding area (m²)", "run-out (m)"]
    head += [f"ε̄p after stage 1, {name} (c left, kPa)" for name, _ in PLACES]
    if args.fos_root:
        head.append(fos_head)
    lines = ["| " + " | ".join(head) + " |", "|---" + "|--:" * (len(head) - 1) + "|"]
    for r in rows:
        cells = [f"`{r['case']}`", r["first"], str(r["onsets"]), str(r["retrogressive"]),
                 f"{r['area']:.1f}", "–" if r["run_out"] is None else f"{r['run_out']:.1f}"]
        cells += [f"{e:.4f} ({max(C_R, C0 + H * e) / 1e3:.1f})" for e in r["eps"]]
        if args.fos_root:
            cells.append(r["fos"])
        lines.append("| " + " | ".join(cells) + " |")
    text = "\n".join(lines) + "\n"
    if args.out:
        try:
            with open(args.out, "w") as f:
                f.write(text)
        except OSError as error:
            fail(f"cannot write {args.out}: {error}")
    print(text, end="")


if __name__ == "__main__":
    main()
