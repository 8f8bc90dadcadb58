"""``sweep`` on Dask: the table's numbers, resuming, and a real scheduler with two workers."""

from __future__ import annotations

import json
import math
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pyarrow as pa
import pytest
from PIL import Image
from scipy.special import ellipk

from pendulum_fmu.cli.main import main
from pendulum_fmu.sweep.grid import COLUMNS, TIMING_COLUMNS
from pendulum_fmu.sweep.run import JOURNAL, JOURNAL_FMU, read_sweep_table
from processes import stop

GRID = ["--amplitudes", "30,75:90:4", "--lengths", "1,2", "--solvers", "dopri5,cvode", "--periods", "3",
        "--points-per-period", "20"]
RUNS = 5 * 2 * 2


def reproducible(table: pa.Table) -> pa.Table:
    """The table without its timing columns (they differ between two runs of one sweep)."""
    return table.drop_columns(list(TIMING_COLUMNS))


@pytest.fixture(scope="module")
def local_sweep(fmu_path: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The small sweep on the default local cluster (2 worker processes)."""
    out = tmp_path_factory.mktemp("sweep-local")
    assert main(["sweep", *GRID, "--workers", "2", "--out", str(out), "--quiet", "--fmu", str(fmu_path)]) == 0
    return out


def test_table_has_every_run_in_grid_order(local_sweep: Path) -> None:
    rows = read_sweep_table(local_sweep / "sweep.csv").to_pylist()
    assert len(rows) == RUNS
    assert list(rows[0]) == list(COLUMNS)
    keys = [(r["solver"], r["length_m"], r["amplitude_deg"]) for r in rows]
    assert keys == [(s, L, a) for s in ("dopri5", "cvode") for L in (1.0, 2.0) for a in (30.0, 75.0, 80.0, 85.0, 90.0)]
    assert {r["status"] for r in rows} == {"ok"}


def test_period_column_is_4K_over_w0(local_sweep: Path) -> None:
    for row in read_sweep_table(local_sweep / "sweep.csv").to_pylist():
        w0 = math.sqrt(row["gravity_m_s2"] / row["length_m"])
        m = math.sin(math.radians(row["amplitude_deg"]) / 2.0) ** 2
        assert row["period_s"] == pytest.approx(4.0 * float(ellipk(m)) / w0, rel=1e-13)
        assert row["period_ratio"] == pytest.approx(2.0 * float(ellipk(m)) / math.pi, rel=1e-13)
        assert row["measured_period_s"] == pytest.approx(row["period_s"], rel=1e-4)
        assert row["stop_time_s"] == pytest.approx(3 * row["period_s"], rel=1e-13)


def test_errors_and_cost_per_interface(local_sweep: Path) -> None:
    for row in read_sweep_table(local_sweep / "sweep.csv").to_pylist():
        assert 0 < row["max_error_rad"] < (1e-6 if row["solver"] == "dopri5" else 1e-4)
        assert row["final_error_rad"] <= row["max_error_rad"]
        assert row["wall_time_s"] > 0
        if row["interface"] == "CS":
            assert row["steps"] > 0 and row["rhs_evaluations"] >= 6 * row["steps"]
        else:
            assert row["interface"] == "ME" and row["solver"] == "cvode"
            assert row["steps"] is None and row["rhs_evaluations"] is None


def test_summary_plots_are_written(local_sweep: Path) -> None:
    for name in ("sweep_period.png", "sweep_error.png", "sweep_cost.png"):
        with Image.open(local_sweep / name) as image:
            assert image.format == "PNG", name


def test_rerun_skips_everything_written(local_sweep: Path, fmu_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    before = read_sweep_table(local_sweep / "sweep.csv")
    assert main(["sweep", *GRID, "--out", str(local_sweep), "--quiet", "--no-plots", "--fmu", str(fmu_path)]) == 0
    assert f"all {RUNS} runs already done" in capsys.readouterr().out
    assert read_sweep_table(local_sweep / "sweep.csv").equals(before)


def test_interrupted_sweep_resumes_where_it_stopped(local_sweep: Path, fmu_path: Path, tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    lines = (local_sweep / JOURNAL).read_text().splitlines(keepends=True)
    # as left by an interruption: header, 7 complete rows, half of the 8th, no table yet
    (tmp_path / JOURNAL).write_text("".join(lines[:8]) + lines[8][:40])
    (tmp_path / JOURNAL_FMU).write_text((local_sweep / JOURNAL_FMU).read_text())
    assert main(["sweep", *GRID, "--workers", "1", "--out", str(tmp_path), "--quiet", "--no-plots",
                 "--fmu", str(fmu_path)]) == 0
    assert f"computed {RUNS - 7} runs" in capsys.readouterr().out
    resumed = read_sweep_table(tmp_path / "sweep.csv")
    original = read_sweep_table(local_sweep / "sweep.csv")
    assert reproducible(resumed).equals(reproducible(original))
    # the 7 runs already written were taken from the journal, not run again
    kept = {tuple(r[c] for c in COLUMNS[:8]): r["wall_time_s"] for r in original.to_pylist()}
    journal_rows = read_sweep_table(tmp_path / JOURNAL).to_pylist()
    assert len(journal_rows) == RUNS
    same = sum(kept[tuple(r[c] for c in COLUMNS[:8])] == r["wall_time_s"] for r in resumed.to_pylist())
    assert same >= 7


def test_a_journal_of_another_fmu_is_not_reused(local_sweep: Path, fmu_path: Path, tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / JOURNAL).write_text((local_sweep / JOURNAL).read_text())
    (tmp_path / JOURNAL_FMU).write_text("0" * 64 + "\n")
    assert main(["sweep", *GRID, "--amplitudes", "30", "--workers", "1", "--out", str(tmp_path), "--no-plots",
                 "--fmu", str(fmu_path)]) == 0
    captured = capsys.readouterr()
    assert "was written by another FMU: starting afresh" in captured.err
    assert "computed 4 runs" in captured.out and "on 1 worker process (" in captured.out  # as -j's help says
    assert len(read_sweep_table(tmp_path / JOURNAL)) == 4


@pytest.fixture(scope="module")
def dask_scheduler(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """A real ``dask scheduler`` and two ``dask worker`` processes on localhost."""
    folder = tmp_path_factory.mktemp("dask")
    scheduler_file = folder / "scheduler.json"
    common = ["--no-dashboard"]
    processes = [subprocess.Popen([sys.executable, "-m", "dask", "scheduler", "--host", "127.0.0.1", "--port", "0",
                                   "--scheduler-file", str(scheduler_file), *common],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)]
    try:
        deadline = time.monotonic() + 60
        while not scheduler_file.exists() and time.monotonic() < deadline:
            time.sleep(0.1)
        for name in ("w1", "w2"):
            processes.append(subprocess.Popen(
                [sys.executable, "-m", "dask", "worker", "--scheduler-file", str(scheduler_file), "--nthreads", "1",
                 "--name", name, "--local-directory", str(folder / name), *common],
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        address = json.loads(scheduler_file.read_text())["address"]
        from distributed import Client

        with Client(address, timeout="30s") as client:
            client.wait_for_workers(2, timeout=60)
        yield address
    finally:
        stop(processes[1:])  # the workers, then the scheduler
        stop(processes[:1])


def test_sweep_through_a_running_scheduler_gives_the_local_table(local_sweep: Path, dask_scheduler: str,
                                                                 fmu_path: Path, tmp_path: Path,
                                                                 capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["sweep", *GRID, "--scheduler", dask_scheduler, "--format", "parquet", "--out", str(tmp_path),
                 "--quiet", "--no-plots", "--fmu", str(fmu_path)]) == 0
    assert f"computed {RUNS} runs" in capsys.readouterr().out
    remote = read_sweep_table(tmp_path / "sweep.parquet")
    local = read_sweep_table(local_sweep / "sweep.csv")
    assert reproducible(remote).equals(reproducible(local))
    # each worker extracted and loaded the FMU once, however many tasks it ran
    from distributed import Client

    from pendulum_fmu.sweep.worker import load_count

    with Client(dask_scheduler) as client:
        assert sorted(client.run(load_count).values()) == [1, 1]


def test_wall_time_is_the_only_column_that_differs(local_sweep: Path) -> None:
    table = read_sweep_table(local_sweep / "sweep.csv")
    assert np.all(np.asarray(table.column("wall_time_s")) > 0)
    assert set(COLUMNS) - set(reproducible(table).column_names) == set(TIMING_COLUMNS)
