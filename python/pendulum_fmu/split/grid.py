"""The time grid of a coupled result: the macro step H read exactly, and what is wrong with the rows.

H is not the median of the time differences (at H = 1e-4 that is 2e-12 off, and a rerun with
it leaves the file's grid). For n + 1 rows on a uniform grid, H = (t_n - t_0) / n carries every
digit the times have; the shortest decimal that puts every t_0 + k H within the times' print
resolution (plus the round-off of an engine that adds H in binary) is then the H the engine was
given. The rows themselves may be out of order (a time earlier than the one before), doubled (a
time written twice) or missing (one gap of exactly 2 H, 3 H, ... on an otherwise uniform grid);
each is a finding that names the rows, and the judge goes on with the rows sorted and single.
A grid whose steps vary otherwise is a variable macro step (legal: both FMUs declare
``canHandleVariableCommunicationStepSize``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from pendulum_fmu.split.diagnosis import Finding

EPS = float(np.finfo(float).eps)
UNIFORM_SHARE = 0.9
"""On a grid with missing rows, at least this share of the steps is exactly H."""


@dataclass(frozen=True)
class Grid:
    """The rows the judge goes on with.

    Attributes
    ----------
    keep : numpy.ndarray
        Indices of the file's rows, sorted by time, each time once.
    time : numpy.ndarray
        Their times as written.
    H : float or None
        The uniform macro step (None on a variable grid).
    index : numpy.ndarray or None
        Each kept row's step number k (t = t_0 + k H) on a uniform grid (None otherwise).
    findings : list of Finding
        Rows out of order, doubled or missing.
    """

    keep: np.ndarray
    time: np.ndarray
    H: float | None
    index: np.ndarray | None
    findings: list[Finding] = field(default_factory=list)

    @property
    def exact_times(self) -> np.ndarray:
        """t_0 + k H on a uniform grid (the times the engine stepped to), else the times as written."""
        if self.H is None or self.index is None:
            return self.time
        return self.time[0] + self.index * self.H


def _tolerance(time: np.ndarray, resolution: np.ndarray, n: int) -> np.ndarray:
    """How far a written time may sit from t_0 + k H: its print's rounding and the round-off of
    adding H n times in binary."""
    return resolution + resolution[0] + 4 * EPS * (n + 1) * np.max(np.abs(time)) + 4 * EPS * np.abs(time)


def exact_step(time: np.ndarray, index: np.ndarray, resolution: np.ndarray) -> float | None:
    """H from rows at step numbers ``index`` (t_k = t_0 + k H), or None when no H puts them all
    within their print resolution of t_0 + k H.

    The shortest decimal that fits is returned (what the engine was given), else the quotient
    (t_n - t_0) / n."""
    n = int(index[-1] - index[0])
    if n <= 0:
        return None
    raw = (time[-1] - time[0]) / n
    tol = _tolerance(time, resolution, n)
    for digits in range(1, 18):
        candidate = float(f"{raw:.{digits}g}")
        if candidate > 0 and np.all(np.abs(time - (time[0] + (index - index[0]) * candidate)) <= tol):
            return candidate
    if np.all(np.abs(time - (time[0] + (index - index[0]) * raw)) <= tol):
        return raw
    return None


def _order_findings(time: np.ndarray, resolution: np.ndarray) -> tuple[np.ndarray, list[Finding]]:
    """Rows sorted by time and each time once; a finding for rows out of order and for doubled ones."""
    findings = []
    order = np.argsort(time, kind="stable")
    if np.any(order != np.arange(time.size)):
        back = np.flatnonzero(np.diff(time) < 0)
        shown = ", ".join(f"row {i + 2} (t = {time[i + 1]:.9g} s after t = {time[i]:.9g} s)" for i in back[:3])
        findings.append(Finding("out-of-order", f"rows out of order: {back.size} time(s) earlier than the row "
                                                f"before: {shown}{' ...' if back.size > 3 else ''}"))
    sorted_time = time[order]
    same = np.diff(sorted_time) <= resolution[order][1:] + resolution[order][:-1]
    if np.any(same):
        twice = sorted_time[1:][same]
        shown = ", ".join(f"{t:.9g}" for t in twice[:5]) + (" ..." if twice.size > 5 else "")
        findings.append(Finding("doubled", f"{twice.size} row(s) doubled: t = {shown} s written twice"))
    keep = order[np.concatenate(([True], ~same))]
    return keep, findings


def read_grid(time: np.ndarray, resolution: np.ndarray, step: float | None = None) -> Grid:
    """The grid of ``time`` (see the module's docstring); ``step`` is the macro step the caller
    states (the file may then hold every m-th communication point)."""
    keep, findings = _order_findings(time, resolution)
    t, res = time[keep], resolution[keep]
    n = t.size - 1
    if step is not None:
        index = np.rint((t - t[0]) / step).astype(np.int64)
        H = exact_step(t, index, res) if np.all(np.diff(index) > 0) else None
        if H is not None and abs(H - step) <= 1e-9 * step:
            return Grid(keep, t, step, index, findings)
    H = exact_step(t, np.arange(n + 1), res)
    if H is not None:
        return Grid(keep, t, H, np.arange(n + 1), findings)
    steps = np.diff(t)
    h = float(np.median(steps))
    ratio = steps / h
    multiple = np.rint(ratio)
    slack = (res[1:] + res[:-1]) / h + 1e-6
    if np.all(multiple >= 1) and np.all(np.abs(ratio - multiple) <= slack) and np.mean(multiple == 1) >= UNIFORM_SHARE:
        index = np.concatenate(([0], np.cumsum(multiple))).astype(np.int64)
        H = exact_step(t, index, res)
        if H is not None:
            gaps = np.flatnonzero(np.diff(index) > 1)
            lost = int(np.sum(np.diff(index)[gaps] - 1))
            where = ", ".join(f"{t[0] + k * H:.9g}" for g in gaps[:5] for k in range(index[g] + 1, index[g + 1]))
            where += " ..." if gaps.size > 5 else ""
            findings.append(Finding("missing", f"{lost} row(s) missing: no row at t = {where} s "
                                               f"(the grid is t0 + k H, H = {H:.9g} s)"))
            return Grid(keep, t, H, index, findings)
    return Grid(keep, t, None, None, findings)
