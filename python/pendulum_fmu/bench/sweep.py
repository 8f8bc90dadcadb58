"""``pendulum-fmu bench sweep``: sweep throughput (runs per second) with 1 and 2 Dask workers.

The sweep is the README's: N amplitudes from 1 to 179 deg, released from rest, 10 exact
periods each, the FMU's dopri5 at its default tolerance, 50 output points a period. For each
worker count a local cluster is started (not timed), every worker loads the FMU, and the
whole sweep is timed from the first submission to the last result; the median of
``--repeat`` sweeps is reported, with the efficiency (the speed-up over the first worker count
divided by the workers' ratio) and the scheduler's own cost per task, timed with empty tasks
on the same cluster; the sweep puts about 0.1 s of runs in a task (``sweep/cluster.py``).
Each worker count runs with the workers' output loop in C
(the package's path) and in Python (the path before it; ``PENDULUM_FMU_LOOP=python`` in
the workers' environment), so that the runs per second per worker are seen before and after.
"""

from __future__ import annotations

import os
import statistics
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from pendulum_fmu.sweep.grid import SweepGrid, SweepPoint

if TYPE_CHECKING:
    from distributed import Client


@dataclass(frozen=True)
class Throughput:
    """Timing of one worker count.

    Attributes
    ----------
    workers : int
        Worker processes (one thread each).
    runs : int
        Runs per sweep.
    seconds : tuple of float
        Wall time of each repeated sweep.
    startup : float
        Seconds to start the local cluster (not in ``seconds``).
    loop : str
        The workers' output loop: ``c`` or ``python``.
    task_seconds : float
        The scheduler's own cost per task on this cluster (:func:`task_cost`), 0 if not measured.
    """

    workers: int
    runs: int
    seconds: tuple[float, ...]
    startup: float
    loop: str = "c"
    task_seconds: float = 0.0

    @property
    def rate(self) -> float:
        """Runs per second, from the median sweep time."""
        return self.runs / statistics.median(self.seconds)


def cores() -> tuple[int | None, int | None, int]:
    """This machine's physical and logical cores (psutil; None where unknown) and the usable ones.

    The usable ones are those this process may run on (its CPU affinity), which a container or
    ``taskset`` may make fewer than the logical cores.
    """
    import psutil

    usable = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    return psutil.cpu_count(logical=False), psutil.cpu_count(logical=True), usable


def _nothing(index: int) -> int:
    """An empty task."""
    return index


def task_cost(client: Client, count: int = 400) -> float:
    """Seconds per task of ``count`` empty tasks on the client's workers, submitted at once.

    What a sweep pays per task besides its runs: the client's submission, the scheduler's
    bookkeeping, the trip to a worker and back. The sweep sizes its tasks so that this is a
    small share of each (:func:`pendulum_fmu.sweep.cluster.task_size`).
    """
    from distributed import wait

    from pendulum_fmu import interrupt

    with interrupt.deferred_interrupt():   # no KeyboardInterrupt inside Dask's blocking calls
        wait(client.map(_nothing, range(8), pure=False))   # warm the path
        start = time.perf_counter()
        futures = client.map(_nothing, range(count), pure=False)
        wait(futures)
        seconds = time.perf_counter() - start
        client.cancel(futures)
    return seconds / count


def bench_points(runs: int, periods: float) -> list[SweepPoint]:
    """``runs`` amplitudes evenly from 1 to 179 deg, from rest, dopri5 at 1e-8."""
    amplitudes = tuple(1.0 + 178.0 * k / max(runs - 1, 1) for k in range(runs))
    return SweepGrid(amplitudes, periods=periods, solvers=("dopri5",)).points()


def measure(fmu: Path, points: list[SweepPoint], workers: int, repeat: int, loop: str = "c") -> Throughput:
    """Time ``repeat`` sweeps of ``points`` on a fresh local cluster of ``workers`` processes
    whose runners use the output ``loop`` ("c" or "python")."""
    from pendulum_fmu.sweep.cluster import dask_client, execute

    saved = os.environ.get("PENDULUM_FMU_LOOP")
    os.environ["PENDULUM_FMU_LOOP"] = loop   # the local workers are started with this environment
    try:
        start = time.perf_counter()
        with dask_client(None, workers) as client:
            client.wait_for_workers(workers)
            startup = time.perf_counter() - start
            seconds = tuple(execute(client, fmu, points, progress=False) for _ in range(repeat))
            per_task = task_cost(client)
    finally:
        if saved is None:
            os.environ.pop("PENDULUM_FMU_LOOP", None)
        else:
            os.environ["PENDULUM_FMU_LOOP"] = saved
    return Throughput(workers, len(points), seconds, startup, loop, per_task)

