"""The shortcuts of the exact port's set-up and batch evaluation, at their switch-overs, against
mpmath at 50 digits (pendulum_fmu.bench.reference.closed_form, independent of the C code).

- Release from rest takes its own path (x0 = +-1 quarter period exactly, m1 = cos^2(th/2)): it
  must agree with the general path, taken by the smallest moving starts (omega0 = +-5e-324,
  +-1e-300), and both with mpmath.
- The double-double sin/cos of the half angle sums a number of leading terms in double-double
  that depends on |th/2| (elliptic.c, J), and reduces by pi/2 past |th/2| = pi/4: states on
  both sides of every switch-over.
- ``exact()`` over many times goes through the lock-step batch: bit for bit the point-by-point
  evaluation.
Tolerances: 5e-14 rad for theta (plus the rounding of a wound-up theta), 5e-14 of the amplitude
2 k w0 for omega (the port's bound), over three periods and after 1e5 periods.
"""

from __future__ import annotations

import math

import mpmath as mp
import numpy as np
import pytest

from pendulum_fmu import exact
from pendulum_fmu.bench.reference import closed_form, max_abs_diff, omega_scale

TOL = 5e-14


def half_angle_switch_overs() -> list[float]:
    """|th/2| where the number of double-double terms J of dd_sincos changes (dd.c, sincos_reduced).

    J is the least j with y^(2j) / (2j + 1)! <= 1e-16 and y^(2j) / (2j)! <= 1e-16; it steps
    where y^(2j) = 1e-16 (2j)!, for the j it takes within |y| <= pi/4.
    """
    points = [(1e-16 * math.factorial(2 * j)) ** (1.0 / (2 * j)) for j in range(1, 14)]
    return [y for y in points if y <= math.pi / 4]


def release_angles() -> list[float]:
    """theta0 (rad) on both sides of every switch-over of the half angle, and of the pi/2 turn."""
    rng = np.random.default_rng(20261123)
    angles = []
    for y in [*half_angle_switch_overs(), math.pi / 4]:
        for side in (-1.0, 1.0):
            angles.append(2.0 * y * (1.0 + side * 1e-9 * rng.uniform(0.5, 1.0)))
    # and, reduced by a turn, near the top (th/2 past pi/2 - small)
    angles += [math.pi - 1e-3, -(math.pi - 2e-7), 2.0 * math.pi + 0.7, -4.0 * math.pi - 1.3]
    return angles


def check_against_mpmath(theta0: float, omega0: float, periods: float) -> None:
    """theta and omega of exact() (L = g = 1) within TOL of mpmath over three periods from
    `periods` periods on."""
    _, _, ref_period = closed_form(theta0, omega0, 1.0, [0.0], digits=30)
    period = float(ref_period) if mp.isfinite(ref_period) else 40.0
    times = periods * period + np.linspace(0.0, 3.0 * period, 25)
    theta, omega = exact(theta0, omega0, 1.0, 1.0, times)
    ref_theta, ref_omega, _ = closed_form(theta0, omega0, 1.0, times)
    rounding = 2.0**-52 * float(np.max(np.abs(theta)))     # of a wound-up theta (rotation)
    assert max_abs_diff(theta, ref_theta) <= TOL + rounding, (theta0, omega0, periods)
    assert max_abs_diff(omega, ref_omega) <= TOL * omega_scale(ref_omega, 1.0), (theta0, omega0, periods)


@pytest.mark.parametrize("theta0", release_angles())
def test_half_angle_switch_overs_against_mpmath(theta0: float) -> None:
    """From rest and moving, on both sides of every switch-over of the sin/cos set-up."""
    check_against_mpmath(theta0, 0.0, 0.0)
    check_against_mpmath(theta0, 0.05, 1e5)


@pytest.mark.parametrize("amplitude_deg", [1e-7, 3.0, 60.0, 120.0, 175.0, 179.99])
def test_from_rest_path_agrees_with_the_general_one(amplitude_deg: float) -> None:
    """Released from rest (x0 = +-1 exactly) against the smallest moving starts and mpmath."""
    for sign in (1.0, -1.0):
        theta0 = sign * math.radians(amplitude_deg)
        for omega0 in (0.0, 5e-324, -5e-324, 1e-300):
            check_against_mpmath(theta0, omega0, 0.0)
            check_against_mpmath(theta0, omega0, 1e5)
        times = np.linspace(0.0, 50.0, 101)
        rest_theta, rest_omega = exact(theta0, 0.0, 1.0, 1.0, times)
        moving_theta, moving_omega = exact(theta0, 5e-324, 1.0, 1.0, times)
        assert np.max(np.abs(rest_theta - moving_theta)) <= 2 * TOL
        assert np.max(np.abs(rest_omega - moving_omega)) <= 2 * TOL


@pytest.mark.parametrize("state", [(1.2, 0.0), (3.0, 0.0), (math.pi, 0.0), (0.4, 1.3), (0.5, 2.5), (0.0, 2.0)])
def test_batch_is_bit_for_bit_the_point_by_point_evaluation(state: tuple[float, float]) -> None:
    """exact() over an array of times (lock-step batch) equals exact() one time at a time."""
    theta0, omega0 = state
    times = np.concatenate([np.random.default_rng(7).uniform(-200.0, 200.0, 97), [0.0, np.nan, np.inf, 1e300]])
    theta, omega = exact(theta0, omega0, 2.0, 9.81, times)
    for i, t in enumerate(times):
        one_theta, one_omega = exact(theta0, omega0, 2.0, 9.81, np.array([t]))
        assert np.array_equal(one_theta, theta[i:i + 1], equal_nan=True)
        assert np.array_equal(one_omega, omega[i:i + 1], equal_nan=True)
