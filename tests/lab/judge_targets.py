"""The judge's speed and memory targets: ``pendulum-fmu bench judge``'s timings, each judged.

A team member's check from a source checkout, not part of the package:
``python tests/lab/judge_targets.py [--rows N ...] [--interface CS ME] [--fmu PATH] [--split-rows N]``.
It times the judge as ``pendulum-fmu bench judge`` does (:func:`pendulum_fmu.bench.judge.measure`:
honest runs of the FMU written as CSV, each judged warm in a child process) and holds each
file to the targets: a verdict on 1,000 rows in under 1 s; 2 million rows in under 5 s (CS)
and 30 s (ME), kept for every larger file; under 1 GB of peak resident memory. With
``--split-rows N`` it also times one ``judge --system split`` call on a file of N macro steps
(:func:`pendulum_fmu.bench.masters.judge_seconds`) against its target of 5 s. Exits 0 when
every figure is within its target, 1 otherwise. The figures move with the machine's load: a
target missed on a busy machine is a figure to look at, not a test failure.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from pendulum_fmu import fmu_path
from pendulum_fmu.bench.judge import INTERFACES, ROWS, Timing, describe_rows, measure
from pendulum_fmu.bench.masters import judge_seconds

SMALL_ROWS = 1_000
"""Files up to this many rows have the small file's target."""
MEMORY_TARGET_MB = 1024.0
"""Peak resident memory of the judging process, imports included."""
SPLIT_TARGET_S = 5.0
"""One ``judge --system split`` call on a file of up to 2e6 macro steps."""


def target_seconds(rows: int, interface: str) -> float:
    """The time a verdict may take: 1 s up to 1,000 rows, else 5 s in CS and 30 s in ME."""
    if rows <= SMALL_ROWS:
        return 1.0
    return 5.0 if interface == "CS" else 30.0


def within(timing: Timing) -> bool:
    """Within the time and the memory target."""
    return (timing.judge_s <= target_seconds(timing.rows, timing.interface)
            and timing.peak_rss_mb <= MEMORY_TARGET_MB)


def table(timings: list[Timing]) -> list[str]:
    """The Markdown table of docs/importers.md: the figures beside their targets."""
    lines = [f"| rows | interface | read s | judge s (total) | target s | peak RSS MB (target {MEMORY_TARGET_MB:g}) "
             "| verdict | within |", "|---:|---|---:|---:|---:|---:|---|---|"]
    for t in timings:
        lines.append(f"| {describe_rows(t.rows)} | {t.interface} | {t.read_s:.2f} | {t.judge_s:.2f} | "
                     f"{target_seconds(t.rows, t.interface):g} | {t.peak_rss_mb:.0f} | "
                     f"{'PASS' if t.passed else 'FAIL'} | {'yes' if within(t) else 'no'} |")
    return lines


def main(argv: list[str] | None = None) -> int:
    """Time the judge, print the figures beside the targets; 0 when all are met."""
    parser = argparse.ArgumentParser(prog="python tests/lab/judge_targets.py", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rows", type=int, nargs="+", default=list(ROWS), help="file sizes in rows")
    parser.add_argument("--interface", choices=INTERFACES, nargs="+", default=list(INTERFACES))
    parser.add_argument("--fmu", type=Path, default=None, help="Pendulum.fmu (default: the package's)")
    parser.add_argument("--split-rows", type=int, default=None, metavar="N",
                        help="also time judge --system split on N macro steps")
    args = parser.parse_args(argv)
    timings = measure(args.fmu or fmu_path(), tuple(args.rows), tuple(args.interface))
    print("\n".join(table(timings)))
    met = all(within(t) and t.passed for t in timings)
    if args.split_rows:
        seconds, cpu, verdict = judge_seconds(args.split_rows)
        print(f"judge --system split on {args.split_rows + 1} rows: {seconds:.2f} s wall, {cpu:.2f} s CPU "
              f"(target {SPLIT_TARGET_S:g} s): {verdict}")
        met = met and seconds <= SPLIT_TARGET_S
    return 0 if met else 1


if __name__ == "__main__":
    sys.exit(main())
