"""Exceptions that separate a user's mistake from a failure of the model or the machine."""

from __future__ import annotations


class UsageError(ValueError):
    """A bad argument: the message names the field and the allowed range.

    The library names the field as its own API does (``"theta0"``, ``"fmu"``, ``"stop_time"``),
    or ``"$NAME"`` for an environment variable, never a command-line flag; the command line
    alone knows which flag sets a field (``cli/fields.py`` maps it to one, e.g. ``fmu`` to
    ``--fmu``) and prints an argparse-style ``error:`` line with exit code 2, never a traceback.
    A message that points at another field writes its name in backquotes (``lower `fps```):
    the command line puts the flag there (``lower --fps``).

    Parameters
    ----------
    field : str
        The field or parameter that is wrong, e.g. ``"L"``, or ``"$NAME"`` for an environment
        variable.
    message : str
        What is wrong and what is allowed; other fields in backquotes.
    """

    def __init__(self, field: str, message: str) -> None:
        where = f"environment variable {field[1:]}" if field.startswith("$") else f"argument {field}"
        super().__init__(f"{where}: {message}")
        self.field = field
        self.message = message


class SimulationError(RuntimeError):
    """The FMU or the importer's solver failed on inputs that passed validation."""


class BuildError(RuntimeError):
    """CMake could not build ``Pendulum.fmu``; the message ends with CMake's output."""
