"""Figures: the seed's study (theta against w0 t, the period ratio T / T0) and a run's error."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from .period import exact_period_ratio  # noqa: E402
from .runner import Trajectory  # noqa: E402
from .simulate import Run  # noqa: E402


def plot_theta_against_w0t(runs: list[Run], kind: str, title: str, path: Path) -> None:
    """Plot theta (deg) against w0 t for several amplitudes, as in the seed's Figures 3-5.

    Parameters
    ----------
    runs : list of Run
        One run per amplitude.
    kind : {"numeric", "exact", "overlay"}
        Which curves: the FMU's numerical theta, its exact theta_exact, or both.
    title : str
        Figure title.
    path : Path
        PNG file to write.
    """
    fig, ax = plt.subplots(figsize=(11, 4.8))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for run, color in zip(runs, colors):
        w0t = run.scenario.w0 * run.result["time"]
        label = f"{run.scenario.amplitude_deg:g} deg"
        if kind in ("numeric", "overlay"):
            ax.plot(w0t, np.degrees(run.result["theta"]), color=color, lw=1.4,
                    label=f"{label} numeric ({run.interface})")
        if kind in ("exact", "overlay"):
            style = dict(ls="none", marker="o", ms=2.5) if kind == "overlay" else dict(lw=1.4)
            ax.plot(w0t, np.degrees(run.result["theta_exact"]), color=color,
                    label=f"{label} exact (Jacobi elliptic)", **style)
    ax.set_xlabel(r"$\omega_0 t$ (rad), $\omega_0 = \sqrt{g/L}$")
    ax.set_ylabel(r"$\theta$ (deg)")
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def plot_period_ratio(amplitudes_deg: np.ndarray, fmu_ratio: np.ndarray, path: Path) -> None:
    """Plot T / T0 against amplitude with the small-angle and log-singularity asymptotes.

    Parameters
    ----------
    amplitudes_deg : numpy.ndarray
        Amplitudes in degrees, up to just below 180.
    fmu_ratio : numpy.ndarray
        T / T0 from the FMU's ``period`` output at those amplitudes.
    path : Path
        PNG file to write.
    """
    theta0 = np.radians(amplitudes_deg)
    gap = 180.0 - amplitudes_deg
    fig, ax = plt.subplots(figsize=(8, 4.8))
    ax.semilogx(gap, fmu_ratio, lw=2.2, label="FMU period / T0")
    ax.semilogx(gap, exact_period_ratio(theta0), "k--", lw=1, label="2 K(m) / pi (scipy)")
    low, high = amplitudes_deg <= 100.0, amplitudes_deg >= 80.0
    ax.semilogx(gap[low], 1.0 + theta0[low] ** 2 / 16.0, ":", lw=2, label=r"small angle $1 + \theta_0^2/16$")
    # K(m) ~ ln(4 / k'), k' = cos(theta0/2) ~ (pi - theta0)/2  =>  T/T0 ~ (2/pi) ln(8 / (pi - theta0))
    ax.semilogx(gap[high], 2.0 / np.pi * np.log(8.0 / (np.pi - theta0[high])), "-.", lw=2,
                label=r"near the top $(2/\pi)\ln(8/(\pi-\theta_0))$")
    ax.invert_xaxis()
    ax.set_ylim(0.9, float(np.max(fmu_ratio)) * 1.05)
    ax.set_xlabel(r"$180^\circ - \theta_0$ (deg), log scale")
    ax.set_ylabel(r"$T / T_0$,  $T_0 = 2\pi\sqrt{L/g}$")
    ax.set_title("Period of the pendulum released from rest")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def _positive(values: np.ndarray) -> np.ndarray:
    """Values for a log axis: zeros (e.g. at t = 0, where the error vanishes) become NaN."""
    return np.where(values > 0.0, values, np.nan)


def plot_comparison(trajectory: Trajectory, path: Path) -> None:
    """Numerical against exact theta, and the error over time, in one PNG.

    Parameters
    ----------
    trajectory : Trajectory
        A run of :class:`~pendulum_fmu.runner.FmuRunner`.
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
    bottom.semilogy(time, _positive(np.abs(trajectory.theta_error)), lw=1.2,
                    label=r"$|\theta - \theta_{exact}|$ (rad)")
    bottom.semilogy(time, _positive(np.abs(result["omega"] - result["omega_exact"])), lw=1.0, alpha=0.8,
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
