"""``exact()`` with one state per point gives the C call's numbers (the overhead it adds is
``pendulum-fmu bench exact``'s figure: no test asserts a timing, tests/package/test_no_timed_tests.py).

The C call is ``pendulum_exact_many`` on arrays already contiguous, the wrapper is ``exact()``
given the scalars and two arrays a phase portrait gives it.
"""

from __future__ import annotations

from pendulum_fmu.bench.exact import wrapper_overhead

POINTS = 200_000


def test_the_wrapper_gives_the_c_calls_numbers() -> None:
    c_best, wrapped_best, same = wrapper_overhead(POINTS, 1)
    assert same
    print(f"exact() {1e9 * wrapped_best / POINTS:.0f} ns a point, its C call {1e9 * c_best / POINTS:.0f} ns")
