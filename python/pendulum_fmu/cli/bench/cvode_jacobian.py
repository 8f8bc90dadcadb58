"""``pendulum-fmu bench cvode-jacobian``: the command line of :mod:`pendulum_fmu.bench.cvode_jacobian`."""

from __future__ import annotations

import argparse

from pendulum_fmu.cli.arguments import fmu_file, plain_text
from pendulum_fmu.cli.extras import module_docstring

NAME = "cvode-jacobian"
HELP = "fmpy's CVODE on the FMU's Model Exchange interface, without and with the FMU's Jacobian"
DESCRIPTION = plain_text(module_docstring("pendulum_fmu.bench.cvode_jacobian") or HELP)
EPILOG = """\
examples:
  pendulum-fmu bench cvode-jacobian
  pendulum-fmu bench cvode-jacobian --fmu build/Pendulum.fmu --fmu build/fmi3/Pendulum.fmu
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench cvode-jacobian``."""
    parser.add_argument("--fmu", type=fmu_file, action="append", default=None, metavar="PATH",
                        help="a Pendulum.fmu to run, once per FMU (default: the package's FMI 2.0 and 3.0 FMUs)")


def run(args: argparse.Namespace) -> int:
    """Print the table."""
    from pendulum_fmu.bench.cvode_jacobian import table
    from pendulum_fmu.fmu.locate import locate_fmu

    fmus = args.fmu or [locate_fmu(None, fmi_version=2), locate_fmu(None, fmi_version=3)]
    print("\n".join(table(fmus)))
    return 0
