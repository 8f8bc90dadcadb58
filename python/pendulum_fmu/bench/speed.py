"""Benchmark: one simulation from Python, the package's path against fmpy and a compiled peer.

The problem (issue 12): released from rest at 80 deg, L = 1 m, g = 9.81 m/s^2, 100 exact
periods, 8 output points a period; every method must reach max |theta - theta_exact| <= 1e-9
on the output points (the truth from :func:`pendulum_fmu.exact`). Measured in one run, best
of ``repeat`` after one warm-up:

- ``package``: :class:`~pendulum_fmu.fmu.runner.FmuRunner` (extracted once; the FMU's rkn;
  ``fmi2DoStep`` and one ``fmi2GetReal`` per point through prebuilt ctypes prototypes);
- ``fmpy wrappers``: the same FMU instance driven by fmpy's ``FMU2Slave.doStep``/``getReal``;
- ``simulate_fmu``: fmpy's ``simulate_fmu("Pendulum.fmu", ...)`` as a user calls it (it
  extracts the FMU every call);
- ``simulate_fmu, tuned``: extracted once, only ``theta`` recorded, the model description
  read once (what an fmpy user can do without this package);
- ``ode dop853``: scipy's ``ode`` with Hairer's compiled DOP853 (Fortran; the right-hand side
  is a Python function), the loosest rtol of 1e-7 .. 1e-13 that reaches the error;
- ``solve_ivp DOP853``: scipy's pure-Python DOP853, likewise.

- ``numbalsoda dop853``: numbalsoda's C++ DOP853 with a numba-compiled right-hand side, called
  once for the whole grid: the compiled peer the issue names. It is optional (it builds from
  source only, with a Fortran compiler: ``apt-get install gfortran`` and
  ``pip install numba==0.68.1 numbalsoda==0.3.4``); without it its row says so.
"""

from __future__ import annotations

import math
import shutil
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from pendulum_fmu.fmu.library import exact
from pendulum_fmu.fmu.runner import FmuRunner, reference_period
from pendulum_fmu.spec import Method, Pendulum, TimeGrid

AMPLITUDE_DEG = 80.0
PERIODS = 100
POINTS_PER_PERIOD = 8
TARGET_ERROR = 1e-9
FMU_TOLERANCE = 1e-8
"""rkn's tolerance for the FMU rows: the loosest decade that reaches TARGET_ERROR here."""
PEER_TOLERANCES = tuple(10.0 ** -k for k in range(7, 14))


@dataclass(frozen=True)
class Timing:
    """One method's best wall time for the whole run, and its error.

    Attributes
    ----------
    name : str
        The method, as printed.
    seconds : float
        Best wall time of one run, s.
    points : int
        Output points of the run (its first point included).
    error : float
        max |theta - theta_exact| over the output points, rad.
    setting : str
        Tolerance or what else was chosen.
    """

    name: str
    seconds: float
    points: int
    error: float
    setting: str

    @property
    def us_per_point(self) -> float:
        """Wall time per output point, microseconds."""
        return 1e6 * self.seconds / self.points


def _best(run: Callable[[], np.ndarray], repeat: int) -> tuple[float, np.ndarray]:
    """Best wall time of ``repeat`` calls after one warm-up, and the last theta."""
    theta = run()
    best = math.inf
    for _ in range(repeat):
        start = time.perf_counter()
        theta = run()
        best = min(best, time.perf_counter() - start)
    return best, theta


def measure(fmu: Path, repeat: int = 5) -> list[Timing]:
    """Time every method on the problem; see the module's text.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.
    repeat : int
        Timed runs per method (the best counts).

    Returns
    -------
    list of Timing
        In the order of the module's list.
    """
    from fmpy import extract, read_model_description, simulate_fmu
    from fmpy.fmi2 import FMU2Slave

    pendulum = Pendulum.from_degrees(AMPLITUDE_DEG)
    method = Method("rkn", FMU_TOLERANCE)
    grid = TimeGrid(PERIODS, "periods", POINTS_PER_PERIOD)
    timings: list[Timing] = []
    with FmuRunner(fmu) as runner:
        period = runner.period(pendulum)
        times = np.asarray(grid.times(reference_period(period, pendulum)), dtype=float)
        truth, _ = exact(pendulum.amplitude_rad, 0.0, pendulum.length, pendulum.gravity, times)

        def error(theta: np.ndarray) -> float:
            return float(np.max(np.abs(theta - truth)))

        seconds, theta = _best(lambda: runner.run(pendulum, method, grid).result["theta"], repeat)
        timings.append(Timing("package (FmuRunner)", seconds, times.size, error(theta), f"rkn, tol {FMU_TOLERANCE:g}"))

        slave: FMU2Slave = runner._fresh_slave()  # the same instance, now driven by fmpy's wrappers
        vr = runner.vr
        refs = [vr["theta"]]

        def fmpy_loop() -> np.ndarray:
            slave.reset()
            slave.setupExperiment(tolerance=FMU_TOLERANCE, startTime=0.0)
            slave.setReal([vr["theta"]], [pendulum.amplitude_rad])
            slave.enterInitializationMode()
            slave.exitInitializationMode()
            out = np.empty(times.size)
            out[0] = slave.getReal(refs)[0]
            for k in range(1, times.size):
                slave.doStep(currentCommunicationPoint=times[k - 1], communicationStepSize=times[k] - times[k - 1])
                out[k] = slave.getReal(refs)[0]
            slave.terminate()
            return out

        seconds, theta = _best(fmpy_loop, repeat)
        timings.append(Timing("fmpy FMU2Slave wrappers", seconds, times.size, error(theta), f"rkn, tol {FMU_TOLERANCE:g}"))
    interval = float(times[1] - times[0])
    stop = float(times[-1])
    options = dict(start_time=0.0, stop_time=stop, output_interval=interval, relative_tolerance=FMU_TOLERANCE,
                   start_values={"theta": pendulum.amplitude_rad}, validate=False)

    seconds, theta = _best(lambda: simulate_fmu(str(fmu), output=["theta", "theta_exact"], **options)["theta"], repeat)
    timings.append(Timing("fmpy simulate_fmu", seconds, times.size, error(theta), f"rkn, tol {FMU_TOLERANCE:g}"))
    unzipped = extract(str(fmu))
    try:
        description = read_model_description(unzipped, validate=False)
        seconds, theta = _best(lambda: simulate_fmu(unzipped, model_description=description, output=["theta"],
                                                    **options)["theta"], repeat)
        timings.append(Timing("fmpy simulate_fmu, tuned", seconds, times.size, error(theta),
                              f"rkn, tol {FMU_TOLERANCE:g}, extracted once, theta only"))
    finally:
        shutil.rmtree(unzipped, ignore_errors=True)
    timings.append(_numbalsoda_row(pendulum, times, truth, repeat))
    timings.append(_peer("scipy ode dop853 (compiled)", _ode_dop853, pendulum, times, truth, repeat))
    timings.append(_peer("scipy solve_ivp DOP853", _solve_ivp_dop853, pendulum, times, truth, repeat))
    return timings


NUMBALSODA = "numbalsoda dop853 (compiled)"
"""The name of numbalsoda's row."""


def _numbalsoda_row(pendulum: Pendulum, times: np.ndarray, truth: np.ndarray, repeat: int) -> Timing:
    """numbalsoda's row, or a row that says it is not installed."""
    try:
        import numba
        import numbalsoda
    except ImportError:
        return Timing(NUMBALSODA, math.nan, times.size, math.nan,
                      "not installed: apt-get install gfortran; pip install numba==0.68.1 numbalsoda==0.3.4")

    @numba.cfunc(numbalsoda.lsoda_sig)
    def rhs(_t, u, du, p):  # type: ignore[no-untyped-def]
        du[0] = u[1]
        du[1] = -p[0] * math.sin(u[0])   # theta'' = -(g/L) sin theta

    start = np.array([pendulum.amplitude_rad, pendulum.omega0])
    data = np.array([pendulum.gravity / pendulum.length])

    def solve(_: Pendulum, grid: np.ndarray, rtol: float) -> np.ndarray:
        solution, ok = numbalsoda.dop853(rhs.address, start, grid, data=data, rtol=rtol, atol=rtol / 100.0)
        return solution[:, 0] if ok else np.full(grid.size, math.nan)

    return _peer(NUMBALSODA, solve, pendulum, times, truth, repeat)


def _ode_dop853(pendulum: Pendulum, times: np.ndarray, rtol: float) -> np.ndarray:
    """Hairer's DOP853 through scipy's ``ode``, from output point to output point."""
    from scipy.integrate import ode

    w0sq = pendulum.gravity / pendulum.length

    def rhs(_: float, y: np.ndarray) -> list[float]:
        return [y[1], -w0sq * math.sin(y[0])]

    solver = ode(rhs).set_integrator("dop853", rtol=rtol, atol=rtol / 100.0, nsteps=10**7)
    solver.set_initial_value([pendulum.amplitude_rad, pendulum.omega0], 0.0)
    out = np.empty(times.size)
    out[0] = pendulum.amplitude_rad
    for k in range(1, times.size):
        out[k] = solver.integrate(times[k])[0]
    return out


def _solve_ivp_dop853(pendulum: Pendulum, times: np.ndarray, rtol: float) -> np.ndarray:
    """scipy's ``solve_ivp`` DOP853 with ``t_eval`` on the grid."""
    from scipy.integrate import solve_ivp

    w0sq = pendulum.gravity / pendulum.length

    def rhs(_: float, y: np.ndarray) -> list[float]:
        return [y[1], -w0sq * math.sin(y[0])]

    solution = solve_ivp(rhs, (0.0, float(times[-1])), [pendulum.amplitude_rad, pendulum.omega0], method="DOP853",
                         t_eval=times, rtol=rtol, atol=rtol / 100.0)
    return np.asarray(solution.y[0])


def _peer(name: str, solve: Callable[[Pendulum, np.ndarray, float], np.ndarray], pendulum: Pendulum,
          times: np.ndarray, truth: np.ndarray, repeat: int) -> Timing:
    """The peer at the loosest tolerance of PEER_TOLERANCES that reaches TARGET_ERROR."""
    for rtol in PEER_TOLERANCES:
        theta = solve(pendulum, times, rtol)
        err = float(np.max(np.abs(theta - truth)))
        if err <= TARGET_ERROR:
            seconds, theta = _best(lambda: solve(pendulum, times, rtol), repeat)
            return Timing(name, seconds, times.size, err, f"rtol {rtol:g}, atol rtol/100")
    return Timing(name, math.nan, times.size, err, f"never <= {TARGET_ERROR:g} down to rtol {PEER_TOLERANCES[-1]:g}")
