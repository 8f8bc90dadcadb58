"""What every engine run leaves: the CSV columns, the writer, and the error an engine reports."""

from __future__ import annotations

import csv
from pathlib import Path

COLUMNS: tuple[str, ...] = ("Body.theta", "Body.omega", "Body.theta_exact", "Body.omega_exact", "Gravity.alpha")
"""The outputs every engine run records, named instance.variable."""


class EngineError(RuntimeError):
    """An engine could not run the system: the engine's own message."""


def write_columns(path: Path, times: list[float], columns: dict[str, list[float]]) -> None:
    """A CSV of ``time`` and :data:`COLUMNS` in full precision (``repr`` of each double)."""
    with open(path, "w", newline="") as stream:
        writer = csv.writer(stream)
        writer.writerow(["time", *COLUMNS])
        for k, t in enumerate(times):
            writer.writerow([repr(float(t)), *(repr(float(columns[name][k])) for name in COLUMNS)])
