"""Exceptions that separate a user's mistake from a failure of the model or the machine."""

from __future__ import annotations


class UsageError(ValueError):
    """A bad argument: the message names the argument and the allowed range.

    The command line turns it into an argparse-style ``error:`` line and exit code 2,
    never a traceback. The Python API raises it for the same mistakes.

    Parameters
    ----------
    argument : str
        The argument as the user wrote it, e.g. ``"-L/--length"``, or ``"$NAME"`` for an
        environment variable.
    message : str
        What is wrong and what is allowed.
    """

    def __init__(self, argument: str, message: str) -> None:
        where = f"environment variable {argument[1:]}" if argument.startswith("$") else f"argument {argument}"
        super().__init__(f"{where}: {message}")
        self.argument = argument
        self.message = message


class SimulationError(RuntimeError):
    """The FMU or the importer's solver failed on inputs that passed validation."""


class BuildError(RuntimeError):
    """CMake could not build ``Pendulum.fmu``; the message ends with CMake's output."""
