"""``pendulum-fmu compare``: one run's numerical solution against the exact one, in one PNG."""

from __future__ import annotations

import argparse

from pendulum_fmu.cli.arguments import (
    add_fmu_argument,
    add_method_arguments,
    add_pendulum_arguments,
    add_time_arguments,
    grid_from,
    method_from,
    output_file,
    problem_from,
)

NAME = "compare"
HELP = "numerical against exact theta and the error over time, as one PNG"
DESCRIPTION = """\
Run the FMU once and draw, in one PNG, the numerical theta over the exact (Jacobi elliptic)
theta, and below it |theta - theta_exact| and |omega - omega_exact| on a log scale.
"""
EPILOG = """\
examples:
  pendulum-fmu compare --amplitude 90 --periods 20 --out compare.png
  pendulum-fmu compare -a 170 --solver rk4 --tolerance 1e-5 --out rk4.png
  pendulum-fmu compare -a 80 --interface ME --tolerance 1e-6 --out cvode.png
  pendulum-fmu compare -a 120 --out run.png --data run.csv
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``compare``."""
    add_pendulum_arguments(parser)
    add_method_arguments(parser)
    add_time_arguments(parser, default_periods=10)
    parser.add_argument("-o", "--out", type=output_file(".png"), default="compare.png", metavar="FILE.png",
                        help="the PNG to write (default compare.png)")
    parser.add_argument("--data", type=output_file(".csv", ".csv.gz", ".parquet"), metavar="FILE",
                        help="also write the time series drawn, as simulate --out does, with its experiment "
                             "(docs/results.md)")
    add_fmu_argument(parser)


def run(args: argparse.Namespace) -> int:
    """Run ``compare`` with parsed arguments."""
    from pendulum_fmu.cli.summary import summary_lines
    from pendulum_fmu.figures.comparison import compare

    problem, method, grid = problem_from(args), method_from(args), grid_from(args)
    trajectory = compare(args.fmu, problem, method, grid, args.out)
    print("\n".join(summary_lines(trajectory)))
    print(f"written   {args.out}")
    if args.data is not None:
        from pendulum_fmu.cli.simulate import trajectory_columns, trajectory_metadata
        from pendulum_fmu.output.experiment_record import record_of, write_series

        write_series(trajectory_columns(trajectory), args.data, record_of(trajectory, args.fmu, NAME),
                     trajectory_metadata(trajectory))
        print(f"written   {args.data}")
    return 0
