"""Which command-line flag sets which field: the library names fields, the command names flags.

A :class:`~pendulum_fmu.errors.UsageError` carries the field its API names (``theta0``,
``fmu``, ``stop_time``); the command line reports it under the flag the user typed, and puts
flags for the fields its message names in backquotes. The flag is read off the subcommand's
own parser (the option whose ``dest`` is the field, or the field's ``dest`` in :data:`DESTS`
where the two differ), so a new option needs no entry here.
"""

from __future__ import annotations

import argparse
import re

from pendulum_fmu.errors import UsageError

DESTS: dict[str, str] = {
    "theta0": "amplitude",  # the command takes the start angle in degrees as --amplitude
    "L": "length",
    "g": "gravity",
}
"""Fields whose option has another ``dest``: field -> dest."""


def _option_of(parser: argparse.ArgumentParser, dest: str) -> str | None:
    """``-L/--length`` for the option of ``parser`` (or of its subcommands) storing to ``dest``."""
    for action in parser._actions:  # argparse keeps no public list of a parser's options
        if action.dest == dest and action.option_strings:
            return "/".join(action.option_strings)
        if action.dest == dest:
            return str(action.metavar or dest).upper()
        if isinstance(action, argparse._SubParsersAction):
            for child in action.choices.values():
                found = _option_of(child, dest)
                if found is not None:
                    return found
    return None


def command_line_message(error: UsageError, parser: argparse.ArgumentParser) -> str:
    """The error as the command line says it: ``argument -L/--length: must be ...``.

    Parameters
    ----------
    error : UsageError
        What the library raised, naming a field or an environment variable.
    parser : argparse.ArgumentParser
        The subcommand's parser, whose options name the flags.

    Returns
    -------
    str
        The message under the flag that sets the field, each field it names in backquotes
        replaced by its flag; an environment variable, or a field no option sets, as the error
        names it.
    """
    message = _MENTION.sub(lambda mention: flag_of(mention.group(1), parser), error.message)
    if error.field.startswith("$"):
        return f"environment variable {error.field[1:]}: {message}"
    return f"argument {flag_of(error.field, parser)}: {message}"


_MENTION = re.compile(r"`(\w+)`")
"""A field a message names in backquotes."""


def flag_of(field: str, parser: argparse.ArgumentParser) -> str:
    """``-L/--length`` for ``L``: the option of ``parser`` that sets ``field``, else the field's name."""
    return _option_of(parser, DESTS.get(field, field)) or field
