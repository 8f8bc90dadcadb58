"""Command-line argument types and the options shared by several subcommands.

Every type here raises :class:`argparse.ArgumentTypeError` with the allowed range, so
argparse prints ``pendulum-fmu simulate: error: argument --length/-L: must be ...`` and
exits with code 2: a user's mistake never shows a traceback.
"""

from __future__ import annotations

import argparse
import math
import re
from collections.abc import Callable, Sequence
from pathlib import Path

from pendulum_fmu.errors import UsageError
from pendulum_fmu.fmu.locate import locate_fmu, runnable_problem
from pendulum_fmu.output.paths import OutputError, check_output_file, check_output_folder
from pendulum_fmu.spec import CS_SOLVERS, DEFAULT_CS_SOLVER, ME_SOLVERS, SOLVERS, InitialValueProblem, Method, TimeGrid

MAX_GRID_VALUES = 100_000
"""Most values one grid axis may expand to (a guard against a typo like ``0:1:1e9``)."""

_ANGLE = re.compile(r"^\s*(?P<number>.+?)\s*(?P<unit>deg|°|rad)?\s*$", re.IGNORECASE)


def _number(text: str) -> float:
    """float(text), or ArgumentTypeError naming the text."""
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None


def _angle(text: str) -> tuple[float, bool]:
    """Parse ``80``, ``80deg`` or ``1.4rad``: (value, True if in radians), range-checked."""
    match = _ANGLE.match(text)
    try:
        value = float(match["number"]) if match else math.nan
    except ValueError:
        match = None
    if match is None:
        raise argparse.ArgumentTypeError(f"{text!r} is not an angle: write a number, optionally ending "
                                         "in deg or rad (e.g. 80, 80deg, 1.4rad)")
    in_radians = (match["unit"] or "").lower() == "rad"
    radians = value if in_radians else math.radians(value)
    if not (math.isfinite(radians) and abs(radians) <= math.pi * (1 + 1e-15)):
        raise argparse.ArgumentTypeError(f"must be a finite angle in [-180, 180] deg (or [-pi, pi] rad), "
                                         f"got {text!r}")
    return value, in_radians


def angle(text: str) -> float:
    """An angle in [-180, 180] deg: ``80``, ``80deg`` or ``1.4rad``; returns radians.

    Parameters
    ----------
    text : str
        A number, degrees unless it ends in ``rad``.

    Returns
    -------
    float
        The angle in radians.
    """
    value, in_radians = _angle(text)
    return value if in_radians else math.radians(value)


def angle_degrees(text: str) -> float:
    """The same as :func:`angle`, returning degrees (``75`` stays exactly 75.0)."""
    value, in_radians = _angle(text)
    return math.degrees(value) if in_radians else value


def finite(unit: str) -> Callable[[str], float]:
    """A type accepting any finite number (``unit`` only names it in the message)."""
    def parse(text: str) -> float:
        value = _number(text)
        if not math.isfinite(value):
            raise argparse.ArgumentTypeError(f"must be a finite number ({unit}), got {text!r}")
        return value
    parse.__name__ = f"finite number ({unit})"
    return parse


def positive(unit: str, upper: float = math.inf) -> Callable[[str], float]:
    """A type accepting a finite number in (0, upper]."""
    def parse(text: str) -> float:
        value = _number(text)
        if not (math.isfinite(value) and 0.0 < value <= upper):
            bound = f"> 0 {unit}" if math.isinf(upper) else f"in (0, {upper:g}] {unit}"
            raise argparse.ArgumentTypeError(f"must be a finite number {bound}, got {text!r}")
        return value
    parse.__name__ = f"positive number ({unit})"
    return parse


def tolerance(text: str) -> float:
    """A relative tolerance in (0, 1)."""
    value = _number(text)
    if not (math.isfinite(value) and 0.0 < value < 1.0):
        raise argparse.ArgumentTypeError(f"must be a relative tolerance in (0, 1), e.g. 1e-8, got {text!r}")
    return value


def integer(low: int, high: int) -> Callable[[str], int]:
    """A type accepting an integer in [low, high]."""
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"must be an integer in [{low}, {high}], got {text!r}") from None
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(f"must be an integer in [{low}, {high}], got {text!r}")
        return value
    parse.__name__ = f"integer in [{low}, {high}]"
    return parse


def grid(item: Callable[[str], float]) -> Callable[[str], list[float]]:
    """A type for one grid axis: comma-separated values and ``start:stop:count`` ranges.

    ``75:90:4`` is 75, 80, 85, 90 (``count`` points from ``start`` to ``stop`` inclusive);
    ``0,0.5,1`` is a list; both mix: ``0,10:80:8``. Each value is checked by ``item``.
    """
    def parse(text: str) -> list[float]:
        values: list[float] = []
        for part in text.split(","):
            fields = part.split(":")
            if len(fields) == 1:
                values.append(item(fields[0]))
                continue
            if len(fields) != 3:
                raise argparse.ArgumentTypeError(f"{part!r}: a range is start:stop:count, e.g. 75:90:16")
            first, last = item(fields[0]), item(fields[1])
            count = integer(1, MAX_GRID_VALUES)(fields[2])
            if count == 1 and first != last:
                raise argparse.ArgumentTypeError(f"{part!r}: a range of 1 point needs start == stop")
            values += [first + (last - first) * k / max(count - 1, 1) for k in range(count)]
        if len(values) > MAX_GRID_VALUES:
            raise argparse.ArgumentTypeError(f"at most {MAX_GRID_VALUES} values, got {len(values)}")
        return values
    parse.__name__ = "grid"
    return parse


def solver_list(text: str) -> list[str]:
    """Comma-separated solver names, each one of :data:`SOLVERS`."""
    names = [name.strip().lower() for name in text.split(",")]
    for name in names:
        if name not in SOLVERS:
            raise argparse.ArgumentTypeError(f"{name!r} is not a solver: choose from {', '.join(SOLVERS)}")
    return names


def output_file(*suffixes: str) -> Callable[[str], Path]:
    """A type for an output file whose suffix is one of ``suffixes`` and whose folder is writable."""
    def parse(text: str) -> Path:
        path = Path(text)
        if not path.name.lower().endswith(suffixes):
            raise argparse.ArgumentTypeError(f"the file name must end in {' or '.join(suffixes)}, got {text!r}")
        try:
            return check_output_file(path)
        except OutputError as error:
            raise argparse.ArgumentTypeError(str(error)) from None
    parse.__name__ = "output file"
    return parse


def output_folder(text: str) -> Path:
    """A type for an output folder that exists or can be created, and can be written."""
    try:
        return check_output_folder(Path(text))
    except OutputError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


def existing_file(text: str) -> Path:
    """A type for a file that must exist (a folder is named as one)."""
    path = Path(text)
    if path.is_dir():
        raise argparse.ArgumentTypeError(f"{text!r} is a folder: give a file")
    if not path.is_file():
        raise argparse.ArgumentTypeError(f"no such file: {text!r}")
    return path


def fmu_file(text: str) -> Path:
    """A type for an FMU: an existing zip archive whose ``modelDescription.xml`` is this project's
    Pendulum (FMI 2.0 or 3.0)."""
    path = existing_file(text)
    problem = runnable_problem(path)
    if problem is not None:
        raise argparse.ArgumentTypeError(problem)
    return path


# -- option groups shared by simulate, compare and animate ------------------------------------
def add_fmu_argument(parser: argparse.ArgumentParser) -> None:
    """``--fmu PATH``: which FMU to run."""
    parser.add_argument("--fmu", type=fmu_file, metavar="PATH",
                        help="the Pendulum.fmu to run, FMI 2.0 or 3.0 (default: $PENDULUM_FMU, the FMU installed "
                             "with the package, or the repository's build/, rebuilt when its sources changed)")
    parser.add_argument("--fmi-version", type=int, choices=(2, 3), default=None, metavar="{2,3}",
                        help="run the package's FMI 2.0 (default) or FMI 3.0 Pendulum.fmu; with --fmu, "
                             "that FMU's version must match")


def resolve_fmu(args: argparse.Namespace) -> None:
    """Settle ``args.fmu`` from ``--fmu`` and ``--fmi-version`` (a no-op for commands without them).

    The one place a command's FMU is found (and built when its sources changed): the command
    runs ``args.fmu`` as it is afterwards. ``--fmi-version 3`` without ``--fmu`` puts the FMI
    3.0 FMU's path in ``args.fmu``; with ``--fmu`` the file's version must be the one asked.

    Raises
    ------
    UsageError
        If the versions disagree or no FMU of the version asked is found.
    BuildError
        If CMake fails to rebuild the checkout's FMU.
    """
    if not hasattr(args, "fmi_version"):
        return
    args.fmu = locate_fmu(args.fmu, fmi_version=args.fmi_version)


def add_pendulum_arguments(parser: argparse.ArgumentParser, default_amplitude: str = "75") -> None:
    """The physical problem: amplitude, initial velocity, L and g."""
    group = parser.add_argument_group("pendulum")
    group.add_argument("-a", "--amplitude", type=angle, default=angle(default_amplitude), metavar="ANGLE",
                       help=f"initial angle from the downward vertical, in [-180, 180] deg; degrees unless it "
                            f"ends in rad: 80, 80deg, 1.4rad, --amplitude=-1.4rad (default {default_amplitude} deg)")
    group.add_argument("-w", "--omega0", type=finite("rad/s"), default=0.0, metavar="RAD_S",
                       help="initial angular velocity, rad/s (default 0: released from rest)")
    group.add_argument("-L", "--length", type=positive("m"), default=1.0, metavar="M",
                       help="length L > 0, m (default 1)")
    group.add_argument("-g", "--gravity", type=positive("m/s^2"), default=9.81, metavar="M_S2",
                       help="gravitational acceleration g > 0, m/s^2 (default 9.81)")


def add_method_arguments(parser: argparse.ArgumentParser) -> None:
    """Interface, solver and tolerance."""
    group = parser.add_argument_group("method")
    group.add_argument("-i", "--interface", choices=("CS", "ME"), type=str.upper, default=None,
                       help="CS: Co-Simulation with the FMU's own solver; ME: Model Exchange with fmpy's "
                            "CVODE (default: CS, or whatever --solver implies)")
    group.add_argument("-s", "--solver", choices=SOLVERS, type=str.lower, default=None, metavar="NAME",
                       help=f"CS: {', '.join(CS_SOLVERS)} (default rkn); ME: {', '.join(ME_SOLVERS)}")
    group.add_argument("-t", "--tolerance", type=tolerance, default=None, metavar="RTOL",
                       help="relative tolerance in (0, 1) (default: the FMU's 1e-8)")


def add_time_arguments(parser: argparse.ArgumentParser, default_periods: float) -> None:
    """Stop time in seconds or in periods, and the output density."""
    group = parser.add_argument_group("time span")
    stop = group.add_mutually_exclusive_group()
    stop.add_argument("-p", "--periods", type=positive("periods", 1e5), default=None,
                      help=f"stop time in exact periods 4K(m)/w0 (default {default_periods:g})")
    stop.add_argument("-T", "--stop-time", type=positive("s", 1e6), default=None, metavar="SECONDS",
                      help="stop time in seconds")
    group.add_argument("-n", "--points-per-period", type=integer(1, 10_000), default=50, metavar="N",
                       help="output points per period, 1-10000 (default 50)")
    parser.set_defaults(default_periods=default_periods)


def problem_from(args: argparse.Namespace) -> InitialValueProblem:
    """The :class:`InitialValueProblem` of the parsed pendulum options (``--amplitude`` parsed to rad)."""
    return InitialValueProblem(args.amplitude, args.omega0, args.length, args.gravity)


def method_from(args: argparse.Namespace) -> Method:
    """The :class:`Method` of the parsed method options (interface and solver reconciled).

    Raises
    ------
    UsageError
        If ``--solver`` is not a method of ``--interface``.
    """
    interface, solver = args.interface, args.solver
    if solver is None:
        solver = ME_SOLVERS[0] if interface == "ME" else DEFAULT_CS_SOLVER
    allowed = ME_SOLVERS if interface == "ME" else CS_SOLVERS if interface == "CS" else SOLVERS
    if solver not in allowed:
        kind = "Model Exchange" if solver in ME_SOLVERS else "Co-Simulation"
        raise UsageError("solver", f"{solver} is a {kind} method: with --interface {interface} choose from "
                                        f"{', '.join(allowed)}")
    return Method(solver, args.tolerance)


def grid_from(args: argparse.Namespace) -> TimeGrid:
    """The :class:`TimeGrid` of the parsed time options."""
    if args.stop_time is not None:
        return TimeGrid(args.stop_time, "s", args.points_per_period)
    periods = args.default_periods if args.periods is None else args.periods
    return TimeGrid(periods, "periods", args.points_per_period)


def size_field(args: argparse.Namespace) -> str:
    """The time field the user gave, for a refusal of a run too big: ``stop_time``, else
    ``periods``, else ``points_per_period`` (the default length alone always fits)."""
    if args.stop_time is not None:
        return "stop_time"
    if args.periods is not None:
        return "periods"
    return "points_per_period"


_ROLE = re.compile(r":[a-z]+:`(~?)([^`<]*?)(?:\s*<([^>]*)>)?`")
"""A Sphinx cross-reference: ``:class:`~pkg.mod.Name```, ``:func:`text <target>```."""


def plain_text(doc: str) -> str:
    """A docstring as ``--help`` shows it: Sphinx roles and double back-quotes become plain words.

    ``:class:`~pendulum_fmu.fmu.runner.FmuRunner``` becomes ``FmuRunner`` (the ``~`` keeps the
    last name), ``:mod:`pendulum_fmu.bench.speed``` stays a dotted name, ````x```` becomes ``x``.
    """
    def word(match: re.Match[str]) -> str:
        text = match[2].strip()
        return text.rsplit(".", 1)[-1] if match[1] else text
    return _ROLE.sub(word, doc).replace("``", "")


def describe(values: Sequence[float], unit: str = "") -> str:
    """Short text of a grid axis: ``75 .. 90 (16 values)``."""
    if len(values) == 1:
        return f"{values[0]:g}{unit}"
    return f"{min(values):g} .. {max(values):g}{unit} ({len(values)} values)"
