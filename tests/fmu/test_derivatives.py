"""Partial derivatives (fmi2GetDirectionalDerivative, fmi3GetDirectionalDerivative,
fmi3GetAdjointDerivative) and output derivatives (fmi2GetRealOutputDerivatives,
fmi3GetOutputDerivatives) of both FMUs, against independent references:

- every (unknown, known) pair ModelStructure declares, at random states in every regime,
  against the analytic Jacobian (written here from the equation; the period's row by mpmath's
  differentiation of its closed form at 50 digits) and against central differences of the
  FMU's own outputs;
- the whole Jacobian times a random seed; the adjoint is the transpose;
- output derivatives of orders 1..3 against mpmath's derivatives of the exact solution.
"""

from __future__ import annotations

import math
import random
from ctypes import c_double
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Model, FMU2Slave
from fmpy.fmi3 import FMU3Model, FMU3Slave

from pendulum_fmu.bench.reference import closed_form

VR = {"L": 1, "g": 2, "theta": 3, "der(theta)": 4, "omega": 5, "der(omega)": 6, "theta_exact": 7,
      "omega_exact": 8, "period": 9, "x": 10, "y": 11}
NAME = {vr: name for name, vr in VR.items()}
# regime -> range of the elliptic parameter m = sin^2(theta/2) + (omega / (2 w0))^2
REGIMES = {"libration": (0.01, 0.9), "libration_near_top": (0.999, 0.99999), "rotation": (1.2, 4.0),
           "fast_rotation": (50.0, 200.0)}
STATES_PER_REGIME = 3


class Driver:
    """One instance of either FMU, the calls the tests need in the version's own words."""

    def __init__(self, fmu: Path, interface: str) -> None:
        md = read_model_description(str(fmu))
        self.fmi3 = md.fmiVersion == "3.0"
        classes = {(False, "ME"): FMU2Model, (False, "CS"): FMU2Slave, (True, "ME"): FMU3Model,
                   (True, "CS"): FMU3Slave}
        token = md.instantiationToken if self.fmi3 else md.guid
        self.interface = interface
        self.fmu = classes[(self.fmi3, interface)](guid=token, unzipDirectory=extract(str(fmu)),
                                                   modelIdentifier="Pendulum", instanceName="jacobian")
        self.fmu.instantiate()
        if self.fmi3:
            self.fmu.enterInitializationMode(startTime=0.0)
        else:
            self.fmu.setupExperiment(startTime=0.0)
            self.fmu.enterInitializationMode()

    def set(self, names: list[str], values: list[float]) -> None:
        (self.fmu.setFloat64 if self.fmi3 else self.fmu.setReal)([VR[n] for n in names], values)

    def get(self, names: list[str]) -> list[float]:
        return (self.fmu.getFloat64 if self.fmi3 else self.fmu.getReal)([VR[n] for n in names])

    def directional(self, unknowns: list[str], knowns: list[str], seed: list[float]) -> np.ndarray:
        u, k = [VR[n] for n in unknowns], [VR[n] for n in knowns]
        return np.array(self.fmu.getDirectionalDerivative(u, k, seed))

    def adjoint(self, unknowns: list[str], knowns: list[str], seed: list[float]) -> np.ndarray:
        u, k = [VR[n] for n in unknowns], [VR[n] for n in knowns]
        return np.array(self.fmu.getAdjointDerivative(u, k, seed, nSensitivity=len(k)))

    def leave_initialization(self) -> None:
        self.fmu.exitInitializationMode()
        if self.interface == "ME":
            self.fmu.enterContinuousTimeMode()

    def set_states(self, theta: float, omega: float) -> None:
        self.fmu.setContinuousStates((c_double * 2)(theta, omega), 2)

    def output_derivatives(self, names: list[str], orders: list[int]) -> list[float]:
        vrs = [VR[n] for n in names]
        if self.fmi3:
            return self.fmu.getOutputDerivatives(vrs, orders)
        return self.fmu.getRealOutputDerivatives(vrs, orders)


def _random_state(regime: str, rng: random.Random) -> dict[str, float]:
    length, gravity = rng.uniform(0.5, 2.0), rng.uniform(1.0, 20.0)
    w0 = math.sqrt(gravity / length)
    m = rng.uniform(*REGIMES[regime])
    half = math.asin(math.sqrt(min(m, 1.0)) * rng.uniform(0.0, 0.99)) if m < 1 else rng.uniform(-math.pi, math.pi) / 2
    theta = 2 * half * rng.choice((-1, 1))
    omega = 2 * w0 * math.sqrt(m - math.sin(theta / 2) ** 2) * rng.choice((-1, 1))
    return {"L": length, "g": gravity, "theta": theta, "omega": omega}


def _states() -> list[tuple[str, int]]:
    return [(regime, i) for regime in REGIMES for i in range(STATES_PER_REGIME)]


def _period(L: mp.mpf, g: mp.mpf, theta: mp.mpf, omega: mp.mpf) -> mp.mpf:
    return closed_form(theta, omega, mp.sqrt(g / L), [0.0], digits=mp.mp.dps)[2]  # mp.diff raises the precision


def _analytic(unknown: str, known: str, s: dict[str, float], initial: bool) -> float:
    """d unknown / d known from the equation, by hand (the FMU's C code is not consulted)."""
    L, g, th = s["L"], s["g"], s["theta"]
    table = {
        ("theta", "theta"): 1.0, ("omega", "omega"): 1.0, ("der(theta)", "omega"): 1.0,
        ("der(omega)", "theta"): -g / L * math.cos(th), ("der(omega)", "L"): g * math.sin(th) / L**2,
        ("der(omega)", "g"): -math.sin(th) / L, ("x", "theta"): L * math.cos(th), ("x", "L"): math.sin(th),
        ("y", "theta"): L * math.sin(th), ("y", "L"): -math.cos(th),
    }
    if initial:  # at the start time the exact solution is the start state
        table.update({("theta_exact", "theta"): 1.0, ("omega_exact", "omega"): 1.0})
        if unknown == "period":
            with mp.workdps(50):
                args = [mp.mpf(s[n]) for n in ("L", "g", "theta", "omega")]
                index = ("L", "g", "theta", "omega").index(known)
                order = [1 if i == index else 0 for i in range(4)]
                return float(mp.diff(_period, args, order))
    return table.get((unknown, known), 0.0)


def _declared(md_fmu: Path, initial: bool) -> list[tuple[str, str]]:
    md = read_model_description(str(md_fmu))
    unknowns = md.initialUnknowns if initial else md.outputs + md.derivatives
    return [(u.variable.name, d.name) for u in unknowns for d in (u.dependencies or [])]


def _shifted_value(driver: Driver, unknown: str, known: str, s: dict[str, float], initial: bool,
                   shift: float) -> float:
    shifted = dict(s, **{known: s[known] + shift})
    if initial:
        driver.set(["L", "g", "theta", "omega"], [shifted[n] for n in ("L", "g", "theta", "omega")])
    else:
        driver.set_states(shifted["theta"], shifted["omega"])
    return driver.get([unknown])[0]


def _central_difference(driver: Driver, unknown: str, known: str, s: dict[str, float], initial: bool) -> float:
    """Richardson-extrapolated central difference (error O(h^4)); the step shrinks with the
    distance |1 - m| from the separatrix, on which the period's derivatives vary."""
    w0sq = s["g"] / s["L"]
    m = math.sin(s["theta"] / 2) ** 2 + s["omega"] ** 2 / (4 * w0sq)
    h = 1e-4 * min(1.0, abs(1.0 - m)) * max(1.0, abs(s[known]))
    estimates = []
    for step in (h, h / 2):
        plus = _shifted_value(driver, unknown, known, s, initial, step)
        minus = _shifted_value(driver, unknown, known, s, initial, -step)
        estimates.append((plus - minus) / (2 * step))
    _shifted_value(driver, unknown, known, s, initial, 0.0)
    return (4 * estimates[1] - estimates[0]) / 3


@pytest.mark.parametrize(("regime", "index"), _states())
@pytest.mark.parametrize("phase", ["initialization", "continuous_time"])
def test_every_declared_partial_matches_analytic_and_central_differences(
        fmu_any: Path, regime: str, index: int, phase: str) -> None:
    rng = random.Random(f"{regime}-{index}")
    s = _random_state(regime, rng)
    initial = phase == "initialization"
    driver = Driver(fmu_any, "ME")
    driver.set(["L", "g", "theta", "omega"], [s[n] for n in ("L", "g", "theta", "omega")])
    if not initial:
        driver.leave_initialization()
    pairs = _declared(fmu_any, initial)
    assert len(pairs) >= (17 if initial else 6)
    for unknown, known in pairs:
        fmu_value = driver.directional([unknown], [known], [1.0])[0]
        exact = _analytic(unknown, known, s, initial)
        assert fmu_value == pytest.approx(exact, rel=1e-12 if unknown == "period" else 1e-14, abs=1e-15), \
            (unknown, known)
        difference = _central_difference(driver, unknown, known, s, initial)
        scale = max(abs(exact), abs(driver.get([unknown])[0]), 1.0)
        assert abs(fmu_value - difference) <= 1e-6 * scale, (unknown, known, fmu_value, difference)


@pytest.mark.parametrize("regime", sorted(REGIMES))
def test_jacobian_times_seed_and_adjoint_is_its_transpose(fmu3_path: Path, regime: str) -> None:
    rng = random.Random(regime)
    s = _random_state(regime, rng)
    driver = Driver(fmu3_path, "ME")
    driver.set(["L", "g", "theta", "omega"], [s[n] for n in ("L", "g", "theta", "omega")])
    unknowns = ["der(theta)", "der(omega)", "theta_exact", "omega_exact", "period", "x", "y"]
    knowns = ["L", "g", "theta", "omega"]
    jacobian = np.array([[_analytic(u, k, s, True) for k in knowns] for u in unknowns])
    seed = [rng.uniform(-1, 1) for _ in knowns]
    assert np.allclose(driver.directional(unknowns, knowns, seed), jacobian @ seed, rtol=1e-9, atol=1e-14)
    rows = np.array([driver.adjoint(unknowns, knowns, [1.0 if j == i else 0.0 for j in range(len(unknowns))])
                     for i in range(len(unknowns))])
    columns = np.array([driver.directional(unknowns, knowns, [1.0 if j == i else 0.0 for j in range(len(knowns))])
                        for i in range(len(knowns))]).T
    assert np.array_equal(rows, columns)
    weights = [rng.uniform(-1, 1) for _ in unknowns]
    assert np.allclose(driver.adjoint(unknowns, knowns, weights), np.array(weights) @ jacobian, rtol=1e-9, atol=1e-14)


@pytest.mark.parametrize("regime", sorted(REGIMES))
def test_output_derivatives_are_the_exact_solutions(fmu_any: Path, regime: str) -> None:
    rng = random.Random(f"out-{regime}")
    s = _random_state(regime, rng)
    driver = Driver(fmu_any, "CS")
    driver.set(["L", "g", "theta", "omega"], [s[n] for n in ("L", "g", "theta", "omega")])
    driver.leave_initialization()
    t = 0.0
    for _ in range(7):
        driver.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=0.137)
        t += 0.137
    names = ["theta", "omega", "theta_exact", "omega_exact", "x", "y"]
    with mp.workdps(50):
        w0 = mp.sqrt(mp.mpf(s["g"]) / mp.mpf(s["L"]))

        def exact(name: str, time: mp.mpf) -> mp.mpf:
            theta, omega, _ = closed_form(s["theta"], s["omega"], w0, [time], digits=mp.mp.dps)
            value = {"theta": theta[0], "omega": omega[0]}
            value["x"], value["y"] = s["L"] * mp.sin(theta[0]), -s["L"] * mp.cos(theta[0])
            return value[name.removesuffix("_exact")]

        for order in (1, 2, 3):
            got = driver.output_derivatives(names, [order] * len(names))
            for name, value in zip(names, got, strict=True):
                reference = float(mp.diff(lambda time, n=name: exact(n, time), mp.mpf(t), order))
                scale = float(s["g"] / s["L"]) ** (order / 2) * max(1.0, abs(s["omega"])) ** 3
                # theta_exact & co. are exact to rounding; theta, omega carry the solver's 1e-8
                tolerance = 1e-12 if name.endswith("_exact") else 1e-6
                assert abs(value - reference) <= tolerance * scale, (name, order, value, reference)


def test_figures_of_the_jacobian_check(fmu_path: Path, fmu3_path: Path) -> None:
    """Prints docs/fmi.md's table (pytest -s): the largest relative deviation of the FMU's
    partials from the analytic ones and from central differences, per regime, both versions."""
    print("\nversion  regime               pairs  max rel. dev. analytic  max rel. dev. central diff.")
    for fmu in (fmu_path, fmu3_path):
        for regime in REGIMES:
            pairs = 0
            worst_analytic = worst_difference = 0.0
            for index in range(STATES_PER_REGIME):
                s = _random_state(regime, random.Random(f"{regime}-{index}"))
                for initial in (True, False):
                    driver = Driver(fmu, "ME")
                    driver.set(["L", "g", "theta", "omega"], [s[n] for n in ("L", "g", "theta", "omega")])
                    if not initial:
                        driver.leave_initialization()
                    for unknown, known in _declared(fmu, initial):
                        value = driver.directional([unknown], [known], [1.0])[0]
                        exact = _analytic(unknown, known, s, initial)
                        difference = _central_difference(driver, unknown, known, s, initial)
                        scale = max(abs(exact), 1e-300)
                        worst_analytic = max(worst_analytic, abs(value - exact) / scale)
                        worst_difference = max(worst_difference, abs(value - difference) / max(scale, 1.0))
                        pairs += 1
            version = "3.0" if fmu == fmu3_path else "2.0"
            print(f"{version:8} {regime:20} {pairs:5}  {worst_analytic:22.1e}  {worst_difference:27.1e}")
            assert worst_analytic <= 1e-12 and worst_difference <= 1e-7
