#!/usr/bin/python3
"""How much a run's probed points fluctuate: pore pressure and velocity about
their running means.

For each probe of each run's probes.csv (rows every [probes] interval_s, set
it to a fraction of a millisecond to see the explicit scheme's undrained
ringing), over the rows of the last stage: the mean p_w, the RMS and the
largest deviation of p_w from its running mean over --window-s (centred), the
mean speed of the solid and the RMS of its velocity's deviation from the
running mean, and the growth of the equivalent plastic strain
(docs/speed-vs-error.md compares the two schemes' toe with it).

  scripts/probe_fluctuations.py RUN [RUN ...] [--window-s 0.02] [--json]

RUN is a run's output folder (holding probes.csv) or the CSV file itself.
Errors in the input give one line "probe_fluctuations: error: ..." and exit
code 2.
"""
import argparse
import json
import os
import sys

import numpy as np

from rainslide_tools.slope_run import InputError, read_probes, run_reporting_errors

# The columns read, in the order of a probe's values (without stage and name).
COLUMNS = ("time_s", "stage", "name", "p_w_pa", "v_x_m_per_s", "v_y_m_per_s",
           "eps_p_bar")
VALUES = tuple(c for c in COLUMNS if c not in ("stage", "name"))


def probe_series(path):
    """Rows of the last stage, per probe name: time, p_w, v_x, v_y, eps_p."""
    if os.path.isdir(path):
        path = os.path.join(path, "probes.csv")
    rows = read_probes(path, COLUMNS)
    if not rows:
        raise InputError(f"{path}: no probe rows")
    last_stage = rows[-1]["stage"]
    series = {}
    for r in rows:
        if r["stage"] == last_stage:
            series.setdefault(r["name"], []).append(tuple(r[c] for c in VALUES))
    return path, {k: np.array(v) for k, v in series.items()}


def fluctuations(a, window_s):
    """Statistics of one probe's rows (time, p_w, v_x, v_y, eps_p)."""
    t, p_w, v, eps_p = a[:, 0], a[:, 1], a[:, 2:4], a[:, 4]
    speed = np.hypot(v[:, 0], v[:, 1])
    interval = np.median(np.diff(t)) if len(t) > 1 else window_s
    width = max(1, int(round(window_s / interval))) | 1  # odd, centred
    stats = {"rows": int(len(t)), "interval_s": float(interval),
             "p_w_mean_pa": float(p_w.mean()),
             "speed_mean_m_per_s": float(speed.mean()),
             "eps_p_growth": float(eps_p[-1] - eps_p[0])}
    stats["p_w_fluctuation_rms_pa"] = None
    stats["p_w_fluctuation_max_pa"] = None
    stats["velocity_fluctuation_rms_m_per_s"] = None
    if len(t) > width:
        p_w_dev = deviation(p_w, width)
        v_dev = np.hypot(deviation(v[:, 0], width), deviation(v[:, 1], width))
        stats["p_w_fluctuation_rms_pa"] = float(np.sqrt((p_w_dev ** 2).mean()))
        stats["p_w_fluctuation_max_pa"] = float(np.abs(p_w_dev).max())
        stats["velocity_fluctuation_rms_m_per_s"] = float(
            np.sqrt((v_dev ** 2).mean()))
    return stats


def deviation(values, width):
    """values minus their centred running mean over `width` rows (the rows
    a full window covers)."""
    mean = np.convolve(values, np.ones(width) / width, mode="valid")
    return values[width // 2:len(values) - width // 2] - mean


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--window-s", type=float, default=0.02,
                        help="running-mean window, s (default 0.02)")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()

    def body():
        if not args.window_s > 0:
            raise InputError(f"--window-s must be > 0 s, got {args.window_s}")
        result = {}
        for run in args.runs:
            path, series = probe_series(run)
            result[path] = {name: fluctuations(a, args.window_s)
                            for name, a in series.items()}
        report(result, args.json)

    return run_reporting_errors("probe_fluctuations", body)


def report(result, as_json):
    """The statistics as JSON or as a Markdown table."""
    if as_json:
        print(json.dumps(result, indent=1))
        return
    print("| run | probe | rows | p_w mean kPa | p_w fluctuation RMS kPa | largest kPa"
          " | speed mean mm/s | velocity fluctuation RMS mm/s | eps_p growth |")
    print("|---|---|--:|--:|--:|--:|--:|--:|--:|")
    for path, probes in result.items():
        for name, s in probes.items():
            rms = s["p_w_fluctuation_rms_pa"]
            top = s["p_w_fluctuation_max_pa"]
            v_rms = s["velocity_fluctuation_rms_m_per_s"]
            print(f"| {path} | {name} | {s['rows']} | {s['p_w_mean_pa'] / 1e3:.2f}"
                  f" | {'-' if rms is None else f'{rms / 1e3:.2f}'}"
                  f" | {'-' if top is None else f'{top / 1e3:.2f}'}"
                  f" | {s['speed_mean_m_per_s'] * 1e3:.2f}"
                  f" | {'-' if v_rms is None else f'{v_rms * 1e3:.2f}'}"
                  f" | {s['eps_p_growth']:.2e} |")


if __name__ == "__main__":
    sys.exit(main())
