"""The exact port at its edges: far times, g and L as given, huge angles, t = t0.

Each hard case runs through the FMU (Model Exchange, ``ExactPort``) against the
closed form in mpmath (``pendulum_fmu.bench.reference.closed_form``) with w0 = sqrt(g / L) taken exactly
from the two doubles, which is the problem the FMU promises to solve.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from pathlib import Path

import mpmath as mp
import pytest
from fmpy.fmi1 import FMICallException

from pendulum_fmu.bench.reference import closed_form, exact_frequency, max_abs_diff
from pendulum_fmu.fmu.exact_port import ExactPort
from test_exact_properties import errors

THETA_TOL = 5e-14
"""theta (rad), relative to max(1, |theta|)."""


@pytest.fixture(scope="module")
def port(fmu_path: Path) -> Iterator[ExactPort]:
    """One Model Exchange instance for the module."""
    with ExactPort(fmu_path) as exact_port:
        yield exact_port


def check_against_reference(port: ExactPort, theta0: float, omega0: float, length: float,
                            gravity: float, t0: float, times: list[float]) -> None:
    """theta within 5e-14 of max(1, |theta|) and omega within 5e-14 of its scale."""
    port.initialize(theta0, omega0, length, gravity, start_time=t0)
    theta, omega = port.evaluate(times)
    w0 = exact_frequency(length, gravity)
    ref_theta, ref_omega, _ = closed_form(theta0, omega0, w0, times, t0)
    theta_scale = max(1.0, max(float(abs(r)) for r in ref_theta))
    omega_scale = max(abs(omega0), 2.0 * float(w0))
    assert max_abs_diff(theta, ref_theta) <= THETA_TOL * theta_scale
    assert max_abs_diff(omega, ref_omega) <= THETA_TOL * omega_scale


# name: (theta0, omega0, L, g, t0, times) -- phases beyond 2^52 quarter periods
FAR_TIMES: dict[str, tuple[float, float, float, float, float, list[float]]] = {
    "rotation at t = 1e16": (0.0, 3.0, 1.0, 1.0, 0.0, [1e16, 1e16 + 0.37]),
    "w0 = 1e10 at t = 1e6": (2.0, 0.0, 1e-10, 1e10, 0.0, [1e6]),
    "libration at 2^58 quarter periods": (1.0, 0.0, 1.0, 1.0, 0.0, [1.7e17]),
}


@pytest.mark.parametrize("case", list(FAR_TIMES))
def test_far_times_against_closed_form(port: ExactPort, case: str) -> None:
    """Defect 1: at far times the phase is computed, not set to zero (was theta = 0 with OK)."""
    check_against_reference(port, *FAR_TIMES[case])


def test_beyond_the_resolved_phase_is_refused(port: ExactPort) -> None:
    """Beyond 2^60 quarter periods the FMU refuses (fmi2Error) instead of a made-up value."""
    port.initialize(1.0, 0.0, 1.0, 1.0)
    with pytest.raises(FMICallException):
        port.evaluate([1e300])
    port.initialize(1.0, 0.0, 1.0, 1.0)
    with pytest.raises(FMICallException):
        port.evaluate([2.0**62])           # just beyond 2^60 quarter periods (w0 = 1)


# states within rounding of the separatrix, regime decided by the doubles L, g
NEAR_SEPARATRIX: dict[str, tuple[float, float, float, float, float, list[float]]] = {
    "librates, fl(w0) rotated": (-3.719371225035692, -11.457420237565678, 2.9079038128992127e-06,
                                 0.0011758347489732547, -4841.935070399459, [-4836.590767737427]),
    "librates, fl(w0) rotated (2)": (3.0849789226170623, 0.034294831419746555, 374.6912982074549,
                                     137.53188593324322, 0.0, [100.0, 1000.0]),
}


@pytest.mark.parametrize("case", list(NEAR_SEPARATRIX))
def test_regime_of_the_doubles_as_given(port: ExactPort, case: str) -> None:
    """Defect 2: g / L and its root in double-double, so the port solves the given problem."""
    check_against_reference(port, *NEAR_SEPARATRIX[case])


def huge_angle_reference(theta0: float, omega0: float, t: float) -> tuple[float, float]:
    """theta(t) - theta0 and omega(t) for L = g = 1 and a huge theta0, reduced at 400 digits."""
    with mp.workdps(400):
        big = mp.mpf(theta0)
        reduced = big - 2 * mp.pi * mp.nint(big / (2 * mp.pi))
    ref_theta, ref_omega, _ = closed_form(reduced, omega0, 1.0, [t])
    with mp.workdps(50):
        return float(ref_theta[0] - reduced), float(ref_omega[0])


@pytest.mark.parametrize("theta0", [2.0**60 * 1.2345, -(2.0**200) * 1.7, 1.0e300, 2.0**53 + 2.0])
def test_huge_angles_reduced_exactly(port: ExactPort, theta0: float) -> None:
    """Defect 9: theta0 mod 2 pi with enough bits of 2 pi for any double (Payne-Hanek)."""
    port.initialize(theta0, 0.3, 1.0, 1.0)
    theta, omega = port.evaluate([0.7])
    change, ref_omega = huge_angle_reference(theta0, 0.3, 0.7)
    assert abs(omega[0] - ref_omega) <= 5e-15
    assert abs(theta[0] - (theta0 + change)) <= math.ulp(theta0)


@pytest.mark.parametrize("theta0, omega0, length, gravity, t0", [
    (math.radians(75.0), 0.0, 1.0, 9.81, 0.0),
    (math.pi, 0.0, 1.0, 9.81, 3.0),
    (-20.0, 0.3, 2.0, 9.81, -50.0),
    (0.5, -2.5, 1.0, 1.0, 1e3),
    (1e300, 1.0, 1.0, 1.0, 0.0),
])
def test_initial_state_bit_for_bit(port: ExactPort, theta0: float, omega0: float, length: float,
                                   gravity: float, t0: float) -> None:
    """Defect 10: at t = t0 the exact port returns the initial state as given, bit for bit."""
    port.initialize(theta0, omega0, length, gravity, start_time=t0)
    theta, omega = port.evaluate([t0])
    assert theta[0] == theta0 and omega[0] == omega0
    assert math.copysign(1.0, omega[0]) == math.copysign(1.0, omega0)


def separatrix_neighbours(state: tuple[float, float, float, float, float],
                          ulps: tuple[int, ...]) -> list[tuple[float, float, float, float, float]]:
    """The state with omega0 moved to the separatrix speed (rounded) and `ulps` ulps beside it."""
    theta0, omega0, length, gravity, t0 = state
    with mp.workdps(50):
        speed = float(2 * mp.sqrt(mp.mpf(gravity) / mp.mpf(length)) * abs(mp.cos(mp.mpf(theta0) / 2)))
    neighbours = []
    for count in ulps:
        omega = speed
        for _ in range(abs(count)):
            omega = math.nextafter(omega, math.inf if count > 0 else 0.0)
        neighbours.append((theta0, math.copysign(omega, omega0), length, gravity, t0))
    return neighbours


MILLION_PERIODS = (-8.590185225219782, -0.00015596141618645683, 101418.16746011787, 0.003754548068946949, 1000.0)


@pytest.mark.parametrize("state", [MILLION_PERIODS, *separatrix_neighbours(MILLION_PERIODS, (-3, -1, 0, 1, 3))],
                         ids=["found", "-3 ulps", "-1 ulp", "rounded", "+1 ulp", "+3 ulps"])
def test_next_to_the_separatrix_after_a_million_periods(
        port: ExactPort, state: tuple[float, float, float, float, float]) -> None:
    """5e-14 after 1e6 periods next to the separatrix (was 1.6e-10, 3.1e-9 beside it)."""
    theta_error, _ = errors(port, state, (1e6 + 0.37,))
    assert theta_error <= 5e-14
