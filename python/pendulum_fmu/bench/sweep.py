"""``pendulum-fmu bench sweep``: sweep throughput (runs per second) with 1 and 2 Dask workers.

The sweep is the README's: N amplitudes from 1 to 179 deg, released from rest, 10 exact
periods each, the FMU's dopri5 at its default tolerance, 50 output points a period. For each
worker count a local cluster is started (not timed), every worker loads the FMU, and the
whole sweep is timed from the first submission to the last result; the median of
``--repeat`` sweeps is reported. Each worker count runs with the workers' output loop in C
(the package's path) and in Python (the path before it; ``PENDULUM_FMU_LOOP=python`` in
the workers' environment), so that the runs per second per worker are seen before and after.
"""

from __future__ import annotations

import os
import statistics
import time
from dataclasses import dataclass
from pathlib import Path

from pendulum_fmu.sweep.grid import SweepGrid, SweepPoint


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
    """

    workers: int
    runs: int
    seconds: tuple[float, ...]
    startup: float
    loop: str = "c"

    @property
    def rate(self) -> float:
        """Runs per second, from the median sweep time."""
        return self.runs / statistics.median(self.seconds)


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
    finally:
        if saved is None:
            os.environ.pop("PENDULUM_FMU_LOOP", None)
        else:
            os.environ["PENDULUM_FMU_LOOP"] = saved
    return Throughput(workers, len(points), seconds, startup, loop)

