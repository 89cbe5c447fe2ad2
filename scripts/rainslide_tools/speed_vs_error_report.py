"""The report of the speed-versus-error sweep (speed_vs_error.py): Pareto
fronts, the tables of docs/speed-vs-error.md, the figure and runs.json/csv."""
import csv
import json
import math
import os

import numpy as np

# --------------------------------------------------------------------------- #
# Pareto front, tables, figures.


def pareto(records):
    """Runs not dominated in (wall_s, error): no other run is at least as
    fast and at least as accurate and strictly better in one of the two."""
    ok = [r for r in records if r.get("status") == "completed" and r.get("error") is not None]
    front = []
    for r in ok:
        dominated = any(o is not r and o["wall_s"] <= r["wall_s"] and o["error"] <= r["error"]
                        and (o["wall_s"] < r["wall_s"] or o["error"] < r["error"]) for o in ok)
        if not dominated:
            front.append(r)
    return sorted(front, key=lambda r: r["wall_s"])


def label(r):
    if r["problem"] == "terzaghi":
        return (f"{r['cells']} cells, {r['points_per_cell']}x{r['points_per_cell']} pts, "
                f"K_w {r['bulk_modulus_pa']:.0e}, C {r['courant_number']}")
    return (f"{r['cells']} cells, K_w {r['bulk_modulus_pa']:.0e}, "
            f"f {r['inertia_scaling']:.0e}, C {r['courant_number']}")


def short_label(r):
    if r["problem"] == "terzaghi":
        return f"{r['cells']}c {r['points_per_cell']}p K{r['bulk_modulus_pa']:.0e} C{r['courant_number']}"
    return f"{r['cells']}c K{r['bulk_modulus_pa']:.0e} f{r['inertia_scaling']:.0e} C{r['courant_number']}"


def fmt(x, spec):
    return "–" if x is None else format(x, spec)


STUDIES = ("terzaghi", "liakopoulos", "liakopoulos_geq")
TITLES = {"terzaghi": "Terzaghi",
          "liakopoulos": "Liakopoulos (geostatic stage as in the case)",
          "liakopoulos_geq": "Liakopoulos (equilibrated geostatic stage)"}


def study_of(r):
    return r.get("study", r["problem"])


def tables(records, total_s):
    out = []
    bad = [r for r in records if r.get("status") != "completed"]
    counts = ", ".join(f"{sum(study_of(r) == s for r in records)} {TITLES[s]}" for s in STUDIES)
    out.append(f"Runs: {len(records)} ({counts}), {len(bad)} not completed; sum of the runs' wall_s "
               f"{sum(r.get('wall_s') or 0 for r in records):.0f} s, sweep wall time {total_s:.0f} s.\n")

    tz = [r for r in records if study_of(r) == "terzaghi"]
    conv = sorted([r for r in tz if "convergence" in r["groups"]], key=lambda r: r["cells"])
    if conv:
        out.append("### Terzaghi convergence (2x2 points, K_w = 2e9 Pa, Courant 0.5)\n")
        out.append("| cells | h (m) | points | L2 points | order | L2 cell means | order | wall (s) | steps | MP-updates/s |")
        out.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        prev = None
        for r in conv:
            if r.get("status") != "completed":
                out.append(f"| {r['cells']} | {1.0 / r['cells']:.4g} | – | failed | | | | | | |")
                prev = None
                continue
            o1 = o2 = ""
            if prev is not None:
                ratio = r["cells"] / prev["cells"]
                o1 = f"{math.log(prev['l2_error_max'] / r['l2_error_max']) / math.log(ratio):.2f}"
                o2 = f"{math.log(prev['l2_error_cell_max'] / r['l2_error_cell_max']) / math.log(ratio):.2f}"
            out.append(f"| {r['cells']} | {1.0 / r['cells']:.4g} | {r['n_particles']} | {r['l2_error_max']:.4f} | {o1} | "
                       f"{r['l2_error_cell_max']:.5f} | {o2} | {r['wall_s']:.2f} | {r['steps']} | "
                       f"{r['mp_updates_per_s']:.3g} |")
            prev = r
        out.append("")

    for study in STUDIES:
        rows = [r for r in records if study_of(r) == study]
        if not rows:
            continue
        front = pareto(rows)
        ids = {r["id"] for r in front}
        title = TITLES[study]
        terz = study == "terzaghi"
        out.append(f"### {title}: Pareto front (error vs wall time)\n")
        if terz:
            out.append("| cells | points | K_w (Pa) | Courant | error (L2 cell means vs K_w = 2e9) | L2 points vs K_w = 2e9 | wall (s) |")
            out.append("|---:|---:|---:|---:|---:|---:|---:|")
            for r in front:
                out.append(f"| {r['cells']} | {r['points_per_cell']}x{r['points_per_cell']} | {r['bulk_modulus_pa']:.0e} | "
                           f"{r['courant_number']} | {r['error']:.5f} | {r['l2_error_max_vs_ref_kw']:.4f} | {r['wall_s']:.2f} |")
        else:
            out.append("| cells | K_w (Pa) | f | Courant | error | cell rel. | outflow rel. | point rel. | settlement rel. | wall (s) |")
            out.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
            for r in front:
                out.append(f"| {r['cells']} | {r['bulk_modulus_pa']:.0e} | {r['inertia_scaling']:.0e} | {r['courant_number']} | "
                           f"{r['error']:.4f} | {r['cell_relative_error_max']:.4f} | {r['outflow_relative_error_max']:.4f} | "
                           f"{r['relative_error_max']:.4f} | {r['settlement_120min_relative_error']:.3f} | {r['wall_s']:.2f} |")
        out.append("")
        out.append(f"### {title}: all runs (P = on the Pareto front)\n")
        if terz:
            out.append("| cells | points | K_w (Pa) | Courant | L2 points | L2 cells | L2 cells vs K_w = 2e9 | L2 points vs K_w = 2e9 | wall (s) | steps | MP-updates/s | P |")
            out.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:-:|")
            key = lambda r: (r["cells"], r["points_per_cell"], -r["bulk_modulus_pa"], r["courant_number"])
        else:
            out.append("| cells | K_w (Pa) | f | Courant | point rel. | cell rel. | outflow rel. | error | settl. 120 min (mm) | settl. rel. | geostatic end (s) | wall (s) | steps | MP-updates/s | P |")
            out.append("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|:-:|")
            key = lambda r: (r["cells"], -r["bulk_modulus_pa"], r["inertia_scaling"], r["courant_number"])
        for r in sorted(rows, key=key):
            mark = "P" if r["id"] in ids else ""
            if r.get("status") != "completed":
                if terz:
                    out.append(f"| {r['cells']} | {r['points_per_cell']}x{r['points_per_cell']} | {r['bulk_modulus_pa']:.0e} | "
                               f"{r['courant_number']} | {r.get('status')} | | | | | | | |")
                else:
                    out.append(f"| {r['cells']} | {r['bulk_modulus_pa']:.0e} | {r['inertia_scaling']:.0e} | {r['courant_number']} | "
                               f"{r.get('status')} | | | | | | | | | | |")
                continue
            if terz:
                out.append(f"| {r['cells']} | {r['points_per_cell']}x{r['points_per_cell']} | {r['bulk_modulus_pa']:.0e} | "
                           f"{r['courant_number']} | {r['l2_error_max']:.4f} | {r['l2_error_cell_max']:.5f} | "
                           f"{r['l2_error_cell_max_vs_ref_kw']:.5f} | {r['l2_error_max_vs_ref_kw']:.4f} | {r['wall_s']:.2f} | "
                           f"{r['steps']} | {r['mp_updates_per_s']:.3g} | {mark} |")
            else:
                geo = r.get("geostatic_end_s")
                conv_mark = "" if r.get("geostatic_converged", True) else " (max)"
                out.append(f"| {r['cells']} | {r['bulk_modulus_pa']:.0e} | {r['inertia_scaling']:.0e} | {r['courant_number']} | "
                           f"{r['relative_error_max']:.4f} | {r['cell_relative_error_max']:.4f} | "
                           f"{r['outflow_relative_error_max']:.4f} | {r['error']:.4f} | {1e3 * r['settlement_120min_m']:.3f} | "
                           f"{r['settlement_120min_relative_error']:.3f} | {fmt(geo, '.1f')}{conv_mark} | "
                           f"{r['wall_s']:.2f} | {r['steps']} | {r['mp_updates_per_s']:.3g} | {mark} |")
        out.append("")
    if bad:
        out.append("### Runs that did not complete\n")
        for r in bad:
            out.append(f"* `{r['id']}` ({r.get('status')}): `{r.get('command')}`\n\n```\n{r.get('output', '').strip()}\n```\n")
    return "\n".join(out) + "\n"


def place_labels(ax, points, texts, min_gap=0.05):
    """Labels to the right of the points, pushed apart vertically (axes
    fraction) so that they do not overlap; a thin line joins a moved label."""
    fig = ax.figure
    fig.canvas.draw()
    to_axes = ax.transAxes.inverted()
    pos = [to_axes.transform(ax.transData.transform(p)) for p in points]
    order = sorted(range(len(points)), key=lambda i: -pos[i][1])
    ys = {}
    last = None
    for i in order:
        y = pos[i][1] + 0.02
        if last is not None and y > last - min_gap:
            y = last - min_gap
        ys[i] = y
        last = y
    # If the lowest label fell out of the axes, shift the stack up.
    low = min(ys.values()) if ys else 0.0
    if low < 0.02:
        for i in ys:
            ys[i] += 0.02 - low
    for i, text in enumerate(texts):
        x = min(pos[i][0] + 0.04, 0.80)
        moved = abs(ys[i] - pos[i][1]) > 0.03 or x < pos[i][0] + 0.02
        ax.annotate(text, xy=points[i], xycoords="data", xytext=(x, ys[i]), textcoords="axes fraction",
                    fontsize=7, color="crimson", va="center", zorder=3.5,
                    bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.75),
                    arrowprops=dict(arrowstyle="-", color="crimson", lw=0.5, alpha=0.6) if moved else None)


def figures(records, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    studies = [s for s in STUDIES if any(study_of(r) == s for r in records)]
    conv = sorted([r for r in records if study_of(r) == "terzaghi" and "convergence" in r["groups"]
                   and r.get("status") == "completed"], key=lambda r: r["cells"])
    n_panels = len(studies) + (1 if len(conv) >= 2 else 0)
    ncols = 2 if n_panels > 1 else 1
    nrows = (n_panels + ncols - 1) // ncols
    fig, axes = plt.subplots(nrows, ncols, figsize=(7.2 * ncols, 5.6 * nrows), squeeze=False)
    flat = list(axes.flat)
    for ax in flat[n_panels:]:
        ax.set_visible(False)
    for ax, study in zip(flat, studies):
        rows = [r for r in records if study_of(r) == study and r.get("status") == "completed"]
        front = pareto(rows)
        ids = {r["id"] for r in front}
        terz = study == "terzaghi"
        if terz:
            colour_key, ckey_name = "bulk_modulus_pa", "K_w (Pa)"
        else:
            colour_key, ckey_name = "inertia_scaling", "inertia scaling f"
        values = sorted({r[colour_key] for r in rows}, reverse=terz)
        cmap = plt.get_cmap("viridis")
        colours = {v: cmap(i / max(1, len(values) - 1) * 0.85) for i, v in enumerate(values)}
        markers = {10: "o", 20: "s", 40: "^", 80: "D"}
        for r in rows:
            if r["id"] in ids:
                continue
            ax.scatter(r["wall_s"], r["error"], s=26, marker=markers.get(r["cells"], "x"),
                       color=colours[r[colour_key]], alpha=0.55, linewidths=0)
        fx = [r["wall_s"] for r in front]
        fy = [r["error"] for r in front]
        ax.step(fx, fy, where="post", color="crimson", lw=1.2, zorder=3)
        for r in front:
            ax.scatter(r["wall_s"], r["error"], s=70, marker=markers.get(r["cells"], "x"),
                       color=colours[r[colour_key]], edgecolors="crimson", linewidths=1.6, zorder=4)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.25)
        ax.set_xlabel("wall time (s), serial backend, 1 thread")
        ax.set_title(TITLES[study], fontsize=10)
        if terz:
            ax.set_ylabel("max relative L2 error of cell-mean p_w\n(vs series solution with K_w = 2e9 Pa)")
        else:
            ax.set_ylabel("max(cell-mean p_w error / top suction,\noutflow relative error) vs OpenGeoSys")
        handles = [Line2D([], [], ls="", marker="o", color=colours[v], label=f"{ckey_name} = {v:.0e}") for v in values]
        handles += [Line2D([], [], ls="", marker=markers[c], color="grey", label=f"{c} cells")
                    for c in sorted({r["cells"] for r in rows}) if c in markers]
        handles.append(Line2D([], [], ls="-", marker="o", color="crimson", mfc="none", label="Pareto front"))
        ax.legend(handles=handles, fontsize=7.5, loc="upper right", framealpha=0.85)
        place_labels(ax, [(r["wall_s"], r["error"]) for r in front], [short_label(r) for r in front])
    if len(conv) >= 2:
        ax = flat[len(studies)]
        h = np.array([1.0 / r["cells"] for r in conv])
        e1 = np.array([r["l2_error_max"] for r in conv])
        e2 = np.array([r["l2_error_cell_max"] for r in conv])
        ax.loglog(h, e1, "o-", label="point-wise L2 (l2_error_max)")
        ax.loglog(h, e2, "s-", label="cell-mean L2 (l2_error_cell_max)")
        ax.loglog(h, e1[0] * (h / h[0]), "k:", lw=0.8, label="slope 1")
        ax.loglog(h, e2[0] * (h / h[0]) ** 2, "k--", lw=0.8, label="slope 2")
        for hi, r in zip(h, conv):
            ax.annotate(f"{r['cells']} cells, {r['wall_s']:.1f} s", (hi, r["l2_error_max"]),
                        textcoords="offset points", xytext=(4, 6), fontsize=7)
        ax.set_xlabel("cell size h (m)")
        ax.set_ylabel("max relative L2 error over Tv = 0.05 ... 1")
        ax.set_title("Terzaghi convergence (2x2 points, K_w = 2e9 Pa, Courant 0.5)", fontsize=10)
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=8, loc="lower right")
    fig.suptitle("rainslide speed vs error (2-core machine, serial backend). Pareto labels: cells (c), "
                 "points per direction (p), water bulk modulus K_w (K), inertia scaling (f), Courant number (C)",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def write_outputs(out_root, records, meta, png):
    with open(os.path.join(out_root, "runs.json"), "w") as f:
        json.dump({"meta": meta, "runs": records}, f, indent=2)
    cols = ["id", "problem", "study", "groups", "status", "geostatic", "cells", "points_per_cell", "bulk_modulus_pa",
            "courant_number", "inertia_scaling", "error", "l2_error_max", "l2_error_cell_max",
            "l2_error_cell_max_vs_ref_kw", "l2_error_max_vs_ref_kw", "relative_error_max",
            "cell_relative_error_max", "outflow_relative_error_max", "settlement_120min_m", "settlement_120min_relative_error", "geostatic_end_s", "wall_s",
            "cpu_s", "process_wall_s", "steps", "dt_s", "mp_updates_per_s", "n_particles", "backend",
            "threads", "load_average_1min_before", "pareto"]
    fronts = {r["id"] for st in STUDIES for r in pareto([x for x in records if study_of(x) == st])}
    with open(os.path.join(out_root, "runs.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for r in records:
            row = []
            for c in cols:
                v = r.get(c)
                if c == "pareto":
                    v = int(r["id"] in fronts)
                elif c == "groups":
                    v = "+".join(v)
                row.append("" if v is None else v)
            w.writerow(row)
    with open(os.path.join(out_root, "tables.md"), "w") as f:
        f.write(tables(records, meta.get("sweep_wall_s_total", meta.get("sweep_wall_s", 0.0))))
    figures(records, png)
