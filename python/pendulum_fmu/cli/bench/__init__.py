"""``pendulum-fmu bench``: the benchmarks, one subcommand each.

Each benchmark is a module here with ``NAME``, ``HELP``, ``DESCRIPTION``, ``EPILOG``,
``configure`` and ``run`` (like :mod:`pendulum_fmu.cli.bench.sweep`) that reads its options
and calls the measurement in :mod:`pendulum_fmu.bench`; to add one, add it to :data:`PARSED`.
"""

from __future__ import annotations

import argparse
from types import ModuleType

from pendulum_fmu.cli.bench import accuracy, exact, fmi_versions, judge, masters, solvers, speed, suite, sweep

NAME = "bench"
HELP = "benchmarks: exact evaluation, work-precision of the solvers, sweep throughput"
DESCRIPTION = "Benchmarks of the FMU and of this tool. 'pendulum-fmu bench BENCHMARK --help' for each one's options."
EPILOG = """\
examples:
  pendulum-fmu bench speed
  pendulum-fmu bench accuracy
  pendulum-fmu bench exact -n 100000
  pendulum-fmu bench sweep --runs 1000 --workers 1 2
  pendulum-fmu bench suite
"""

PARSED: tuple[ModuleType, ...] = (solvers, accuracy, exact, fmi_versions, judge, masters, speed, sweep, suite)
"""Benchmarks with ``NAME``, ``HELP``, ``DESCRIPTION``, ``EPILOG``, ``configure`` and ``run``."""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the benchmark subcommands."""
    benchmarks = parser.add_subparsers(dest="benchmark", metavar="BENCHMARK", title="benchmarks", required=True)
    for module in PARSED:
        sub = benchmarks.add_parser(module.NAME, help=module.HELP, description=module.DESCRIPTION,
                                    epilog=module.EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
        module.configure(sub)
        sub.set_defaults(subparser=sub, bench_handler=module.run)


def run(args: argparse.Namespace) -> int:
    """Run the benchmark chosen."""
    return int(args.bench_handler(args))
