"""``pendulum-fmu bench masters``: the command line of :mod:`pendulum_fmu.bench.masters`."""

from __future__ import annotations

import argparse
import sys

from pendulum_fmu.cli.arguments import integer, output_file, plain_text, positive
from pendulum_fmu.cli.extras import module_docstring

NAME = "masters"
HELP = "co-simulation masters on the split pendulum: error and wall time against H, orders, work-precision figure"
DESCRIPTION = plain_text(module_docstring("pendulum_fmu.bench.masters") or HELP)
EPILOG = """\
examples:
  pendulum-fmu bench masters --plot masters.png
  pendulum-fmu bench masters --steps 0.01 0.005 --stop 2 --no-engines
  pendulum-fmu bench masters --steps 0.001 --no-engines --judge-rows 100000
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench masters``."""
    parser.add_argument("--steps", type=positive("s", 1.0), nargs="+", default=[1e-3, 5e-4, 2.5e-4, 1.25e-4],
                        metavar="H", help="macro steps in s, each in (0, 1] (default: 0.001 0.0005 0.00025 0.000125, "
                                          "where every reference master's error means something)")
    parser.add_argument("--stop", type=positive("s", 1000.0), default=10.0, metavar="T",
                        help="end time in s (default 10)")
    parser.add_argument("--no-engines", action="store_true", help="the reference masters only")
    parser.add_argument("--judge-rows", type=integer(3, 2_000_001), metavar="N",
                        help="also time one judge call (--system split) on a file of N macro steps (N + 1 rows)")
    parser.add_argument("--plot", type=output_file(".png"), metavar="FILE.png",
                        help="also draw the work-precision figure (error against wall time)")


def run(args: argparse.Namespace) -> int:
    """Measure, print the table and the engines' versions, draw the figure."""
    from pendulum_fmu.bench import masters as bench

    steps = tuple(sorted(set(args.steps), reverse=True))
    if args.stop / steps[-1] > 2e6:
        print(f"pendulum-fmu bench masters: --stop {args.stop:g} with H = {steps[-1]:g} is over 2e6 steps",
              file=sys.stderr)
        return 2
    points = bench.measure(steps, args.stop, engines=not args.no_engines)
    print(f"split pendulum from 75 deg, L = 1 m, g = 9.81 m/s2, 0..{args.stop:g} s; reference masters through "
          f"fmpy (FMI 2.0); engines: {bench.versions()}")
    print("\n".join(bench.table(points)))
    if args.plot:
        bench.figure(points, args.plot)
        print(f"figure: {args.plot}")
    if args.judge_rows:
        seconds, cpu, verdict = bench.judge_seconds(args.judge_rows)
        print(f"judge --system split on {args.judge_rows + 1} rows: {seconds:.2f} s wall, {cpu:.2f} s CPU: {verdict}")
    return 0
