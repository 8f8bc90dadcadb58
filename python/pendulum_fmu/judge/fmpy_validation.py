"""What fmpy's cross-check validation says of a result: a band of 10 % of each signal's range
around the reference, the check called ``fmpy band``.

fmpy's ``fmpy.cross_check.validate_result`` (the rule of the FMI cross-check, 9.2.5) resamples
the reference to ``SAMPLES`` equally spaced times from the first to the last reference time,
widens it by the extremes of ``WINDOW`` neighbouring samples and by ``WIDTH`` of the
reference's range (of ``|value|`` when the signal is constant, ``0.5`` when it is 0), and
passes a signal when at most ``LIMIT`` of the result's rows lie outside that band (linearly
interpolated to the rows' times; rows outside the reference's span are not counted). The
same rule is written here with numpy alone, in O(rows), so that it costs little on a file of
millions of rows; ``tests/judge/test_cross_check.py`` checks that it agrees with fmpy's.

Here the reference is the exact solution at the file's own times, so the check shows what
the loose rule lets through: it is reported with the status ``info`` and never decides.
"""

from __future__ import annotations

import numpy as np

from pendulum_fmu.judge.checks import Reference
from pendulum_fmu.judge.reading import Result
from pendulum_fmu.judge.verdict import Check

SAMPLES = 1000
"""Samples of the resampled reference."""
WINDOW = 21
"""Neighbouring samples (10 to either side) whose extremes bound the band."""
WIDTH = 0.1
"""The band's half width, as a fraction of the reference's range."""
LIMIT = 0.1
"""The largest fraction of rows outside the band that still passes."""


def _sliding(values: np.ndarray, window: int, pick: str) -> np.ndarray:
    """The minimum or maximum of ``window`` samples centred on each sample, the window cut at the ends.

    Cutting the window equals scipy's ``reflect`` boundary (fmpy's) for a minimum or maximum:
    the reflected samples near an end are samples the cut window already holds.
    """
    half = window // 2
    padded = np.concatenate((np.full(half, values[0]), values, np.full(half, values[-1])))
    windows = np.lib.stride_tricks.sliding_window_view(padded, window)
    return windows.min(axis=1) if pick == "min" else windows.max(axis=1)


def outside_fractions(t: np.ndarray, t_ref: np.ndarray,
                      signals: dict[str, tuple[np.ndarray, np.ndarray]]) -> dict[str, float]:
    """The fraction of the rows of each signal outside the cross-check band around its reference.

    Parameters
    ----------
    t : numpy.ndarray
        The result's times.
    t_ref : numpy.ndarray
        The reference's times (non-decreasing); repeated times keep their first value.
    signals : dict of str to (values, reference values)
        Each signal's values at ``t`` and its reference at ``t_ref``.

    Returns
    -------
    dict of str to float
        Per signal: its rows outside the band, within the reference's span, divided by all rows.
    """
    t_start, t_stop = float(t_ref[0]), float(t_ref[-1])
    t_band = np.linspace(t_start, t_stop, SAMPLES)
    keep = np.concatenate(([True], np.diff(t_ref) > 0))
    t_kept = t_ref[keep]
    in_span = (t >= t_start) & (t <= t_stop)
    fractions = {}
    for name, (y, y_ref) in signals.items():
        y_band = np.interp(t_band, t_kept, y_ref[keep])
        low, high = float(np.min(y_band)), float(np.max(y_band))
        if low == high:
            width = 0.5 if low == 0 else abs(low) * WIDTH
        else:
            width = (high - low) * WIDTH
        y_min = np.interp(t, t_band, _sliding(y_band, WINDOW, "min") - width)
        y_max = np.interp(t, t_band, _sliding(y_band, WINDOW, "max") + width)
        # as fmpy writes it: a NaN compares false both ways, so it is never outside
        outside = ((y < y_min) | (y > y_max)) & in_span
        fractions[name] = float(np.count_nonzero(outside)) / float(y.size)
    return fractions


def outside_fraction(t: np.ndarray, y: np.ndarray, t_ref: np.ndarray, y_ref: np.ndarray) -> float:
    """:func:`outside_fractions` for one signal ``y(t)`` and its reference ``y_ref(t_ref)``."""
    return outside_fractions(t, t_ref, {"y": (y, y_ref)})["y"]


def fmpy_validation_check(result: Result, ref: Reference) -> Check:
    """fmpy's cross-check band, with the exact solution at the file's times as the reference.

    Every variable of the file is compared (theta and omega with the exact theta and omega,
    theta_exact and omega_exact likewise). The status is ``info``: the line says whether
    fmpy's validation would pass the file, and by how much, next to the judge's own verdict.
    """
    exact = {"theta": ref.theta, "omega": ref.omega, "theta_exact": ref.theta, "omega_exact": ref.omega}
    fractions = outside_fractions(result.time, result.time,
                                  {name: (np.asarray(values, dtype=float), exact[name])
                                   for name, values in result.values.items() if name in exact})
    figures: dict[str, object] = {"outside": fractions, "limit": LIMIT}
    if not fractions:
        return Check("fmpy band", "info", "no variable to compare", {**figures, "passes": None})
    worst = max(fractions, key=lambda name: fractions[name])
    passes = fractions[worst] <= LIMIT
    figures["passes"] = passes
    rule = (f"the cross-check band ({WIDTH:.0%} of each signal's range, {WINDOW // 2} of {SAMPLES} samples "
            f"either side; fails above {LIMIT:.0%} of the rows outside)")
    spread = ", ".join(f"{name} {fraction:.1%}" for name, fraction in fractions.items())
    verdict = "would pass" if passes else "would fail"
    return Check("fmpy band", "info", f"fmpy's validation {verdict} this file: rows outside {rule}: {spread}",
                 figures)
