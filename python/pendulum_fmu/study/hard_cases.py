"""The hard cases: near the top, over it, for long and late; every solver, nothing silent.

Each case runs every Co-Simulation solver at the FMU's default tolerance (1e-8) and Model
Exchange through fmpy's CVODE at the study's tolerance (1e-10). For each run: the error
max |theta - theta_exact|; whether every step was certified, recomputed from the run's own
outputs by the certificate's rule (:func:`certificate_departures`, ``docs/certificate.md``)
and told by the FMU (its logged ``certificate:`` and ``hard case:`` warnings, counted); and
the cost. Model Exchange has no certificate (the importer integrates): its points beyond
100 tol of the scales are counted instead, and said. A run that fails is a row that says why.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from pendulum_fmu.errors import SimulationError
from pendulum_fmu.fmu.runner import FmuRunner, Trajectory, reference_period
from pendulum_fmu.spec import CS_SOLVERS, InitialValueProblem, Method, TimeGrid
from pendulum_fmu.study.seed import ME_TOLERANCE
from pendulum_fmu.study.speed import microseconds

EXACT_ERROR = 5e-14
"""The exact port's own error bound, the room the certificate leaves (CERTIFICATE_EXACT_ERROR)."""
LONG_PERIODS = 10_000.0
"""The long run's length in periods (Co-Simulation)."""
LONG_PERIODS_ME = 1_000.0
"""The long run's length through fmpy's CVODE: a Python call per evaluation makes 10^4 periods
take about half a minute here, more than the whole study; the table says so."""
LARGE_START_S = 1e9
"""The large start time, s (about 32 years: a time's last bit is 1.2e-7 s)."""
QUICK_S = 0.02
"""A run quicker than this, s, is run :data:`QUICK_REPEATS` times more and timed best of all."""
QUICK_REPEATS = 2
ROTATION_EXCESS = 1e-9
"""The rotation just above the separatrix: omega0 = 2 w0 (1 + this), theta0 = 0."""


@dataclass(frozen=True)
class HardCase:
    """One hard initial value problem.

    Attributes
    ----------
    name : str
        What it is, for the table.
    short : str
        Its name in a sentence.
    problem : InitialValueProblem
        Start values (L = 1 m, g = 9.81 m/s^2).
    periods : float
        Length in periods (exact periods; revolutions in rotation).
    start_time : float
        The experiment's start time, s.
    me_periods : float
        Length of the CVODE run, periods.
    """

    name: str
    short: str
    problem: InitialValueProblem
    periods: float = 10.0
    start_time: float = 0.0
    me_periods: float | None = None


def hard_cases() -> tuple[HardCase, ...]:
    """The study's hard cases, in the table's order."""
    ivp = InitialValueProblem
    w0 = ivp(0.0).w0
    return (
        HardCase("released at 179.9 deg from rest", "179.9 deg release", ivp.from_degrees(179.9)),
        HardCase("released at 179.9999 deg from rest", "179.9999 deg release", ivp.from_degrees(179.9999)),
        HardCase(f"rotation just above the separatrix: theta0 = 0, omega0 = 2 w0 (1 + {ROTATION_EXCESS:g})",
                 "rotation above the separatrix", ivp(0.0, 2.0 * w0 * (1.0 + ROTATION_EXCESS))),
        HardCase("creeping over the top: theta0 = pi, omega0 = 1e-15 rad/s", "creep over the top",
                 ivp(math.pi, 1e-15)),
        HardCase("long run: 90 deg from rest, " + f"{LONG_PERIODS:,.0f}".replace(",", " ") + " periods", "long run",
                 ivp.from_degrees(90.0), LONG_PERIODS, me_periods=LONG_PERIODS_ME),
        HardCase(f"large start time: 75 deg from rest at t0 = {LARGE_START_S:g} s", "large start time",
                 ivp.from_degrees(75.0), start_time=LARGE_START_S),
    )


@dataclass(frozen=True)
class HardRun:
    """One solver on one hard case.

    Attributes
    ----------
    case : HardCase
        The problem.
    method : Method
        Solver and tolerance.
    periods : float
        Periods run.
    max_error : float
        max |theta - theta_exact| over the output points, rad (NaN if the run failed).
    steps_beyond : int
        Communication points where the state is beyond the certificate's bound (Co-Simulation:
        the steps that must return Warning) or beyond 100 tol of the scales (Model Exchange).
    points : int
        Communication points after the start (Co-Simulation: DoSteps).
    certificate_warnings : int
        ``certificate:`` messages the FMU logged (one at the first crossing, one more at each
        tenfold growth).
    hard_case_warnings : int
        ``hard case:`` messages (a libration carried over the top, a rotation reversed).
    first_warning : str
        The first warning message, if any.
    rhs_evaluations : int
        Right-hand-side evaluations (CVODE: ``fmi2GetDerivatives`` calls).
    wall_per_period : float
        Wall time per simulated period, s.
    failure : str
        Why the run failed; empty if it finished.
    asked_points : int
        The communication points asked for after the start (a run that ended early has fewer).
    """

    case: HardCase
    method: Method
    periods: float
    max_error: float
    steps_beyond: int
    points: int
    certificate_warnings: int
    hard_case_warnings: int
    first_warning: str
    rhs_evaluations: int
    wall_per_period: float
    failure: str = ""
    asked_points: int = 0

    @property
    def verdict(self) -> str:
        """What the run's status says, in words: certified, warned, uncertified, silent or failed."""
        if self.failure:
            return f"FAILED: {self.failure}"
        if self.points < self.asked_points:
            return (f"ENDED EARLY after {self.points} of {self.asked_points} points; "
                    + self._status().replace("certified: all", "the points run certified:"))
        return self._status()

    def _status(self) -> str:
        if self.method.interface == "ME":
            if self.steps_beyond:
                return f"UNCERTIFIED (ME): {self.steps_beyond} of {self.points} points beyond 100 tol"
            return f"uncertified (ME): all {self.points} points within 100 tol"
        warned = self.certificate_warnings + self.hard_case_warnings
        if self.steps_beyond and not warned:
            return f"SILENT: {self.steps_beyond} of {self.points} steps beyond the bound and no warning"
        if not self.steps_beyond and not warned:
            return f"certified: all {self.points} steps OK"
        parts = [f"WARNED: {self.steps_beyond} of {self.points} steps beyond the bound"]
        if self.certificate_warnings:
            plural = "s" if self.certificate_warnings != 1 else ""
            parts.append(f"{self.certificate_warnings} certificate message{plural}")
        if self.hard_case_warnings:
            parts.append("hard case")
        return "; ".join(parts)


def certificate_departures(run: Trajectory, exact_error: float = EXACT_ERROR) -> np.ndarray:
    """The certificate's departure at each output point after the first (docs/certificate.md).

    departure = max(|theta - theta_exact| / ((100 tol - e) max(1, |theta_exact|)),
    |omega - omega_exact| / ((100 tol - e) max(w0, |omega_exact|))); a Co-Simulation step
    returns OK only where it is at most 1. ``exact_error`` = 0 gives the true bound 100 tol.

    Parameters
    ----------
    run : Trajectory
        A run with its recorded theta, omega and their exact values.
    exact_error : float
        e, the room left for the exact port's own error (rad, in units of the scales).

    Returns
    -------
    numpy.ndarray
        One departure per communication point after the start.
    """
    r = run.result[1:]
    bound = 100.0 * run.method.effective_tolerance - exact_error
    theta = np.abs(r["theta"] - r["theta_exact"]) / (bound * np.maximum(1.0, np.abs(r["theta_exact"])))
    omega = np.abs(r["omega"] - r["omega_exact"]) / (bound * np.maximum(run.problem.w0, np.abs(r["omega_exact"])))
    return np.asarray(np.maximum(theta, omega))


def assess(case: HardCase, run: Trajectory) -> HardRun:
    """The row of one finished run."""
    me = run.method.interface == "ME"
    departures = certificate_departures(run, 0.0 if me else EXACT_ERROR)
    warnings = run.warnings
    counted_in = reference_period(run.period, run.problem)
    asked = run.grid.point_count(counted_in) - 1
    periods = float(run.result["time"][-1] - run.start_time) / counted_in
    rhs = run.rhs_evaluations if run.rhs_evaluations is not None else run.derivative_calls or 0
    return HardRun(case, run.method, periods, run.max_error, int(np.count_nonzero(departures > 1.0)),
                   len(departures), sum(w.startswith("certificate:") for w in warnings),
                   sum("hard case:" in w for w in warnings), warnings[0] if warnings else "", rhs,
                   run.wall_time / periods, asked_points=asked)


def run_hard_cases(runner: FmuRunner, points_per_period: int,
                   progress: Callable[[str], None] | None = None) -> list[HardRun]:
    """Every solver on every hard case.

    Parameters
    ----------
    runner : FmuRunner
        The loaded FMU.
    points_per_period : int
        Output points a period.
    progress : callable, optional
        Called with one line before each case.

    Returns
    -------
    list of HardRun
        By case, then dopri5, rk4, rkn, symplectic and CVODE.
    """
    rows = []
    methods = [Method(s) for s in CS_SOLVERS] + [Method("cvode", ME_TOLERANCE)]
    for case in hard_cases():
        if progress is not None:
            progress(f"hard case: {case.name}, 4 solvers and CVODE")
        for method in methods:
            periods = case.me_periods if method.interface == "ME" and case.me_periods else case.periods
            grid = TimeGrid(periods, "periods", points_per_period)
            try:
                run = runner.run(case.problem, method, grid, start_time=case.start_time)
                for _ in range(QUICK_REPEATS if run.wall_time < QUICK_S else 0):   # the same run: best wall time
                    again = runner.run(case.problem, method, grid, start_time=case.start_time)
                    run = again if again.wall_time < run.wall_time else run
                rows.append(assess(case, run))
            except SimulationError as failure:
                rows.append(HardRun(case, method, periods, math.nan, 0, 0, 0, 0, "", 0, math.nan, str(failure)))
    return rows


HARD_HEADER = ("case", "method", "periods", "max abs(theta - theta_exact) (rad)", "every step certified?",
               "rhs evaluations", "wall per period (us)")
"""The hard cases' table."""


def hard_rows(runs: list[HardRun]) -> list[tuple[str, ...]]:
    """One row of :data:`HARD_HEADER` per run; a case is named on its first row only."""
    rows: list[tuple[str, ...]] = []
    for k, run in enumerate(runs):
        first = k == 0 or runs[k - 1].case != run.case
        wall = microseconds(run.wall_per_period)
        error = f"{run.max_error:.2e}" if math.isfinite(run.max_error) else "-"
        method = f"{run.method.solver} ({run.method.interface}, tol {run.method.effective_tolerance:g})"
        rows.append((run.case.name if first else "", method, f"{run.periods:g}", error, run.verdict,
                     f"{run.rhs_evaluations:,}".replace(",", " "), wall))
    return rows


def hard_summary(runs: list[HardRun]) -> str:
    """One sentence: how many runs were certified, warned, uncertified beyond 100 tol, silent, failed."""
    cs = [r for r in runs if r.method.interface == "CS" and not r.failure]
    warned = [r for r in cs if r.certificate_warnings or r.hard_case_warnings]
    silent = [r for r in cs if r.steps_beyond and not (r.certificate_warnings or r.hard_case_warnings)]
    me_beyond = [r for r in runs if r.method.interface == "ME" and not r.failure and r.steps_beyond]
    failed = [r for r in runs if r.failure]
    by_case: dict[str, list[str]] = {}
    for run in warned:
        by_case.setdefault(run.case.short, []).append(run.method.solver)
    named = "; ".join(f"{', '.join(solvers)} on the {short}" for short, solvers in by_case.items())
    text = (f"Of {len(cs)} Co-Simulation runs, {len(cs) - len(warned) - len(silent)} had every step certified and "
            f"{len(warned)} warned{f' ({named})' if named else ''}; {len(silent)} went beyond the bound "
            "without a warning. ")
    text += (f"CVODE (Model Exchange, not certified by the FMU) went beyond 100 tol in {len(me_beyond)} of "
             f"{sum(r.method.interface == 'ME' for r in runs)} cases")
    text += f"; {len(failed)} runs failed." if failed else "; no run failed."
    return text


CSV_COLUMNS = ("case", "solver", "tolerance", "periods", "start_time_s", "max_error_rad", "steps_beyond",
               "points", "certificate_warnings", "hard_case_warnings", "rhs_evaluations", "wall_per_period_s",
               "verdict", "first_warning")
"""The columns of ``hard_cases.csv``."""


def hard_record(run: HardRun) -> tuple[str, ...]:
    """One line of ``hard_cases.csv`` (full precision)."""
    return (run.case.name, run.method.solver, repr(run.method.effective_tolerance), repr(run.periods),
            repr(run.case.start_time), repr(run.max_error), str(run.steps_beyond), str(run.points),
            str(run.certificate_warnings), str(run.hard_case_warnings), str(run.rhs_evaluations),
            repr(run.wall_per_period), run.verdict, run.first_warning)
