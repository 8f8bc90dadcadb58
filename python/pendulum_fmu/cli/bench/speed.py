"""``pendulum-fmu bench speed``: the command line of :mod:`pendulum_fmu.bench.speed`."""

from __future__ import annotations

import argparse

import pendulum_fmu.bench.speed as speed
from pendulum_fmu.cli.arguments import add_fmu_argument, integer, plain_text

NAME = "speed"
HELP = "one simulation from Python: this package's path against fmpy and scipy's DOP853, side by side"
DESCRIPTION = plain_text(speed.__doc__ or HELP)
EPILOG = """\
examples:
  pendulum-fmu bench speed                 # 10 interleaved rounds: best and median
  pendulum-fmu bench speed --repeat 40
  pendulum-fmu bench speed --fmi-version 3
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench speed``."""
    parser.add_argument("--repeat", type=integer(1, 1000), default=10, metavar="N",
                        help="rounds, one timed run of every method each, 1-1000 (default 10)")
    add_fmu_argument(parser)


def run(args: argparse.Namespace) -> int:
    """Measure and print the table: best and median per run and per point, error, and ratios."""
    from pendulum_fmu.fmu import driver

    fmu = args.fmu
    timings = speed.measure(fmu, args.repeat)
    by_name = {t.name: t for t in timings}
    peer = by_name[speed.NUMBALSODA]
    if not peer.seconds:
        peer = by_name["scipy ode dop853 (compiled)"]
    print(f"{speed.AMPLITUDE_DEG:g} deg from rest, {speed.PERIODS} periods, {speed.POINTS_PER_PERIOD} outputs a "
          f"period, error <= {speed.TARGET_ERROR:g}; {args.repeat} interleaved rounds; FMU {fmu}; "
          f"C loop {driver.library_path() or 'not found'}")
    print(f"| method | setting | best ms | median ms | us per point | max error (rad) | {peer.name} / this, "
          f"best | median |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for t in timings:
        if not t.seconds:
            print(f"| {t.name} | {t.setting} | - | - | - | {t.error:.1e} | - | - |")
            continue
        print(f"| {t.name} | {t.setting} | {1e3 * t.best:.3f} | {1e3 * t.median:.3f} | {t.us_per_point:.2f} | "
              f"{t.error:.1e} | {peer.best / t.best:.2f} | {peer.median / t.median:.2f} |")
    for t in timings:
        if t.seconds:
            print(f"bench_speed method={t.name!r} best_ms={1e3 * t.best:.4f} median_ms={1e3 * t.median:.4f} "
                  f"error={t.error:.3e}")
    return 0
