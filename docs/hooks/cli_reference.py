"""MkDocs hook: writes the command line reference (``cli.md``) from the argparse parsers.

The page holds the marker ``<!-- cli-reference -->``; this hook replaces it with the
``--help`` of ``pendulum-fmu`` and of every subcommand, as the program prints it, so the
reference cannot drift from the code.
"""

from __future__ import annotations

import argparse
import os
from typing import Any

MARKER = "<!-- cli-reference -->"


def _subcommands(parser: argparse.ArgumentParser) -> dict[str, argparse.ArgumentParser]:
    for action in parser._actions:  # noqa: SLF001 - argparse keeps its subparsers here only
        if isinstance(action, argparse._SubParsersAction):  # noqa: SLF001
            return dict(action.choices)
    return {}


def _help(parser: argparse.ArgumentParser) -> str:
    return parser.format_help().rstrip()


def reference() -> str:
    """The Markdown of the reference: one section per command, its ``--help`` verbatim."""
    os.environ["COLUMNS"] = "80"  # argparse wraps at the terminal width; the page shows 80 columns
    from pendulum_fmu.cli.main import build_parser

    top = build_parser()
    sections = [f"## pendulum-fmu\n\n```text\n{_help(top)}\n```\n"]
    for name, sub in _subcommands(top).items():
        sections.append(f"## pendulum-fmu {name}\n\n```text\n{_help(sub)}\n```\n")
        for inner, leaf in _subcommands(sub).items():
            sections.append(f"### pendulum-fmu {name} {inner}\n\n```text\n{_help(leaf)}\n```\n")
    return "\n".join(sections)


def on_page_markdown(markdown: str, page: Any, **_: Any) -> str:
    """Fill the marker of ``cli.md``; a ``cli.md`` without the marker is an error."""
    if page.file.src_uri != "cli.md":
        return markdown
    if MARKER not in markdown:
        raise ValueError(f"cli.md lost its marker {MARKER}")
    return markdown.replace(MARKER, reference())
