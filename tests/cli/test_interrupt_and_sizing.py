"""The two helpers that keep the commands safe: SIGINT deferred around FMU calls, and work sized before it starts."""

from __future__ import annotations

import ctypes
import math
import os
import signal
from pathlib import Path
from typing import Any

import pytest

from pendulum_fmu import interrupt
from pendulum_fmu.errors import UsageError
from pendulum_fmu.fmu.runner import FmuRunner
from pendulum_fmu.sizing import BYTES_PER_POINT, check_run, check_sweep, planned_run
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid
from pendulum_fmu.sweep.grid import SweepGrid


@pytest.fixture()
def default_sigint() -> object:
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    interrupt.forget()
    yield
    signal.signal(signal.SIGINT, previous)
    interrupt.forget()


def test_sigint_inside_a_ctypes_callback_is_raised_after_the_call(default_sigint: object) -> None:
    """The reproducer of the lost Ctrl-C: SIGINT while C calls back into Python."""
    calls: list[int] = []

    @ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p)
    def compare(a: int, b: int) -> int:  # qsort calls it from C, as CVODE calls the right-hand side
        if not calls:
            os.kill(os.getpid(), signal.SIGINT)  # handled at the next bytecode: inside this callback
        calls.append(1)
        return 0

    values = (ctypes.c_int * 64)(*range(64))
    libc = ctypes.CDLL(None)
    with pytest.raises(KeyboardInterrupt):
        with interrupt.deferred_interrupt():
            libc.qsort(values, 64, ctypes.sizeof(ctypes.c_int), compare)
            assert len(calls) > 1, "the callback was cut short"
            assert interrupt.pending()
    assert not interrupt.pending()
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


def test_an_interrupt_replaces_the_error_it_caused(default_sigint: object) -> None:
    with pytest.raises(KeyboardInterrupt):
        with interrupt.deferred_interrupt():
            os.kill(os.getpid(), signal.SIGINT)
            raise RuntimeError("the solver stopped because of the interrupt")


def test_without_sigint_nothing_changes(default_sigint: object) -> None:
    with interrupt.deferred_interrupt():
        pass
    with pytest.raises(ValueError):
        with interrupt.deferred_interrupt():
            raise ValueError("a real error")


def test_an_interrupt_swallowed_on_its_way_is_raised_at_the_next_run(default_sigint: object) -> None:
    interrupt.default_dispositions()
    try:
        os.kill(os.getpid(), signal.SIGINT)
    except KeyboardInterrupt:
        pass  # a library's bare "except:" in the way
    with pytest.raises(KeyboardInterrupt):
        with interrupt.deferred_interrupt():
            pytest.fail("a run started after an interrupt")


def test_an_ignored_sigint_is_left_ignored() -> None:
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        with interrupt.deferred_interrupt():
            assert signal.getsignal(signal.SIGINT) == signal.SIG_IGN
    finally:
        signal.signal(signal.SIGINT, previous)


@pytest.mark.parametrize(("grid", "period"), [
    (TimeGrid(10, "periods", 50), 2.244706444), (TimeGrid(3.3, "s", 7), 2.0), (TimeGrid(1, "periods", 1), 1.0),
    (TimeGrid(2.5, "s", 50, output_interval=0.04), 9.9), (TimeGrid(1e3, "periods", 97), 0.123),
])
def test_grid_points_counts_the_times_without_building_them(grid: TimeGrid, period: float) -> None:
    assert grid.point_count(period) == len(grid.times(period))


def test_a_run_is_refused_past_half_the_memory() -> None:
    memory = 8 * 10 ** 9
    fits = int(memory * 0.5 / BYTES_PER_POINT)
    assert check_run(fits, memory=memory) == pytest.approx(fits * 3e-6)
    with pytest.raises(UsageError, match=r"this run would record 15\.6 million output points, about 4 GB of "
                                         r"memory, over the limit of half the 8 GB available: lower `stop_time` or "
                                         r"`points_per_period` \(at most about 15\.6 million points fit\)$") as refused:
        check_run(fits + 1, memory=memory)
    assert refused.value.field == "stop_time"   # the library names fields; the command line, flags


def test_a_sweep_is_counted_without_building_it_and_refused_past_the_memory() -> None:
    sweep = SweepGrid(tuple(1.0 + k * 178 / 99_999 for k in range(100_000)),
                      tolerances=tuple(10 ** (-4 - 6 * k / 999) for k in range(1000)))
    assert len(sweep) == 100_000_000 == math.prod((100_000, 1000, 1, 1, 1, 1))
    with pytest.raises(UsageError, match=r"this sweep has 100 million runs, about 410 GB of memory"):
        check_sweep(len(sweep), 501, 2, memory=16 * 10 ** 9)
    small = SweepGrid((10.0, 10.0, 20.0), solvers=("rkn", "rkn"))
    assert len(small) == len(small.points()) == 2


@pytest.mark.parametrize("solver", ["rkn", "cvode"])
def test_a_planned_run_initializes_the_fmu_once(fmu_path: Path, monkeypatch: pytest.MonkeyPatch, solver: str) -> None:
    """The size check reads the period of the run's own initialization (Model Exchange: fmpy's
    simulate_fmu then initializes the instance it is handed once more, itself)."""
    calls: list[Any] = []
    initialize = FmuRunner._initialize
    monkeypatch.setattr(FmuRunner, "_initialize", lambda runner, *args: calls.append(args) or initialize(runner, *args))
    method = Method(solver)
    with FmuRunner(fmu_path) as runner:
        trajectory = planned_run(runner, InitialValueProblem.from_degrees(80.0), method, TimeGrid(1, "periods", 10))
        assert len(calls) == 1 and trajectory.result.size == 11
        with pytest.raises(UsageError, match="output points"):
            planned_run(runner, InitialValueProblem.from_degrees(80.0), method, TimeGrid(1e12, "periods", 1000))
        assert len(calls) == 2   # refused after its initialization, before any point
