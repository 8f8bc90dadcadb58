"""``pendulum-fmu sweep``: a parameter grid run in parallel on Dask, resumable.

By default the runs go to a local cluster of worker processes on this machine; with
``--scheduler tcp://host:port`` they go to any running Dask scheduler and its workers
(which need this package installed). The FMU is sent to every worker once and each worker
loads it once (:mod:`pendulum_fmu.sweep_worker`). Finished runs are appended to
``runs.journal.csv`` as they arrive; a sweep interrupted and started again with the same
``--out`` skips the runs already there (if the FMU is the same one, byte for byte). At the end the table (CSV or Parquet, in grid
order) and three summary plots are written.
"""

from __future__ import annotations

import argparse
import hashlib
import logging
import math
import re
import sys
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from .arguments import add_fmu_argument, angle_degrees, describe, finite, grid, integer, positive, solver_list, tolerance
from .errors import UsageError
from .locate import locate_fmu
from .spec import DEFAULT_CS_SOLVER
from .sweep_grid import COLUMN_KINDS, COLUMNS, SweepGrid, SweepPoint, point_of

if TYPE_CHECKING:
    import pyarrow as pa
    from distributed import Client

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

TASKS_PER_THREAD = 8
MAX_BATCH = 64
JOURNAL = "runs.journal.csv"
JOURNAL_FMU = "runs.journal.sha256"
"""The SHA-256 of the FMU that wrote the journal: rows of another FMU are not reused."""
_ADDRESS = re.compile(r"^(tcp|tls|ucx|ws|wss|inproc)://[^\s/]+$")


@dataclass
class SweepOutcome:
    """What a sweep did.

    Attributes
    ----------
    rows : list of dict
        One row per grid point, in grid order.
    computed : int
        Runs computed now.
    skipped : int
        Runs found already written in the journal.
    seconds : float
        Wall time of the computed runs, from submission to the last result.
    workers : int
        Worker threads that ran them (0 if nothing was computed).
    table : Path or None
        The table written.
    """

    rows: list[dict[str, Any]]
    computed: int
    skipped: int
    seconds: float
    workers: int
    table: Path | None = None


# -- Dask -------------------------------------------------------------------------------------
def scheduler_address(text: str) -> str:
    """argparse type: a Dask scheduler address such as ``tcp://127.0.0.1:8786``."""
    if not _ADDRESS.match(text):
        raise argparse.ArgumentTypeError(f"must be a Dask scheduler address like tcp://host:8786, got {text!r}")
    return text


@contextmanager
def dask_client(scheduler: str | None = None, workers: int = 2) -> Iterator[Client]:
    """A Dask client: on ``scheduler`` if given, else on a new local cluster of processes.

    Parameters
    ----------
    scheduler : str, optional
        Address of a running scheduler (``tcp://host:port``).
    workers : int
        Worker processes of the local cluster (one thread each: fmpy's loop holds the GIL).

    Yields
    ------
    distributed.Client
        Connected, with at least one worker.

    Raises
    ------
    UsageError
        If the scheduler cannot be reached or has no worker.
    """
    from distributed import Client, LocalCluster

    if scheduler is None:
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                               silence_logs=logging.ERROR)
        client = Client(cluster)
        try:
            yield client
        finally:
            client.close()
            cluster.close()
        return
    try:
        client = Client(scheduler, timeout="10s")
    except (OSError, TimeoutError) as error:
        raise UsageError("--scheduler", f"cannot reach a Dask scheduler at {scheduler}: {error}") from None
    try:
        try:
            client.wait_for_workers(1, timeout=30)
        except TimeoutError:
            raise UsageError("--scheduler", f"the scheduler at {scheduler} has no worker (waited 30 s)") from None
        yield client
    finally:
        client.close()


def worker_threads(client: Client) -> int:
    """Total worker threads behind a client."""
    return max(1, sum(client.nthreads().values()))


def batches(points: Sequence[SweepPoint], threads: int, batch_size: int | None = None) -> list[list[SweepPoint]]:
    """Split points into tasks of about equal cost: about 8 per worker thread, at most 64 runs each.

    The points are dealt out like cards (task i gets points i, i + n, i + 2n, ...), so each
    task holds amplitudes from the whole range, costs about the same as the others, and the
    last tasks of a sweep finish together instead of one straggler holding it up.

    Parameters
    ----------
    points : sequence of SweepPoint
        The runs.
    threads : int
        Worker threads that will run them.
    batch_size : int, optional
        Runs per task instead of the default.

    Returns
    -------
    list of list of SweepPoint
        Every point exactly once; the tasks' sizes differ by at most one.
    """
    if not points:
        return []
    size = batch_size or MAX_BATCH
    tasks = max(math.ceil(len(points) / size), 1 if batch_size else min(len(points), TASKS_PER_THREAD * threads))
    return [list(points[i::tasks]) for i in range(tasks)]


def execute(client: Client, fmu: Path, points: Sequence[SweepPoint],
            on_rows: Callable[[list[dict[str, Any]]], None] = lambda rows: None, progress: bool = True,
            batch_size: int | None = None) -> float:
    """Run points on the client's workers; hand each finished batch's rows to ``on_rows``.

    Parameters
    ----------
    client : distributed.Client
        Connected client.
    fmu : Path
        The FMU, sent to every worker once.
    points : sequence of SweepPoint
        The runs.
    on_rows : callable
        Called in the client with every batch's rows as it finishes (any order).
    progress : bool
        Show a progress bar (runs done, rate, time left) on stderr.
    batch_size : int, optional
        Runs per task (default: about 8 tasks per worker thread, at most 64 runs each).

    Returns
    -------
    float
        Seconds from the first submission to the last result.
    """
    from distributed import as_completed
    from tqdm import tqdm

    from .sweep_worker import run_points, warm

    data = fmu.read_bytes()
    client.run(warm, data)  # every worker loads the FMU now, not inside the timed first task
    # A key of its own (hash=False): a second sweep on the same client must not reuse the key of
    # the first one's data, which the scheduler may be releasing at that moment.
    shared = client.scatter(data, broadcast=True, hash=False)
    start = time.perf_counter()
    futures = [client.submit(run_points, shared, batch, pure=False)
               for batch in batches(points, worker_threads(client), batch_size)]
    bar = tqdm(total=len(points), unit="run", desc="sweep", disable=not progress, file=sys.stderr,
               dynamic_ncols=True, smoothing=0.05)
    try:
        for future in as_completed(futures):
            rows = future.result()
            on_rows(rows)
            bar.update(len(rows))
    except BaseException:
        client.cancel(futures)
        raise
    finally:
        bar.close()
    return time.perf_counter() - start


# -- the sweep ----------------------------------------------------------------------------------
def run_sweep(fmu: Path, sweep: SweepGrid, out: Path, table_format: str = "csv", scheduler: str | None = None,
              workers: int = 2, progress: bool = True, plots: bool = True) -> SweepOutcome:
    """Run a sweep into ``out``, skipping runs already in its journal.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.
    sweep : SweepGrid
        The grid.
    out : Path
        Output folder: ``runs.journal.csv``, ``sweep.csv`` (or ``.parquet``) and the plots.
    table_format : {"csv", "parquet"}
        Format of the final table.
    scheduler : str, optional
        A running Dask scheduler's address; default a local cluster of ``workers`` processes.
    workers : int
        Local worker processes.
    progress : bool
        Show the progress bar.
    plots : bool
        Write the summary plots.

    Returns
    -------
    SweepOutcome
        The rows in grid order and what was done.

    Notes
    -----
    The local cluster starts its workers as new processes (multiprocessing's "spawn"), which
    import the calling script again: call this from a script under
    ``if __name__ == "__main__":``.
    """
    from .journal import Journal, read_journal
    from .tables import write_table

    points = sweep.points()
    journal_path, stamp = out / JOURNAL, out / JOURNAL_FMU
    digest = hashlib.sha256(fmu.read_bytes()).hexdigest()
    same_fmu = stamp.is_file() and stamp.read_text().strip() == digest
    done = read_journal(journal_path) if same_fmu else {}
    if journal_path.is_file() and not same_fmu and progress:
        print(f"{journal_path} was written by another FMU: starting afresh", file=sys.stderr)
    pending = [point for point in points if point.key not in done]
    skipped = len(points) - len(pending)
    seconds, threads = 0.0, 0
    if pending:
        journal = Journal(journal_path, keep=done.values(), restart=not same_fmu)
        stamp.write_text(digest + "\n")
        try:
            def record(rows: list[dict[str, Any]]) -> None:
                journal.append(rows)
                for row in rows:
                    done[point_of(row).key] = row

            with dask_client(scheduler, workers) as client:
                threads = worker_threads(client)
                if skipped and progress:
                    print(f"resuming: {skipped} of {len(points)} runs already in {journal_path}", file=sys.stderr)
                seconds = execute(client, fmu, pending, record, progress)
        finally:
            journal.close()
    rows = [done[point.key] for point in points]
    table = out / f"sweep.{table_format}"
    write_table({column: [row[column] for row in rows] for column in COLUMNS}, table,
                {"fmu": str(fmu), "runs": str(len(rows))}, COLUMN_KINDS)
    if plots:
        from .sweep_plots import plot_sweep

        plot_sweep(rows, out)
    return SweepOutcome(rows, len(pending), skipped, seconds, threads, table)


def read_sweep_table(path: Path) -> pa.Table:
    """Read a sweep's table (or journal) with its column types: CSV or Parquet."""
    from .tables import read_table

    return read_table(path, COLUMN_KINDS)


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
                      help="dopri5, rk4, rkn, symplectic (Co-Simulation) and cvode (Model Exchange) "
                           "(default rkn)")
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
    output.add_argument("-o", "--out", type=Path, default=Path("out/sweep"), metavar="DIR",
                        help="output folder; rerunning into the same folder resumes (default out/sweep)")
    output.add_argument("-f", "--format", choices=("csv", "parquet"), default="csv", help="table format (default csv)")
    output.add_argument("--no-plots", action="store_true", help="write the table only")
    output.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    add_fmu_argument(parser)


def grid_from(args: argparse.Namespace) -> SweepGrid:
    """The :class:`SweepGrid` of parsed sweep options."""
    return SweepGrid(tuple(args.amplitudes), tuple(args.omega0), tuple(args.lengths),
                     tuple(args.gravities), tuple(args.solvers), tuple(args.tolerances), args.periods,
                     args.points_per_period)


def run(args: argparse.Namespace) -> int:
    """Run ``sweep`` with parsed arguments."""
    import os

    if args.scheduler is not None and args.workers is not None:
        raise UsageError("--workers", "sets the size of the local cluster: not allowed with --scheduler")
    sweep = grid_from(args)
    if args.out.exists() and not args.out.is_dir():
        raise UsageError("--out", f"{str(args.out)!r} is a file: give a folder")
    fmu = locate_fmu(args.fmu)
    total = len(sweep)
    print(f"sweep of {total} runs: amplitude {describe(sweep.amplitudes_deg, ' deg')}, "
          f"omega0 {describe(sweep.omega0s, ' rad/s')}, L {describe(sweep.lengths, ' m')}, "
          f"g {describe(sweep.gravities, ' m/s^2')}, solvers {', '.join(sweep.solvers)}, "
          f"tolerance {describe(sweep.tolerances)}; {sweep.periods:g} periods each")
    outcome = run_sweep(fmu, sweep, args.out, args.format, args.scheduler, args.workers or os.cpu_count() or 1,
                        progress=not args.quiet, plots=not args.no_plots)
    failed = sum(1 for row in outcome.rows if row["status"] != "ok")
    if outcome.computed:
        print(f"computed {outcome.computed} runs in {outcome.seconds:.2f} s on {outcome.workers} worker threads "
              f"({outcome.computed / outcome.seconds:.1f} runs/s); {outcome.skipped} already done")
    else:
        print(f"all {outcome.skipped} runs already done")
    if failed:
        print(f"{failed} runs failed: see the status column", file=sys.stderr)
    print(f"written   {outcome.table}" + ("" if args.no_plots else f" and the plots sweep_*.png in {args.out}"))
    return 1 if failed else 0
