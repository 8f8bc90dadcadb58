"""``pendulum-fmu sweep``: the command line of :mod:`pendulum_fmu.sweep.run` (what a sweep
does, where it runs and how it resumes is told there); this module reads the arguments and
prints the outcome."""

from __future__ import annotations

import argparse
import math
import re
import sys

from pendulum_fmu.cli.arguments import (
    add_fmu_argument,
    angle_degrees,
    describe,
    finite,
    grid,
    integer,
    output_folder,
    positive,
    solver_list,
    tolerance,
)
from pendulum_fmu.cli.extras import require_extra
from pendulum_fmu.errors import UsageError
from pendulum_fmu.spec import CS_SOLVERS, DEFAULT_CS_SOLVER, ME_SOLVERS
from pendulum_fmu.sweep.grid import SweepGrid

NAME = "sweep"
HELP = "a parameter grid run in parallel on Dask: period, max error and cost of every run"
DESCRIPTION = """\
Run every combination of the given amplitudes, initial velocities, lengths, gravities,
solvers and tolerances, in parallel on Dask, and write one row per run (the FMU's exact
period, the measured period, the largest error against the exact solution, the solver's
steps and right-hand-side evaluations, the wall time) to a table, with summary plots.

Each axis takes comma-separated values and start:stop:count ranges (count points, both
ends included): --amplitudes 75:90:16 or --amplitudes 10,45,75:90:4.
"""
EPILOG = """\
examples:
  pendulum-fmu sweep --amplitudes 1:179:100 --solvers dopri5,rkn,rk4,cvode --out out/sweep
  pendulum-fmu sweep -a 75:90:4 --tolerances 1e-4,1e-6,1e-8,1e-10 --format parquet
  pendulum-fmu sweep -a 10:170:50 --scheduler tcp://10.0.0.5:8786     # a running Dask scheduler
an interrupted sweep (Ctrl-C) is resumed by running the same command again.
"""

_ADDRESS = re.compile(r"^(tcp|tls|ucx|ws|wss|inproc)://[^\s/]+$")


def scheduler_address(text: str) -> str:
    """argparse type: a Dask scheduler address such as ``tcp://127.0.0.1:8786``."""
    if not _ADDRESS.match(text):
        raise argparse.ArgumentTypeError(f"must be a Dask scheduler address like tcp://host:8786, got {text!r}")
    return text


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``sweep``."""
    axes = parser.add_argument_group("grid (comma-separated values and start:stop:count ranges)")
    axes.add_argument("-a", "--amplitudes", type=grid(angle_degrees), default=[75.0], metavar="ANGLES",
                      help="initial angles in [-180, 180] deg (suffix rad for radians) (default 75)")
    axes.add_argument("-w", "--omega0", type=grid(finite("rad/s")), default=[0.0], metavar="RAD_S",
                      help="initial angular velocities, rad/s (default 0)")
    axes.add_argument("-L", "--lengths", type=grid(positive("m")), default=[1.0], metavar="M",
                      help="lengths > 0, m (default 1)")
    axes.add_argument("-g", "--gravities", type=grid(positive("m/s^2")), default=[9.81], metavar="M_S2",
                      help="gravitational accelerations > 0, m/s^2 (default 9.81)")
    axes.add_argument("-s", "--solvers", type=solver_list, default=[DEFAULT_CS_SOLVER], metavar="NAMES",
                      help=f"{', '.join(CS_SOLVERS)} (Co-Simulation) and {', '.join(ME_SOLVERS)} (Model Exchange) "
                           f"(default {DEFAULT_CS_SOLVER})")
    axes.add_argument("-t", "--tolerances", type=grid(tolerance), default=[1e-8], metavar="RTOLS",
                      help="relative tolerances in (0, 1) (default 1e-8)")
    runs = parser.add_argument_group("every run")
    runs.add_argument("-p", "--periods", type=positive("periods", 1e4), default=10.0,
                      help="stop time in exact periods, in (0, 10000] (default 10)")
    runs.add_argument("-n", "--points-per-period", type=integer(1, 10_000), default=50, metavar="N",
                      help="output points per period, where the error is measured, 1-10000 (default 50)")
    where = parser.add_argument_group("where")
    where.add_argument("--scheduler", type=scheduler_address, default=None, metavar="ADDRESS",
                       help="a running Dask scheduler, e.g. tcp://127.0.0.1:8786 (default: a local cluster)")
    where.add_argument("-j", "--workers", type=integer(1, 256), default=None, metavar="N",
                       help="worker processes of the local cluster, 1-256 (default: the number of CPUs)")
    output = parser.add_argument_group("output")
    output.add_argument("-o", "--out", type=output_folder, default="out/sweep", metavar="DIR",
                        help="output folder; rerunning into the same folder resumes (default out/sweep)")
    output.add_argument("-f", "--format", choices=("csv", "parquet"), default="csv", help="table format (default csv)")
    output.add_argument("--no-plots", action="store_true", help="write the table only")
    output.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    add_fmu_argument(parser)


def runs_text(count: int) -> str:
    """``1 run``, ``2 runs``."""
    return f"{count} run" if count == 1 else f"{count} runs"


def periods_text(count: float) -> str:
    """``period`` for exactly 1, else ``periods``."""
    return "period" if count == 1 else "periods"


def grid_from(args: argparse.Namespace) -> SweepGrid:
    """The :class:`SweepGrid` of parsed sweep options."""
    return SweepGrid(tuple(args.amplitudes), tuple(args.omega0), tuple(args.lengths),
                     tuple(args.gravities), tuple(args.solvers), tuple(args.tolerances), args.periods,
                     args.points_per_period)


def run(args: argparse.Namespace) -> int:
    """Run ``sweep`` with parsed arguments."""
    import os

    require_extra("sweep", "sweep")

    if args.scheduler is not None and args.workers is not None:
        raise UsageError("--workers", "sets the size of the local cluster: not allowed with --scheduler")
    from pendulum_fmu.sizing import SLOW_SECONDS, check_sweep, duration_text

    sweep = grid_from(args)
    total = len(sweep)
    workers = args.workers or os.cpu_count() or 1
    seconds = check_sweep(total, math.ceil(args.periods * args.points_per_period) + 1,
                          1 if args.scheduler else workers)  # refused at once when it cannot fit
    fmu = args.fmu
    print(f"sweep of {runs_text(total)}: amplitude {describe(sweep.amplitudes_deg, ' deg')}, "
          f"omega0 {describe(sweep.omega0s, ' rad/s')}, L {describe(sweep.lengths, ' m')}, "
          f"g {describe(sweep.gravities, ' m/s^2')}, solvers {', '.join(sweep.solvers)}, "
          f"tolerance {describe(sweep.tolerances)}; {sweep.periods:g} {periods_text(sweep.periods)} each"
          + (f"; about {duration_text(seconds)} on {workers} worker processes" if seconds > SLOW_SECONDS
             and args.scheduler is None else ""), flush=True)
    from pendulum_fmu.output.paths import make_output_folder
    from pendulum_fmu.sweep.cluster import check_scheduler
    from pendulum_fmu.sweep.run import run_sweep

    if args.scheduler is not None:
        check_scheduler(args.scheduler)  # nothing listening: one line at once, and no folder made
    make_output_folder(args.out)
    outcome = run_sweep(fmu, sweep, args.out, args.format, args.scheduler, workers,
                        progress=not args.quiet, plots=not args.no_plots)
    failed = sum(1 for row in outcome.rows if row["status"] != "ok")
    if outcome.computed:
        n = outcome.workers
        where = (f"{n} worker thread{'s' * (n != 1)} of the scheduler" if args.scheduler is not None
                 else f"{n} worker process{'es' * (n != 1)}")  # the local cluster: one thread a process
        print(f"computed {runs_text(outcome.computed)} in {outcome.seconds:.2f} s on {where} "
              f"({outcome.computed / outcome.seconds:.1f} runs/s); {outcome.skipped} already done")
    else:
        print(f"all {runs_text(outcome.skipped)} already done")
    if failed:
        reasons = sorted({str(row["status"]).removeprefix("failed: ") for row in outcome.rows if row["status"] != "ok"})
        every = "every run failed" if failed == len(outcome.rows) else f"{runs_text(failed)} failed"
        print(f"{every} (see the status column), e.g.: {reasons[0]}", file=sys.stderr)
    warned = [row["fmu_warning"] for row in outcome.rows if row.get("fmu_warning")]
    if warned:
        print(f"warning: the FMU warned in {runs_text(len(warned))} (column fmu_warning), e.g. {warned[0]}",
              file=sys.stderr)
    plots = ", ".join(path.name for path in outcome.plots)
    print(f"written   {outcome.table}" + (f" and {plots} in {args.out}" if plots else
                                          "" if args.no_plots else " (no plots: no run has an error to show)"))
    return 1 if failed else 0
