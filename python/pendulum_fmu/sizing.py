"""The size of a piece of work, estimated before it starts: output points, memory, runs, time.

A command that is asked for more than the machine can hold refuses at once, in one line
that says how much it would be and what to change, instead of failing after minutes (or
printing nothing for minutes). The figures per point and per run are measured on this
project's FMU (``pendulum-fmu bench speed``) and rounded up; they are estimates for a
refusal and a progress hint, not promises.
"""

from __future__ import annotations

import logging
import os
from pathlib import Path
from typing import TYPE_CHECKING

from pendulum_fmu.errors import UsageError
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid

if TYPE_CHECKING:
    from pendulum_fmu.fmu.runner import FmuRunner, Trajectory

_log = logging.getLogger(__name__)
"""Says a long run's size and estimate before it starts (INFO; the command line shows it on stderr)."""

BYTES_PER_POINT = 256
"""Memory per output point of one run: the recorded values, the result table, the time list
(Python floats) and the copies a table writer or a plot makes (7 columns of 8 bytes, a few times)."""
SECONDS_PER_POINT = 3e-6
"""Wall time per output point of a Co-Simulation run at the default tolerance (rounded up)."""
BYTES_PER_SWEEP_RUN = 4096
"""Memory per sweep run kept by the client: the grid point, its row (about 25 values) and the journal's copy."""
SECONDS_PER_SWEEP_RUN = 3e-3
"""Wall time per sweep run besides its points: the reset, initialization and the row."""
MEMORY_SHARE = 0.5
"""Share of the memory available now that one command may plan to use."""
MAX_SECONDS = 7 * 24 * 3600.0
"""Longest work accepted (one week on this machine's speed)."""
SLOW_SECONDS = 3.0
"""Work estimated longer than this says so before it starts."""


def available_memory() -> int:
    """Bytes of memory available to a new allocation now (``MemAvailable``; else the physical memory)."""
    try:
        for line in Path("/proc/meminfo").read_text().splitlines():
            if line.startswith("MemAvailable:"):
                return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_PAGE_SIZE")) * int(os.sysconf("SC_PHYS_PAGES"))
    except (OSError, ValueError, AttributeError):
        return 8 * 1024 ** 3


def quantity(count: float) -> str:
    """``4.5e9`` as ``4.5 billion``, ``25,000`` as ``25,000``."""
    if count >= 1e9:
        return f"{count / 1e9:.3g} billion"
    if count >= 1e6:
        return f"{count / 1e6:.3g} million"
    return f"{count:,.0f}"


def size_text(count: float) -> str:
    """Bytes as ``1.2 GB``, ``340 MB``, ``12 kB``."""
    for unit, scale in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if count >= scale:
            return f"{count / scale:.3g} {unit}"
    return f"{count:.0f} B"


def duration_text(seconds: float) -> str:
    """Seconds as ``2 s``, ``3 min``, ``5.1 h``, ``12 days``."""
    if seconds < 90:
        return f"{seconds:.0f} s"
    if seconds < 5400:
        return f"{seconds / 60:.0f} min"
    if seconds < 72 * 3600:
        return f"{seconds / 3600:.1f} h"
    return f"{seconds / 86400:.0f} days"


def check_run(points: int, field: str = "stop_time", memory: int | None = None) -> float:
    """Refuse a run whose output points do not fit in memory; return its estimated seconds.

    Parameters
    ----------
    points : int
        Output points of the run (:meth:`TimeGrid.point_count`).
    field : {"stop_time", "periods", "points_per_period"}
        The field that set the run's size, named in the refusal.
    memory : int, optional
        Bytes available (default :func:`available_memory`).

    Returns
    -------
    float
        Estimated wall time, s.

    Raises
    ------
    UsageError
        When the points need more than :data:`MEMORY_SHARE` of the memory available, or the
        run would take longer than :data:`MAX_SECONDS`.
    """
    memory = available_memory() if memory is None else memory
    need = points * BYTES_PER_POINT
    fits = int(memory * MEMORY_SHARE / BYTES_PER_POINT)
    if need > memory * MEMORY_SHARE:
        raise UsageError(field, f"this run would record {quantity(points)} output points, about "
                                f"{size_text(need)} of memory, over the limit of half the "
                                f"{size_text(memory)} available: {_advice(field)} (at most about "
                                f"{quantity(fits)} points fit)")
    seconds = points * SECONDS_PER_POINT
    if seconds > MAX_SECONDS:
        raise UsageError(field, f"this run would record {quantity(points)} output points, about "
                                f"{duration_text(seconds)} of computing: {_advice(field)}")
    return seconds


def _advice(field: str) -> str:
    """What to lower when a run is too big: the field named, and the output density if not that one."""
    density = "points_per_period"
    return f"lower `{field}`" if field == density else f"lower `{field}` or `{density}`"


def length_field(grid: TimeGrid) -> str:
    """The field that set the run's length: ``stop_time`` for seconds, ``periods`` for periods."""
    return "stop_time" if grid.unit == "s" else "periods"


def sweep_run_seconds(points_per_run: int) -> float:
    """Estimated wall time of one sweep run of this many output points (rounded up).

    The sweep also uses it to size its tasks before it has measured a run
    (:func:`pendulum_fmu.sweep.cluster.task_size`).
    """
    return SECONDS_PER_SWEEP_RUN + points_per_run * SECONDS_PER_POINT


def check_sweep(runs: int, points_per_run: int, workers: int, memory: int | None = None,
                runs_field: str = "amplitudes", fewer: str = "use fewer values on its axes") -> float:
    """Refuse a sweep that does not fit in memory or in :data:`MAX_SECONDS`; return its estimated seconds.

    Parameters
    ----------
    runs : int
        Runs of the grid.
    points_per_run : int
        Output points of each run (periods times points per period).
    workers : int
        Worker threads that share the runs (and each hold one run's points).
    memory : int, optional
        Bytes available (default :func:`available_memory`).
    runs_field, fewer : str
        The field a refusal for too many runs names, and what it advises (other fields in
        backquotes, as :class:`~pendulum_fmu.errors.UsageError` says).

    Raises
    ------
    UsageError
        Naming the number of runs or points, the memory or time it needs, and what to change.
    """
    memory = available_memory() if memory is None else memory
    per_run = points_per_run * BYTES_PER_POINT
    if per_run * workers > memory * MEMORY_SHARE:
        raise UsageError("periods", f"each run would record {quantity(points_per_run)} output points, about "
                                    f"{size_text(per_run)} of memory per worker ({workers} workers), and "
                                    f"{size_text(memory)} is available: lower `periods` or "
                                    "`points_per_period`, or use fewer `workers`")
    need = runs * BYTES_PER_SWEEP_RUN
    if need > memory * MEMORY_SHARE:
        fits = int(memory * MEMORY_SHARE / BYTES_PER_SWEEP_RUN)
        raise UsageError(runs_field, f"this sweep has {quantity(runs)} runs, about {size_text(need)} of "
                                     f"memory for their rows, and {size_text(memory)} is available: {fewer} "
                                     f"(at most about {quantity(fits)} runs fit)")
    seconds = runs * sweep_run_seconds(points_per_run) / max(workers, 1)
    if seconds > MAX_SECONDS:
        raise UsageError(runs_field, f"this sweep has {quantity(runs)} runs of {quantity(points_per_run)} "
                                     f"points, about {duration_text(seconds)} on {workers} workers: {fewer}, "
                                     "fewer periods or points per period")
    return seconds


def planned_run(runner: FmuRunner, problem: InitialValueProblem, method: Method, grid: TimeGrid,
                field: str | None = None, what: str = "simulating") -> Trajectory:
    """Run one problem, its size checked before the first output point, saying so when it will take a while.

    The check comes between the FMU's initialization (which gives the period the grid counts
    in) and the first output point: the run is initialized once.

    Parameters
    ----------
    runner : FmuRunner
        The loaded FMU.
    problem, method, grid
        What to run.
    field : str, optional
        The field to name in a refusal (default: the one that set the run's length,
        :func:`length_field`).
    what : str
        The verb of the progress line (``simulating``, ``drawing``), logged at INFO
        (``simulating 10 million output points: about 30 s ...``) before a run estimated
        longer than :data:`SLOW_SECONDS`.

    Returns
    -------
    Trajectory
        The run.

    Raises
    ------
    UsageError
        From :func:`check_run`, before any output point is computed.
    """
    def plan(period: float) -> None:
        points = grid.point_count(period)
        seconds = check_run(points, length_field(grid) if field is None else field)
        if seconds > SLOW_SECONDS:
            _log.info("%s %s output points: about %s ...", what, quantity(points), duration_text(seconds))

    return runner.run(problem, method, grid, plan)
