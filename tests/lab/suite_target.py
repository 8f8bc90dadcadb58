"""The suite's speed target: ``pendulum-fmu bench suite``'s timings against 60 s.

A team member's check from a source checkout, not part of the package:
``python tests/lab/suite_target.py [--engines fmpy fmpy-cli]``. It times the whole Pendulum
suite as ``pendulum-fmu bench suite`` does (:func:`pendulum_fmu.bench.suite.measure`: every
case in a process of its own, judged, three reports) and holds the fmpy engine to the target:
under 60 s on 2 cores. Exits 0 when every engine timed is under it, 1 otherwise (the figure
moves with the machine's load).
"""

from __future__ import annotations

import argparse
import sys

from pendulum_fmu.bench.suite import ENGINES, SuiteTiming, measure

TARGET_S = 60.0
"""The whole Pendulum suite through fmpy, judged and reported, in under this (2 cores)."""


def table(timings: list[SuiteTiming]) -> list[str]:
    """The Markdown table of docs/suite.md, with the target's column."""
    first = timings[0]
    lines = [f"| engine | cases | passed | wall s | engine runs s | judging s | wall / {first.engine}'s | "
             f"under {TARGET_S:g} s |", "|---|---:|---:|---:|---:|---:|---:|---|"]
    for t in timings:
        lines.append(f"| {t.engine} | {t.cases} | {t.passed} | {t.wall_s:.1f} | {t.run_s:.1f} | {t.judge_s:.1f} | "
                     f"{t.wall_s / first.wall_s:.2f} | {'yes' if t.wall_s < TARGET_S else 'no'} |")
    return lines


def main(argv: list[str] | None = None) -> int:
    """Time each engine's pass and print it beside the target; 0 when every one is under it."""
    parser = argparse.ArgumentParser(prog="python tests/lab/suite_target.py", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--engines", nargs="+", choices=ENGINES, default=list(ENGINES))
    args = parser.parse_args(argv)
    timings = measure(tuple(args.engines))
    print("\n".join(table(timings)))
    return 0 if all(t.wall_s < TARGET_S and t.passed == t.cases for t in timings) else 1


if __name__ == "__main__":
    sys.exit(main())
