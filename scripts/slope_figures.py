#!/usr/bin/python3
"""Figures of a rainslide slope run in the style of Wang, Vardon & Hicks (2018), §3.

Usage: slope_figures.py DIR [--out FIGDIR] [--times T1,T2,...] [--stage NAME]

Reads DIR/particles.h5 (DIR/metrics.json and DIR/probes.csv if present) and
writes into FIGDIR (default DIR/figures):
  fig7_pw_epsp.png     two-phase runs: per time (and the final snapshot) pore
                       pressure p_w (kPa) over plastic shear strain eps_p_bar;
  fig10_epsp.png       dry runs (no p_w): the eps_p_bar panels only (Fig. 10);
  fig8_shear_stress.png  shear stress sigma_xy (kPa) at the --times;
  fig9_vw_over_K.png   v_w / K against time at the probes A-D from probes.csv
                       (|v_w| solid, v_w,x dashed); skipped if probes.csv is absent;
  final_state.png      eps_p_bar, displacement magnitude since the stage start
                       and the sliding groups of slope_metrics.py at the end.
Times are stage times (t = 0 at the start of the analysed stage: the rainfall,
i.e. stage 2, of a slope case); each panel uses the nearest snapshot and says
which. Default --times: for a run whose metrics.json verdict says it failed,
5 s before the first slide and each onset (at most four panels); otherwise
10,16.25,18.75,25 for two-phase runs, 0.5,2.0 for dry ones.
Colour scales: eps_p_bar logarithmic from 1e-3 (where the soil yields) to 1
(--eps-scale linear for 0 to --eps-max); p_w from -50 kPa to the hydrostatic
pressure at the base of the deepest column of the body, rho_w g times its
height (--pw-range to set both).
Points are drawn as squares of the initial point spacing at their current
positions; the initial ground surface is the thin grey line.
Errors in the input give one line "slope_figures: error: ..." and exit code 2.
"""
import argparse
import math
import os
import signal
import sys

import numpy as np

import slope_metrics as sm

DPI = 110
PROBE_COLUMNS = ["time_s", "stage", "name", "point_id", "x_m", "y_m", "u_x_m", "u_y_m",
                 "v_x_m_per_s", "v_y_m_per_s", "v_w_x_m_per_s", "v_w_y_m_per_s", "p_w_pa",
                 "S", "eps_p_bar", "K_m_per_s"]


def _mpl():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return matplotlib, plt


def parse_floats(text, what, count=None):
    try:
        values = [float(v) for v in text.split(",") if v.strip() != ""]
    except ValueError:
        raise sm.InputError(f"{what}: expected comma-separated numbers, got '{text}'")
    if not values or (count is not None and len(values) != count):
        raise sm.InputError(f"{what}: expected {count or 'one or more'} number(s), got '{text}'")
    return values


#---------------------------------------------------------------------------#
class Plotter:
    """Shared state: the run, the point spacing, extents and the initial surface."""

    def __init__(self, run, out_dir, eps_max=1.0, eps_log=True, pw_range=None):
        self.run = run
        self.out = out_dir
        self.spacing = run.point_spacing()
        x0 = run.initial_positions()
        self.surface = sm.surface_profile(x0, self.spacing)
        self.eps_max = eps_max
        self.eps_log = eps_log
        self.pw_range = pw_range or (-50.0, self.hydrostatic_max_kpa(x0))
        self.interval = self._typical_interval()
        self._noted = set()  # requested times already reported as far from a snapshot
        # Extent: every point of the stage's snapshots, plus the initial state.
        lo, hi = x0.min(axis=0), x0.max(axis=0)
        for s in run.stage_snapshots:
            x = run.field(s, "x")[run.active(s)]
            x = x[np.isfinite(x).all(axis=1)]  # an unstable run's last snapshot may hold NaN
            if len(x):
                lo, hi = np.minimum(lo, x.min(axis=0)), np.maximum(hi, x.max(axis=0))
        pad = 2.0 * self.spacing
        self.xlim = (lo[0] - pad, hi[0] + pad)
        self.ylim = (lo[1] - pad, hi[1] + pad)

    def hydrostatic_max_kpa(self, x0):
        """rho_w g (kPa) times the tallest column of the initial body (points in
        vertical strips one point spacing wide, plus one spacing)."""
        strips = np.floor(x0[:, 0] / self.spacing).astype(np.int64)
        order = np.argsort(strips, kind="stable")
        strips, y = strips[order], x0[order, 1]
        starts = np.flatnonzero(np.r_[True, np.diff(strips) != 0])
        height = np.maximum.reduceat(y, starts) - np.minimum.reduceat(y, starts)
        return 9.81 * (float(height.max()) + self.spacing)

    def _typical_interval(self):
        t = [s.t for s in self.run.stage_snapshots]
        d = np.diff(t)
        return float(np.median(d)) if d.size else 0.0

    def pick(self, times):
        """[(requested t or None for the final, snapshot)], warning about far matches."""
        picks = []
        for t in times:
            snap = self.run.nearest(t)
            if abs(snap.t - t) > max(0.5 * self.interval, 1e-6) and t not in self._noted:
                self._noted.add(t)
                print(f"slope_figures: note: no snapshot near t = {t:g} s; using snapshot "
                      f"{snap.name} at t = {snap.t:.4g} s")
            picks.append((t, snap))
        return picks

    def title(self, requested, snap, what):
        if requested is None:
            text = f"{what}, final: snapshot {snap.name}, t = {snap.t:.4g} s"
        else:
            text = f"{what}, t = {requested:g} s (snapshot {snap.name}, t = {snap.t:.4g} s)"
        if self.aspect() > 1.0:  # narrow panels: one item per line
            text = text.replace(", ", "\n").replace(" (", "\n(")
        return text

    def draw(self, ax, snap, values, cmap, norm, only=None):
        """Points of `snap` as squares of the point spacing coloured by `values`."""
        from matplotlib.collections import PolyCollection
        act = self.run.active(snap) if only is None else only
        act = act & np.isfinite(self.run.field(snap, "x")).all(axis=1)
        x = self.run.field(snap, "x")[act]
        h = 0.6 * self.spacing  # covers the wider gap of Gauss-point layouts
        corners = np.array([[-h, -h], [h, -h], [h, h], [-h, h]])
        pc = PolyCollection(x[:, None, :] + corners[None, :, :], array=np.asarray(values)[act],
                            cmap=cmap, norm=norm, edgecolors="none", antialiased=False,
                            rasterized=True)
        ax.add_collection(pc)
        self.frame(ax)
        return pc

    def frame(self, ax):
        xs, ys = self.surface
        ax.plot(xs, ys, color="0.55", lw=0.6, zorder=3)
        ax.set_xlim(*self.xlim)
        ax.set_ylim(*self.ylim)
        ax.set_aspect("equal")
        ax.tick_params(labelsize=7)
        ax.set_ylabel("y (m)", fontsize=7)

    def aspect(self):
        return (self.ylim[1] - self.ylim[0]) / (self.xlim[1] - self.xlim[0])

    def layout(self, n_items, n_quantities, width_one=9.0, width_two=13.0, extra_h=0.0):
        """Axes per item (time), each a list of quantities: for a wide domain (a slope)
        stacks of panels in 1 or 2 columns; for a tall one (a column) one row."""
        _, plt = _mpl()
        aspect = self.aspect()
        if aspect > 1.0:
            n = n_items * n_quantities
            panel_h = 4.5
            width = min(n * (panel_h / aspect + 0.9) + 1.0, 20.0)
            fig, axes = plt.subplots(1, n, figsize=(width, panel_h + 1.6), squeeze=False,
                                     constrained_layout=True)
            grid = [[axes[0][i * n_quantities + q] for q in range(n_quantities)]
                    for i in range(n_items)]
            for ax in axes[0]:
                ax.set_xlabel("x (m)", fontsize=7)
            return fig, grid
        ncol = 1 if n_items <= 3 else 2
        nrow_items = math.ceil(n_items / ncol)
        width = width_one if ncol == 1 else width_two
        panel_w = (width - 1.3) / ncol
        height = nrow_items * n_quantities * (panel_w * aspect + 0.45) + 0.3 + extra_h
        fig, axes = plt.subplots(nrow_items * n_quantities, ncol, figsize=(width, height),
                                 squeeze=False, constrained_layout=True)
        grid = []
        for i in range(n_items):
            r, c = divmod(i, ncol)
            grid.append([axes[r * n_quantities + q][c] for q in range(n_quantities)])
        for i in range(n_items, nrow_items * ncol):
            r, c = divmod(i, ncol)
            for q in range(n_quantities):
                axes[r * n_quantities + q][c].set_axis_off()
        for ax in grid[-1][-1:] + ([grid[-2][-1]] if ncol == 2 and n_items > 1 else []):
            ax.set_xlabel("x (m)", fontsize=7)
        return fig, grid

    def save(self, fig, name):
        path = os.path.join(self.out, name)
        fig.savefig(path, dpi=DPI)
        _, plt = _mpl()
        plt.close(fig)
        print(f"wrote {path} ({os.path.getsize(path) / 1024:.0f} kB)")
        return path

    # Norms ----------------------------------------------------------------
    def eps_norm(self):
        from matplotlib import colors
        if self.eps_log:
            return colors.LogNorm(vmin=1e-3 * self.eps_max, vmax=self.eps_max, clip=True)
        return colors.Normalize(vmin=0.0, vmax=self.eps_max)

    def eps_cmap(self):
        """magma_r, with eps_p_bar = 0 (masked on the log scale) in its lowest colour."""
        matplotlib, _ = _mpl()
        cmap = matplotlib.colormaps["magma_r"].copy()
        cmap.set_bad(cmap(0.0))
        return cmap

    def pw_norm(self):
        from matplotlib import colors
        lo, hi = self.pw_range
        if lo < 0.0 < hi:
            return colors.TwoSlopeNorm(vmin=lo, vcenter=0.0, vmax=hi)
        return colors.Normalize(vmin=lo, vmax=hi)

    # Figures --------------------------------------------------------------
    def fig_pw_epsp(self, times):
        """Fig. 7 (two-phase: p_w over eps_p_bar) or Fig. 10 (dry: eps_p_bar)."""
        picks = self.pick(times) + [(None, self.run.stage_snapshots[-1])]
        two = self.run.two_phase
        # Room for the horizontal colour bars below the panels.
        fig, grid = self.layout(len(picks), 2 if two else 1, extra_h=1.3 if two else 0.7)
        pw_axes, eps_axes = [], []
        pw_pc = eps_pc = None
        for (t, snap), axs in zip(picks, grid):
            if two:
                pw = self.run.field(snap, "pore_pressure") / 1e3
                pw_pc = self.draw(axs[0], snap, pw, "RdYlBu", self.pw_norm())
                axs[0].set_title(self.title(t, snap, "$p_w$"), fontsize=8)
                pw_axes.append(axs[0])
            eps = self.run.field(snap, "plastic_shear_strain")
            eps_pc = self.draw(axs[-1], snap, eps, self.eps_cmap(), self.eps_norm())
            axs[-1].set_title(self.title(t, snap, r"$\bar\epsilon_p$"), fontsize=8)
            eps_axes.append(axs[-1])
        # Horizontal colour bars below all panels (p_w and eps rows alternate).
        all_axes = [a for axs in grid for a in axs]
        if two:
            cb = fig.colorbar(pw_pc, ax=all_axes, location="bottom", shrink=0.5, aspect=50,
                              extend="both", pad=0.01)
            cb.set_label("pore pressure $p_w$ (kPa)", fontsize=8)
            cb.ax.tick_params(labelsize=7)
        cb = fig.colorbar(eps_pc, ax=all_axes, location="bottom", shrink=0.5, aspect=50,
                          extend="max", pad=0.01)
        cb.set_label(r"plastic shear strain invariant $\bar\epsilon_p$"
                     + (" (log scale)" if self.eps_log else ""), fontsize=8)
        cb.ax.tick_params(labelsize=7)
        fig.suptitle(f"{self.run.case_name()}: stage '{self.run.stage}', t since its start"
                     + ("" if two else " (dry / total stress: no $p_w$)"), fontsize=9)
        return self.save(fig, "fig7_pw_epsp.png" if two else "fig10_epsp.png")

    def fig_shear_stress(self, times, limit_kpa=None):
        """Fig. 8: sigma_xy (kPa, tension-positive convention) at the times."""
        from matplotlib import colors
        picks = self.pick(times)
        values = [self.run.field(s, "stress")[:, 2] / 1e3 for _, s in picks]
        if limit_kpa is None:
            allv = np.concatenate([np.abs(v[self.run.active(s)]) for v, (_, s) in zip(values, picks)])
            allv = allv[np.isfinite(allv)]
            limit_kpa = max(5.0, 5.0 * math.ceil(np.percentile(allv, 99) / 5.0)) if allv.size else 5.0
        norm = colors.TwoSlopeNorm(vmin=-limit_kpa, vcenter=0.0, vmax=limit_kpa)
        fig, grid = self.layout(len(picks), 1)
        pc = None
        for (t, snap), v, axs in zip(picks, values, grid):
            pc = self.draw(axs[0], snap, v, "RdBu_r", norm)
            axs[0].set_title(self.title(t, snap, r"$\sigma_{xy}$"), fontsize=8)
        cb = fig.colorbar(pc, ax=[a[0] for a in grid], shrink=0.9, extend="both", aspect=30)
        cb.set_label(r"shear stress $\sigma_{xy}$ (kPa)", fontsize=8)
        cb.ax.tick_params(labelsize=7)
        fig.suptitle(f"{self.run.case_name()}: shear stress, stage '{self.run.stage}' "
                     f"(colour limits ±{limit_kpa:g} kPa)", fontsize=9)
        return self.save(fig, "fig8_shear_stress.png")

    def fig_final(self, metrics_result):
        """eps_p_bar, |u| since the stage start and the sliding groups at the end."""
        from matplotlib import colors
        _, plt = _mpl()
        snap = self.run.stage_snapshots[-1]
        fig, grid = self.layout(1, 3)
        axs = grid[0]
        eps = self.run.field(snap, "plastic_shear_strain")
        pc = self.draw(axs[0], snap, eps, self.eps_cmap(), self.eps_norm())
        axs[0].set_title(self.title(None, snap, r"$\bar\epsilon_p$"), fontsize=8)
        cb = fig.colorbar(pc, ax=axs[0], shrink=0.9, extend="max")
        cb.set_label(r"$\bar\epsilon_p$", fontsize=8)
        u = self.run.displacement_since_start(snap)
        d = np.hypot(u[:, 0], u[:, 1])
        pc = self.draw(axs[1], snap, d, "viridis",
                       colors.Normalize(0.0, max(1e-3, float(d[self.run.active(snap)].max()))))
        axs[1].set_title(self.title(None, snap, "displacement magnitude since the stage start"),
                         fontsize=8)
        cb = fig.colorbar(pc, ax=axs[1], shrink=0.9)
        cb.set_label("|u| (m)", fontsize=8)
        # Sliding groups of slope_metrics (grey: not sliding).
        _, labels = metrics_result["_labels"][snap.name]
        act = self.run.active(snap)
        self.draw(axs[2], snap, np.zeros(len(labels)), colors.ListedColormap(["0.85"]),
                  colors.Normalize(0, 1), only=act & (labels < 0))
        n_groups = 0
        if (labels >= 0).any():
            uniq, lab = np.unique(labels[labels >= 0], return_inverse=True)
            n_groups = uniq.size
            vals = np.zeros(len(labels))
            vals[labels >= 0] = lab
            cmap = plt.get_cmap("tab10", max(n_groups, 1))
            self.draw(axs[2], snap, vals, cmap, colors.Normalize(-0.5, max(n_groups, 1) - 0.5),
                      only=act & (labels >= 0))
        toe = metrics_result["toe_x_m"]
        fin = metrics_result["final"]
        axs[2].axvline(toe, color="k", lw=0.7, ls="--")
        if fin["max_x_sliding_m"] is not None:
            axs[2].axvline(fin["max_x_sliding_m"], color="C3", lw=0.7, ls="--")
        ro = fin["run_out_m"]
        axs[2].set_title(f"sliding groups (slope_metrics): {n_groups} group(s), area "
                         f"{fin['sliding_area_m2']:.1f} m², run-out "
                         + (f"{ro:.2f} m" if ro is not None else "-")
                         + f" (toe x = {toe:g} m, dashed)", fontsize=8)
        fig.suptitle(f"{self.run.case_name()}: final state", fontsize=9)
        return self.save(fig, "final_state.png")

    def fig_probes(self, path):
        """Fig. 9: v_w / K at the probes against stage time."""
        _, plt = _mpl()
        rows = sm.read_probes(path, ("time_s", "stage", "name", "x_m", "y_m", "v_w_x_m_per_s",
                                     "v_w_y_m_per_s", "K_m_per_s"))
        # Rows of the stage, plus a record at its start time written by the previous stage.
        t0, tol = self.run.stage_start_s, 1e-9 * max(1.0, abs(self.run.stage_start_s))
        own = [r for r in rows if r["stage"] == self.run.stage or abs(r["time_s"] - t0) <= tol]
        if not any(r["stage"] == self.run.stage for r in own):
            own = [r for r in rows if r["time_s"] >= self.run.stage_start_s - 1e-9]
        if not own:
            print(f"slope_figures: note: {path} has no row of stage '{self.run.stage}'; "
                  "fig9 skipped")
            return None
        if not any(r["K_m_per_s"] > 0 and math.isfinite(r["v_w_x_m_per_s"]) for r in own):
            print(f"slope_figures: note: {path} has no water velocity with K > 0 (a dry run?); "
                  "fig9 skipped")
            return None
        names = sorted({r["name"] for r in own})
        fig, ax = plt.subplots(figsize=(8.5, 4.8), constrained_layout=True)
        where = []
        for k, name in enumerate(names):
            rs = sorted((r for r in own if r["name"] == name), key=lambda r: r["time_s"])
            t = np.array([r["time_s"] for r in rs]) - self.run.stage_start_s
            K = np.array([r["K_m_per_s"] for r in rs])
            vx = np.array([r["v_w_x_m_per_s"] for r in rs])
            vy = np.array([r["v_w_y_m_per_s"] for r in rs])
            with np.errstate(divide="ignore", invalid="ignore"):
                mag, comp = np.hypot(vx, vy) / K, vx / K
            color = f"C{k % 10}"
            where.append(f"{name} ({rs[0]['x_m']:.1f}, {rs[0]['y_m']:.1f})")
            ax.plot(t, mag, color=color, lw=1.2, label=f"{name}: $|v_w|/K$")
            ax.plot(t, comp, color=color, lw=0.9, ls="--", label=f"{name}: $v_{{w,x}}/K$")
        ax.axhline(0.0, color="0.6", lw=0.5)
        ax.set_xlabel(f"time since the start of stage '{self.run.stage}' (s)")
        ax.set_ylabel("$v_w / K$ (-)")
        ax.set_title(f"{self.run.case_name()}: water velocity $v_w$ over the saturated hydraulic "
                     "conductivity K at the probes\n(solid: magnitude, dashed: x component; "
                     f"x, y in m at t = {t[0]:.3g} s: {', '.join(where)})", fontsize=8)
        ax.legend(fontsize=7, ncol=4, loc="upper center", bbox_to_anchor=(0.5, -0.14))
        ax.grid(alpha=0.3)
        return self.save(fig, "fig9_vw_over_K.png")


def default_times(run):
    """Stage times of the panels: around the slides of the run's verdict if it
    failed in the analysed stage, else the paper's times (two-phase) or 0.5, 2 s."""
    verdict = (run.metrics or {}).get("verdict") or {}
    onsets = [o["stage_time_s"] for o in verdict.get("onsets", [])
              if o.get("stage") == run.stage]
    if onsets:
        return [max(0.0, onsets[0] - 5.0)] + onsets[:3]
    return [10.0, 16.25, 18.75, 25.0] if run.two_phase else [0.5, 2.0]


def main(argv=None):
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("dir", help="results folder of a run")
    p.add_argument("--out", help="figure folder (default DIR/figures)")
    p.add_argument("--times", help="stage times, comma-separated (default: around the slides "
                                   "of a failed run, else 10,16.25,18.75,25 for two-phase runs, "
                                   "0.5,2.0 for dry runs)")
    p.add_argument("--eps-max", type=float, default=1.0, help="upper colour limit of eps_p_bar")
    p.add_argument("--eps-scale", choices=("log", "linear"), default="log",
                   help="colour scale of eps_p_bar: log (1e-3 to --eps-max, default) or linear")
    p.add_argument("--pw-range", help="p_w colour limits in kPa, 'LOW,HIGH' (default -50 to "
                                      "the hydrostatic pressure at the base of the body)")
    p.add_argument("--sxy-lim", type=float, help="sigma_xy colour limit in kPa (default: the 99th "
                                                 "percentile of |sigma_xy|, rounded up to 5 kPa)")
    sm.add_options(p)
    args = p.parse_args(argv)

    def body():
        toe, opts = sm.options_from(args)
        pw_range = tuple(parse_floats(args.pw_range, "--pw-range", 2)) if args.pw_range else None
        run = sm.Run(args.dir, args.stage)
        try:
            times = parse_floats(args.times, "--times") if args.times else default_times(run)
            out = args.out or os.path.join(args.dir, "figures")
            try:
                os.makedirs(out, exist_ok=True)
            except OSError as e:
                raise sm.InputError(f"{out}: cannot create the figure folder ({e})")
            plotter = Plotter(run, out, args.eps_max, args.eps_scale == "log", pw_range)
            plotter.fig_pw_epsp(times)
            plotter.fig_shear_stress(times, args.sxy_lim)
            plotter.fig_final(sm.slope_metrics(run, toe, **opts))
            probes = os.path.join(args.dir, "probes.csv")
            if os.path.isfile(probes):
                plotter.fig_probes(probes)
            else:
                print(f"slope_figures: note: {probes} not found; fig9 (v_w/K at the probes) skipped")
        finally:
            run.close()

    return sm.run_reporting_errors("slope_figures", body)


if __name__ == "__main__":
    sys.exit(main())
