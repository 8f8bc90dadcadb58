"""The seed's study: amplitudes 75-90 deg, Co-Simulation and Model Exchange, numeric vs exact.

The seed is Arwin Tsalas, "Simulasi model matematika gerak pendulum sederhana" (Universitas
Negeri Surabaya): its Figures 3-5 show theta against w0 t at 75, 80, 85 and 90 deg.
"""

from __future__ import annotations

import csv
import math
import shutil
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from pendulum_fmu.fmu.simulate import Interface, Run

SEED_AMPLITUDES_DEG = (75.0, 80.0, 85.0, 90.0)
ME_TOLERANCE = 1e-10
TABLE_HEADER = ("amplitude (deg)", "interface", "exact period (s)", "measured period (s)",
                "T/T0", "max abs(theta - theta_exact) (rad)")


def run_study(fmu: Path, periods: float = 10.0) -> list[Run]:
    """Simulate every seed amplitude in CS (default tolerance) and ME (rtol 1e-10).

    Parameters
    ----------
    fmu : Path
        The FMU.
    periods : float
        Exact periods to simulate.

    Returns
    -------
    list of Run
        CS runs first, then ME runs, each in the order of the amplitudes.
    """
    from pendulum_fmu.fmu.simulate import Scenario, simulate

    runs = []
    settings: tuple[tuple[Interface, float | None], ...] = (("CS", None), ("ME", ME_TOLERANCE))
    for interface, tolerance in settings:
        for amplitude in SEED_AMPLITUDES_DEG:
            scenario = Scenario(amplitude_deg=amplitude, periods=periods)
            runs.append(simulate(fmu, scenario, interface, tolerance))
    return runs


def table_rows(runs: list[Run]) -> list[tuple[str, ...]]:
    """One row of TABLE_HEADER per run."""
    from pendulum_fmu.fmu.period import exact_period, measured_period

    rows: list[tuple[str, ...]] = []
    for run in runs:
        s = run.scenario
        period = exact_period(math.radians(s.amplitude_deg), s.w0)
        measured = measured_period(run.result["time"], run.result["theta"])
        rows.append((f"{s.amplitude_deg:g}", run.interface, f"{period:.9f}", f"{measured:.9f}",
                     f"{period * s.w0 / (2 * math.pi):.6f}", f"{run.max_error:.2e}"))
    return rows


def format_table(rows: list[tuple[str, ...]]) -> str:
    """A Markdown table of the rows under TABLE_HEADER."""
    lines = ["| " + " | ".join(TABLE_HEADER) + " |", "|" + "---|" * len(TABLE_HEADER)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return "\n".join(lines)


def write_csv(runs: list[Run], path: Path) -> None:
    """All runs in one long CSV: one line per run and time point."""
    with path.open("w", newline="") as file:
        writer = csv.writer(file)
        writer.writerow(["interface", "amplitude_deg", "time_s", "w0t", "theta_rad", "theta_exact_rad",
                         "omega_rad_s", "omega_exact_rad_s"])
        for run in runs:
            r = run.result
            for i in range(r.size):
                writer.writerow([run.interface, run.scenario.amplitude_deg, repr(float(r["time"][i])),
                                 repr(float(run.scenario.w0 * r["time"][i])), repr(float(r["theta"][i])),
                                 repr(float(r["theta_exact"][i])), repr(float(r["omega"][i])),
                                 repr(float(r["omega_exact"][i]))])


def period_ratio_curve(fmu: Path) -> tuple[np.ndarray, np.ndarray]:
    """T / T0 from the FMU's ``period`` output, amplitudes from 1 deg to 179.999999 deg.

    One Model Exchange instance is reset and re-initialized for each amplitude (L = 1,
    g = 9.81), and ``period`` is read right after initialization.
    """
    from fmpy import extract, instantiate_fmu, read_model_description

    amplitudes = 180.0 - np.logspace(np.log10(179.0), -6, 120)
    md = read_model_description(str(fmu))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    w0 = math.sqrt(9.81)
    unzipped = extract(str(fmu))
    instance = instantiate_fmu(unzipped, md, fmi_type="ModelExchange")
    ratios = []
    for amplitude in amplitudes:
        instance.reset()
        instance.setupExperiment(startTime=0.0)
        instance.enterInitializationMode()
        instance.setReal([vr["theta"]], [math.radians(amplitude)])
        instance.exitInitializationMode()
        ratios.append(instance.getReal([vr["period"]])[0] * w0 / (2 * math.pi))
    instance.freeInstance()
    shutil.rmtree(unzipped, ignore_errors=True)
    return amplitudes, np.array(ratios)
