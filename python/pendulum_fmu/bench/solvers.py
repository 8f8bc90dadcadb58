"""``pendulum-fmu bench solvers``: the speed-against-error study of the Co-Simulation solvers.

Runs every solver of the FMU and its peers on the same problems and the same output grid,
measures their true error against the FMU's exact solution and their cost, and writes:

- ``runs.csv``: every run (one case, one method, one tolerance);
- ``points.csv``: the runs aggregated per problem (P1: its four amplitudes together);
- ``floors.csv``: the cost of the exact solution at the same points (C driver);
- ``wp_P1.png``, ``wp_P2.png``, ``wp_P3.png``: the work-precision diagrams;
- ``report.md``: the tables, the default's ranking and its cost beside DOP853's.

Problems: P1 75, 80, 85, 90 deg over 10 periods; P2 179.99 deg over 20 periods; P3 90 deg
over 10,000 periods; all from rest, 50 points a period. Methods: the FMU's dopri5, rk4, rkn
and symplectic, through the C driver (``tests/c/bench_solvers``: the model's own cost) and
through fmpy (what a user sees); scipy ``solve_ivp`` RK45, DOP853, LSODA, Radau; scipy
``ode`` dop853; CVODE through fmpy on the FMU's Model Exchange interface; fmpy's fixed-step
forward Euler on it (the baseline: how today's co-simulation FMUs integrate).

A Python run predicted to take longer than ``--budget`` seconds is skipped and listed as
such (on P3 most of the slow peers at tight tolerances); the C driver runs everything.

``pendulum-fmu bench solvers`` runs it (:mod:`pendulum_fmu.cli.bench.solvers` reads its options).
:func:`run_study` returns what it measured (:class:`Study`), for a caller that judges it
further (the repository's ``tests/lab/solver_targets.py`` holds it to the project's targets).
"""

from __future__ import annotations

import math
import shutil
import time
from collections.abc import Callable, Collection
from dataclasses import dataclass
from pathlib import Path

from fmpy import extract, read_model_description

from pendulum_fmu.bench.workprecision.analysis import (
    LEVELS,
    Point,
    against_dop853,
    aggregate,
    best_method,
    curve,
    log_slope,
)
from pendulum_fmu.bench.workprecision.cdriver import Floor, run_driver, shared_library
from pendulum_fmu.bench.workprecision.peers import PEERS, SOLVE_IVP_METHODS
from pendulum_fmu.bench.workprecision.problems import Grid, cases, make_grid
from pendulum_fmu.bench.workprecision.report import cost_table, energy_table, plot_problem, write_csv
from pendulum_fmu.bench.workprecision.runs import (
    Run,
    run_fmu_cs,
    run_fmu_me,
    run_ode_dop853,
    run_solve_ivp,
)
from pendulum_fmu.errors import SimulationError
from pendulum_fmu.spec import CS_SOLVERS

FMU_TOLS: tuple[float, ...] = tuple(float(f"1e-{k}") for k in range(3, 13))
"""Tolerances of the FMU's solvers: 1e-3 .. 1e-12."""
PEER_TOLS: tuple[float, ...] = tuple(float(f"1e-{k}") for k in range(3, 14))
"""Relative tolerances of the peers: 1e-3 .. 1e-13 (DOP853 needs 1e-13 to approach 1e-12)."""
P3_TOLS: tuple[float, ...] = (1e-4, 1e-7, 1e-10)
"""Tolerances of the Python runs on P3 (10,000 periods; the C driver runs all of FMU_TOLS)."""
EULER_STEPS: tuple[int, ...] = (1, 4, 16, 64, 256, 1024)
"""Forward Euler: steps an output interval (50 to 51,200 a period)."""
GROWTH = 3.0
"""A tighter tolerance is predicted to cost at most this many times the previous one."""

TITLES = {"P1": "P1: 75, 80, 85, 90 deg from rest, 10 periods each, 50 points a period",
          "P2": "P2: 179.99 deg from rest, 20 periods, 50 points a period",
          "P3": "P3: 90 deg from rest, {periods:g} periods, 50 points a period"}


class Budget:
    """Predicts a run's wall time from the previous tolerance of the same method and case."""

    def __init__(self, seconds: float) -> None:
        self.seconds = seconds
        self.last: dict[tuple[str, float, str], float] = {}

    def allows(self, case_key: tuple[str, float], method: str, hint: float | None = None) -> bool:
        """Whether to run; ``hint`` is a prediction when there is no previous run."""
        previous = self.last.get((*case_key, method))
        predicted = previous * GROWTH if previous is not None else hint
        return predicted is None or predicted <= self.seconds

    def record(self, case_key: tuple[str, float], method: str, run: Run) -> None:
        """Remembers a run's wall time."""
        if math.isfinite(run.wall_s):
            self.last[(*case_key, method)] = run.wall_s


def _skipped(grid: Grid, runner: str, method: str, tol: float, budget: float) -> Run:
    case = grid.case
    return Run(problem=case.problem, amplitude_deg=case.amplitude_deg, periods=case.periods, runner=runner,
               method=method, tol=tol, status="skipped", note=f"predicted over the budget of {budget:g} s")


def python_runs(unzipped: Path, grid: Grid, tols_fmu: tuple[float, ...], tols_peer: tuple[float, ...],
                euler: tuple[int, ...], budget: Budget, peers: Collection[str],
                hints: dict[tuple[str, str, float], float],
                log: Callable[[str], None]) -> list[Run]:
    """Every Python run of one case: the FMU's solvers through fmpy, then the peers.

    Parameters
    ----------
    unzipped : Path
        The extracted FMU.
    grid : Grid
        Case and output grid.
    tols_fmu, tols_peer : tuple of float
        Tolerances of the FMU's solvers and of the peers.
    euler : tuple of int
        Euler steps per output interval.
    budget : Budget
        Time budget of a run.
    peers : collection of str
        The peers to run, some of :data:`PEERS`.
    hints : dict
        (runner, method, tol) -> a predicted wall time for a first run (from P1 for P3).
    log : callable
        Progress output.

    Returns
    -------
    list of Run
        The runs, skipped ones included.
    """
    case = grid.case
    key = (case.problem, case.amplitude_deg)
    jobs: list[tuple[str, str, float]] = [("fmpy", s, t) for s in CS_SOLVERS for t in tols_fmu]
    jobs += [("scipy", m, t) for m in (*SOLVE_IVP_METHODS, "dop853") if m in peers for t in tols_peer]
    jobs += [("fmpy-me", "cvode", t) for t in tols_fmu if "cvode" in peers]
    jobs += [("fmpy-me", "euler", float(k)) for k in euler if "euler" in peers]
    runs = []
    for runner, method, tol in jobs:
        if not budget.allows(key, method + runner, hints.get((runner, method, tol))):
            runs.append(_skipped(grid, runner, method, tol, budget.seconds))
            continue
        if runner == "fmpy":
            run = run_fmu_cs(unzipped, grid, method, tol)
        elif runner == "scipy":
            run = run_ode_dop853(grid, tol) if method == "dop853" else run_solve_ivp(grid, method, tol)
        else:
            run = run_fmu_me(unzipped, grid, method, tol)
        budget.record(key, method + runner, run)
        runs.append(run)
        log(f"  {case.problem} {case.amplitude_deg:g} deg {runner:7s} {method:10s} tol {tol:<8g} {run.status:6s} "
            f"err {run.max_err:.2e} evals {run.rhs_evaluations:>9} wall {run.wall_s:.3f} s")
    return runs


def report(points: list[Point], floors: list[Floor], default: str, problems: list[str], p3_periods: float,
           quick: bool = False) -> str:
    """The Markdown report: tables per problem, the default's ranking and its cost beside DOP853's
    (a quick run's few tolerances: only at the errors the default reaches)."""
    parts = ["# Speed against error: the FMU's solvers and their peers", "",
             "Cells: right-hand-side evaluations to reach the error (and wall time per simulated period); "
             "'-': not reached. P1 sums its four amplitudes.", ""]
    for problem in problems:
        title = TITLES[problem].format(periods=p3_periods)
        parts += [f"## {title}", "", cost_table(points, problem), ""]
        if problem == "P3":
            parts += ["Energy behaviour (P3):", "", energy_table(points, problem), ""]
    if "P1" in problems:
        ranking = best_method(points, "P1", "c", list(CS_SOLVERS), list(LEVELS))
        parts += ["## The default", "", f"The FMU's default solver is `{default}`. Cheapest of the FMU's solvers "
                  "on P1 at each error level: " + ", ".join(f"{lvl:.0e}: {m or 'none'}" for lvl, m in ranking.items()),
                  ""]
        rows = [row for row in against_dop853(points, default) if not quick or math.isfinite(row[1])]
        if any(math.isfinite(ivp) or math.isfinite(hairer) for _, _, ivp, hairer in rows):  # with the peers
            parts += ["| error | " + default + " | solve_ivp DOP853 | ode dop853 | ratio |", "|---|---|---|---|---|"]
            for level, ours, ivp, hairer in rows:
                best = min(ivp, hairer)
                ratio = f"{ours / best:.2f}" if math.isfinite(best) else "DOP853 does not reach it"
                parts.append(f"| {level:.0e} | {ours:,.0f} | {ivp:,.0f} | {hairer:,.0f} | {ratio} |".replace(",", " "))
            parts.append("")
    return "\n".join(parts)


@dataclass(frozen=True)
class Study:
    """What one run of the study measured (its files are in ``out``).

    Attributes
    ----------
    runs : list of Run
        Every run, skipped and failed ones included.
    points : list of Point
        The runs aggregated per problem, runner, method and tolerance.
    floors : list of Floor
        The exact evaluation's cost at the same points (C driver).
    default : str
        The FMU's default solver.
    problems : list of str
        The problems run.
    report : str
        The Markdown of ``report.md``.
    """

    runs: list[Run]
    points: list[Point]
    floors: list[Floor]
    default: str
    problems: list[str]
    report: str

    @property
    def failed(self) -> list[Run]:
        """The runs whose solver gave up."""
        return [r for r in self.runs if r.status == "failed"]


def run_study(fmu: Path, driver: Path, out: Path, problems: list[str], budget_s: float = 30.0,
              p3_periods: float = 10_000.0, points: int = 50, peers: Collection[str] = PEERS, quick: bool = False,
              log: Callable[[str], None] = lambda line: None) -> Study:
    """Run the study and write its files.

    Parameters
    ----------
    fmu : Path
        The FMI 2.0 Pendulum.fmu.
    driver : Path
        The C driver ``tests/c/bench_solvers`` of a CMake build.
    out : Path
        Output folder, created with its missing parents.
    problems : list of str
        Some of ``P1``, ``P2``, ``P3``.
    budget_s : float
        Skip a Python run predicted to take longer, s.
    p3_periods : float
        Length of P3 in periods.
    points : int
        Output points a period.
    peers : collection of str
        The peers to run beside the FMU's solvers, some of :data:`PEERS` (none: only the FMU's).
    quick : bool
        A smoke run: tolerances 1e-4 and 1e-8, P3 at most 100 periods.
    log : callable
        Takes each line of progress and, last, the report and the summary line.

    Returns
    -------
    Study
        The runs, their points, the floors and the report.

    Raises
    ------
    SimulationError
        If the C driver cannot run.
    """
    fmu_tols, peer_tols, p3_tols, euler = FMU_TOLS, PEER_TOLS, P3_TOLS, EULER_STEPS
    if quick:
        fmu_tols = peer_tols = p3_tols = (1e-4, 1e-8)
        euler = (1, 16)
        p3_periods = min(p3_periods, 100.0)
    out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    unzipped = Path(extract(str(fmu)))
    try:
        md = read_model_description(str(unzipped), validate=False)
        solver_variable = next(v for v in md.modelVariables if v.name == "solver")
        default = CS_SOLVERS[int(solver_variable.start) - 1]
        log(f"bench solvers: FMU {fmu} (default solver {default}), C driver {driver}")

        log("C driver: the FMU's solvers and the exact-evaluation floor ...")
        try:
            c_runs, floors = run_driver(driver, shared_library(unzipped), problems, list(fmu_tols), p3_periods,
                                        points)
        except (RuntimeError, OSError) as error:  # OSError: a file the kernel cannot execute
            raise SimulationError(f"the C driver {driver} failed: {error}") from None
        runs: list[Run] = list(c_runs)
        budget = Budget(budget_s)
        hints: dict[tuple[str, str, float], float] = {}
        for problem in problems:
            for case in cases(problem, p3_periods):
                grid = make_grid(unzipped, case, points)
                log(f"{problem} {case.amplitude_deg:g} deg, {case.periods:g} periods: Python runs ...")
                p3 = problem == "P3"
                new = python_runs(unzipped, grid, p3_tols if p3 else fmu_tols, p3_tols if p3 else peer_tols,
                                  euler[:2] if p3 else euler, budget, peers, hints, log)
                runs += new
                if problem == "P1" and case.amplitude_deg == 90.0:
                    scale = p3_periods / case.periods
                    hints = {(r.runner, r.method, r.tol): r.wall_s * scale for r in new if math.isfinite(r.wall_s)}
        aggregated = aggregate(runs)
        write_csv(out / "runs.csv", runs)
        write_csv(out / "points.csv", aggregated)
        write_csv(out / "floors.csv", floors)
        for problem in problems:
            plot_problem(aggregated, floors, problem, TITLES[problem].format(periods=p3_periods),
                         out / f"wp_{problem}.png")
        consistency = _fmpy_matches_c(aggregated)
        text = report(aggregated, floors, default, problems, p3_periods, quick)
        text += f"\nThe FMU's evaluation counts through fmpy equal the C driver's: {consistency}\n"
        text += f"\nTolerance proportionality of the default on P1 (slope of log error against log tol): " \
                f"{log_slope(curve(aggregated, 'P1', 'c', default)):.2f}\n" if "P1" in problems else ""
        (out / "report.md").write_text(text)
        log(text)
        study = Study(runs, aggregated, floors, default, list(problems), text)
        log(f"bench solvers: {len(runs)} runs ({len(study.failed)} failed, "
            f"{sum(r.status == 'skipped' for r in runs)} skipped over the budget) in "
            f"{time.perf_counter() - started:.0f} s; written to {out}")
        return study
    finally:
        shutil.rmtree(unzipped, ignore_errors=True)


def _fmpy_matches_c(points: list[Point]) -> str:
    """Whether the FMU's counters agree between the fmpy and the C runs (same tolerances)."""
    c = {(p.problem, p.method, p.tol): (p.rhs_evaluations, p.max_err) for p in points if p.runner == "c"}
    pairs = [(c[(p.problem, p.method, p.tol)], (p.rhs_evaluations, p.max_err)) for p in points
             if p.runner == "fmpy" and p.status == "ok" and (p.problem, p.method, p.tol) in c]
    same = sum(a[0] == b[0] for a, b in pairs)
    return f"{same} of {len(pairs)} points"
