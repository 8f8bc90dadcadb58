"""The cost to reach an error: one method's work-precision front and a level read off it.

A method run at several tolerances gives (cost, error) pairs. Its *front* keeps the pairs no
cheaper pair beats in error; the cost to reach an error e is read off the front by log-log
interpolation between the two front pairs around e (the cheapest pair if it is already below
e; infinite if no pair reaches e). The same rule for every method, here for the study's
report and in :mod:`pendulum_fmu.bench.workprecision.analysis` for ``bench solvers``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable


def pareto_front(pairs: Iterable[tuple[float, float]]) -> list[tuple[float, float]]:
    """The (error, cost) pairs that no cheaper pair beats in error, by increasing cost.

    Parameters
    ----------
    pairs : iterable of (float, float)
        (cost, error) of one method, one pair a tolerance; errors that are not > 0 (or NaN)
        are left out, since a log scale cannot place them.

    Returns
    -------
    list of (float, float)
        (error, cost), errors strictly decreasing as the cost increases.
    """
    kept: list[tuple[float, float]] = []
    for cost, error in sorted(pairs):
        if error > 0.0 and (not kept or error < kept[-1][0]):
            kept.append((error, cost))
    return kept


def cost_to_reach(front: list[tuple[float, float]], error: float) -> float:
    """The cost at which a method's front reaches ``error`` (log-log interpolation).

    Parameters
    ----------
    front : list of (float, float)
        :func:`pareto_front`'s (error, cost) pairs.
    error : float
        The error level (> 0).

    Returns
    -------
    float
        The interpolated cost; +inf if no pair reaches ``error``.
    """
    if not front or front[-1][0] > error:
        return math.inf
    if front[0][0] <= error:
        return front[0][1]
    for (e0, c0), (e1, c1) in zip(front, front[1:], strict=False):   # neighbours
        if e1 <= error <= e0:
            w = math.log(e0 / error) / math.log(e0 / e1)
            return math.exp((1.0 - w) * math.log(c0) + w * math.log(c1))
    return math.inf  # not reached: the loop covers every e between the first and last
