"""The step certificate at its edges, against an independent mpmath reference.

Every Co-Simulation ``fmi2DoStep`` that returns OK certifies that the TRUE error is within the
bound (``docs/certificate.md``)::

    |theta - theta(t)| <= 100 tol max(1, |theta(t)|),  |omega - omega(t)| <= 100 tol max(w0, |omega(t)|)

Here ``theta(t)``, ``omega(t)`` come from mpmath's Jacobi elliptic functions at 40 digits
(:func:`true_state`, written for this test from the pendulum's closed form, not from the FMU's
exact port), at the step's end time as the FMU holds it (a double), measured from the start
time exactly. The runs: random states (libration, rotation, near the separatrix), L and g in
1e-3 .. 1e3, tolerances 1e-4 .. 1e-12, start times 0 and +-1 .. 2^41, every solver. The cases once
found wrong are tests of their own: the start times that were refused, the rk4 case whose OK was
1 + 9.7e-6 of the true bound, and the tolerances below the floor, which run at the floor with a
warning naming both.
"""

from __future__ import annotations

import math
import random
import shutil
import tempfile
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import mpmath as mp
import pytest
from fmpy import read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave

from mpmath_pendulum import DIGITS, true_state
from pendulum_fmu.fmu.log import FmuLog, register, shared_callbacks

SOLVERS = ("dopri5", "rk4", "rkn", "symplectic")
"""The ``solver`` enumeration's items, value 1 .. 4 (modelDescription.xml)."""

FLOOR = 1e-14
"""The smallest Co-Simulation tolerance (INTEGRATOR_TOLERANCE_FLOOR, fmu_src/solvers/integrator.h)."""


def true_departure(theta: float, omega: float, start: Start, tol: float, t_end: float) -> float:
    """The step's true error in units of its bound 100 tol (theta and omega, the larger)."""
    with mp.workdps(DIGITS):
        th, om = true_state(start.theta0, start.omega0, start.g, start.length, mp.mpf(t_end) - mp.mpf(start.t0))
        w0 = mp.sqrt(mp.mpf(start.g) / mp.mpf(start.length))
        a = abs(mp.mpf(theta) - th) / (100 * mp.mpf(tol) * max(1, abs(th)))
        b = abs(mp.mpf(omega) - om) / (100 * mp.mpf(tol) * max(w0, abs(om)))
        return float(max(a, b))


@dataclass(frozen=True)
class Start:
    """A Co-Simulation experiment's start: state, parameters, start time."""

    theta0: float
    omega0: float
    length: float
    g: float
    t0: float = 0.0


class Fmi2:
    """The FMI 2.0 FMU, unpacked once, instantiated afresh for each run with a log of its own."""

    def __init__(self, fmu: Path, folder: Path) -> None:
        self.md = read_model_description(str(fmu))
        shutil.unpack_archive(str(fmu), str(folder), "zip")
        self.folder = folder
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.count = 0

    def start(self, start: Start, solver: str, tol: float) -> tuple[Any, FmuLog]:
        """An initialized slave (an FMICallException if the FMU refuses) and its log."""
        self.count += 1
        log = FmuLog()
        slave = FMU2Slave(guid=self.md.guid, unzipDirectory=str(self.folder),
                          modelIdentifier=self.md.coSimulation.modelIdentifier,
                          instanceName=f"edges{self.count}")
        register(slave.instanceName, log)
        slave.instantiate(callbacks=shared_callbacks())
        try:
            slave.setupExperiment(tolerance=tol, startTime=start.t0)
            slave.enterInitializationMode()
            slave.setReal([self.vr[n] for n in ("L", "g", "theta", "omega")],
                          [start.length, start.g, start.theta0, start.omega0])
            slave.setInteger([self.vr["solver"]], [SOLVERS.index(solver) + 1])
            slave.exitInitializationMode()
        except FMICallException:
            slave.freeInstance()
            raise
        return slave, log

    def state(self, slave: Any) -> tuple[float, float]:
        """theta and omega of the slave."""
        theta, omega = slave.getReal([self.vr["theta"], self.vr["omega"]])
        return float(theta), float(omega)


@pytest.fixture(scope="module")
def fmi2(fmu_path: Path) -> Iterator[Fmi2]:
    with tempfile.TemporaryDirectory(prefix="certificate-edges-") as folder:
        yield Fmi2(fmu_path, Path(folder))


@dataclass
class Checked:
    """What the steps of some runs returned, against the true error."""

    ok: int = 0
    warned: int = 0
    ok_beyond: int = 0
    worst_ok: float = 0.0
    failures: list[str] | None = None

    def record(self, status: int, departure: float, what: str) -> None:
        if status == 0:
            self.ok += 1
            self.worst_ok = max(self.worst_ok, departure)
            if not departure <= 1.0:
                self.ok_beyond += 1
                self.failures = (self.failures or []) + [f"{what}: OK at {departure:.6g} of the true bound"]
        else:
            self.warned += 1


def run_steps(fmi2: Fmi2, start: Start, solver: str, tol: float, ends: list[float], checked: Checked) -> None:
    """DoSteps to each end time in turn, every status checked against the true error."""
    slave, _ = fmi2.start(start, solver, tol)
    try:
        now = start.t0
        for end in ends:
            # fmpy's doStep drops the status; its wrapped fmi2DoStep returns it (and raises
            # above fmi2Warning)
            status = int(slave.fmi2DoStep(slave.component, now, end - now, 1))
            now = now + (end - now)   # the FMU's time: point + step, as it rounds it
            theta, omega = fmi2.state(slave)
            checked.record(status, true_departure(theta, omega, start, tol, now),
                           f"{solver} tol {tol:g} {start} t {now!r}")
    finally:
        slave.terminate()
        slave.freeInstance()


def test_reference_solves_the_pendulum() -> None:
    """The reference starts at the start values, keeps the energy and obeys the ODE (so that it
    can fail: a wrong sign or branch breaks one of these)."""
    for theta0, omega0 in ((1.2, 0.4), (-2.9, -0.1), (7.0, 1.0), (0.3, 9.0), (-1.0, -12.0), (3.0, 0.0)):
        th, om = true_state(theta0, omega0, 9.81, 0.7, mp.mpf(0))
        assert abs(th - theta0) < 1e-30 and abs(om - omega0) < 1e-30
        with mp.workdps(DIGITS):
            w0sq = mp.mpf(9.81) / mp.mpf(0.7)
            energy0 = mp.mpf(omega0) ** 2 / 2 - w0sq * mp.cos(mp.mpf(theta0))
            for t in (mp.mpf("0.31"), mp.mpf("2.7"), mp.mpf("11.3")):
                th, om = true_state(theta0, omega0, 9.81, 0.7, t)
                assert abs(om ** 2 / 2 - w0sq * mp.cos(th) - energy0) < 1e-30
                dt = mp.mpf("1e-12")
                th_plus, om_plus = true_state(theta0, omega0, 9.81, 0.7, t + dt)
                th_minus, om_minus = true_state(theta0, omega0, 9.81, 0.7, t - dt)
                assert abs((th_plus - th_minus) / (2 * dt) - om) < 1e-18
                assert abs((om_plus - om_minus) / (2 * dt) + w0sq * mp.sin(th)) < 1e-18


def test_far_start_times_are_ok_and_within_the_true_bound(fmi2: Fmi2) -> None:
    """The steps the minimum step of absolute time refused ("step size underflow"): OK now, for
    every solver, within the true bound."""
    deg75 = math.radians(75.0)
    checked = Checked()
    for solver in SOLVERS:
        run_steps(fmi2, Start(deg75, 0.0, 1e-6, 1e6, 1e7), solver, 1e-8, [1e7 + 6.283185307179586e-07], checked)
        run_steps(fmi2, Start(deg75, 0.0, 1.0, 9.81, 2.0 ** 41), solver, 1e-8, [2.0 ** 41 + 0.224], checked)
    assert checked.ok == 8 and checked.ok_beyond == 0, checked.failures


def test_rk4_first_crossing_is_not_ok_beyond_the_true_bound(fmi2: Fmi2) -> None:
    """rk4 at tol 1e-12 from theta0 = 0, omega0 = 6.264183967988169 (L = 1, g = 9.81), the
    case whose first crossing was once OK at 1 + 9.7e-6 of the true bound: every OK on a grid
    of 0.05 s up to the first warning, and at each end time of a bisection of that crossing (one
    DoStep from 0 each: the steps do not depend on the grid), is within the true bound."""
    start = Start(0.0, 6.264183967988169, 1.0, 9.81)
    checked = Checked()
    run_steps(fmi2, start, "rk4", 1e-12, [0.05 * (i + 1) for i in range(130)], checked)
    assert checked.ok_beyond == 0 and checked.warned > 0, checked
    low, high = 6.05, 6.1   # the last OK and the first warning of that grid
    for _ in range(45):
        middle = 0.5 * (low + high)
        probe = Checked()
        run_steps(fmi2, start, "rk4", 1e-12, [middle], probe)
        checked.ok_beyond += probe.ok_beyond
        checked.failures = (checked.failures or []) + (probe.failures or []) or None
        checked.worst_ok = max(checked.worst_ok, probe.worst_ok)
        low, high = (middle, high) if probe.ok else (low, middle)
    assert checked.ok_beyond == 0, checked.failures
    assert 0.99 < checked.worst_ok <= 1.0, checked.worst_ok   # the bisection came up to the bound


@pytest.mark.parametrize("solver", SOLVERS)
@pytest.mark.parametrize("tol", [5e-324, 1e-20, 1e-16, 1e-15])
def test_below_the_floor_runs_at_the_floor_with_a_warning(fmi2: Fmi2, tol: float, solver: str) -> None:
    """Below the floor (1e-14) the run takes the floor: fmi2SetupExperiment returns a warning
    that names the tolerance asked for and the one used, and every OK step is within the true
    bound at the floor (mpmath). (Importers pass 1e-16 for "as accurate as possible"; a refusal
    lost their run.)"""
    start = Start(1.3089969389957472, 0.0, 1.0, 9.81)
    slave, log = fmi2.start(start, solver, tol)
    warnings = [message for status, _, message in log.entries if status == 1]
    assert not [entry for entry in log.entries if entry[0] >= 3], log.entries
    assert len(warnings) == 1, log.entries
    assert f"tolerance {tol:g} is below {FLOOR:g}" in warnings[0], warnings[0]
    assert f"the run uses tolerance {FLOOR:g}" in warnings[0], warnings[0]
    checked = Checked()
    try:
        now = 0.0
        for end in (0.05, 0.4, 1.1, 2.3):
            status = int(slave.fmi2DoStep(slave.component, now, end - now, 1))
            now = now + (end - now)
            theta, omega = fmi2.state(slave)
            checked.record(status, true_departure(theta, omega, start, FLOOR, now), f"{solver} asked {tol:g} t {now!r}")
    finally:
        slave.terminate()
        slave.freeInstance()
    assert checked.ok_beyond == 0, checked.failures
    assert checked.ok + checked.warned == 4


def test_fmi3_runs_below_the_floor_at_the_floor(fmu3_path: Path) -> None:
    """FMI 3.0 takes the tolerance at fmi3EnterInitializationMode: a warning there naming both
    tolerances, then the run."""
    md = read_model_description(str(fmu3_path))
    with tempfile.TemporaryDirectory(prefix="certificate-edges3-") as folder:
        shutil.unpack_archive(str(fmu3_path), folder, "zip")
        log = FmuLog()
        slave = FMU3Slave(guid=md.instantiationToken, unzipDirectory=folder,
                          modelIdentifier=md.coSimulation.modelIdentifier, instanceName="floor3")
        slave.instantiate(logMessage=log.fmi3_callback)
        slave.enterInitializationMode(tolerance=1e-16, startTime=0.0)
        slave.exitInitializationMode()
        slave.doStep(currentCommunicationPoint=0.0, communicationStepSize=0.5)
        theta_vr = next(v.valueReference for v in md.modelVariables if v.name == "theta")
        theta = float(slave.getFloat64([theta_vr])[0])
        slave.terminate()
        slave.freeInstance()
    messages = [message for _, _, message in log.entries]
    assert any(f"tolerance 1e-16 is below {FLOOR:g}" in m and f"the run uses tolerance {FLOOR:g}" in m
               for m in messages), log.entries
    true_theta = float(true_state(1.3089969389957472, 0.0, 9.81, 1.0, mp.mpf("0.5"))[0])
    assert abs(theta - true_theta) <= 100 * FLOOR * max(1.0, abs(theta))


def random_start(rng: random.Random, t0: float) -> Start:
    """A random state: libration, rotation or within 1e-4 .. 1e-8 of the separatrix."""
    length, g = 10.0 ** rng.uniform(-3, 3), 10.0 ** rng.uniform(-3, 3)
    w0 = math.sqrt(g / length)
    kind = rng.choice(("libration", "rotation", "separatrix"))
    if kind == "libration":
        return Start(rng.uniform(-3.1, 3.1), rng.uniform(-0.5, 0.5) * w0, length, g, t0)
    if kind == "rotation":
        return Start(rng.uniform(-math.pi, math.pi), rng.choice((-1, 1)) * rng.uniform(2.2, 8.0) * w0, length, g, t0)
    closeness = 10.0 ** rng.uniform(-8, -4) * rng.choice((-1, 1))
    return Start(0.0, rng.choice((-1, 1)) * 2.0 * w0 * (1.0 + closeness), length, g, t0)


RANDOM_RUNS = 400
"""Runs of the random test (six DoSteps each; about 10 s)."""


def test_random_oks_are_within_the_true_bound(fmi2: Fmi2) -> None:
    """Random states, tolerances 1e-4 .. 1e-12, start times 0 and +-1 .. 2^41, every solver: no OK beyond
    the true bound, and most steps OK (the test has something to check)."""
    rng = random.Random(26)
    checked = Checked()
    for i in range(RANDOM_RUNS):
        t0 = 0.0 if i % 4 == 0 else float(rng.choice((1, -1)) * 2.0 ** rng.uniform(0, 41))
        start = random_start(rng, t0)
        tol = 10.0 ** rng.uniform(-12, -4)
        w0 = math.sqrt(start.g / start.length)
        h = rng.uniform(0.2, 3.0) / w0
        ends = [t0 + (j + 1) * h for j in range(6)]
        run_steps(fmi2, start, SOLVERS[i % 4], tol, ends, checked)
    assert checked.ok_beyond == 0, checked.failures
    assert checked.ok >= 0.8 * (checked.ok + checked.warned), checked


def measure(fmu: Path, runs: int) -> None:
    """Print, per solver and tolerance, what ``runs`` random runs of 10 DoSteps (the random test's
    states, start times 0 .. 2^41) returned against the true error: steps, OK, within the true
    bound, OK beyond it, and the worst true error in units of 100 tol (docs/certificate.md); a
    tolerance below the FMU's floor runs at the floor and is measured against the floor's bound
    (the row says ``at 1e-14``)."""
    tolerances = (1e-8, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14, 1e-15, 1e-16)
    with tempfile.TemporaryDirectory(prefix="certificate-edges-") as folder:
        fmi2 = Fmi2(fmu, Path(folder))
        print(f"{'solver':<11} {'tol':<6} {'steps':>6} {'OK':>6} {'within':>6} {'OK beyond':>9} {'worst':>9}")
        for solver in SOLVERS:
            for tol in tolerances:
                rng = random.Random(7)
                checked, steps, within, worst = Checked(), 0, 0, 0.0
                try:
                    for i in range(runs):
                        start = random_start(rng, 0.0 if i % 2 == 0 else 2.0 ** rng.uniform(0, 41))
                        h = rng.uniform(0.2, 3.0) / math.sqrt(start.g / start.length)
                        slave, _ = fmi2.start(start, solver, tol)
                        now = start.t0
                        for j in range(10):
                            end = start.t0 + (j + 1) * h
                            status = int(slave.fmi2DoStep(slave.component, now, end - now, 1))
                            now = now + (end - now)
                            departure = true_departure(*fmi2.state(slave), start, max(tol, FLOOR), now)
                            checked.record(status, departure, "")
                            steps, within, worst = steps + 1, within + (departure <= 1.0), max(worst, departure)
                        slave.terminate()
                        slave.freeInstance()
                except FMICallException:
                    print(f"{solver:<11} {tol:<6.0e} refused")
                    continue
                print(f"{solver:<11} {tol:<6.0e} {steps:6d} {checked.ok:6d} {within:6d} {checked.ok_beyond:9d} "
                      f"{worst:9.3g}{f'  at {FLOOR:g}' if tol < FLOOR else ''}", flush=True)


if __name__ == "__main__":
    import sys

    measure(Path(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) > 2 else 40)
