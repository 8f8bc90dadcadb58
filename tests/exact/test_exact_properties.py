"""Random states against mpmath at adaptive precision: the exact port everywhere.

States: theta0 uniform in [-4 pi, 4 pi]; L and g log-uniform in 1e-6 .. 1e6; omega0 at rest,
across scales (1e-3 .. 1e2 times the separatrix speed, both signs) and within a few ulps of
the separatrix speed; start times 0, 1e3 and -50; times a fraction of a period, a few
periods, and about 1e6 periods after the start. The reference is mpmath's own elliptic
functions (``ellipfun``, ``ellipk``, ``ellipf``: theta-function and AGM code, not the FMU's
Landen scheme), through ``pendulum_fmu.bench.reference.closed_form``, at a precision chosen for the
state (digits for the phase after 1e6 periods and for m1 next to the separatrix) and
confirmed by a second evaluation 15 digits higher.

Bounds (absolute theta error relative to max(1, |theta|); omega relative to its scale):
5e-14 up to a few periods and after 1e6 periods, also within ulps of the separatrix (where
m1 is formed in triple-double: in double-double the phase after 1e6 periods was 1.9e-12
off there). ``python tests/exact/test_exact_properties.py [FMU [COUNT]]`` prints the errors state
by state and the worst cases (docs/math.md, its accuracy).
"""

from __future__ import annotations

import math
import sys
from collections.abc import Iterator
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

from pendulum_fmu.bench.reference import closed_form
from pendulum_fmu.fmu.exact_port import ExactPort

NEAR_TOL = 5e-14
"""theta and omega bound up to a few periods."""

FAR_TOL = 5e-14
"""theta bound after 1e6 periods, relative to max(1, |theta|)."""



FAR_PERIODS = 1e6
N_STATES = 24
START_TIMES = (0.0, 1e3, -50.0)


def random_states(seed: int, count: int) -> list[tuple[float, float, float, float, float]]:
    """(theta0, omega0, L, g, t0) drawn as the module docstring says (fixed seed)."""
    rng = np.random.default_rng(seed)
    states = []
    for index in range(count):
        theta0 = float(rng.uniform(-4.0 * math.pi, 4.0 * math.pi))
        length = float(10.0 ** rng.uniform(-6.0, 6.0))
        gravity = float(10.0 ** rng.uniform(-6.0, 6.0))
        with mp.workdps(40):
            separatrix = float(2 * mp.sqrt(mp.mpf(gravity) / mp.mpf(length))
                               * abs(mp.cos(mp.mpf(theta0) / 2)))
        kind = index % 4
        sign = 1.0 if rng.uniform() < 0.5 else -1.0
        if kind == 0:
            omega0 = 0.0
        elif kind in (1, 2):
            omega0 = sign * separatrix * float(10.0 ** rng.uniform(-3.0, 2.0))
        else:
            omega0 = separatrix
            for _ in range(int(rng.integers(-3, 4))):   # a few ulps either side
                omega0 = math.nextafter(omega0, math.inf if rng.uniform() < 0.5 else 0.0)
            omega0 *= sign
        states.append((theta0, omega0, length, gravity, START_TIMES[index % 3]))
    return states


def reference(theta0: float, omega0: float, length: float, gravity: float, t0: float,
              times: list[float], periods: float) -> tuple[list[mp.mpf], list[mp.mpf]]:
    """closed_form at adaptive precision, confirmed 15 digits higher."""
    digits = 40 + int(math.log10(1.0 + periods)) + 20
    answers = []
    for extra in (0, 15):
        with mp.workdps(digits + extra):
            w0 = mp.sqrt(mp.mpf(gravity) / mp.mpf(length))
            answers.append(closed_form(theta0, omega0, w0, times, t0, digits=digits + extra)[:2])
    (theta, omega), (theta_check, omega_check) = answers
    with mp.workdps(digits):
        for a, b in zip(theta + omega, theta_check + omega_check, strict=True):
            assert abs(a - b) <= mp.mpf(10) ** -25 * max(1, abs(b)), "reference not converged"
    return theta, omega


@pytest.fixture(scope="module")
def port(fmu_path: Path) -> Iterator[ExactPort]:
    """One Model Exchange instance for the module."""
    with ExactPort(fmu_path) as exact_port:
        yield exact_port


def errors(port: ExactPort, state: tuple[float, float, float, float, float],
           fractions: tuple[float, ...]) -> tuple[float, float]:
    """Worst theta error relative to max(1, |theta|) and omega error relative to its scale."""
    theta0, omega0, length, gravity, t0 = state
    port.initialize(theta0, omega0, length, gravity, start_time=t0)
    period = port.period()
    if not math.isfinite(period):
        period = 20.0 * math.sqrt(length / gravity)
    times = [t0 + f * period for f in fractions]
    theta, omega = port.evaluate(times)
    ref_theta, ref_omega = reference(theta0, omega0, length, gravity, t0, times, max(fractions))
    scale_omega = max(abs(omega0), 2.0 * math.sqrt(gravity / length))
    with mp.workdps(30):
        theta_error = max(float(abs(mp.mpf(float(v)) - r)) / max(1.0, float(abs(r)))
                          for v, r in zip(theta, ref_theta, strict=True))
        omega_error = max(float(abs(mp.mpf(float(v)) - r)) for v, r in zip(omega, ref_omega, strict=True))
    return theta_error, omega_error / scale_omega


STATES = random_states(11, N_STATES)


@pytest.mark.parametrize("state", STATES, ids=[f"state{i}" for i in range(N_STATES)])
def test_random_state_first_periods(port: ExactPort, state: tuple[float, float, float, float, float]) -> None:
    """A fraction of a period and a few periods: theta and omega within 5e-14."""
    theta_error, omega_error = errors(port, state, (0.37, 2.9))
    assert theta_error <= NEAR_TOL and omega_error <= NEAR_TOL


@pytest.mark.parametrize("state", STATES, ids=[f"state{i}" for i in range(N_STATES)])
def test_random_state_after_a_million_periods(port: ExactPort,
                                              state: tuple[float, float, float, float, float]) -> None:
    """About 1e6 periods after the start: theta within FAR_TOL of max(1, |theta|)."""
    theta_error, _ = errors(port, state, (FAR_PERIODS + 0.37,))
    assert theta_error <= FAR_TOL


def at_separatrix(state: tuple[float, float, float, float, float]) -> bool:
    """|omega0| within 1e-12 (relative) of the separatrix speed 2 w0 |cos(theta0/2)|."""
    theta0, omega0, length, gravity, _ = state
    with mp.workdps(40):
        speed = 2 * mp.sqrt(mp.mpf(gravity) / mp.mpf(length)) * abs(mp.cos(mp.mpf(theta0) / 2))
        return bool(abs(abs(mp.mpf(omega0)) / speed - 1) < mp.mpf("1e-12"))


if __name__ == "__main__":
    # python tests/exact/test_exact_properties.py [FMU [COUNT]]: the worst errors over COUNT states
    from pendulum_fmu.fmu.build import find_fmu

    fmu = Path(sys.argv[1]) if len(sys.argv) > 1 else find_fmu()
    with ExactPort(fmu) as exact_port:
        count = int(sys.argv[2]) if len(sys.argv) > 2 else N_STATES
        worst_near = worst_far = worst_separatrix = 0.0
        for number, sample in enumerate(random_states(11, count)):
            near = max(errors(exact_port, sample, (0.37, 2.9)))
            far = errors(exact_port, sample, (FAR_PERIODS + 0.37,))[0]
            worst_near = max(worst_near, near)
            if at_separatrix(sample):
                worst_separatrix = max(worst_separatrix, far)
            else:
                worst_far = max(worst_far, far)
            print(f"state {number:3d} {sample}: first periods {near:.2e}, after 1e6 periods {far:.2e}")
        print(f"worst over {count} states: {worst_near:.2e} (first periods), after 1e6 periods "
              f"{worst_far:.2e} (more than 1e-12 from the separatrix speed), {worst_separatrix:.2e} "
              "(within it); theta relative to max(1, |theta|), omega to its scale")
