"""The FMU's exact solution (theta_exact, omega_exact, period) against mpmath at 50 digits.

Everything goes through the FMU (Model Exchange, :class:`pendulum_fmu.fmu.exact_port.ExactPort`).
The references take the FMU's binary inputs exactly (theta0, omega0, t, L and g as given,
w0 = sqrt(g / L) of those two doubles unrounded, as the FMU takes it) and work at 50
significant digits:

(a) ``mpmath.odefun``: Taylor integration of theta'' = -w0^2 sin(theta) itself, over a
    fraction of a period (it costs seconds per case at 50 digits);
(b) the closed form with mpmath's own ``ellipfun``, ``ellipk``, ``ellipf``: three periods in
    every regime, the period, and 1e6 periods at 170 deg.

Plus hypothesis properties over (theta0, omega0, L, g) with the hard corners (amplitudes
within 1e-12 of pi, at rest, on and next to the separatrix, fast rotation): accuracy against
(b), conservation of H = omega^2/2 + 2 w0^2 sin^2(theta/2), odd symmetry, and continuity
across the separatrix.
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pendulum_fmu.bench.reference import DIGITS, closed_form, exact_frequency, frequency, max_abs_diff, omega_scale
from pendulum_fmu.fmu.exact_port import ExactPort
from reference_cache import cached

THETA_TOL = 5e-14
"""Accuracy target for theta (rad) over the first three periods."""

OMEGA_REL_TOL = 5e-14
"""Accuracy target for omega, relative to the amplitude of omega."""


# --------------------------------------------------------------------------------------
# references
# --------------------------------------------------------------------------------------

def ode_reference(theta0: float, omega0: float, w0: float,
                  times: Sequence[float]) -> tuple[list[mp.mpf], list[mp.mpf]]:
    """Solution by ``mpmath.odefun`` (Taylor series method) at ``DIGITS`` digits from t = 0.

    Parameters
    ----------
    theta0, omega0 : float
        Initial state at t = 0.
    w0 : float or mpmath.mpf
        sqrt(g / L) (the exact root of the doubles g / L, see :func:`exact_frequency`).
    times : sequence of float
        Increasing times >= 0 (odefun caches the path, so each later time extends it).

    Returns
    -------
    theta, omega : list of mpmath.mpf
    """
    def compute() -> list[list[str]]:
        with mp.workdps(DIGITS):
            w0_squared = mp.mpf(w0) ** 2
            solution = mp.odefun(lambda _t, y: [y[1], -w0_squared * mp.sin(y[0])],
                                 0, [mp.mpf(theta0), mp.mpf(omega0)])
            values = [solution(mp.mpf(t)) for t in times]
            return [[str(v[0]) for v in values], [str(v[1]) for v in values]]

    # odefun costs seconds per case: computed once, then read from build/test-cache/.
    theta, omega = cached("odefun", (theta0, omega0, w0, tuple(times), DIGITS), compute)
    with mp.workdps(DIGITS):
        return [mp.mpf(v) for v in theta], [mp.mpf(v) for v in omega]


@pytest.fixture(scope="module")
def port(fmu_path: Path) -> Iterator[ExactPort]:
    """One Model Exchange instance of the FMU for the whole module."""
    with ExactPort(fmu_path) as exact_port:
        yield exact_port


# --------------------------------------------------------------------------------------
# regimes: three periods against the closed form, and the period
# --------------------------------------------------------------------------------------

W0_EARTH = frequency(1.0, 9.81)
# g / L = 6.25: w0 = 2.5 exactly, so omega0 = 5 is exactly on the separatrix

# name: (theta0, omega0, L, g, t0)
REGIME_CASES: dict[str, tuple[float, float, float, float, float]] = {
    "rest at the bottom": (0.0, 0.0, 1.0, 9.81, 0.0),
    "tiny amplitude 1e-8": (1e-8, 0.0, 1.0, 9.81, 0.0),
    "10 deg": (math.radians(10.0), 0.0, 1.0, 9.81, 0.0),
    "90 deg, started at t0 = 12.5": (math.radians(90.0), 0.0, 2.0, 9.81, 12.5),
    "170 deg": (math.radians(170.0), 0.0, 1.0, 1.0, 0.0),
    "moving, downward swing": (0.3, -1.2, 0.5, 2.0, 0.0),
    "pi - 1e-6": (math.pi - 1e-6, 0.0, 1.0, 9.81, 0.0),
    "pi - 1e-12": (math.pi - 1e-12, 0.0, 1.0, 9.81, 0.0),
    "-(pi - 1e-12)": (-(math.pi - 1e-12), 0.0, 1.0, 9.81, 0.0),
    "pi + 1e-12 (other side of the top)": (math.pi + 1e-12, 0.0, 1.0, 9.81, 0.0),
    "pi (the double), at rest": (math.pi, 0.0, 1.0, 9.81, 0.0),
    "theta0 = 20 rad": (20.0, 0.3, 1.0, 2.89, 0.0),
    "separatrix, forward": (0.0, 5.0, 1.0, 6.25, 0.0),
    "separatrix, backward": (0.0, -5.0, 1.0, 6.25, 0.0),
    "next to the separatrix, 2 fl(w0)": (0.0, 2.0 * W0_EARTH, 1.0, 9.81, 0.0),
    "libration next to the separatrix": (0.0, 2.0 * (1.0 - 1e-12), 1.0, 1.0, 0.0),
    "rotation next to the separatrix": (0.0, 2.0 * (1.0 + 1e-12), 1.0, 1.0, 0.0),
    "rotation, forward": (0.5, 2.5, 1.0, 1.0, 0.0),
    "rotation, backward": (0.5, -2.5, 1.0, 1.0, 0.0),
    "fast rotation": (-1.0, -100.0, 0.6, 1.0, 0.0),
    "rotation creeping over the top": (math.pi, 1e-10, 1.0, 1.0, 0.0),
}


@pytest.mark.parametrize("case", list(REGIME_CASES))
def test_three_periods_against_closed_form(port: ExactPort, case: str) -> None:
    """theta within 5e-14 rad and omega within 5e-14 of its amplitude over three periods."""
    theta0, omega0, length, gravity, t0 = REGIME_CASES[case]
    w0 = frequency(length, gravity)
    port.initialize(theta0, omega0, length, gravity, start_time=t0)
    period = port.period()
    horizon = 3.0 * period if math.isfinite(period) else 40.0 / w0
    times = t0 + np.linspace(0.0, horizon, 61)
    theta, omega = port.evaluate(times)
    ref_theta, ref_omega, ref_period = closed_form(theta0, omega0, exact_frequency(length, gravity),
                                                   times, t0)
    assert max_abs_diff(theta, ref_theta) <= THETA_TOL
    assert max_abs_diff(omega, ref_omega) <= OMEGA_REL_TOL * omega_scale(ref_omega, w0)
    if mp.isinf(ref_period):
        assert period == math.inf
    else:
        assert abs(period - float(ref_period)) <= 4e-16 * float(ref_period)


def test_start_value_reproduced(port: ExactPort) -> None:
    """At t0 the exact solution returns the start values bit for bit."""
    for theta0, omega0, length, gravity, t0 in REGIME_CASES.values():
        port.initialize(theta0, omega0, length, gravity, start_time=t0)
        theta, omega = port.evaluate([t0])
        assert theta[0] == theta0 and omega[0] == omega0


def test_one_million_periods_at_170_degrees(port: ExactPort) -> None:
    """After 1e6 periods at 170 deg (w0 = 1) theta and omega are still right to 1e-14."""
    theta0 = math.radians(170.0)
    port.initialize(theta0, 0.0, 1.0, 1.0)
    period = port.period()
    times = 1e6 * period + np.linspace(0.0, period, 9)
    theta, omega = port.evaluate(times)
    ref_theta, ref_omega, _ = closed_form(theta0, 0.0, 1.0, times)
    assert max_abs_diff(theta, ref_theta) <= 1e-14
    assert max_abs_diff(omega, ref_omega) <= 1e-14


def test_rotation_winds_up_continuously(port: ExactPort) -> None:
    """In rotation theta grows without wrapping: one revolution per period, in both directions."""
    for omega0 in (2.5, -2.5):
        port.initialize(0.5, omega0, 1.0, 1.0)
        period = port.period()
        theta, _ = port.evaluate(np.linspace(0.0, 10.0 * period, 2001))
        steps = np.diff(theta)
        assert np.all(np.sign(steps) == np.sign(omega0))
        assert np.max(np.abs(steps)) < 0.1
        assert abs(theta[-1] - (0.5 + math.copysign(20.0 * math.pi, omega0))) <= 1e-12


# --------------------------------------------------------------------------------------
# independent reference: Taylor integration of the ODE (mpmath.odefun)
# --------------------------------------------------------------------------------------

# name: (theta0, omega0, L, g, times); short horizons, odefun costs seconds at 50 digits
ODE_CASES: dict[str, tuple[float, float, float, float, tuple[float, ...]]] = {
    "90 deg": (math.radians(90.0), 0.0, 1.0, 1.0, (0.1, 0.3, 0.6)),
    "pi - 1e-9": (math.pi - 1e-9, 0.0, 1.0, 1.0, (0.2, 0.6)),
    "rotation": (0.5, 2.5, 1.0, 1.0, (0.2, 0.5)),
    "separatrix": (0.0, 5.0, 1.0, 6.25, (0.05, 0.15)),
}


@pytest.mark.slow
@pytest.mark.parametrize("case", list(ODE_CASES))
def test_against_ode_integration(port: ExactPort, case: str) -> None:
    """theta and omega agree with a 50-digit Taylor integration of the ODE itself."""
    theta0, omega0, length, gravity, times = ODE_CASES[case]
    w0 = frequency(length, gravity)
    port.initialize(theta0, omega0, length, gravity)
    theta, omega = port.evaluate(times)
    ref_theta, ref_omega = ode_reference(theta0, omega0, exact_frequency(length, gravity), times)
    assert max_abs_diff(theta, ref_theta) <= THETA_TOL
    assert max_abs_diff(omega, ref_omega) <= OMEGA_REL_TOL * max(abs(omega0), 2.0 * w0)


# --------------------------------------------------------------------------------------
# properties (hypothesis)
# --------------------------------------------------------------------------------------

lengths = st.floats(min_value=0.05, max_value=20.0)
gravities = st.floats(min_value=0.5, max_value=30.0)
# angles: ordinary ones, and the corners (near the top on both sides, tiny, several turns)
angles = st.one_of(
    st.floats(min_value=-12.0, max_value=12.0),
    st.sampled_from([0.0, 1e-300, 1e-12, math.pi, -math.pi, 3.0 * math.pi, -7.0 * math.pi]),
    st.floats(min_value=1e-15, max_value=1e-6).map(lambda d: math.pi - d),
    st.floats(min_value=1e-15, max_value=1e-6).map(lambda d: d - math.pi),
    st.floats(min_value=1e-15, max_value=1e-6).map(lambda d: math.pi + d),
)
# omega0 as a multiple of the separatrix speed 2 w0 cos(theta0/2) (with 0 and the border)
speed_factors = st.one_of(
    st.floats(min_value=-3.0, max_value=3.0),
    st.sampled_from([0.0, 1.0, -1.0, 1.0 - 1e-12, 1.0 + 1e-12, -1.0 + 1e-12, 1e-9, 40.0]),
)


def separatrix_speed(theta0: float, w0: float) -> float:
    """|omega| on the separatrix at theta0: 2 w0 |cos(theta0/2)| (in double)."""
    return 2.0 * w0 * abs(math.cos(theta0 / 2.0))


def initial_speed(theta0: float, factor: float, w0: float) -> float:
    """omega0 = factor * the separatrix speed, with a floor so that factor 0 means rest."""
    return factor * max(separatrix_speed(theta0, w0), 1e-3 * w0) if factor else 0.0


def start_motion(port: ExactPort, theta0: float, factor: float, length: float,
                 gravity: float) -> tuple[float, float, float]:
    """Initialize the port; return w0, omega0 and a time span (one period, or 20/w0 if none)."""
    w0 = frequency(length, gravity)
    omega0 = initial_speed(theta0, factor, w0)
    port.initialize(theta0, omega0, length, gravity)
    period = port.period()
    return w0, omega0, period if math.isfinite(period) else 20.0 / w0


PROPERTY_SETTINGS = settings(max_examples=40, deadline=None,
                             suppress_health_check=[HealthCheck.too_slow])


@PROPERTY_SETTINGS
@given(theta0=angles, factor=speed_factors, length=lengths, gravity=gravities,
       fractions=st.lists(st.floats(min_value=0.0, max_value=2.0), min_size=1, max_size=3))
def test_accuracy_property(port: ExactPort, theta0: float, factor: float, length: float,
                           gravity: float, fractions: list[float]) -> None:
    """Any state: theta within 5e-14 (plus rounding of a large theta) and omega within 5e-14."""
    w0, omega0, span = start_motion(port, theta0, factor, length, gravity)
    times = [f * span for f in fractions]
    theta, omega = port.evaluate(times)
    ref_theta, ref_omega, _ = closed_form(theta0, omega0, exact_frequency(length, gravity), times)
    theta_scale = max(1.0, float(max(abs(r) for r in ref_theta)))
    assert max_abs_diff(theta, ref_theta) <= THETA_TOL + 4e-16 * theta_scale
    assert max_abs_diff(omega, ref_omega) <= OMEGA_REL_TOL * max(omega_scale(ref_omega, w0),
                                                                  abs(omega0), 2.0 * w0)


@PROPERTY_SETTINGS
@given(theta0=angles, factor=speed_factors, length=lengths, gravity=gravities,
       fractions=st.lists(st.floats(min_value=0.0, max_value=50.0), min_size=5, max_size=5))
def test_energy_conserved(port: ExactPort, theta0: float, factor: float, length: float,
                          gravity: float, fractions: list[float]) -> None:
    """H = omega^2/2 + 2 w0^2 sin^2(theta/2) stays at its initial value to rounding."""
    w0, omega0, span = start_motion(port, theta0, factor, length, gravity)
    theta, omega = port.evaluate([f * span for f in fractions])
    energy0 = 0.5 * omega0**2 + 2.0 * w0**2 * math.sin(theta0 / 2.0) ** 2
    energy = 0.5 * omega**2 + 2.0 * w0**2 * np.sin(theta / 2.0) ** 2
    assert np.max(np.abs(energy - energy0)) <= 2e-14 * (energy0 + 2.0 * w0**2)


@PROPERTY_SETTINGS
@given(theta0=angles, factor=speed_factors, length=lengths, gravity=gravities,
       fraction=st.floats(min_value=0.0, max_value=3.0))
def test_odd_symmetry(port: ExactPort, theta0: float, factor: float, length: float,
                      gravity: float, fraction: float) -> None:
    """(theta0, omega0) -> (-theta0, -omega0) mirrors the whole motion."""
    w0, omega0, span = start_motion(port, theta0, factor, length, gravity)
    t = fraction * span
    theta, omega = port.evaluate([t])
    port.initialize(-theta0, -omega0, length, gravity)
    mirrored_theta, mirrored_omega = port.evaluate([t])
    assert abs(theta[0] + mirrored_theta[0]) <= 2.0 * THETA_TOL + 1e-15 * abs(theta[0])
    assert abs(omega[0] + mirrored_omega[0]) <= 2.0 * OMEGA_REL_TOL * max(abs(omega0), 2.0 * w0)


@PROPERTY_SETTINGS
@given(half_angle=st.floats(min_value=-1.5, max_value=1.5),
       epsilon=st.one_of(st.just(0.0), st.floats(min_value=-1e-10, max_value=1e-10)),
       length=lengths, gravity=gravities,
       fraction=st.floats(min_value=0.0, max_value=2.0))
def test_continuous_across_the_separatrix(port: ExactPort, half_angle: float, epsilon: float,
                                          length: float, gravity: float, fraction: float) -> None:
    """Just below (libration), on, and just above (rotation) the separatrix the motions agree.

    omega0 = 2 w0 cos(theta0/2) (1 + epsilon); over w0 t <= 2 the solution stays within
    ~1e-7 of the separatrix solution theta = 2 atan(sinh(w0 t + asinh(tan(theta0/2)))).
    """
    theta0 = 2.0 * half_angle
    w0 = frequency(length, gravity)
    omega0 = 2.0 * w0 * math.cos(half_angle) * (1.0 + epsilon)
    port.initialize(theta0, omega0, length, gravity)
    t = fraction / w0
    theta, omega = port.evaluate([t])
    with mp.workdps(DIGITS):
        u = mp.mpf(w0) * t + mp.asinh(mp.tan(mp.mpf(theta0) / 2))
        separatrix_theta = 2 * mp.atan(mp.sinh(u))
        separatrix_omega = 2 * mp.mpf(w0) / mp.cosh(u)
    assert abs(theta[0] - float(separatrix_theta)) <= 1e-7
    assert abs(omega[0] - float(separatrix_omega)) <= 1e-7 * w0
