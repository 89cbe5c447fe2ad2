#!/usr/bin/python3
"""Factor of safety against time, with the wetting front, from `rainslide fos --every-s`.

Usage: fos_history.py DIR [--columns X ...] [--half-width-m W] [--wet-pa P]
                      [--with DIR ...] [--out PNG]

Reads DIR/fos_history.json (one row per search), DIR/states.h5 (the searched
states) and DIR/t_*/mechanism.h5. For every search time it gives the factor
of safety, the depth of the wetting front below the ground surface in each
column (the deepest point within --half-width-m, 0.5 m, of x whose p_w is
above --wet-pa, default -25 kPa: half the slope's initial suction lost) and
where the mechanism of the smallest failing F is (the x range and the
deepest point of the points that moved more than a tenth of the largest
displacement). Writes DIR/fos_history.png (FS and the front depths against
time; with --with, also the FS of other histories, e.g. the phi and c_r
variants) and DIR/fos_history.md (the table), and prints the table. Errors in
the input give one line "fos_history: error: ..." and exit code 2.
"""
import argparse
import json
import os
import sys

import numpy as np


def fail(message):
    print(f"fos_history: error: {message}", file=sys.stderr)
    sys.exit(2)


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as error:
        fail(f"cannot read {path}: {error}")


def read_states(path):
    """The searched states: (stage time, positions, p_w) in file order."""
    import h5py

    states = []
    try:
        with h5py.File(path, "r") as f:
            for name in sorted(f["snapshots"].keys()):
                snap = f["snapshots"][name]
                p_w = snap["pore_pressure"][:] if "pore_pressure" in snap else None
                states.append((float(snap.attrs["stage_time_s"]), snap["x"][:], p_w))
    except (OSError, KeyError) as error:
        fail(f"cannot read {path}: {error}")
    return states


def front_depth(x, p_w, column_x, half_width, wet_pa):
    """Depth (m) of the deepest wetted point below the column's top point."""
    in_column = np.abs(x[:, 0] - column_x) <= half_width
    if p_w is None or not in_column.any():
        return float("nan")
    top = x[in_column, 1].max()
    wet = in_column & (p_w >= wet_pa)
    return float(top - x[wet, 1].min()) if wet.any() else 0.0


def mechanism_extent(path):
    """x range and the deepest y of the points that moved > 10 % of the most."""
    import h5py

    try:
        with h5py.File(path, "r") as f:
            snaps = f["snapshots"]
            last = snaps[sorted(snaps.keys())[-1]]
            x0 = last["x"][:] - last["displacement"][:]
            u = np.hypot(last["displacement"][:, 0], last["displacement"][:, 1])
    except (OSError, KeyError) as error:
        fail(f"cannot read {path}: {error}")
    moved = u > 0.1 * u.max()
    return (float(x0[moved, 0].min()), float(x0[moved, 0].max()),
            float(x0[moved, 1].min()), float(u.max()))


def read_history(folder):
    """The document `folder`/fos_history.json and its rows (at least one)."""
    history = read_json(os.path.join(folder, "fos_history.json"))
    rows = history.get("rows")
    if not isinstance(rows, list) or not rows:
        fail(f"{folder}/fos_history.json: no rows (did a search finish?)")
    return history, rows


def fos_series(folder):
    """(case name, stage times, FS) of the history in `folder`; NaN where
    no factor was found."""
    history, rows = read_history(folder)
    times, factors = [], []
    for k, row in enumerate(rows):
        t = row.get("stage_time_s") if isinstance(row, dict) else None
        if not isinstance(t, (int, float)):
            fail(f"{folder}/fos_history.json: rows[{k}].stage_time_s: "
                 f"expected a number of seconds, found {t!r}")
        fs = row.get("factor_of_safety")
        times.append(float(t))
        factors.append(float(fs) if isinstance(fs, (int, float)) else np.nan)
    return history.get("case", folder), np.array(times), np.array(factors)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    parser.add_argument("--columns", type=float, nargs="+", default=[7.5, 35.0],
                        help="x of the columns whose wetting front is given (m)")
    parser.add_argument("--half-width-m", type=float, default=0.5,
                        help="points within this of a column's x belong to it (m)")
    parser.add_argument("--wet-pa", type=float, default=-25.0e3,
                        help="p_w above which a point counts as wetted (Pa)")
    parser.add_argument("--with", dest="others", nargs="+", default=[],
                        metavar="DIR", help="also draw the FS of these histories")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    if not args.half_width_m > 0.0:
        parser.error(f"--half-width-m must be > 0 m, got {args.half_width_m:g}")
    others = [fos_series(folder) for folder in args.others]
    history, rows = read_history(args.dir)
    states = read_states(os.path.join(args.dir, "states.h5"))
    if len(states) < len(rows):
        fail(f"{args.dir}/states.h5: {len(states)} states for {len(rows)} rows")
    table = []
    for k, (row, (t, x, p_w)) in enumerate(zip(rows, states)):
        depths = [front_depth(x, p_w, c, args.half_width_m, args.wet_pa)
                  for c in args.columns]
        if not isinstance(row, dict) or not isinstance(row.get("folder"), str):
            fail(f"{args.dir}/fos_history.json: rows[{k}] has no 'folder'")
        fos_dir = os.path.join(args.dir, row["folder"])
        fos = read_json(os.path.join(fos_dir, "fos.json"))
        extent = None
        if "mechanism" in fos:
            extent = mechanism_extent(os.path.join(fos_dir, fos["mechanism"]["hdf5"]))
        table.append((t, row.get("factor_of_safety"), row.get("bracket"), depths,
                      extent, row.get("wall_s")))
    lines = ["| rain time (s) | FS | bracket | "
             + " | ".join(f"front depth at x = {c:g} m (m)" for c in args.columns)
             + " | mechanism (initial x range, deepest y, m) | search wall (s) |",
             "|" + "---|" * (5 + len(args.columns))]
    for t, fs, bracket, depths, extent, wall in table:
        fs_text = f"{fs:.3f}" if fs is not None else "not found"
        br = f"[{bracket[0]:.3g}, {bracket[1]:.3g}]" if bracket else ""
        mech = (f"x {extent[0]:.1f}-{extent[1]:.1f}, y >= {extent[2]:.1f}"
                if extent else "none")
        lines.append(f"| {t:.2f} | {fs_text} | {br} | "
                     + " | ".join(f"{d:.2f}" for d in depths)
                     + f" | {mech} | {'–' if wall is None else f'{wall:.0f}'} |")
    below = [t for t, fs, *_ in table if fs is not None and fs < 1.0]
    lines.append("")
    lines.append(f"FS first below 1 at t = {below[0]:.2f} s" if below
                 else "FS stays at or above 1 at every search time")
    text = "\n".join(lines) + "\n"
    table_path = os.path.join(args.dir, "fos_history.md")
    try:
        with open(table_path, "w") as f:
            f.write(text)
    except OSError as error:
        fail(f"cannot write {table_path}: {error}")
    print(text, end="")

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = np.array([r[0] for r in table])
    fs = np.array([np.nan if r[1] is None else r[1] for r in table])
    fig, ax = plt.subplots(figsize=(8, 4.5))
    case = history.get("case", "")
    ax.plot(t, fs, "ko-", label=f"FS, {case}" if others else "factor of safety")
    for k, (name, other_t, other_fs) in enumerate(others):
        ax.plot(other_t, other_fs, "o-", ms=4, color=f"C{k}", label=f"FS, {name}")
    ax.axhline(1.0, color="r", lw=0.8, ls="--")
    ax.set_xlabel("time since the rain began (s)")
    ax.set_ylabel("factor of safety (strength reduction)")
    ax.set_title(f"{case}: FS and the wetting front")
    depth_ax = ax.twinx()
    for k, c in enumerate(args.columns):
        depth_ax.plot(t, [r[3][k] for r in table], "s--", ms=3,
                      color=str(0.35 + 0.3 * k / max(1, len(args.columns) - 1)),
                      label=f"wetting front at x = {c:g} m")
    depth_ax.set_ylabel(f"depth of p_w >= {args.wet_pa / 1e3:g} kPa (m)")
    handles = ax.get_legend_handles_labels()
    more = depth_ax.get_legend_handles_labels()
    ax.legend(handles[0] + more[0], handles[1] + more[1], loc="best", fontsize=8)
    figure = args.out or os.path.join(args.dir, "fos_history.png")
    fig.tight_layout()
    try:
        fig.savefig(figure, dpi=120)
    except OSError as error:
        fail(f"cannot write {figure}: {error}")
    print(f"figure: {figure}")


if __name__ == "__main__":
    main()
