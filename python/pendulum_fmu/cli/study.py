"""``pendulum-fmu study``: the command line of :mod:`pendulum_fmu.study`."""

from __future__ import annotations

import argparse
import sys

from pendulum_fmu.cli.arguments import add_fmu_argument, output_folder, positive

NAME = "study"
HELP = "the seed's study: 75-90 deg, Figures 3-5, period ratio, error table, speed against error, hard cases"
DESCRIPTION = """\
The seed's study (the README's main job): build the FMU, release the pendulum from rest at
75, 80, 85 and 90 deg, simulate it in Co-Simulation (the FMU's default solver, rkn, at its
default tolerance 1e-8) and in Model Exchange (fmpy's CVODE at 1e-10), and write to --out:
Figures 3-5 (theta against t/T0: numerical, exact, overlaid), the period ratio T/T0 against
amplitude up to 179.999999 deg, runs.csv, report.md and report.html (tables and figures in one
page). Then speed against error: every solver (dopri5, rk4, rkn, symplectic; CVODE) at the seed's
amplitudes over a range of tolerances, its error and cost (right-hand-side evaluations, wall time
per period) against the exact solution's cost (speed_vs_error.png, speed.csv); and the hard cases
(releases at 179.9 and 179.9999 deg, a rotation just above the separatrix, a creep over the top,
10,000 periods, a start at t0 = 1e9 s): each solver's error, whether every step was certified or
which warned, and its cost (hard_cases.csv). The tables and the fastest method at each error
level are printed.
"""
EPILOG = """\
examples:
  pendulum-fmu study                      # writes out/study/
  pendulum-fmu study --out /tmp/study --periods 5
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``study``."""
    parser.add_argument("--out", type=output_folder, default="out/study", metavar="DIR",
                        help="output folder, created with its missing parents (default: out/study in the current "
                             "folder)")
    add_fmu_argument(parser)
    parser.add_argument("--periods", type=positive("periods", 1000), default=10.0,
                        help="exact periods to simulate, in (0, 1000] (default 10)")


def run(args: argparse.Namespace) -> int:
    """Run the study with parsed arguments; write plots, CSV, table and reports to ``args.out``."""
    from pendulum_fmu.output.whole_folder import whole_folder
    from pendulum_fmu.study.job import write_study

    def progress(line: str) -> None:
        print(f"study: {line} ...", file=sys.stderr, flush=True)

    # Every stage says what it does (seconds each on a loaded machine); the files appear in
    # args.out only when all are written: an interrupted study leaves the folder as it was.
    with whole_folder(args.out) as partial:
        outcome = write_study(args.fmu, partial, args.periods, progress)
    print(outcome.table)
    print(f"\nSpeed against error (10 periods at each amplitude):\n\n{outcome.speed_table}\n\n{outcome.fastest}")
    print(f"\nHard cases:\n\n{outcome.hard_table}\n\n{outcome.hard_summary}")
    if outcome.warnings:
        print(f"warning: the FMU warned during the study (column fmu_warning of runs.csv): "
              f"{'; '.join(outcome.warnings)}", file=sys.stderr)
    print(f"\nwritten to {args.out} (open report.html)")
    return 0

