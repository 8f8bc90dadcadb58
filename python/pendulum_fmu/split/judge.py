"""Judge a coupled result of the split pendulum: three answers, kept apart.

- **Conformance**: is it a correct co-simulation of the SSP's system? It fails only for a defect
  found, each named with its evidence (:mod:`~pendulum_fmu.split.grid`: rows out of order,
  doubled, missing; :mod:`~pendulum_fmu.split.diagnosis`: rows labelled early or late, start
  values other than the SSP's; :mod:`~pendulum_fmu.split.inputs`: a wrong sign, a wrong
  connection, a parameter mismatch between the FMUs, inputs stale by k exchanges, steps out of
  order, a dropped connection). Variable and decimated grids are legal.
- **Identification**: which reference master it reproduces, to round-off plus the print's
  resolution, or "a master of its own" (:mod:`~pendulum_fmu.split.identify`); never a failure.
- **Accuracy**: its error against the exact pendulum, where, its growth, its rank among the
  reference masters at the same H, and over several runs the observed order
  (:mod:`~pendulum_fmu.split.accuracy`). It decides pass or fail only against what the caller
  states: a largest error, an order, the master the run implements.

::

    from pendulum_fmu.split.judge import judge_split, judge_runs
    verdict = judge_split("engine.csv")
    print(verdict.summary)                 # conformant; behaves as ...; error ... rad at H = ...
    runs = judge_runs(["h1.csv", "h2.csv", "h3.csv"], order=1.0)
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from pendulum_fmu.spec import InitialValueProblem
from pendulum_fmu.split.accuracy import Accuracy, Order, accuracy, observed_order
from pendulum_fmu.split.diagnosis import Finding, label_finding, label_shift, start_finding
from pendulum_fmu.split.grid import read_grid
from pendulum_fmu.split.identify import Identification, identify
from pendulum_fmu.split.inputs import law_findings, read_law
from pendulum_fmu.split.pair import DEFAULT_PROBLEM
from pendulum_fmu.split.reading import read_coupled

ORDER_SLACK = 0.2
"""``--order P`` holds when the observed order is at least P minus this."""


@dataclass(frozen=True)
class Conformance:
    """Is the file a correct co-simulation of the SSP's system?

    Attributes
    ----------
    findings : list of Finding
        The defects found, each with its evidence (none: conformant).
    exchange : str
        What the inputs show of the master's exchange ("" when not read).
    """

    findings: list[Finding] = field(default_factory=list)
    exchange: str = ""

    @property
    def passed(self) -> bool:
        """No defect found."""
        return not self.findings


@dataclass(frozen=True)
class Criterion:
    """A pass/fail test of accuracy the caller stated: ``max-error``, ``order`` or ``master``."""

    name: str
    passed: bool
    line: str


@dataclass(frozen=True)
class SplitVerdict:
    """The judge's three answers for one coupled result.

    Attributes
    ----------
    source : str
        The file judged.
    rows : int
        Rows judged (sorted, each time once).
    H : float
        The macro step: the exact one on a uniform grid, else the mean step.
    uniform : bool
        The rows lie on t_0 + k H.
    problem : InitialValueProblem
        The system judged against (the SSP's, or ``--start``'s).
    conformance : Conformance
    identification : Identification
    accuracy : Accuracy
    criteria : list of Criterion
        The accuracy tests the caller stated.
    seconds : float or None
        The wall time the engine reported in the file's header (``# wall time = S``), if any.
    head : list of str
        The lines about the file and the problem.
    """

    source: str
    rows: int
    H: float
    uniform: bool
    problem: InitialValueProblem
    conformance: Conformance
    identification: Identification
    accuracy: Accuracy
    criteria: list[Criterion] = field(default_factory=list)
    seconds: float | None = None
    head: list[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        """Conformant, and every stated criterion met."""
        return self.conformance.passed and all(c.passed for c in self.criteria)

    @property
    def exit_code(self) -> int:
        """0 pass, 1 fail."""
        return 0 if self.passed else 1

    @property
    def error(self) -> float:
        """Largest |theta - theta_exact| (rad)."""
        return self.accuracy.error

    @property
    def master(self) -> str | None:
        """The reference master reproduced (None: a master of its own)."""
        return self.identification.master

    @property
    def findings(self) -> list[Finding]:
        """The conformance defects."""
        return self.conformance.findings

    @property
    def reference_errors(self) -> dict[str, float]:
        """Each reference master's error at H over the compared rows."""
        return self.identification.reference_errors

    @property
    def summary(self) -> str:
        """The three answers in one line."""
        return summary(self)

    @property
    def lines(self) -> list[str]:
        """One line per answer and finding, the summary last."""
        return verdict_lines(self)


def _row(label: str, status: str, text: str) -> str:
    return f"{label:<16s}{status:<6s}{text}"


_WALL = re.compile(r"^\s*#.*\bwall[ _-]?time\b\s*[:=]?\s*(?P<s>[0-9.eE+-]+)", re.IGNORECASE)


def reported_seconds(data: Any) -> float | None:
    """The wall time an engine wrote in a comment line of the file's head (``# wall time = 1.5``)."""
    if not isinstance(data, (str, Path)):
        return None
    try:
        with open(data, encoding="utf-8", errors="replace") as stream:
            for _, line in zip(range(50), stream, strict=False):
                match = _WALL.match(line)
                if match:
                    try:
                        return float(match.group("s"))
                    except ValueError:
                        return None
    except OSError:
        return None
    return None


def _exchange_text(schedule: Any, law: Any) -> str:
    if law is None:
        return ""
    how = "zero-order hold, read back to round-off" if law.held else "inputs read back on average"
    return f"{schedule.describe()}; {how}" if schedule is not None else how


def judge_split(data: Any, problem: InitialValueProblem | None = None, master: str | None = None,
                instance: str | None = None, step: float | None = None,
                max_error: float | None = None) -> SplitVerdict:
    """Judge a coupled result of the split pendulum (see the module's docstring).

    Parameters
    ----------
    data : str, Path or table
        The result (what :func:`pendulum_fmu.split.reading.read_coupled` reads).
    problem : InitialValueProblem, optional
        The run's parameters and start values, as stated by the caller; None: the SSP's
        (:data:`~pendulum_fmu.split.pair.DEFAULT_PROBLEM`). A row at t = 0 other than a stated
        start is a finding.
    master : str, optional
        The reference master the run implements (:attr:`Master.name`): a criterion.
    instance : str, optional
        Body's instance name in the file.
    step : float, optional
        The macro step the run used, when the file holds every m-th communication point.
    max_error : float, optional
        The largest error allowed (rad): a criterion.

    Returns
    -------
    SplitVerdict

    Raises
    ------
    pendulum_fmu.judge.ReadError
        When the file cannot be read or has under 3 rows.
    ValueError
        For an unknown ``master``.
    """
    from pendulum_fmu.fmu.library import exact
    from pendulum_fmu.judge.reading import ReadError
    from pendulum_fmu.split.masters import master_named

    if master:
        master_named(master)
    result = read_coupled(data, instance)
    if result.time.size < 3 or not np.all(np.isfinite(result.time)):
        raise ReadError(f"{result.source}: {result.time.size} rows: a coupled run needs at least 3 at finite times")
    if "theta" not in result.values:
        raise ReadError(f"{result.source}: no Body theta column")
    grid = read_grid(result.time, result.resolution["time"], step)
    values = {name: column[grid.keep] for name, column in result.values.items()}
    resolution = {name: column[grid.keep] for name, column in result.resolution.items()}
    if grid.time.size < 3:
        raise ReadError(f"{result.source}: {grid.time.size} distinct times: a coupled run needs at least 3")
    stated = problem is not None
    problem = problem or DEFAULT_PROBLEM
    findings = list(grid.findings)
    times = grid.exact_times
    H = grid.H if grid.H is not None else float((times[-1] - times[0]) / (times.size - 1))
    index = grid.index
    if grid.H is not None and index is not None:
        index = index + int(round(times[0] / grid.H)) - int(index[0])
    finite = np.ones(times.size, dtype=bool)
    for name in ("theta", "omega"):
        if name in values:
            finite &= np.isfinite(values[name])
    if not np.all(finite):
        bad = grid.time[~finite]
        shown = ", ".join(f"{t:.9g}" for t in bad[:5]) + (" ..." if bad.size > 5 else "")
        findings.append(Finding("not-finite", f"{bad.size} row(s) with theta or omega not a number: t = {shown} s"))
        if np.count_nonzero(finite) < 3:
            raise ReadError(f"{result.source}: fewer than 3 rows with finite theta and omega")
        values = {name: column[finite] for name, column in values.items()}
        resolution = {name: column[finite] for name, column in resolution.items()}
        times = times[finite]
        index = index[finite] if index is not None else None
    shift = label_shift(times, values, resolution, problem, H) if grid.H is not None else 0
    if shift:
        findings.append(label_finding(shift, H, "theta_exact" in values))
        times = times + shift * H
        index = index + shift if index is not None else None
    begin = start_finding(times, values, resolution, problem, stated)
    if begin is not None:
        findings.append(begin)
    k = problem.g / problem.L
    law = read_law(times, values, resolution, k)
    schedule = None
    if law is not None:
        found, schedule = law_findings(law, k)
        findings += found
    exchange = _exchange_text(schedule, law)
    own = []
    if grid.H is None:
        own.append("variable macro step")
    if schedule is not None and schedule.multirate > 1:
        own.append(f"multirate: Body's input refreshed every {schedule.multirate} macro steps")
    rerun_problem = problem
    if begin is not None:
        rerun_problem = replace(problem, theta0=float(values["theta"][0]),
                                omega0=float(values.get("omega", np.array([problem.omega0]))[0]))
    decimated = law is None or not law.held  # rows that are single held steps are every point
    who = identify(index, grid.H, values["theta"], resolution["theta"], rerun_problem, step, ", ".join(own),
                   decimated)
    reference = exact(problem.theta0, problem.omega0, problem.L, problem.g, times)[0]
    within = np.arange(times.size) < who.rows if who.rows else None
    acc = accuracy(times, values["theta"], reference, within, who.reference_errors, who.master)
    criteria = []
    if max_error is not None:
        ok = acc.error <= max_error
        criteria.append(Criterion("max-error", ok, f"error {acc.error:.3g} rad {'within' if ok else 'above'} "
                                                   f"--max-error {max_error:g}"))
    if master:
        ok = who.master == master
        criteria.append(Criterion("master", ok, f"{'behaves as' if ok else 'does not behave as'} the "
                                                f"{master_named(master).describe()} it names"
                                                + ("" if ok else f" ({who.text})")))
    head = [_row("file", "INFO", f"{result.time.size} rows from t = {result.time[0]:.6g} to {result.time[-1]:.6g} s, "
                                 + (f"macro step H = {H:.12g} s (t_k = t_0 + k H to the print)" if grid.H is not None
                                    else f"variable macro step, {np.min(np.diff(grid.time)):.6g} to "
                                         f"{np.max(np.diff(grid.time)):.6g} s")
                                 + f", Body's columns {result.instance or '(bare)'}"),
            _row("problem", "INFO", f"L = {problem.L:g} m, g = {problem.g:g} m/s2, theta0 = {problem.theta0:.10g} rad "
                                    f"({math.degrees(problem.theta0):.6g} deg), omega0 = {problem.omega0:.6g} rad/s"
                                    f" ({'stated' if stated else 'the SSP' + chr(39) + 's'})")]
    return SplitVerdict(result.source, int(grid.time.size), H, grid.H is not None, problem,
                        Conformance(findings, exchange), who, acc, criteria, reported_seconds(data), head)


def _h_text(verdict: SplitVerdict) -> str:
    h = verdict.identification.H or verdict.H
    return f"H = {h:.6g}" if verdict.uniform else f"mean H = {verdict.H:.6g}"


def summary(verdict: SplitVerdict, order: Order | None = None) -> str:
    """"conformant; behaves as Jacobi with zero-order hold; error 3.56 rad at H = 0.01 (order 1.0 over 4 runs)"."""
    conformance = "conformant" if verdict.conformance.passed else \
        "not conformant: " + ", ".join(dict.fromkeys(f.kind for f in verdict.findings))
    who = verdict.identification
    identity = f"behaves as {who.text}" if who.master else who.text.split(";")[0]
    text = f"{conformance}; {identity}; error {verdict.error:.3g} rad at {_h_text(verdict)}"
    if order is not None:
        text += f" (order {order.order:.1f} over {order.runs} runs)"
    return text


def verdict_lines(verdict: SplitVerdict, order: Order | None = None) -> list[str]:
    """The verdict in lines: file, problem, conformance and its findings, identification,
    accuracy, the criteria, the summary."""
    lines = list(verdict.head)
    conf = verdict.conformance
    lines.append(_row("conformance", "PASS" if conf.passed else "FAIL",
                      ("no defect found" if conf.passed else f"{len(conf.findings)} defect(s) found")
                      + (f" ({conf.exchange})" if conf.exchange else "")))
    for finding in conf.findings:
        lines.append(_row(finding.kind, "FAIL", finding.line))
    who = verdict.identification
    if who.master:
        every = f", one row every {who.every} macro steps" if who.every > 1 else ""
        span = (f" over the first {who.rows} rows (to t = {who.span:.6g} s)" if who.truncated
                else f" over all {who.rows} rows")
        text = (f"behaves as {who.text} at H = {who.H:.6g}{every}: the two differ by "
                f"{who.differences[who.master]:.2g} rad{span}")
    else:
        text = who.text
    lines.append(_row("identification", "INFO", text))
    acc = verdict.accuracy
    growth = f"grows as t^{acc.growth:.2f}" if math.isfinite(acc.growth) else "none over the first half"
    text = (f"error {acc.error:.3g} rad at t = {acc.at:.6g} s ({growth})")
    if acc.rank:
        span = f" over the first {who.rows} rows" if who.truncated else ""
        text += f"; {acc.rank} at H = {who.H:.6g}{span}"
    elif not verdict.uniform:
        text += "; not ranked (a variable macro step: the reference masters run at a fixed H)"
    lines.append(_row("accuracy", "INFO", text))
    if verdict.seconds is not None:
        lines.append(_row("wall time", "INFO", f"{verdict.seconds:.6g} s as the engine reports"))
    for criterion in verdict.criteria:
        lines.append(_row(criterion.name, "PASS" if criterion.passed else "FAIL", criterion.line))
    lines.append(_row("summary", "PASS" if verdict.passed else "FAIL", summary(verdict, order)))
    return lines


@dataclass(frozen=True)
class SplitRuns:
    """Several runs of one master judged together.

    Attributes
    ----------
    verdicts : list of SplitVerdict
        One per file, largest H first.
    order : Order or None
        The observed order over them.
    criteria : list of Criterion
        The stated criteria over the runs (``order``), beside each file's own.
    """

    verdicts: list[SplitVerdict]
    order: Order | None
    criteria: list[Criterion] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        """Every run passes and every criterion over the runs holds."""
        return all(v.passed for v in self.verdicts) and all(c.passed for c in self.criteria)

    @property
    def exit_code(self) -> int:
        """0 pass, 1 fail."""
        return 0 if self.passed else 1

    @property
    def summary(self) -> str:
        """The finest run's summary, with the order over the runs."""
        return summary(self.verdicts[-1], self.order)

    @property
    def lines(self) -> list[str]:
        """Each run's lines under its file name, then the order, the criteria and the summary."""
        lines: list[str] = []
        for verdict in self.verdicts:
            lines.append(f"== {verdict.source}")
            lines += verdict_lines(verdict)[:-1]
            lines.append(_row("summary", "PASS" if verdict.passed else "FAIL", summary(verdict)))
        lines.append("== over the runs")
        lines.append(_row("runs", "INFO", " | ".join(
            f"H = {v.identification.H or v.H:.6g}: {v.error:.3g} rad"
            + (f" in {v.seconds:.3g} s" if v.seconds is not None else "") for v in self.verdicts)))
        if self.order is not None:
            pairs = ", ".join(f"{p:.2f}" for p in self.order.pairs)
            lines.append(_row("order", "INFO", f"error = {self.order.constant:.3g} H^{self.order.order:.2f} over "
                                               f"{self.order.runs} runs (between consecutive H: {pairs})"))
        for criterion in self.criteria:
            lines.append(_row(criterion.name, "PASS" if criterion.passed else "FAIL", criterion.line))
        lines.append(_row("summary", "PASS" if self.passed else "FAIL", self.summary))
        return lines


def judge_runs(sources: Sequence[Any], problem: InitialValueProblem | None = None, master: str | None = None,
               instance: str | None = None, step: float | None = None, max_error: float | None = None,
               order: float | None = None) -> SplitRuns:
    """Judge several runs of one master at different H (see :func:`judge_split`); ``order``: the
    least observed order allowed (less :data:`ORDER_SLACK`)."""
    verdicts = [judge_split(s, problem, master, instance, step, max_error) for s in sources]
    verdicts.sort(key=lambda v: -(v.identification.H or v.H))
    found = observed_order([v.identification.H or v.H for v in verdicts], [v.error for v in verdicts])
    criteria = []
    if order is not None:
        if found is None:
            criteria.append(Criterion("order", False, f"--order {order:g} needs runs at two H or more"))
        else:
            ok = found.order >= order - ORDER_SLACK
            criteria.append(Criterion("order", ok, f"observed order {found.order:.2f} {'at least' if ok else 'below'} "
                                                   f"--order {order:g} (less {ORDER_SLACK:g})"))
    return SplitRuns(verdicts, found, criteria)
