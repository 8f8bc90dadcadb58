"""Work-precision curves: runs aggregated per problem, cost at a given error, the default.

A *point* is one method at one tolerance on one problem: for P1 the four amplitudes
together (the error is the largest of the four, the cost the sum). A method's *curve* is its
points over the tolerances; its *front* keeps the points that no cheaper point beats in
error. The cost to reach an error e is read off the front by log-log interpolation between
the two front points around e (the cheapest point if it is already below e; infinite if no
point reaches e); the same rule for every method.
"""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass

import numpy as np

from pendulum_fmu.bench.workprecision.runs import Run
from pendulum_fmu.study.tradeoff import cost_to_reach, pareto_front


@dataclass(frozen=True)
class Point:
    """One method at one tolerance on one problem.

    Attributes
    ----------
    problem : str
        ``"P1"``, ``"P2"`` or ``"P3"``.
    runner : str
        ``"c"``, ``"fmpy"``, ``"scipy"`` or ``"fmpy-me"``.
    method : str
        Solver name.
    tol : float
        Tolerance (Euler: steps an output interval).
    status : str
        ``"ok"`` if every case of the problem ran, else the first other status.
    max_err : float
        Largest error over the cases.
    rhs_evaluations : int
        Sum over the cases.
    wall_s : float
        Sum over the cases.
    periods : float
        Simulated periods, summed over the cases.
    energy_err_max, energy_err_first, energy_err_last : float
        Largest over the cases.
    flipped : bool
        A libration turned into a rotation in one of the cases.
    rejected : int
        Rejected steps, summed.
    """

    problem: str
    runner: str
    method: str
    tol: float
    status: str
    max_err: float
    rhs_evaluations: int
    wall_s: float
    periods: float
    energy_err_max: float
    energy_err_first: float
    energy_err_last: float
    flipped: bool
    rejected: int

    @property
    def label(self) -> str:
        """The curve's name: the method, with the runner where it is not obvious."""
        if self.runner == "c":
            return f"{self.method} (FMU, C driver)"
        if self.runner == "fmpy":
            return f"{self.method} (FMU, fmpy)"
        if self.runner == "fmpy-me":
            return f"{'CVODE' if self.method == 'cvode' else 'forward Euler'} (fmpy, ME)"
        return f"{'ode dop853' if self.method == 'dop853' else 'solve_ivp ' + self.method} (scipy)"

    @property
    def wall_per_period(self) -> float:
        """Wall time per simulated period in s."""
        return self.wall_s / self.periods


def aggregate(runs: list[Run]) -> list[Point]:
    """Groups runs into points (one per problem, runner, method and tolerance).

    Parameters
    ----------
    runs : list of Run
        All runs of a study.

    Returns
    -------
    list of Point
        In the order the groups first appear.
    """
    groups: dict[tuple[str, str, str, float], list[Run]] = defaultdict(list)
    for run in runs:
        groups[(run.problem, run.runner, run.method, run.tol)].append(run)
    points = []
    for (problem, runner, method, tol), members in groups.items():
        bad = [r.status for r in members if r.status != "ok"]
        ok = not bad

        def worst(values: list[float], ok: bool = ok) -> float:
            return max(values) if ok else math.nan

        points.append(Point(problem=problem, runner=runner, method=method, tol=tol,
                            status="ok" if ok else bad[0],
                            max_err=worst([r.max_err for r in members]),
                            rhs_evaluations=sum(r.rhs_evaluations for r in members),
                            wall_s=sum(r.wall_s for r in members) if ok else math.nan,
                            periods=sum(r.periods for r in members),
                            energy_err_max=worst([r.energy_err_max for r in members]),
                            energy_err_first=worst([r.energy_err_first for r in members]),
                            energy_err_last=worst([r.energy_err_last for r in members]),
                            flipped=ok and any(r.flipped for r in members),
                            rejected=sum(r.rejected for r in members)))
    return points


def curve(points: list[Point], problem: str, runner: str, method: str) -> list[Point]:
    """The ok points of one method on one problem, by decreasing tolerance."""
    selected = [p for p in points if p.problem == problem and p.runner == runner and p.method == method
                and p.status == "ok" and math.isfinite(p.max_err)]
    return sorted(selected, key=lambda p: -p.tol)


def front(points: list[Point], cost: str = "rhs_evaluations") -> list[tuple[float, float]]:
    """The (error, cost) pairs no cheaper point beats in error, by increasing cost.

    Parameters
    ----------
    points : list of Point
        One method's points.
    cost : str
        ``"rhs_evaluations"`` or ``"wall_per_period"``.

    Returns
    -------
    list of (float, float)
        Errors strictly decreasing as the cost increases
        (:func:`pendulum_fmu.study.tradeoff.pareto_front`).
    """
    return pareto_front((float(getattr(p, cost)), p.max_err) for p in points)


def cost_at(points: list[Point], error: float, cost: str = "rhs_evaluations") -> float:
    """The cost to reach a given error on a method's front (module docstring).

    Parameters
    ----------
    points : list of Point
        One method's points on one problem.
    error : float
        The error level.
    cost : str
        ``"rhs_evaluations"`` or ``"wall_per_period"``.

    Returns
    -------
    float
        The interpolated cost; +inf if no point reaches ``error``.
    """
    return cost_to_reach(front(points, cost), error)


def log_slope(points: list[Point]) -> float:
    """Least-squares slope of log(error) against log(tolerance): 1 is tolerance proportionality."""
    x = np.log([p.tol for p in points])
    y = np.log([max(p.max_err, 1e-300) for p in points])
    return float(np.polyfit(x, y, 1)[0]) if len(points) >= 2 else math.nan


def best_method(points: list[Point], problem: str, runner: str, methods: list[str],
                levels: list[float]) -> dict[float, str]:
    """At each error level, the method that reaches it with the fewest evaluations.

    Parameters
    ----------
    points : list of Point
        All points.
    problem : str
        The problem.
    runner : str
        The runner whose methods compete (the FMU's solvers: ``"c"``).
    methods : list of str
        Candidates.
    levels : list of float
        Error levels.

    Returns
    -------
    dict of float to str
        Level -> the cheapest method ("" if none reaches it).
    """
    winners = {}
    for level in levels:
        costs = {m: cost_at(curve(points, problem, runner, m), level) for m in methods}
        name, value = min(costs.items(), key=lambda item: item[1])
        winners[level] = name if math.isfinite(value) else ""
    return winners


LEVELS: tuple[float, ...] = (1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12)
"""The error levels at which the default is ranked and set beside DOP853."""


def against_dop853(points: list[Point], default: str,
                   levels: tuple[float, ...] = LEVELS) -> list[tuple[float, float, float, float]]:
    """The default's evaluations beside DOP853's at each error level on P1.

    Parameters
    ----------
    points : list of Point
        All points (the FMU's from the C driver; scipy's from the Python runs).
    default : str
        The FMU's default solver.
    levels : tuple of float
        Error levels.

    Returns
    -------
    list of (float, float, float, float)
        Per level: the level, the default's evaluations (C driver), ``solve_ivp`` DOP853's and
        ``ode`` dop853's; inf where a method does not reach the level.
    """
    ours = curve(points, "P1", "c", default)
    ivp = curve(points, "P1", "scipy", "DOP853")
    hairer = curve(points, "P1", "scipy", "dop853")
    return [(level, cost_at(ours, level), cost_at(ivp, level), cost_at(hairer, level)) for level in levels]
