"""A case's result against the exact solution: the judge for ``Pendulum.fmu``, the split judge for
the SSP, and the suite's own check that the result spans the experiment."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from pendulum_fmu.suite.cases import Case

SPAN_SLACK = 1e-9
"""Relative slack, of the experiment's length, on a result's first and last time."""


@dataclass(frozen=True)
class Judged:
    """The verdict on one result.

    Attributes
    ----------
    passed : bool
    line : str
        The verdict line (``PASS: ...`` or ``FAIL (...): ...``).
    error : float or None
        Largest |theta - theta_exact| over the result, rad.
    ratio : float or None
        The worst error as a share of its bound (1 at the bound): for Pendulum the judge's
        bound (the certificate's for Co-Simulation, the Model Exchange bound), for the split
        pendulum the run's error over the claimed master's (1 when it reproduces it).
    properties : dict
        Further figures for the JUnit properties and the JSON.
    """

    passed: bool
    line: str
    error: float | None = None
    ratio: float | None = None
    properties: dict[str, Any] = field(default_factory=dict)


def span_problem(case: Case, time: np.ndarray) -> str | None:
    """Why the result's times do not span the experiment (None when they do).

    It starts at the start time and ends at the stop time, to :data:`SPAN_SLACK` of the
    length (the last output interval may be short; a file that starts one interval late, as
    libcosim's samples do, still spans it when its second point would be the first).
    """
    slack = SPAN_SLACK * max(case.stop - case.start, abs(case.stop))
    first, last = float(time[0]), float(time[-1])
    late_start = abs(first - case.start) > slack and abs(first - (case.start + case.interval)) > slack
    if late_start or abs(last - case.stop) > slack:
        return (f"the result covers t = {first!r} .. {last!r} s; the experiment is {case.start:g} .. {case.stop:g} s "
                f"(output interval {case.interval:g} s)")
    return None


def judge_pendulum(case: Case, csv: Path, fmu: Path | None) -> Judged:
    """``pendulum_fmu.judge.judge`` with the case's start values, tolerance, start time and interval.

    Raises
    ------
    pendulum_fmu.judge.ReadError
        The result cannot be read.
    """
    from pendulum_fmu.judge import judge

    start = {**case.start_values, "tolerance": case.tolerance, "startTime": case.start}
    verdict = judge(csv, start=start, interface="ME" if case.interface == "me" else "CS", step=case.interval, fmu=fmu,
                    read_experiment_file=False)
    figures = {check.name: check.numbers for check in verdict.checks}
    error = figures.get("theta error", {}).get("largest")
    ratio = figures.get("bound", {}).get("worst_ratio")
    properties = {"omega_error": figures.get("omega error", {}).get("largest"), "tolerance": case.tolerance}
    problem = span_problem(case, _times(csv)) if verdict.passed else None
    if problem is not None:
        return Judged(False, f"FAIL (span): {problem}; the judge alone: {verdict.line}", error, ratio, properties)
    return Judged(verdict.passed, verdict.line, error, ratio if ratio is None or ratio >= 0 else None, properties)


def _times(csv: Path) -> np.ndarray:
    from pendulum_fmu.judge.reading import read_result

    return read_result(csv).time


def judge_split_result(csv: Path, master: str | None) -> Judged:
    """The split judge on a coupled result, with the master the engine claims as its criterion.

    The one call into :mod:`pendulum_fmu.split.judge`: where its interface changes, this
    function alone follows. It passes when the run is a conformant co-simulation that reproduces
    ``master`` (or, with no master claimed, when it is conformant); its ratio is the run's error
    over the claimed master's at the same H (1 when it reproduces it).
    """
    from pendulum_fmu.split.judge import judge_split

    verdict = judge_split(csv, master=master)
    claimed = verdict.reference_errors.get(master) if master else None
    ratio = verdict.error / claimed if claimed else None
    text = f"{'PASS' if verdict.passed else 'FAIL'}: {verdict.summary}"
    if not verdict.passed and verdict.findings:
        text = f"FAIL ({', '.join(f.kind for f in verdict.findings)}): {verdict.summary}"
    return Judged(verdict.passed, text, verdict.error, ratio,
                  {"macro_step": verdict.H, "behaves_as": verdict.master or "", "claimed_master": master or "",
                   "claimed_master_error": claimed})
