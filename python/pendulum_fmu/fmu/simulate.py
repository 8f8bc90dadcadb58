"""Run the FMU through fmpy, in Co-Simulation or Model Exchange."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

import numpy as np
from fmpy import simulate_fmu
from scipy.special import ellipk

Interface = Literal["CS", "ME"]

RECORDED = ("theta", "omega", "theta_exact", "omega_exact")


@dataclass(frozen=True)
class Scenario:
    """An initial value problem of the pendulum and how long to run it.

    Attributes
    ----------
    amplitude_deg : float
        Initial angle theta(0) in degrees.
    omega0 : float
        Initial angular velocity in rad/s.
    length : float
        L in m.
    gravity : float
        g in m/s^2.
    periods : float
        Duration in exact periods (released from rest) or, for other states, in small-angle
        periods 2 pi / w0.
    points_per_period : int
        Output points per period.
    """

    amplitude_deg: float
    omega0: float = 0.0
    length: float = 1.0
    gravity: float = 9.81
    periods: float = 10.0
    points_per_period: int = 50

    @property
    def w0(self) -> float:
        """Small-angle angular frequency sqrt(g / L) in rad/s."""
        return math.sqrt(self.gravity / self.length)

    @property
    def period(self) -> float:
        """Period used for the time span: 4 K(m) / w0 at rest, else 2 pi / w0 (seconds)."""
        if self.omega0 == 0.0 and abs(self.amplitude_deg) < 180.0:
            m = math.sin(math.radians(self.amplitude_deg) / 2.0) ** 2
            return 4.0 * float(ellipk(m)) / self.w0
        return 2.0 * math.pi / self.w0

    def start_values(self) -> dict[str, float]:
        """Start values to hand to the FMU."""
        return {"L": self.length, "g": self.gravity,
                "theta": math.radians(self.amplitude_deg), "omega": self.omega0}


@dataclass
class Run:
    """One simulation's recorded outputs.

    Attributes
    ----------
    scenario : Scenario
        What was simulated.
    interface : str
        ``"CS"`` or ``"ME"``.
    tolerance : float or None
        Relative tolerance handed to the FMU / CVODE (None: the FMU's default experiment).
    result : numpy.ndarray
        Structured array with fields time, theta, omega, theta_exact, omega_exact.
    """

    scenario: Scenario
    interface: Interface
    tolerance: float | None
    result: np.ndarray = field(repr=False)

    @property
    def max_error(self) -> float:
        """max |theta - theta_exact| over the recorded points (rad)."""
        return float(np.max(np.abs(self.result["theta"] - self.result["theta_exact"])))


def simulate(fmu: Path, scenario: Scenario, interface: Interface = "CS",
             tolerance: float | None = None) -> Run:
    """Simulate one scenario with fmpy.

    Parameters
    ----------
    fmu : Path
        The FMU file.
    scenario : Scenario
        Initial state, parameters and time span.
    interface : {"CS", "ME"}
        Co-Simulation (the FMU's own solver) or Model Exchange (fmpy's CVODE).
    tolerance : float, optional
        Relative tolerance; None uses the FMU's default experiment (1e-8).

    Returns
    -------
    Run
        The recorded outputs on the grid of ``points_per_period`` points a period.
    """
    step = scenario.period / scenario.points_per_period
    steps = round(scenario.periods * scenario.points_per_period)
    result = simulate_fmu(
        str(fmu),
        fmi_type="CoSimulation" if interface == "CS" else "ModelExchange",
        start_time=0.0,
        stop_time=steps * step,
        output_interval=step,
        relative_tolerance=tolerance,
        start_values=scenario.start_values(),
        output=list(RECORDED),
        validate=False,
    )
    return Run(scenario=scenario, interface=interface, tolerance=tolerance, result=result)
