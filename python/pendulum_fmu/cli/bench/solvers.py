"""``pendulum-fmu bench solvers``: the command line of :mod:`pendulum_fmu.bench.solvers`."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from pendulum_fmu.bench.workprecision.peers import PEERS
from pendulum_fmu.cli.arguments import plain_text
from pendulum_fmu.cli.extras import module_docstring

NAME = "solvers"
HELP = "work-precision of the solvers: error against cost"
DESCRIPTION = plain_text((module_docstring("pendulum_fmu.bench.solvers") or HELP)
                         .split("\n``pendulum-fmu bench solvers`` runs")[0])
EPILOG = """\
examples:
  bash scripts/bench.sh solvers --quick             # in the repository: builds the C driver, about 30 s
  bash scripts/bench.sh solvers --out out/bench    # the full study, about 6 min on 2 cores
                                                   # (the script also judges the project's targets)
  pendulum-fmu bench solvers --driver build/tests/c/bench_solvers --problems P1 --no-peers
  pendulum-fmu bench solvers --driver build/tests/c/bench_solvers --problems P1 --peers DOP853,dop853
"""
NO_DRIVER = ("the study times the FMU's solvers with the C driver tests/c/bench_solvers, a test program of the "
             "repository that the package does not carry: run bash scripts/bench.sh solvers in a source checkout, "
             "or give --driver")
"""The one line without ``--driver``: the package carries no test program and looks for none."""
PROBLEMS = ("P1", "P2", "P3")


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench solvers``."""
    parser.add_argument("--fmu", type=Path, default=None, metavar="PATH",
                        help="the FMU (default: $PENDULUM_FMU, the installed one, or the repository's build/)")
    parser.add_argument("--driver", type=Path, default=None, metavar="PATH",
                        help="the C driver tests/c/bench_solvers of a CMake build, built for this FMU (required; "
                             "bash scripts/bench.sh solvers builds it and gives it)")
    parser.add_argument("--out", type=Path, default=Path("out") / "bench", metavar="DIR",
                        help="output folder, created with its missing parents (default: out/bench)")
    parser.add_argument("--problems", default="P1,P2,P3",
                        help="comma-separated subset of P1,P2,P3 (default: P1,P2,P3)")
    parser.add_argument("--budget", type=float, default=30.0,
                        help="skip a Python run predicted to take longer, seconds (default: 30.0)")
    parser.add_argument("--p3-periods", type=float, default=10_000.0,
                        help="length of P3 in periods (default: 10000.0)")
    parser.add_argument("--points", type=int, default=50, help="output points a period (default: 50)")
    chosen = parser.add_mutually_exclusive_group()
    chosen.add_argument("--peers", default=",".join(PEERS), metavar="NAMES",
                        help=f"comma-separated peers to run beside the FMU's solvers (default: all, {','.join(PEERS)})")
    chosen.add_argument("--no-peers", action="store_true", help="only the FMU's solvers")
    parser.add_argument("--quick", action="store_true",
                        help="a smoke run: tolerances 1e-4 and 1e-8, P3 at most 100 periods")


def run(args: argparse.Namespace) -> int:
    """Check the options, then run the study: 0 when every run ran, 1 when one failed, 2 on bad usage."""
    from pendulum_fmu.bench.solvers import run_study
    from pendulum_fmu.cli.fields import command_line_message
    from pendulum_fmu.errors import BuildError, SimulationError, UsageError
    from pendulum_fmu.fmu.identity import fmi_version_of
    from pendulum_fmu.fmu.locate import locate_fmu
    from pendulum_fmu.output.paths import OutputError, check_output_folder

    problems = [p.strip() for p in args.problems.split(",") if p.strip()]
    if not problems or any(p not in PROBLEMS for p in problems):
        print(f"bench solvers: --problems must name P1, P2 and/or P3, got {args.problems!r}", file=sys.stderr)
        return 2
    peers = [] if args.no_peers else [p.strip() for p in args.peers.split(",") if p.strip()]
    unknown = [p for p in peers if p not in PEERS]
    if unknown or not (peers or args.no_peers):
        print(f"pendulum-fmu bench solvers: error: argument --peers: {args.peers!r} names no peer or an unknown one "
              f"({', '.join(unknown) or 'none given'}); the peers are {', '.join(PEERS)}", file=sys.stderr)
        return 2
    try:
        fmu = locate_fmu(args.fmu)
        check_output_folder(args.out)
        if fmi_version_of(fmu) != 2:
            raise UsageError("fmu", f"{str(fmu)!r} is an FMI 3.0 FMU: bench solvers drives the FMI 2.0 API from "
                                    "its C driver, give the FMI 2.0 Pendulum.fmu")
    except UsageError as error:
        print(f"pendulum-fmu bench solvers: error: {command_line_message(error, args.subparser)}", file=sys.stderr)
        return 2
    except (BuildError, OutputError) as error:
        print(f"pendulum-fmu bench solvers: error: {error}", file=sys.stderr)
        return 2
    driver = args.driver
    if driver is None:
        print(f"pendulum-fmu bench solvers: error: {NO_DRIVER}", file=sys.stderr)
        return 2
    if not driver.is_file() or not os.access(driver, os.X_OK):
        print(f"pendulum-fmu bench solvers: error: argument --driver: {str(driver)!r} is not an executable file: "
              "give the C driver tests/c/bench_solvers of a CMake build", file=sys.stderr)
        return 2
    try:
        study = run_study(fmu, driver, args.out, problems, args.budget, args.p3_periods, args.points,
                          peers, args.quick, log=print)
    except SimulationError as error:
        print(f"pendulum-fmu bench solvers: error: {error}", file=sys.stderr)
        return 1
    return 1 if study.failed else 0
