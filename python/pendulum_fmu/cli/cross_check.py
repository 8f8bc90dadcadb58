"""``pendulum-fmu cross-check``: the FMUs in the FMI cross-check repository's layout."""

from __future__ import annotations

import argparse
from pathlib import Path

from pendulum_fmu.cli.arguments import fmu_file, output_folder

NAME = "cross-check"
HELP = "export both FMUs in the FMI cross-check layout (fmus/<version>/<cs|me>/<platform>/...)"
DESCRIPTION = """\
Write OUT/fmus/<FMI version>/<cs|me>/<platform>/PendulumFMU/<version>/Pendulum/ for every
FMI version, interface and platform the FMUs carry, as the FMI cross-check rules lay it out:
Pendulum.fmu, Pendulum_ref.csv (the FMU's own reference result, the exact solution of the
default experiment), Pendulum_ref.opt (the model description's DefaultExperiment) and
ReadMe.txt. Platforms: linux64, win64, darwin64, and for FMI 3.0 also aarch64-linux
(aarch64-darwin has no cross-check name and is left out). Prints each folder written.
An importer judges its result of one of them with 'pendulum-fmu judge RESULT.csv
--cross-check-verdict DIR', which reads the folder's Pendulum_ref.opt.
"""
EPILOG = """\
examples:
  pendulum-fmu cross-check out/cross-check
  pendulum-fmu cross-check xc --fmu build/fmi3/Pendulum.fmu
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``cross-check``."""
    parser.add_argument("out", type=output_folder, metavar="OUT", help="the folder to write fmus/ into")
    parser.add_argument("--fmu", type=fmu_file, action="append", default=None, metavar="PATH",
                        help="an FMU to export; repeat for several (default: the FMI 2.0 and the FMI 3.0 FMU, "
                             "found as for simulate)")


def run(args: argparse.Namespace) -> int:
    """Export, print each model folder written, return 0."""
    from pendulum_fmu.errors import UsageError
    from pendulum_fmu.fmu.cross_check import describe, export, platforms
    from pendulum_fmu.fmu.locate import locate_fmu

    fmus: list[Path] = args.fmu or [locate_fmu(None, fmi_version=2), locate_fmu(None, fmi_version=3)]
    for fmu in fmus:
        try:
            described = describe(fmu)
            _, left_out = platforms(fmu, described)
        except ValueError as error:
            raise UsageError("fmu", str(error)) from None
        if left_out:
            print(f"{fmu}: no cross-check platform for binaries/{', binaries/'.join(left_out)}: left out")
    try:
        folders = export(fmus, args.out)
    except ValueError as error:
        raise UsageError("fmu", str(error)) from None
    for folder in folders:
        print(folder)
    return 0
