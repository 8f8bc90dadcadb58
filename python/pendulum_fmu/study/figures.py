"""The study's figures, drawn for the HTML report (about 1000 px wide, text at 11-13 pt).

- :func:`plot_solutions`: the seed's Figures 3 and 4, one row per amplitude on a shared
  axis of t / T0, with a mark at the end of every period;
- :func:`plot_comparison_grid`: Figure 5, numerical against exact, one column per amplitude,
  with |theta - theta_exact| of both interfaces on a log axis underneath;
- :func:`plot_period_ratio`: T / T0 against the amplitude on a linear axis, and the approach
  to 180 deg in a second panel, with the measured numerical periods as markers.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import MaxNLocator

from pendulum_fmu.fmu.period import exact_period_ratio
from pendulum_fmu.fmu.runner import Trajectory
from pendulum_fmu.study.seed import PeriodCurve

if TYPE_CHECKING:
    from matplotlib.typing import RcKeyType

STYLE: dict[RcKeyType, Any] = {"font.size": 12, "axes.titlesize": 13, "axes.labelsize": 12, "legend.fontsize": 11,
                                 "xtick.labelsize": 11, "ytick.labelsize": 11}
NUMERIC_COLOR = "tab:blue"
EXACT_COLOR = "black"
ME_COLOR = "tab:orange"
CS_ERROR_COLOR = "tab:purple"
EXACT_BAND = "0.72"
ZERO_ROW = 6.0
"""Figure 5: ME's exact-zero ticks sit this factor above CS's on the log axis, so neither hides the other."""
T_LABEL = r"$t / T_0$"


def _cycles(run: Trajectory) -> np.ndarray:
    """The run's output times in small-angle periods T0 = 2 pi sqrt(L/g), as in Figures 3 and 4."""
    return run.result["time"] / run.problem.small_angle_period


def constants_text(runs: list[Trajectory]) -> str:
    """``L = 1 m, g = 9.81 m/s^2, T0 = 2 pi sqrt(L/g) = 2.006 s`` for the runs' pendulum (mathtext);
    each distinct pendulum once, should the runs differ."""
    seen = dict.fromkeys((r.problem.L, r.problem.g, r.problem.small_angle_period) for r in runs)
    return "; ".join(rf"L = {length:g} m, g = {gravity:g} m/s$^2$, $T_0 = 2\pi\sqrt{{L/g}}$ = {t0:.4g} s"
                     for length, gravity, t0 in seen)


def _positive(values: np.ndarray) -> np.ndarray:
    """For a log axis: zeros (the error at t = 0) become NaN."""
    return np.where(values > 0.0, values, np.nan)


def plot_solutions(runs: list[Trajectory], field: str, title: str, path: Path) -> None:
    """theta (deg) against t / T0, one row per amplitude on a shared time axis.

    Every row counts time in small-angle periods T0 = 2 pi sqrt(L/g), so the grid lines at
    whole T0 are the same for all amplitudes; a triangle marks the end of each of the run's
    own periods T. The larger the amplitude, the further its triangles fall behind the grid
    lines (after 10 periods, 90 deg is almost two T0 behind): the period grows with
    amplitude at every period, not only at the end. Dashed lines at +theta0 and -theta0.

    Parameters
    ----------
    runs : list of Trajectory
        One Co-Simulation run per amplitude.
    field : {"theta", "theta_exact"}
        The numerical or the exact solution.
    title : str
        Figure title.
    path : Path
        PNG to write.
    """
    color = NUMERIC_COLOR if field == "theta" else EXACT_COLOR
    with plt.rc_context(STYLE):
        fig, axes = plt.subplots(len(runs), 1, figsize=(10.5, 1.75 * len(runs) + 1.5), sharex=True, sharey=True,
                                 squeeze=False)
        for ax, run in zip(axes[:, 0], runs, strict=True):
            amplitude = run.problem.theta0_deg
            t0 = run.problem.small_angle_period
            cycles = run.result["time"] / t0
            ax.plot(cycles, np.degrees(run.result[field]), color=color, lw=1.3)
            for sign in (1.0, -1.0):
                ax.axhline(sign * amplitude, color="tab:red", lw=1.0, ls="--", alpha=0.8)
            ax.text(1.005, amplitude, r"$+\theta_0$", transform=ax.get_yaxis_transform(), color="tab:red",
                    va="center", fontsize=10)
            ax.text(1.005, -amplitude, r"$-\theta_0$", transform=ax.get_yaxis_transform(), color="tab:red",
                    va="center", fontsize=10)
            ratio = run.period / t0
            ends = np.arange(1, int(cycles[-1] / ratio + 1e-9) + 1) * ratio
            ax.plot(ends, np.full(ends.size, 112.0), "v", color="0.15", ms=6, clip_on=False)
            ax.set_ylim(-100, 100)
            ax.set_yticks([-90, 0, 90])
            ax.set_xticks(np.arange(0, math.ceil(cycles[-1]) + 1))
            ax.grid(alpha=0.45, axis="x", color="0.5", lw=0.8)
            ax.grid(alpha=0.2, axis="y")
            ax.set_ylabel(rf"$\theta_0$ = {amplitude:g}$^\circ$" + "\n" + r"$\theta$ (deg)")
            ax.text(1.008, 0.5, f"T =\n{ratio:.4f} $T_0$", transform=ax.transAxes, va="center", fontsize=10.5)
        last = axes[-1, 0]
        last.set_xlim(0, max(run.result["time"][-1] / run.problem.small_angle_period for run in runs))
        last.set_xlabel(rf"$t / T_0$ (grid lines every $T_0$);  {constants_text(runs)}")
        fig.suptitle(title + "\n" + r"$\blacktriangledown$ end of each period T: the larger $\theta_0$, the further "
                     r"behind the $T_0$ grid lines", fontsize=13)
        fig.tight_layout(rect=(0, 0, 0.965, 1))
        fig.savefig(path, dpi=110)
        plt.close(fig)


def plot_comparison_grid(cs_runs: list[Trajectory], me_runs: list[Trajectory], path: Path) -> None:
    """Figure 5: for each amplitude, numerical over exact theta, and the error on a log axis.

    Top row: the last two periods of the Co-Simulation run: the exact solution as a wide pale
    band, the numerical one as a thin line on top of it (inside the band where they agree).
    Bottom row: |theta - theta_exact| over the whole run for Co-Simulation (rkn) and Model
    Exchange (CVODE); errors that are exactly 0 (a log axis has no place for them) are marked
    by ticks on the bottom edge.

    Parameters
    ----------
    cs_runs, me_runs : list of Trajectory
        One run per amplitude each, in the same order.
    path : Path
        PNG to write.
    """
    count = len(cs_runs)
    floor = 1e-17
    with plt.rc_context(STYLE):
        fig, axes = plt.subplots(2, count, figsize=(2.9 * count + 0.8, 8.0), sharey="row", squeeze=False)
        zeros_seen = False
        for column, (cs, me) in enumerate(zip(cs_runs, me_runs, strict=True)):
            top, bottom = axes[0, column], axes[1, column]
            cycles = _cycles(cs)
            last = cycles >= cycles[-1] - 2.0 * cs.period / cs.problem.small_angle_period - 1e-9
            top.plot(cycles[last], np.degrees(cs.result["theta_exact"][last]), color=EXACT_BAND, lw=7,
                     solid_capstyle="butt", label="exact (wide band)")
            top.plot(cycles[last], np.degrees(cs.result["theta"][last]), color=NUMERIC_COLOR, lw=1.3,
                     label="numerical, CS rkn (thin line)")
            top.set_title(rf"$\theta_0$ = {cs.problem.theta0_deg:g}$^\circ$, last 2 periods")
            top.set_xlabel(T_LABEL)
            top.grid(alpha=0.3)
            for run, color, label, row in ((cs, CS_ERROR_COLOR, "error, CS (rkn, tol 1e-8)", 1.0),
                                           (me, ME_COLOR, f"error, ME (CVODE, rtol {me.method.effective_tolerance:g})",
                                            ZERO_ROW)):
                error = np.abs(run.theta_error)
                bottom.semilogy(_cycles(run), _positive(error), color=color, lw=1.1, label=label)
                zero = error == 0.0
                if zero.any():  # CS's ticks on the bottom edge, ME's a row above: both seen at t = 0
                    zeros_seen = True
                    bottom.plot(_cycles(run)[zero], np.full(int(zero.sum()), floor * row), "|", color=color, ms=9,
                                mew=1.5, clip_on=False)
            bottom.set_xlabel(T_LABEL)
            bottom.grid(alpha=0.3, which="major")
            bottom.set_ylim(floor, 1e-4)
        axes[0, 0].set_ylabel(r"$\theta$ (deg)")
        axes[1, 0].set_ylabel(r"$|\theta - \theta_{exact}|$ (rad)")
        top_handles, top_labels = axes[0, 0].get_legend_handles_labels()
        fig.legend(top_handles, top_labels, loc="upper center", bbox_to_anchor=(0.5, 0.915), ncol=2, frameon=False,
                   fontsize=10)
        handles, labels = axes[1, 0].get_legend_handles_labels()
        if zeros_seen:
            for color, where in ((CS_ERROR_COLOR, "CS, bottom edge"), (ME_COLOR, "ME, a row above")):
                handles.append(plt.Line2D([], [], ls="none", marker="|", ms=9, mew=1.5, color=color))
                labels.append(f"error exactly 0 ({where}: a log axis has no 0)")
        fig.legend(handles, labels, loc="lower center", ncol=2, frameon=False, fontsize=10)
        fig.suptitle("Figure 5: numerical against exact (top), and the error over the whole run (bottom)\n"
                     + constants_text(cs_runs), fontsize=13)
        for ax in axes.flat:  # whole T0 on every panel, as in Figures 3 and 4
            ax.xaxis.set_major_locator(MaxNLocator(nbins=5, integer=True))
        fig.tight_layout(rect=(0, 0.08, 1, 0.885))
        fig.savefig(path, dpi=110)
        plt.close(fig)


def plot_period_ratio(curve: PeriodCurve, seed_amplitudes_deg: tuple[float, ...], path: Path) -> None:
    r"""T / T0 against amplitude (linear), and near 180 deg against 180 deg - theta0 (log).

    Left: the whole range, the seed's 75-90 deg shaded, the small-angle series and the
    periods measured from simulations (circles; those too high for this panel are drawn in
    the right one only, and said so). Right: the approach to 180 deg on a log axis of the
    distance 180 deg - theta0, which shrinks to the right; the FMU's output as a wide band,
    scipy's 2K(m)/pi as crosses on it and the logarithmic asymptote as a dashed line.

    Parameters
    ----------
    curve : PeriodCurve
        The FMU's period output and the measured numerical periods.
    seed_amplitudes_deg : tuple of float
        The seed's amplitudes, shaded in the left panel.
    path : Path
        PNG to write.
    """
    a, ratio = curve.amplitudes_deg, curve.ratios
    theta0 = np.radians(a)
    marker_a, measured = curve.marker_amplitudes_deg, curve.measured_ratios
    markers = dict(ls="none", marker="o", ms=7, mfc="white", mec="tab:red", mew=1.6, zorder=5,
                   label="measured from a simulation (CS, rkn)")
    with plt.rc_context(STYLE):
        fig, (left, right) = plt.subplots(1, 2, figsize=(12.5, 5.4), gridspec_kw={"width_ratios": (1.2, 1)})
        top_ratio = 3.2
        inside = a <= 179.5
        left.axvspan(min(seed_amplitudes_deg), max(seed_amplitudes_deg), color="0.9",
                     label=f"the seed's {min(seed_amplitudes_deg):g}-{max(seed_amplitudes_deg):g}$^\\circ$")
        left.plot(a[inside], ratio[inside], color=NUMERIC_COLOR, lw=2.4, label=r"FMU period output, $4K(m)/\omega_0$")
        small = a <= 120.0
        left.plot(a[small], 1.0 + theta0[small] ** 2 / 16.0, "--", color="0.3", lw=1.4,
                  label=r"small angle: $1 + \theta_0^2/16$, $\theta_0$ in rad")
        shown = measured <= top_ratio
        left.plot(marker_a[shown], measured[shown], **markers)
        hidden = marker_a[~shown]
        if hidden.size:
            # in the empty space below the legend and above the curve, pointing to the top right
            left.annotate(f"measured at {', '.join(f'{v:g}' for v in hidden)}$^\\circ$:\nT/$T_0$ > {top_ratio:g}, "
                          "see the right panel", xy=(179.0, top_ratio), xytext=(8, 2.55), fontsize=10,
                          ha="left", va="top", arrowprops={"arrowstyle": "->", "color": "0.3",
                                                           "connectionstyle": "arc3,rad=-0.15"})
        left.set_xlim(0, 181)
        left.set_xticks(range(0, 181, 30))
        left.set_ylim(0.95, top_ratio)
        left.set_xlabel(r"amplitude $\theta_0$ (deg)")
        left.set_ylabel(r"$T / T_0$,  $T_0 = 2\pi\sqrt{L/g}$")
        left.set_title("period against amplitude")
        left.grid(alpha=0.3)
        left.legend(loc="upper left", fontsize=10)

        near = a >= 150.0
        gap = 180.0 - a[near]
        right.semilogx(gap, ratio[near], color=NUMERIC_COLOR, lw=7, alpha=0.35, solid_capstyle="butt",
                       label=r"FMU period output, $4K(m)/\omega_0$ (band)")
        every = max(1, int(near.sum()) // 14)
        right.semilogx(gap[::every], exact_period_ratio(theta0[near])[::every], "x", color="k", ms=6, mew=1.4,
                       label=r"$2K(m)/\pi$ from scipy (crosses)")
        # K(m) ~ ln(4/k'), k' = cos(theta0/2) ~ (pi - theta0)/2, so T/T0 ~ (2/pi) ln(8/(pi - theta0)).
        right.semilogx(gap, 2.0 / np.pi * np.log(8.0 / (np.pi - theta0[near])), "--", color="tab:green", lw=1.6,
                       label=r"asymptote $(2/\pi)\ln(8/(\pi-\theta_0))$")
        top = marker_a >= 150.0
        right.semilogx(180.0 - marker_a[top], measured[top], **markers)
        right.set_xlim(60.0, 3e-7)  # decreasing: theta0 grows to the right
        right.set_xlabel(r"$180^\circ - \theta_0$ (deg), log scale: $\theta_0$ grows to the right $\rightarrow$")
        right.set_ylabel(r"$T / T_0$")
        right.set_title(r"the approach to 180$^\circ$: T grows like a logarithm")
        right.grid(alpha=0.3, which="major")  # a line a decade; the minor ticks stay as ticks
        right.legend(loc="upper left", fontsize=10)
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)
