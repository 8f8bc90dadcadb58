"""The suite's cases: the hard cases of ``Pendulum.fmu`` (read from ``cases.csv``, which CMake
also reads to put them in the FMUs) and the split pendulum's SSP at a sweep of macro steps."""

from __future__ import annotations

import csv
import fnmatch
import math
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Literal

from pendulum_fmu.errors import UsageError

DATA = Path(__file__).with_name("cases.csv")
"""The one list of the Pendulum cases: the registry here and the FMUs' validation experiments."""
SPLIT_STEPS: tuple[float, ...] = (0.1, 0.05, 0.02)
"""The macro steps H of the split pendulum's cases."""
SPLIT_STOP = 10.0
"""Their stop time, s (from 0)."""
NUMBERS = ("theta", "omega", "L", "g", "startTime", "stopTime", "interval", "tolerance")

Kind = Literal["pendulum", "split"]


@dataclass(frozen=True)
class Case:
    """One experiment of the suite.

    Attributes
    ----------
    name : str
        Unique, e.g. ``cs2-tolerance``; the JUnit test case's name and the case folder's.
    fmi : {"2.0", "3.0"}
    interface : {"cs", "me"}
        Co-Simulation or Model Exchange (the split cases are Co-Simulation).
    kind : {"pendulum", "split"}
        ``Pendulum.fmu`` or the split pendulum's ``PendulumSplit.ssp``.
    start_values : dict
        theta, omega (rad, rad/s), L (m), g (m/s^2), set before initialization.
    start, stop, interval, tolerance : float
        The experiment: start and stop time, output interval (the macro step for the split
        cases), relative tolerance.
    catches : str
        What an importer gets wrong that this case shows, in one line.
    """

    name: str
    fmi: str
    interface: str
    kind: Kind
    start: float
    stop: float
    interval: float
    tolerance: float
    catches: str
    start_values: dict[str, float] = field(default_factory=dict)

    @property
    def fmi_major(self) -> int:
        """2 or 3."""
        return int(self.fmi[0])

    def describe(self) -> str:
        """``name  FMI 2.0  CS  what it catches``: the line of ``suite list``."""
        return f"{self.name:26s} FMI {self.fmi}  {self.interface.upper()}  {self.catches}"


def _number(text: str, what: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(f"{DATA.name}: {what} {text!r} is not finite")
    return value


@lru_cache(maxsize=1)
def read_data(path: Path = DATA) -> tuple[str, tuple[Case, ...]]:
    """The suite's version and its Pendulum cases, as ``cases.csv`` lists them.

    Raises
    ------
    ValueError
        A malformed line, a repeated name, or a start time not before the stop time.
    """
    lines = [line for line in path.read_text().splitlines() if line.strip() and not line.startswith("#")]
    key, _, version = lines[0].partition(";")
    if key != "version" or not version:
        raise ValueError(f"{path.name}: the first line must be 'version;N'")
    rows = list(csv.DictReader(lines[1:], delimiter=";"))
    cases = []
    for row in rows:
        if None in row or any(value is None for value in row.values()):
            raise ValueError(f"{path.name}: line of {row.get('name')!r} has the wrong number of fields")
        numbers = {name: _number(row[name], f"{row['name']}'s {name}") for name in NUMBERS}
        if not numbers["stopTime"] > numbers["startTime"] or numbers["interval"] <= 0 or numbers["tolerance"] <= 0:
            raise ValueError(f"{path.name}: {row['name']}: needs startTime < stopTime, interval > 0, tolerance > 0")
        if row["fmi"] not in ("2.0", "3.0") or row["interface"] not in ("cs", "me"):
            raise ValueError(f"{path.name}: {row['name']}: fmi is 2.0 or 3.0, interface cs or me")
        cases.append(Case(row["name"], row["fmi"], row["interface"], "pendulum", numbers["startTime"],
                          numbers["stopTime"], numbers["interval"], numbers["tolerance"], row["catches"],
                          {name: numbers[name] for name in ("theta", "omega", "L", "g")}))
    names = [case.name for case in cases]
    if len(set(names)) != len(names):
        raise ValueError(f"{path.name}: a case name is repeated")
    return version, tuple(cases)


def split_cases() -> tuple[Case, ...]:
    """The split pendulum's SSP, FMI 2.0 and 3.0, at each macro step of :data:`SPLIT_STEPS`."""
    return tuple(Case(f"split{fmi[0]}-H{step:g}", fmi, "cs", "split", 0.0, SPLIT_STOP, step, 0.0,
                      f"a master's coupling at macro step H = {step:g} s: its scheme and hold as it claims, "
                      "rows labelled with their own time, inputs from the start values")
                 for fmi in ("2.0", "3.0") for step in SPLIT_STEPS)


def suite_version() -> str:
    """The suite's version (``cases.csv``'s first line): results of one version compare."""
    return read_data()[0]


def all_cases() -> tuple[Case, ...]:
    """Every case: the Pendulum cases, then the split ones."""
    return read_data()[1] + split_cases()


def select(patterns: str | None, kinds: tuple[Kind, ...] = ("pendulum", "split")) -> list[Case]:
    """The cases whose name matches one of the comma-separated shell patterns (all when None).

    Raises
    ------
    UsageError
        When a pattern matches no case (field ``cases``).
    """
    cases = [case for case in all_cases() if case.kind in kinds]
    if patterns is None:
        return cases
    chosen: list[Case] = []
    for pattern in (p.strip() for p in patterns.split(",") if p.strip()):
        matched = [case for case in cases if fnmatch.fnmatchcase(case.name, pattern)]
        if not matched:
            raise UsageError("cases", f"{pattern!r} matches no case (see 'pendulum-fmu suite list')")
        chosen += [case for case in matched if case not in chosen]
    return chosen
