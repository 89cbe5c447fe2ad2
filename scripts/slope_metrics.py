#!/usr/bin/python3
"""Failure metrics of a rainslide slope run (Wang, Vardon & Hicks 2018, §3).

Usage: slope_metrics.py DIR [--stage NAME] [--toe-x 56.33|auto] [--json] [thresholds]

Reads DIR/particles.h5 (and DIR/metrics.json), analyses every snapshot of the
failure stage (default: the second stage, the rainfall of a slope case; the
only stage of a one-stage run such as the dry slope) and writes the result under
the key "slope" of DIR/metrics.json (via DIR/metrics.json.partial + os.replace).
A summary goes to stdout (--json: the whole "slope" object).

Definitions (also written into the JSON under "definition"):
  reference state  the points at the start of the stage: the snapshot that
                   ended the previous stage (same time_s), else x - displacement
                   of the stage's first snapshot (the positions at the last
                   displacement reset, i.e. the run start for a first stage);
  sliding point    active point with |x - x_ref| > disp_threshold (0.1 m) and
                   plastic_shear_strain > eps_threshold (0.05), or with
                   |x - x_ref| > moved_threshold (0.5 m);
  sliding group    sliding points linked by chains of neighbours closer than
                   link_factor (1.5) x the initial point spacing; a group
                   counts only if its area (sum of point volumes, m^2 in plane
                   strain) is at least min_group_area (1 m^2);
  sliding area     sum of the areas of the counted groups;
  first failure    the first snapshot of the stage with a counted group;
  later slide      a snapshot where (a) a counted group appears that is not
                   linked (link distance, current positions) to any point that
                   was in a counted group at an earlier snapshot, or (b) the
                   newly sliding area (points in counted groups never counted
                   before) grows faster than jump_rate (m^2/s) after a quiet
                   spell: once fired, rule (b) re-arms only after the rate has
                   stayed below jump_rate / 2 for quiet_s seconds. The first
                   failure arms it the same way;
  run-out          largest x of any point of a counted group minus the toe x
                   (the lower-right corner of the cut, default 56.33 m);
  max displacement largest |x - x_ref| of any active point.

Importable: Run (snapshot access), connected_groups, slope_metrics.
Errors in the input give one line "slope_metrics: error: ..." and exit code 2.
"""
import argparse
import json
import math
import os
import signal
import sys

import numpy as np

from rainslide_tools.slope_groups import (connected_groups, derive_toe_x, sliding_groups,  # noqa: F401
                                          surface_profile)
from rainslide_tools.slope_pressure import crest_hydrostatic, pore_pressure_pulses, pressure_peak  # noqa: F401
from rainslide_tools.slope_run import (METRICS, PARTICLES, Frame, InputError, Run, Snapshot,  # noqa: F401
                                       read_metrics, read_probes, run_reporting_errors, write_metrics_key)
from rainslide_tools.slope_run import json_num as _json_num

DEFAULT_TOE_X = 56.33

DEFAULTS = {
    "disp_threshold_m": 0.1,
    "eps_threshold": 0.05,
    "moved_threshold_m": 0.5,
    "link_factor": 1.5,
    "min_group_area_m2": 1.0,
    "jump_rate_m2_per_s": 4.0,
    "quiet_s": 1.0,
}


def slope_metrics(run, toe_x=DEFAULT_TOE_X, **options):
    """Failure metrics of run.stage (see the module docstring) as a JSON-ready dict.

    toe_x: a number, or "auto" to derive it from the initial surface profile.
    options: any key of DEFAULTS. Also returns per-snapshot labels in
    result["_labels"] (name -> (ids, group label or -1)); drop it before writing.
    """
    opt = dict(DEFAULTS)
    for k, v in options.items():
        if k not in opt:
            raise TypeError(f"unknown option {k}")
        if v is not None:
            opt[k] = float(v)
    spacing = run.point_spacing()
    link = opt["link_factor"] * spacing
    x_init = run.initial_positions()
    toe_derived = derive_toe_x(x_init, spacing)
    if isinstance(toe_x, str) and toe_x == "auto":
        toe, toe_source = toe_derived, "derived from the initial surface profile"
    else:
        toe, toe_source = float(toe_x), "given (--toe-x)"
    ref_ids, ref_x = run.reference_positions()
    wave_speed = ((run.metrics or {}).get("time_step") or {}).get(
        "final_max_wave_speed_m_per_s")

    series = {k: [] for k in ("time_s", "sliding_area_m2", "n_groups", "n_sliding_points",
                              "new_area_m2", "new_rate_m2_per_s", "max_x_sliding_m",
                              "run_out_m", "max_displacement_m")}
    ever = np.zeros(len(ref_ids), dtype=bool)  # by reference index: ever in a counted group
    slides, labels_out = [], {}
    first_failure = None
    armed, last_high = True, -math.inf
    t_prev = 0.0
    final = None
    for snap in run.stage_snapshots:
        t = snap.t
        ids = run.field(snap, "id")
        kref = np.searchsorted(ref_ids, ids)
        x = run.field(snap, "x")
        u = run.displacement_since_start(snap)
        dist = np.hypot(u[:, 0], u[:, 1])
        eps = run.field(snap, "plastic_shear_strain")
        vol = run.field(snap, "volume")
        act = run.active(snap)
        cand = act & (((dist > opt["disp_threshold_m"]) & (eps > opt["eps_threshold"]))
                      | (dist > opt["moved_threshold_m"]))
        labels, counted, areas = sliding_groups(x, vol, cand, link, opt["min_group_area_m2"])
        in_group = labels >= 0
        labels_out[snap.name] = (ids, labels)
        area = float(areas.sum())
        was = ever[kref]
        new = in_group & ~was
        new_area = float(vol[new].sum())
        dt = t - t_prev
        rate = new_area / dt if dt > 0 else (math.inf if new_area > 0 else 0.0)

        # Rule (a): a counted group not linked to any earlier counted point.
        detached = []
        if counted.size and was.any():
            both = in_group | (was & act)
            lab2 = connected_groups(x[both], link)
            old_lab = np.unique(lab2[was[both]])
            idx_both = np.flatnonzero(both)
            for g in counted:
                members = labels[idx_both] == g
                if not np.isin(lab2[members], old_lab).any():
                    detached.append(int(g))
        # Rule (b): the newly sliding area jumps after a quiet spell.
        jump = False
        if first_failure is not None:
            if armed and rate >= opt["jump_rate_m2_per_s"]:
                jump, armed, last_high = True, False, t
            elif not armed:
                if rate >= 0.5 * opt["jump_rate_m2_per_s"]:
                    last_high = t
                elif t - last_high >= opt["quiet_s"]:
                    armed = True

        reason = None
        if first_failure is None and counted.size:
            first_failure, reason = t, "first failure"
            armed, last_high = False, t
        elif detached or jump:
            reason = "+".join((["detached group"] if detached else []) +
                              (["area jump"] if jump else []))
        if reason:
            x0_new = ref_x[kref[new]]
            slides.append({
                "time_s": _json_num(t),
                "snapshot": snap.name,
                "reason": reason,
                "new_area_m2": _json_num(new_area),
                "new_rate_m2_per_s": _json_num(rate),
                "detached_groups": len(detached),
                "detached_area_m2": _json_num(float(sum(vol[labels == g].sum() for g in detached))),
                "sliding_area_m2": _json_num(area),
                "n_groups": int(counted.size),
                "initial_x_range_m": [_json_num(x0_new[:, 0].min()), _json_num(x0_new[:, 0].max())]
                if x0_new.size else None,
            })
        ever[kref[in_group]] = True

        max_x = float(x[in_group, 0].max()) if in_group.any() else None
        # Also over every sliding point, fragments below the minimum area included.
        frag = cand & np.isfinite(x[:, 0])
        max_x_all = float(x[frag, 0].max()) if frag.any() else None
        max_d = float(dist[act].max()) if act.any() else 0.0
        series["time_s"].append(_json_num(t))
        series["sliding_area_m2"].append(_json_num(area))
        series["n_groups"].append(int(counted.size))
        series["n_sliding_points"].append(int(in_group.sum()))
        series["new_area_m2"].append(_json_num(new_area))
        series["new_rate_m2_per_s"].append(_json_num(rate))
        series["max_x_sliding_m"].append(_json_num(max_x))
        series["run_out_m"].append(_json_num(max_x - toe) if max_x is not None else None)
        series["max_displacement_m"].append(_json_num(max_d))
        a = int(np.argmax(np.where(act, dist, -1.0))) if act.any() else 0
        final = {"time_s": _json_num(t), "snapshot": snap.name, "stage": snap.stage,
                 "sliding_area_m2": _json_num(area), "n_groups": int(counted.size),
                 "run_out_m": _json_num(max_x - toe) if max_x is not None else None,
                 "max_x_sliding_m": _json_num(max_x),
                 "run_out_incl_fragments_m": _json_num(max_x_all - toe)
                 if max_x_all is not None else None,
                 "max_displacement_m": _json_num(max_d),
                 "max_displacement_point_id": int(ids[a]),
                 "max_displacement_point_initial_xy_m": [_json_num(v) for v in ref_x[kref[a]]]}
        t_prev = t

    run_outs = [v for v in series["run_out_m"] if v is not None]
    return {
        "definition": {
            "stage_time": "time since the start of the analysed stage (t = 0 of the paper's "
                          "figures for the rainfall stage)",
            "reference_state": run.reference_source,
            "sliding_point": "active, and (|x - x_ref| > disp_threshold_m and plastic_shear_strain"
                             " > eps_threshold) or |x - x_ref| > moved_threshold_m",
            "sliding_group": "sliding points linked by neighbours closer than link_factor x "
                             "point_spacing_m; counted if its area (sum of volumes) >= "
                             "min_group_area_m2",
            "first_failure": "first snapshot of the stage with a counted sliding group",
            "later_slide": "a snapshot where (a) a counted group is not linked to any point "
                           "counted at an earlier snapshot ('detached group'), or (b) the area "
                           "newly entering counted groups grows at >= jump_rate_m2_per_s after "
                           "a quiet spell ('area jump'; re-armed when the rate stayed below "
                           "jump_rate/2 for quiet_s; the first failure arms it the same way)",
            "run_out": "largest x of a point in a counted group minus toe_x_m "
                       "(final.run_out_incl_fragments_m: of any sliding point, fragments "
                       "below min_group_area_m2 included)",
            "max_displacement": "largest |x - x_ref| over active points",
            "parameters": {k: v for k, v in opt.items()},
        },
        "stage": run.stage,
        "crest_hydrostatic_error": crest_hydrostatic(run),
        "pore_pressure_pulses": pore_pressure_pulses(run, wave_speed),
        "pressure_peak": pressure_peak(run, wave_speed),
        "stage_start_time_s": _json_num(run.stage_start_s),
        "stage_start_source": run.stage_start_source,
        "snapshots_analysed": len(run.stage_snapshots),
        "point_spacing_m": _json_num(spacing),
        "link_distance_m": _json_num(link),
        "toe_x_m": _json_num(toe),
        "toe_x_source": toe_source,
        "toe_x_derived_m": _json_num(toe_derived),
        "first_failure_time_s": _json_num(first_failure) if first_failure is not None else None,
        "failed": first_failure is not None,
        "slides": slides,
        "slide_times_s": [s["time_s"] for s in slides],
        "final": final,
        "max_run_out_m": _json_num(max(run_outs)) if run_outs else None,
        "series": series,
        "_labels": labels_out,
    }


def public(result):
    """The result without the in-memory label arrays."""
    return {k: v for k, v in result.items() if not k.startswith("_")}


def summary_lines(r):
    f = r["final"]
    lines = [f"stage '{r['stage']}' (starts at run time {r['stage_start_time_s']} s), "
             f"{r['snapshots_analysed']} snapshots, point spacing {r['point_spacing_m']} m, "
             f"link {r['link_distance_m']} m",
             f"toe x {r['toe_x_m']} m ({r['toe_x_source']}; derived {r['toe_x_derived_m']} m)"]
    if r["first_failure_time_s"] is None:
        lines.append("no failure: no sliding group of the minimum area in any snapshot")
    else:
        lines.append(f"first failure at t = {r['first_failure_time_s']} s")
        for s in r["slides"]:
            lines.append(f"  slide at t = {s['time_s']:8.3f} s  {s['reason']:<28s} new area "
                         f"{s['new_area_m2']:8.2f} m2, sliding area {s['sliding_area_m2']:8.2f} m2,"
                         f" from initial x {s['initial_x_range_m']}")
    lines.append(f"final (t = {f['time_s']} s): sliding area {f['sliding_area_m2']} m2 in "
                 f"{f['n_groups']} group(s), run-out {f['run_out_m']} m "
                 f"(max x {f['max_x_sliding_m']} m; {f['run_out_incl_fragments_m']} m with "
                 f"fragments), max displacement {f['max_displacement_m']} m")
    return lines


def add_options(parser):
    """The threshold options, shared with slope_figures.py."""
    parser.add_argument("--stage", help="stage to analyse (default: the second stage, or the only one)")
    parser.add_argument("--frame", default=None,
                        help="'deg,dx,dy': the model was rotated by deg about the origin and "
                             "shifted by (dx, dy) m; positions are mapped back first")
    parser.add_argument("--toe-x", default=str(DEFAULT_TOE_X),
                        help=f"toe x in m, or 'auto' (default {DEFAULT_TOE_X})")
    for k, v in DEFAULTS.items():
        parser.add_argument("--" + k.replace("_", "-"), type=float, default=None,
                            help=f"(default {v})")


def options_from(args):
    toe = args.toe_x
    if toe != "auto":
        try:
            toe = float(toe)
        except ValueError:
            raise InputError(f"--toe-x: expected a number or 'auto', got '{toe}'")
    return toe, {k: getattr(args, k) for k in DEFAULTS}


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("dir", help="results folder of a run")
    p.add_argument("--json", action="store_true", help="print the whole 'slope' object as JSON")
    p.add_argument("--no-write", action="store_true", help="do not update DIR/metrics.json")
    add_options(p)
    args = p.parse_args(argv)
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)

    def body():
        toe, opts = options_from(args)
        frame = Frame.parse(args.frame) if args.frame else None
        run = Run(args.dir, args.stage, metrics_required=not args.no_write, frame=frame)
        try:
            result = public(slope_metrics(run, toe, **opts))
            if frame is not None:
                result["frame"] = frame.as_list()
        finally:
            run.close()
        if not args.no_write:
            write_metrics_key(args.dir, "slope", result)
        if args.json:
            print(json.dumps(result, indent=2, allow_nan=False))
        else:
            print("\n".join(summary_lines(result)))
            if not args.no_write:
                print(f"written under \"slope\" in {os.path.join(args.dir, METRICS)}")

    return run_reporting_errors("slope_metrics", body, f"{args.dir}: ")

if __name__ == "__main__":
    sys.exit(main())
