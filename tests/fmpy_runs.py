"""The seed's runs through fmpy's own ``simulate_fmu``, beside the package's runner.

The tests of the seed's study drive the FMU the plain way an importer would (fmpy's
Co-Simulation loop, or its CVODE in Model Exchange) rather than through
:class:`~pendulum_fmu.fmu.runner.FmuRunner`, so that they check the FMU and not the package's
loop. The time span counts in the period of the problem released from rest (4 K(m) / w0,
K from scipy's ``ellipkm1``: no cancellation near the top), or in 2 pi / w0 otherwise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

import numpy as np
from fmpy import simulate_fmu
from scipy.special import ellipkm1

Interface = Literal["CS", "ME"]

SEED_OUTPUTS = ("theta", "omega", "theta_exact", "omega_exact")
"""What every seed run records, besides time."""


@dataclass(frozen=True)
class Scenario:
    """An initial value problem of the pendulum and how long to run it.

    Attributes
    ----------
    amplitude_deg : float
        theta(0), degrees.
    omega0 : float
        theta'(0), rad/s.
    length, gravity : float
        L (m) and g (m/s^2).
    periods : float
        Duration in periods (see :attr:`period`).
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
        """sqrt(g / L), rad/s."""
        return math.sqrt(self.gravity / self.length)

    @property
    def period(self) -> float:
        """4 K(m) / w0 released from rest below the top, else 2 pi / w0, s."""
        if self.omega0 == 0.0 and abs(self.amplitude_deg) < 180.0:
            return 4.0 * float(ellipkm1(math.cos(math.radians(self.amplitude_deg) / 2.0) ** 2)) / self.w0
        return 2.0 * math.pi / self.w0

    def start_values(self) -> dict[str, float]:
        """The FMU's start values."""
        return {"L": self.length, "g": self.gravity, "theta": math.radians(self.amplitude_deg), "omega": self.omega0}


@dataclass
class FmpyRun:
    """One run's recorded outputs (``time`` and :data:`SEED_OUTPUTS`)."""

    scenario: Scenario
    interface: Interface
    tolerance: float | None
    result: np.ndarray = field(repr=False)

    @property
    def max_error(self) -> float:
        """max |theta - theta_exact| over the recorded points, rad."""
        return float(np.max(np.abs(self.result["theta"] - self.result["theta_exact"])))


def simulate(fmu: Path, scenario: Scenario, interface: Interface = "CS", tolerance: float | None = None) -> FmpyRun:
    """Run ``scenario`` with fmpy's ``simulate_fmu`` (None: the FMU's default tolerance)."""
    step = scenario.period / scenario.points_per_period
    steps = round(scenario.periods * scenario.points_per_period)
    result = simulate_fmu(str(fmu), fmi_type="CoSimulation" if interface == "CS" else "ModelExchange",
                          start_time=0.0, stop_time=steps * step, output_interval=step, relative_tolerance=tolerance,
                          start_values=scenario.start_values(), output=list(SEED_OUTPUTS), validate=False)
    return FmpyRun(scenario, interface, tolerance, result)
