"""Which fixed-step method made a file, at any length.

A method is identified on a prefix of the file and confirmed on every row:

1. on the first :data:`PREFIX_ROWS` steps, each candidate (:data:`METHODS` at h, h/2, h/4,
   h/10) is rerun from the experiment's start values; it explains the file when the rerun
   reproduces theta and omega to :data:`AGREEMENT` of the prefix's error against the exact
   solution;
2. with theta and omega both in the file, a one-step method's row k + 1 is a function of
   row k alone, so every step of the file is checked at once (numpy, on whole columns):
   |x_{k+1} - method(x_k)| within what the print's rounding and the importer's clock allow.

The step of row k is h where the written step is within 1e-3 of h, else the written step
itself: a shorter last step to the stop time and a repeated last row (step 0) are checked
as what they are, as fmuCheck writes them.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from pendulum_fmu.judge.reading import Result
from pendulum_fmu.judge.verdict import Experiment

EPS = float(np.finfo(float).eps)
PREFIX_ROWS = 2000
"""Rows rerun step by step from the start values (the rest is checked row by row at once)."""
AGREEMENT = 1e-3
"""A rerun explains the file when it reproduces it to this fraction of the file's error."""
PARTS = (1, 2, 4, 10)
"""The method's step is h / parts: an importer may take several steps per output."""
CHUNK_ROWS = 500_000
"""Rows checked at once (bounds the memory of the step-by-step check)."""

Vector = np.ndarray | float
Step = Callable[[Vector, Vector, Vector, float], tuple[Vector, Vector]]


def _rate(theta: Vector, omega: Vector, c: float) -> tuple[Vector, Vector]:
    """(theta', omega') = (omega, -(g/L) sin theta), c = g/L."""
    return omega, -c * np.sin(theta)


def _euler(theta: Vector, omega: Vector, h: Vector, c: float) -> tuple[Vector, Vector]:
    d_theta, d_omega = _rate(theta, omega, c)
    return theta + h * d_theta, omega + h * d_omega


def _symplectic_euler(theta: Vector, omega: Vector, h: Vector, c: float) -> tuple[Vector, Vector]:
    moved = omega + h * _rate(theta, omega, c)[1]
    return theta + h * moved, moved


def _heun(theta: Vector, omega: Vector, h: Vector, c: float) -> tuple[Vector, Vector]:
    a_theta, a_omega = _rate(theta, omega, c)
    b_theta, b_omega = _rate(theta + h * a_theta, omega + h * a_omega, c)
    return theta + 0.5 * h * (a_theta + b_theta), omega + 0.5 * h * (a_omega + b_omega)


def _rk4(theta: Vector, omega: Vector, h: Vector, c: float) -> tuple[Vector, Vector]:
    k1 = _rate(theta, omega, c)
    k2 = _rate(theta + 0.5 * h * k1[0], omega + 0.5 * h * k1[1], c)
    k3 = _rate(theta + 0.5 * h * k2[0], omega + 0.5 * h * k2[1], c)
    k4 = _rate(theta + h * k3[0], omega + h * k3[1], c)
    return (theta + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
            omega + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]))


METHODS: dict[str, Step] = {"explicit Euler": _euler, "symplectic Euler": _symplectic_euler, "Heun (RK2)": _heun,
                            "classic RK4": _rk4}
"""The fixed-step methods tried, in this order; each takes (theta, omega, h, g/L), scalars or arrays."""


@dataclass(frozen=True)
class FixedStep:
    """A fixed-step method that reproduces the file."""

    method: str
    step: float
    agreement: float
    """Largest |file - rerun| over theta and omega on the rerun prefix."""
    every_step: float | None = None
    """Largest |x_{k+1} - method(x_k)| over all rows (None: theta or omega missing, only the
    prefix was checked)."""
    rows_checked: int = 0
    """Rows the method was confirmed on."""


def advance(method: str, theta: Vector, omega: Vector, h: Vector, parts: int, c: float) -> tuple[Vector, Vector]:
    """``parts`` steps of ``method`` of h / parts each."""
    step = METHODS[method]
    small = h / parts
    for _ in range(parts):
        theta, omega = step(theta, omega, small, c)
    return theta, omega


def row_steps(t: np.ndarray, h: float) -> np.ndarray:
    """The step from each row to the next: h where the written step is within 1e-3 of h,
    else the written step (a short last step, a repeated row)."""
    written = np.diff(t)
    return np.where(np.abs(written - h) <= 1e-3 * h, h, written)


def step_mismatch(result: Result, method: str, parts: int, c: float, steps: np.ndarray,
                  rows: slice) -> tuple[float, bool]:
    """Largest |x_{k+1} - method(x_k)| over the steps of ``rows`` (k within it), and whether
    each is within its allowance.

    Allowed for theta (omega alike, with c the coupling): r(theta_{k+1}) + r(theta_k) +
    1.5 s r(omega_k) from the print's rounding r (a rounded start moves one step's end by
    about itself plus s times the other's), eps (|t_k| + |t_{k+1}|) |theta'| from a clock
    that sums its steps, and 16 parts eps (|theta_{k+1}| + s |theta'|) of arithmetic.
    """
    theta, omega = result.values["theta"], result.values["omega"]
    r_theta, r_omega = result.resolution["theta"], result.resolution["omega"]
    t = result.time
    start, stop = rows.start or 0, min(rows.stop, t.size - 1)
    worst, within = 0.0, True
    for first in range(start, stop, CHUNK_ROWS):
        k = slice(first, min(first + CHUNK_ROWS, stop))
        nxt = slice(k.start + 1, k.stop + 1)
        s = steps[k]
        moved_theta, moved_omega = advance(method, theta[k], omega[k], s, parts, c)
        d_theta = np.abs(theta[nxt] - moved_theta)
        d_omega = np.abs(omega[nxt] - moved_omega)
        rate_theta, rate_omega = np.abs(omega[k]), c * np.abs(np.sin(theta[k]))
        clock = EPS * (np.abs(t[k]) + np.abs(t[nxt]))
        arithmetic = 16 * parts * EPS
        allowed_theta = (r_theta[nxt] + r_theta[k] + 1.5 * s * r_omega[k] + clock * rate_theta
                         + arithmetic * (np.abs(theta[nxt]) + s * rate_theta))
        allowed_omega = (r_omega[nxt] + r_omega[k] + 1.5 * s * c * r_theta[k] + clock * rate_omega
                         + arithmetic * (np.abs(omega[nxt]) + s * rate_omega))
        with np.errstate(invalid="ignore"):
            within = within and bool(np.all(d_theta <= allowed_theta) and np.all(d_omega <= allowed_omega))
        worst = max(worst, float(np.max(d_theta, initial=0.0)), float(np.max(d_omega, initial=0.0)))
        if not within:
            break
    return worst, within


def _rerun(method: str, parts: int, experiment: Experiment, steps: np.ndarray, rows: int) -> np.ndarray:
    """theta and omega (rows x 2) of ``method`` run step by step from the start values."""
    c = experiment.problem.g / experiment.problem.L
    out = np.empty((rows, 2))
    theta: Vector = experiment.problem.theta0
    omega: Vector = experiment.problem.omega0
    out[0] = theta, omega
    for k in range(1, rows):
        theta, omega = advance(method, theta, omega, float(steps[k - 1]), parts, c)
        out[k] = theta, omega
    return out


def identify_fixed_step(result: Result, experiment: Experiment, h: float, error: float) -> FixedStep | None:
    """The first of :data:`METHODS` at step h, h/2, h/4 or h/10 that made the file (see the
    module's description), else None.

    Parameters
    ----------
    result : Result
        The file; its first row must be at the experiment's start time.
    experiment : Experiment
        The start values and g/L the rerun starts from.
    h : float
        The file's output step.
    error : float
        The file's largest error against the exact solution (a file without error is not
        a fixed-step method's).
    """
    from pendulum_fmu.fmu.library import exact

    names = [n for n in ("theta", "omega") if n in result.values]
    if not names or error <= 0 or not math.isfinite(error) or result.rows < 2:
        return None
    if result.time[0] != experiment.start_time:
        return None
    c = experiment.problem.g / experiment.problem.L
    steps = row_steps(result.time, h)
    both = len(names) == 2
    prefix = min(result.rows, PREFIX_ROWS + 1)
    p = experiment.problem
    exact_theta, exact_omega = exact(p.theta0, p.omega0, p.L, p.g,
                                     result.time[:prefix] - experiment.start_time)
    truth = {"theta": exact_theta, "omega": exact_omega}
    with np.errstate(invalid="ignore"):
        prefix_error = max(float(np.max(np.abs(result.values[n][:prefix] - truth[n]))) for n in names)
    if not prefix_error > 0:
        return None
    for method in METHODS:
        for parts in PARTS:
            if both and not step_mismatch(result, method, parts, c, steps, slice(0, prefix - 1))[1]:
                continue
            rerun = _rerun(method, parts, experiment, steps, prefix)
            with np.errstate(invalid="ignore"):
                agreement = max(float(np.max(np.abs(result.values[n][:prefix] - rerun[:, i])))
                                for i, n in enumerate(("theta", "omega")) if n in result.values)
            if not agreement <= AGREEMENT * prefix_error:
                continue
            if not both:
                return FixedStep(method, h / parts, agreement, None, prefix)
            every, within = step_mismatch(result, method, parts, c, steps, slice(0, result.rows - 1))
            if within:
                return FixedStep(method, h / parts, agreement, every, result.rows)
    return None


__all__ = ["AGREEMENT", "FixedStep", "METHODS", "PREFIX_ROWS", "advance", "identify_fixed_step", "row_steps",
           "step_mismatch"]
