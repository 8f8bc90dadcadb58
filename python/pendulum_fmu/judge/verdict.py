"""The judge's answer as data: one :class:`Check` per check, the :class:`Experiment` judged
against, and the :class:`Verdict` over them (with the :class:`Series` a plot draws)."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import TYPE_CHECKING, Any, Literal

import numpy as np

from pendulum_fmu.spec import InitialValueProblem

if TYPE_CHECKING:
    from pendulum_fmu.judge.experiment_files import ExperimentFile

Status = Literal["pass", "fail", "info"]
"""``info`` reports numbers without deciding (a check that does not apply, or a diagnosis)."""


@dataclass(frozen=True)
class Check:
    """One check of a result file.

    Attributes
    ----------
    name : str
        Short identifier, e.g. ``"time grid"``.
    status : {"pass", "fail", "info"}
        The check's own outcome.
    line : str
        What it found, one line for people, with its figures.
    numbers : dict
        The same figures as numbers (JSON-ready: floats, ints, strings, lists of them); the
        verdict's JSON writes them under ``"figures"``.
    """

    name: str
    status: Status
    line: str
    numbers: dict[str, Any] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        """The check as JSON-ready data: name, status, line, figures."""
        return {"name": self.name, "status": self.status, "line": self.line, "figures": self.numbers}


@dataclass(frozen=True)
class Experiment:
    """What the run was meant to compute: the problem, the interface and the tolerance.

    Attributes
    ----------
    problem : InitialValueProblem
        The pendulum: theta0, omega0 (rad, rad/s), L (m), g (m/s^2).
    interface : {"CS", "ME"}
        Co-Simulation (the FMU's own solver) or Model Exchange (the importer's solver).
    tolerance : float
        The experiment's relative tolerance (the model description's default when not given).
    tolerance_stated : bool
        True when the tolerance was given (by the caller or a file), False for the default.
    solver : str or None
        The FMU's Co-Simulation solver when given; None: the FMU's default.
    given : tuple of str
        The names set by the caller or stated by a file (the rest are the model description's
        defaults).
    start_time : float
        When the run started (the start values hold there): given as ``startTime``, else the
        model description's DefaultExperiment.
    """

    problem: InitialValueProblem
    interface: Literal["CS", "ME"]
    tolerance: float
    tolerance_stated: bool
    solver: str | None = None
    given: tuple[str, ...] = ()
    start_time: float = 0.0

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready, the problem's fields first and flat, as the verdict's JSON has them."""
        return {**asdict(self.problem), "interface": self.interface, "tolerance": self.tolerance,
                "tolerance_stated": self.tolerance_stated, "solver": self.solver, "given": list(self.given),
                "start_time": self.start_time}


@dataclass(frozen=True)
class Series:
    """The time series a verdict was made from, for a plot: nothing in it is read again.

    Attributes
    ----------
    time : numpy.ndarray
        The file's times, s.
    values : dict of str to numpy.ndarray
        The file's columns by variable (theta, omega, theta_exact, omega_exact: those it holds).
    exact_theta, exact_omega : numpy.ndarray
        The exact solution at those times (``pendulum_fmu.exact``).
    errors : dict of str to numpy.ndarray
        theta - exact theta and omega - exact omega, for the columns the file holds.
    allowed_error : dict of str to numpy.ndarray
        The bound: the largest |error| the judge allows at each time, by variable.
    exact_column_differences : dict of str to (numpy.ndarray, numpy.ndarray)
        For theta_exact and omega_exact: |column - pendulum_fmu.exact| and the difference the
        print's rounding allows, at each time.
    """

    time: np.ndarray
    values: dict[str, np.ndarray]
    exact_theta: np.ndarray
    exact_omega: np.ndarray
    errors: dict[str, np.ndarray]
    allowed_error: dict[str, np.ndarray]
    exact_column_differences: dict[str, tuple[np.ndarray, np.ndarray]]


@dataclass(frozen=True)
class Verdict:
    """The judge's verdict on one result.

    Attributes
    ----------
    passed : bool
        True when no check failed.
    line : str
        The verdict in one line: PASS or FAIL and why.
    checks : tuple of Check
        Every check, in the order they ran.
    experiment : Experiment
        What the result was judged against.
    source : str
        Where the result came from (a file name, or "DataFrame").
    columns : dict
        The file's column names that were used, by variable (``"theta"`` -> ``"pend.theta"``).
    instance : str
        The instance prefix of those columns ("" for bare names).
    experiment_file : ExperimentFile or None
        The file that stated the experiment beneath the caller's values (the result's record, a
        ``_ref.opt``, the FMU's ``.exp``); None when none did or none was read.
    series : Series or None
        The time series judged (for :func:`pendulum_fmu.judge.report.write_plot`); not in
        :meth:`to_dict`.
    """

    passed: bool
    line: str
    checks: tuple[Check, ...]
    experiment: Experiment
    source: str
    columns: dict[str, str]
    instance: str = ""
    experiment_file: ExperimentFile | None = None
    series: Series | None = field(default=None, compare=False, repr=False)

    @property
    def exit_code(self) -> int:
        """0 when passed, 1 when failed (the command line's exit status)."""
        return 0 if self.passed else 1

    def check(self, name: str) -> Check:
        """The check called ``name`` (KeyError when it did not run)."""
        for check in self.checks:
            if check.name == name:
                return check
        raise KeyError(name)

    def to_dict(self) -> dict[str, Any]:
        """Everything but the series as plain JSON-ready data."""
        return {"passed": self.passed, "verdict": self.line, "source": self.source, "columns": self.columns,
                "instance": self.instance, "experiment": self.experiment.to_dict(),
                "checks": [c.to_dict() for c in self.checks]}
