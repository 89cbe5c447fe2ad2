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

PARTICLES = "particles.h5"
METRICS = "metrics.json"
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


class InputError(Exception):
    """A missing or unusable input; the message names the file and what is missing."""


def run_reporting_errors(script, body, results=""):
    """Runs body() and returns its exit code (0 if it returns None). A missing or
    unusable input (InputError) or an unreadable result file (OSError, e.g. h5py on
    a damaged file; `results` names it) is printed as '<script>: error: ...' and
    gives 2."""
    try:
        code = body()
    except InputError as e:
        print(f"{script}: error: {e}", file=sys.stderr)
        return 2
    except OSError as e:  # h5py read errors of a damaged file
        print(f"{script}: error: {results}cannot read the results ({e})", file=sys.stderr)
        return 2
    return 0 if code is None else code


def _text(value):
    """An HDF5 string attribute (bytes or str) as str."""
    if isinstance(value, (bytes, np.bytes_)):
        return value.decode("utf-8", "replace")
    return str(value)


def read_metrics(run_dir, required=True):
    """DIR/metrics.json as a dict (None if absent and not required)."""
    path = os.path.join(run_dir, METRICS)
    if not os.path.isfile(path):
        if required:
            raise InputError(f"{path}: file not found")
        return None
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        raise InputError(f"{path}: not readable JSON ({e})")
    if not isinstance(data, dict):
        raise InputError(f"{path}: top level is not a JSON object")
    return data


def write_metrics_key(run_dir, key, value):
    """Adds/replaces metrics[key] in DIR/metrics.json atomically."""
    path = os.path.join(run_dir, METRICS)
    data = read_metrics(run_dir, required=True)
    data[key] = value
    partial = path + ".partial"
    try:
        with open(partial, "w") as f:
            json.dump(data, f, indent=2, sort_keys=True, allow_nan=False)
            f.write("\n")
            f.flush()
            os.fsync(f.fileno())
        os.replace(partial, path)
    except OSError as e:
        raise InputError(f"{path}: cannot write ({e})")


#---------------------------------------------------------------------------#
class Snapshot:
    """One /snapshots/NNNNNN group: its attributes; fields through Run.field."""

    def __init__(self, name, attrs):
        self.name = name
        self.path = "/snapshots/" + name
        self.time_s = float(attrs["time_s"])
        self.stage = _text(attrs["stage"])
        self.stage_time_s = float(attrs["stage_time_s"]) if "stage_time_s" in attrs else None
        self.step = int(attrs.get("step", -1))
        self.t = None  # time since the analysed stage's start (set by Run)

    def __repr__(self):
        return f"Snapshot({self.name}, stage={self.stage}, t={self.t})"


class Run:
    """A results folder: snapshots of particles.h5 and the analysed stage.

    stage: the stage to analyse (default: the second stage if there are two
    or more, else the only one). Snapshots of that stage (and a final
    "failure" snapshot after it) get .t = time since the stage start.
    """

    def __init__(self, run_dir, stage=None, metrics_required=False):
        import h5py  # imported here so that --help works without h5py

        self.dir = run_dir
        if not os.path.isdir(run_dir):
            raise InputError(f"{run_dir}: results folder not found")
        self.h5_path = os.path.join(run_dir, PARTICLES)
        if not os.path.isfile(self.h5_path):
            extra = " (particles.h5.partial exists: is the run still going?)" \
                if os.path.isfile(self.h5_path + ".partial") else ""
            raise InputError(f"{self.h5_path}: file not found{extra}")
        self.metrics = read_metrics(run_dir, required=metrics_required)
        try:
            self._h5 = h5py.File(self.h5_path, "r")
        except OSError as e:
            raise InputError(f"{self.h5_path}: not a readable HDF5 file ({e})")
        if "snapshots" not in self._h5:
            raise InputError(f"{self.h5_path}: no group /snapshots")
        self.snapshots = []
        for name in sorted(self._h5["snapshots"].keys()):
            attrs = self._h5["snapshots"][name].attrs
            for a in ("time_s", "stage"):
                if a not in attrs:
                    raise InputError(f"{self.h5_path}: /snapshots/{name} has no attribute '{a}'")
            self.snapshots.append(Snapshot(name, attrs))
        if not self.snapshots:
            raise InputError(f"{self.h5_path}: no snapshots in /snapshots")
        self.snapshots.sort(key=lambda s: (s.time_s, s.name))
        self._cache = {}
        self._choose_stage(stage)
        self.two_phase = self.has_field(self.stage_snapshots[-1], "pore_pressure")

    # Stages ---------------------------------------------------------------
    def _choose_stage(self, stage):
        order = []
        stages_json = (self.metrics or {}).get("stages")
        if isinstance(stages_json, list):
            order = [str(s.get("name")) for s in stages_json if isinstance(s, dict)]
        for s in self.snapshots:
            if s.stage != "failure" and s.stage not in order:
                order.append(s.stage)
        self.stage_names = order
        if stage is None:
            if not order:
                raise InputError(f"{self.h5_path}: no snapshot belongs to a named stage")
            stage = order[1] if len(order) >= 2 else order[0]
        own = [s for s in self.snapshots if s.stage == stage]
        if not own:
            raise InputError(f"{self.h5_path}: no snapshot of stage '{stage}' "
                             f"(stages in the file: {', '.join(order) or 'none'})")
        self.stage = stage
        # Stage start (run time): time_s - stage_time_s of the stage's snapshots,
        # else the durations of the earlier stages in metrics.json.
        if all(s.stage_time_s is not None for s in own):
            self.stage_start_s = float(np.median([s.time_s - s.stage_time_s for s in own]))
            self.stage_start_source = "particles.h5 (time_s - stage_time_s)"
        else:
            self.stage_start_s = self._start_from_metrics(stage)
            self.stage_start_source = "metrics.json (durations of the earlier stages)"
        last = own[-1]
        after = [s for s in self.snapshots if s.stage == "failure" and s.time_s >= last.time_s]
        self.stage_snapshots = own + after[:1]
        for s in self.stage_snapshots:
            s.t = s.time_s - self.stage_start_s
        # Reference: the previous stage's end snapshot at the stage start.
        tol = 1e-9 * max(1.0, abs(self.stage_start_s))
        prev = [s for s in self.snapshots if s.stage != stage and s.stage != "failure"
                and abs(s.time_s - self.stage_start_s) <= tol]
        if prev:
            self.reference = prev[-1]
            self.reference.t = 0.0
            self.reference_source = (f"snapshot {self.reference.name} (end of stage "
                                     f"'{self.reference.stage}' at the stage start)")
        else:
            self.reference = None
            self.reference_source = (f"x - displacement of snapshot {own[0].name} "
                                     "(positions at the last displacement reset)")

    def _start_from_metrics(self, stage):
        path = os.path.join(self.dir, METRICS)
        stages = (self.metrics or {}).get("stages")
        if not isinstance(stages, list):
            raise InputError(f"{self.h5_path}: snapshots lack 'stage_time_s' and {path} has "
                             "no 'stages' list to take the stage start from")
        start = 0.0
        for s in stages:
            if not isinstance(s, dict) or "name" not in s or "duration_s" not in s:
                raise InputError(f"{path}: an entry of 'stages' lacks 'name' or 'duration_s'")
            if s["name"] == stage:
                return start
            start += float(s["duration_s"])
        raise InputError(f"{path}: 'stages' has no stage '{stage}'")

    # Fields ---------------------------------------------------------------
    def has_field(self, snap, name):
        return name in self._h5[snap.path]

    def field(self, snap, name):
        key = (snap.name, name)
        if key not in self._cache:
            group = self._h5[snap.path]
            if name not in group:
                raise InputError(f"{self.h5_path}: {snap.path} has no dataset '{name}'")
            if len(self._cache) > 64:
                self._cache.clear()
            self._cache[key] = group[name][()]
        return self._cache[key]

    def reference_positions(self):
        """(sorted ids, positions at the stage start)."""
        if "_ref" not in self._cache:
            if self.reference is not None:
                snap = self.reference
                x0 = self.field(snap, "x")
            else:
                snap = self.stage_snapshots[0]
                x0 = self.field(snap, "x") - self.field(snap, "displacement")
            ids = self.field(snap, "id")
            order = np.argsort(ids, kind="stable")
            self._cache["_ref"] = (ids[order], x0[order])
        return self._cache["_ref"]

    def displacement_since_start(self, snap):
        """(n, 2) displacement of each point of `snap` since the stage start."""
        ref_ids, ref_x = self.reference_positions()
        ids = self.field(snap, "id")
        k = np.searchsorted(ref_ids, ids)
        k = np.clip(k, 0, len(ref_ids) - 1)
        if len(ref_ids) == 0 or np.any(ref_ids[k] != ids):
            raise InputError(f"{self.h5_path}: {snap.path} has point ids missing "
                             "from the stage-start reference")
        return self.field(snap, "x") - ref_x[k]

    def initial_positions(self):
        """Positions at the run start: x - displacement of the first snapshot."""
        snap = self.snapshots[0]
        return self.field(snap, "x") - self.field(snap, "displacement")

    def point_spacing(self):
        """Initial point spacing: sqrt of the median point volume of the first snapshot."""
        vol = self.field(self.snapshots[0], "volume")
        vol = vol[vol > 0]
        if vol.size == 0:
            raise InputError(f"{self.h5_path}: {self.snapshots[0].path}/volume has no positive value")
        return float(math.sqrt(np.median(vol)))

    def active(self, snap):
        if self.has_field(snap, "status"):
            return self.field(snap, "status") == 1
        return np.ones(len(self.field(snap, "x")), dtype=bool)

    def nearest(self, t):
        """The snapshot of the stage (or the reference, t = 0) nearest to stage time t."""
        cands = ([self.reference] if self.reference is not None else []) + self.stage_snapshots
        return min(cands, key=lambda s: (abs(s.t - t), -s.t))

    def case_name(self):
        name = (self.metrics or {}).get("case")
        return str(name) if name else os.path.basename(os.path.normpath(self.dir))

    def close(self):
        self._h5.close()


#---------------------------------------------------------------------------#
def _neighbour_pairs(xy, link):
    """Index pairs (i < j or across cells) of points closer than `link` (grid hash)."""
    n = len(xy)
    if n < 2:
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    cell = np.floor((xy - xy.min(axis=0)) / link).astype(np.int64) + 1
    ny = int(cell[:, 1].max()) + 3
    key = cell[:, 0] * ny + cell[:, 1]
    order = np.argsort(key, kind="stable")
    sorted_key = key[order]
    pi, pj = [], []
    # Half of the 3x3 neighbourhood: each pair of cells is visited once.
    for dx, dy in ((0, 0), (1, -1), (1, 0), (1, 1), (0, 1)):
        nkey = key + dx * ny + dy
        start = np.searchsorted(sorted_key, nkey, "left")
        count = np.searchsorted(sorted_key, nkey, "right") - start
        total = int(count.sum())
        if total == 0:
            continue
        i = np.repeat(np.arange(n), count)
        offset = np.arange(total) - np.repeat(np.cumsum(count) - count, count)
        j = order[np.repeat(start, count) + offset]
        keep = np.sum((xy[i] - xy[j]) ** 2, axis=1) <= link * link
        if dx == 0 and dy == 0:
            keep &= i < j
        pi.append(i[keep])
        pj.append(j[keep])
    return np.concatenate(pi), np.concatenate(pj)


def connected_groups(xy, link):
    """Labels 0..G-1 of the groups of points linked by chains closer than `link`."""
    xy = np.asarray(xy, dtype=float).reshape(-1, 2)
    n = len(xy)
    if n == 0:
        return np.zeros(0, dtype=np.int64)
    i, j = _neighbour_pairs(xy, link)
    label = np.arange(n)
    # Hook roots to the smallest neighbouring label, then jump pointers.
    while i.size:
        li, lj = label[i], label[j]
        differ = li != lj
        if not differ.any():
            break
        li, lj = li[differ], lj[differ]
        low = np.minimum(li, lj)
        np.minimum.at(label, li, low)
        np.minimum.at(label, lj, low)
        while True:
            jumped = label[label]
            if np.array_equal(jumped, label):
                break
            label = jumped
    return np.unique(label, return_inverse=True)[1].astype(np.int64)


def sliding_groups(xy, area, candidate, link, min_area):
    """Groups of candidate points: (group label per point or -1, counted labels, areas)."""
    idx = np.flatnonzero(candidate)
    labels = np.full(len(xy), -1, dtype=np.int64)
    if idx.size == 0:
        return labels, np.zeros(0, dtype=np.int64), np.zeros(0)
    lab = connected_groups(xy[idx], link)
    g_area = np.bincount(lab, weights=area[idx])
    counted = np.flatnonzero(g_area >= min_area)
    keep = np.isin(lab, counted)
    labels[idx[keep]] = lab[keep]
    return labels, counted, g_area[counted]


#---------------------------------------------------------------------------#
def surface_profile(x0, spacing):
    """Top of the initial soil per column of points: (column x, top y = highest
    point + spacing / 2). Points generated in vertical columns (the usual case)
    give one column per distinct x; otherwise columns of width `spacing`."""
    key = np.round(x0[:, 0] / (1e-3 * spacing)).astype(np.int64)
    uniq, col = np.unique(key, return_inverse=True)
    if uniq.size > 0.5 * len(x0):  # not in columns: bin them
        origin = x0[:, 0].min() - 0.5 * spacing
        col = np.floor((x0[:, 0] - origin) / spacing).astype(np.int64)
    ncol = col.max() + 1
    top = np.full(ncol, -np.inf)
    np.maximum.at(top, col, x0[:, 1])
    xc = np.bincount(col, weights=x0[:, 0], minlength=ncol)
    cnt = np.bincount(col, minlength=ncol)
    ok = cnt > 0
    return xc[ok] / cnt[ok], top[ok] + 0.5 * spacing


def derive_toe_x(x0, spacing):
    """x of the lower-right corner of the sloping surface: where the initial surface
    profile reaches the flat floor at its right end (midway between the last column
    above the floor and the first column on it; within a point spacing)."""
    xc, top = surface_profile(x0, spacing)
    floor = top[-1]
    k = len(top) - 1
    while k > 0 and top[k - 1] <= floor + 0.5 * spacing:
        k -= 1
    return float(0.5 * (xc[k - 1] + xc[k])) if k > 0 else float(xc[0])


def _json_num(v, digits=6):
    if v is None or not np.isfinite(v):
        return None
    return float(round(float(v), digits))


CREST_X_M = (2.0, 10.0)
RHO_W = 1000.0  # kg/m^3
RHO_W_G = RHO_W * 9.81


def crest_hydrostatic(run):
    """p_w under the crest (2 < x < 10 m) against hydrostatic.

    Per snapshot of the stage: the saturated (S > 0.99) points whose p_w is not
    held at 0, against rho_w g (y_ref - y), y_ref the mean height of the held
    (p_w = 0) points in the same strip. Returns the final snapshot's RMS and
    largest |error| (Pa) and the largest RMS over the stage, or None for a
    dry run or a strip with no held point.
    """
    if not run.two_phase:
        return None
    worst, final = None, None
    for snap in run.stage_snapshots:
        x = run.field(snap, "x")
        p = run.field(snap, "pore_pressure")
        S = run.field(snap, "saturation")
        strip = run.active(snap) & (x[:, 0] > CREST_X_M[0]) & (x[:, 0] < CREST_X_M[1])
        held = strip & (p == 0.0)
        wet = strip & (p != 0.0) & (S > 0.99)
        if not held.any() or not wet.any():
            continue
        y_ref = float(x[held, 1].mean())
        err = p[wet] - RHO_W_G * (y_ref - x[wet, 1])
        rms = float(np.sqrt(np.mean(err ** 2)))
        final = {"time_s": _json_num(snap.t), "rms_pa": _json_num(rms),
                 "max_abs_pa": _json_num(float(np.abs(err).max())),
                 "points": int(wet.sum())}
        if worst is None or rms > worst["rms_pa"]:
            worst = {"time_s": _json_num(snap.t), "rms_pa": _json_num(rms)}
    if final is None:
        return None
    return {"definition": "saturated points (S > 0.99) with 2 < x < 10 m whose p_w is not "
                          "held, against rho_w g (y_ref - y), y_ref the mean height of the "
                          "held p_w = 0 points of the strip",
            "final": final, "largest_rms": worst}


def pore_pressure_pulses(run, wave_speed):
    """The largest p_w of each snapshot against hydrostatic plus Joukowsky.

    The model has no gas phase (as the paper's): where the last unsaturated
    pores at an impermeable base fill, the inflowing water stops within a step
    and sends a water-hammer pulse of Joukowsky's pressure c rho_w n S |w|
    (c the undrained wave speed, w = v_w - v_s). Per snapshot of the stage,
    every point's p_w against rho_w g (y_top - y), y_top the highest point of
    its 0.5 m column of soil, plus c times the largest seepage momentum of any
    point in this and the previous snapshot. Returns the largest ratio and
    where it was, or None for a dry run or without a wave speed.
    """
    if not run.two_phase or not wave_speed:
        return None
    worst, momentum_before = None, 0.0
    for snap in run.stage_snapshots:
        active = run.active(snap)
        x = run.field(snap, "x")[active]
        p = run.field(snap, "pore_pressure")[active]
        w = run.field(snap, "water_velocity")[active] - run.field(snap, "velocity")[active]
        momentum = RHO_W * run.field(snap, "porosity")[active] * \
            run.field(snap, "saturation")[active] * np.hypot(w[:, 0], w[:, 1])
        recent = max(float(momentum.max()), momentum_before)
        momentum_before = float(momentum.max())
        column = np.floor(x[:, 0] / 0.5).astype(int)
        column -= column.min()
        top = np.full(column.max() + 1, -np.inf)
        np.maximum.at(top, column, x[:, 1])
        hydrostatic = RHO_W_G * (top[column] - x[:, 1])
        joukowsky = wave_speed * recent
        ratio = p / (hydrostatic + joukowsky)
        k = int(np.argmax(ratio))
        if worst is None or ratio[k] > worst["ratio"]:
            worst = {"ratio": _json_num(float(ratio[k])), "time_s": _json_num(snap.t),
                     "xy_m": [_json_num(v) for v in x[k]],
                     "p_w_pa": _json_num(float(p[k])),
                     "hydrostatic_pa": _json_num(float(hydrostatic[k])),
                     "joukowsky_pa": _json_num(joukowsky)}
    if worst is None:
        return None
    return {"definition": "largest p_w / (rho_w g (y_top - y) + c max rho_w n S |v_w - v_s|) "
                          "over the points and snapshots of the stage; y_top the top of the "
                          "point's 0.5 m column of soil, the momentum the largest of any point "
                          "in the snapshot and the one before, c the undrained wave speed",
            "wave_speed_m_per_s": _json_num(wave_speed), "largest": worst}


def pressure_peak(run, wave_speed):
    """How the total stress carries the largest p_w of the stage.

    Finds the point and snapshot of the largest p_w and follows that point (by
    id) to the snapshot before. Reports its p_w, its total mean pressure
    p = -tr(sigma')/3 + S p_w (compression positive; `stress` is Bishop's
    effective stress sigma' = sigma + S p_w m) and its effective mean pressure
    p' = -tr(sigma')/3 at both, their changes, and the point's solid speed at
    both. An undrained compression of saturated soil raises p_w with the total
    pressure while p' stays (Skempton's B = dp_w / dp near 1); a change dv of
    the solid's velocity sends an undrained wave of total pressure
    rho_m c |dv| (Joukowsky; rho_m = m_s / V + n S rho_w, c the undrained wave
    speed), reported with the ratio of the total pressure's change to it.
    None for a dry run.
    """
    if not run.two_phase:
        return None
    snaps = run.stage_snapshots
    best = None
    for k, snap in enumerate(snaps):
        active = run.active(snap)
        p = np.where(active, run.field(snap, "pore_pressure"), -np.inf)
        i = int(np.argmax(p))
        if best is None or p[i] > best[2]:
            best = (k, i, float(p[i]))
    if best is None or best[0] == 0:
        return None
    k, i, _ = best

    def state(snap, index):
        """(the point's JSON entry, its solid velocity)."""
        sig = run.field(snap, "stress")[index]
        p_w = float(run.field(snap, "pore_pressure")[index])
        S = float(run.field(snap, "saturation")[index])
        p_eff = -(sig[0] + sig[1] + sig[3]) / 3.0
        v = run.field(snap, "velocity")[index]
        return {"time_s": _json_num(snap.t),
                "xy_m": [_json_num(c) for c in run.field(snap, "x")[index]],
                "p_w_pa": _json_num(p_w), "saturation": _json_num(S),
                "total_mean_pressure_pa": _json_num(p_eff + S * p_w),
                "effective_mean_pressure_pa": _json_num(p_eff),
                "solid_speed_m_per_s": _json_num(float(np.hypot(v[0], v[1])))}, v

    point_id = int(run.field(snaps[k], "id")[i])
    before_ids = run.field(snaps[k - 1], "id")
    j = np.flatnonzero(before_ids == point_id)
    peak, v_peak = state(snaps[k], i)
    result = {"definition": "the point of the largest p_w of the stage, at that snapshot and "
                            "the one before: p_w, total mean pressure -tr(sigma')/3 + S p_w "
                            "and effective mean pressure -tr(sigma')/3 (compression "
                            "positive), solid speed; Skempton's B = dp_w / dp between them; "
                            "the undrained wave rho_m c |dv_s| of the solid's velocity "
                            "change, c the undrained wave speed",
              "point_id": point_id, "peak": peak}
    if j.size:
        before, v_before = state(snaps[k - 1], int(j[0]))
        result["before"] = before
        d_total = peak["total_mean_pressure_pa"] - before["total_mean_pressure_pa"]
        d_p_w = peak["p_w_pa"] - before["p_w_pa"]
        result["skempton_b"] = _json_num(d_p_w / d_total) if d_total else None
        if wave_speed:
            rho_m = float(run.field(snaps[k], "mass")[i] / run.field(snaps[k], "volume")[i]
                          + run.field(snaps[k], "porosity")[i] * peak["saturation"] * RHO_W)
            dv = float(np.hypot(*(v_peak - v_before)))
            wave = rho_m * wave_speed * dv
            result["undrained_wave"] = {
                "mixture_density_kg_per_m3": _json_num(rho_m),
                "wave_speed_m_per_s": _json_num(wave_speed),
                "solid_velocity_change_m_per_s": _json_num(dv),
                "pressure_pa": _json_num(wave),
                "total_pressure_change_over_it": _json_num(d_total / wave) if wave else None}
    return result


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
        run = Run(args.dir, args.stage, metrics_required=not args.no_write)
        try:
            result = public(slope_metrics(run, toe, **opts))
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
