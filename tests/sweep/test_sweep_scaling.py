"""The sweep's tasks and what ``bench sweep`` prints: the tasks it sends for a given run cost,
the dealing at any cost, the scheduler's cost per task measured, and the benchmark's table.
No test here asserts a timing (tests/package/test_no_timed_tests.py): the speed-up of 2 workers over 1,
the cost per task and the many-core figures are what ``pendulum-fmu bench sweep`` and
``scripts/measure-many-cores.sh`` print."""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from pathlib import Path

import pytest

from pendulum_fmu.bench.sweep import bench_points, cores, task_cost
from pendulum_fmu.cli.main import main
from pendulum_fmu.sweep.cluster import TASK_SECONDS, TASKS_PER_THREAD, batches, dask_client, execute, task_size
from pendulum_fmu.sweep.grid import SweepPoint

COST = 0.004
"""The cost of one run the sweep is handed in the test of its tasks: a fixed figure, so that the
tasks' sizes are known in advance (a run timed on a loaded machine sized them differently from
one run to the next, and a test that compared them failed while the sizing was right)."""

pytestmark = pytest.mark.slow


def test_a_sweep_sends_tasks_of_a_tenth_of_a_second(fmu_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The tasks really submitted: sized from the run cost the workers' timing returns (here
    fixed at COST, after the real timing ran and returned a positive figure), every run once."""
    import pendulum_fmu.sweep.cluster as cluster

    timed: list[float] = []
    measured_run_seconds = cluster.measured_run_seconds

    def fixed(client: object, data: object, points: Sequence[SweepPoint]) -> float:
        timed.append(measured_run_seconds(client, data, points))  # the real timing, on the workers
        return COST

    sizes: list[list[int]] = []
    dealt = cluster.batches

    def recording(points: Sequence[SweepPoint], threads: int, batch_size: int | None = None,
                  cost: float | None = None) -> list[list[SweepPoint]]:
        assert cost == COST   # the figure the timing returned, handed on
        parts = dealt(points, threads, batch_size, cost)
        sizes.append([len(part) for part in parts])
        return parts

    monkeypatch.setattr(cluster, "measured_run_seconds", fixed)
    monkeypatch.setattr(cluster, "batches", recording)
    points = bench_points(2000, 1.0)
    rows: list[dict[str, object]] = []
    with dask_client(None, 2) as client:
        execute(client, fmu_path, points, rows.extend, progress=False)
    assert len(rows) == 2000 and len({row["amplitude_deg"] for row in rows}) == 2000
    (seconds,), (tasks,) = timed, sizes
    assert seconds > 0                                      # the workers timed a run
    # 0.1 s of work a task at 4 ms a run: 25 runs, 80 tasks, at least two per worker
    assert task_size(2000, 2, COST) == 25
    assert tasks == [25] * 80


@pytest.mark.parametrize("cost", [1e-7, 1e-4, 0.004, 0.03, 0.2, 5.0])
@pytest.mark.parametrize(("runs", "threads"), [(1, 1), (7, 2), (2000, 2), (2001, 16), (100_000, 64)])
def test_tasks_hold_a_tenth_of_a_second_or_two_per_thread(cost: float, runs: int, threads: int) -> None:
    """The dealing for a given run cost (no clock): every run once, sizes within one of each
    other, about TASK_SECONDS of work a task, yet at least two tasks a thread when the runs allow."""
    points = bench_points(runs, 1.0)
    parts = batches(points, threads, None, cost)
    sizes = [len(part) for part in parts]
    assert sorted(p.amplitude_deg for part in parts for p in part) == sorted(p.amplitude_deg for p in points)
    assert max(sizes) - min(sizes) <= 1
    size = task_size(runs, threads, cost)
    assert max(sizes) <= size
    by_balance = math.ceil(runs / (TASKS_PER_THREAD * threads))
    assert size == max(1, min(math.ceil(TASK_SECONDS / cost), by_balance))
    if size > 1:
        assert (size - 1) * cost < TASK_SECONDS or size == by_balance
    if runs >= TASKS_PER_THREAD * threads:
        assert len(parts) >= TASKS_PER_THREAD * threads or size * cost >= TASK_SECONDS


def test_the_scheduler_cost_is_measured(fmu_path: Path) -> None:
    """Empty tasks: what the sweep pays per task besides its runs (``bench sweep`` prints it;
    its size, about a millisecond, is the reason tasks hold 0.1 s)."""
    with dask_client(None, 2) as client:
        per_task = task_cost(client, 300)
    assert per_task > 0 and math.isfinite(per_task)


def test_bench_sweep_prints_cores_efficiency_and_cost_per_task(fmu_path: Path,
                                                              capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["bench", "sweep", "--runs", "60", "--periods", "1", "--workers", "1", "2", "--repeat", "1",
                 "--loop", "c", "--fmu", str(fmu_path)]) == 0
    out = capsys.readouterr().out
    physical, logical, usable = cores()
    assert f"cores: {physical or '?'} physical, {logical or '?'} logical, {usable} usable by this process" in out
    header = next(line for line in out.splitlines() if "efficiency" in line)
    assert header.split() == ["loop", "workers", "runs", "seconds", "runs/s", "per", "worker", "speed-up",
                              "efficiency", "ms/task", "startup", "(s)"]
    rows = {int(line.split()[1]): line.split() for line in out.splitlines() if re.match(r"^\s+c\s+\d", line)}
    assert rows[1][6] == "1.00x" and rows[1][7] == "1.00" and float(rows[1][8]) > 0
    speedup = float(rows[2][6].rstrip("x"))
    assert float(rows[2][7]) == pytest.approx(speedup / 2, abs=0.01) and float(rows[2][8]) > 0
    for workers in (1, 2):
        match = re.search(rf"^bench_sweep loop=c workers={workers} runs=60 .* task_ms=([0-9.]+) ", out, re.MULTILINE)
        assert match is not None and float(match.group(1)) > 0, out
