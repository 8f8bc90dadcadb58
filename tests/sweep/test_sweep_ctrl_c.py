"""Ctrl-C at random moments through the installed ``pendulum-fmu`` console script.

A terminal's Ctrl-C reaches the whole process group: the command, its Dask nanny and worker
processes and multiprocessing's resource tracker. The console script's main module is
imported again by every spawned worker (``python -m`` is not), which is where the command's
own SIGINT handler once leaked into the workers. Each moment asserts: exit 130 within 5 s,
one line on stderr, no traceback from any process, no ``.tmp`` file, and a table that holds
exactly the runs of the journal.
"""

from __future__ import annotations

import csv
import os
import random
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

MOMENTS = 20
"""SIGINTs sent: one at a random moment in each of this many equal slices of the time from 0.2 s
to the end of an uninterrupted sweep, so that the start, every stage and the end are hit in
every run (fifty plain random moments took three minutes and could leave a stage out)."""
SWEEP = ["sweep", "-a", "1:179:400", "-p", "2", "-j", "2", "-q", "--no-plots"]


def console_script() -> Path:
    """The installed ``pendulum-fmu`` beside this interpreter, or a skip naming the install command."""
    path = Path(sys.executable).parent / "pendulum-fmu"
    if not path.is_file():
        pytest.skip("the pendulum-fmu console script is not installed: pip install -e .")
    return path


def start(command: list[str], cwd: Path) -> subprocess.Popen[str]:
    """The command in a session of its own (a process group, as a terminal's job)."""
    return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True, cwd=cwd)


def rows(path: Path) -> list[dict[str, str]]:
    """The rows of a CSV table (none if the file is not there)."""
    if not path.is_file():
        return []
    with path.open(newline="") as file:
        return list(csv.DictReader(file))


def journal_rows(path: Path) -> list[dict[str, str]]:
    """The complete rows of the journal (a line cut short at the end is not one)."""
    if not path.is_file():
        return []
    text = path.read_text()
    complete = text[:text.rfind("\n") + 1]
    return list(csv.DictReader(complete.splitlines()))


def catches_sigint(pid: int) -> bool:
    """Whether the process has a SIGINT handler yet (Linux: the SigCgt mask of /proc/PID/status)."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except OSError:
        return True
    caught = next((line.split()[1] for line in status.splitlines() if line.startswith("SigCgt:")), None)
    return caught is None or bool(int(caught, 16) & (1 << (signal.SIGINT - 1)))


def wait_for_the_interpreter(process: subprocess.Popen[str], limit: float = 10.0) -> None:
    """Wait until the process's interpreter has set its SIGINT handler (at most ``limit`` s).

    Before that SIGINT kills any Python program, silently, with exit -2: a gap of the
    interpreter's own start, a few hundredths of a second, which a loaded machine stretched
    to seconds once (docs/for-people.md). The moments here are those of the command.
    """
    deadline = time.monotonic() + limit
    while process.poll() is None and not catches_sigint(process.pid) and time.monotonic() < deadline:
        time.sleep(0.005)


def interrupted_at(command: list[str], cwd: Path, moment: float) -> tuple[int | None, float, str]:
    """Send SIGINT to the command's group ``moment`` s after its start.

    Returns
    -------
    tuple
        The exit code (``None`` if it ended before the moment), the seconds from the signal
        to the exit, and stderr.
    """
    process = start(command, cwd)
    try:
        process.wait(timeout=moment)
        return None, 0.0, process.communicate()[1]
    except subprocess.TimeoutExpired:
        pass
    wait_for_the_interpreter(process)
    if process.poll() is not None:
        return None, 0.0, process.communicate()[1]
    os.killpg(process.pid, signal.SIGINT)
    sent = time.monotonic()
    try:
        _, stderr = process.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        pytest.fail(f"a sweep interrupted {moment:.2f} s after its start still ran 30 s later")
    return process.returncode, time.monotonic() - sent, stderr


def interrupted_inside(command: list[str], cwd: Path, moment: float,
                       out: Path | None = None) -> tuple[int, float, str, float]:
    """:func:`interrupted_at`, at 0.6 times the moment again while the command ends before it.

    ``out``, the command's output folder, is removed before each try (a sweep would resume).

    Returns
    -------
    tuple
        The exit code, the seconds from the signal to the exit, stderr, and the moment used.
    """
    for _ in range(6):
        if out is not None:
            shutil.rmtree(out, ignore_errors=True)
        code, seconds, stderr = interrupted_at(command, cwd, moment)
        assert "Traceback" not in stderr, f"uninterrupted:\n{stderr}"
        if code is not None:
            return code, seconds, stderr, moment
        moment = max(0.2, 0.6 * moment)
    pytest.fail(f"the command ended within {moment:.2f} s six times: nothing to interrupt")


def test_ctrl_c_in_every_slice_of_a_sweep_through_the_console_script(fmu_path: Path, tmp_path: Path) -> None:
    """Exit 130 within 5 s, one line, no traceback, no partial file, the finished runs kept."""
    script = console_script()
    fmu = tmp_path / "Pendulum.fmu"
    shutil.copyfile(fmu_path, fmu)   # the checkout's build/ may be rebuilt meanwhile
    whole = tmp_path / "whole"
    began = time.monotonic()
    done = subprocess.run([str(script), *SWEEP, "-o", str(whole), "--fmu", str(fmu)], capture_output=True,
                          text=True, cwd=tmp_path, timeout=300)
    length = time.monotonic() - began
    assert done.returncode == 0, done.stderr
    assert done.stderr == "", f"a sweep that ends normally logged its shutdown:\n{done.stderr}"
    generator = random.Random(27)
    width = (length - 0.2) / MOMENTS
    moments = [0.2 + width * (k + generator.random()) for k in range(MOMENTS)]
    for index, moment in enumerate(moments):
        out = tmp_path / f"z{index}"
        code, seconds, stderr, moment = interrupted_inside(
            [str(script), *SWEEP, "-o", str(out), "--fmu", str(fmu)], tmp_path, moment, out)
        where = f"SIGINT at {moment:.2f} s of {length:.2f} s"
        assert "Traceback" not in stderr, f"{where}:\n{stderr}"
        lines = [line for line in stderr.splitlines() if line.strip()]
        assert code == 130, f"{where}: exit {code}\n{stderr}"
        assert len(lines) == 1 and lines[0].startswith("pendulum-fmu") and "interrupted" in lines[0], \
            f"{where}:\n{stderr}"
        assert not list(tmp_path.glob(f"z{index}/**/*.tmp")), f"{where}: a partial file is left"
        table, journal = rows(out / "sweep.csv"), journal_rows(out / "runs.journal.csv")
        if table:   # written on the interrupt: exactly the runs the journal holds
            assert sorted(float(row["amplitude_deg"]) for row in table) == \
                sorted(float(row["amplitude_deg"]) for row in journal), where


@pytest.mark.parametrize("moment", [0.3, 1.0, 1.8, 2.6, 3.5, 5.0])
def test_ctrl_c_in_bench_sweep_through_the_console_script(fmu_path: Path, tmp_path: Path, moment: float) -> None:
    """``bench sweep`` starts and closes a cluster per worker count: any moment, one line and 130."""
    script = console_script()
    command = [str(script), "bench", "sweep", "--runs", "300", "--periods", "2", "--workers", "1", "2",
               "--repeat", "1", "--loop", "c", "--fmu", str(fmu_path)]
    code, seconds, stderr, moment = interrupted_inside(command, tmp_path, moment)
    assert "Traceback" not in stderr, stderr
    lines = [line for line in stderr.splitlines() if line.strip()]
    assert code == 130, (code, seconds, stderr)
    assert len(lines) == 1 and lines[0].startswith("pendulum-fmu") and lines[0].endswith("interrupted"), stderr
