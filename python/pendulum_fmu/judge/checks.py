"""The judge's checks, each one a function of the result that returns a :class:`Check`.

Every check reports its figures; the bound check alone decides whether the numbers are
accurate enough, the others whether the file is what it claims (its time grid, its exact
columns, no value alone out of line with its neighbours).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from pendulum_fmu.judge import sensitivity
from pendulum_fmu.judge.reading import Result
from pendulum_fmu.judge.sensitivity import Allowance
from pendulum_fmu.judge.verdict import Check, Experiment

EPS = float(np.finfo(float).eps)
HALF_NANOSECOND = 5e-10
"""Clocks that count whole nanoseconds (libcosim) place each time within this of k h."""
EXACT_AGREEMENT = 1e-13
"""|column - pendulum_fmu.exact| allowed per unit of max(1, |value|) beyond the printed
resolution: the FMU's exact outputs and the library are the same C code (bit for bit on one
platform; within 1.1e-15 across the ones measured)."""
CS_FACTOR = 100.0
"""The certificate's bound (docs/certificate.md): 100 tol."""
ME_FACTOR = 300.0
"""Model Exchange: the importer's solver may make a local error of 300 tol (times the scales
max(1, |theta|), max(w0, |omega|)) per natural period 2 pi / w0, propagated by the pendulum's
linearised flow and accumulated (:mod:`pendulum_fmu.judge.sensitivity`), plus 300 tol at the
output time. Calibrated on CVODE, DOP853, LSODA, Radau and RK45 at their own tolerances
(tests/helpers/me_bound_table.py, docs/importers.md, "The bound")."""
SPIKE_RATIO = 100.0
"""A value whose error stands this many times above its neighbours' errors is isolated."""
NEIGHBOURS = 3
"""Rows either side whose largest error sets the scale of :func:`isolated_values`."""
GROWTH_POINTS = 10_000
"""At most about this many rows, evenly spread, fit the error's growth."""
LEVEL = 1e-4
"""The file's own error level in :func:`isolated_values`: this fraction of its largest error."""
SMOOTH_RATIO = 30.0
"""A value off the smooth curve of its neighbours' errors by this many times their own
roughness is isolated, where the solution itself is smooth on the file's grid
(:func:`isolated_values`)."""
SMOOTH_ABOVE = 3.0
"""... whose error is more than this many times its neighbours' largest, of the opposite sign."""
ROUGH_WINDOW = 6
"""Rows either side whose own roughness (second differences) sets the scale of the smooth-curve
test; the rows next to the value, which its own offset disturbs, are left out."""
CURVE_RATIO = 3.0
"""The solution is smooth at a row when its second differences there are at most this many
times those of the window's outer rows."""


@dataclass(frozen=True)
class Reference:
    """The exact solution at the file's times for the experiment's problem."""

    t: np.ndarray
    """Times from the start of the run (the experiment's start time)."""
    theta: np.ndarray
    omega: np.ndarray
    accumulation: Allowance | None = None
    """Model Exchange: the local errors allowed to the importer's solver, propagated by the
    pendulum's linearised flow and accumulated to each time (:func:`sensitivity.allowance`);
    None for Co-Simulation, whose bound needs none."""


def reference(result: Result, experiment: Experiment) -> Reference:
    """pendulum_fmu.exact at the file's own times, counted from the experiment's start time,
    and for Model Exchange the allowance of :func:`bound`."""
    from pendulum_fmu.fmu.library import exact

    t = result.time - experiment.start_time
    p = experiment.problem
    theta, omega = exact(p.theta0, p.omega0, p.L, p.g, t)
    if experiment.interface != "ME":
        return Reference(t, theta, omega)
    return Reference(t, theta, omega, sensitivity.allowance(t, theta, omega, experiment, ME_FACTOR))


def _at(result: Result, k: int) -> str:
    return f"t = {result.time[k]:.6g} s (row {k + 1})"


# --- time grid -------------------------------------------------------------------------------

def nominal_step(mean_step: float) -> float:
    """The shortest decimal (up to 6 significant digits) within 1e-5 of ``mean_step``,
    relative: the step the importer was asked for, as a person would have written it."""
    for digits in range(1, 7):
        candidate = float(f"{mean_step:.{digits}g}")
        if abs(candidate - mean_step) <= 1e-5 * mean_step:
            return candidate
    return mean_step


def _duplicates(result: Result, steps: np.ndarray) -> tuple[np.ndarray, bool]:
    """Rows that repeat the time of the row before, and whether the only one is the last row
    with the same values (an extra final row, as fmuCheck writes)."""
    rows = np.flatnonzero(steps == 0) + 1
    last_only = rows.size == 1 and rows[0] == result.rows - 1 and all(
        v[-1] == v[-2] or not (np.isfinite(v[-1]) or np.isfinite(v[-2])) for v in result.values.values())
    return rows, last_only


def time_grid(result: Result, step: float | None = None) -> tuple[Check, float | None]:
    """Monotone times, no row twice, the step h, no rows missing, and the drift of t_k from
    t_0 + k h.

    h is the shortest decimal near the median step (or ``step``); a step of m h (m >= 2) is
    m - 1 rows missing; a shorter last step is the stop time off the grid. Allowed drift at
    row k: 2 k eps max(|t_k|, h) (a clock that sums its steps), half a nanosecond (a clock
    counting whole nanoseconds), and the times' printed resolution.

    Returns
    -------
    Check, and the step h (None when the grid is not uniform or not monotone).
    """
    t = result.time
    n = t.size
    if not np.all(np.isfinite(t)):
        nonfinite = int(np.flatnonzero(~np.isfinite(t))[0])
        return Check("time grid", "fail", f"time is {t[nonfinite]} at row {nonfinite + 1}", {"rows": n}), None
    steps = np.diff(t)
    back = np.flatnonzero(steps < 0)
    if back.size:
        b = int(back[0])
        return Check("time grid", "fail", f"not monotone: time goes back from {float(t[b])!r} to {float(t[b + 1])!r} "
                     f"at row {b + 2}", {"rows": n, "first_backstep_row": b + 2}), None
    span = float(t[-1] - t[0])
    if span <= 0:
        return Check("time grid", "fail", f"all {n} rows at t = {float(t[0])!r}: no time span", {"rows": n}), None
    repeated, extra_final_row = _duplicates(result, steps)
    keep = np.concatenate(([True], steps > 0))
    unique = t[keep]
    positive = np.diff(unique)
    h = float(step) if step else nominal_step(float(np.median(positive)))
    figures: dict[str, float | int | bool | str | list[int]] = {"rows": n, "start": float(t[0]), "end": float(t[-1]),
                                                    "step": h, "repeated_times": int(repeated.size)}
    if repeated.size and not extra_final_row:
        j = int(repeated[0])
        figures["duplicate_rows"] = [int(r) + 1 for r in repeated[:20]]
        return Check("time grid", "fail", f"{repeated.size} duplicate row(s): t = {t[j]:.10g} s is written again in "
                     f"row {j + 1}; the pendulum has no events, so no time may repeat", figures), None
    ratio = positive / h
    multiple = np.rint(ratio)
    on_grid = (multiple >= 1) & (np.abs(ratio - multiple) <= 1e-3 * multiple)
    short_last = positive.size > 0 and 0 < ratio[-1] < 1 - 1e-3
    if short_last:
        on_grid[-1] = True
        multiple[-1] = ratio[-1]
    if np.mean(on_grid) < 0.9:
        figures.update(uniform=False, smallest_step=float(positive.min()), largest_step=float(positive.max()))
        return Check("time grid", "info", f"{n} rows, {t[0]:.6g} to {t[-1]:.6g} s, not a uniform grid "
                     f"(steps {positive.min():.3g} to {positive.max():.3g} s): no k h to drift from", figures), None
    gaps = np.flatnonzero(on_grid & (multiple >= 2))
    rows = np.flatnonzero(keep)
    if gaps.size:
        missing = int(np.sum(multiple[gaps] - 1))
        g = int(gaps[0])
        figures.update(uniform=True, missing_rows=missing, first_gap_time=float(unique[g]))
        return Check("time grid", "fail", f"{missing} row(s) missing: the step from t = {unique[g]:.6g} s "
                     f"(row {rows[g] + 1}) is {int(multiple[g])} h, h = {h:.6g} s; {gaps.size} such gap(s)",
                     figures), h
    k = np.arange(unique.size, dtype=float)
    if short_last:
        k[-1] = k[-2] + ratio[-1]

    def drift(h: float) -> tuple[np.ndarray, np.ndarray]:
        """t_k - (t_0 + k h), and the rounding allowed at each row."""
        allowed = 2 * k * EPS * np.maximum(np.abs(unique), h) + HALF_NANOSECOND + result.resolution["time"][rows]
        if short_last:
            allowed[-1] = np.inf  # the stop time: off the grid by design
        return unique - (unique[0] + k * h), allowed

    deviation, allowed = drift(h)
    over = np.flatnonzero(np.abs(deviation) > allowed)
    last_full = unique.size - 2 if short_last else unique.size - 1
    if over.size and not step and last_full > 0:
        # a step that is no short decimal (a computed one, such as a period over 50): the
        # times' own step, when the grid holds to rounding with it
        own = float((unique[last_full] - unique[0]) / k[last_full])
        own_deviation, own_allowed = drift(own)
        if not np.any(np.abs(own_deviation) > own_allowed):
            h, deviation, allowed, over = own, own_deviation, own_allowed, own_deviation[:0].astype(int)
            figures["step"] = h
    worst = int(np.argmax(np.where(np.isfinite(allowed), np.abs(deviation), 0.0)))
    figures.update(uniform=True, largest_deviation=float(deviation[worst]), at_time=float(unique[worst]),
                   allowed_there=float(allowed[worst]), rows_over=int(over.size))
    extra = ", the last row written twice (an extra final row)" if extra_final_row else ""
    last = ", the last step shorter (the stop time)" if short_last else ""
    head = f"{n} rows{extra}{last}, {t[0]:.6g} to {t[-1]:.6g} s, step h = {h:.{6 if h == nominal_step(h) else 17}g} s"
    if over.size:
        first = int(over[0])
        figures["first_over_time"] = float(unique[first])
        return Check("time grid", "fail", f"{head}; times drift from k h: {deviation[worst]:+.2e} s at "
                     f"{_at(result, int(rows[worst]))}, first beyond rounding ({allowed[first]:.1e} s) at "
                     f"t = {unique[first]:.6g} s; {over.size} rows off", figures), h
    return Check("time grid", "pass", f"{head}; largest drift from k h {abs(deviation[worst]):.1e} s "
                 f"(at t = {unique[worst]:.6g} s; rounding allows {allowed[worst]:.1e})", figures), h


# --- exact columns -----------------------------------------------------------------------------

def slopes(ref: Reference, experiment: Experiment) -> dict[str, np.ndarray]:
    """d/dt of the exact theta and omega (for the effect of a rounded time)."""
    return {"theta": ref.omega, "omega": -(experiment.problem.g / experiment.problem.L) * np.sin(ref.theta)}


def print_rounding(result: Result, ref: Reference, experiment: Experiment, column: str) -> np.ndarray:
    """How far the print's rounding can move a column's value at each row: half a unit in its
    last printed digit, plus its rate of change times the time's uncertainty: the time's print
    rounding and one unit in the last place of the time (the importer's label and the FMU's
    clock are each a double, rounded apart: libcosim's k H from integer nanoseconds against the
    FMU's t + H differ by one ulp on some rows of a 1000 s run)."""
    rate = slopes(ref, experiment)[column.removesuffix("_exact")]
    return result.resolution[column] + np.abs(rate) * (result.resolution["time"] + np.spacing(np.abs(result.time)))


def clock_rounding(result: Result, ref: Reference, experiment: Experiment, column: str) -> np.ndarray:
    """How far the FMU's own clock can move a column's value from its value at the written
    time: its rate times one ulp of the time. An importer that writes t = k h while the FMU's
    clock is the sum of the communication points and steps (FMI4j: ``doStep(k h, h)``, the
    FMU at fl(k h + h), the file at fl((k + 1) h)) has the two one ulp apart in about a third
    of the rows, at any time."""
    rate = slopes(ref, experiment)[column.removesuffix("_exact")]
    return np.abs(rate) * np.spacing(np.abs(result.time))


def exact_mismatch(result: Result, ref: Reference, experiment: Experiment) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """For each exact column present: (|column - reference|, allowed) per row.

    Allowed: :data:`EXACT_AGREEMENT` max(1, |value|), the print's rounding
    (:func:`print_rounding`) and the time's own (:func:`clock_rounding`).
    """
    out = {}
    for name, exact_name in (("theta", "theta_exact"), ("omega", "omega_exact")):
        if exact_name in result.values:
            expected = getattr(ref, name)
            diff = np.abs(result.values[exact_name] - expected)
            allowed = (EXACT_AGREEMENT * np.maximum(1.0, np.abs(expected))
                       + print_rounding(result, ref, experiment, exact_name)
                       + clock_rounding(result, ref, experiment, exact_name))
            out[exact_name] = (np.where(np.isfinite(diff), diff, np.inf), allowed)
    return out


# --- errors of theta and omega ------------------------------------------------------------------

def growth(t: np.ndarray, error: np.ndarray) -> tuple[float, float] | None:
    """(p, C) of |error| ~ C t^p, fitted to the running maximum of |error| over the last 90 %
    of the time span (None when the error is 0 or the span too short)."""
    envelope = np.maximum.accumulate(np.abs(error))
    mask = (t >= 0.1 * t[-1]) & (envelope > 0) & (t > 0)
    if np.sum(mask) < 5:
        return None
    rows = np.flatnonzero(mask)
    rows = rows[:: max(1, rows.size // GROWTH_POINTS)]  # the envelope is monotone: a sample fits it alike
    p, log_c = np.polyfit(np.log(t[rows]), np.log(envelope[rows]), 1)
    return float(p), float(math.exp(log_c))


def describe_growth(fit: tuple[float, float] | None) -> str:
    """"grows linearly (|e| ~ 2.1e-03 t^1.02)" and the like."""
    if fit is None:
        return "no growth to fit"
    p, c = fit
    if p < 0.4:
        how = "stays level"
    elif abs(p - 1) <= 0.25:
        how = "grows linearly with t"
    elif abs(p - 2) <= 0.25:
        how = "grows quadratically with t"
    else:
        how = f"grows as t^{p:.1f}"
    return f"{how} (|e| ~ {c:.2g} t^{p:.2f})"


def state_errors(result: Result, ref: Reference) -> dict[str, np.ndarray]:
    """theta - theta_exact and omega - omega_exact (reference), for the columns present."""
    return {name: result.values[name] - getattr(ref, name) for name in ("theta", "omega") if name in result.values}


def error_check(result: Result, ref: Reference, name: str, error: np.ndarray) -> Check:
    """Largest error of ``name``, where, and how it grows."""
    bad = ~np.isfinite(error)
    if np.any(bad):
        k = int(np.flatnonzero(bad)[0])
        return Check(f"{name} error", "fail", f"{name} is {result.values[name][k]} at {_at(result, k)}",
                     {"first_nonfinite_time": float(result.time[k])})
    k = int(np.argmax(np.abs(error)))
    fit = growth(ref.t, error)
    figures = {"largest": float(abs(error[k])), "at_time": float(result.time[k]),
               "growth_power": fit[0] if fit else None, "growth_constant": fit[1] if fit else None}
    return Check(f"{name} error", "info", f"{name}: largest error {abs(error[k]):.2e} at t = {result.time[k]:.6g} s; "
                 f"{describe_growth(fit)}", figures)


def _neighbourhood(e: np.ndarray, width: int) -> np.ndarray:
    """The largest of e over the ``width`` rows either side of each row, the row itself left out."""
    out = np.zeros_like(e)
    for d in range(1, width + 1):
        np.maximum(out[d:], e[:-d], out=out[d:])
        np.maximum(out[:-d], e[d:], out=out[:-d])
    return out


def _outer_max(values: np.ndarray, width: int) -> np.ndarray:
    """The largest of ``values`` over rows 2..``width`` either side of each row (the row and its
    two next neighbours left out)."""
    out = np.zeros_like(values)
    for d in range(2, width + 1):
        np.maximum(out[d:], values[:-d], out=out[d:])
        np.maximum(out[:-d], values[d:], out=out[:-d])
    return out


def _second_difference(values: np.ndarray) -> np.ndarray:
    """|x_{k-1} - 2 x_k + x_{k+1}| / 2 at each inner row, 0 at the two ends."""
    out = np.zeros_like(values)
    out[1:-1] = np.abs(values[1:-1] - 0.5 * (values[:-2] + values[2:]))
    return out


def _smooth_solution(ref: Reference) -> np.ndarray:
    """Rows where the exact solution is smooth on the file's grid: its second differences
    there and at the two next rows at most CURVE_RATIO times the largest of the outer window's.
    Where it is not (the fast passage at the bottom of a swing near the separatrix, a few rows
    a period), an honest error can turn as sharply as the solution does."""
    smooth = np.ones(ref.t.size, dtype=bool)
    for curve in (ref.theta, ref.omega):
        bend = _second_difference(curve)
        near = np.maximum(bend, np.maximum(np.concatenate(([0.0], bend[:-1])), np.concatenate((bend[1:], [0.0]))))
        smooth &= near <= CURVE_RATIO * _outer_max(bend, ROUGH_WINDOW)
    return smooth


def isolated_values(result: Result, ref: Reference, errors: dict[str, np.ndarray], interface: str = "CS") -> Check:
    """Values whose error stands alone, which no integrator makes and a mangled file does.

    Two tests; rows too near either end for their window are not judged:

    - off the mean of their two neighbours by SPIKE_RATIO times the largest error of the
      NEIGHBOURS rows either side;
    - in a Model Exchange file (an importer's solver with dense output, whose error is smooth
      from row to row) where the exact solution is smooth on the file's grid
      (:func:`_smooth_solution`): off the mean of their two neighbours by SMOOTH_RATIO times
      the error curve's own roughness there (its largest such offset over rows 2..ROUGH_WINDOW
      either side), with an error of the opposite sign to both neighbours' and more than
      SMOOTH_ABOVE times the larger: a value off a smooth error curve, however small that
      curve's error. (A Co-Simulation file's error jumps at the FMU's step ends, by up to 50
      times its roughness in honest rkn runs of the judge's corpus: only the first test holds
      there. In the corpus's honest Model Exchange runs no row meets the second test; the
      closest same-sign one is 7.8 times its neighbours.)

    The scales are never below rounding (1e-14 max(1, |value|) and the print's resolution);
    the first is not below LEVEL times the file's largest error either, so that an error
    crossing zero next to a value cannot make that value look alone.
    """
    found: list[tuple[str, int, float, float, str]] = []
    for name, error in errors.items():
        if error.size < 3 or not np.all(np.isfinite(error)):
            continue
        scale = np.maximum(1.0, np.abs(getattr(ref, name)))
        e = np.abs(error)
        floor = np.maximum(1e-14 * scale + result.resolution[name], LEVEL * float(e.max()))
        around = np.maximum(_neighbourhood(e, NEIGHBOURS), floor)
        off = np.zeros_like(error)
        off[1:-1] = error[1:-1] - 0.5 * (error[:-2] + error[2:])
        spikes = np.abs(off) > SPIKE_RATIO * around
        # a full neighbourhood either side: the first rows, where the error is born from the exact
        # start value, and the last ones have too few neighbours to stand out from
        spikes[:NEIGHBOURS] = spikes[error.size - NEIGHBOURS:] = False
        rounding = 1e-14 * scale + result.resolution[name]
        rough = np.maximum(_outer_max(np.abs(off), ROUGH_WINDOW), rounding)
        near = np.maximum(_neighbourhood(e, 1), rounding)
        opposite = np.zeros(error.size, dtype=bool)
        side = np.sign(error)
        opposite[1:-1] = (side[:-2] == side[2:]) & (side[1:-1] == -side[2:]) & (side[2:] != 0)
        off_curve = (interface == "ME") & opposite & (np.abs(off) > SMOOTH_RATIO * rough) & (e > SMOOTH_ABOVE * near)
        off_curve[:ROUGH_WINDOW] = off_curve[error.size - ROUGH_WINDOW:] = False
        if off_curve.any():
            off_curve &= _smooth_solution(ref)
        found += [(name, int(k), float(off[k]), float(around[k]) if spikes[k] else float(rough[k]),
                   f"their error {around[k]:.1e}" if spikes[k] else
                   f"their errors lie on a smooth curve to {rough[k]:.1e}, the nearest {near[k]:.1e} of the "
                   "other sign")
                  for k in np.flatnonzero(spikes | off_curve)]
    if not errors:
        return Check("isolated values", "info", "no theta or omega column to look at")
    if not found:
        return Check("isolated values", "pass", f"no value stands out of its neighbours' error by {SPIKE_RATIO:g}x",
                     {"count": 0})
    name, k, jump, _, why = max(found, key=lambda f: abs(f[2]) / f[3])
    return Check("isolated values", "fail", f"{len(found)} value(s) out of line: {name} at {_at(result, k)} is "
                 f"{jump:+.2e} off its neighbours ({why}): a mangled value, no solver's error",
                 {"count": len(found), "variable": name, "at_time": float(result.time[k]), "jump": jump,
                  "rows": [f[1] + 1 for f in found[:20]]})


# --- the bound -----------------------------------------------------------------------------------

def me_allowance(ref: Reference, experiment: Experiment) -> Allowance:
    """The Model Exchange allowance of ``ref`` (computed here when ``ref`` carries none)."""
    if ref.accumulation is not None:
        return ref.accumulation
    return sensitivity.allowance(ref.t, ref.theta, ref.omega, experiment, ME_FACTOR)


def bound(name: str, ref: Reference, experiment: Experiment) -> np.ndarray:
    """The allowed |error| of ``name`` ("theta" or "omega") at each time.

    Co-Simulation, the certificate's bound (docs/certificate.md): 100 tol max(1, |theta_e|) and
    100 tol max(w0, |omega_e|). Model Exchange: a local error of ME_FACTOR tol (the same
    scales) per natural period 2 pi / w0, each propagated to the row's time by the pendulum's
    linearised flow (the energy error's phase drift included) and summed, plus ME_FACTOR tol
    at the row (:mod:`pendulum_fmu.judge.sensitivity`; docs/importers.md, "The bound").
    """
    if experiment.interface == "ME":
        return getattr(me_allowance(ref, experiment), name)
    if name == "theta":
        scale = np.maximum(1.0, np.abs(ref.theta))
    else:
        scale = np.maximum(experiment.problem.w0, np.abs(ref.omega))
    return CS_FACTOR * experiment.tolerance * scale


def bound_check(result: Result, ref: Reference, experiment: Experiment, errors: dict[str, np.ndarray]) -> Check:
    """Every theta and omega within :func:`bound`; the line says what allows the error shown."""
    tol_text = f"tol = {experiment.tolerance:g}{'' if experiment.tolerance_stated else ' (the experiment default)'}"
    if experiment.interface == "CS":
        what, why, extra = "the certificate's bound 100 tol", "", {}
    else:
        allowance = me_allowance(ref, experiment)
        what = f"the ME bound {ME_FACTOR:g} tol x growth"
        why = f" ({allowance.describe(experiment.start_time)})"
        extra = allowance.numbers()
    if not errors:
        return Check("bound", "info", f"no theta or omega column: {what} not applied", {})
    worst_ratio, worst = -1.0, ("", 0)
    over = 0
    for name, error in errors.items():
        ratio = np.abs(error) / bound(name, ref, experiment)
        ratio = np.where(np.isnan(ratio), np.inf, ratio)
        over += int(np.sum(ratio > 1))
        k = int(np.argmax(ratio))
        if ratio[k] > worst_ratio:
            worst_ratio, worst = float(ratio[k]), (name, k)
    name, k = worst
    figures = {"interface": experiment.interface, "tolerance": experiment.tolerance, "worst_ratio": worst_ratio,
               "variable": name, "at_time": float(result.time[k]), "rows_over": over, **extra}
    if over:
        return Check("bound", "fail", f"{over} values beyond {what}{why} ({tol_text}); worst {name} at "
                     f"t = {result.time[k]:.6g} s, {worst_ratio:.3g} times the bound", figures)
    because = _allowed_there(result, ref, experiment, name, k, figures)
    return Check("bound", "pass", f"within {what}{why} ({tol_text}); worst {name} at t = {result.time[k]:.6g} s, "
                 f"{worst_ratio:.2g} of the bound{because}", figures)


def _allowed_there(result: Result, ref: Reference, experiment: Experiment, name: str, k: int,
                   figures: dict[str, Any]) -> str:
    """Why the error at row k is allowed, where the bound there is more than 100 tol in the
    state's natural unit (CS: a large |theta_e| or |omega_e|), and how much of it the print's
    rounding takes; adds the figures."""
    allowed = float(bound(name, ref, experiment)[k])
    parts = []
    if experiment.interface == "CS":
        value = float(abs(getattr(ref, name)[k]))
        unit, natural = ("rad", 1.0) if name == "theta" else ("rad/s", experiment.problem.w0)
        if value > natural:
            parts.append(f"the bound grows with |{name}_e| = {value:.4g} {unit} there: 100 tol |{name}_e| = "
                         f"{allowed:.1e}")
    rounding = float(print_rounding(result, ref, experiment, name)[k])
    figures["print_rounding_there"] = rounding
    if result.formats is not None and rounding >= 0.1 * allowed:
        parts.append(f"the print's rounding there ({result.formats[name].describe()}: {rounding:.1e}) is "
                     f"{rounding / allowed:.2g} of the bound")
    return f" ({'; '.join(parts)})" if parts else ""
