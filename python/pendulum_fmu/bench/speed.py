"""Benchmark: one simulation from Python, the package's path against fmpy and compiled peers.

The problem: released from rest at 80 deg, L = 1 m, g = 9.81 m/s^2, 100 exact
periods, 8 output points a period; every method must reach max |theta - theta_exact| <= 1e-9
on the output points (the truth from pendulum_fmu.exact). Every method runs at the loosest
tolerance of 1e-7 .. 1e-13 (decades) that reaches that error. After one warm-up each, the
methods take turns, one run each per round, in a new (seeded) random order every round, with
Python's cyclic garbage collector off during the rounds (as ``timeit`` does: no method pays
for collecting another's garbage); best and median over the rounds are reported.

- package, C loop: FmuRunner.run as every command and the sweep's workers call it: the FMU's
  rkn, DoStep and one GetReal of all six recorded outputs (theta, omega, their exact values,
  x, y) per point from the C library pendulum_driver, straight into the result array;
- package, Python loop (before): the same run with the same calls made from Python through
  prebuilt ctypes prototypes (FmuRunner(loop="python"), the path before the C loop);
- package C loop, theta and omega: the same C loop (without the Python of FmuRunner.run around
  it) recording only what numbalsoda returns; then with the exact solution, then all six
  outputs: where a full run's time goes;
- fmpy FMU2Slave wrappers: the same FMU instance driven by fmpy's doStep/getReal;
- fmpy simulate_fmu: simulate_fmu("Pendulum.fmu", ...) as a user calls it (it extracts the
  FMU every call); tuned: extracted once, only theta recorded, the model description read once;
- numbalsoda dop853: numbalsoda's C++ DOP853 with a numba-compiled right-hand side, called
  once for the whole grid: the compiled peer. Optional (it builds from source only,
  with a Fortran compiler: apt-get install gfortran and pip install numba==0.68.1
  numbalsoda==0.3.4); without it its row says so;
- scipy ode dop853: Hairer's compiled DOP853 (Fortran) with a Python right-hand side;
- scipy solve_ivp DOP853: scipy's pure-Python DOP853.
"""

from __future__ import annotations

import gc
import math
import random
import shutil
import statistics
import time
from collections.abc import Callable
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from pendulum_fmu.fmu import driver
from pendulum_fmu.fmu.library import exact
from pendulum_fmu.fmu.runner import FmuRunner, reference_period
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid

AMPLITUDE_DEG = 80.0
PERIODS = 100
POINTS_PER_PERIOD = 8
TARGET_ERROR = 1e-9
PEER_TOLERANCES = tuple(10.0 ** -k for k in range(7, 14))
"""The tolerances tried, loosest first, for the FMU's rkn and for every peer alike."""
PACKAGE = "package, C loop (FmuRunner)"
PACKAGE_PYTHON = "package, Python loop (before)"
NUMBALSODA = "numbalsoda dop853 (compiled)"


@dataclass(frozen=True)
class MethodTimes:
    """One method's wall times over the rounds, and its error.

    Attributes
    ----------
    name : str
        The method, as printed.
    seconds : tuple of float
        Wall time of one run in each round, s (empty when the method did not run).
    points : int
        Output points of the run (its first point included).
    error : float
        max |theta - theta_exact| over the output points, rad.
    setting : str
        Tolerance or what else was chosen.
    """

    name: str
    seconds: tuple[float, ...]
    points: int
    error: float
    setting: str

    @property
    def best(self) -> float:
        """Fastest round, s (NaN when the method did not run)."""
        return min(self.seconds) if self.seconds else math.nan

    @property
    def median(self) -> float:
        """Median round, s (NaN when the method did not run)."""
        return statistics.median(self.seconds) if self.seconds else math.nan

    @property
    def us_per_point(self) -> float:
        """Best wall time per output point, microseconds."""
        return 1e6 * self.best / self.points


@dataclass
class _Method:
    """A method ready to time: ``run`` returns theta on the grid."""

    name: str
    run: Callable[[], np.ndarray]
    error: float
    setting: str


def _loosest(solve: Callable[[float], np.ndarray], truth: np.ndarray) -> tuple[float, float] | tuple[None, float]:
    """(rtol, error) of the loosest tolerance reaching TARGET_ERROR, or (None, last error)."""
    error = math.nan
    for rtol in PEER_TOLERANCES:
        error = float(np.max(np.abs(solve(rtol) - truth)))
        if error <= TARGET_ERROR:
            return rtol, error
    return None, error


def measure(fmu: Path, rounds: int = 10) -> list[MethodTimes]:
    """Time every method on the problem in interleaved rounds; see the module's text.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu`` (FMI 2.0 or 3.0).
    rounds : int
        Rounds; each method runs once per round, in turn.

    Returns
    -------
    list of MethodTimes
        In the order of the module's list.
    """
    problem = InitialValueProblem.from_degrees(AMPLITUDE_DEG)
    grid = TimeGrid(PERIODS, "periods", POINTS_PER_PERIOD)
    scratch: list[Path] = []
    try:
        with FmuRunner(fmu) as runner, FmuRunner(fmu, loop="python") as python_runner:
            period = runner.period(problem)
            times = grid.times_array(reference_period(period, problem))
            truth, _ = exact(problem.theta0, problem.omega0, problem.L, problem.g, times)
            methods, rtol = _package_methods(runner, python_runner, problem, grid, times, truth)
            methods += _fmpy_methods(runner, fmu, problem, times, truth, rtol, scratch)
            unavailable: list[MethodTimes] = []
            for name, solve in ((NUMBALSODA, _numbalsoda(problem)), ("scipy ode dop853 (compiled)", _ode_dop853),
                                ("scipy solve_ivp DOP853", _solve_ivp_dop853)):
                if isinstance(solve, str):
                    unavailable.append(MethodTimes(name, (), times.size, math.nan, solve))
                    continue
                peer_rtol, error = _loosest(partial(solve, problem, times), truth)
                if peer_rtol is None:
                    unavailable.append(MethodTimes(name, (), times.size, error,
                                              f"never <= {TARGET_ERROR:g} down to rtol {PEER_TOLERANCES[-1]:g}"))
                    continue
                methods.append(_Method(name, partial(solve, problem, times, peer_rtol), error,
                                       f"rtol {peer_rtol:g}, atol rtol/100"))
            seconds: dict[str, list[float]] = {m.name: [] for m in methods}
            for method in methods:
                method.run()   # warm-up
            gc.collect()
            gc.disable()   # as timeit does: no method pays for collecting another's garbage
            try:
                shuffle = random.Random(0).shuffle
                for _ in range(rounds):   # a new order every round: no method always follows the same one
                    order = list(methods)
                    shuffle(order)
                    for method in order:
                        start = time.perf_counter()
                        method.run()
                        seconds[method.name].append(time.perf_counter() - start)
            finally:
                gc.enable()
    finally:
        for folder in scratch:
            shutil.rmtree(folder, ignore_errors=True)
    timings = [MethodTimes(m.name, tuple(seconds[m.name]), times.size, m.error, m.setting) for m in methods]
    rows = [PACKAGE, PACKAGE_PYTHON, *LOOP_ROWS, "fmpy FMU2Slave wrappers",
             "fmpy simulate_fmu", "fmpy simulate_fmu, tuned", NUMBALSODA, "scipy ode dop853 (compiled)",
             "scipy solve_ivp DOP853"]
    every = timings + unavailable
    return sorted(every, key=lambda t: rows.index(t.name) if t.name in rows else len(rows))


def _package_methods(runner: FmuRunner, python_runner: FmuRunner, problem: InitialValueProblem, grid: TimeGrid,
                     times: np.ndarray, truth: np.ndarray) -> tuple[list[_Method], float]:
    """The package's rows, all at rkn's loosest tolerance that reaches the error, and that tolerance."""
    def full_run(on: FmuRunner, method: Method) -> np.ndarray:
        return on.run(problem, method, grid).result["theta"]

    rtol, error = _loosest(lambda r: full_run(runner, Method("rkn", r)), truth)
    if rtol is None:
        raise RuntimeError(f"the FMU's rkn does not reach {TARGET_ERROR:g} on the benchmark problem")
    method = Method("rkn", rtol)
    setting = f"rkn, tol {rtol:g}"
    rows = [_Method(PACKAGE, lambda: full_run(runner, method), error, f"{setting}, 6 outputs, {runner.loop} loop"),
            _Method(PACKAGE_PYTHON, lambda: full_run(python_runner, method),
                    float(np.max(np.abs(full_run(python_runner, method) - truth))), f"{setting}, 6 outputs")]
    if runner.loop != "c":
        return rows, rtol
    for label, names in LOOP_ROWS.items():
        rows.append(_loop_row(runner, problem, method, times, truth, label, names, setting))
    return rows, rtol


LOOP_ROWS: dict[str, tuple[str, ...]] = {
    "package C loop, theta and omega": ("theta", "omega"),
    "package C loop, + theta_exact, omega_exact": ("theta", "omega", "theta_exact", "omega_exact"),
    "package C loop, all 6 outputs": ("theta", "omega", "theta_exact", "omega_exact", "x", "y"),
}
"""The C loop alone (reset, initialization, loop, terminate; no Trajectory), recording what
numbalsoda returns, then adding the FMU's outputs: where a full run's time goes."""


def _loop_row(runner: FmuRunner, problem: InitialValueProblem, method: Method, times: np.ndarray,
              truth: np.ndarray, label: str, names: tuple[str, ...], setting: str) -> _Method:
    """A row of :data:`LOOP_ROWS`: the runner's instance (:meth:`FmuRunner.initialized`) driven by
    a C loop over ``names``."""
    rows = np.dtype([("time", np.float64)] + [(name, np.float64) for name in names])

    def initialized() -> Any:
        return runner.initialized(problem, method)

    loop = driver.OutputLoop(initialized(), runner.fmi_version, [runner.vr[name] for name in names])

    def run() -> np.ndarray:
        slave = initialized()
        out = np.empty(times.size, dtype=rows)
        loop.run(times, out, names[0], runner.log)
        slave.terminate()
        return out["theta"]

    return _Method(label, run, float(np.max(np.abs(run() - truth))), f"{setting}, {', '.join(names)}")


def _fmpy_methods(runner: FmuRunner, fmu: Path, problem: InitialValueProblem, times: np.ndarray,
                  truth: np.ndarray, rtol: float, scratch: list[Path]) -> list[_Method]:
    """fmpy's rows at the same tolerance as the package (FMI 2.0 only for the wrapper loop);
    the folders to delete afterwards go to ``scratch``."""
    from fmpy import extract, read_model_description, simulate_fmu

    rows: list[_Method] = []
    if runner.fmi_version == 2:
        # the runner's own instance, now driven by fmpy's wrappers
        slave = runner.initialized(problem, Method("rkn", rtol))
        vr = runner.vr
        refs = [vr["theta"]]

        def fmpy_loop() -> np.ndarray:
            slave.reset()
            slave.setupExperiment(tolerance=rtol, startTime=0.0)
            slave.setReal([vr["theta"]], [problem.theta0])
            slave.enterInitializationMode()
            slave.exitInitializationMode()
            out = np.empty(times.size)
            out[0] = slave.getReal(refs)[0]
            for k in range(1, times.size):
                slave.doStep(currentCommunicationPoint=times[k - 1], communicationStepSize=times[k] - times[k - 1])
                out[k] = slave.getReal(refs)[0]
            slave.terminate()
            return out

        rows.append(_Method("fmpy FMU2Slave wrappers", fmpy_loop, float(np.max(np.abs(fmpy_loop() - truth))),
                            f"rkn, tol {rtol:g}"))
    interval = float(times[1] - times[0])
    options = dict(start_time=0.0, stop_time=float(times[-1]), output_interval=interval, relative_tolerance=rtol,
                   start_values={"theta": problem.theta0}, validate=False)

    def plain() -> np.ndarray:
        return np.asarray(simulate_fmu(str(fmu), output=["theta", "theta_exact"], **options)["theta"])

    rows.append(_Method("fmpy simulate_fmu", plain, float(np.max(np.abs(plain() - truth))), f"rkn, tol {rtol:g}"))
    unzipped = extract(str(fmu))
    scratch.append(Path(unzipped))
    description = read_model_description(unzipped, validate=False)

    def tuned() -> np.ndarray:
        return np.asarray(simulate_fmu(unzipped, model_description=description, output=["theta"], **options)["theta"])

    rows.append(_Method("fmpy simulate_fmu, tuned", tuned, float(np.max(np.abs(tuned() - truth))),
                        f"rkn, tol {rtol:g}, extracted once, theta only"))
    return rows


def _numbalsoda(problem: InitialValueProblem) -> Callable[[InitialValueProblem, np.ndarray, float], np.ndarray] | str:
    """numbalsoda's solver on this problem, or why it cannot run."""
    try:
        import numba
        import numbalsoda
    except ImportError:
        return "not installed: apt-get install gfortran; pip install numba==0.68.1 numbalsoda==0.3.4"

    @numba.cfunc(numbalsoda.lsoda_sig)
    def rhs(_t, u, du, p):  # type: ignore[no-untyped-def]
        du[0] = u[1]
        du[1] = -p[0] * math.sin(u[0])   # theta'' = -(g/L) sin theta

    start = np.array([problem.theta0, problem.omega0])
    data = np.array([problem.g / problem.L])

    def solve(_: InitialValueProblem, grid: np.ndarray, rtol: float) -> np.ndarray:
        solution, ok = numbalsoda.dop853(rhs.address, start, grid, data=data, rtol=rtol, atol=rtol / 100.0)
        return solution[:, 0] if ok else np.full(grid.size, math.nan)

    return solve


def _ode_dop853(problem: InitialValueProblem, times: np.ndarray, rtol: float) -> np.ndarray:
    """Hairer's DOP853 through scipy's ``ode``, from output point to output point."""
    from scipy.integrate import ode

    w0sq = problem.g / problem.L

    def rhs(_: float, y: np.ndarray) -> list[float]:
        return [y[1], -w0sq * math.sin(y[0])]

    solver = ode(rhs).set_integrator("dop853", rtol=rtol, atol=rtol / 100.0, nsteps=10**7)
    solver.set_initial_value([problem.theta0, problem.omega0], 0.0)
    out = np.empty(times.size)
    out[0] = problem.theta0
    for k in range(1, times.size):
        out[k] = solver.integrate(times[k])[0]
    return out


def _solve_ivp_dop853(problem: InitialValueProblem, times: np.ndarray, rtol: float) -> np.ndarray:
    """scipy's ``solve_ivp`` DOP853 with ``t_eval`` on the grid."""
    from scipy.integrate import solve_ivp

    w0sq = problem.g / problem.L

    def rhs(_: float, y: np.ndarray) -> list[float]:
        return [y[1], -w0sq * math.sin(y[0])]

    solution = solve_ivp(rhs, (0.0, float(times[-1])), [problem.theta0, problem.omega0], method="DOP853",
                         t_eval=times, rtol=rtol, atol=rtol / 100.0)
    return np.asarray(solution.y[0])
