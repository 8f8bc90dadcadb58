"""What is wrong with a coupled result that no reference master reproduces.

Two readings of the file, neither needing a rerun:

- the time grid: a macro step that drifts (the communication points leave t_0 + k H), and rows
  labelled one step early (Body's own ``theta_exact`` is the exact pendulum one step later
  than the row's time);
- the input Body got over each step: with the input held, omega_(k+1) - omega_k = a_k h_k, and
  a_k is Gravity's -(g/L) sin(theta) at some communication point: the same one (Gauss-Seidel,
  lag 0), the one before (Jacobi, lag 1), two before (an input held one step too long, lag
  2), or a constant (a connection dropped), or 0 (an input never set).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from pendulum_fmu.split.pair import Problem

DRIFT_TOLERANCE = 1e-6
"""Largest |t_k - (t_0 + k H)| / H before the grid counts as drifting (an engine that adds H
in binary drifts by about 1e-11 H in 1,000 steps)."""
LAG_TOLERANCE = 1e-7
"""Relative agreement of a step's input with a lag's value for the step to count as that lag."""


@dataclass(frozen=True)
class Finding:
    """One defect: a short kind (``drift``, ``labels``, ``held-too-long``, ``dropped``,
    ``out-of-order``, ``start-dropped``) and the line that explains it."""

    kind: str
    line: str


def grid_findings(time: np.ndarray, H: float, resolution: float) -> list[Finding]:
    """Drift of the communication points from t_0 + k H (H the median step)."""
    k = np.arange(time.size)
    off = time - (time[0] + k * H)
    worst = int(np.argmax(np.abs(off)))
    steps = np.diff(time)
    if abs(off[worst]) <= DRIFT_TOLERANCE * H + 2 * resolution:
        return []
    return [Finding("drift", f"the macro step drifts: steps from {steps.min():.9g} to {steps.max():.9g} s, "
                             f"t = {time[worst]:.9g} s is {off[worst]:+.3g} s off t0 + k H (H = {H:.6g} s)")]


def label_finding(time: np.ndarray, theta_exact: np.ndarray, problem: Problem, H: float) -> Finding | None:
    """Rows labelled one step early: Body's ``theta_exact`` is the exact pendulum at t + H."""
    from pendulum_fmu.fmu.library import exact

    at_time = np.nanmax(np.abs(theta_exact - exact(problem.theta0, problem.omega0, problem.L, problem.g, time)[0]))
    later = np.nanmax(np.abs(theta_exact - exact(problem.theta0, problem.omega0, problem.L, problem.g,
                                                 time + H)[0]))
    if at_time > 1e-8 and later <= 1e-9:
        return Finding("labels", f"rows labelled one step early: the values at t + H are written at t "
                                 f"(Body.theta_exact is the exact pendulum at t + H to {later:.1g}, off "
                                 f"{at_time:.2g} at t)")
    return None


def step_lags(time: np.ndarray, theta: np.ndarray, omega: np.ndarray, problem: Problem) -> list[str]:
    """For each step between rows: which input Body held (``"0"``, ``"1"``, ``"2"``: Gravity's
    alpha from the row that many before; ``"zero"``; ``"?"``: none of those)."""
    a = np.diff(omega) / np.diff(time)
    f = problem.alpha(theta)
    labels = []
    for k, value in enumerate(a):
        tol = LAG_TOLERANCE * max(1.0, abs(value))
        found = "?"
        for lag in (0, 1, 2):
            if k - lag >= 0 and abs(value - f[k - lag]) <= tol:
                found = str(lag)
                break
        if found == "?" and abs(value) <= tol:
            found = "zero"
        labels.append(found)
    return labels


def input_findings(time: np.ndarray, theta: np.ndarray, omega: np.ndarray, problem: Problem) -> list[Finding]:
    """The defects the inputs Body held show (see the module's docstring); [] when none."""
    a = np.diff(omega) / np.diff(time)
    if a.size >= 3 and np.all(np.abs(a - a[0]) <= LAG_TOLERANCE * max(1.0, abs(a[0]))):
        return [Finding("dropped", f"a connection dropped: Body's input alpha stayed {a[0]:.6g} rad/s2 over "
                                   f"all {a.size} steps (Gravity's alpha never reached Body, or Body's theta "
                                   "never Gravity)")]
    labels = step_lags(time, theta, omega, problem)
    total = len(labels)
    leading = next((i for i, name in enumerate(labels) if name != "zero"), total)
    # the first two steps have no lag 2 (and the first no lag 1): count from the third
    counts = {name: labels[max(2, leading):].count(name) for name in ("0", "1", "2", "zero", "?")}
    if counts["?"] > total // 10:
        return []
    if counts["2"] > 0 and counts["2"] >= total - max(2, leading) - counts["?"]:
        return [Finding("held-too-long", f"an input held one step too long: at {counts['2']} of {total} steps "
                                         "Body got Gravity's alpha from theta two communication points back "
                                         "(Jacobi's is one back, Gauss-Seidel's the same point)")]
    if counts["0"] > 0 and counts["1"] > 0:
        return [Finding("out-of-order", f"the FMUs stepped out of order: Body got Gravity's alpha of the same "
                                        f"communication point at {counts['0']} steps and of the one before at "
                                        f"{counts['1']} (Gravity stepped before Body at some steps, after at others)")]
    if 0 < leading < total:
        lag = "Gauss-Seidel's (same point)" if counts["0"] else "Jacobi's (one point back)"
        return [Finding("start-dropped", f"an input's start value dropped: Body's alpha was 0 over the first "
                                         f"{leading} step(s) instead of Gravity's, then {lag}")]
    return []
