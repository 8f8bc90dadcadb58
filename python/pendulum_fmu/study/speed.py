"""Speed against error at the seed's amplitudes: every solver over a range of tolerances.

Each Co-Simulation solver of the FMU (dopri5, rk4, rkn, symplectic) at tolerances 1e-3 ..
1e-12 and Model Exchange through fmpy's CVODE at 1e-4 .. 1e-12 run the seed's four
amplitudes (75, 80, 85, 90 deg from rest) on the study's grid (50 points a period). A point
is one method at one tolerance: its error is the largest max |theta - theta_exact| of the
four runs, its cost the sum of their right-hand-side evaluations (machine-independent: the
FMU's ``stats.rhs_evaluations``, CVODE's ``fmi2GetDerivatives`` calls) and their wall time
per simulated period (this machine; a Co-Simulation run is timed best of :data:`CS_REPEATS`,
since one takes about a millisecond, a CVODE run best of :data:`ME_REPEATS`). The floor is the
exact solution's own cost: the FMU's Jacobi-elliptic evaluation at the same output points
(:func:`pendulum_fmu.fmu.library.exact`, best of :data:`FLOOR_REPEATS`), no right-hand side.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass

from pendulum_fmu.errors import BuildError, SimulationError
from pendulum_fmu.fmu.library import exact
from pendulum_fmu.fmu.runner import FmuRunner, reference_period
from pendulum_fmu.spec import CS_SOLVERS, InitialValueProblem, Method, TimeGrid
from pendulum_fmu.study.tradeoff import cost_to_reach, pareto_front

CS_TOLERANCES: tuple[float, ...] = tuple(10.0 ** -k for k in range(3, 13))
"""Tolerances of the FMU's solvers: 1e-3 .. 1e-12."""
ME_TOLERANCES: tuple[float, ...] = tuple(10.0 ** -k for k in range(4, 13))
"""Relative tolerances of CVODE: 1e-4 .. 1e-12."""
METHODS: tuple[str, ...] = (*CS_SOLVERS, "cvode")
"""The methods compared, in the tables' order."""
LEVELS: tuple[float, ...] = (1e-4, 1e-6, 1e-8, 1e-10, 1e-12)
"""Error levels (rad) of the table and of the fastest-method sentence."""
CS_REPEATS = 3
"""A Co-Simulation run's wall time is the best of this many runs."""
ME_REPEATS = 2
"""A CVODE run's wall time is the best of this many runs."""
FLOOR_REPEATS = 5
"""The floor's wall time is the best of this many evaluations."""


@dataclass(frozen=True)
class SpeedPoint:
    """One method at one tolerance over the seed's amplitudes.

    Attributes
    ----------
    method : str
        ``dopri5``, ``rk4``, ``rkn``, ``symplectic`` (Co-Simulation) or ``cvode`` (Model Exchange).
    tolerance : float
        Relative tolerance.
    max_error : float
        max |theta - theta_exact| over the output points of every amplitude, rad; NaN if a run failed.
    rhs_evaluations : int
        Right-hand-side evaluations, summed over the amplitudes.
    steps : int or None
        Accepted steps, summed (Co-Simulation; None for CVODE, whose steps fmpy does not tell).
    wall_per_period : float
        Wall time per simulated period, s (summed over the amplitudes, divided by their periods).
    periods : float
        Simulated periods, summed.
    failure : str
        Why a run failed; empty when every run finished.
    """

    method: str
    tolerance: float
    max_error: float
    rhs_evaluations: int
    steps: int | None
    wall_per_period: float
    periods: float
    failure: str = ""

    @property
    def interface(self) -> str:
        """``ME`` for CVODE, ``CS`` for the FMU's own solvers."""
        return Method(self.method).interface


@dataclass(frozen=True)
class Floor:
    """The exact solution's cost at the same output points.

    Attributes
    ----------
    wall_per_period : float
        Wall time per simulated period, s; NaN where the ``pendulum_exact`` library is missing.
    points : int
        Output points evaluated (all amplitudes).
    note : str
        Why it was not measured; empty when it was.
    """

    wall_per_period: float
    points: int
    note: str = ""


@dataclass(frozen=True)
class SpeedStudy:
    """Every point of the speed-against-error study and its floor."""

    points: tuple[SpeedPoint, ...]
    floor: Floor
    amplitudes_deg: tuple[float, ...]
    periods: float


def _run_point(runner: FmuRunner, method: str, tolerance: float, problems: list[InitialValueProblem],
               grid: TimeGrid) -> SpeedPoint:
    """One method at one tolerance over every amplitude (a failed run gives a NaN error and its reason)."""
    error, rhs, steps, wall, periods = 0.0, 0, 0, 0.0, 0.0
    repeats = CS_REPEATS if method != "cvode" else ME_REPEATS
    for problem in problems:
        try:
            runs = [runner.run(problem, Method(method, tolerance), grid) for _ in range(repeats)]
        except SimulationError as failure:
            return SpeedPoint(method, tolerance, math.nan, rhs, None, math.nan, periods, str(failure))
        run = runs[0]
        error = max(error, run.max_error)
        rhs += run.rhs_evaluations if run.rhs_evaluations is not None else run.derivative_calls or 0
        steps += run.steps or 0
        wall += min(r.wall_time for r in runs)
        periods += float(run.result["time"][-1] - run.start_time) / reference_period(run.period, problem)
    return SpeedPoint(method, tolerance, error, rhs, steps if method != "cvode" else None, float(wall / periods),
                      float(periods))


def measure_floor(runner: FmuRunner, problems: list[InitialValueProblem], grid: TimeGrid) -> Floor:
    """The exact solution at the grid's points of every problem, best of :data:`FLOOR_REPEATS`."""
    grids = []
    for problem in problems:
        counted_in = reference_period(runner.period(problem), problem)
        times = grid.times_array(counted_in)
        grids.append((problem, times, float(times[-1]) / counted_in))
    points = sum(len(times) for _, times, _ in grids)
    try:
        best = math.inf
        for _ in range(FLOOR_REPEATS):
            start = time.perf_counter()
            for problem, times, _ in grids:
                exact(problem.theta0, problem.omega0, problem.L, problem.g, times, workers=1)
            best = min(best, time.perf_counter() - start)
    except BuildError as missing:
        return Floor(math.nan, points, f"not measured: {missing}")
    return Floor(best / sum(periods for _, _, periods in grids), points)


def measure_speed(runner: FmuRunner, amplitudes_deg: tuple[float, ...], periods: float,
                  points_per_period: int, progress: Callable[[str], None] | None = None) -> SpeedStudy:
    """Run every method at every tolerance over the amplitudes; measure the floor.

    Parameters
    ----------
    runner : FmuRunner
        The loaded FMU.
    amplitudes_deg : tuple of float
        Release angles from rest (the seed's).
    periods : float
        Exact periods a run.
    points_per_period : int
        Output points a period.
    progress : callable, optional
        Called with one line before each method.

    Returns
    -------
    SpeedStudy
        The points in the order of :data:`METHODS` and their tolerances, and the floor.
    """
    grid = TimeGrid(periods, "periods", points_per_period)
    problems = [InitialValueProblem.from_degrees(a) for a in amplitudes_deg]
    found: list[SpeedPoint] = []
    for method in METHODS:
        tolerances = ME_TOLERANCES if method == "cvode" else CS_TOLERANCES
        if progress is not None:
            progress(f"speed against error: {method} at {len(tolerances)} tolerances "
                     f"({tolerances[0]:g} .. {tolerances[-1]:g}), {len(problems)} amplitudes")
        found += [_run_point(runner, method, tol, problems, grid) for tol in tolerances]
    return SpeedStudy(tuple(found), measure_floor(runner, problems, grid), tuple(amplitudes_deg), periods)


def curve(points: tuple[SpeedPoint, ...] | list[SpeedPoint], method: str) -> list[SpeedPoint]:
    """The finished points of one method, by decreasing tolerance."""
    return sorted((p for p in points if p.method == method and not p.failure and math.isfinite(p.max_error)),
                  key=lambda p: -p.tolerance)


def cost_at(points: list[SpeedPoint], level: float, cost: str) -> float:
    """The cost (``rhs_evaluations`` or ``wall_per_period``) at which one method's points reach ``level``."""
    return cost_to_reach(pareto_front((float(getattr(p, cost)), p.max_error) for p in points), level)


def fastest(study: SpeedStudy, level: float, cost: str) -> tuple[str, float] | None:
    """The method that reaches ``level`` at the least cost, and that cost; None if none reaches it."""
    costs = [(cost_at(curve(study.points, m), level, cost), m) for m in METHODS]
    value, method = min(costs)
    return (method, value) if math.isfinite(value) else None


def fastest_sentence(study: SpeedStudy) -> str:
    """One sentence: the fastest method at each error level, by wall time and by evaluations."""
    parts = []
    for level in LEVELS:
        by_wall = fastest(study, level, "wall_per_period")
        by_rhs = fastest(study, level, "rhs_evaluations")
        if by_wall is None:
            parts.append(f"{level:.0e} rad: none of the methods reaches it")
            continue
        text = f"{level:.0e} rad: {by_wall[0]} ({microseconds(by_wall[1])} us a period)"
        if by_rhs is not None and by_rhs[0] != by_wall[0]:
            text += f", though {by_rhs[0]} needs the fewest evaluations"
        parts.append(text)
    return ("Fastest to reach each max error over the seed's amplitudes (least wall time per simulated "
            "period on this machine): " + "; ".join(parts) + ".")


SPEED_HEADER = ("method", *(f"error {level:.0e}" for level in LEVELS), "best error (rad) at tol")
"""The table: per method, evaluations (and microseconds per period) to reach each level."""


def microseconds(seconds: float) -> str:
    """A wall time in us: three digits, or whole microseconds in groups of three from 1000 up."""
    if not math.isfinite(seconds):
        return "-"
    value = seconds * 1e6
    return f"{value:,.0f}".replace(",", " ") if value >= 1000 else f"{value:.3g}"


def speed_rows(study: SpeedStudy) -> list[tuple[str, ...]]:
    """One row of :data:`SPEED_HEADER` per method, and the floor's."""
    rows = []
    for method in METHODS:
        points = curve(study.points, method)
        label = f"{method} ({Method(method).interface})"
        cells = []
        for level in LEVELS:
            rhs, wall = cost_at(points, level, "rhs_evaluations"), cost_at(points, level, "wall_per_period")
            cells.append("-" if not math.isfinite(rhs) else f"{rhs:,.0f} ({microseconds(wall)} us)".replace(",", " "))
        failed = [p for p in study.points if p.method == method and p.failure]
        best = min(points, key=lambda p: p.max_error) if points else None
        tail = f"{best.max_error:.2e} at {best.tolerance:.0e}" if best is not None else "-"
        if failed:
            tail += f" (failed at tol {', '.join(f'{p.tolerance:.0e}' for p in failed)})"
        rows.append((label, *cells, tail))
    floor = study.floor
    floor_cell = (f"0 ({microseconds(floor.wall_per_period)} us)" if math.isfinite(floor.wall_per_period)
                  else floor.note)
    rows.append(("exact solution (floor)", *([floor_cell] * len(LEVELS)), "5e-14 (its bound)"))
    return rows


POINT_COLUMNS = ("method", "interface", "tolerance", "max_error_rad", "rhs_evaluations", "steps",
                 "wall_per_period_s", "periods", "failure")
"""The columns of ``speed.csv``: one line a point."""


def point_record(point: SpeedPoint) -> tuple[str, ...]:
    """One line of ``speed.csv`` (full precision)."""
    return (point.method, point.interface, repr(point.tolerance), repr(point.max_error), str(point.rhs_evaluations),
            "" if point.steps is None else str(point.steps), repr(point.wall_per_period), repr(point.periods),
            point.failure)

