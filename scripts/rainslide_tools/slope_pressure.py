"""Pore pressures of a slope run against hydrostatic: under the crest, the
largest pulses against hydrostatic plus Joukowsky's water hammer, and the
state of the point at the largest p_w."""
import numpy as np

from .slope_run import json_num as _json_num

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
