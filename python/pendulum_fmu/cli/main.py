"""The ``pendulum-fmu`` command: argparse subcommands, one module each.

Each subcommand module has ``NAME``, ``HELP``, ``DESCRIPTION``, ``EPILOG``, ``configure(parser)``
and ``run(args) -> int``, and imports its heavy dependencies (fmpy, matplotlib, Dask) inside
``run``, so ``--help`` answers at once. A user's mistake (:class:`UsageError`, or a value
argparse rejects) prints ``pendulum-fmu CMD: error: argument ...: ...`` and exits with 2;
a failed build or simulation prints its reason and exits with 1; neither shows a traceback.
"""

from __future__ import annotations

import argparse
import re
import sys
from types import ModuleType
from typing import Any, NoReturn

from pendulum_fmu import __version__
from pendulum_fmu.cli import animate, bench, compare, completion, cross_check, judge, simulate, study, suite, sweep
from pendulum_fmu.cli.arguments import resolve_fmu
from pendulum_fmu.cli.fields import command_line_message
from pendulum_fmu.cli.progress import progress_on_stderr
from pendulum_fmu.errors import BuildError, SimulationError, UsageError
from pendulum_fmu.interrupt import check as check_interrupt
from pendulum_fmu.interrupt import default_dispositions, exit_quietly_on_interrupt
from pendulum_fmu.interrupt import forget as forget_interrupt

COMMANDS: tuple[ModuleType, ...] = (simulate, compare, study, animate, sweep, bench, judge, cross_check, suite,
                                    completion)

DESCRIPTION = """\
Build, run and check Pendulum.fmu: the nonlinear pendulum theta'' + (g/L) sin(theta) = 0,
FMI 2.0 and 3.0, Co-Simulation and Model Exchange, with its exact Jacobi-elliptic solution inside.
"""
EPILOG = """\
'pendulum-fmu COMMAND --help' shows each command's options. The FMU used is --fmu PATH,
else $PENDULUM_FMU, else the one installed with the package, else the repository's build/
(rebuilt with CMake when its sources changed); --fmi-version 3 chooses the FMI 3.0 FMU.

examples:
  pendulum-fmu study
  pendulum-fmu simulate --amplitude 85 --periods 20 --out run.csv
  pendulum-fmu compare --amplitude 170 --solver rk4 --tolerance 1e-6 --out rk4.png
  pendulum-fmu animate --amplitude 120 --out pendulum.gif
  pendulum-fmu sweep --amplitudes 1:179:100 --solvers dopri5,rkn,cvode --out out/sweep
  pendulum-fmu bench sweep
  pendulum-fmu judge result.csv --interface ME --start tolerance=1e-6
  pendulum-fmu cross-check out/cross-check
  pendulum-fmu suite run --engine fmpy --out out/suite
  eval "$(pendulum-fmu completion bash)"          # complete commands and options in bash
"""


class _Formatter(argparse.RawDescriptionHelpFormatter):
    """Keep the descriptions' line breaks; a little more room for option names."""

    def __init__(self, prog: str) -> None:
        super().__init__(prog, max_help_position=34)


NEGATIVE_NUMBER = re.compile(r"^-(\d|\.\d)|^-(inf|infinity|nan)$", re.IGNORECASE)
"""An argument that is a value, not an option: a minus, then a digit (-1, -.5, -1e-6, -1.4rad,
-1:1:3, -10,20) or -inf / -nan. No option of this command starts with a digit."""


class OneLineParser(argparse.ArgumentParser):
    """An argument parser whose errors are one line: what is wrong, and where the help is.

    Negative numbers are values (``-t -1e-6``, ``-a -1.4rad``, ``-w -1:1:3``), as ``-1`` is:
    argparse's own pattern knows only ``-1`` and ``-1.5`` and says "expected one argument".
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = NEGATIVE_NUMBER

    def _parse_optional(self, arg_string: str) -> Any:
        """A negative number is a value even where it starts like an option (``-inf`` like ``-i nf``)."""
        if NEGATIVE_NUMBER.match(arg_string) and not self._has_negative_number_optionals:
            return None
        return super()._parse_optional(arg_string)

    def error(self, message: str) -> NoReturn:
        """Print ``PROG: error: MESSAGE (see PROG --help)`` to stderr and exit with 2."""
        self.exit(2, f"{self.prog}: error: {message} (see '{self.prog} --help')\n")


def build_parser() -> argparse.ArgumentParser:
    """The full parser, every subcommand configured."""
    parser = OneLineParser(prog="pendulum-fmu", description=DESCRIPTION, epilog=EPILOG, formatter_class=_Formatter)
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    parser.set_defaults(root_parser=parser)  # for 'completion', which walks the whole tree
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", title="commands", required=True)
    for module in COMMANDS:
        sub = commands.add_parser(module.NAME, help=module.HELP, description=module.DESCRIPTION,
                                  epilog=module.EPILOG, formatter_class=_Formatter)
        module.configure(sub)
        sub.set_defaults(handler=module.run)
        if sub.get_default("subparser") is None:
            sub.set_defaults(subparser=sub)
    return parser


def _unexpected(error: Exception) -> str:
    """One line for an error no check foresaw: its kind, its text, and a request to report it."""
    if isinstance(error, OSError) and error.strerror:
        return f"{error.strerror}" + (f": {error.filename!r}" if error.filename else "")
    text = " ".join(str(error).split()) or "no message"
    return f"{type(error).__name__}: {text} (unexpected: please report it with the command that caused it)"


def main(argv: list[str] | None = None) -> int:
    """Run ``pendulum-fmu COMMAND [options]``, the library's progress lines on stderr.

    Parameters
    ----------
    argv : list of str, optional
        Arguments without the program name (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code: 0 done, 1 a build or run failed, 2 a bad argument, 130 interrupted.
        argparse's own errors and ``--help`` leave through ``SystemExit`` as usual.
    """
    default_dispositions()  # Ctrl-C stops the command even if SIGINT was inherited as ignored
    arguments = sys.argv[1:] if argv is None else list(argv)
    try:
        check_interrupt()  # one that came during the imports and was swallowed there
    except KeyboardInterrupt:
        forget_interrupt()
        print(f"\npendulum-fmu {' '.join(arguments[:2])}: interrupted", file=sys.stderr)
        return 130
    except Exception as error:  # noqa: BLE001 -- one line, never a traceback
        print(f"pendulum-fmu {' '.join(arguments[:2])}: error: {_unexpected(error)}", file=sys.stderr)
        return 1
    try:
        parser = build_parser()
        args = parser.parse_args(arguments)
    except KeyboardInterrupt:
        forget_interrupt()
        print("\npendulum-fmu: interrupted", file=sys.stderr)
        return 130
    subparser: argparse.ArgumentParser = args.subparser
    hint = "; run the same command again to resume" if args.command == "sweep" else ""
    try:
        with progress_on_stderr():  # the library's progress lines (a build starting, a long run's estimate)
            resolve_fmu(args)
            check_interrupt()
            code = int(args.handler(args))
        check_interrupt()  # one a garbage collector's callback could not raise (interrupt._quiet_unraisable)
        if argv is None:   # the program itself: an interrupt from here to its exit is one line too
            exit_quietly_on_interrupt(f"\n{subparser.prog}: interrupted{hint}\n")
        return code
    except UsageError as error:
        subparser.error(command_line_message(error, subparser))  # one line: "error: argument ...", exit 2
    except (BuildError, SimulationError) as error:
        print(f"{subparser.prog}: error: {error}", file=sys.stderr)
        return 1
    except OSError as error:  # a file that vanished or a full disk, after the checks passed
        where = f": {error.filename!r}" if error.filename else ""
        print(f"{subparser.prog}: error: {error.strerror or error}{where}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        forget_interrupt()
        print(f"\n{subparser.prog}: interrupted{hint}", file=sys.stderr)
        return 130
    except Exception as error:  # noqa: BLE001 -- the promise is one line, never a traceback
        print(f"{subparser.prog}: error: {_unexpected(error)}", file=sys.stderr)
        return 1
    return 0  # not reached: subparser.error exits
