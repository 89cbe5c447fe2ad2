#!/usr/bin/python3
"""History of one region of a rainslide run's points through its last stage.

The points are chosen by where they were at the start of the last stage (the
rainfall of the slope cases), so the same points are followed as they move.
At every --every-s seconds of stage time, for each run given: the largest and
the median displacement since the stage start, the mean and largest pore
pressure, the largest equivalent plastic strain and how many points have
yielded during the stage (their plastic strain grew by more than
--yield-strain). The yield onset is the first snapshot at which at least
--yield-points points have yielded.

  scripts/region_history.py RUN [RUN ...] --x-range 53.5 57 [--y-range 0 6]
      [--every-s 1] [--yield-strain 0.01] [--yield-points 3] [--json]

Used in docs/speed-vs-error.md for the toe of the closest reading, where the
explicit and semi-implicit runs yield at the same time and then creep at
rates their numerical damping sets.
"""
import argparse
import json
import os
import sys

import h5py
import numpy as np


def stage_snapshots(snapshots):
    """Keys of the last stage's snapshots, in order, and the snapshot before
    the stage's first (its start state), or the first one if there is none."""
    keys = sorted(snapshots.keys())
    last = snapshots[keys[-1]].attrs["stage"]
    stage = [k for k in keys if snapshots[k].attrs["stage"] == last]
    first = keys.index(stage[0])
    start = keys[first - 1] if first > 0 else stage[0]
    return start, stage


def region_history(run, x_range, y_range, every_s, yield_strain, yield_points):
    """Rows of the region's history (dicts) and its yield onset (s or None)."""
    path = os.path.join(run, "particles.h5")
    if not os.path.isfile(path):
        raise ValueError(f"{path}: file not found")
    with h5py.File(path, "r") as f:
        snapshots = f["snapshots"]
        start_key, keys = stage_snapshots(snapshots)
        start = snapshots[start_key]
        x0 = start["x"][:]
        in_region = ((x0[:, 0] >= x_range[0]) & (x0[:, 0] <= x_range[1]) &
                     (x0[:, 1] >= y_range[0]) & (x0[:, 1] <= y_range[1]))
        if not in_region.any():
            raise ValueError(f"{path}: no point starts the last stage in x {x_range} m, "
                             f"y {y_range} m")
        eps_start = start["plastic_shear_strain"][:][in_region]
        two_phase = "pore_pressure" in start
        rows, onset = [], None
        for key in keys:
            snap = snapshots[key]
            t = float(snap.attrs["stage_time_s"])
            eps = snap["plastic_shear_strain"][:][in_region]
            yielded = int(np.count_nonzero(eps - eps_start > yield_strain))
            if onset is None and yielded >= yield_points:
                onset = t
            ratio = t / every_s
            if abs(ratio - round(ratio)) > 1e-6 or t <= 0.0:
                continue
            u = np.linalg.norm(snap["displacement"][:][in_region], axis=1)
            row = {"t_s": t, "u_max_m": float(u.max()), "u_median_m": float(np.median(u)),
                   "eps_p_max": float(eps.max()), "yielded": yielded}
            if two_phase:
                p_w = snap["pore_pressure"][:][in_region]
                row["p_w_mean_pa"] = float(p_w.mean())
                row["p_w_max_pa"] = float(p_w.max())
            rows.append(row)
    return {"run": run, "points": int(np.count_nonzero(in_region)), "yield_onset_s": onset,
            "rows": rows}


def markdown(histories):
    """One table, a block of columns per run, a row per time."""
    names = [os.path.basename(os.path.normpath(h["run"])) for h in histories]
    columns = "u max cm | u median cm | p_w mean kPa | p_w max kPa | eps_p max | yielded"
    lines = ["| t s | " + " | ".join(f"{n}: {columns}" for n in names) + " |",
             "|--:|" + "--:|--:|--:|--:|--:|--:|" * len(names)]
    times = sorted({r["t_s"] for h in histories for r in h["rows"]})
    for t in times:
        cells = []
        for h in histories:
            row = next((r for r in h["rows"] if abs(r["t_s"] - t) < 1e-9), None)
            if row is None:
                cells.append(" | ".join(["–"] * 6))
                continue
            p_mean = row.get("p_w_mean_pa", float("nan")) / 1e3
            p_max = row.get("p_w_max_pa", float("nan")) / 1e3
            cells.append(f"{100 * row['u_max_m']:.2f} | {100 * row['u_median_m']:.3f} | "
                         f"{p_mean:.2f} | {p_max:.1f} | {row['eps_p_max']:.3f} | "
                         f"{row['yielded']}")
        lines.append(f"| {t:g} | " + " | ".join(cells) + " |")
    for name, h in zip(names, histories):
        onset = "none" if h["yield_onset_s"] is None else f"{h['yield_onset_s']:g} s"
        lines.append(f"\n{name}: {h['points']} points, yield onset {onset}")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="results folders")
    parser.add_argument("--x-range", nargs=2, type=float, required=True, metavar=("MIN", "MAX"),
                        help="x at the stage start, m")
    parser.add_argument("--y-range", nargs=2, type=float, default=(-1e30, 1e30),
                        metavar=("MIN", "MAX"), help="y at the stage start, m")
    parser.add_argument("--every-s", type=float, default=1.0, help="table interval, s")
    parser.add_argument("--yield-strain", type=float, default=0.01,
                        help="plastic strain growth during the stage that counts as yielded")
    parser.add_argument("--yield-points", type=int, default=3,
                        help="yielded points that mark the onset")
    parser.add_argument("--json", action="store_true", help="print JSON, not Markdown")
    args = parser.parse_args(argv)
    if not args.every_s > 0.0 or args.yield_points < 1 or not args.yield_strain >= 0.0:
        parser.error("--every-s must be > 0, --yield-points >= 1, --yield-strain >= 0")
    try:
        histories = [region_history(run, args.x_range, args.y_range, args.every_s,
                                    args.yield_strain, args.yield_points) for run in args.runs]
    except (OSError, KeyError, ValueError) as error:
        print(f"region_history: error: {error}", file=sys.stderr)
        return 2
    print(json.dumps(histories, indent=1) if args.json else markdown(histories))
    return 0


if __name__ == "__main__":
    sys.exit(main())
