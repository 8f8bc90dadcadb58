"""The sweep's grid, batches and journal, without Dask."""

from __future__ import annotations

import math
from pathlib import Path

from pendulum_fmu.sizing import SECONDS_PER_POINT, SECONDS_PER_SWEEP_RUN, sweep_run_seconds
from pendulum_fmu.sweep.cluster import TASK_SECONDS, TASKS_PER_THREAD, batches, estimated_run_seconds, task_size
from pendulum_fmu.sweep.grid import COLUMNS, SweepGrid, SweepPoint
from pendulum_fmu.sweep.journal import Journal, read_journal


def _row(point: SweepPoint, error: float) -> dict[str, object]:
    row: dict[str, object] = dict.fromkeys(COLUMNS)
    row.update(amplitude_deg=point.amplitude_deg, omega0_rad_s=point.omega0, length_m=point.length,
               gravity_m_s2=point.gravity, solver=point.solver, tolerance=point.tolerance, periods=point.periods,
               points_per_period=point.points_per_period, interface="CS", max_error_rad=error, steps=10,
               status="ok")
    return row


def test_grid_order_is_solver_outermost_amplitude_innermost_without_duplicates() -> None:
    grid = SweepGrid((75.0, 80.0, 75.0), lengths=(1.0, 2.0), solvers=("rkn", "dopri5"))
    points = grid.points()
    assert len(grid) == len(points) == 8
    assert [(p.solver, p.length, p.amplitude_deg) for p in points[:3]] == [("rkn", 1.0, 75.0), ("rkn", 1.0, 80.0),
                                                                          ("rkn", 2.0, 75.0)]


def test_batches_cover_every_point_once_with_equal_shares_of_the_range() -> None:
    points = SweepGrid(tuple(float(a) for a in range(1, 1001))).points()
    parts = batches(points, threads=2, run_seconds=0.001)   # 1-ms runs: 100 a task (0.1 s), 10 tasks
    assert sorted(p.key for part in parts for p in part) == sorted(p.key for p in points)
    assert len(parts) == 10 and {len(part) for part in parts} == {100}
    assert all(part[0].amplitude_deg <= 10 and part[-1].amplitude_deg >= 990 for part in parts)
    assert max(len(part) for part in batches(points, threads=1, batch_size=40)) == 40
    assert len(batches(points[:5], threads=2, run_seconds=0.001)) == 3 and batches([], threads=2) == []


def test_tasks_hold_a_tenth_of_a_second_of_work_yet_two_per_thread() -> None:
    assert TASK_SECONDS == 0.1 and TASKS_PER_THREAD == 2
    assert task_size(100_000, threads=16, run_seconds=0.001) == 100      # by cost: 0.1 s a task
    assert task_size(100_000, threads=16, run_seconds=0.0066) == 16      # 6.6-ms runs: 16 a task
    assert task_size(1600, threads=16, run_seconds=0.001) == 50          # by balance: 32 tasks of 50
    assert task_size(1600, threads=2, run_seconds=0.001) == 100
    assert task_size(10, threads=16, run_seconds=0.001) == 1             # fewer runs than threads
    assert task_size(1000, threads=2, run_seconds=5.0) == 1              # a long run is a task of its own
    assert task_size(1000, threads=2, run_seconds=0.0) == 250            # a cost of zero: by balance alone
    # without a measured cost the sizing estimate is used: 10 periods of 50 points, about 4.5 ms
    points = SweepGrid(tuple(float(a) for a in range(1, 1001))).points()
    cost = estimated_run_seconds(points[0])
    assert cost == sweep_run_seconds(501) == SECONDS_PER_SWEEP_RUN + 501 * SECONDS_PER_POINT
    assert len(batches(points, threads=2)) == math.ceil(1000 / math.ceil(TASK_SECONDS / cost))


def test_journal_round_trip_is_exact_and_ignores_a_cut_row(tmp_path: Path) -> None:
    points = SweepGrid((1.0 / 3.0, 75.0, 80.0)).points()
    journal = Journal(tmp_path / "j.csv")
    journal.append(_row(p, 1e-9 * (i + 1)) for i, p in enumerate(points))
    journal.close()
    rows = read_journal(tmp_path / "j.csv")
    assert set(rows) == {p.key for p in points}
    assert rows[points[0].key]["max_error_rad"] == 1e-9 and rows[points[0].key]["steps"] == 10
    assert rows[points[0].key]["rhs_evaluations"] is None
    text = (tmp_path / "j.csv").read_text()
    (tmp_path / "j.csv").write_text(text[: text.rindex("\n", 0, len(text) - 1) + 15])  # last row cut short
    assert set(read_journal(tmp_path / "j.csv")) == {p.key for p in points[:2]}
    # appending after a cut row rewrites the good rows first
    journal = Journal(tmp_path / "j.csv", keep=read_journal(tmp_path / "j.csv").values())
    journal.append([_row(points[2], 3e-9)])
    journal.close()
    assert set(read_journal(tmp_path / "j.csv")) == {p.key for p in points}


def test_a_journal_of_other_columns_reads_as_empty(tmp_path: Path) -> None:
    (tmp_path / "j.csv").write_text("a,b\n1,2\n")
    assert read_journal(tmp_path / "j.csv") == {}
    assert read_journal(tmp_path / "missing.csv") == {}
