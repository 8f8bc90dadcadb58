"""The seed's runs through fmpy's own ``simulate_fmu``, beside the package's runner.

The tests of the seed's study drive the FMU the plain way an importer would (fmpy's
Co-Simulation loop, or its CVODE in Model Exchange) rather than through
:class:`~pendulum_fmu.fmu.runner.FmuRunner`, so that they check the FMU and not the package's
loop. Released from rest below the top, the time span counts in the period 4 K(m) / w0, K
from scipy's ``ellipkm1`` (no cancellation near the top).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

import numpy as np
from fmpy import simulate_fmu
from scipy.special import ellipkm1

from pendulum_fmu.spec import InitialValueProblem

Interface = Literal["CS", "ME"]


@dataclass(frozen=True)
class Scenario:
    """The pendulum (L = 1 m, g = 9.81 m/s^2) released from rest at ``amplitude_deg``, run for
    ``periods`` periods with ``points_per_period`` output points each."""

    amplitude_deg: float
    periods: float = 10.0
    points_per_period: int = 50

    @property
    def problem(self) -> InitialValueProblem:
        """The initial value problem."""
        return InitialValueProblem.from_degrees(self.amplitude_deg)

    @property
    def w0(self) -> float:
        """sqrt(g / L), rad/s."""
        return self.problem.w0

    @property
    def period(self) -> float:
        """4 K(m) / w0, s."""
        return 4.0 * float(ellipkm1(math.cos(self.problem.theta0 / 2.0) ** 2)) / self.w0


@dataclass
class FmpyRun:
    """One run: time, theta, omega, theta_exact and omega_exact at the output points."""

    scenario: Scenario
    result: np.ndarray = field(repr=False)

    @property
    def max_error(self) -> float:
        """max |theta - theta_exact| over the output points, rad."""
        return float(np.max(np.abs(self.result["theta"] - self.result["theta_exact"])))


def simulate(fmu: Path, scenario: Scenario, interface: Interface = "CS", tolerance: float | None = None) -> FmpyRun:
    """Run ``scenario`` with fmpy's ``simulate_fmu`` (None: the FMU's default tolerance)."""
    step = scenario.period / scenario.points_per_period
    steps = round(scenario.periods * scenario.points_per_period)
    result = simulate_fmu(str(fmu), fmi_type="CoSimulation" if interface == "CS" else "ModelExchange",
                          start_time=0.0, stop_time=steps * step, output_interval=step, relative_tolerance=tolerance,
                          start_values=scenario.problem.start_values(),
                          output=["theta", "omega", "theta_exact", "omega_exact"], validate=False)
    return FmpyRun(scenario, result)
