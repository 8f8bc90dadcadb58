"""``pendulum-fmu bench``: the benchmarks, one subcommand each.

``exact`` and ``solvers`` are modules of their own with a ``main(argv)``; the command line
hands them the rest of the arguments untouched. To add one, add a line to
:data:`FORWARDED` (it appears as soon as its module exists) or a module with
``configure``/``run`` like :mod:`pendulum_fmu.cli.bench.sweep`.
"""

from __future__ import annotations

import argparse
import importlib
import importlib.util
import sys

from types import ModuleType

from pendulum_fmu.cli.bench import accuracy, exact, fmi_versions, judge, speed, sweep

NAME = "bench"
HELP = "benchmarks: exact evaluation, work-precision of the solvers, sweep throughput"
DESCRIPTION = "Benchmarks of the FMU and of this tool. 'pendulum-fmu bench BENCHMARK --help' for each one's options."
EPILOG = """\
examples:
  pendulum-fmu bench speed
  pendulum-fmu bench accuracy
  pendulum-fmu bench exact -n 100000
  pendulum-fmu bench sweep --runs 1000 --workers 1 2
"""

FORWARDED: dict[str, tuple[str, str]] = {
    "solvers": ("pendulum_fmu.bench.solvers", "work-precision of the solvers: error against cost"),
}
"""Benchmark name -> (module with ``main(argv) -> int``, one-line help)."""

PARSED: tuple[ModuleType, ...] = (accuracy, exact, fmi_versions, judge, speed, sweep)
"""Benchmarks with ``NAME``, ``HELP``, ``DESCRIPTION``, ``EPILOG``, ``configure`` and ``run``."""


def available() -> dict[str, tuple[str, str]]:
    """The forwarded benchmarks whose module is installed."""
    return {name: entry for name, entry in FORWARDED.items() if importlib.util.find_spec(entry[0]) is not None}


def forward(argv: list[str]) -> int | None:
    """Run ``bench NAME ...`` of a forwarded benchmark; None when ``argv`` is not one.

    The module parses its own arguments (its ``--help`` included), under the program name
    ``pendulum-fmu bench NAME``.
    """
    if len(argv) < 2 or argv[0] != NAME or argv[1] not in available():
        return None
    module = importlib.import_module(available()[argv[1]][0])
    saved = sys.argv[0]
    sys.argv[0] = f"pendulum-fmu bench {argv[1]}"
    try:
        return int(module.main(argv[2:]) or 0)
    finally:
        sys.argv[0] = saved


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the benchmark subcommands."""
    benchmarks = parser.add_subparsers(dest="benchmark", metavar="BENCHMARK", title="benchmarks", required=True)
    for name, (_, text) in available().items():
        # Listed for --help only: forward() runs these before argparse sees them.
        benchmarks.add_parser(name, help=text, add_help=False)
    for module in PARSED:
        sub = benchmarks.add_parser(module.NAME, help=module.HELP, description=module.DESCRIPTION,
                                    epilog=module.EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
        module.configure(sub)
        sub.set_defaults(subparser=sub, bench_handler=module.run)


def run(args: argparse.Namespace) -> int:
    """Run the benchmark chosen."""
    return int(args.bench_handler(args))
