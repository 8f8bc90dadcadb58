"""Judge a coupled result of the split pendulum: its error against the exact pendulum, which
reference master reproduces it on its own grid, what is wrong when none does, and a verdict.

::

    from pendulum_fmu.split.judge import judge_split
    verdict = judge_split("engine.csv")          # or master="gauss-seidel-zoh"
    print("\\n".join(verdict.lines))

The verdict passes when the file is a reference master's run (to 1 % of that master's error)
with no defect found and its error is within :data:`FACTOR` times the best reference master's
of the same coupling at that H (or of ``master`` when the caller names what it implements, and
the file then behaves as that master).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from pendulum_fmu.split.diagnosis import Finding, grid_findings, input_findings, label_finding
from pendulum_fmu.split.masters import Coupled, Master, master_named, masters_for, run_master
from pendulum_fmu.split.pair import Problem
from pendulum_fmu.split.reading import read_coupled

FACTOR = 4.0
"""Default bound: the error may be this many times the best reference master's of the same coupling."""
MATCH = 0.01
"""A file reproduces a master when they differ by at most this fraction of the master's error."""


@dataclass(frozen=True)
class SplitVerdict:
    """The judge's answer for a coupled result.

    Attributes
    ----------
    passed : bool
        The verdict.
    lines : list of str
        One line per finding, the verdict last.
    H : float
        The macro step read from the times.
    error : float
        Largest |theta - theta_exact| over the file's points (rad).
    master : str or None
        The reference master the file behaves as (:attr:`Master.name`), None when none does.
    findings : list of Finding
        The defects found.
    reference_errors : dict of str to float
        Each reference master's error at H on the file's points.
    """

    passed: bool
    lines: list[str]
    H: float
    error: float
    master: str | None
    findings: list[Finding] = field(default_factory=list)
    reference_errors: dict[str, float] = field(default_factory=dict)

    @property
    def exit_code(self) -> int:
        """0 pass, 1 fail."""
        return 0 if self.passed else 1


def _number(text: str) -> float:
    text = text.strip()
    if text.endswith("deg"):
        return math.radians(float(text[:-3]))
    return float(text)


def parse_start(items: Sequence[str]) -> dict[str, float]:
    """``NAME=VALUE`` items (theta in rad or ``80deg``, omega, L, g) as a dict; ValueError otherwise."""
    known = {"theta": "theta0", "omega": "omega0", "L": "L", "g": "g"}
    values: dict[str, float] = {}
    for item in items:
        name, _, value = item.partition("=")
        if name.strip() not in known or not value:
            raise ValueError(f"--start {item!r}: give theta, omega, L or g as NAME=VALUE")
        values[known[name.strip()]] = _number(value)
    return values


def _row(label: str, status: str, text: str) -> str:
    return f"{label:<16s}{status:<6s}{text}"


def _problem(time: np.ndarray, values: dict[str, np.ndarray], resolution: dict[str, np.ndarray],
             given: dict[str, float]) -> Problem:
    """Parameters from ``given`` or the SSP's; start values from ``given``, else the row at t = 0
    (the SSP's own value when the row is that value rounded in print)."""
    base = Problem()
    start = dict(L=base.L, g=base.g, theta0=base.theta0, omega0=base.omega0)
    if abs(time[0]) < 1e-12:
        for name, key in (("theta", "theta0"), ("omega", "omega0")):
            if name in values and abs(values[name][0] - start[key]) > resolution[name][0]:
                start[key] = float(values[name][0])
    start.update(given)
    return Problem(**start)


def _compare(coupled: Coupled, index: np.ndarray, theta: np.ndarray) -> tuple[float, float]:
    """(largest difference from the file, the master's own error), both on the file's points."""
    difference = float(np.max(np.abs(theta - coupled.theta[index])))
    own = float(np.max(np.abs(coupled.theta[index] - coupled.theta_exact[index])))
    return difference, own


def judge_split(data: Any, start: Sequence[str] = (), master: str | None = None, factor: float = FACTOR,
                instance: str | None = None) -> SplitVerdict:
    """Judge a coupled result of the split pendulum.

    Parameters
    ----------
    data : str, Path or table
        The result (what :func:`pendulum_fmu.split.reading.read_coupled` reads).
    start : sequence of str
        ``NAME=VALUE`` of the run (theta, omega, L, g); by default the SSP's, and the start
        values of the row at t = 0 when the file has one.
    master : str, optional
        The reference master the caller implements (:attr:`Master.name`): the bound is
        ``factor`` times its error.
    factor : float
        The bound's factor.
    instance : str, optional
        Body's instance name in the file.

    Returns
    -------
    SplitVerdict

    Raises
    ------
    pendulum_fmu.judge.ReadError
        When the file cannot be read.
    ValueError
        For an unknown ``master`` or a bad ``start`` item.
    """
    from pendulum_fmu.fmu.library import exact

    named = master_named(master) if master else None
    result = read_coupled(data, instance)
    time, theta = result.time, result.values["theta"]
    H = float(np.median(np.diff(time))) if time.size >= 3 else math.nan
    if not (H > 0 and np.all(np.isfinite(time)) and np.all(np.diff(time) > 0)):
        from pendulum_fmu.judge.reading import ReadError

        raise ReadError(f"{result.source}: {time.size} rows: a coupled run needs at least 3 at increasing times")
    lines = [_row("file", "INFO", f"{time.size} points from t = {time[0]:.6g} to {time[-1]:.6g} s, "
                                  f"macro step H = {H:.6g} s, Body's columns {result.instance or '(bare)'}")]
    findings = grid_findings(time, H, float(np.max(result.resolution["time"])))
    problem = _problem(time, result.values, result.resolution, parse_start(start))
    labels = label_finding(time, result.values["theta_exact"], problem, H) if "theta_exact" in result.values else None
    if labels is not None:
        findings.append(labels)
        time = time + H
        problem = _problem(time, result.values, result.resolution, parse_start(start))
    lines.append(_row("problem", "INFO", f"L = {problem.L:g} m, g = {problem.g:g} m/s2, theta0 = "
                                         f"{problem.theta0:.10g} rad ({math.degrees(problem.theta0):.6g} deg), "
                                         f"omega0 = {problem.omega0:.6g} rad/s"))
    reference = exact(problem.theta0, problem.omega0, problem.L, problem.g, time)[0]
    errors = np.abs(theta - reference)
    error = float(np.nanmax(errors))
    half = time <= time[0] + (time[-1] - time[0]) / 2
    early = float(np.nanmax(errors[half]))
    growth = math.log2(error / early) if early > 0 and error > 0 else float("nan")
    worst = int(np.nanargmax(errors))
    lines.append(_row("error", "INFO", f"largest |theta - exact| {error:.3g} rad at t = {time[worst]:.6g} s; "
                                       f"{early:.3g} over the first half: grows as t^{growth:.2f}"))
    index = np.rint(time / H).astype(int)
    drifting = any(f.kind == "drift" for f in findings)
    if drifting or index[0] < 0:
        index = np.arange(time.size) + max(0, int(round(time[0] / H)))
    stop = int(index[-1]) * H
    references: dict[str, tuple[float, float]] = {}
    for candidate in masters_for(2):
        references[candidate.name] = _compare(run_master(candidate, H, stop, problem), index, theta)
    resolution = 2 * float(np.max(result.resolution["theta"]))
    matches = [(diff / max(own, 1e-300), name) for name, (diff, own) in references.items()
               if diff <= MATCH * own + resolution]
    behaves = min(matches)[1] if matches and not drifting else None
    if behaves is not None:
        diff, own = references[behaves]
        lines.append(_row("master", "INFO", f"behaves as {master_named(behaves).describe()} at H = {H:.6g}: "
                                            f"error {error:.3g}, as that scheme gives ({own:.3g}; the two differ by "
                                            f"{diff:.2g}){' once its rows are relabelled' if labels else ''}"))
    else:
        nearest = min(references, key=lambda name: references[name][0])
        lines.append(_row("master", "INFO", f"no reference master reproduces it at H = {H:.6g} (nearest: "
                                            f"{master_named(nearest).describe()}, {references[nearest][0]:.3g} "
                                            "apart)"))
        if "omega" in result.values and not drifting:
            findings += input_findings(time, theta, result.values["omega"], problem)
    for finding in findings:
        lines.append(_row(finding.kind, "FAIL", finding.line))
    if behaves is None and not findings:
        findings.append(Finding("unexplained", "no reference master and no known defect reproduces the file"))
        lines.append(_row("unexplained", "FAIL", findings[-1].line))
    passed, verdict = _bound(named, behaves, references, error, factor, H)
    behaves = behaves if not findings else None
    passed = passed and not findings
    lines.append(_row("verdict", "PASS" if passed else "FAIL", verdict if passed or not findings else
                      f"{findings[0].line.split(':')[0]}; {verdict}"))
    return SplitVerdict(passed, lines, H, error, behaves, findings,
                        {name: own for name, (_, own) in references.items()})


def _bound(named: Master | None, behaves: str | None, references: dict[str, tuple[float, float]], error: float,
           factor: float, H: float) -> tuple[bool, str]:
    """The bound's line: against ``named``, else the best master of the coupling the file shows."""
    if named is not None:
        bound_master = named
    else:
        coupling = master_named(behaves).coupling if behaves else "zoh"
        bound_master = min((master_named(n) for n in references if master_named(n).coupling == coupling),
                           key=lambda m: references[m.name][1])
    best = references[bound_master.name][1]
    ratio = error / best if best > 0 else float("inf")
    within = error <= factor * best
    text = (f"error {error:.3g} is {ratio:.3g} times {bound_master.describe()}'s {best:.3g} at H = {H:.6g}: "
            f"{'within' if within else 'above'} the bound of {factor:g} times")
    if named is not None and behaves is not None and behaves != named.name:
        return False, (f"it behaves as {master_named(behaves).describe()}, not as the {named.describe()} "
                       f"it names; {text}")
    return within, text
