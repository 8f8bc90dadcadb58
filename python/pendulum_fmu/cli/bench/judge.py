"""``pendulum-fmu bench judge``: the command line of :mod:`pendulum_fmu.bench.judge`."""

from __future__ import annotations

import argparse
import sys

import pendulum_fmu.bench.judge as bench_judge
from pendulum_fmu.cli.arguments import add_fmu_argument, integer, plain_text

NAME = "judge"
HELP = "how fast the judge reads and judges files of 1e3 to 2e6 rows (CS and ME), and its peak memory"
DESCRIPTION = plain_text(bench_judge.__doc__ or HELP)
EPILOG = """\
examples:
  pendulum-fmu bench judge                       # 1e3, 2e5 and 2e6 rows, CS and ME
  pendulum-fmu bench judge --rows 1000 200000 --interface CS
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench judge``."""
    parser.add_argument("--rows", type=integer(2, 20_000_000), nargs="+", default=list(bench_judge.ROWS),
                        metavar="N", help="file sizes in rows, 2-20000000 (default: 1000 200000 2000000)")
    parser.add_argument("--interface", choices=bench_judge.INTERFACES, nargs="+", default=list(bench_judge.INTERFACES),
                        help="judge as CS and/or ME (default both)")
    add_fmu_argument(parser)


def run(args: argparse.Namespace) -> int:
    """Write the files, judge each warm in a child process, print the table."""
    fmu = args.fmu  # settled by resolve_fmu before any command runs
    try:
        timings = bench_judge.measure(fmu, tuple(args.rows), tuple(args.interface))
    except (RuntimeError, OSError) as error:
        print(f"pendulum-fmu bench judge: {error}", file=sys.stderr)
        return 1
    print(f"honest runs of the FMU's rkn (tol 1e-8, {bench_judge.AMPLITUDE_DEG:g} deg, an output every "
          f"{bench_judge.OUTPUT_INTERVAL:g} s), CSV; each judged warm in a child process; FMU {fmu}")
    print("| rows | interface | read s | judge s (total) | peak RSS MB | verdict |")
    print("|---:|---|---:|---:|---:|---|")
    for t in timings:
        verdict = "PASS" if t.passed else "FAIL"
        print(f"| {bench_judge.describe_rows(t.rows)} | {t.interface} | {t.read_s:.2f} | {t.judge_s:.2f} | "
              f"{t.peak_rss_mb:.0f} | {verdict} |")
    for t in timings:
        print(f"bench_judge rows={t.rows} interface={t.interface} read_s={t.read_s:.4f} judge_s={t.judge_s:.4f} "
              f"peak_rss_mb={t.peak_rss_mb:.1f} passed={t.passed}")
    failed = [t for t in timings if not t.passed]
    for t in failed:
        print(f"not passed: {bench_judge.describe_rows(t.rows)} rows {t.interface}: {t.line}")
    return 0
