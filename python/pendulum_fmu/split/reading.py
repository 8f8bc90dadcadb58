"""Read a coupled result: Body's columns through the judge's reader (any instance prefix it knows).

The split system's file holds Body's ``theta`` and ``omega`` (and ``theta_exact``,
``omega_exact`` when the engine records them) beside Gravity's ``theta`` input and ``alpha``
output. Gravity's ``theta`` makes two instances with a ``theta`` column: Body is the one with
``omega``.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from pendulum_fmu.judge.reading import ReadError, Result, read_result

_OMEGA = re.compile(r"^\s*[\"']?(?:(?P<instance>[^\"']*?)(?:::|\.|/))?omega\b")


def _instance_with_omega(path: Path) -> str | None:
    """The instance prefix of the first ``omega`` column in the file's header, or None."""
    try:
        with path.open(encoding="utf-8", errors="replace") as stream:
            header = next((line for line in stream if line.strip() and not line.lstrip().startswith("#")), "")
    except OSError:
        return None
    for cell in re.split(r"[,;\t]", header):
        match = _OMEGA.match(cell)
        if match:
            return (match.group("instance") or "").strip("{}")
    return None


def read_coupled(data: Any, instance: str | None = None) -> Result:
    """Body's outputs from a coupled result (a CSV or Parquet path, or a table).

    Parameters
    ----------
    data : str, Path, pandas.DataFrame, numpy structured array or mapping
        What :func:`pendulum_fmu.judge.reading.read_result` reads.
    instance : str, optional
        Body's instance name; by default the only instance with ``theta``, else the one with
        ``omega``.

    Returns
    -------
    Result
        With at least ``theta``.

    Raises
    ------
    ReadError
        One line, when the file cannot be read or has no Body columns.
    """
    try:
        return read_result(data, instance)
    except ReadError as error:
        if instance is not None or "several instances" not in str(error) or not isinstance(data, (str, Path)):
            raise
        body = _instance_with_omega(Path(data))
        if body is None:
            raise
        return read_result(data, body)
