"""A sweep on a real Dask cluster: ``dask scheduler`` and ``dask worker`` started as processes of
their own (the console scripts beside this interpreter) on 127.0.0.1, a worker killed in the
middle of the sweep, and a scheduler that is not there."""

from __future__ import annotations

import csv
import json
import os
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from processes import stop

RUNS = 400
SWEEP = ["sweep", "-a", f"1:179:{RUNS}", "-p", "20", "-q", "--no-plots"]


def installed(name: str) -> Path:
    """A console script beside this interpreter, or a skip naming the install command."""
    path = Path(sys.executable).parent / name
    if not path.is_file():
        pytest.skip(f"the {name} console script is not installed: pip install -e '.[sweep]'")
    return path


def free_port() -> int:
    """A TCP port nothing listens on at this moment."""
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


@pytest.fixture
def cluster(tmp_path: Path) -> Iterator[tuple[str, list[subprocess.Popen[bytes]]]]:
    """A scheduler on a free port and two workers without nannies (a killed worker stays dead)."""
    dask = installed("dask")
    state = tmp_path / "scheduler.json"
    scheduler = subprocess.Popen([str(dask), "scheduler", "--host", "127.0.0.1", "--port", str(free_port()),
                                  "--no-dashboard", "--scheduler-file", str(state)],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    workers: list[subprocess.Popen[bytes]] = []
    try:
        deadline = time.monotonic() + 60
        while not state.exists() and time.monotonic() < deadline:
            time.sleep(0.1)
        assert state.exists(), "the scheduler did not start within 60 s"
        address = json.loads(state.read_text())["address"]
        for name in ("w1", "w2"):
            workers.append(subprocess.Popen(
                [str(dask), "worker", address, "--nthreads", "1", "--no-nanny", "--name", name, "--no-dashboard",
                 "--local-directory", str(tmp_path / name)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        from distributed import Client

        with Client(address, timeout="30s") as client:
            client.wait_for_workers(2, timeout=60)
        yield address, workers
    finally:
        stop(workers)
        stop([scheduler])


def journal_lines(path: Path) -> int:
    """Complete rows in the journal so far."""
    return path.read_text().count("\n") - 1 if path.is_file() else 0


def test_a_worker_killed_in_the_middle_loses_and_doubles_nothing(
        cluster: tuple[str, list[subprocess.Popen[bytes]]], fmu_path: Path, tmp_path: Path) -> None:
    address, workers = cluster
    script = installed("pendulum-fmu")
    out = tmp_path / "sweep"
    sweep = subprocess.Popen([str(script), *SWEEP, "--scheduler", address, "-o", str(out), "--fmu", str(fmu_path)],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    journal = out / "runs.journal.csv"
    deadline = time.monotonic() + 120
    while journal_lines(journal) < 2 and time.monotonic() < deadline and sweep.poll() is None:
        time.sleep(0.05)
    written = journal_lines(journal)
    assert 0 < written < RUNS, f"the sweep was not under way when the worker was to be killed ({written} rows)"
    os.kill(workers[0].pid, signal.SIGKILL)
    stdout, stderr = sweep.communicate(timeout=300)
    assert sweep.returncode == 0, stderr
    with (out / "sweep.csv").open(newline="") as file:
        amplitudes = [float(row["amplitude_deg"]) for row in csv.DictReader(file)]
    assert len(amplitudes) == RUNS and len(set(amplitudes)) == RUNS, "a run is missing or doubled"
    assert amplitudes == sorted(amplitudes) and amplitudes[0] == 1.0 and amplitudes[-1] == 179.0
    assert f"computed {RUNS} runs" in stdout
    assert workers[0].wait(timeout=10) == -signal.SIGKILL and workers[1].poll() is None


def test_a_scheduler_that_is_not_there_is_one_line_and_no_folder(fmu_path: Path, tmp_path: Path) -> None:
    script = installed("pendulum-fmu")
    out = tmp_path / "never"
    address = f"tcp://127.0.0.1:{free_port()}"
    done = subprocess.run([str(script), *SWEEP, "--scheduler", address, "-o", str(out), "--fmu", str(fmu_path)],
                          capture_output=True, text=True, timeout=60)   # a hang: the timeout
    assert done.returncode == 2
    assert done.stderr.splitlines() == [f"pendulum-fmu sweep: error: argument --scheduler: cannot reach a Dask "
                                        f"scheduler at {address}: Connection refused (see 'pendulum-fmu sweep --help')"]
    assert not out.exists()
