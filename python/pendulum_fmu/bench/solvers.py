"""``pendulum-fmu bench solvers``: the speed-against-error study of the Co-Simulation solvers.

Runs every solver of the FMU and its peers on the same problems and the same output grid,
measures their true error against the FMU's exact solution and their cost, and writes:

- ``runs.csv``: every run (one case, one method, one tolerance);
- ``points.csv``: the runs aggregated per problem (P1: its four amplitudes together);
- ``floors.csv``: the cost of the exact solution at the same points (C driver);
- ``wp_P1.png``, ``wp_P2.png``, ``wp_P3.png``: the work-precision diagrams;
- ``report.md``: the tables, the default's ranking and the targets, each met or not.

Problems: P1 75, 80, 85, 90 deg over 10 periods; P2 179.99 deg over 20 periods; P3 90 deg
over 10,000 periods; all from rest, 50 points a period. Methods: the FMU's dopri5, rk4, rkn
and symplectic, through the C driver (``tests/c/bench_solvers``: the model's own cost) and
through fmpy (what a user sees); scipy ``solve_ivp`` RK45, DOP853, LSODA, Radau; scipy
``ode`` dop853; CVODE through fmpy on the FMU's Model Exchange interface; fmpy's fixed-step
forward Euler on it (the baseline: how today's co-simulation FMUs integrate).

A Python run predicted to take longer than ``--budget`` seconds is skipped and listed as
such (on P3 most of the slow peers at tight tolerances); the C driver runs everything.

Usage::

    pendulum-fmu bench solvers [--out out/bench] [--problems P1,P2,P3] [--quick]
    python -m pendulum_fmu.bench.solvers ...
"""

from __future__ import annotations

import argparse
import math
import os
import shutil
import sys
import time
from pathlib import Path
from typing import Callable

from fmpy import extract, read_model_description

from pendulum_fmu.errors import BuildError, UsageError
from pendulum_fmu.fmu.identity import fmi_version_of
from pendulum_fmu.fmu.locate import locate_fmu
from pendulum_fmu.output.paths import OutputError, check_output_folder
from pendulum_fmu.bench.workprecision.analysis import Point, aggregate, best_method, curve, log_slope
from pendulum_fmu.bench.workprecision.cdriver import Floor, find_driver, run_driver, shared_library
from pendulum_fmu.bench.workprecision.problems import Grid, cases, make_grid
from pendulum_fmu.bench.workprecision.report import cost_table, energy_table, plot_problem, write_csv
from pendulum_fmu.bench.workprecision.runs import (FMU_SOLVERS, SOLVE_IVP_METHODS, Run, run_fmu_cs, run_fmu_me, run_ode_dop853,
                      run_solve_ivp)
from pendulum_fmu.bench.workprecision.targets import (T1_LEVELS, Verdict, default_near_separatrix, default_vs_dop853, fmpy_against_dop853,
                         grid_independence, wall_against_floor)

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


def build_parser() -> argparse.ArgumentParser:
    """The command's options (``pendulum-fmu bench solvers --help``)."""
    parser = argparse.ArgumentParser(
        prog="pendulum-fmu bench solvers",
        description=(__doc__ or "").split("Usage::")[0].replace("``", ""),
        epilog="examples:\n  pendulum-fmu bench solvers --quick                # about 30 s\n"
               "  pendulum-fmu bench solvers --out out/bench       # the full study, about 6 min on 2 cores\n"
               "  pendulum-fmu bench solvers --problems P1 --no-peers\n",
        formatter_class=_HelpFormatter)
    parser.add_argument("--fmu", type=Path, default=None, metavar="PATH",
                        help="the FMU (default: $PENDULUM_FMU, the installed one, or the repository's build/)")
    parser.add_argument("--driver", type=Path, default=None, metavar="PATH",
                        help="the C driver tests/c/bench_solvers (default: in the FMU's CMake build)")
    parser.add_argument("--out", type=Path, default=Path("out") / "bench", metavar="DIR",
                        help="output folder, created with its missing parents")
    parser.add_argument("--problems", default="P1,P2,P3", help="comma-separated subset of P1,P2,P3")
    parser.add_argument("--budget", type=float, default=30.0,
                        help="skip a Python run predicted to take longer, seconds")
    parser.add_argument("--p3-periods", type=float, default=10_000.0, help="length of P3 in periods")
    parser.add_argument("--points", type=int, default=50, help="output points a period")
    parser.add_argument("--no-peers", action="store_true", help="only the FMU's solvers")
    parser.add_argument("--quick", action="store_true",
                        help="a smoke run: tolerances 1e-4 and 1e-8, P3 100 periods, no targets 2 and 4")
    return parser


class _HelpFormatter(argparse.RawDescriptionHelpFormatter, argparse.ArgumentDefaultsHelpFormatter):
    """Keep the description's lines and show every default that is not None or False."""

    def _get_help_string(self, action: argparse.Action) -> str | None:
        if action.default is None or action.default is False:
            return action.help
        return super()._get_help_string(action)


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
                euler: tuple[int, ...], budget: Budget, peers: bool, hints: dict[tuple[str, str, float], float],
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
    peers : bool
        Also run the peers.
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
    jobs: list[tuple[str, str, float]] = [("fmpy", s, t) for s in FMU_SOLVERS for t in tols_fmu]
    if peers:
        jobs += [("scipy", m, t) for m in (*SOLVE_IVP_METHODS, "dop853") for t in tols_peer]
        jobs += [("fmpy-me", "cvode", t) for t in tols_fmu]
        jobs += [("fmpy-me", "euler", float(k)) for k in euler]
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


def _markdown_targets(verdicts: list[Verdict]) -> str:
    lines = ["| target | met | measured |", "|---|---|---|"]
    lines += [f"| {v.name} | {'yes' if v.met else 'NO'} | {v.figure} |" for v in verdicts]
    return "\n".join(lines)


def report(points: list[Point], floors: list[Floor], verdicts: list[Verdict],
           t1_rows: list[tuple[float, float, float, float]], default: str, problems: list[str],
           p3_periods: float) -> str:
    """The Markdown report: tables per problem, the default's ranking, the targets."""
    parts = ["# Speed against error: the FMU's solvers and their peers", "",
             "Cells: right-hand-side evaluations to reach the error (and wall time per simulated period); "
             "'-': not reached. P1 sums its four amplitudes.", ""]
    for problem in problems:
        title = TITLES[problem].format(periods=p3_periods)
        parts += [f"## {title}", "", cost_table(points, problem), ""]
        if problem == "P3":
            parts += ["Energy behaviour (P3):", "", energy_table(points, problem), ""]
    if "P1" in problems:
        ranking = best_method(points, "P1", "c", list(FMU_SOLVERS), list(T1_LEVELS))
        parts += ["## The default", "", f"The FMU's default solver is `{default}`. Cheapest of the FMU's solvers "
                  "on P1 at each error level: " + ", ".join(f"{lvl:.0e}: {m or 'none'}" for lvl, m in ranking.items()),
                  ""]
        parts += ["| error | " + default + " | solve_ivp DOP853 | ode dop853 | ratio |", "|---|---|---|---|---|"]
        for level, ours, ivp, hairer in t1_rows:
            best = min(ivp, hairer)
            ratio = f"{ours / best:.2f}" if math.isfinite(best) else "DOP853 does not reach it"
            parts.append(f"| {level:.0e} | {ours:,.0f} | {ivp:,.0f} | {hairer:,.0f} | {ratio} |".replace(",", " "))
        parts.append("")
    parts += ["## Targets", "", _markdown_targets(verdicts), ""]
    return "\n".join(parts)


def main(argv: list[str] | None = None) -> int:
    """Run the study.

    Parameters
    ----------
    argv : list of str, optional
        Arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        0 when every target is met, 1 when one is not or a run failed, 2 on bad usage.
    """
    args = build_parser().parse_args(argv)
    problems = [p.strip() for p in args.problems.split(",") if p.strip()]
    if not problems or any(p not in ("P1", "P2", "P3") for p in problems):
        print(f"bench solvers: --problems must name P1, P2 and/or P3, got {args.problems!r}", file=sys.stderr)
        return 2
    try:
        fmu = locate_fmu(args.fmu)
        check_output_folder(args.out)
        if fmi_version_of(fmu) != 2:
            raise UsageError("--fmu", f"{str(fmu)!r} is an FMI 3.0 FMU: bench solvers drives the FMI 2.0 API from "
                                      "its C driver, give the FMI 2.0 Pendulum.fmu")
    except (UsageError, BuildError, OutputError) as error:
        print(f"pendulum-fmu bench solvers: error: {error}", file=sys.stderr)
        return 2
    driver = args.driver or find_driver(fmu)
    if driver is None or not driver.is_file():
        print("pendulum-fmu bench solvers: error: the C driver tests/c/bench_solvers is not installed with the "
              "package: run it from a source checkout after cmake --build build, or give --driver", file=sys.stderr)
        return 2
    if not os.access(driver, os.X_OK):
        print(f"pendulum-fmu bench solvers: error: argument --driver: {str(driver)!r} is not an executable file: "
              "give the C driver tests/c/bench_solvers of a CMake build", file=sys.stderr)
        return 2
    fmu_tols, peer_tols, p3_tols, euler = FMU_TOLS, PEER_TOLS, P3_TOLS, EULER_STEPS
    p3_periods = args.p3_periods
    if args.quick:
        fmu_tols = peer_tols = p3_tols = (1e-4, 1e-8)
        euler = (1, 16)
        p3_periods = min(p3_periods, 100.0)
    out: Path = args.out
    out.mkdir(parents=True, exist_ok=True)
    log = print
    started = time.perf_counter()
    unzipped = Path(extract(str(fmu)))
    try:
        md = read_model_description(str(unzipped), validate=False)
        solver_variable = next(v for v in md.modelVariables if v.name == "solver")
        default = FMU_SOLVERS[int(solver_variable.start) - 1]
        log(f"bench solvers: FMU {fmu} (default solver {default}), C driver {driver}")

        log("C driver: the FMU's solvers and the exact-evaluation floor ...")
        try:
            c_runs, floors = run_driver(driver, shared_library(unzipped), problems, list(fmu_tols), p3_periods,
                                        args.points)
        except (RuntimeError, OSError) as error:  # OSError: a file the kernel cannot execute
            print(f"pendulum-fmu bench solvers: error: the C driver {driver} failed: {error}", file=sys.stderr)
            return 1
        runs: list[Run] = list(c_runs)
        budget = Budget(args.budget)
        hints: dict[tuple[str, str, float], float] = {}
        for problem in problems:
            for case in cases(problem, p3_periods):
                grid = make_grid(unzipped, case, args.points)
                log(f"{problem} {case.amplitude_deg:g} deg, {case.periods:g} periods: Python runs ...")
                p3 = problem == "P3"
                new = python_runs(unzipped, grid, p3_tols if p3 else fmu_tols, p3_tols if p3 else peer_tols,
                                  euler[:2] if p3 else euler, budget, not args.no_peers, hints, log)
                runs += new
                if problem == "P1" and case.amplitude_deg == 90.0:
                    scale = p3_periods / case.periods
                    hints = {(r.runner, r.method, r.tol): r.wall_s * scale for r in new if math.isfinite(r.wall_s)}
        points = aggregate(runs)
        write_csv(out / "runs.csv", runs)
        write_csv(out / "points.csv", points)
        write_csv(out / "floors.csv", floors)
        for problem in problems:
            plot_problem(points, floors, problem, TITLES[problem].format(periods=p3_periods), out / f"wp_{problem}.png")

        verdicts: list[Verdict] = []
        t1_rows: list[tuple[float, float, float, float]] = []
        if "P1" in problems and not args.no_peers:
            # --quick runs tolerances 1e-4 and 1e-8 only: target 1 is judged at the errors they reach.
            verdict, t1_rows = default_vs_dop853(points, default, reachable_only=args.quick)
            verdicts.append(verdict)
        if "P1" in problems:
            verdicts.append(wall_against_floor(points, floors, default)[0])
        if "P2" in problems:
            verdicts.append(default_near_separatrix(points, default)[0])
        if not args.quick:
            log("targets 2 and 4 ...")
            verdicts.append(fmpy_against_dop853(fmu, unzipped)[0])
            verdicts.append(grid_independence(unzipped)[0])
        consistency = _fmpy_matches_c(points)
        text = report(points, floors, verdicts, t1_rows, default, problems, p3_periods)
        text += f"\nThe FMU's evaluation counts through fmpy equal the C driver's: {consistency}\n"
        text += f"\nTolerance proportionality of the default on P1 (slope of log error against log tol): " \
                f"{log_slope(curve(points, 'P1', 'c', default)):.2f}\n" if "P1" in problems else ""
        (out / "report.md").write_text(text)
        log(text)
        failed = [r for r in runs if r.status == "failed"]
        log(f"bench solvers: {len(runs)} runs ({len(failed)} failed, "
            f"{sum(r.status == 'skipped' for r in runs)} skipped over the budget) in "
            f"{time.perf_counter() - started:.0f} s; written to {out}")
        return 0 if all(v.met for v in verdicts) and not failed else 1
    finally:
        shutil.rmtree(unzipped, ignore_errors=True)


def _fmpy_matches_c(points: list[Point]) -> str:
    """Whether the FMU's counters agree between the fmpy and the C runs (same tolerances)."""
    c = {(p.problem, p.method, p.tol): (p.rhs_evaluations, p.max_err) for p in points if p.runner == "c"}
    pairs = [(c[(p.problem, p.method, p.tol)], (p.rhs_evaluations, p.max_err)) for p in points
             if p.runner == "fmpy" and p.status == "ok" and (p.problem, p.method, p.tol) in c]
    same = sum(a[0] == b[0] for a, b in pairs)
    return f"{same} of {len(pairs)} points"


if __name__ == "__main__":
    sys.exit(main())
