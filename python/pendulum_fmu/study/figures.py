"""The study's figures, drawn for the HTML report (about 1000 px wide, text at 11-13 pt).

- :func:`plot_solutions`: the seed's Figures 3 and 4, one panel per amplitude (small
  multiples), theta against w0 t;
- :func:`plot_comparison_grid`: Figure 5, numerical against exact, one column per amplitude,
  with |theta - theta_exact| of both interfaces on a log axis underneath;
- :func:`plot_period_ratio`: T / T0 against the amplitude on a linear axis, and the approach
  to 180 deg in a second panel, with the measured numerical periods as markers.
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pendulum_fmu.fmu.period import exact_period_ratio  # noqa: E402
from pendulum_fmu.fmu.runner import Trajectory  # noqa: E402
from pendulum_fmu.study.seed import PeriodCurve  # noqa: E402

STYLE = {"font.size": 12, "axes.titlesize": 13, "axes.labelsize": 12, "legend.fontsize": 11,
         "xtick.labelsize": 11, "ytick.labelsize": 11}
NUMERIC_COLOR = "tab:blue"
EXACT_COLOR = "black"
ME_COLOR = "tab:orange"
W0T_LABEL = r"$\omega_0 t$ (rad)"


def _w0t(run: Trajectory) -> np.ndarray:
    return run.pendulum.w0 * run.result["time"]


def _positive(values: np.ndarray) -> np.ndarray:
    """For a log axis: zeros (the error at t = 0) become NaN."""
    return np.where(values > 0.0, values, np.nan)


def plot_solutions(runs: list[Trajectory], field: str, title: str, path: Path) -> None:
    """theta (deg) against w0 t, one panel per amplitude, 2 x 2.

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
        fig, axes = plt.subplots(2, 2, figsize=(10, 6.4), sharex=True, sharey=True)
        for ax, run in zip(axes.flat, runs):
            amplitude = run.pendulum.amplitude_deg
            ax.plot(_w0t(run), np.degrees(run.result[field]), color=color, lw=1.3)
            ax.axhline(amplitude, color="0.6", lw=0.8, ls=":")
            ax.axhline(-amplitude, color="0.6", lw=0.8, ls=":")
            ax.set_title(rf"$\theta_0$ = {amplitude:g}$^\circ$")
            ax.set_ylim(-100, 100)
            ax.set_yticks([-90, -45, 0, 45, 90])
            ax.grid(alpha=0.3)
        for ax in axes[1]:
            ax.set_xlabel(W0T_LABEL)
        for ax in axes[:, 0]:
            ax.set_ylabel(r"$\theta$ (deg)")
        fig.suptitle(title)
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)


def plot_comparison_grid(cs_runs: list[Trajectory], me_runs: list[Trajectory], path: Path) -> None:
    """Figure 5: for each amplitude, numerical over exact theta, and the error on a log axis.

    Top row: the last two periods of the Co-Simulation run, numerical as a line, exact as
    open circles (so both stay visible where they coincide). Bottom row:
    |theta - theta_exact| over the whole run for Co-Simulation (rkn) and Model Exchange (CVODE).

    Parameters
    ----------
    cs_runs, me_runs : list of Trajectory
        One run per amplitude each, in the same order.
    path : Path
        PNG to write.
    """
    count = len(cs_runs)
    with plt.rc_context(STYLE):
        fig, axes = plt.subplots(2, count, figsize=(2.8 * count + 0.8, 6.6), sharey="row",
                                 gridspec_kw={"height_ratios": (1, 1)})
        for column, (cs, me) in enumerate(zip(cs_runs, me_runs)):
            top, bottom = axes[0, column], axes[1, column]
            w0t = _w0t(cs)
            last = w0t >= w0t[-1] - 2.0 * cs.period * cs.pendulum.w0 - 1e-9
            top.plot(w0t[last], np.degrees(cs.result["theta"][last]), color=NUMERIC_COLOR, lw=1.6,
                     label="numerical (CS, rkn)")
            top.plot(w0t[last], np.degrees(cs.result["theta_exact"][last]), "o", mfc="none", mec=EXACT_COLOR,
                     ms=4.5, mew=0.8, label="exact")
            top.set_title(rf"$\theta_0$ = {cs.pendulum.amplitude_deg:g}$^\circ$, last 2 periods")
            top.grid(alpha=0.3)
            bottom.semilogy(w0t, _positive(np.abs(cs.theta_error)), color=NUMERIC_COLOR, lw=1.2,
                            label="error, CS (rkn, tol 1e-8)")
            bottom.semilogy(_w0t(me), _positive(np.abs(me.theta_error)), color=ME_COLOR, lw=1.2,
                            label=f"error, ME (CVODE, rtol {me.method.effective_tolerance:g})")
            bottom.set_xlabel(W0T_LABEL)
            bottom.grid(alpha=0.3, which="major")
            bottom.set_ylim(1e-17, 1e-4)
        axes[0, 0].set_ylabel(r"$\theta$ (deg)")
        axes[1, 0].set_ylabel(r"$|\theta - \theta_{exact}|$ (rad)")
        handles = axes[0, 0].get_legend_handles_labels()[0] + axes[1, 0].get_legend_handles_labels()[0]
        labels = axes[0, 0].get_legend_handles_labels()[1] + axes[1, 0].get_legend_handles_labels()[1]
        fig.legend(handles, labels, loc="lower center", ncol=4, frameon=False)
        fig.suptitle("Figure 5: numerical against exact, and the error over the whole run")
        fig.tight_layout(rect=(0, 0.06, 1, 1))
        fig.savefig(path, dpi=110)
        plt.close(fig)


def plot_period_ratio(curve: PeriodCurve, seed_amplitudes_deg: tuple[float, ...], path: Path) -> None:
    """T / T0 against amplitude (linear), and near 180 deg against 180 deg - theta0 (log).

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
    markers = dict(ls="none", marker="o", ms=7, mfc="white", mec="tab:red", mew=1.6,
                   label="measured from a simulation (CS, rkn)")
    with plt.rc_context(STYLE):
        fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5.2), gridspec_kw={"width_ratios": (1.25, 1)})
        inside = a <= 179.5
        left.axvspan(min(seed_amplitudes_deg), max(seed_amplitudes_deg), color="0.9", label="the seed's 75-90 deg")
        left.plot(a[inside], ratio[inside], color=NUMERIC_COLOR, lw=2.4, label="FMU period output, 4K(m)/w0")
        small = a <= 120.0
        left.plot(a[small], 1.0 + theta0[small] ** 2 / 16.0, "--", color="0.3", lw=1.4,
                  label=r"small angle: $1 + \theta_0^2/16$")
        left.plot(curve.marker_amplitudes_deg[curve.marker_amplitudes_deg <= 179.5],
                  curve.measured_ratios[curve.marker_amplitudes_deg <= 179.5], **markers)
        left.set_xlim(0, 180)
        left.set_xticks(range(0, 181, 30))
        left.set_ylim(0.95, 3.2)
        left.set_xlabel(r"amplitude $\theta_0$ (deg)")
        left.set_ylabel(r"$T / T_0$,  $T_0 = 2\pi\sqrt{L/g}$")
        left.set_title("period against amplitude")
        left.grid(alpha=0.3)
        left.legend(loc="upper left")

        near = a >= 150.0
        gap = 180.0 - a[near]
        right.semilogx(gap, ratio[near], color=NUMERIC_COLOR, lw=2.4, label="FMU period output")
        # K(m) ~ ln(4/k'), k' = cos(theta0/2) ~ (pi - theta0)/2, so T/T0 ~ (2/pi) ln(8/(pi - theta0)).
        right.semilogx(gap, 2.0 / np.pi * np.log(8.0 / (np.pi - theta0[near])), "--", color="0.3", lw=1.4,
                       label=r"$(2/\pi)\ln(8/(\pi-\theta_0))$")
        right.semilogx(gap, exact_period_ratio(theta0[near]), ":", color="tab:green", lw=1.6,
                       label="2K(m)/pi, scipy")
        top = curve.marker_amplitudes_deg >= 150.0
        right.semilogx(180.0 - curve.marker_amplitudes_deg[top], curve.measured_ratios[top], **markers)
        right.invert_xaxis()
        right.set_xlabel(r"$180^\circ - \theta_0$ (deg), log scale")
        right.set_title("the approach to 180 deg: T grows like a logarithm")
        right.grid(alpha=0.3, which="both")
        right.legend(loc="upper left")
        fig.tight_layout()
        fig.savefig(path, dpi=110)
        plt.close(fig)
