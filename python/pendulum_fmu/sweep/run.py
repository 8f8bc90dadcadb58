"""A sweep: a parameter grid run in parallel on Dask, resumable.

By default the runs go to a local cluster of worker processes on this machine; with
``--scheduler tcp://host:port`` they go to any running Dask scheduler and its workers
(which need this package installed). The FMU is sent to every worker once and each worker
loads it once (:mod:`pendulum_fmu.sweep.worker`). Finished runs are appended to
``runs.journal.csv`` as they arrive; a sweep interrupted and started again with the same
``--out`` skips the runs already there (if the FMU is the same one, byte for byte). At the
end the table (CSV or Parquet, in grid order) and three summary plots are written.
"""

from __future__ import annotations

import hashlib
import logging
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendulum_fmu.sweep.cluster import dask_client, execute, worker_threads
from pendulum_fmu.sweep.grid import COLUMN_KINDS, COLUMNS, SweepGrid, point_of

if TYPE_CHECKING:
    import pyarrow as pa

_log = logging.getLogger(__name__)
"""Says a journal is reused or set aside (INFO; the command line shows it on stderr)."""

JOURNAL = "runs.journal.csv"
JOURNAL_FMU = "runs.journal.sha256"
"""The SHA-256 of the FMU that wrote the journal: rows of another FMU are not reused."""


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
    plots : list of Path
        The plots written (none of a sweep in which every run failed).
    """

    rows: list[dict[str, Any]]
    computed: int
    skipped: int
    seconds: float
    workers: int
    table: Path | None = None
    plots: list[Path] = field(default_factory=list)


# -- Dask -------------------------------------------------------------------------------------
# -- the sweep ----------------------------------------------------------------------------------
def run_sweep(fmu: Path, sweep: SweepGrid, out: Path, table_format: str = "csv", scheduler: str | None = None,
              workers: int = 2, progress: bool = True, plots: bool = True) -> SweepOutcome:
    """Run a sweep into ``out``, skipping runs already in its journal.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``, FMI 2.0 or 3.0.
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
        Show the progress bar (on stderr) and log at INFO whether the journal is resumed or set aside.
    plots : bool
        Write the summary plots.

    Returns
    -------
    SweepOutcome
        The rows in grid order and what was done.

    Raises
    ------
    UsageError
        If ``fmu`` is not this project's Pendulum FMU.

    Notes
    -----
    The local cluster starts its workers as new processes (multiprocessing's "spawn"), which
    import the calling script again: call this from a script under
    ``if __name__ == "__main__":``.
    """
    from pendulum_fmu.errors import UsageError
    from pendulum_fmu.fmu.identity import pendulum_problem
    from pendulum_fmu.sweep.journal import Journal, read_journal

    problem = pendulum_problem(fmu)   # before any worker starts: another model would fail every run
    if problem is not None:
        raise UsageError("fmu", problem)
    points = sweep.points()
    journal_path, stamp = out / JOURNAL, out / JOURNAL_FMU
    digest = hashlib.sha256(fmu.read_bytes()).hexdigest()
    same_fmu = stamp.is_file() and stamp.read_text().strip() == digest
    done = read_journal(journal_path) if same_fmu else {}
    if journal_path.is_file() and not same_fmu and progress:
        _log.info("%s was written by another FMU: starting afresh", journal_path)
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
                    _log.info("resuming: %d of %d runs already in %s", skipped, len(points), journal_path)
                seconds = execute(client, fmu, pending, record, progress)
        except KeyboardInterrupt:
            journal.close()
            # What finished is what the journal holds: the interrupt may have come between a
            # batch's append and its bookkeeping in ``done``.
            finished = read_journal(journal_path)
            _write_rows([finished[p.key] for p in points if p.key in finished], out, table_format, fmu)
            raise
        finally:
            journal.close()
    rows = [done[point.key] for point in points]
    table = _write_rows(rows, out, table_format, fmu)
    drawn: list[Path] = []
    if plots:
        from pendulum_fmu.sweep.plots import plot_sweep

        drawn = plot_sweep(rows, out)
    return SweepOutcome(rows, len(pending), skipped, seconds, threads, table, drawn)


def _write_rows(rows: list[dict[str, Any]], out: Path, table_format: str, fmu: Path) -> Path:
    """The sweep's table ``out/sweep.<format>`` of these rows."""
    from pendulum_fmu.output.tables import write_table

    table = out / f"sweep.{table_format}"
    write_table({column: [row[column] for row in rows] for column in COLUMNS}, table,
                {"fmu": str(fmu), "runs": str(len(rows))}, COLUMN_KINDS)
    return table


def read_sweep_table(path: Path) -> pa.Table:
    """Read a sweep's table (or journal) with its column types: CSV or Parquet."""
    from pendulum_fmu.output.tables import read_table

    return read_table(path, COLUMN_KINDS)
