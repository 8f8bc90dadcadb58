"""The sweep's journal: rows appended as runs finish, read back to resume an interrupted sweep.

A CSV file with the table's columns. Floats are written with ``repr`` so a point read back
compares equal to the point of the grid; a row cut short by an interruption (or any line
that does not parse) is ignored, so its run is simply done again.
"""

from __future__ import annotations

import csv
from collections.abc import Iterable
from pathlib import Path
from typing import Any, TextIO

from pendulum_fmu.sweep.grid import COLUMN_KINDS, COLUMNS, Key, point_of


def _cell(value: Any) -> str:
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)
    return str(value)


def _parse(column: str, text: str) -> Any:
    """A journal cell back to its value: int, float, str or None (empty)."""
    kind = COLUMN_KINDS[column]
    if kind == "str":
        return text
    if text == "":
        return None
    return int(text) if kind == "int" else float(text)


def read_journal(path: Path) -> dict[Key, dict[str, Any]]:
    """The complete rows of a journal, by run key (later rows win).

    Parameters
    ----------
    path : Path
        The journal; a missing file or a header of other columns reads as empty.

    Returns
    -------
    dict
        Run key -> row (column -> value).
    """
    rows: dict[Key, dict[str, Any]] = {}
    if not path.is_file():
        return rows
    with path.open(newline="") as file:
        lines = file.read().split("\n")
    if not lines or lines[0].split(",") != list(COLUMNS):
        return rows
    complete = lines[1:-1] if lines[-1] != "" else lines[1:]  # no newline at the end: cut short
    for fields in csv.reader(line for line in complete if line):
        if len(fields) != len(COLUMNS):
            continue
        try:
            row = {column: _parse(column, text) for column, text in zip(COLUMNS, fields, strict=True)}
            rows[point_of(row).key] = row
        except (ValueError, TypeError):
            continue
    return rows


class Journal:
    """Append rows to a journal, starting it with a header if it is new or unreadable.

    Parameters
    ----------
    path : Path
        The journal file.
    keep : iterable of dict
        Rows to write first when the journal has to be restarted (those read from it).
    restart : bool
        Start the journal afresh (with ``keep`` only) even if it could be appended to.
    """

    def __init__(self, path: Path, keep: Iterable[dict[str, Any]] = (), restart: bool = False) -> None:
        path.parent.mkdir(parents=True, exist_ok=True)
        text = "" if restart or not path.is_file() else path.read_text()
        # a new or foreign file, or a row cut short: rewrite the good rows rather than append
        fresh = text.split("\n", 1)[0].split(",") != list(COLUMNS) or not text.endswith("\n")
        self._file: TextIO = path.open("w" if fresh else "a", newline="")
        self._writer = csv.writer(self._file, lineterminator="\n")
        if fresh:
            self._writer.writerow(COLUMNS)
            self.append(keep)

    def append(self, rows: Iterable[dict[str, Any]]) -> None:
        """Write rows and flush them to disk."""
        for row in rows:
            self._writer.writerow([_cell(row[column]) for column in COLUMNS])
        self._file.flush()

    def close(self) -> None:
        """Close the file."""
        self._file.close()
