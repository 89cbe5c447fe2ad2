#!/usr/bin/python3
"""Strong-scaling table of the rainslide benchmarks (standard library only).

Reads the Google Benchmark JSON files written by bench/strong_scaling.sh (one
per process: repetition x OpenMP thread count), takes the median of each
benchmark over the repetitions, writes a JSON summary and prints a Markdown
table of material-point updates per second.

Benchmark names are <kernel>/<backend>/<scatter>/cells_high:<n>/real_time with
scatter = plain | duplicated | atomic | none.
"""

import argparse
import json
import statistics
import sys

KERNELS = ["p2g", "p2g_grid_update", "g2p_remap", "point_update", "step",
           "step_dry", "step_saturated", "step_unsaturated"]
KERNEL_LABELS = {
    "p2g": "P2G (mass, momentum, force)",
    "p2g_grid_update": "P2G + grid update (takes the sums, dry update)",
    "g2p_remap": "G2P + MUSL remap (momentum scatter, remapped velocity)",
    "point_update": "last point loop (vel. gradient, Mohr-Coulomb, positions, diagnostics)",
    "step": "whole step (Simulation::advance)",
    "step_dry": "whole step, dry scene (soil block)",
    "step_saturated": "whole step, saturated two-phase scene",
    "step_unsaturated": "whole step, unsaturated two-phase scene (van Genuchten)",
}


def parse_name(name):
    """(kernel, backend, scatter, cells_high) of a benchmark name, or None."""
    parts = name.split("/")
    if len(parts) < 4 or not parts[3].startswith("cells_high:"):
        return None
    return parts[0], parts[1], parts[2], int(parts[3].split(":")[1])


def load_runs(path):
    """Context and {(kernel, backend, scatter, n): run} of one JSON file.

    A file holds one process's runs (one repetition) or, if run with
    Google Benchmark repetitions, their median aggregates.
    """
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    runs = {}
    for b in data.get("benchmarks", []):
        if b.get("error_occurred"):
            continue
        key = parse_name(b.get("run_name", b["name"]))
        if key is None:
            continue
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                runs[key] = b
        elif key not in runs:
            runs[key] = b
    return data.get("context", {}), runs


def median(values):
    return statistics.median(values) if values else None


def cv(values):
    if len(values) < 2:
        return None
    return statistics.stdev(values) / statistics.mean(values)


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

    # samples[(kernel, n)][(backend, scatter, threads)] = [run, ...], one run
    # per process (repetition).
    samples = {}
    points = {}
    contexts = {}
    for path in args.inputs:
        context, runs = load_runs(path)
        threads = int(context.get("openmp_threads", "0"))
        contexts.setdefault(str(threads), context)
        for (kernel, backend, scatter, n), b in runs.items():
            t = 1 if backend == "Serial" else threads
            slot = samples.setdefault((kernel, n), {})
            slot.setdefault((backend, scatter, t), []).append(b)
            points[(kernel, n)] = int(b.get("points", 0))

    # Median over the repetitions.
    results = {}
    for key, slot in samples.items():
        results[key] = {}
        for variant, runs in slot.items():
            rates = [r["items_per_second"] for r in runs]
            times = [r["real_time"] for r in runs]
            results[key][variant] = {
                "mp_updates_per_s": median(rates),
                "real_time": median(times),
                "time_unit": runs[0].get("time_unit"),
                "cv_rate": cv(rates),
                "repetitions": len(runs),
                "yielded_fraction": runs[0].get("yielded"),
            }

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
            "inputs": sorted(path.rsplit("/", 1)[-1] for path in args.inputs),
            "OMP_PROC_BIND": "spread",
            "OMP_PLACES": "threads",
        },
        "context": contexts,
        "results": summary,
    }
    reps = sorted(
        {v["repetitions"] for slot in results.values() for v in slot.values()}
    )
    cvs = [
        v["cv_rate"]
        for slot in results.values()
        for v in slot.values()
        if v["cv_rate"] is not None
    ]
    out["settings"]["repetitions_found"] = reps
    with open(args.output, "w", encoding="utf-8") as f:
        json.dump(out, f, indent=2)
        f.write("\n")

    print(
        "Material-point updates per second, millions (median of "
        f"{'/'.join(map(str, reps))} repetitions, each a separate process; "
        f"largest coefficient of variation {max(cvs) * 100 if cvs else 0:.0f}%, "
        f"median {statistics.median(cvs) * 100 if cvs else 0:.0f}%). "
        "OpenMP default = ScatterDuplicated "
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
