"""``pendulum-fmu bench sweep``: sweep throughput (runs per second) with 1 and 2 Dask workers.

The sweep is the README's: N amplitudes from 1 to 179 deg, released from rest, 10 exact
periods each, the FMU's dopri5 at its default tolerance, 50 output points a period. For each
worker count a local cluster is started (not timed), every worker loads the FMU, and the
whole sweep is timed from the first submission to the last result; the median of
``--repeat`` sweeps is reported.
"""

from __future__ import annotations

import argparse
import statistics
import time
from dataclasses import dataclass
from pathlib import Path

from .arguments import add_fmu_argument, integer, positive
from .locate import locate_fmu
from .sweep_grid import SweepGrid, SweepPoint

NAME = "sweep"
HELP = "sweep throughput, runs/s with 1 and 2 Dask workers, and the speed-up"


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
    """

    workers: int
    runs: int
    seconds: tuple[float, ...]
    startup: float

    @property
    def rate(self) -> float:
        """Runs per second, from the median sweep time."""
        return self.runs / statistics.median(self.seconds)


def bench_points(runs: int, periods: float) -> list[SweepPoint]:
    """``runs`` amplitudes evenly from 1 to 179 deg, from rest, dopri5 at 1e-8."""
    amplitudes = tuple(1.0 + 178.0 * k / max(runs - 1, 1) for k in range(runs))
    return SweepGrid(amplitudes, periods=periods, solvers=("dopri5",)).points()


def measure(fmu: Path, points: list[SweepPoint], workers: int, repeat: int) -> Throughput:
    """Time ``repeat`` sweeps of ``points`` on a fresh local cluster of ``workers`` processes."""
    from .sweep import dask_client, execute

    start = time.perf_counter()
    with dask_client(None, workers) as client:
        client.wait_for_workers(workers)
        startup = time.perf_counter() - start
        seconds = tuple(execute(client, fmu, points, progress=False) for _ in range(repeat))
    return Throughput(workers, len(points), seconds, startup)


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench sweep``."""
    parser.add_argument("--runs", type=integer(1, 1_000_000), default=1000,
                        help="amplitudes in the sweep, one run each (default 1000)")
    parser.add_argument("--periods", type=positive("periods", 1e4), default=10.0,
                        help="exact periods per run (default 10)")
    parser.add_argument("--workers", type=integer(1, 256), nargs="+", default=[1, 2], metavar="N",
                        help="worker counts to time, the first one is the baseline (default: 1 2)")
    parser.add_argument("--repeat", type=integer(1, 100), default=5,
                        help="sweeps timed per worker count; the median counts (default 5)")
    add_fmu_argument(parser)


def run(args: argparse.Namespace) -> int:
    """Run the benchmark and print runs/s per worker count and the speed-ups."""
    fmu = locate_fmu(args.fmu)
    points = bench_points(args.runs, args.periods)
    print(f"sweep of {len(points)} runs (amplitudes 1-179 deg from rest, {args.periods:g} periods, dopri5 "
          f"at 1e-8), median of {args.repeat}; FMU {fmu}")
    print(f"{'workers':>7}  {'runs':>6}  {'seconds':>8}  {'runs/s':>8}  {'speed-up':>8}  {'startup (s)':>11}")
    results = []
    for workers in args.workers:
        result = measure(fmu, points, workers, args.repeat)
        results.append(result)
        speedup = result.rate / results[0].rate
        print(f"{workers:>7}  {result.runs:>6}  {statistics.median(result.seconds):>8.3f}  {result.rate:>8.1f}  "
              f"{speedup:>7.2f}x  {result.startup:>11.2f}", flush=True)
    for result in results:
        print(f"bench_sweep workers={result.workers} runs={result.runs} rate={result.rate:.2f} "
              f"seconds={','.join(f'{s:.3f}' for s in result.seconds)}")
    if len(results) > 1:
        print(f"speed-up {results[-1].workers} vs {results[0].workers} workers: "
              f"{results[-1].rate / results[0].rate:.2f}x")
    return 0
