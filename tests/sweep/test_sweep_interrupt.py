"""Ctrl-C during a sweep: one line, the cluster gone within seconds, the journal and sweep.csv of what finished."""

from __future__ import annotations

import csv
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest


@pytest.mark.slow
@pytest.mark.parametrize("inherited", [signal.SIG_DFL, signal.SIG_IGN], ids=["SIGINT default", "SIGINT ignored"])
def test_ctrl_c_prints_one_line_and_leaves_the_finished_runs(fmu_path: Path, tmp_path: Path,
                                                             inherited: signal.Handlers) -> None:
    """Whatever SIGINT disposition the command inherits: set here explicitly, not taken from
    how pytest was started (``bash scripts/test.sh &`` from a script hands SIGINT on ignored,
    and the command must still stop on it: it sets its own disposition)."""
    out = tmp_path / "sweep"
    command = [sys.executable, "-m", "pendulum_fmu", "sweep", "-a", "1:179:3000", "-p", "20", "-j", "2", "-q",
               "-o", str(out), "--fmu", str(fmu_path)]
    # A terminal's Ctrl-C goes to the whole process group: the command's own session stands for it.
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               start_new_session=True, cwd=tmp_path,
                               preexec_fn=lambda: signal.signal(signal.SIGINT, inherited))
    journal = out / "runs.journal.csv"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and (not journal.is_file() or journal.read_text().count("\n") < 3):
        time.sleep(0.2)
    assert journal.is_file(), "no run finished within 120 s"
    os.killpg(process.pid, signal.SIGINT)
    _, stderr = process.communicate(timeout=30)   # a sweep that ignored the signal: the timeout
    sent = time.monotonic()
    assert process.returncode == 130
    lines = [line for line in stderr.splitlines() if line.strip()]
    assert lines == ["pendulum-fmu sweep: interrupted; run the same command again to resume"], stderr
    with journal.open() as file:
        journal_rows = list(csv.DictReader(file))
    with (out / "sweep.csv").open() as file:
        table_rows = list(csv.DictReader(file))
    assert 0 < len(table_rows) == len(journal_rows) < 3000
    assert {float(row["amplitude_deg"]) for row in table_rows} == {float(row["amplitude_deg"]) for row in journal_rows}
    survivors = "?"
    while time.monotonic() - sent < 30 and survivors:
        survivors = subprocess.run(["pgrep", "-a", "-s", str(process.pid)], capture_output=True, text=True).stdout
        time.sleep(0.2)
    assert survivors == "", f"processes outlived the sweep by 30 s: {survivors}"
