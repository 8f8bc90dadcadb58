"""The judge's answer as data: one :class:`Check` per check, and the :class:`Verdict` over them."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from typing import Any, Literal

Status = Literal["pass", "fail", "info"]
"""``info`` reports figures without deciding (a check that does not apply, or a diagnosis)."""


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
    figures : dict
        The same figures as numbers (JSON-ready: floats, ints, strings, lists of them).
    """

    name: str
    status: Status
    line: str
    figures: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Experiment:
    """What the run was meant to compute: the problem, the interface and the tolerance.

    Attributes
    ----------
    theta0, omega0 : float
        Start values, rad and rad/s.
    L, g : float
        Length (m) and gravitational acceleration (m/s^2).
    interface : {"CS", "ME"}
        Co-Simulation (the FMU's own solver) or Model Exchange (the importer's solver).
    tolerance : float
        The experiment's relative tolerance (the model description's default when not given).
    tolerance_stated : bool
        True when the tolerance was given (``--start tolerance=...``), False for the default.
    solver : str or None
        The FMU's Co-Simulation solver when given; None: the FMU's default.
    start_time : float
        When the run started (the start values hold there): ``--start startTime=...``, else the
        model description's DefaultExperiment.
    given : tuple of str
        The names set by the caller (the rest are the model description's defaults).
    """

    theta0: float
    omega0: float
    L: float
    g: float
    interface: Literal["CS", "ME"]
    tolerance: float
    tolerance_stated: bool
    solver: str | None = None
    given: tuple[str, ...] = ()
    start_time: float = 0.0

    @property
    def w0(self) -> float:
        """sqrt(g / L), rad/s."""
        return float((self.g / self.L) ** 0.5)


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
    """

    passed: bool
    line: str
    checks: tuple[Check, ...]
    experiment: Experiment
    source: str
    columns: dict[str, str]
    instance: str = ""

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
        """Everything as plain JSON-ready data."""
        return {"passed": self.passed, "verdict": self.line, "source": self.source, "columns": self.columns,
                "instance": self.instance,
                "experiment": asdict(self.experiment), "checks": [asdict(c) for c in self.checks]}
