"""One run's numerical solution against the exact one, and the error over time, in one PNG."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pendulum_fmu.fmu.runner import FmuRunner, Trajectory  # noqa: E402
from pendulum_fmu.spec import Method, Pendulum, TimeGrid  # noqa: E402


def positive_or_nan(values: np.ndarray) -> np.ndarray:
    """Values for a log axis: zeros (e.g. at t = 0, where the error vanishes) become NaN."""
    return np.where(values > 0.0, values, np.nan)


def plot_comparison(trajectory: Trajectory, path: Path) -> None:
    """Numerical against exact theta, and the error over time, in one PNG.

    Parameters
    ----------
    trajectory : Trajectory
        A run of :class:`~pendulum_fmu.fmu.runner.FmuRunner`.
    path : Path
        PNG file to write.
    """
    result, p = trajectory.result, trajectory.pendulum
    time = result["time"]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(10, 6.4), sharex=True,
                                      gridspec_kw={"height_ratios": (3, 2)})
    top.plot(time, np.degrees(result["theta"]), lw=1.6, label=f"numeric ({trajectory.method.label})")
    top.plot(time, np.degrees(result["theta_exact"]), "k--", lw=1.0, label="exact (Jacobi elliptic, in the FMU)")
    top.set_ylabel(r"$\theta$ (deg)")
    top.legend(fontsize=8, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=2, frameon=False)
    top.grid(alpha=0.3)
    bottom.semilogy(time, positive_or_nan(np.abs(trajectory.theta_error)), lw=1.2,
                    label=r"$|\theta - \theta_{exact}|$ (rad)")
    bottom.semilogy(time, positive_or_nan(np.abs(result["omega"] - result["omega_exact"])), lw=1.0, alpha=0.8,
                    label=r"$|\omega - \omega_{exact}|$ (rad/s)")
    bottom.axhline(trajectory.method.effective_tolerance, color="grey", ls=":", lw=1,
                   label=f"tolerance {trajectory.method.effective_tolerance:g}")
    bottom.set_xlabel("t (s)")
    bottom.set_ylabel("absolute error (rad, rad/s)")
    bottom.legend(fontsize=8, loc="lower right")
    bottom.grid(alpha=0.3, which="both")
    fig.suptitle(f"Numerical against exact: {p.amplitude_deg:.6g} deg, omega0 = {p.omega0:g} rad/s, "
                 f"L = {p.length:g} m, g = {p.gravity:g} m/s$^2$", fontsize=11)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def compare(fmu: Path, pendulum: Pendulum, method: Method, grid: TimeGrid, out: Path) -> Trajectory:
    """Simulate and write the comparison figure.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.
    pendulum, method, grid
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
        trajectory = planned_run(runner, pendulum, method, grid)  # refused at once when it cannot fit
    plot_comparison(trajectory, out)
    return trajectory

