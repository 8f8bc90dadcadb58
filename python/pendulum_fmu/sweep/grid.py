"""A sweep's parameter grid, one point per run, and the columns of its result table."""

from __future__ import annotations

import itertools
import math
from dataclasses import astuple, dataclass, fields
from typing import Any

from pendulum_fmu.spec import DEFAULT_CS_SOLVER, InitialValueProblem, Method, TimeGrid

Key = tuple[float, float, float, float, str, float, float, int]
"""A run's identity: its input values, exactly (used to skip runs already written)."""


@dataclass(frozen=True)
class SweepPoint:
    """The inputs of one run of a sweep.

    Attributes
    ----------
    amplitude_deg : float
        theta(0), deg.
    omega0 : float
        theta'(0), rad/s.
    length, gravity : float
        L (m) and g (m/s^2).
    solver : str
        A name of :data:`~pendulum_fmu.spec.SOLVERS`.
    tolerance : float
        Relative tolerance.
    periods : float
        Stop time in exact periods.
    points_per_period : int
        Output points per period (the error is measured at them).
    """

    amplitude_deg: float
    omega0: float
    length: float
    gravity: float
    solver: str
    tolerance: float
    periods: float
    points_per_period: int

    @property
    def key(self) -> Key:
        """The tuple of inputs, in field order."""
        return astuple(self)

    def problem(self) -> InitialValueProblem:
        """The problem to run."""
        return InitialValueProblem.from_degrees(self.amplitude_deg, self.omega0, self.length, self.gravity)

    def method(self) -> Method:
        """The solver and tolerance."""
        return Method(self.solver, self.tolerance)

    def grid(self) -> TimeGrid:
        """The output points."""
        return TimeGrid(self.periods, "periods", self.points_per_period)


INPUT_COLUMNS: dict[str, str] = {
    "amplitude_deg": "amplitude_deg",
    "omega0_rad_s": "omega0",
    "length_m": "length",
    "gravity_m_s2": "gravity",
    "solver": "solver",
    "tolerance": "tolerance",
    "periods": "periods",
    "points_per_period": "points_per_period",
}
"""Table column -> :class:`SweepPoint` field, for the inputs."""

OUTPUT_COLUMNS: tuple[str, ...] = (
    "interface",           # CS or ME
    "period_s",            # the FMU's exact period output
    "period_ratio",        # period / T0, T0 = 2 pi sqrt(L/g)
    "measured_period_s",   # from the numerical theta's downward zero crossings (NaN in rotation)
    "stop_time_s",
    "max_error_rad",       # max |theta - theta_exact| over the output points
    "max_omega_error_rad_s",
    "final_error_rad",     # |theta - theta_exact| at the stop time
    "steps",               # CS solver counters (empty in ME)
    "rejected_steps",
    "rhs_evaluations",
    "wall_time_s",         # seconds for the run on its worker: the cost
    "status",              # "ok", or why the run failed
    "fmu_warning",         # what the FMU logged with status fmi2Warning during the run ("; "-joined), or empty
)

COLUMNS: tuple[str, ...] = tuple(INPUT_COLUMNS) + OUTPUT_COLUMNS
COLUMN_KINDS: dict[str, str] = {column: "float" for column in COLUMNS} | {
    "solver": "str", "interface": "str", "status": "str", "fmu_warning": "str",
    "points_per_period": "int", "steps": "int", "rejected_steps": "int", "rhs_evaluations": "int"}
"""The value type of every column: ``float``, ``int`` (may be empty) or ``str``."""
TIMING_COLUMNS: tuple[str, ...] = ("wall_time_s",)
"""Columns that differ between two runs of the same sweep (everything else is reproducible)."""

_POINT_TYPES = {f.name: f.type for f in fields(SweepPoint)}


def point_of(row: dict[str, Any]) -> SweepPoint:
    """The :class:`SweepPoint` of a table row (values may be strings, as read from CSV)."""
    values: dict[str, Any] = {}
    for column, name in INPUT_COLUMNS.items():
        kind = _POINT_TYPES[name]
        raw = row[column]
        values[name] = raw if kind == "str" else int(raw) if kind == "int" else float(raw)
    return SweepPoint(**values)


@dataclass(frozen=True)
class SweepGrid:
    """The Cartesian product of parameter values, in a fixed order.

    Attributes
    ----------
    amplitudes_deg, omega0s, lengths, gravities : tuple of float
        Values of each axis.
    solvers : tuple of str
        Solver names.
    tolerances : tuple of float
        Relative tolerances.
    periods : float
        Stop time of every run, in exact periods.
    points_per_period : int
        Output points per period.
    """

    amplitudes_deg: tuple[float, ...]
    omega0s: tuple[float, ...] = (0.0,)
    lengths: tuple[float, ...] = (1.0,)
    gravities: tuple[float, ...] = (9.81,)
    solvers: tuple[str, ...] = (DEFAULT_CS_SOLVER,)
    tolerances: tuple[float, ...] = (1e-8,)
    periods: float = 10.0
    points_per_period: int = 50

    def points(self) -> list[SweepPoint]:
        """Every run, solver and tolerance outermost, amplitude innermost; duplicates dropped."""
        product = itertools.product(self.solvers, self.tolerances, self.gravities, self.lengths, self.omega0s,
                                    self.amplitudes_deg)
        unique = dict.fromkeys(SweepPoint(a, w, L, g, s, t, self.periods, self.points_per_period)
                               for s, t, g, L, w, a in product)
        return list(unique)

    def __len__(self) -> int:
        """The number of distinct runs, without building them (a product of distinct values per axis)."""
        return math.prod(len(set(axis)) for axis in (self.solvers, self.tolerances, self.gravities, self.lengths,
                                                     self.omega0s, self.amplitudes_deg))
