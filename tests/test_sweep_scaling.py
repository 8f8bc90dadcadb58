"""What a 2-core machine can show of the sweep's scaling: the tasks it sends,
the scheduler's own cost per task, 2 workers faster than 1 on runs of about 1 ms, and what
``bench sweep`` prints. The many-core figures come from ``scripts/measure-many-cores.sh``."""

from __future__ import annotations

import re
import statistics
from collections.abc import Sequence
from pathlib import Path

import pytest

from pendulum_fmu.bench.sweep import bench_points, cores, measure, task_cost
from pendulum_fmu.cli.main import main
from pendulum_fmu.sweep.cluster import TASK_SECONDS, dask_client, execute, task_size
from pendulum_fmu.sweep.grid import SweepPoint

pytestmark = pytest.mark.slow


def test_a_sweep_sends_tasks_of_a_tenth_of_a_second(fmu_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The tasks really submitted: sized from the run the workers timed, every run once."""
    import pendulum_fmu.sweep.cluster as cluster

    sizes: list[list[int]] = []
    measured: list[float] = []
    dealt = cluster.batches

    def recording(points: Sequence[SweepPoint], threads: int, batch_size: int | None = None,
                  run_seconds: float | None = None) -> list[list[SweepPoint]]:
        assert run_seconds is not None
        measured.append(run_seconds)
        parts = dealt(points, threads, batch_size, run_seconds)
        sizes.append([len(part) for part in parts])
        return parts

    monkeypatch.setattr(cluster, "batches", recording)
    points = bench_points(2000, 1.0)
    rows: list[dict[str, object]] = []
    with dask_client(None, 2) as client:
        execute(client, fmu_path, points, rows.extend, progress=False)
    assert len(rows) == 2000 and len({row["amplitude_deg"] for row in rows}) == 2000
    (cost,), (tasks,) = measured, sizes
    assert 1e-5 < cost < 0.05, cost                         # one run of one period: well under 50 ms
    size = max(tasks)
    assert sum(tasks) == 2000 and max(tasks) - min(tasks) <= 1
    assert size == task_size(2000, 2, cost)
    assert size == 500 or TASK_SECONDS <= size * cost < TASK_SECONDS + cost   # 0.1 s of work, or 2 per worker
    assert len(tasks) >= 4                                  # at least two per worker


def test_the_scheduler_costs_about_a_millisecond_a_task(fmu_path: Path) -> None:
    """Empty tasks: what the sweep pays per task besides its runs, the reason tasks hold 0.1 s."""
    with dask_client(None, 2) as client:
        per_task = task_cost(client, 300)
    assert 1e-5 < per_task < 0.02, per_task
    assert per_task < TASK_SECONDS / 5


def test_two_workers_are_faster_than_one_on_1_ms_runs(fmu_path: Path) -> None:
    if cores()[2] < 2:
        pytest.skip("needs 2 usable cores: run it on a machine (or taskset) with two")
    points = bench_points(1000, 10.0)     # ten periods of dopri5: about 1 ms a run
    one = measure(fmu_path, points, 1, 3)
    two = measure(fmu_path, points, 2, 3)
    per_run = statistics.median(one.seconds) / len(points)
    assert 2e-4 < per_run < 1e-2, per_run
    assert two.rate > 1.1 * one.rate, (one.rate, two.rate)


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
