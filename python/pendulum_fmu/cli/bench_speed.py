"""``pendulum-fmu bench speed``: the command line of :mod:`pendulum_fmu.bench.speed`."""

from __future__ import annotations

import argparse
import math

import pendulum_fmu.bench.speed as speed
from pendulum_fmu.cli.arguments import add_fmu_argument, integer, plain_text
from pendulum_fmu.fmu.locate import locate_fmu

NAME = "speed"
HELP = "one simulation from Python: this package's path against fmpy and scipy's DOP853, side by side"
DESCRIPTION = plain_text(speed.__doc__ or HELP)
EPILOG = """\
examples:
  pendulum-fmu bench speed                 # best of 5 per method
  pendulum-fmu bench speed --repeat 20
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench speed``."""
    parser.add_argument("--repeat", type=integer(1, 1000), default=5, metavar="N",
                        help="timed runs per method, the best counts, 1-1000 (default 5)")
    add_fmu_argument(parser)


def run(args: argparse.Namespace) -> int:
    """Measure and print the table: per run, per point, error, and ratios."""
    fmu = locate_fmu(args.fmu)
    timings = speed.measure(fmu, args.repeat)
    by_name = {t.name: t for t in timings}
    fmpy = by_name["fmpy simulate_fmu"]
    peer = by_name["scipy ode dop853 (compiled)"]
    print(f"{speed.AMPLITUDE_DEG:g} deg from rest, {speed.PERIODS} periods, {speed.POINTS_PER_PERIOD} outputs a "
          f"period, error <= {speed.TARGET_ERROR:g}; best of {args.repeat}")
    print(f"| method | setting | ms per run | us per point | max error (rad) | simulate_fmu / this | "
          f"ode dop853 / this |")
    print("|---|---|---:|---:|---:|---:|---:|")
    for t in timings:
        if math.isnan(t.seconds):
            print(f"| {t.name} | {t.setting} | - | - | {t.error:.1e} | - | - |")
            continue
        print(f"| {t.name} | {t.setting} | {1e3 * t.seconds:.2f} | {t.us_per_point:.2f} | {t.error:.1e} | "
              f"{fmpy.seconds / t.seconds:.2f} | {peer.seconds / t.seconds:.2f} |")
    return 0
