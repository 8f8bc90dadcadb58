"""What went wrong, inferred from the numbers: different parameters or start values, a
known fixed-step method, or a tolerance other than the experiment's.

Each inference reproduces the file: a parameter fit recomputes the exact solution with the
fitted values; a fixed-step method is rerun on the file's grid; a tolerance is found by
running CVODE (fmpy's, the solver most importers use) on the FMU at decades of tolerance
and interpolating where its error meets the file's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from pendulum_fmu.judge.explain import fixed_step
from pendulum_fmu.judge.reading import Result
from pendulum_fmu.judge.verdict import Experiment

State = tuple[float, float]
SCAN_ROWS = 2000
"""The scan of L uses at most about this many rows, evenly spread (the fit itself uses all)."""


@dataclass(frozen=True)
class Fit:
    """Start values and parameters that reproduce some columns with the exact solution."""

    theta0: float
    omega0: float
    L: float
    g: float
    residual: float
    """Largest |column - exact(fitted)| over the fitted columns."""

    def differences(self, experiment: Experiment, resolution: float = 0.0) -> list[str]:
        """"L = 1.1 (not 1)" for each value that differs from the experiment's by more than
        1e-9 relative, or 10 times the columns' print ``resolution`` (relative)."""
        out = []
        relative = max(1e-9, 10 * resolution)
        for name, fitted, stated in (("theta", self.theta0, experiment.problem.theta0),
                                     ("omega", self.omega0, experiment.problem.omega0),
                                     ("L", self.L, experiment.problem.L)):
            if abs(fitted - stated) > relative * max(1.0, abs(stated)):
                out.append(f"{name} = {fitted:.10g} (not {stated:.10g})")
        return out


def fit_parameters(t: np.ndarray, columns: dict[str, np.ndarray], experiment: Experiment) -> Fit | None:
    """Fit theta0, omega0 and L (g held: only g/L matters) so that the exact solution matches
    ``columns`` (keys among theta, omega, theta_exact, omega_exact) at the times ``t``
    (counted from the start).

    The start values begin at the file's first row when it is at t = 0, L at a scan of
    w0 over a factor of 2 either way; then scipy's least squares polishes all three.
    """
    from scipy.optimize import least_squares

    from pendulum_fmu.fmu.library import exact

    thetas = [v for k, v in columns.items() if k.startswith("theta")]
    omegas = [v for k, v in columns.items() if k.startswith("omega")]
    if not thetas and not omegas or t.size < 10:  # three unknowns: too few rows fit anything
        return None
    theta0 = float(thetas[0][0]) if thetas and t[0] == 0 else experiment.problem.theta0
    omega0 = float(omegas[0][0]) if omegas and t[0] == 0 else experiment.problem.omega0
    g = experiment.problem.g

    def residuals(theta_start: float, omega_start: float, length: np.ndarray | float, every: int = 1) -> np.ndarray:
        theta, omega = exact(theta_start, omega_start, np.atleast_1d(length)[:, None], g, t[::every])
        parts = [theta - v[::every] for v in thetas] + [(omega - v[::every]) / experiment.problem.w0 for v in omegas]
        return np.concatenate(parts, axis=-1)

    lengths = experiment.problem.L * np.geomspace(1e-2, 1e2, 481)
    every = max(1, t.size // SCAN_ROWS)
    with np.errstate(all="ignore"):
        scan = np.nanmax(np.abs(residuals(theta0, omega0, lengths, every)), axis=-1)
    if not np.any(np.isfinite(scan)):
        return None
    start = np.array([theta0, omega0, math.log(float(lengths[int(np.nanargmin(scan))]))])

    def vector(x: np.ndarray) -> np.ndarray:
        with np.errstate(all="ignore"):
            r = residuals(float(x[0]), float(x[1]), math.exp(float(x[2])))[0]
        return np.where(np.isfinite(r), r, 1e3)

    solved = least_squares(vector, start, x_scale=np.array([1.0, experiment.problem.w0, 1.0]), xtol=1e-15, ftol=1e-15,
                           gtol=1e-15, max_nfev=200)
    theta_f, omega_f, log_l = (float(v) for v in solved.x)
    r = vector(solved.x)
    scaled = np.concatenate([r[: len(thetas) * t.size], r[len(thetas) * t.size:] * experiment.problem.w0])
    return Fit(theta_f, omega_f, math.exp(log_l), g, float(np.max(np.abs(scaled))))


# --- fixed-step methods: explain/fixed_step.py (a prefix rerun, then every row at once) ---------

identify_fixed_step = fixed_step.identify_fixed_step
FixedStep = fixed_step.FixedStep
METHODS = fixed_step.METHODS


# --- tolerance ---------------------------------------------------------------------------------

def cvode_errors(fmu: Path, result: Result, experiment: Experiment, tolerances: list[float]) -> list[float]:
    """Largest |theta - exact| of fmpy's CVODE on the FMU (Model Exchange) at each tolerance,
    on the file's output grid."""
    from fmpy import simulate_fmu

    from pendulum_fmu.fmu.library import exact

    start, stop = experiment.start_time, float(result.time[-1])
    interval = (stop - float(result.time[0])) / max(1, result.rows - 1)
    out = []
    for tol in tolerances:
        run = simulate_fmu(str(fmu), fmi_type="ModelExchange", solver="CVode", relative_tolerance=tol,
                           start_time=start, stop_time=stop, output_interval=interval, output=["theta"],
                           start_values=experiment.problem.start_values())
        theta, _ = exact(*_arguments(experiment), run["time"] - start)
        out.append(float(np.max(np.abs(run["theta"] - theta))))
    return out


def cvode_agreement(fmu: Path, result: Result, experiment: Experiment) -> float | None:
    """Largest |theta - CVODE's theta| over the file's rows, CVODE (fmpy's, Model Exchange) run
    at the experiment's tolerance on the file's grid; None when the rerun's times are not the
    file's (another grid, or no theta column)."""
    from fmpy import simulate_fmu

    if "theta" not in result.values:
        return None
    start, stop = experiment.start_time, float(result.time[-1])
    interval = (stop - float(result.time[0])) / max(1, result.rows - 1)
    run = simulate_fmu(str(fmu), fmi_type="ModelExchange", solver="CVode", relative_tolerance=experiment.tolerance,
                       start_time=start, stop_time=stop, output_interval=interval, output=["theta"],
                       start_values=experiment.problem.start_values())
    if run.size != result.rows or not np.allclose(run["time"], result.time, rtol=1e-9, atol=1e-9 * interval):
        return None
    return float(np.max(np.abs(run["theta"] - result.values["theta"])))


def solver_name(solver: str | None) -> str:
    """The FMU's Co-Simulation solver by name: ``solver`` as given (a name or the enumeration's
    number, 1 = dopri5 ...), or the FMU's default."""
    from pendulum_fmu.spec import CS_SOLVERS, DEFAULT_CS_SOLVER

    if solver is None:
        return DEFAULT_CS_SOLVER
    text = str(solver).strip()
    if text.isdigit() and 1 <= int(text) <= len(CS_SOLVERS):
        return CS_SOLVERS[int(text) - 1]
    return text if text in CS_SOLVERS else DEFAULT_CS_SOLVER


def fmu_errors(fmu: Path, result: Result, experiment: Experiment, tolerances: list[float]) -> list[float]:
    """Largest |theta - exact| of the FMU's own Co-Simulation solver at each tolerance, on the
    file's output step and span (from the start)."""
    from pendulum_fmu.fmu.runner import FmuRunner
    from pendulum_fmu.spec import Method, TimeGrid

    span = float(result.time[-1]) - experiment.start_time
    interval = (float(result.time[-1]) - float(result.time[0])) / max(1, result.rows - 1)
    grid = TimeGrid(stop=span, unit="s", output_interval=interval)
    solver = solver_name(experiment.solver)
    with FmuRunner(fmu) as runner:
        return [runner.run(experiment.problem, Method(solver, tol), grid).max_error for tol in tolerances]


def effective_tolerance(error: float, tolerances: list[float], errors: list[float]) -> float | None:
    """The tolerance at which CVODE's error (log-log interpolated) equals ``error``; None when
    ``error`` is outside the range the runs span."""
    pairs = sorted(zip(errors, tolerances, strict=True))
    logs_e = np.log10([e for e, _ in pairs])
    logs_t = np.log10([t for _, t in pairs])
    if error <= 0 or not (pairs[0][0] <= error <= pairs[-1][0]) or len(pairs) < 2:
        return None
    return float(10 ** np.interp(math.log10(error), logs_e, logs_t))


def _arguments(experiment: Experiment) -> tuple[float, float, float, float]:
    """theta0, omega0, L, g: the problem as ``pendulum_fmu.exact`` takes it."""
    p = experiment.problem
    return p.theta0, p.omega0, p.L, p.g
