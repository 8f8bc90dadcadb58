"""The seed's study: amplitudes 75-90 deg, Co-Simulation and Model Exchange, numeric vs exact.

The seed is Arwin Tsalas, "Simulasi model matematika gerak pendulum sederhana" (Universitas
Negeri Surabaya): its Figures 3-5 show theta against w0 t at 75, 80, 85 and 90 deg (redrawn
here against t/T0, in small-angle periods, so that the period's growth shows). Every run
goes through :class:`~pendulum_fmu.fmu.runner.FmuRunner` (the FMU extracted and loaded once).
"""

from __future__ import annotations

import csv
import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from pendulum_fmu.fmu.period import measured_period
from pendulum_fmu.fmu.runner import FmuRunner, Trajectory
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid

SEED_AMPLITUDES_DEG = (75.0, 80.0, 85.0, 90.0)
ME_TOLERANCE = 1e-10
POINTS_PER_PERIOD = 50
TABLE_HEADER = ("amplitude (deg)", "interface", "exact period (s)", "measured period (s)",
                "T/T0", "max abs(theta - theta_exact) (rad)")
MARKER_AMPLITUDES_DEG = (10.0, 30.0, 50.0, 75.0, 80.0, 85.0, 90.0, 110.0, 130.0, 150.0, 170.0, 175.0, 179.0,
                         179.9, 179.99)
"""Amplitudes whose period is also measured from a simulation (markers of the period figure)."""


@dataclass(frozen=True)
class PeriodCurve:
    """T / T0 against amplitude: the FMU's ``period`` output and measured numerical periods.

    Attributes
    ----------
    amplitudes_deg, ratios : numpy.ndarray
        The curve from the FMU's exact ``period`` (dense, 0.5 to 179.999999 deg).
    marker_amplitudes_deg, measured_ratios : numpy.ndarray
        Periods measured from the zero crossings of Co-Simulation runs (rkn, tol 1e-10).
    """

    amplitudes_deg: np.ndarray
    ratios: np.ndarray
    marker_amplitudes_deg: np.ndarray
    measured_ratios: np.ndarray


def run_study(runner: FmuRunner, periods: float = 10.0,
              progress: Callable[[str], None] | None = None) -> list[Trajectory]:
    """Simulate every seed amplitude in CS (the FMU's default method) and ME (CVODE, rtol 1e-10).

    Parameters
    ----------
    runner : FmuRunner
        The loaded FMU.
    periods : float
        Exact periods to simulate.
    progress : callable, optional
        Called with one line before each run (what it is, and how many are left).

    Returns
    -------
    list of Trajectory
        CS runs first, then ME runs, each in the order of the amplitudes.
    """
    grid = TimeGrid(periods, "periods", POINTS_PER_PERIOD)
    methods = (Method(), Method("cvode", ME_TOLERANCE))
    todo = [(method, a) for method in methods for a in SEED_AMPLITUDES_DEG]
    runs = []
    for k, (method, a) in enumerate(todo, 1):
        if progress is not None:
            progress(f"run {k} of {len(todo)}: {a:g} deg, {method.label}, {periods:g} periods")
        runs.append(runner.run(InitialValueProblem.from_degrees(a), method, grid))
    return runs


def table_rows(runs: list[Trajectory]) -> list[tuple[str, ...]]:
    """One row of TABLE_HEADER per run."""
    rows: list[tuple[str, ...]] = []
    for run in runs:
        p = run.problem
        measured = measured_period(run.result["time"], run.result["theta"])
        rows.append((f"{p.theta0_deg:g}", run.method.interface, f"{run.period:.9f}", f"{measured:.9f}",
                     f"{run.period / p.small_angle_period:.6f}", f"{run.max_error:.2e}"))
    return rows


def format_table(rows: list[tuple[str, ...]]) -> str:
    """A Markdown table of the rows under TABLE_HEADER."""
    lines = ["| " + " | ".join(TABLE_HEADER) + " |", "|" + "---|" * len(TABLE_HEADER)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def write_csv(runs: list[Trajectory], path: Path) -> None:
    """All runs in one long CSV: one line per run and time point, and the FMU's warnings of the run."""
    with path.open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["interface", "amplitude_deg", "time_s", "w0t", "theta_rad", "theta_exact_rad",
                         "omega_rad_s", "omega_exact_rad_s", "fmu_warning"])
        for run in runs:
            r, p = run.result, run.problem
            warning = "; ".join(run.warnings)
            for i in range(r.size):
                writer.writerow([run.method.interface, f"{p.theta0_deg:g}", repr(float(r["time"][i])),
                                 repr(float(p.w0 * r["time"][i])), repr(float(r["theta"][i])),
                                 repr(float(r["theta_exact"][i])), repr(float(r["omega"][i])),
                                 repr(float(r["omega_exact"][i])), warning])


def period_curve(runner: FmuRunner) -> PeriodCurve:
    """T / T0 from the FMU's ``period`` output, and measured at MARKER_AMPLITUDES_DEG.

    The curve is dense on a linear axis (0.5 .. 179.5 deg) and, toward the top, in
    180 deg - theta0 from 10 down to 1e-6 deg; the markers are Co-Simulation runs of 10
    exact periods, rkn at tol 1e-10, 50 points a period (L = 1, g = 9.81).
    """
    linear = np.linspace(0.5, 179.5, 359)
    top = 180.0 - np.logspace(1.0, -6.0, 120)
    amplitudes = np.unique(np.concatenate([linear, top]))
    ratios = np.array([runner.period(InitialValueProblem.from_degrees(float(a))) for a in amplitudes])
    ratios = ratios * math.sqrt(9.81) / (2.0 * math.pi)
    grid = TimeGrid(10, "periods", POINTS_PER_PERIOD)
    measured = []
    for amplitude in MARKER_AMPLITUDES_DEG:
        run = runner.run(InitialValueProblem.from_degrees(amplitude), Method("rkn", 1e-10), grid)
        measured.append(measured_period(run.result["time"], run.result["theta"]) / run.problem.small_angle_period)
    return PeriodCurve(amplitudes, ratios, np.array(MARKER_AMPLITUDES_DEG), np.array(measured))
