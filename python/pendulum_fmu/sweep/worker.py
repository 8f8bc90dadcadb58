"""What a Dask worker runs: batches of sweep points on an FMU loaded once per worker.

The client sends the FMU's bytes once (scattered to every worker); the first use on a
worker writes them to a temporary file and builds a :class:`FmuRunner` (unzip, ``dlopen``,
instantiate), which every later task on that worker reuses. Workers need this
package installed, nothing else: no shared file system, no FMU on their disk.
"""

from __future__ import annotations

import atexit
import hashlib
import math
import os
import tempfile
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from pendulum_fmu.errors import SimulationError
from pendulum_fmu.fmu.runner import FmuRunner, Trajectory
from pendulum_fmu.sweep.grid import INPUT_COLUMNS, OUTPUT_COLUMNS, SweepPoint

_lock = threading.Lock()
_idle: dict[str, list[FmuRunner]] = {}
_loads = 0


def _load(fmu_bytes: bytes) -> FmuRunner:
    """Write the bytes to a temporary file and load a runner from it (unzip, dlopen)."""
    global _loads
    handle, name = tempfile.mkstemp(prefix="pendulum-", suffix=".fmu")
    with os.fdopen(handle, "wb") as file:
        file.write(fmu_bytes)
    try:
        runner = FmuRunner(Path(name))
    finally:
        os.unlink(name)
    atexit.register(runner.close)
    with _lock:
        _loads += 1
    return runner


@contextmanager
def borrowed_runner(fmu_bytes: bytes) -> Iterator[FmuRunner]:
    """A runner for the FMU with these bytes, for the duration of a ``with`` block.

    Runners are kept per process and per FMU content (a rebuilt FMU gets new ones); a
    runner serves one thread at a time, so a worker with one thread loads the FMU once,
    and one with n threads at most n times.

    Parameters
    ----------
    fmu_bytes : bytes
        The content of ``Pendulum.fmu``.

    Yields
    ------
    FmuRunner
        Loaded, reset between runs by the runner itself.
    """
    digest = hashlib.sha256(fmu_bytes).hexdigest()
    with _lock:
        idle = _idle.setdefault(digest, [])
        runner = idle.pop() if idle else None
    if runner is None:
        runner = _load(fmu_bytes)
    try:
        yield runner
    finally:
        with _lock:
            _idle[digest].append(runner)


def load_count() -> int:
    """How many times this process has extracted and loaded an FMU (for tests)."""
    return _loads


def warm(fmu_bytes: bytes, sample: SweepPoint | None = None) -> tuple[int, float]:
    """Load the FMU on this worker ahead of the first task, and time one run of ``sample``.

    Returns
    -------
    tuple of (int, float)
        The process id, and the wall time of the sample run in seconds (0 without a sample,
        and for a sample that failed).
    """
    with borrowed_runner(fmu_bytes) as runner:
        if sample is None:
            return os.getpid(), 0.0
        start = time.perf_counter()
        try:
            runner.run(sample.problem(), sample.method(), sample.grid())
        except SimulationError:
            return os.getpid(), 0.0
        return os.getpid(), time.perf_counter() - start


def row_of(point: SweepPoint, trajectory: Trajectory) -> dict[str, Any]:
    """One table row: the point's inputs and the run's period, errors and cost."""
    from pendulum_fmu.fmu.period import measured_period

    result = trajectory.result
    row: dict[str, Any] = {column: getattr(point, name) for column, name in INPUT_COLUMNS.items()}
    error = trajectory.theta_error
    row.update(
        interface=trajectory.method.interface,
        period_s=trajectory.period,
        period_ratio=trajectory.period / trajectory.problem.small_angle_period,
        measured_period_s=measured_period(result["time"], result["theta"]),
        stop_time_s=float(result["time"][-1]),
        max_error_rad=trajectory.max_error,
        max_omega_error_rad_s=trajectory.max_omega_error,
        final_error_rad=abs(float(error[-1])),
        steps=trajectory.steps,
        rejected_steps=trajectory.rejected_steps,
        rhs_evaluations=trajectory.rhs_evaluations,
        wall_time_s=trajectory.wall_time,
        status="ok",
        fmu_warning="; ".join(trajectory.warnings),
    )
    return row


def failed_row(point: SweepPoint, error: Exception) -> dict[str, Any]:
    """The row of a run that failed: its inputs, NaN results and the reason."""
    row: dict[str, Any] = {column: getattr(point, name) for column, name in INPUT_COLUMNS.items()}
    row.update({column: math.nan for column in OUTPUT_COLUMNS})
    row.update(interface=point.method().interface, steps=None, rejected_steps=None, rhs_evaluations=None,
               status=f"failed: {error}".replace("\n", " "), fmu_warning="")
    return row


def run_points(fmu_bytes: bytes, points: list[SweepPoint]) -> list[dict[str, Any]]:
    """Run a batch of points on this thread's runner; one row per point, in order."""
    rows = []
    with borrowed_runner(fmu_bytes) as runner:
        for point in points:
            try:
                rows.append(row_of(point, runner.run(point.problem(), point.method(), point.grid())))
            except SimulationError as error:
                rows.append(failed_row(point, error))
    return rows

