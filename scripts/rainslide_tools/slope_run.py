"""Reading a rainslide results folder: particles.h5 snapshots, metrics.json,
probes.csv.

Shared by slope_metrics.py, slope_figures.py, slope_summary.py,
probe_fluctuations.py, study_panel.py and study_table.py. Errors in the input
are InputError with a message naming the file and what is missing.
"""
import csv
import json
import math
import os
import sys

import numpy as np

PARTICLES = "particles.h5"
METRICS = "metrics.json"


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


def read_probes(path, columns):
    """Rows of a probes.csv as dicts, every column but stage and name as a
    float (an empty cell as nan); `columns` are those the caller needs."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            header = reader.fieldnames or []
            missing = sorted(set(columns) - set(header))
            if missing:
                raise InputError(f"{path}: no column(s) {', '.join(missing)} "
                                 f"(header: {','.join(header) or 'empty'})")
            rows = []
            for n, r in enumerate(reader, start=2):
                try:
                    for c in header:
                        if c not in ("stage", "name"):
                            r[c] = float(r[c]) if r[c] not in ("", None) else math.nan
                except ValueError:
                    raise InputError(f"{path}: line {n}: column {c} is not a number ('{r[c]}')")
                rows.append(r)
    except OSError as e:
        raise InputError(f"{path}: cannot read ({e})")
    return rows


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


FRAME_VECTORS = ("x", "displacement", "velocity", "water_velocity")


class Frame:
    """A model built rotated by deg about the origin, then shifted by (dx, dy):
    x' = R(deg) x + (dx, dy). to_case maps its vectors back: x = R(-deg)(x' - shift)."""

    def __init__(self, deg, dx, dy):
        self.deg, self.shift = float(deg), np.array([float(dx), float(dy)])
        a = math.radians(self.deg)
        self.back = np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]])

    @classmethod
    def parse(cls, text):
        """The frame of a --frame option 'deg,dx,dy'."""
        try:
            deg, dx, dy = (float(v) for v in text.split(","))
        except ValueError:
            raise InputError(f"--frame: expected 'deg,dx,dy' (degrees, metres), got '{text}'")
        return cls(deg, dx, dy)

    def to_case(self, v, shift):
        v = np.asarray(v, dtype=float)
        return ((v - self.shift) if shift else v) @ self.back.T

    def as_list(self):
        return [self.deg, float(self.shift[0]), float(self.shift[1])]


class Run:
    """A results folder: snapshots of particles.h5 and the analysed stage.

    stage: the stage to analyse (default: the second stage if there are two
    or more, else the only one). Snapshots of that stage (and a final
    "failure" snapshot after it) get .t = time since the stage start.
    """

    def __init__(self, run_dir, stage=None, metrics_required=False, frame=None):
        import h5py  # imported here so that --help works without h5py

        self.dir = run_dir
        self.frame = frame
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
            value = group[name][()]
            if self.frame is not None and name in FRAME_VECTORS:
                value = self.frame.to_case(value, shift=name == "x")
            self._cache[key] = value
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


def json_num(v, digits=6):
    """v rounded to `digits` decimals for JSON; None if missing or not finite."""
    if v is None or not np.isfinite(v):
        return None
    return float(round(float(v), digits))
