"""``pendulum-fmu simulate``: one run, its time series to CSV or Parquet, a summary printed."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

import numpy as np

from pendulum_fmu.cli.arguments import (
    add_fmu_argument,
    add_method_arguments,
    add_pendulum_arguments,
    add_time_arguments,
    grid_from,
    method_from,
    output_file,
    problem_from,
    size_field,
)

if TYPE_CHECKING:
    from pendulum_fmu.fmu.runner import Trajectory

NAME = "simulate"
HELP = "simulate one pendulum; write its time series (CSV or Parquet)"
DESCRIPTION = """\
Simulate the pendulum once through the FMU and print what it cost and how far the numerical
solution strays from the exact one. With --out, write every output point: time, theta,
omega, their exact values, the bob's position and the error.
"""
EPILOG = """\
examples:
  pendulum-fmu simulate --amplitude 85 --periods 20 --out run.csv
  pendulum-fmu simulate -a 1.2rad -w 0.5 -L 2 --interface ME --tolerance 1e-10 --out run.parquet
  pendulum-fmu simulate -a 170 --solver symplectic --stop-time 60
"""

COLUMNS: dict[str, str] = {
    "time_s": "time",
    "theta_rad": "theta",
    "omega_rad_s": "omega",
    "theta_exact_rad": "theta_exact",
    "omega_exact_rad_s": "omega_exact",
    "x_m": "x",
    "y_m": "y",
}
"""Output column -> FMU variable (or ``time``)."""


def trajectory_columns(trajectory: Trajectory) -> dict[str, np.ndarray]:
    """The time series of a run as named columns with units, plus the error."""
    columns = {name: trajectory.result[field] for name, field in COLUMNS.items()}
    columns["theta_error_rad"] = trajectory.theta_error
    return columns


def trajectory_metadata(trajectory: Trajectory) -> dict[str, str]:
    """The run's inputs and scalar results, for the Parquet schema."""
    p, m = trajectory.problem, trajectory.method
    return {"amplitude_rad": repr(p.theta0), "omega0_rad_s": repr(p.omega0), "length_m": repr(p.L),
            "gravity_m_s2": repr(p.g), "interface": m.interface, "solver": m.solver,
            "tolerance": repr(m.effective_tolerance), "period_s": repr(trajectory.period),
            "max_error_rad": repr(trajectory.max_error), "steps": str(trajectory.steps),
            "rhs_evaluations": str(trajectory.rhs_evaluations)}


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``simulate``."""
    add_pendulum_arguments(parser)
    add_method_arguments(parser)
    add_time_arguments(parser, default_periods=10)
    parser.add_argument("-o", "--out", type=output_file(".csv", ".csv.gz", ".parquet"), metavar="FILE",
                        help="write the time series to FILE.csv, FILE.csv.gz or FILE.parquet, with its experiment "
                             "(a CSV's in FILE.csv.experiment.json beside it; docs/results.md) "
                             "(default: print the summary only)")
    add_fmu_argument(parser)


def run(args: argparse.Namespace) -> int:
    """Run ``simulate`` with parsed arguments."""
    from pendulum_fmu.cli.summary import summary_lines
    from pendulum_fmu.fmu.runner import FmuRunner
    from pendulum_fmu.output.experiment_record import record_of, write_series

    problem, method, grid = problem_from(args), method_from(args), grid_from(args)
    from pendulum_fmu.sizing import planned_run

    with FmuRunner(args.fmu) as runner:
        # refused at once when it cannot fit, naming the time option given
        trajectory = planned_run(runner, problem, method, grid, size_field(args))
        version = runner.fmi_version
        description = runner.model_description
    print(f"fmu       FMI {version}.0, {args.fmu}")
    print("\n".join(summary_lines(trajectory)))
    if args.out is not None:
        record = record_of(trajectory, args.fmu, NAME, description)
        write_series(trajectory_columns(trajectory), args.out, record, trajectory_metadata(trajectory))
        beside = "" if args.out.name.lower().endswith(".parquet") else \
            f" (its experiment: {args.out.name}.experiment.json)"
        print(f"written   {args.out}{beside}")
    return 0
