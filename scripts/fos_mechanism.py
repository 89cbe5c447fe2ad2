#!/usr/bin/python3
"""Figure of the failure mechanism written by `rainslide fos`.

Usage: fos_mechanism.py DIR [--out PNG]

Reads DIR/fos.json and DIR/mechanism.h5 (the points at the end of the
smallest failing trial) and draws two panels at the points' positions:
the displacement magnitude of that trial (m) and the plastic shear strain
eps_p_bar. Writes PNG (default DIR/mechanism.png). Errors in the input give
one line "fos_mechanism: error: ..." and exit code 2.
"""
import argparse
import json
import os
import sys

import numpy as np


def fail(message):
    print(f"fos_mechanism: error: {message}", file=sys.stderr)
    sys.exit(2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    try:
        with open(os.path.join(args.dir, "fos.json")) as f:
            fos = json.load(f)
    except (OSError, ValueError) as error:
        fail(f"cannot read {args.dir}/fos.json: {error}")
    if "mechanism" not in fos:
        fail(f"{args.dir}/fos.json: no trial failed, so there is no mechanism")
    import h5py
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    path = os.path.join(args.dir, fos["mechanism"]["hdf5"])
    try:
        with h5py.File(path, "r") as f:
            snapshots = f["snapshots"]
            last = snapshots[sorted(snapshots.keys())[-1]]
            x = last["x"][:]
            u = np.hypot(last["displacement"][:, 0], last["displacement"][:, 1])
            eps = last["plastic_shear_strain"][:]
    except (OSError, KeyError) as error:
        fail(f"cannot read {path}: {error}")
    fig, axes = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
    for ax, value, label in ((axes[0], u, "displacement (m)"),
                             (axes[1], eps, "plastic shear strain")):
        s = ax.scatter(x[:, 0], x[:, 1], c=value, s=4, marker="s",
                       cmap="viridis")
        fig.colorbar(s, ax=ax, label=label)
        ax.set_aspect("equal")
        ax.set_ylabel("y (m)")
    axes[1].set_xlabel("x (m)")
    fs = fos.get("factor_of_safety")
    title = (f"{fos.get('case', '')}: FS = {fs:.3f}" if fs is not None
             else f"{fos.get('case', '')}: {fos.get('status')}")
    axes[0].set_title(f"{title}; mechanism at F = {fos['mechanism']['factor']:.4g}")
    fig.tight_layout()
    out = args.out or os.path.join(args.dir, "mechanism.png")
    try:
        fig.savefig(out, dpi=120)
    except OSError as error:
        fail(f"cannot write {out}: {error}")
    print(out)


if __name__ == "__main__":
    main()
