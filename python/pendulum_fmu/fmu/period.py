"""Periods: the exact curve T / T0 for the figures, and one measured from a simulated time series.

A run's period is the FMU's own ``period`` output (:meth:`~pendulum_fmu.fmu.runner.FmuRunner.run`
reads it after initialization); :func:`exact_period_ratio` draws the dense exact curve of the
figures over amplitudes no run was made at.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.special import ellipkm1


def exact_period_ratio(amplitude_rad: np.ndarray | float) -> np.ndarray:
    """T / T0 = 2 K(m) / pi with m = sin^2(theta0 / 2), for release from rest.

    Parameters
    ----------
    amplitude_rad : array_like
        Amplitudes theta0 in (-pi, pi), rad.

    Returns
    -------
    numpy.ndarray
        The period over the small-angle period T0 = 2 pi sqrt(L / g).
    """
    half = np.asarray(amplitude_rad, dtype=float) / 2.0
    # scipy's ellipkm1 takes m1 = cos^2(theta0/2) directly: no cancellation near the top.
    return 2.0 * ellipkm1(np.cos(half) ** 2) / math.pi


def measured_period(time: np.ndarray, theta: np.ndarray) -> float:
    """Period measured from the downward zero crossings of theta.

    The crossing times are located by linear interpolation (theta'' = 0 where theta = 0,
    so the interpolation error is of third order) and the period is the least-squares
    slope of crossing time against crossing number.

    Parameters
    ----------
    time, theta : numpy.ndarray
        A sampled solution covering at least two full periods.

    Returns
    -------
    float
        The measured period in seconds, NaN with fewer than two crossings.
    """
    down = np.nonzero((theta[:-1] > 0.0) & (theta[1:] <= 0.0))[0]
    if down.size < 2:
        return math.nan
    fraction = theta[down] / (theta[down] - theta[down + 1])
    crossings = time[down] + fraction * (time[down + 1] - time[down])
    slope, _ = np.polyfit(np.arange(crossings.size), crossings, 1)
    return float(slope)
