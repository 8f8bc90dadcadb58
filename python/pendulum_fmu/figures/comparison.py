"""One run's numerical solution against the exact one, and the error over time, in one PNG."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from pendulum_fmu.fmu.runner import FmuRunner, Trajectory
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid


def positive_or_nan(values: np.ndarray) -> np.ndarray:
    """Values for a log axis: zeros (e.g. at t = 0, where the error vanishes) become NaN."""
    return np.where(values > 0.0, values, np.nan)


def error_panel(ax: plt.Axes, time: np.ndarray, error: np.ndarray, color: str, label: str) -> None:
    """One absolute error on its own log axis, labelled by its unit; times where it is exactly 0
    (no place on a log axis) as ticks on the bottom edge, explained above the panel."""
    ax.semilogy(time, positive_or_nan(error), color=color, lw=1.2)
    zero = error == 0.0
    if zero.any():
        ax.plot(time[zero], np.zeros(int(zero.sum())), "|", color=color, ms=10, mew=1.5, clip_on=False,
                transform=ax.get_xaxis_transform(), label="exactly 0 (ticks on the bottom edge: a log axis has no 0)")
        ax.legend(fontsize=8, loc="lower right", bbox_to_anchor=(1.0, 1.0), frameon=False, borderaxespad=0.1)
    ax.set_ylabel(label)
    ax.grid(alpha=0.3, which="major")


def plot_comparison(trajectory: Trajectory, path: Path) -> None:
    """Numerical against exact theta, and each error over time on its own axis, in one PNG.

    The errors of theta (rad) and omega (rad/s) are absolute, each on its own log axis, with
    their exact zeros marked; the solver's tolerance is relative, so it is named in the legend
    and not drawn as a line on an absolute axis. Every legend sits above its panel, off the curves.

    Parameters
    ----------
    trajectory : Trajectory
        A run of :class:`~pendulum_fmu.fmu.runner.FmuRunner`.
    path : Path
        PNG file to write.
    """
    result, p = trajectory.result, trajectory.problem
    time = result["time"]
    fig, (top, theta_ax, omega_ax) = plt.subplots(3, 1, figsize=(10, 8), sharex=True,
                                                  gridspec_kw={"height_ratios": (3, 2, 2)})
    top.plot(time, np.degrees(result["theta"]), lw=1.6,
             label=f"numeric ({trajectory.method.label}, a relative tolerance)")
    top.plot(time, np.degrees(result["theta_exact"]), "k--", lw=1.0, label="exact (Jacobi elliptic, in the FMU)")
    top.set_ylabel(r"$\theta$ (deg)")
    top.legend(fontsize=8, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=2, frameon=False)
    top.grid(alpha=0.3)
    error_panel(theta_ax, time, np.abs(trajectory.theta_error), "tab:blue", r"$|\theta - \theta_{exact}|$ (rad)")
    error_panel(omega_ax, time, np.abs(result["omega"] - result["omega_exact"]), "tab:orange",
                r"$|\omega - \omega_{exact}|$ (rad/s)")
    omega_ax.set_xlabel("t (s)")
    fig.suptitle(f"Numerical against exact: {p.theta0_deg:.6g} deg, omega0 = {p.omega0:g} rad/s, "
                 f"L = {p.L:g} m, g = {p.g:g} m/s$^2$", fontsize=11)
    fig.align_ylabels()
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def compare(fmu: Path, problem: InitialValueProblem, method: Method, grid: TimeGrid, out: Path) -> Trajectory:
    """Simulate and write the comparison figure.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.
    problem, method, grid
        What to run.
    out : Path
        The PNG to write.

    Returns
    -------
    Trajectory
        The run drawn.
    """
    from pendulum_fmu.sizing import planned_run

    with FmuRunner(fmu) as runner:
        trajectory = planned_run(runner, problem, method, grid)  # refused at once when it cannot fit
    plot_comparison(trajectory, out)
    return trajectory

