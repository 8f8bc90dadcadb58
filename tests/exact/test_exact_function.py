"""``pendulum_fmu.exact``: the C library pendulum_exact over numpy arrays, the FMU's theta_exact bit for bit."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from scipy.special import ellipj, ellipk

from pendulum_fmu import exact
from pendulum_fmu.fmu.exact_port import ExactPort

CASES = [  # theta0 (rad), omega0 (rad/s), L (m), g (m/s^2): every regime
    (math.radians(80.0), 0.0, 1.0, 9.81),
    (math.radians(179.9999), 0.0, 2.0, 9.81),
    (math.pi, 0.0, 1.0, 9.81),
    (0.3, 2.0, 0.5, 3.7),
    (0.0, 2.0 * math.sqrt(9.81), 1.0, 9.81),      # separatrix
    (-1.0, -9.0, 1.0, 9.81),                       # rotation, backwards
]


@pytest.mark.parametrize("case", CASES)
def test_equals_the_fmus_theta_exact_bit_for_bit(fmu_path: Path, case: tuple[float, float, float, float]) -> None:
    times = np.linspace(0.0, 37.0, 211)
    theta, omega = exact(*case, times)
    with ExactPort(fmu_path) as port:
        port.initialize(*case)
        fmu_theta, fmu_omega = port.evaluate(times)
    assert np.array_equal(theta, fmu_theta) and np.array_equal(omega, fmu_omega)


def test_agrees_with_scipy_ellipj_in_libration() -> None:
    theta0, w0 = math.radians(75.0), math.sqrt(9.81)
    m = math.sin(theta0 / 2.0) ** 2
    times = np.linspace(0.0, 20.0, 1001)
    sn, _, dn, _ = ellipj(w0 * times + ellipk(m), m)        # released from rest: u = w0 t + K
    reference = 2.0 * np.arctan2(math.sqrt(m) * sn, dn)
    theta, _ = exact(theta0, 0.0, 1.0, 9.81, times)
    assert np.max(np.abs(theta - reference)) < 1e-12


def test_inputs_broadcast_and_bad_ones_give_nan() -> None:
    theta, omega = exact(np.array([[0.5], [1.0]]), 0.0, [1.0, -1.0, 2.0], 9.81, 0.7)
    assert theta.shape == (2, 3)
    assert np.isnan(theta[:, 1]).all() and np.isfinite(theta[:, [0, 2]]).all()
    single, _ = exact(1.0, 0.0, 2.0, 9.81, 0.7)
    assert single.shape == () and single == theta[1, 2]
    nan_time, _ = exact(1.0, 0.0, 1.0, 9.81, [0.1, math.nan])
    assert math.isfinite(nan_time[0]) and math.isnan(nan_time[1])


def test_a_missing_library_is_one_line_naming_the_platform(tmp_path: Path) -> None:
    code = ("import os; os.environ['PENDULUM_EXACT_LIB'] = '/nonexistent/libpendulum_exact.so'\n"
            "from pendulum_fmu.cli.main import main\n"
            "import pendulum_fmu\n"
            "try:\n    pendulum_fmu.exact(1.0, 0.0, 1.0, 9.81, 0.5)\n"
            "except pendulum_fmu.BuildError as error:\n    print(error)\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert done.stdout.strip() == "$PENDULUM_EXACT_LIB names no file: '/nonexistent/libpendulum_exact.so'"
    assert done.stderr == ""


def test_threads_give_the_values_of_one_thread_bit_for_bit() -> None:
    """Both C entries (one state over many times, a state per point), split over 1 .. 7 threads."""
    rng = np.random.default_rng(27)
    times = rng.uniform(-50.0, 50.0, 100_003)
    states = (rng.uniform(-4.0, 4.0, 100_003), rng.uniform(-8.0, 8.0, 100_003), 1.3, 9.81)
    for args in [(*CASES[0], times), (*CASES[4], times), (*CASES[5], times), (*states, times)]:
        one = exact(*args, workers=1)
        for workers in (2, 3, 7):
            split = exact(*args, workers=workers)
            for a, b in zip(one, split, strict=True):
                assert a.tobytes() == b.tobytes(), workers


def test_large_arrays_are_split_over_the_usable_cores_and_small_ones_are_not(monkeypatch: pytest.MonkeyPatch) -> None:
    import threading

    from pendulum_fmu.fmu import library

    assert library.usable_cores() >= 1
    assert library.thread_count(1000) == 1                               # small: the calling thread
    assert library.thread_count(10_000_000) == min(library.usable_cores(), library.MAX_THREADS)
    assert library.thread_count(3 * library.MIN_POINTS_PER_THREAD) == min(library.usable_cores(), 3)
    assert library.thread_count(10, workers=16) == 10 and library.thread_count(10**6, workers=3) == 3
    for bad in (0, -1, 1.5, True):
        with pytest.raises(ValueError, match="workers must be a positive integer"):
            exact(0.5, 0.0, 1.0, 9.81, [0.0, 1.0], workers=bad)  # type: ignore[arg-type]
    parts = library.chunks(1_000_003, 3)
    assert parts[0][0] == 0 and parts[-1][1] == 1_000_003 and len(parts) == 3
    assert all(b == c and b % library.ALIGN == 0 for (_, b), (c, _) in zip(parts, parts[1:], strict=False))
    seen: set[str] = set()
    original = library._library()

    class Recording:
        """The library, noting the thread of each call."""

        def __getattr__(self, name: str) -> object:
            function = getattr(original, name)

            def call(*args: object) -> object:
                seen.add(threading.current_thread().name)
                return function(*args)
            return call

    monkeypatch.setattr(library, "_library", Recording)
    exact(0.5, 0.0, 1.0, 9.81, np.linspace(0.0, 1.0, 1000), workers=2)
    assert len(seen) == 2 and threading.current_thread().name in seen, seen


def _exact_in_a_forked_child(queue: Any) -> None:
    t = np.linspace(0.0, 10.0, 300_000)
    theta, _ = exact(np.radians(170.0), 0.0, 1.0, 9.81, t, workers=2)
    queue.put(float(theta[-1]))


def test_a_forked_child_evaluates_on_threads_of_its_own() -> None:
    """A process forked after exact() ran on threads inherits the pool but not its threads:
    the child must make its own pool, not wait for ever on the parent's."""
    import multiprocessing

    t = np.linspace(0.0, 10.0, 300_000)
    theta, _ = exact(np.radians(170.0), 0.0, 1.0, 9.81, t, workers=2)  # the parent's pool now exists
    context = multiprocessing.get_context("fork")
    queue = context.Queue()
    child = context.Process(target=_exact_in_a_forked_child, args=(queue,))
    child.start()
    child.join(60)
    hung = child.is_alive()
    if hung:
        child.kill()
    assert not hung, "the forked child hung in exact()"
    assert child.exitcode == 0 and queue.get(timeout=5) == float(theta[-1])
