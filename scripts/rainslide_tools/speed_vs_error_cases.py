"""The runs of the speed-versus-error sweep (speed_vs_error.py): the plans of
the Terzaghi and Liakopoulos columns and their case texts, made from
cases/terzaghi.toml and cases/liakopoulos.toml by editing keys."""
import importlib.util
import json
import math
import os
import re
import tomllib

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
VERIFY = os.path.join(ROOT, "scripts", "verification")
TV_SNAPSHOTS = [0.05, 0.1, 0.2, 0.5, 1.0]


def load_module(name, path):
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


# --------------------------------------------------------------------------- #
# The sweep. Each entry is one run; "id" names its folder.


def terzaghi_plan():
    runs = []
    seen = set()

    def add(cells, ppc, kw, courant, group):
        key = (cells, ppc, kw, courant)
        if key in seen:
            for r in runs:
                if r["key"] == key and group not in r["groups"]:
                    r["groups"].append(group)
            return
        seen.add(key)
        runs.append({"problem": "terzaghi", "study": "terzaghi", "key": key, "groups": [group],
                     "params": {"cells": cells, "points_per_cell": ppc, "bulk_modulus_pa": kw,
                                "courant_number": courant},
                     "id": f"terzaghi_c{cells}_p{ppc}_kw{kw:.0e}_cfl{courant}"})

    for cells in (10, 20, 40, 80):                       # 1. convergence
        add(cells, 2, 2.0e9, 0.5, "convergence")
    for cells in (10, 20, 40):                           # 2. full factorial sweep
        for ppc in (1, 2, 3):
            for kw in (2.0e9, 2.0e8, 2.0e7):
                for courant in (0.25, 0.5, 0.9):
                    add(cells, ppc, kw, courant, "sweep")
    return runs


def liakopoulos_plan():
    """Two sets of the same parameter grid: the geostatic stage as in
    cases/liakopoulos.toml (it stops when E_kin / max E_kin < 1e-6, which can
    happen at a turning point of the decaying skeleton oscillation, i.e. away
    from equilibrium), and an "equilibrated" geostatic stage that runs for a
    fixed time of about five skeleton periods (see liakopoulos_case)."""
    runs = []

    def add(cells, kw, f, courant, geostatic):
        study = "liakopoulos" if geostatic == "case" else "liakopoulos_geq"
        runs.append({"problem": "liakopoulos", "study": study, "key": (cells, kw, f, courant, geostatic),
                     "groups": ["sweep"],
                     "params": {"cells": cells, "bulk_modulus_pa": kw, "inertia_scaling": f,
                                "courant_number": courant, "geostatic": geostatic},
                     "id": f"liakopoulos_c{cells}_kw{kw:.0e}_f{f:.0e}_cfl{courant}"
                           + ("" if geostatic == "case" else "_geq")})

    for geostatic in ("case", "equilibrated"):
        for kw in (2.0e9, 2.0e8, 2.0e7):
            for f in (1.0e4, 1.0e5, 1.0e6):
                for courant in (0.5, 0.9):
                    add(10, kw, f, courant, geostatic)   # 10 cells: full factorial
        for kw in (2.0e9, 2.0e8, 2.0e7):
            for f in (1.0e4, 1.0e5, 1.0e6):
                for courant in (0.5, 0.9):
                    # 20 cells: pruned. The Courant number's effect is measured at
                    # 10 cells; at 20 cells courant 0.5 is run only where it is
                    # cheap (f >= 1e5), courant 0.9 everywhere.
                    if courant == 0.5 and f < 1.0e5:
                        continue
                    add(20, kw, f, courant, geostatic)
    return runs


# --------------------------------------------------------------------------- #
# Case text editing: replace `key = value` lines, add missing tables.


def toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    if isinstance(v, str):
        return json.dumps(v)
    raise TypeError(v)


def set_key(text, key, value, table=None):
    """Sets `key = value` on the one line that assigns key (any table).

    If no line assigns key, the key is added under `[table]`, and the table is
    added before the first [[materials]] if it is missing too."""
    pattern = re.compile(r"^(\s*" + re.escape(key) + r"\s*=\s*).*$", re.M)
    hits = pattern.findall(text)
    if len(hits) > 1:
        raise ValueError(f"key {key} is assigned {len(hits)} times; cannot edit")
    if hits:
        return pattern.sub(lambda m: m.group(1) + toml_value(value), text, count=1)
    if table is None:
        raise ValueError(f"key {key} not found")
    header = re.compile(r"^\[" + re.escape(table) + r"\]\s*$", re.M)
    m = header.search(text)
    if m:
        return text[:m.end()] + f"\n{key} = {toml_value(value)}" + text[m.end():]
    m = re.search(r"^\[\[materials\]\]", text, re.M)
    return text[:m.start()] + f"[{table}]\n{key} = {toml_value(value)}\n\n" + text[m.start():]


def set_stage_key(text, stage, key, value):
    """Sets `key = value` in the [[stages]] table named `stage` (the lines
    between its `name = "stage"` and the next table header)."""
    lines = text.split("\n")
    start = next(i for i, l in enumerate(lines) if re.match(r'^\s*name\s*=\s*"' + re.escape(stage) + '"', l))
    end = next((i for i in range(start + 1, len(lines)) if lines[i].lstrip().startswith("[")), len(lines))
    for i in range(start, end):
        if re.match(r"^\s*" + re.escape(key) + r"\s*=", lines[i]):
            lines[i] = f"{key} = {toml_value(value)}"
            return "\n".join(lines)
    lines.insert(start + 1, f"{key} = {toml_value(value)}")
    return "\n".join(lines)


def terzaghi_physics(case):
    """c_v, H, y_top, t_ramp and p0 of a Terzaghi case (the verification
    script's consolidation_parameters)."""
    tz = load_module("terzaghi_verification", os.path.join(VERIFY, "terzaghi.py"))
    return tz.consolidation_parameters(case)


def terzaghi_case(base_text, p):
    base = tomllib.loads(base_text)
    H = 1.0
    h = H / p["cells"]
    ppc = p["points_per_cell"]
    text = base_text
    text = set_key(text, "bulk_modulus_pa", p["bulk_modulus_pa"], "water")
    text = set_key(text, "cell_size_m", h)
    text = set_key(text, "cells", [1, p["cells"] + 2])
    text = set_key(text, "polygon_m", [[0.0, 0.0], [h, 0.0], [h, H], [0.0, H]])
    # The load acts on the top row of points. Their centres are at
    # H - h/(2 ppc); the next row is at H - 3h/(2 ppc): the box starts at
    # H - h/ppc (= H - h/2 for the case's 2 x 2 points; for 1 or 3 points per
    # direction H - h/2 would hit a row of points exactly).
    text = set_key(text, "box_m", [[-1.0, H - h / ppc], [1.0, H]])
    text = set_key(text, "length_m", h)
    text = set_key(text, "points_per_cell", ppc, "particles")
    text = set_key(text, "courant_number", p["courant_number"], "solver")
    # Snapshot times from c_v of this K_w: t = Tv H^2 / c_v + t_ramp / 2.
    phys = terzaghi_physics(tomllib.loads(text))
    times = [round(tv * H * H / phys["c_v"] + 0.5 * phys["t_ramp"], 6) for tv in TV_SNAPSHOTS]
    text = set_key(text, "snapshot_times_s", times)
    text = set_key(text, "duration_s", round(times[-1] + 0.01, 6))
    text = set_key(text, "description", f"Terzaghi variant: {p['cells']} cells, {ppc}x{ppc} points, "
                   f"K_w = {p['bulk_modulus_pa']:.0e} Pa, courant {p['courant_number']} (speed_vs_error.py)")
    # Check the edit.
    c = tomllib.loads(text)
    assert c["grid"]["cell_size_m"] == h and c["grid"]["cells"] == [1, p["cells"] + 2]
    assert c["particles"]["points_per_cell"] == ppc
    assert c["solver"]["courant_number"] == p["courant_number"]
    assert c["water"]["bulk_modulus_pa"] == p["bulk_modulus_pa"]
    assert c["stages"][0]["loads"][0]["length_m"] == h
    assert len(base["stages"]) == len(c["stages"]) == 1
    return text


def liakopoulos_case(base_text, p):
    H = 1.0
    h = H / p["cells"]
    text = base_text
    text = set_key(text, "bulk_modulus_pa", p["bulk_modulus_pa"], "water")
    text = set_key(text, "cell_size_m", h)
    text = set_key(text, "cells", [1, p["cells"]])
    text = set_key(text, "polygon_m", [[0.0, 0.0], [h, 0.0], [h, H], [0.0, H]])
    text = set_key(text, "courant_number", p["courant_number"], "solver")
    text = set_key(text, "inertia_scaling", p["inertia_scaling"], "solver")
    geo_duration = None
    if p.get("geostatic", "case") == "equilibrated":
        # The geostatic stage runs for a fixed time instead of stopping at the
        # first step with E_kin / max E_kin < 1e-6: 200 s x max(1, sqrt(f / 1e5))
        # (the damped skeleton oscillation has a ~40 s period at f = 1e5 and
        # ~100 s at f = 1e6 and is below 1e-3 mm after ~3 periods).
        geo_duration = round(200.0 * max(1.0, math.sqrt(p["inertia_scaling"] / 1.0e5)), 1)
        text = set_stage_key(text, "geostatic", "ke_ratio_tolerance", 1.0e-12)
        text = set_stage_key(text, "geostatic", "duration_s", geo_duration)
    text = set_key(text, "description", f"Liakopoulos variant: {p['cells']} cells, "
                   f"K_w = {p['bulk_modulus_pa']:.0e} Pa, inertia scaling {p['inertia_scaling']:.0e}, "
                   f"courant {p['courant_number']}"
                   + (", equilibrated geostatic stage" if geo_duration is not None else "")
                   + " (speed_vs_error.py)")
    c = tomllib.loads(text)
    if geo_duration is not None:
        geo = [s for s in c["stages"] if s["name"] == "geostatic"][0]
        assert geo["duration_s"] == geo_duration and geo["ke_ratio_tolerance"] == 1.0e-12
    assert c["grid"]["cell_size_m"] == h and c["grid"]["cells"] == [1, p["cells"]]
    assert c["solver"]["courant_number"] == p["courant_number"]
    assert c["solver"]["inertia_scaling"] == p["inertia_scaling"]
    assert c["water"]["bulk_modulus_pa"] == p["bulk_modulus_pa"]
    return text
