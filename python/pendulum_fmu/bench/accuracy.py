"""Benchmark: the accuracy of the FMU's exact solution against mpmath at 50 digits.

For each case the FMU is initialized through Model Exchange
(:class:`~pendulum_fmu.fmu.exact_port.ExactPort`), ``theta_exact`` and ``omega_exact`` are
read at N equally spaced times over three periods (40 / w0 on the separatrix), and compared
with :func:`~pendulum_fmu.bench.reference.closed_form` at the same binary inputs. The omega
error is relative to the amplitude of omega. The last case runs one period after 10^6
periods and also reports the naive scipy evaluation
theta = 2 arcsin(sqrt(m) sn(K - w0 t | m)) there, for comparison.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from pendulum_fmu.bench.reference import DIGITS, closed_form, exact_frequency, frequency, max_abs_diff, omega_scale
from pendulum_fmu.fmu.exact_port import ExactPort
from pendulum_fmu.spec import InitialValueProblem

CASES: dict[str, InitialValueProblem] = {
    "at rest at the bottom": InitialValueProblem(0.0),
    "10 deg": InitialValueProblem.from_degrees(10.0),
    "90 deg": InitialValueProblem.from_degrees(90.0),
    "170 deg": InitialValueProblem.from_degrees(170.0),
    "pi - 1e-6": InitialValueProblem(math.pi - 1e-6),
    "pi - 1e-12": InitialValueProblem(math.pi - 1e-12),
    "pi (the double)": InitialValueProblem(math.pi),
    "separatrix, forward": InitialValueProblem(0.0, 5.0, g=6.25),          # g/L = 6.25: w0 = 2.5 exactly
    "separatrix, backward": InitialValueProblem(0.0, -5.0, g=6.25),
    "rotation, forward": InitialValueProblem(0.5, 2.5, g=1.0),
    "rotation, backward": InitialValueProblem(0.5, -2.5, g=1.0),
}
LONG_CASE = "170 deg, w0 = 1, after 1e6 periods"


@dataclass(frozen=True)
class Accuracy:
    """The errors of one case.

    Attributes
    ----------
    case : str
        Its name.
    theta_error : float
        max |theta_exact - reference| over the points, rad.
    omega_error : float
        max |omega_exact - reference| over the points, divided by the amplitude of omega.
    naive_scipy_error : float
        The naive scipy evaluation's theta error (NaN where not measured).
    """

    case: str
    theta_error: float
    omega_error: float
    naive_scipy_error: float = math.nan


def measure(fmu: Path, points: int = 301) -> list[Accuracy]:
    """Every case of CASES over three periods, then the 10^6-period case.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.
    points : int
        Evaluation times per case.

    Returns
    -------
    list of Accuracy
        In the order of CASES, the long case last.
    """
    results = []
    with ExactPort(fmu) as port:
        for name, problem in CASES.items():
            port.initialize(problem.theta0, problem.omega0, problem.L, problem.g)
            period = port.period()
            horizon = 3.0 * period if math.isfinite(period) else 40.0 / frequency(problem.L, problem.g)
            times = np.linspace(0.0, horizon, points)
            results.append(_compare(name, port, problem, times))
        long_case = InitialValueProblem.from_degrees(170.0, g=1.0)
        port.initialize(long_case.theta0, 0.0, 1.0, 1.0)
        period = port.period()
        times = 1e6 * period + np.linspace(0.0, period, points)
        long_run = _compare(LONG_CASE, port, long_case, times)
        results.append(Accuracy(LONG_CASE, long_run.theta_error, long_run.omega_error,
                                _naive_scipy_error(long_case.theta0, times)))
    return results


def _compare(name: str, port: ExactPort, problem: InitialValueProblem, times: np.ndarray) -> Accuracy:
    theta, omega = port.evaluate(times)
    ref_theta, ref_omega, _ = closed_form(problem.theta0, problem.omega0, exact_frequency(problem.L, problem.g), times)
    return Accuracy(name, max_abs_diff(theta, ref_theta),
                    max_abs_diff(omega, ref_omega) / omega_scale(ref_omega, frequency(problem.L, problem.g)))


def _naive_scipy_error(theta0: float, times: np.ndarray) -> float:
    """theta = 2 arcsin(sqrt(m) sn(K - t | m)) with scipy (w0 = 1), against mpmath."""
    from scipy.special import ellipj, ellipk

    m = math.sin(theta0 / 2.0) ** 2
    sn = ellipj(ellipk(m) - times, m)[0]
    naive = 2.0 * np.arcsin(math.sqrt(m) * sn)
    ref_theta, _, _ = closed_form(theta0, 0.0, 1.0, times)
    return max_abs_diff(naive, ref_theta)


__all__ = ["CASES", "DIGITS", "LONG_CASE", "Accuracy", "measure"]
