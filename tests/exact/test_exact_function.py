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


def random_states(count: int, seed: int) -> tuple[np.ndarray, ...]:
    """``count`` states of every kind, most of them releases from rest (the batched path):
    any angle, next to the top, just past pi, tiny; moving librations, rotations; runs of
    one L and g; times within 50 periods and a few at 1e6 periods."""
    rng = np.random.default_rng(seed)
    theta0 = rng.uniform(-math.pi, math.pi, count)
    kind = rng.uniform(0.0, 1.0, count)
    near_top = kind < 0.1
    theta0[near_top] = np.sign(theta0[near_top]) * math.pi * (1.0 - 10.0 ** rng.uniform(-16.0, -1.0, near_top.sum()))
    past_pi = (kind >= 0.1) & (kind < 0.15)
    theta0[past_pi] = np.sign(theta0[past_pi]) * (math.pi + rng.uniform(0.0, 0.058, past_pi.sum()))
    tiny = (kind >= 0.15) & (kind < 0.2)
    theta0[tiny] *= 10.0 ** rng.uniform(-300.0, 0.0, tiny.sum())
    length = np.repeat(rng.uniform(0.1, 5.0, count // 4 + 1), 4)[:count]   # runs of one L and g
    gravity = np.repeat(rng.uniform(1.0, 20.0, count // 4 + 1), 4)[:count]
    omega0 = np.where(kind > 0.8, rng.uniform(-3.0, 3.0, count) * np.sqrt(gravity / length), 0.0)
    periods = np.where(rng.uniform(0.0, 1.0, count) < 0.95, 50.0, 1e6)
    times = rng.uniform(-1.0, 1.0, count) * periods * 2.0 * math.pi * np.sqrt(length / gravity)
    return theta0, omega0, length, gravity, times


def test_a_state_per_point_is_each_states_own_evaluation_bit_for_bit() -> None:
    """exact() over arrays of states (set up and evaluated in blocks) gives each state's values
    as exact() with that state alone (one set-up, the scalar evaluation) gives them."""
    theta0, omega0, length, gravity, times = random_states(3000, seed=38)
    theta, omega = exact(theta0, omega0, length, gravity, times)
    for i in range(theta0.size):
        alone = exact(theta0[i], omega0[i], length[i], gravity[i], [times[i], times[i]])
        assert theta[i].tobytes() == alone[0][0].tobytes() and omega[i].tobytes() == alone[1][0].tobytes(), i


def test_a_state_per_point_is_the_fmus_theta_exact_bit_for_bit(fmu_path: Path) -> None:
    theta0, omega0, length, gravity, times = random_states(40, seed=39)
    theta, omega = exact(theta0, omega0, length, gravity, times)
    for i in range(theta0.size):
        with ExactPort(fmu_path) as port:
            port.initialize(theta0[i], omega0[i], length[i], gravity[i])
            fmu_theta, fmu_omega = port.evaluate(np.array([times[i]]))
        assert theta[i].tobytes() == fmu_theta[0].tobytes() and omega[i].tobytes() == fmu_omega[0].tobytes(), i


def test_scalars_and_arrays_broadcast_to_the_same_bits() -> None:
    """A scalar input goes to C as one value (stride 0), an array whole: every mix of the two,
    2-D broadcasting, and runs of one state longer than the library's block of 256 give the
    values of full arrays element by element."""
    rng = np.random.default_rng(256)
    theta0 = rng.uniform(-3.0, 3.0, 700)
    times = rng.uniform(-50.0, 50.0, 700)
    full = exact(theta0, np.full(700, 0.5), np.full(700, 1.5), np.full(700, 9.81), times)
    mixed = exact(theta0, 0.5, 1.5, 9.81, times)
    assert all(a.tobytes() == b.tobytes() for a, b in zip(full, mixed, strict=True))
    # one state over 700 times as a stride-0 state: the one-state path's values
    run = exact(np.full(700, 1.2), 0.0, 1.5, 9.81, times)
    alone = exact(1.2, 0.0, 1.5, 9.81, times)
    assert all(a.tobytes() == b.tobytes() for a, b in zip(run, alone, strict=True))
    grid = exact(theta0[:30, None], 0.0, np.array([0.5, 1.0, 2.0]), 9.81, times[:30, None])
    assert grid[0].shape == (30, 3)
    for j, length in enumerate((0.5, 1.0, 2.0)):
        column = exact(theta0[:30], 0.0, length, 9.81, times[:30])
        assert grid[0][:, j].tobytes() == column[0].tobytes() and grid[1][:, j].tobytes() == column[1].tobytes()
