"""The study's work-precision figure: error against cost for every method, with the floor.

Two panels share the error axis (max |theta - theta_exact| over the seed's amplitudes, log,
more accurate to the right): the cost in right-hand-side evaluations (machine-independent)
and in wall time per simulated period (this machine), where the exact solution's own cost at
the same points is drawn as the floor. Each marker is one tolerance; the loosest and the
tightest are labelled in the left panel.
"""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from pendulum_fmu.study.figures import STYLE
from pendulum_fmu.study.speed import LEVELS, METHODS, SpeedStudy, curve

COLORS = {"dopri5": "tab:blue", "rk4": "tab:red", "rkn": "tab:green", "symplectic": "tab:purple",
          "cvode": "tab:orange"}
MARKERS = {"dopri5": "o", "rk4": "s", "rkn": "D", "symplectic": "^", "cvode": "v"}
SMALLEST_SHOWN = 1e-16
"""Errors below this (none so far) are drawn at it, so that a log axis can place them."""


def _label(method: str) -> str:
    return "CVODE (ME, fmpy)" if method == "cvode" else f"{method} (CS, FMU)"


def plot_work_precision(study: SpeedStudy, path: Path) -> None:
    """Error against evaluations and against wall time per period, one curve a method.

    Parameters
    ----------
    study : SpeedStudy
        The points and the floor.
    path : Path
        PNG to write.
    """
    with plt.rc_context(STYLE):
        fig, (ax_rhs, ax_wall) = plt.subplots(1, 2, figsize=(13.0, 7.0), sharex=True, constrained_layout=True)
        for method in METHODS:
            points = curve(study.points, method)
            if not points:
                continue
            errors = [max(p.max_error, SMALLEST_SHOWN) for p in points]
            style = {"color": COLORS[method], "marker": MARKERS[method], "markersize": 5,
                     "linewidth": 2.4 if method == "rkn" else 1.5, "label": _label(method)}
            ax_rhs.loglog(errors, [p.rhs_evaluations for p in points], **style)
            ax_wall.loglog(errors, [p.wall_per_period * 1e6 for p in points], **style)
            for k in (0, len(points) - 1):   # left panel only: the right one has the same points
                ax_rhs.annotate(f"{points[k].tolerance:.0e}", (errors[k], points[k].rhs_evaluations),
                                textcoords="offset points", xytext=(4, -12 if k == 0 else 5), fontsize=8,
                                color=COLORS[method])
        floor = study.floor.wall_per_period
        if math.isfinite(floor):
            ax_wall.axhline(floor * 1e6, color="black", linewidth=1.3, linestyle="-.",
                            label=f"floor: the exact solution at the same points ({floor * 1e6:.2g} us)")
        ax_rhs.text(0.98, 0.02, "the exact solution evaluates no right-hand side:\nits floor is the right panel's line",
                    transform=ax_rhs.transAxes, ha="right", va="bottom", fontsize=9, color="0.3")
        for ax in (ax_rhs, ax_wall):
            for level in LEVELS:
                ax.axvline(level, color="0.85", linewidth=0.8, zorder=0)
            ax.grid(True, which="major", axis="y", alpha=0.4)
            ax.set_xlabel(r"max $|\theta - \theta_{\mathrm{exact}}|$ (rad), more accurate to the right")
        ax_rhs.invert_xaxis()   # shared: both panels
        ax_rhs.set_ylabel("right-hand-side evaluations (sum of the 4 runs)")
        ax_rhs.set_title("cost in evaluations of sin (machine-independent)")
        ax_wall.set_ylabel("wall time per simulated period (us)")
        ax_wall.set_title("cost in wall time (this machine)")
        handles, labels = ax_wall.get_legend_handles_labels()   # one legend for both, below them
        fig.legend(handles, labels, loc="outside lower center", ncol=3, fontsize=10)
        amplitudes = ", ".join(f"{a:g}" for a in study.amplitudes_deg)
        fig.suptitle(f"Speed against error: {amplitudes} deg from rest, {study.periods:g} periods each\n"
                     "one marker a tolerance (the loosest and the tightest labelled on the left)", fontsize=13)
        fig.savefig(path, dpi=110)
        plt.close(fig)
