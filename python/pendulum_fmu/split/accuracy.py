"""How accurate a coupled result is: its error against the exact pendulum, where, its growth, its
rank among the reference masters at the same H, and over several runs the observed order.

The error is the largest |theta - theta_exact| at the file's rows (theta_exact from
``pendulum_fmu.exact`` at the grid's exact times); its growth is p in error ~ t^p between the
first half of the run and the whole. The rank compares the file's error with each reference
master's on the same rows (the reruns of :mod:`pendulum_fmu.split.identify`). Over runs at
several H the order p and constant C fit error = C H^p by least squares in log-log.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

SAME = 1e-9
"""Two errors within this relative difference rank equal."""


@dataclass(frozen=True)
class Accuracy:
    """The error of one run.

    Attributes
    ----------
    error : float
        Largest |theta - theta_exact| (rad).
    at : float
        Where (s).
    growth : float
        p in error ~ t^p (NaN when the first half has no error).
    rank : str
        Among the reference masters at the same H, in words ("" when none was rerun).
    compared : float
        The file's error over the rows the reference masters were rerun over (the rank's).
    reference_errors : dict of str to float
        The reference masters' errors over those rows.
    """

    error: float
    at: float
    growth: float
    rank: str = ""
    compared: float = math.nan
    reference_errors: dict[str, float] = field(default_factory=dict)


def rank(error: float, references: dict[str, float], identified: str | None = None) -> str:
    """Where ``error`` sits among the reference masters' errors, in words (the ``identified``
    master's place when the run reproduces one)."""
    from pendulum_fmu.split.masters import master_named

    if not references:
        return ""
    ordered = sorted(references.items(), key=lambda item: item[1])
    count = len(ordered)
    described = [(master_named(name).describe(), value) for name, value in ordered]
    same = [master_named(identified).describe()] if identified in references else \
        [text for text, value in described if abs(value - error) <= SAME * max(error, value)]
    if same:
        return f"as {same[0]} ({error:.3g}): rank {[t for t, _ in described].index(same[0]) + 1} of {count}"
    if error < ordered[0][1]:
        return f"better than all {count} reference masters (best: {described[0][0]}, {ordered[0][1]:.3g})"
    if error > ordered[-1][1]:
        return f"worse than all {count} reference masters (worst: {described[-1][0]}, {ordered[-1][1]:.3g})"
    above = next(i for i, (_, value) in enumerate(ordered) if value > error)
    return (f"between {described[above - 1][0]} ({ordered[above - 1][1]:.3g}) and {described[above][0]} "
            f"({ordered[above][1]:.3g}), rank {above + 1} of {count + 1}")


def accuracy(time: np.ndarray, theta: np.ndarray, exact_theta: np.ndarray, within: np.ndarray | None = None,
             references: dict[str, float] | None = None, identified: str | None = None) -> Accuracy:
    """The error of a run (see the module's docstring); ``within`` marks the rows the reference
    masters were compared on; ``identified``, the master the run reproduces."""
    errors = np.abs(theta - exact_theta)
    worst = int(np.nanargmax(errors))
    error = float(errors[worst])
    half = time <= time[0] + (time[-1] - time[0]) / 2
    early = float(np.nanmax(errors[half]))
    growth = math.log2(error / early) if early > 0 and error > 0 else math.nan
    if not references or within is None:
        return Accuracy(error, float(time[worst]), growth)
    compared = float(np.nanmax(errors[within]))
    return Accuracy(error, float(time[worst]), growth, rank(compared, references, identified), compared,
                    dict(references))


@dataclass(frozen=True)
class Order:
    """The observed order over several runs of one master: error = C H^p.

    Attributes
    ----------
    order : float
        p, by least squares on log(error) against log(H).
    constant : float
        C (rad / s^p).
    runs : int
        The number of runs fitted (distinct H).
    pairs : list of float
        The order between consecutive H (largest first).
    """

    order: float
    constant: float
    runs: int
    pairs: list[float]


def observed_order(steps: list[float], errors: list[float]) -> Order | None:
    """The order and constant over runs at ``steps`` with ``errors`` (None under two distinct H)."""
    pairs = sorted((h, e) for h, e in zip(steps, errors, strict=True) if h > 0 and e > 0 and math.isfinite(e))
    if len({h for h, _ in pairs}) < 2:
        return None
    x = np.log([h for h, _ in pairs])
    y = np.log([e for _, e in pairs])
    p, c = np.polyfit(x, y, 1)
    descending = pairs[::-1]
    consecutive = [math.log(descending[i][1] / descending[i + 1][1]) / math.log(descending[i][0] / descending[i + 1][0])
                   for i in range(len(descending) - 1) if descending[i][0] != descending[i + 1][0]]
    return Order(float(p), float(math.exp(c)), len(pairs), consecutive)
