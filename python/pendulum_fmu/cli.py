"""The ``pendulum-fmu`` command: subcommands that each hand over to one module's ``main``."""

from __future__ import annotations

import sys
from typing import Callable


def _study(argv: list[str]) -> int:
    from .study import main
    return main(argv)


def _bench_exact(argv: list[str]) -> int:
    from .bench_exact import main
    return main(argv)


SUBCOMMANDS: dict[str, tuple[Callable[[list[str]], int], str]] = {
    "study": (_study, "build the FMU and run the seed's study (plots, CSV, table, report)"),
    "bench-exact": (_bench_exact, "time the FMU's exact evaluation in C against scipy's ellipj"),
}


def main(argv: list[str] | None = None) -> int:
    """Dispatch ``pendulum-fmu SUBCOMMAND [options]``.

    Parameters
    ----------
    argv : list of str, optional
        Arguments without the program name (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit code.
    """
    args = sys.argv[1:] if argv is None else argv
    if not args or args[0] in ("-h", "--help") or args[0] not in SUBCOMMANDS:
        lines = ["usage: pendulum-fmu SUBCOMMAND [options]   (SUBCOMMAND --help for its options)", ""]
        lines += [f"  {name:<12} {text}" for name, (_, text) in SUBCOMMANDS.items()]
        print("\n".join(lines), file=sys.stdout if args and args[0] in ("-h", "--help") else sys.stderr)
        return 0 if args and args[0] in ("-h", "--help") else 2
    command, _ = SUBCOMMANDS[args[0]]
    return command(args[1:])
