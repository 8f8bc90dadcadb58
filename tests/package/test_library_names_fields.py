"""The library names the fields of its API in a UsageError; only ``cli/`` knows the flags.

A ``UsageError`` raised outside ``python/pendulum_fmu/cli/`` names the field its Python API
uses (``fmu``, ``periods``, ``theta0``) or ``$ENVVAR``, never a command-line flag (``--fmu``,
``-p/--periods``) nor a metavar (``RESULT``): ``cli/fields.py`` maps the field to the flag the
user typed. The checker reads the code (its syntax tree) and is first run on an example with
each kind of mistake, so that a checker which finds nothing cannot pass unnoticed.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[2] / "python" / "pendulum_fmu"

METAVAR = re.compile(r"[A-Z][A-Z0-9_]+")
"""An upper-case metavar (``RESULT``, ``PATH``); a one-letter field such as ``L`` is a field."""


def _first_text(call: ast.Call) -> str | None:
    """The first argument's text when it is a string literal, or the literal start of an f-string."""
    if not call.args:
        return None
    first = call.args[0]
    if isinstance(first, ast.Constant) and isinstance(first.value, str):
        return first.value
    if isinstance(first, ast.JoinedStr) and first.values and isinstance(first.values[0], ast.Constant):
        return str(first.values[0].value)
    return None


def flag_fields(source: str, name: str = "<example>") -> list[str]:
    """``file:line: "--fmu"`` for each UsageError in ``source`` whose field is a flag or a metavar."""
    found = []
    for node in ast.walk(ast.parse(source)):
        if not isinstance(node, ast.Call):
            continue
        called = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", None)
        text = _first_text(node) if called == "UsageError" else None
        if text is not None and (text.startswith("-") or METAVAR.fullmatch(text)):
            found.append(f"{name}:{node.lineno}: {text!r}")
    return found


def test_the_checker_finds_flags_and_metavars_and_passes_fields() -> None:
    example = '''
raise UsageError("--fmu", "no such file")
raise errors.UsageError("-p/--periods", "too long")
raise UsageError("RESULT", "unreadable")
raise UsageError(f"--{name}", "bad")
raise UsageError("fmu", "no such file: pass `fmu` PATH")
raise UsageError("L", "must be > 0")
raise UsageError("$PENDULUM_FMU", "no such file")
raise UsageError(field, "chosen by the caller")
'''
    assert flag_fields(example) == ["<example>:2: '--fmu'", "<example>:3: '-p/--periods'",
                                    "<example>:4: 'RESULT'", "<example>:5: '--'"]


def test_no_usage_error_outside_cli_names_a_flag_or_a_metavar() -> None:
    files = [path for path in sorted(PACKAGE.rglob("*.py")) if "cli" not in path.relative_to(PACKAGE).parts]
    assert len(files) > 50  # the package, not an empty folder
    found = [hit for path in files
             for hit in flag_fields(path.read_text(encoding="utf-8"), str(path.relative_to(PACKAGE)))]
    assert found == [], "a UsageError outside cli/ names a flag (name the API's field; cli/fields.py maps it):\n" \
                        + "\n".join(found)
