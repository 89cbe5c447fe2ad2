#!/usr/bin/python3
"""Side-by-side panel of slope runs against the paper's Fig. 7 sequence.

Usage: study_panel.py OUT.png LABEL=DIR [LABEL=DIR ...] [--frame LABEL=deg,dx,dy]

One column per time of the paper's description (10, 16.25, 18.75, 25 s of
rain), one row per run: the material points at that time (positions mapped
back to the case's frame for a rotated model), grey where the soil still
holds suction (p_w < -25 kPa), blue where the front has passed, and the
plastic shear strain eps_p_bar > 0.05 over them in red (the slide bands).
The top row quotes what the paper describes at that time (§3.2, Fig. 7).
Each run's sliding area (slope_metrics.py, if analysed) is in its row label.
Errors in the input give one line "study_panel: error: ..." and exit code 2.
"""
import argparse
import json
import os
import sys

import numpy as np

from rainslide_tools.slope_run import Frame, InputError, Run, run_reporting_errors

PAPER = (
    (10.0, "initial superficial failure at the\nslope surface near its steepest part,\n"
           "where it is fully saturated"),
    (16.25, "a wedge formed through saturated\nand unsaturated soil; the saturated\n"
            "soil further upslope fails"),
    (18.75, "retrogression continues: a further\nfailure initiates upslope"),
    (25.0, "failure developed throughout the\nfull length of the slope (a series\n"
           "of individual failures)"),
)
WET_PA = -25.0e3
SLIDE_EPS = 0.05


def parse_pairs(values, what):
    pairs = []
    for v in values:
        if "=" not in v:
            raise InputError(f"{what}: expected LABEL=VALUE, got '{v}'")
        label, value = v.split("=", 1)
        pairs.append((label, value))
    return pairs


def sliding_area(run_dir):
    try:
        with open(os.path.join(run_dir, "metrics.json")) as f:
            slope = json.load(f).get("slope") or {}
    except (OSError, ValueError):
        return None
    return (slope.get("final") or {}).get("sliding_area_m2")


def draw_run(axes, run, label):
    for ax, (t, _) in zip(axes, PAPER):
        snap = run.nearest(t)
        act = run.active(snap)
        x = run.field(snap, "x")[act]
        eps = run.field(snap, "plastic_shear_strain")[act]
        wet = (run.field(snap, "pore_pressure")[act] >= WET_PA) if run.two_phase \
            else np.zeros(len(x), dtype=bool)
        ax.scatter(x[~wet, 0], x[~wet, 1], s=0.6, c="0.7", lw=0)
        ax.scatter(x[wet, 0], x[wet, 1], s=0.6, c="tab:blue", lw=0)
        band = eps > SLIDE_EPS
        ax.scatter(x[band, 0], x[band, 1], s=0.8, c="tab:red", lw=0)
        ax.set_aspect("equal")
        ax.set_xlim(0, 75)
        ax.set_ylim(-1, 21)
        ax.set_title(f"{snap.t:.2f} s", fontsize=8)
        ax.tick_params(labelsize=6)
    axes[0].set_ylabel(label, fontsize=7)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out")
    p.add_argument("runs", nargs="+", help="LABEL=DIR")
    p.add_argument("--frame", action="append", default=[], help="LABEL=deg,dx,dy")
    args = p.parse_args()

    def body():
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        runs = parse_pairs(args.runs, "runs")
        frames = dict(parse_pairs(args.frame, "--frame"))
        fig, axs = plt.subplots(len(runs) + 1, len(PAPER), figsize=(16, 1.0 + 2.2 * len(runs)),
                                squeeze=False,
                                gridspec_kw={"height_ratios": [0.45] + [1.0] * len(runs)})
        for ax, (t, text) in zip(axs[0], PAPER):
            ax.axis("off")
            ax.text(0.0, 0.5, f"paper, {t:g} s:\n{text}", fontsize=8, va="center")
        for row, (label, run_dir) in zip(axs[1:], runs):
            frame = Frame.parse(frames[label]) if label in frames else None
            run = Run(run_dir, frame=frame)
            try:
                area = sliding_area(run_dir)
                name = label + ("" if area is None else f"\n(final sliding {area:.0f} m²)")
                draw_run(row, run, name)
            finally:
                run.close()
        fig.suptitle("The paper's sequence (top) against the runs: grey unsaturated, blue "
                     f"wetted (p_w >= {WET_PA / 1e3:g} kPa), red eps_p_bar > {SLIDE_EPS:g}",
                     fontsize=9)
        fig.tight_layout()
        try:
            fig.savefig(args.out, dpi=130)
        except OSError as e:
            raise InputError(f"{args.out}: cannot write ({e})")
        print(f"written {args.out}")

    return run_reporting_errors("study_panel", body)


if __name__ == "__main__":
    sys.exit(main())
