"""``pendulum-fmu bench fmi-versions``: the tables of :mod:`pendulum_fmu.bench.fmi_versions` and
:mod:`pendulum_fmu.bench.cvode_jacobian`, the FMI 3.0 FMU beside the FMI 2.0 one."""

from __future__ import annotations

import argparse

from pendulum_fmu.cli.arguments import fmu_file, plain_text
from pendulum_fmu.cli.extras import module_docstring, require_extra

NAME = "fmi-versions"
HELP = "the FMI 3.0 FMU beside the FMI 2.0 one: accuracy, exact port, fmpy's CVODE with the FMU's Jacobian"
DESCRIPTION = plain_text(module_docstring("pendulum_fmu.bench.fmi_versions") or HELP)
EPILOG = """\
examples:
  pendulum-fmu bench fmi-versions
  pendulum-fmu bench fmi-versions --fmi2 build/Pendulum.fmu --fmi3 build/fmi3/Pendulum.fmu
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench fmi-versions``."""
    parser.add_argument("--fmi2", type=fmu_file, metavar="PATH",
                        help="the FMI 2.0 Pendulum.fmu (default: the one the package finds)")
    parser.add_argument("--fmi3", type=fmu_file, metavar="PATH",
                        help="the FMI 3.0 Pendulum.fmu (default: the one the package finds)")


def run(args: argparse.Namespace) -> int:
    """Print the three tables."""
    require_extra("bench fmi-versions", "bench", ("mpmath",))
    from pendulum_fmu.bench.cvode_jacobian import table as cvode_table
    from pendulum_fmu.bench.fmi_versions import regime_table, seed_table
    from pendulum_fmu.fmu.locate import locate_fmu
    from pendulum_fmu.fmu.runner import FmuRunner

    fmi2 = locate_fmu(args.fmi2, fmi_version=2)
    fmi3 = locate_fmu(args.fmi3, fmi_version=3)
    with FmuRunner(fmi2) as two, FmuRunner(fmi3) as three:
        print("\n".join(seed_table(two, three)))
        print()
        print("\n".join(regime_table(three)))
    print()
    print("\n".join(cvode_table([fmi2, fmi3])))
    return 0
