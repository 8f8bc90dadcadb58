"""``pendulum-fmu bench accuracy``: the command line of :mod:`pendulum_fmu.bench.accuracy`."""

from __future__ import annotations

import argparse
import math

from pendulum_fmu.cli.arguments import add_fmu_argument, integer, plain_text
from pendulum_fmu.cli.extras import module_docstring, require_extra

NAME = "accuracy"
HELP = "the FMU's exact solution against mpmath at 50 digits, every regime (the headline figures' table)"
DESCRIPTION = plain_text(module_docstring("pendulum_fmu.bench.accuracy") or HELP)
EPILOG = """\
examples:
  pendulum-fmu bench accuracy              # 301 points a case, a few seconds (3.4 s measured)
  pendulum-fmu bench accuracy --points 31
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench accuracy``."""
    parser.add_argument("--points", type=integer(2, 100_000), default=301, metavar="N",
                        help="evaluation times per case, 2-100000 (default 301)")
    add_fmu_argument(parser)


def run(args: argparse.Namespace) -> int:
    """Measure and print the table."""
    require_extra("bench accuracy", "bench", ("mpmath",))
    import pendulum_fmu.bench.accuracy as accuracy

    results = accuracy.measure(args.fmu, args.points)
    print(f"against mpmath at {accuracy.DIGITS} digits, {args.points} points a case over 3 periods "
          f"(40/w0 on the separatrix)")
    print("| case | max abs(theta error) (rad) | max abs(omega error) / amplitude | naive scipy theta error (rad) |")
    print("|---|---|---|---|")
    for r in results:
        naive = "" if math.isnan(r.naive_scipy_error) else f"{r.naive_scipy_error:.2g}"
        print(f"| {r.case} | {r.theta_error:.2g} | {r.omega_error:.2g} | {naive} |")
    return 0
