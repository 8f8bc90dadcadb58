"""Findings a coupled result shows without a rerun: rows labelled early or late, start values.

- Rows labelled one step early (late): Body's ``theta_exact``, when written, is the exact
  pendulum at t + H (t - H) instead of t; without it, the first row at t = 0 holds the state one
  step after the start (early), or the first row is at t = H and holds the start (late).
- Start values: the row at the start time is not the SSP's start state (or the one ``--start``
  gives) beyond the print's resolution. That is reported, never taken as a new start.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from pendulum_fmu.spec import InitialValueProblem

EXACT_AGREEMENT = 1e-9
"""Body's theta_exact agrees with pendulum_fmu.exact to this (rad), plus the print."""


@dataclass(frozen=True)
class Finding:
    """One defect: a short kind and the line that explains it, with its evidence.

    Kinds: ``out-of-order``, ``doubled``, ``missing``, ``not-finite`` (rows), ``labels`` (rows
    labelled early or late), ``start`` (start values), ``sign``, ``connection``, ``parameter``,
    ``stale``, ``dropped``, ``start-dropped`` (inputs)."""

    kind: str
    line: str


def _exact(problem: InitialValueProblem, time: np.ndarray) -> np.ndarray:
    from pendulum_fmu.fmu.library import exact

    return exact(problem.theta0, problem.omega0, problem.L, problem.g, time)[0]


def label_shift(time: np.ndarray, values: dict[str, np.ndarray], resolution: dict[str, np.ndarray],
                problem: InitialValueProblem, H: float) -> int:
    """+1 when the rows are labelled one step early (the values at t + H are written at t), -1
    late, 0 neither (see the module's docstring)."""
    if "theta_exact" in values:
        column = values["theta_exact"]
        allowed = EXACT_AGREEMENT + 2 * resolution["theta_exact"]
        if np.all(np.abs(column - _exact(problem, time)) <= allowed + np.abs(column) * 1e-12):
            return 0
        for shift in (1, -1):
            if np.all(np.abs(column - _exact(problem, time + shift * H)) <= allowed + np.abs(column) * 1e-12):
                return shift
        return 0
    if "omega" not in values or time.size < 3:
        return 0
    theta, omega = values["theta"][0], values["omega"][0]
    start = abs(theta - problem.theta0) + abs(omega - problem.omega0) * H
    slack = resolution["theta"][0] + resolution["omega"][0] * H + 1e-15
    if abs(time[0]) <= resolution["time"][0] + 1e-15 and start > slack:
        one = _exact(problem, np.array([H]))[0]
        from pendulum_fmu.fmu.library import exact

        one_omega = exact(problem.theta0, problem.omega0, problem.L, problem.g, np.array([H]))[1][0]
        later = abs(theta - one) + abs(omega - one_omega) * H
        if later < 0.1 * start:
            return 1
    if abs(time[0] - H) <= 1e-9 * H + resolution["time"][0] and start <= slack:
        return -1
    return 0


def label_finding(shift: int, H: float, has_exact: bool) -> Finding:
    """The finding for rows labelled early (``shift`` 1) or late (-1)."""
    word, sign = ("early", "+") if shift > 0 else ("late", "-")
    evidence = (f"Body.theta_exact is the exact pendulum at t {sign} H" if has_exact else
                ("the row at t = 0 holds the state one step after the start" if shift > 0 else
                 f"the first row, at t = {H:.6g} s, holds the start state"))
    return Finding("labels", f"rows labelled one step {word}: the values at t {sign} H are written at t ({evidence})")


def start_finding(time: np.ndarray, values: dict[str, np.ndarray], resolution: dict[str, np.ndarray],
                  problem: InitialValueProblem, stated: bool) -> Finding | None:
    """The row at t = 0 is not the start state (the SSP's, or ``--start``'s when ``stated``)."""
    if abs(time[0]) > resolution["time"][0] + 1e-12:
        return None
    off = []
    for name, value in (("theta", problem.theta0), ("omega", problem.omega0)):
        if name in values and abs(values[name][0] - value) > 2 * resolution[name][0] + 1e-12 * max(1.0, abs(value)):
            shown = f"{values[name][0]:.10g}"
            if name == "theta":
                shown += f" ({math.degrees(values[name][0]):.6g} deg)"
            off.append(f"{name}(0) = {shown} where {'--start gives' if stated else 'the SSP starts at'} {value:.10g}")
    if not off:
        return None
    whose = "the stated" if stated else "the SSP's"
    return Finding("start", f"start values other than {whose}: {'; '.join(off)} (the error is against {whose} "
                            "start; give --start when the run changed it)")
