"""The study's figures: theta against w0 t (the seed's Figures 3-5) and the period ratio T / T0."""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from pendulum_fmu.fmu.period import exact_period_ratio  # noqa: E402


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
