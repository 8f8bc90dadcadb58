"""With one state per point, ``exact()`` adds at most 20 % to the C call it wraps (issue 27, item 3).

CPU time of this process (``time.process_time``), best of five interleaved rounds, so the
load of other processes on the machine does not count. The C call is ``pendulum_exact_many``
on arrays already contiguous, the wrapper is ``exact()`` given the scalars and two arrays a
phase portrait gives it (what it broadcasts and copies is its own cost).
"""

from __future__ import annotations

import math
import time

import numpy as np

from pendulum_fmu.fmu.library import _library, exact

POINTS = 200_000


def test_the_wrapper_adds_at_most_a_fifth_to_the_c_call() -> None:
    library = _library()
    theta0 = math.radians(80.0) * (1.0 + 1e-9 * (np.arange(POINTS) % 1024))
    times = np.random.default_rng(27).uniform(0.0, 100.0, POINTS)
    arrays = [theta0, np.zeros(POINTS), np.ones(POINTS), np.ones(POINTS), times]
    theta, omega = np.empty(POINTS), np.empty(POINTS)
    c_best = wrapped_best = math.inf
    for _ in range(5):
        start = time.process_time()
        library.pendulum_exact_many(POINTS, *arrays, theta, omega)
        c_best = min(c_best, time.process_time() - start)
        start = time.process_time()
        values = exact(theta0, 0.0, 1.0, 1.0, times, workers=1)
        wrapped_best = min(wrapped_best, time.process_time() - start)
    assert values[0].tobytes() == theta.tobytes() and values[1].tobytes() == omega.tobytes()
    assert wrapped_best <= 1.2 * c_best, (f"exact() {1e9 * wrapped_best / POINTS:.0f} ns a point, "
                                          f"its C call {1e9 * c_best / POINTS:.0f} ns")
