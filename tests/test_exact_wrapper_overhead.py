"""With one state per point, ``exact()`` adds at most 20 % to the C call it wraps.

CPU time of this process (``time.process_time``), best of five interleaved rounds, so the
load of other processes on the machine does not count. The C call is ``pendulum_exact_many``
on arrays already contiguous, the wrapper is ``exact()`` given the scalars and two arrays a
phase portrait gives it (what it broadcasts and copies is its own cost).
"""

from __future__ import annotations

from pendulum_fmu.bench.exact import wrapper_overhead

POINTS = 200_000


def test_the_wrapper_adds_at_most_a_fifth_to_the_c_call() -> None:
    c_best, wrapped_best, same = wrapper_overhead(POINTS, 5)
    assert same
    assert wrapped_best <= 1.2 * c_best, (f"exact() {1e9 * wrapped_best / POINTS:.0f} ns a point, "
                                          f"its C call {1e9 * c_best / POINTS:.0f} ns")
