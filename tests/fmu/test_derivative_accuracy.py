"""Partial and output derivatives accurate relative to their own size, in the hard corners,
on both FMUs, against mpmath at 80 digits:

- d period / d(L, g, theta, omega) in Initialization Mode, from slow libration to rotation at
  1e6 w0 and within ulps of the top, for w0 from 1e-6 to 1e6; the reference is the chain rule
  through m written out in mpmath (dT/dm dm/dx plus T's own dependence on w0), whose
  cancellation is harmless at 80 digits;
- orders 1..3 of theta_exact and omega_exact in Co-Simulation after a step, released within
  ulps of the top, on the separatrix next to the top, creeping over the top, wound up by 1e6 rad
  and in rotation at 1e3 and 1e6 w0; the reference is the equation's derivatives
  (theta'' = -a sin theta, ...) at the closed-form solution of mpmath.

Target: within 1e-12 of the value, or, where the value is 0, within 1e-15 of its scale.
``pytest tests/fmu/test_derivative_accuracy.py -s`` prints the measured worst deviations
(docs/derivatives.md).
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath as mp
import pytest

from pendulum_fmu.bench.reference import closed_form, exact_frequency
from test_derivatives import Driver

DIGITS = 80
RELATIVE = 1e-12
ZERO_SCALE = 1e-15
KNOWNS = ("L", "g", "theta", "omega")


def _w0(length: float, gravity: float) -> float:
    return math.sqrt(gravity / length)


# name -> (L, g, theta0, omega0)
PERIOD_CASES = {
    "backward rotation 1e6 w0, theta0 = -0.3, L = 1e6": (1e6, 9.81, -0.3, -1e6 * math.sqrt(9.81 / 1e6)),
    "rotation 1e6 w0, w0 = 1e6": (1e-6, 1e6, 0.7, 1e6 * 1e6),
    "rotation 1e6 w0, w0 = 1e-6": (1e6, 1e-6, -2.1, -1e6 * 1e-6),
    "rotation 1e3 w0": (1.0, 9.81, 3.0, 1e3 * _w0(1.0, 9.81)),
    "rotation 1e3 w0, theta0 wound 1e6 rad": (1.0, 9.81, 1e6 + 0.3, 1e3 * _w0(1.0, 9.81)),
    "rotation 3 w0": (1.0, 9.81, 0.4, 3 * _w0(1.0, 9.81)),
    "rotation 1e-14 rad/s over the top": (1.0, 9.81, math.pi, 1e-14),
    "libration within ulps of the top (theta0 = pi)": (1.0, 9.81, math.pi, 0.0),
    "libration one ulp above pi": (1.0, 9.81, math.nextafter(math.pi, 4.0), 0.0),
    "libration pi - 2^-40, w0 = 1e-6": (1e6, 1e-6, math.pi - 2.0**-40, 0.0),
    "libration 1e-15 below the separatrix speed": (1.0, 9.81, 0.0, 2 * _w0(1.0, 9.81) * (1 - 1e-15)),
    "libration, w0 = 1e3": (1e-3, 1e3, 1.0, 0.5),
    "small libration": (1.0, 9.81, 1e-3, 0.0),
}

# name -> (L, g, theta0, omega0, t): t generic, away from the crossings of theta through 0 or pi
OUTPUT_CASES = {
    "theta0 = pi, w0 = 1e6, t = 2.3248e-6": (1e-6, 1e6, math.pi, 0.0, 2.324778563656447e-06),
    "theta0 = pi, w0 t = 3": (1.0, 9.81, math.pi, 0.0, 3 / _w0(1.0, 9.81)),
    "theta0 = pi, w0 t = 20": (1.0, 9.81, math.pi, 0.0, 20 / _w0(1.0, 9.81)),
    "theta0 = pi, w0 t = 45": (1.0, 9.81, math.pi, 0.0, 45 / _w0(1.0, 9.81)),
    "one ulp above pi, w0 t = 10": (1.0, 9.81, math.nextafter(math.pi, 4.0), 0.0, 10 / _w0(1.0, 9.81)),
    "pi - 2^-40, w0 = 1e-6, w0 t = 15": (1e6, 1e-6, math.pi - 2.0**-40, 0.0, 15 / 1e-6),
    "separatrix (g = 4, L = 1, omega0 = 2 w0), w0 t = 18": (1.0, 4.0, 0.0, 4.0, 9.0),
    "separatrix backward, w0 t = 7": (1.0, 4.0, 0.0, -4.0, 3.5),
    "1e-14 rad/s over the top, w0 t = 12": (1.0, 9.81, math.pi, 1e-14, 12 / _w0(1.0, 9.81)),
    "rotation 1e-12 above the separatrix": (1.0, 9.81, 0.0, 2 * _w0(1.0, 9.81) * (1 + 1e-12), 5.3),
    "rotation 1e3 w0, theta0 wound 1e6 rad": (1.0, 9.81, 1e6 + 0.3, 1e3 * _w0(1.0, 9.81), 0.37),
    "rotation 1e6 w0": (1.0, 9.81, -0.3, -1e6 * _w0(1.0, 9.81), 1.3e-3),
    "rotation 1e6 w0, L = 1e6": (1e6, 9.81, -0.3, -1e6 * _w0(1e6, 9.81), 0.77),
    "libration 80 deg, w0 = 1e3": (1e-3, 1e3, math.radians(80.0), 0.0, 0.0123),
    "small libration": (1.0, 9.81, 1e-3, 0.0, 0.4),
    "at rest at the bottom": (1.0, 9.81, 0.0, 0.0, 1.0),
}


def _dK(m: mp.mpf) -> mp.mpf:
    """dK/dm = (E - (1 - m) K) / (2 m (1 - m)) (DLMF 19.4.1); pi/8 at m = 0."""
    if m == 0:
        return mp.pi / 8
    return (mp.ellipe(m) - (1 - m) * mp.ellipk(m)) / (2 * m * (1 - m))


def period_partials(length: float, gravity: float, theta: float, omega: float) -> dict[str, mp.mpf]:
    """d period / d(L, g, theta, omega) by the chain rule through m at DIGITS digits."""
    with mp.workdps(DIGITS):
        L, g, th, om = (mp.mpf(v) for v in (length, gravity, theta, omega))
        w0 = mp.sqrt(g / L)
        m = mp.sin(th / 2) ** 2 + om**2 * L / (4 * g)
        if m < 1:
            T, dT_dm = 4 * mp.ellipk(m) / w0, 4 * _dK(m) / w0
        else:
            p = 1 / m
            T = 2 * mp.ellipk(p) / (mp.sqrt(m) * w0)
            dT_dm = -2 * _dK(p) / (m**2 * mp.sqrt(m) * w0) - mp.ellipk(p) / (m * mp.sqrt(m) * w0)
        dm = {"L": om**2 / (4 * g), "g": -om**2 * L / (4 * g**2), "theta": mp.sin(th) / 2, "omega": om * L / (2 * g)}
        own = {"L": T / (2 * L), "g": -T / (2 * g), "theta": 0, "omega": 0}  # T = f(m) / w0, w0 = sqrt(g / L)
        partials = {k: dT_dm * dm[k] + own[k] for k in KNOWNS}
        partials["period"] = T
        return partials


def exact_output_derivatives(length: float, gravity: float, theta0: float, omega0: float,
                             t: float) -> dict[tuple[str, int], mp.mpf]:
    """Orders 1..3 of theta_exact and omega_exact from the equation at mpmath's closed form."""
    with mp.workdps(DIGITS):
        a = mp.mpf(gravity) / mp.mpf(length)
        thetas, omegas, _ = closed_form(theta0, omega0, exact_frequency(length, gravity), [t], digits=DIGITS)
        th, om = thetas[0], omegas[0]
        s, c = mp.sin(th), mp.cos(th)
        return {("theta_exact", 1): om, ("theta_exact", 2): -a * s, ("theta_exact", 3): -a * c * om,
                ("omega_exact", 1): -a * s, ("omega_exact", 2): -a * c * om,
                ("omega_exact", 3): a * s * (om**2 + a * c)}


def _deviation(value: float, reference: mp.mpf, scale: float) -> float:
    """|value - reference| in units of the target: relative to the reference, or to 1e-15 of
    ``scale`` where the reference is 0 (<= 1 passes)."""
    error = abs(mp.mpf(value) - reference)
    if reference == 0:
        return float(error / (ZERO_SCALE * scale))
    return float(error / (RELATIVE * abs(reference)))


@pytest.mark.parametrize("case", sorted(PERIOD_CASES))
def test_period_partials_are_accurate_relative_to_their_size(fmu_any: Path, case: str) -> None:
    length, gravity, theta, omega = PERIOD_CASES[case]
    driver = Driver(fmu_any, "ME")
    driver.set(list(KNOWNS), [length, gravity, theta, omega])
    reference = period_partials(length, gravity, theta, omega)
    period = float(reference["period"])
    scales = {"L": period / length, "g": period / gravity, "theta": period, "omega": period / _w0(length, gravity)}
    for known in KNOWNS:
        value = float(driver.directional(["period"], [known], [1.0])[0])
        deviation = _deviation(value, reference[known], scales[known])
        assert deviation <= 1.0, (case, known, value, float(reference[known]))


@pytest.mark.parametrize("case", sorted(OUTPUT_CASES))
def test_exact_output_derivatives_are_accurate_relative_to_their_size(fmu_any: Path, case: str) -> None:
    length, gravity, theta0, omega0, t = OUTPUT_CASES[case]
    driver = Driver(fmu_any, "CS")
    driver.set(list(KNOWNS), [length, gravity, theta0, omega0])
    driver.leave_initialization()
    driver.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=t)
    reference = exact_output_derivatives(length, gravity, theta0, omega0, t)
    a = gravity / length
    omega_max = 2 * math.sqrt(a) + abs(omega0)
    for (name, order), expected in reference.items():
        value = driver.output_derivatives([name], [order])[0]
        n = order + (name == "omega_exact")  # the time derivative of theta of that order
        scale = omega_max ** n  # |theta^(n)| <= (2 w0 + |omega0|)^n
        deviation = _deviation(value, expected, scale)
        assert deviation <= 1.0, (case, name, order, value, float(expected))


def test_figures_of_derivative_accuracy(fmu_path: Path, fmu3_path: Path) -> None:
    """Prints docs/derivatives.md's table (pytest -s): per case, the worst deviation of the
    period partials and of the exact outputs' derivatives, relative to their own size."""
    print("\nversion  worst |error| / |value|  case")
    for fmu in (fmu_path, fmu3_path):
        version = "3.0" if fmu == fmu3_path else "2.0"
        for case, (length, gravity, theta, omega) in PERIOD_CASES.items():
            driver = Driver(fmu, "ME")
            driver.set(list(KNOWNS), [length, gravity, theta, omega])
            reference = period_partials(length, gravity, theta, omega)
            worst = max(float(abs(mp.mpf(float(driver.directional(["period"], [k], [1.0])[0])) - reference[k])
                              / abs(reference[k])) for k in KNOWNS if reference[k] != 0)
            print(f"{version:8} {worst:23.1e}  d period / d(L, g, theta, omega): {case}")
            assert worst <= RELATIVE
        for case, (length, gravity, theta0, omega0, t) in OUTPUT_CASES.items():
            driver = Driver(fmu, "CS")
            driver.set(list(KNOWNS), [length, gravity, theta0, omega0])
            driver.leave_initialization()
            driver.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=t)
            reference = exact_output_derivatives(length, gravity, theta0, omega0, t)
            errors = [float(abs(mp.mpf(driver.output_derivatives([name], [order])[0]) - expected) / abs(expected))
                      for (name, order), expected in reference.items() if expected != 0]
            worst = max(errors, default=0.0)
            print(f"{version:8} {worst:23.1e}  orders 1-3 of theta_exact, omega_exact: {case}")
            assert worst <= RELATIVE
