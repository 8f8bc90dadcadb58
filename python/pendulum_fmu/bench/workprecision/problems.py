"""The problems of the speed-against-error study and their exact answers.

P1 is the seed's amplitudes 75, 80, 85 and 90 deg over 10 periods, P2 179.99 deg over 20
periods (the pendulum released next to the top, 7.6e-9 below the separatrix in energy), P3
90 deg over 10,000 periods. All start from rest with g = 9.81 m/s2 and L = 1 m (a
:class:`Case` holds its :class:`~pendulum_fmu.spec.InitialValueProblem` and its length in
periods), and are sampled on the same grid: ``points`` points a period, t_i = i T / points.

The truth is the FMU's own ``theta_exact``, read through its Model Exchange interface at the
grid times (:func:`exact_theta`); it is checked against mpmath by tests of its own.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from fmpy import read_model_description
from fmpy.fmi2 import FMU2Model

from pendulum_fmu.spec import InitialValueProblem


@dataclass(frozen=True)
class Case:
    """One initial value problem of a study problem, and how long it runs.

    Attributes
    ----------
    problem : str
        ``"P1"``, ``"P2"`` or ``"P3"``.
    ivp : InitialValueProblem
        The pendulum and its start (from rest, L = 1 m, g = 9.81 m/s2 in every study problem).
    periods : float
        Length of the run in exact periods.
    """

    problem: str
    ivp: InitialValueProblem
    periods: float

    @classmethod
    def from_rest(cls, problem: str, amplitude_deg: float, periods: float) -> Case:
        """The case released from rest at ``amplitude_deg`` degrees, L = 1 m, g = 9.81 m/s2."""
        return cls(problem, InitialValueProblem.from_degrees(amplitude_deg), periods)

    @property
    def amplitude_deg(self) -> float:
        """Release angle in degrees."""
        return self.ivp.theta0_deg

    @property
    def w0sq(self) -> float:
        """w0^2 = g / L in 1/s2."""
        return self.ivp.g / self.ivp.L

    @property
    def energy0(self) -> float:
        """H0 = omega0^2 / 2 + 2 w0^2 sin^2(theta0 / 2), the energy per unit m L^2 (J/(kg m2))."""
        return 0.5 * self.ivp.omega0 ** 2 + 2.0 * self.w0sq * math.sin(0.5 * self.ivp.theta0) ** 2


def cases(problem: str, p3_periods: float = 10_000.0) -> tuple[Case, ...]:
    """The initial value problems of a study problem.

    Parameters
    ----------
    problem : str
        ``"P1"``, ``"P2"`` or ``"P3"``.
    p3_periods : float
        Length of P3 in periods (10,000 in the study; shorter for a quick run).

    Returns
    -------
    tuple of Case
        Four cases for P1, one for P2 and P3.

    Raises
    ------
    ValueError
        For an unknown problem name.
    """
    if problem == "P1":
        return tuple(Case.from_rest("P1", a, 10.0) for a in (75.0, 80.0, 85.0, 90.0))
    if problem == "P2":
        return (Case.from_rest("P2", 179.99, 20.0),)
    if problem == "P3":
        return (Case.from_rest("P3", 90.0, p3_periods),)
    raise ValueError(f"unknown problem {problem!r}: P1, P2 or P3")


@dataclass(frozen=True)
class Grid:
    """The output grid of one case and the exact solution on it.

    Attributes
    ----------
    case : Case
        The problem.
    period : float
        The exact period in s (the FMU's ``period``).
    points : int
        Output points a period.
    times : numpy.ndarray
        t_i = i * (period / points), i = 0 .. periods * points (as fmpy forms them).
    theta_exact : numpy.ndarray
        The exact angle at ``times``.
    """

    case: Case
    period: float
    points: int
    times: np.ndarray
    theta_exact: np.ndarray

    @property
    def interval(self) -> float:
        """Output interval period / points in s."""
        return self.period / self.points

    @property
    def stop_time(self) -> float:
        """Last grid time in s."""
        return float(self.times[-1])


def _model_exchange_instance(unzipped: Path, case: Case) -> FMU2Model:
    """An initialized Model Exchange instance of the FMU in continuous-time mode."""
    md = read_model_description(str(unzipped), validate=False)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    fmu = FMU2Model(guid=md.guid, unzipDirectory=str(unzipped), modelIdentifier=md.modelExchange.modelIdentifier,
                    instanceName="truth")
    fmu.instantiate()
    fmu.setupExperiment(startTime=0.0)
    start = case.ivp.start_values()
    fmu.setReal([vr[name] for name in start], list(start.values()))
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    fmu.enterContinuousTimeMode()
    return fmu


def exact_theta(unzipped: Path, case: Case, times: np.ndarray) -> tuple[float, np.ndarray]:
    """The FMU's exact period and ``theta_exact`` at the given times.

    Parameters
    ----------
    unzipped : Path
        The extracted FMU.
    case : Case
        The problem.
    times : numpy.ndarray
        Times in s.

    Returns
    -------
    tuple of (float, numpy.ndarray)
        The period in s and theta_exact at ``times`` in rad.
    """
    md = read_model_description(str(unzipped), validate=False)
    vr = {v.name: v.valueReference for v in md.modelVariables}
    fmu = _model_exchange_instance(unzipped, case)
    try:
        period = float(fmu.getReal([vr["period"]])[0])
        theta = np.empty(len(times))
        ref = [vr["theta_exact"]]
        for i, t in enumerate(times):
            fmu.setTime(float(t))
            theta[i] = fmu.getReal(ref)[0]
    finally:
        fmu.terminate()
        fmu.freeInstance()
    return period, theta


def make_grid(unzipped: Path, case: Case, points: int) -> Grid:
    """The output grid of a case with the exact solution on it.

    Parameters
    ----------
    unzipped : Path
        The extracted FMU.
    case : Case
        The problem.
    points : int
        Output points a period.

    Returns
    -------
    Grid
        Times and theta_exact, computed once per case and shared by every run.
    """
    period, _ = exact_theta(unzipped, case, np.zeros(0))
    n = round(case.periods * points)
    times = np.arange(n + 1) * (period / points)
    _, theta = exact_theta(unzipped, case, times)
    return Grid(case=case, period=period, points=points, times=times, theta_exact=theta)


def energy_errors(theta: np.ndarray, omega: np.ndarray, case: Case) -> tuple[float, float, float]:
    """Relative energy error of a numerical solution.

    Parameters
    ----------
    theta, omega : numpy.ndarray
        The solution on the grid.
    case : Case
        The problem (its w0^2 and its energy H0).

    Returns
    -------
    tuple of float
        max |H - H0| / H0 over all points, over the first tenth and over the last tenth of
        them (a drift shows as the last larger than the first);
        H = omega^2 / 2 + 2 w0^2 sin^2(theta / 2).
    """
    h = 0.5 * omega**2 + 2.0 * case.w0sq * np.sin(0.5 * theta) ** 2
    rel = np.abs(h - case.energy0) / case.energy0
    tenth = max(len(rel) // 10, 1)
    return float(np.max(rel)), float(np.max(rel[:tenth])), float(np.max(rel[-tenth:]))
