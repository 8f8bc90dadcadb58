"""``pendulum-fmu bench sweep``: the command line of :mod:`pendulum_fmu.bench.sweep`."""

from __future__ import annotations

import argparse
import statistics
import sys

import pendulum_fmu.bench.sweep as bench_sweep
from pendulum_fmu.bench.sweep import bench_points, cores, measure
from pendulum_fmu.cli.arguments import add_fmu_argument, integer, plain_text, positive
from pendulum_fmu.cli.extras import require_extra

NAME = "sweep"
HELP = "sweep throughput, runs/s with 1 and 2 Dask workers, the speed-up, efficiency and cost per task"
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
    parser.add_argument("--loop", choices=("c", "python", "both"), default="both",
                        help="the workers' output loop: c (the package's), python (before it) or both, "
                             "to compare runs/s per worker (default both)")
    add_fmu_argument(parser)


def run(args: argparse.Namespace) -> int:
    """Run the benchmark and print runs/s per worker count and loop, and the speed-ups."""
    require_extra("bench sweep", "bench", ("dask", "distributed", "tqdm"))
    import math

    from pendulum_fmu.fmu.runner import FmuRunner
    from pendulum_fmu.sizing import SLOW_SECONDS, check_sweep, duration_text

    loops = ["c", "python"] if args.loop == "both" else [args.loop]
    # Every timed sweep, on the fewest workers asked for: refused at once past a week or the memory.
    seconds = check_sweep(args.runs * args.repeat * len(args.workers) * len(loops), math.ceil(args.periods * 50) + 1,
                          min(args.workers), runs_field="runs",
                          fewer="fewer `runs`, `repeat` or `workers` counts, or one `loop`")
    if seconds > SLOW_SECONDS:
        print(f"bench sweep: about {duration_text(seconds)} of sweeps ...", file=sys.stderr, flush=True)
    fmu = args.fmu
    points = bench_points(args.runs, args.periods)
    with FmuRunner(fmu) as runner:  # a run that fails here would be timed as a fast one: refuse now
        probe = points[0]
        runner.run(probe.problem(), probe.method(), probe.grid())
    physical, logical, usable = cores()
    print(f"sweep of {len(points)} runs (amplitudes 1-179 deg from rest, {args.periods:g} periods, dopri5 "
          f"at 1e-8), median of {args.repeat}; FMU {fmu}")
    print(f"cores: {physical or '?'} physical, {logical or '?'} logical, {usable} usable by this process")
    print(f"{'loop':>6}  {'workers':>7}  {'runs':>6}  {'seconds':>8}  {'runs/s':>8}  {'per worker':>10}  "
          f"{'speed-up':>8}  {'efficiency':>10}  {'ms/task':>7}  {'startup (s)':>11}")
    results = []
    for loop in loops:
        first = None
        for workers in args.workers:
            result = measure(fmu, points, workers, args.repeat, loop)
            results.append(result)
            first = first or result
            speedup = result.rate / first.rate
            print(f"{loop:>6}  {workers:>7}  {result.runs:>6}  {statistics.median(result.seconds):>8.3f}  "
                  f"{result.rate:>8.1f}  {result.rate / workers:>10.1f}  {speedup:>7.2f}x  "
                  f"{speedup * first.workers / workers:>10.2f}  {result.task_seconds * 1e3:>7.2f}  "
                  f"{result.startup:>11.2f}", flush=True)
    for result in results:
        print(f"bench_sweep loop={result.loop} workers={result.workers} runs={result.runs} rate={result.rate:.2f} "
              f"per_worker={result.rate / result.workers:.2f} task_ms={result.task_seconds * 1e3:.3f} "
              f"seconds={','.join(f'{s:.3f}' for s in result.seconds)}")
    by_key = {(r.loop, r.workers): r for r in results}
    for workers in args.workers:
        if ("c", workers) in by_key and ("python", workers) in by_key:
            print(f"C loop / Python loop, {workers} worker(s): "
                  f"{by_key['c', workers].rate / by_key['python', workers].rate:.2f}x runs per second per worker")
    if len(args.workers) > 1:
        last, first_count = args.workers[-1], args.workers[0]
        for loop in loops:
            print(f"speed-up {last} vs {first_count} workers ({loop} loop): "
                  f"{by_key[loop, last].rate / by_key[loop, first_count].rate:.2f}x")
    return 0
