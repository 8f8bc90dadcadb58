"""``pendulum-fmu bench sweep``: the command line of :mod:`pendulum_fmu.bench.sweep`."""

from __future__ import annotations

import argparse
import sys
import statistics

import pendulum_fmu.bench.sweep as bench_sweep
from pendulum_fmu.bench.sweep import bench_points, measure
from pendulum_fmu.cli.arguments import add_fmu_argument, integer, plain_text, positive
from pendulum_fmu.fmu.locate import locate_fmu

NAME = "sweep"
HELP = "sweep throughput, runs/s with 1 and 2 Dask workers, and the speed-up"
DESCRIPTION = plain_text(bench_sweep.__doc__ or HELP)
EPILOG = """\
examples:
  pendulum-fmu bench sweep                          # 1000 runs, 1 and 2 workers, median of 5
  pendulum-fmu bench sweep --runs 200 --workers 1 2 4 --repeat 3
"""


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
    import math

    from pendulum_fmu.fmu.runner import FmuRunner
    from pendulum_fmu.sizing import SLOW_SECONDS, check_sweep, duration_text

    # Every timed sweep, on the fewest workers asked for: refused at once past a week or the memory.
    seconds = check_sweep(args.runs * args.repeat * len(args.workers), math.ceil(args.periods * 50) + 1,
                          min(args.workers), runs_argument="--runs", fewer="fewer --runs, --repeat or --workers counts")
    if seconds > SLOW_SECONDS:
        print(f"bench sweep: about {duration_text(seconds)} of sweeps ...", file=sys.stderr, flush=True)
    fmu = locate_fmu(args.fmu)
    points = bench_points(args.runs, args.periods)
    with FmuRunner(fmu) as runner:  # a run that fails here would be timed as a fast one: refuse now
        first = points[0]
        runner.run(first.pendulum(), first.method(), first.grid())
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
