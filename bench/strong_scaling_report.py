#!/usr/bin/python3
"""Strong-scaling table of the rainslide benchmarks (standard library only).

Reads Google Benchmark JSON files written by bench/strong_scaling.sh (one per
OpenMP thread count), takes the median over the repetitions, writes a JSON
summary and prints a Markdown table of material-point updates per second.

Benchmark names are <kernel>/<backend>/<scatter>/cells_high:<n>/real_time with
scatter = plain | duplicated | atomic | none.
"""

import argparse
import json
import sys

KERNELS = ["p2g", "p2g_overhead", "grid_update", "g2p", "remap", "stress_update", "step"]
KERNEL_LABELS = {
    "p2g": "P2G (mass, momentum, force)",
    "p2g_overhead": "P2G fixed cost only (grid reset + ScatterView create/contribute, no point loop)",
    "grid_update": "grid update (active nodes + dry update)",
    "g2p": "G2P (velocity)",
    "remap": "MUSL remap (p2gMomentum + remapVelocity)",
    "stress_update": "stress update (vel. gradient + Mohr-Coulomb)",
    "step": "whole step (Simulation::advance)",
}


def parse_name(name):
    """(kernel, backend, scatter, cells_high) of a benchmark name, or None."""
    parts = name.split("/")
    if len(parts) < 4 or not parts[3].startswith("cells_high:"):
        return None
    return parts[0], parts[1], parts[2], int(parts[3].split(":")[1])


def load_runs(path):
    """Median (or single-run) entries of one Google Benchmark JSON file."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    runs = {}
    cvs = {}
    for b in data.get("benchmarks", []):
        if "error_occurred" in b and b["error_occurred"]:
            continue
        key = parse_name(b.get("run_name", b["name"]))
        if key is None:
            continue
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                runs[key] = b
            elif b.get("aggregate_name") == "cv":
                cvs[key] = b.get("real_time")
        elif key not in runs:
            runs[key] = b
    return data.get("context", {}), runs, cvs


def fmt_rate(value):
    return "—" if value is None else f"{value / 1e6:.2f}"


def fmt_ratio(num, den):
    if num is None or den is None or den == 0:
        return "—"
    return f"{num / den:.2f}×"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("inputs", nargs="+", help="raw_nt<N>.json files")
    parser.add_argument("--output", required=True)
    parser.add_argument("--repetitions", type=int, default=0)
    parser.add_argument("--min-time", type=float, default=0.0)
    parser.add_argument("--filter", default=".")
    args = parser.parse_args()

    # results[(kernel, n)][(backend, scatter, threads)] = entry
    results = {}
    points = {}
    contexts = {}
    for path in args.inputs:
        context, runs, cvs = load_runs(path)
        threads = int(context.get("openmp_threads", "0"))
        contexts[str(threads)] = context
        for (kernel, backend, scatter, n), b in runs.items():
            t = 1 if backend == "Serial" else threads
            entry = {
                "mp_updates_per_s": b.get("items_per_second"),
                "real_time": b.get("real_time"),
                "time_unit": b.get("time_unit"),
                "cv_real_time": cvs.get((kernel, backend, scatter, n)),
                "yielded_fraction": b.get("yielded"),
            }
            slot = results.setdefault((kernel, n), {})
            # Serial is run once; keep the first (1-thread run) if repeated.
            slot.setdefault((backend, scatter, t), entry)
            points[(kernel, n)] = int(b.get("points", 0))

    def rate(slot, backend, scatters, threads):
        for s in scatters:
            e = slot.get((backend, s, threads))
            if e is not None:
                return e["mp_updates_per_s"]
        return None

    rows = []
    summary = []
    order = sorted(
        results,
        key=lambda k: (KERNELS.index(k[0]) if k[0] in KERNELS else 99, k[1]),
    )
    for kernel, n in order:
        slot = results[(kernel, n)]
        serial = rate(slot, "Serial", ["plain", "none"], 1)
        dup1 = rate(slot, "OpenMP", ["duplicated", "none"], 1)
        dup2 = rate(slot, "OpenMP", ["duplicated", "none"], 2)
        atom1 = rate(slot, "OpenMP", ["atomic"], 1)
        atom2 = rate(slot, "OpenMP", ["atomic"], 2)
        no_scatter = any(k[1] == "none" for k in slot)
        summary.append(
            {
                "kernel": kernel,
                "cells_high": n,
                "points": points[(kernel, n)],
                "scatter": not no_scatter,
                "serial": slot.get(("Serial", "plain", 1))
                or slot.get(("Serial", "none", 1)),
                "openmp_default": {
                    str(t): slot.get(("OpenMP", "duplicated", t))
                    or slot.get(("OpenMP", "none", t))
                    for t in (1, 2)
                },
                "openmp_atomic": {
                    str(t): slot.get(("OpenMP", "atomic", t)) for t in (1, 2)
                },
                "speedup_default_2_over_1": dup2 / dup1 if dup1 and dup2 else None,
                "speedup_atomic_2_over_1": atom2 / atom1 if atom1 and atom2 else None,
                "speedup_default_2_over_serial": dup2 / serial
                if serial and dup2
                else None,
            }
        )
        label = KERNEL_LABELS.get(kernel, kernel)
        rows.append(
            f"| {label} | {points[(kernel, n)]:,} | {fmt_rate(serial)} "
            f"| {fmt_rate(dup1)} | {fmt_rate(dup2)} | {fmt_ratio(dup2, dup1)} "
            f"| {fmt_ratio(dup2, serial)} "
            f"| {fmt_rate(atom1)} | {fmt_rate(atom2)} | {fmt_ratio(atom2, atom1)} |"
        )

    out = {
        "description": "Median material-point updates per second; "
        "speed-ups are 2 threads over 1 thread (strong scaling) "
        "and 2 threads over Serial",
        "settings": {
            "repetitions": args.repetitions,
            "min_time_s": args.min_time,
            "filter": args.filter,
            "inputs": [path.rsplit("/", 1)[-1] for path in args.inputs],
            "OMP_PROC_BIND": "spread",
            "OMP_PLACES": "threads",
        },
        "context": contexts,
        "results": summary,
    }
    with open(args.output, "w", encoding="utf-8") as f:
        json.dump(out, f, indent=2)
        f.write("\n")

    print(
        "Material-point updates per second, millions (median of "
        f"{args.repetitions} repetitions). OpenMP default = ScatterDuplicated "
        "for scatter kernels (no scatter in grid update, G2P, stress update); "
        "atomic = ScatterNonDuplicated.\n"
    )
    print(
        "| kernel | points | Serial | OpenMP default 1T | OpenMP default 2T "
        "| speed-up 2T/1T | 2T vs Serial | OpenMP atomic 1T | OpenMP atomic 2T "
        "| atomic 2T/1T |"
    )
    print("|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    for row in rows:
        print(row)
    print(f"\nwritten: {args.output}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
