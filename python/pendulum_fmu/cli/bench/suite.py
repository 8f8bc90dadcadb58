"""``pendulum-fmu bench suite``: the command line of :mod:`pendulum_fmu.bench.suite`."""

from __future__ import annotations

import argparse

import pendulum_fmu.bench.suite as bench_suite
from pendulum_fmu.cli.arguments import plain_text

NAME = "suite"
HELP = "the whole Pendulum suite through fmpy, judged and reported, against fmpy's command line"
DESCRIPTION = plain_text(bench_suite.__doc__ or HELP)
EPILOG = """\
examples:
  pendulum-fmu bench suite
  pendulum-fmu bench suite --engines fmpy
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench suite``."""
    parser.add_argument("--engines", nargs="+", choices=bench_suite.ENGINES, default=list(bench_suite.ENGINES),
                        help="the engines to time (default: fmpy and fmpy-cli)")


def run(args: argparse.Namespace) -> int:
    """Time each engine's pass; print the table, with the ratio to the first engine."""
    from pendulum_fmu.suite.reports import machine

    timings = bench_suite.measure(tuple(args.engines))
    print(f"the Pendulum cases of the suite, judged and reported; {machine()}")
    print(f"| engine | cases | passed | wall s | engine runs s | judging s | wall / {timings[0].engine}'s |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for t in timings:
        print(f"| {t.engine} | {t.cases} | {t.passed} | {t.wall_s:.1f} | {t.run_s:.1f} | {t.judge_s:.1f} | "
              f"{t.wall_s / timings[0].wall_s:.2f} |")
    for t in timings:
        print(f"bench_suite engine={t.engine} cases={t.cases} passed={t.passed} wall_s={t.wall_s:.3f} "
              f"run_s={t.run_s:.3f} judge_s={t.judge_s:.3f}")
    return 0
