#!/usr/bin/python3
"""Summary plot across slope runs: sliding area and run-out against stage time.

Usage: slope_summary.py DIR1 [DIR2 ...] --out FILE.png [--table FILE.md]
                        [--recompute] [--stage NAME]

Per DIR, the series come from the "slope" key of DIR/metrics.json (written by
slope_metrics.py); a DIR without it (or with --recompute) is analysed from
DIR/particles.h5 with slope_metrics' defaults (metrics.json is not changed).
One line per case, labelled with metrics.json "case"; the first failure is
marked with a dot. Run-out is the largest x of a sliding point minus the toe x
(negative while the sliding mass has not passed the toe).
--table also writes a Markdown table, one row per case: first failure, later
slides, final sliding area, run-out and maximum displacement, how the run
ended, steps, wall time, threads and MP-updates/s (from metrics.json).
Errors in the input give one line "slope_summary: error: ..." and exit code 2.
"""
import argparse
import os
import signal
import sys

import numpy as np

import slope_metrics as sm


def case_series(run_dir, recompute=False, stage=None, toe_x=sm.DEFAULT_TOE_X, opts=None):
    """(label, slope dict) of one results folder."""
    metrics = sm.read_metrics(run_dir, required=True)
    path = os.path.join(run_dir, sm.METRICS)
    if "case" not in metrics:
        raise sm.InputError(f"{path}: no key 'case'")
    slope = metrics.get("slope")
    if recompute or not isinstance(slope, dict) or (stage and slope.get("stage") != stage):
        run = sm.Run(run_dir, stage, metrics_required=True)
        try:
            slope = sm.public(sm.slope_metrics(run, toe_x, **(opts or {})))
        finally:
            run.close()
    series = slope.get("series")
    if not isinstance(series, dict):
        raise sm.InputError(f"{path}: key 'slope' has no 'series' (rerun slope_metrics.py)")
    for k in ("time_s", "sliding_area_m2", "run_out_m"):
        if k not in series:
            raise sm.InputError(f"{path}: key 'slope.series' has no '{k}' (rerun slope_metrics.py)")
    return str(metrics["case"]), slope


def fmt(value, digits=1):
    """A number for the table ('–' if missing)."""
    return "–" if value is None else f"{value:.{digits}f}"


def table_row(label, slope, metrics):
    """One Markdown row of --table."""
    final = slope.get("final") or {}
    later = [f"{sl['time_s']:g}" for sl in slope.get("slides", [])[1:]]
    stage = next((st for st in metrics.get("stages", []) if st.get("name") == slope.get("stage")), {})
    ended = f"{stage.get('stop_reason', '?')} at {fmt(stage.get('duration_s'), 2)} s"
    threads = metrics.get("threads")
    backend = f"{metrics.get('backend', '?')} {threads}T" if threads else metrics.get("backend", "?")
    return (f"| `{label}` | {fmt(slope.get('first_failure_time_s'), 2)} | {', '.join(later) or '–'} | "
            f"{fmt(final.get('sliding_area_m2'), 0)} | {fmt(final.get('run_out_m'))} | "
            f"{fmt(final.get('max_displacement_m'))} | {ended} | {metrics.get('steps', '–')} | "
            f"{fmt(metrics.get('wall_s'), 0)} ({backend}) | {fmt((metrics.get('mp_updates_per_s') or 0) / 1e6, 2)} |")


TABLE_HEADER = ("| case | first failure (s) | later slides (s) | final sliding area (m²) | run-out (m) "
                "| max displacement (m) | stage ended | steps | wall (s) | MP-updates/s (millions) |\n"
                "|---|--:|---|--:|--:|--:|---|--:|--:|--:|\n")


def main(argv=None):
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("dirs", nargs="+", help="results folders")
    p.add_argument("--out", required=True, help="output PNG")
    p.add_argument("--table", help="also write a Markdown table of the cases to this file")
    p.add_argument("--recompute", action="store_true",
                   help="analyse particles.h5 even where metrics.json has a 'slope' key")
    sm.add_options(p)
    args = p.parse_args(argv)

    def body():
        toe, opts = sm.options_from(args)
        cases = [case_series(d, args.recompute, args.stage, toe, opts) for d in args.dirs]
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        labels = [c[0] for c in cases]
        fig, (ax_a, ax_r) = plt.subplots(2, 1, figsize=(8.0, 6.5), sharex=True,
                                         constrained_layout=True)
        for k, ((label, slope), d) in enumerate(zip(cases, args.dirs)):
            if labels.count(label) > 1:
                label = f"{label} ({os.path.basename(os.path.normpath(d))})"
            s = slope["series"]
            t = np.array(s["time_s"], dtype=float)
            area = np.array([np.nan if v is None else v for v in s["sliding_area_m2"]], dtype=float)
            ro = np.array([np.nan if v is None else v for v in s["run_out_m"]], dtype=float)
            color = f"C{k % 10}"
            ax_a.plot(t, area, color=color, lw=1.3, label=f"{label} (stage '{slope.get('stage')}')")
            ax_r.plot(t, ro, color=color, lw=1.3, label=label)
            t0 = slope.get("first_failure_time_s")
            if t0 is not None:
                i = int(np.argmin(np.abs(t - t0)))
                ax_a.plot([t[i]], [area[i]], "o", color=color, ms=4)
            for sl in slope.get("slides", [])[1:]:
                ax_a.axvline(sl["time_s"], color=color, lw=0.5, ls=":")
        ax_a.set_ylabel("sliding area (m²)")
        ax_a.set_title("sliding area (dot: first failure, dotted: later slides)", fontsize=9)
        ax_a.legend(fontsize=7)
        ax_a.grid(alpha=0.3)
        ax_r.axhline(0.0, color="0.6", lw=0.5)
        ax_r.set_ylabel("run-out (m)")
        ax_r.set_xlabel("time since the start of the analysed stage (s)")
        ax_r.set_title("run-out: largest x of a sliding point minus the toe x", fontsize=9)
        ax_r.grid(alpha=0.3)
        out_dir = os.path.dirname(os.path.abspath(args.out))
        if not os.path.isdir(out_dir):
            raise sm.InputError(f"{out_dir}: output folder not found")
        try:
            fig.savefig(args.out, dpi=110)
        except OSError as e:
            raise sm.InputError(f"{args.out}: cannot write ({e})")
        plt.close(fig)
        if args.table:
            rows = [table_row(label, slope, sm.read_metrics(d, required=True))
                    for (label, slope), d in zip(cases, args.dirs)]
            try:
                with open(args.table, "w") as f:
                    f.write(TABLE_HEADER + "\n".join(rows) + "\n")
            except OSError as e:
                raise sm.InputError(f"{args.table}: cannot write ({e})")
        print(f"wrote {args.out} ({os.path.getsize(args.out) / 1024:.0f} kB)")

    return sm.run_reporting_errors("slope_summary", body)


if __name__ == "__main__":
    sys.exit(main())
