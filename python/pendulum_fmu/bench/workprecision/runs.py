"""One run of one method on one case of the speed-against-error study.

Every runner returns a :class:`Run`: the error max |theta - theta_exact| on the case's grid,
the energy error, the cost in right-hand-side evaluations (machine-independent) and in
wall time. The runners:

- :func:`run_fmu_cs`: the FMU's own Co-Simulation solvers through ``fmpy.simulate_fmu``
  (what a user sees); the cost is read from the FMU's ``stats.*`` variables.
- :func:`run_solve_ivp`: ``scipy.integrate.solve_ivp`` (RK45, DOP853, LSODA, Radau) with
  ``t_eval`` on the grid; the implicit and stiff-switching methods get the analytic
  Jacobian, whose evaluations (one cos each) are counted with the right-hand side's.
- :func:`run_ode_dop853`: ``scipy.integrate.ode`` with ``dop853`` (Hairer's Fortran code),
  integrating from grid point to grid point.
- :func:`run_fmu_me`: fmpy's CVODE, or fmpy's fixed-step forward Euler (the co-simulation
  of today's FMUs: the baseline), on the FMU's Model Exchange interface; every
  ``fmi2GetDerivatives`` call is counted.

The C driver's runs (``tests/c/bench_solvers``) are parsed by :mod:`pendulum_fmu.bench.workprecision.cdriver`.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from fmpy import read_model_description, simulate_fmu
from fmpy.simulation import instantiate_fmu
from scipy.integrate import ode, solve_ivp

from pendulum_fmu.bench.workprecision.problems import Grid, energy_errors
from pendulum_fmu.spec import CS_SOLVERS


@dataclass
class Run:
    """The outcome of one run.

    Attributes
    ----------
    problem : str
        ``"P1"``, ``"P2"`` or ``"P3"``.
    amplitude_deg : float
        Release angle.
    periods : float
        Simulated periods.
    runner : str
        ``"c"`` (the C driver), ``"fmpy"`` (the FMU's solvers through fmpy), ``"scipy"`` or
        ``"fmpy-me"`` (fmpy's own solvers on the Model Exchange interface).
    method : str
        Solver name (``rkn``, ``DOP853``, ``dop853``, ``cvode``, ``euler``, ...).
    tol : float
        Relative tolerance; for ``euler`` the number of Euler steps an output interval.
    status : str
        ``"ok"``, ``"failed"`` (the solver gave up) or ``"skipped"`` (over the time budget).
    rhs_evaluations : int
        Right-hand-side evaluations (sin), plus the Jacobian's or the interpolation's cos
        where a method needs them.
    steps : int
        Accepted steps (0 where the method does not tell).
    rejected : int
        Rejected steps (0 where the method does not tell).
    max_err : float
        max |theta - theta_exact| on the grid (rad).
    energy_err_max, energy_err_first, energy_err_last : float
        max |H - H0| / H0 over all points, the first and the last tenth of them.
    max_abs_theta : float
        max |theta| (a libration that stays below pi did not turn into a rotation).
    wall_s : float
        Wall time of the run in s.
    note : str
        Why a run failed or was skipped.
    """

    problem: str
    amplitude_deg: float
    periods: float
    runner: str
    method: str
    tol: float
    status: str = "ok"
    rhs_evaluations: int = 0
    steps: int = 0
    rejected: int = 0
    max_err: float = math.nan
    energy_err_max: float = math.nan
    energy_err_first: float = math.nan
    energy_err_last: float = math.nan
    max_abs_theta: float = math.nan
    wall_s: float = math.nan
    note: str = field(default="")

    @property
    def flipped(self) -> bool:
        """True if |theta| reached pi: a libration carried over the top."""
        return bool(self.max_abs_theta >= math.pi)


def _measured(run: Run, grid: Grid, theta: np.ndarray, omega: np.ndarray) -> Run:
    """Fills the error fields of ``run`` from a solution on ``grid``."""
    run.max_err = float(np.max(np.abs(theta - grid.theta_exact)))
    run.energy_err_max, run.energy_err_first, run.energy_err_last = energy_errors(theta, omega, grid.case)
    run.max_abs_theta = float(np.max(np.abs(theta)))
    return run


def _new_run(grid: Grid, runner: str, method: str, tol: float) -> Run:
    case = grid.case
    return Run(problem=case.problem, amplitude_deg=case.amplitude_deg, periods=case.periods, runner=runner,
               method=method, tol=tol)


def run_fmu_cs(unzipped: Path, grid: Grid, solver: str, tol: float) -> Run:
    """The FMU's Co-Simulation solver through ``fmpy.simulate_fmu``.

    Parameters
    ----------
    unzipped : Path
        The extracted FMU (extracted once: ``simulate_fmu`` would otherwise unzip it again
        for every run).
    grid : Grid
        Case and output grid.
    solver : str
        One of :data:`CS_SOLVERS`.
    tol : float
        Relative tolerance handed to ``fmi2SetupExperiment``.

    Returns
    -------
    Run
        Error, energy, the FMU's counters and the wall time of the ``simulate_fmu`` call.
    """
    run = _new_run(grid, "fmpy", solver, tol)
    md = read_model_description(str(unzipped), validate=False)
    case = grid.case
    start = time.perf_counter()
    result = simulate_fmu(str(unzipped), model_description=md, validate=False, fmi_type="CoSimulation",
                          start_time=0.0, stop_time=grid.stop_time, output_interval=grid.interval,
                          relative_tolerance=tol,
                          start_values={**case.ivp.start_values(), "solver": CS_SOLVERS.index(solver) + 1},
                          output=["theta", "omega", "stats.steps", "stats.rejected_steps",
                                  "stats.rhs_evaluations"])
    run.wall_s = time.perf_counter() - start
    if len(result) != len(grid.times) or not np.allclose(result["time"], grid.times, rtol=1e-12, atol=0.0):
        run.status, run.note = "failed", f"{len(result)} output points, expected {len(grid.times)}"
        return run
    run.rhs_evaluations = int(result["stats.rhs_evaluations"][-1])
    run.steps = int(result["stats.steps"][-1])
    run.rejected = int(result["stats.rejected_steps"][-1])
    return _measured(run, grid, np.asarray(result["theta"]), np.asarray(result["omega"]))


class _CountingRhs:
    """theta' = omega, omega' = -w0^2 sin(theta), counting its calls; and its Jacobian."""

    def __init__(self, w0sq: float) -> None:
        self.w0sq = w0sq
        self.calls = 0
        self.jac_calls = 0

    def __call__(self, t: float, y: np.ndarray) -> list[float]:
        self.calls += 1
        return [y[1], -self.w0sq * math.sin(y[0])]

    def jac(self, t: float, y: np.ndarray) -> list[list[float]]:
        self.jac_calls += 1
        return [[0.0, 1.0], [-self.w0sq * math.cos(y[0]), 0.0]]


PEER_ATOL_FACTOR = 1e-2
"""scipy peers run at atol = rtol * PEER_ATOL_FACTOR (the DOP853 reference
runs at rtol 1e-10 with atol 1e-12)."""


def run_solve_ivp(grid: Grid, method: str, rtol: float, atol: float | None = None) -> Run:
    """``scipy.integrate.solve_ivp`` on the grid (``t_eval``: its dense output).

    Parameters
    ----------
    grid : Grid
        Case and output grid.
    method : str
        One of :data:`pendulum_fmu.bench.workprecision.peers.SOLVE_IVP_METHODS`.
    rtol : float
        Relative tolerance.
    atol : float, optional
        Absolute tolerance (default rtol * :data:`PEER_ATOL_FACTOR`).

    Returns
    -------
    Run
        Error, energy, right-hand-side (+ Jacobian) evaluations and the wall time of the call.
    """
    run = _new_run(grid, "scipy", method, rtol)
    rhs = _CountingRhs(grid.case.w0sq)
    state0 = [grid.case.ivp.theta0, grid.case.ivp.omega0]
    options: dict[str, Any] = {}
    if method in ("LSODA", "Radau"):
        options["jac"] = rhs.jac
    start = time.perf_counter()
    sol = solve_ivp(rhs, (0.0, grid.stop_time), state0, method=method, t_eval=grid.times,
                    rtol=rtol, atol=rtol * PEER_ATOL_FACTOR if atol is None else atol, **options)
    run.wall_s = time.perf_counter() - start
    run.rhs_evaluations = rhs.calls + rhs.jac_calls
    if not sol.success or sol.y.shape[1] != len(grid.times):
        run.status, run.note = "failed", str(sol.message)
        return run
    return _measured(run, grid, sol.y[0], sol.y[1])


def run_ode_dop853(grid: Grid, rtol: float) -> Run:
    """``scipy.integrate.ode`` with ``dop853`` (Hairer's code), from grid point to grid point.

    Parameters
    ----------
    grid : Grid
        Case and output grid.
    rtol : float
        Relative tolerance (atol = rtol * :data:`PEER_ATOL_FACTOR`).

    Returns
    -------
    Run
        Error, energy, right-hand-side evaluations and the wall time of the loop.
    """
    run = _new_run(grid, "scipy", "dop853", rtol)
    rhs = _CountingRhs(grid.case.w0sq)
    n = len(grid.times)
    theta, omega = np.empty(n), np.empty(n)
    theta[0], omega[0] = grid.case.ivp.theta0, grid.case.ivp.omega0
    start = time.perf_counter()
    solver = ode(rhs).set_integrator("dop853", rtol=rtol, atol=rtol * PEER_ATOL_FACTOR, nsteps=10**9)
    solver.set_initial_value([theta[0], omega[0]], 0.0)
    for i in range(1, n):
        y = solver.integrate(grid.times[i])
        if not solver.successful():
            run.status, run.note = "failed", f"dop853 stopped at t = {solver.t:g}"
            run.wall_s = time.perf_counter() - start
            return run
        theta[i], omega[i] = y[0], y[1]
    run.wall_s = time.perf_counter() - start
    run.rhs_evaluations = rhs.calls
    return _measured(run, grid, theta, omega)


def _counting(function: Callable[..., Any], counter: list[int]) -> Callable[..., Any]:
    """Wraps an FMU method, counting its calls in counter[0]."""

    def wrapper(*args: Any) -> Any:
        counter[0] += 1
        return function(*args)

    return wrapper


def run_fmu_me(unzipped: Path, grid: Grid, method: str, tol: float) -> Run:
    """fmpy's own solver on the FMU's Model Exchange interface.

    Parameters
    ----------
    unzipped : Path
        The extracted FMU.
    grid : Grid
        Case and output grid.
    method : str
        ``"cvode"`` (SUNDIALS CVODE as fmpy sets it up: BDF, relative tolerance ``tol``,
        absolute tolerance ``tol`` times the states' nominal 1) or ``"euler"`` (fixed-step
        forward Euler, ``tol`` steps an output interval: fmpy takes one Euler step per
        output interval, so the run records every step and keeps every ``tol``-th).
    tol : float
        Relative tolerance (cvode) or Euler steps per output interval (euler).

    Returns
    -------
    Run
        Error, energy, ``fmi2GetDerivatives`` calls and the wall time of the run.
    """
    run = _new_run(grid, "fmpy-me", method, tol)
    md = read_model_description(str(unzipped), validate=False)
    fmu = instantiate_fmu(str(unzipped), md, "ModelExchange")
    counter = [0]
    fmu.getDerivatives = _counting(fmu.getDerivatives, counter)
    case = grid.case
    options: dict[str, Any]
    every = 1
    if method == "cvode":
        options = {"solver": "CVode", "relative_tolerance": tol, "output_interval": grid.interval}
    else:
        every = round(tol)
        step = grid.interval / every
        options = {"solver": "Euler", "step_size": step, "output_interval": step}
    start = time.perf_counter()
    try:
        result = simulate_fmu(str(unzipped), model_description=md, fmu_instance=fmu, validate=False,
                              fmi_type="ModelExchange", start_time=0.0, stop_time=grid.stop_time,
                              record_events=False,
                              start_values=case.ivp.start_values(),
                              output=["theta", "omega"], **options)
    except Exception as error:  # noqa: BLE001 -- fmpy raises plain Exceptions for solver failures
        run.status, run.note = "failed", str(error).splitlines()[0][:120]
        return run
    finally:
        run.wall_s = time.perf_counter() - start
        fmu.freeInstance()
    run.rhs_evaluations = counter[0]
    if method == "euler":
        run.steps = counter[0]
    result = result[::every]
    if len(result) != len(grid.times) or not np.allclose(result["time"], grid.times, rtol=1e-9, atol=0.0):
        run.status, run.note = "failed", f"{len(result)} output points, expected {len(grid.times)}"
        return run
    return _measured(run, grid, np.asarray(result["theta"]), np.asarray(result["omega"]))
