"""What the values are right for when they are wrong for the experiment.

A result whose values miss the exact solution everywhere is often the right solution of a
slightly different question: theta written in degrees, the run started at another time, every
value shifted in time (a lag, or one row early), a clock that runs fast, or other parameters
or start values. Each alternative recomputes the exact solution for its question and is kept
only when the file's columns fit it; the caller says what fitting means (to the exact port's
agreement for the exact columns, well inside their error for theta and omega).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from pendulum_fmu.judge.explain.inference import Fit, fit_parameters
from pendulum_fmu.judge.verdict import Experiment

Columns = dict[str, np.ndarray]
"""Values by column name: theta, omega, theta_exact, omega_exact."""
Fits = Callable[[Columns], bool]
"""Whether the columns fit an alternative, given column - alternative for each column."""

KNOWN_GRAVITIES = (9.80665, 9.81, 9.8, 1.62, 3.71, 24.79)
"""Standard gravity, its usual roundings, the Moon, Mars and Jupiter (m/s^2)."""
NEWTON_STEPS = 6


@dataclass(frozen=True)
class Explanation:
    """An alternative question that the file answers right.

    Attributes
    ----------
    cause : str
        ``degrees``, ``startTime``, ``shift``, ``clock`` or ``parameters``.
    line : str
        The reason, for the verdict line.
    numbers : dict
        The fitted values, JSON-ready.
    """

    cause: str
    line: str
    numbers: dict[str, Any] = field(default_factory=dict)


def solution(experiment: Experiment, tau: np.ndarray, names: list[str], theta0: float | None = None,
             omega0: float | None = None, length: float | None = None) -> Columns:
    """The exact solution at the times ``tau`` from the start: theta for the theta columns,
    omega for the omega columns."""
    from pendulum_fmu.fmu.library import exact

    with np.errstate(all="ignore"):
        theta, omega = exact(experiment.problem.theta0 if theta0 is None else theta0,
                             experiment.problem.omega0 if omega0 is None else omega0,
                             experiment.problem.L if length is None else length, experiment.problem.g, tau)
    return {name: theta if name.startswith("theta") else omega for name in names}


def _residuals(columns: Columns, alternative: Columns) -> Columns:
    return {name: columns[name] - alternative[name] for name in columns}


def _newton(columns: Columns, experiment: Experiment, times: Callable[[float], np.ndarray],
            times_derivative: Callable[[float], np.ndarray], start: float) -> float | None:
    """The p for which columns = exact(times(p)) in least squares (Gauss-Newton: p += sum(r d) /
    sum(d d), d = x'(times(p)) times'(p); omega weighted by 1/w0)."""
    names = list(columns)
    c = experiment.problem.g / experiment.problem.L
    p = start
    for _ in range(NEWTON_STEPS):
        tau = times(p)
        at = solution(experiment, tau, ["theta", "omega"])
        rate = {"theta": at["omega"], "omega": -c * np.sin(at["theta"])}
        dtau = times_derivative(p)
        top = bottom = 0.0
        for name in names:
            key = "theta" if name.startswith("theta") else "omega"
            weight = 1.0 if key == "theta" else 1.0 / experiment.problem.w0 ** 2
            d = rate[key] * dtau
            r = columns[name] - at[key]
            ok = np.isfinite(d) & np.isfinite(r)
            top += weight * float(np.dot(r[ok], d[ok]))
            bottom += weight * float(np.dot(d[ok], d[ok]))
        if bottom <= 0 or not math.isfinite(top / bottom):
            return None
        p += top / bottom
    return p if math.isfinite(p) else None


def degrees(columns: Columns, experiment: Experiment, tau: np.ndarray, fits: Fits) -> Explanation | None:
    """theta (and perhaps omega) written in degrees (deg/s) where the FMU gives radians."""
    if not any(name.startswith("theta") for name in columns):
        return None
    exact_values = solution(experiment, tau, list(columns))
    for omega_too in (True, False):
        converted = {n: np.radians(v) if n.startswith("theta") or omega_too else v for n, v in columns.items()}
        if fits(_residuals(converted, exact_values)):
            what = "theta and omega are" if omega_too and any(n.startswith("omega") for n in columns) else "theta is"
            return Explanation("degrees", f"{what} in degrees: times pi/180 the values are the exact solution; "
                               "the importer wrote degrees where the FMU gives radians", {"omega_too": omega_too})
    return None


def start_time(columns: Columns, experiment: Experiment, time: np.ndarray, fits: Fits) -> Explanation | None:
    """The run started at the file's first time, not at the experiment's start time."""
    first = float(time[0])
    if first == experiment.start_time:
        return None
    if not fits(_residuals(columns, solution(experiment, time - first, list(columns)))):
        return None
    return Explanation("startTime", f"the values are the exact solution from startTime = {first:.10g} s, not "
                       f"{experiment.start_time:.10g} s: the run's start time was not given to the judge "
                       f"(--start startTime={first:.10g})", {"start_time": first})


def shift(columns: Columns, experiment: Experiment, tau: np.ndarray, step: float | None,
          fits: Fits) -> Explanation | None:
    """Every value belongs to a time a fixed amount earlier or later than the one written:
    columns = exact(tau - a), a fitted (from 0, and from one step either way)."""
    starts = [0.0] + ([step, -step] if step else [])
    for begin in starts:
        a = _newton(columns, experiment, lambda p: tau - p, lambda p: np.full_like(tau, -1.0), begin)
        if a is None or a == 0:
            continue
        if step and abs(abs(a) - step) <= 1e-6 * step:  # a whole row: snap to it
            a = math.copysign(step, a)
        if not fits(_residuals(columns, solution(experiment, tau - a, list(columns)))):
            continue
        if step and abs(a) == step:
            rows = "one row late (each row holds the previous row's value)" if a > 0 else \
                "one row early (each row holds the next row's value)"
            how = f"by one step, h = {step:.6g} s: the values are written {rows}"
        else:
            how = (f"by {a:+.3g} s: each value belongs to its time {'minus' if a > 0 else 'plus'} {abs(a):.3g} s "
                   f"({'a time lag' if a > 0 else 'values ahead of their times'})")
        return Explanation("shift", f"the values are shifted against their times {how}", {"shift": a})
    return None


def clock(columns: Columns, experiment: Experiment, tau: np.ndarray, fits: Fits) -> Explanation | None:
    """The times are scaled: columns = exact(tau / s), the clock running s times fast."""
    b = _newton(columns, experiment, lambda p: p * tau, lambda p: tau, 1.0)
    if b is None or b <= 0 or b == 1:
        return None
    if not fits(_residuals(columns, solution(experiment, b * tau, list(columns)))):
        return None
    s = 1.0 / b
    return Explanation("clock", f"the times are scaled: the value written at t belongs to t/{s:.10g} from the "
                       f"start (the clock runs {s:.10g} times {'fast' if s > 1 else 'slow'})", {"clock_scale": s})


def digits(value: float, relative: float) -> int:
    """The fewest significant digits that give ``value`` to within ``relative``."""
    for n in range(1, 17):
        if abs(float(f"{value:.{n}g}") - value) <= relative * abs(value):
            return n
    return 17


def name_parameters(fit: Fit, experiment: Experiment, relative: float) -> list[str]:
    """The fit's differences with the experiment, naming g or L for the fitted g/L.

    Only g/L enters the motion, so a fitted L with g held is the same answer as a fitted g
    with L held. The judge names the one a person is likelier to have set: a known value of
    g (standard gravity, the Moon, ...), else the one with fewer significant digits (L = 2,
    not g = 4.905), within the fit's ``relative`` precision.
    """
    changed = fit.differences(experiment, relative)
    length_entry = next((c for c in changed if c.startswith("L = ")), None)
    if length_entry is None:
        return changed
    gravity = experiment.problem.g * experiment.problem.L / fit.L
    known = any(abs(gravity - k) <= max(relative, 1e-9) * k for k in KNOWN_GRAVITIES)
    if known or digits(gravity, max(relative, 1e-12)) < digits(fit.L, max(relative, 1e-12)):
        named = f"g = {gravity:.10g} (not {experiment.problem.g:.10g})"
        return [named if c is length_entry else c for c in changed]
    return changed


def parameters(columns: Columns, experiment: Experiment, tau: np.ndarray, fits: Fits,
               relative: float) -> tuple[Explanation, Fit] | None:
    """Other start values or g/L: the least-squares fit of :func:`inference.fit_parameters`."""
    fit = fit_parameters(tau, columns, experiment)
    if fit is None:
        return None
    changed = name_parameters(fit, experiment, relative)
    if not changed:
        return None
    alternative = solution(experiment, tau, list(columns), fit.theta0, fit.omega0, fit.L)
    if not fits(_residuals(columns, alternative)):
        return None
    return Explanation("parameters", f"they are the exact solution for {', '.join(changed)} (fits to "
                       f"{fit.residual:.1e}): the importer set different parameters or start values",
                       {"theta0": fit.theta0, "omega0": fit.omega0, "L": fit.L, "g": fit.g,
                        "residual": fit.residual, "changed": changed}), fit


def explain(columns: Columns, experiment: Experiment, time: np.ndarray, step: float | None, fits: Fits,
            relative: float) -> tuple[Explanation, Fit | None] | None:
    """The first alternative the columns fit: degrees, another start time, shifted times, a
    scaled clock, other parameters or start values (None when none does)."""
    tau = time - experiment.start_time
    trials: list[Callable[[], Explanation | None]] = [
        lambda: degrees(columns, experiment, tau, fits),
        lambda: shift(columns, experiment, tau, step, fits),
        lambda: clock(columns, experiment, tau, fits)]
    # a first time two steps or more after the start time is a start time not given; less, a lag
    offset = float(time[0]) - experiment.start_time
    trials.insert(1 if step is None or abs(offset) >= 2 * step else 3,
                  lambda: start_time(columns, experiment, time, fits))
    for trial in trials:
        found = trial()
        if found is not None:
            return found, None
    return parameters(columns, experiment, tau, fits, relative)
