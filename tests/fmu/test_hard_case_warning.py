"""A hard case never passes silently, end to end: the FMU's fmi2Warning ("hard case: ...") when
its numerical solution goes over the top while the exact one does not reaches the user of the
``pendulum-fmu`` commands as one line, and the sweep's table as its ``fmu_warning`` column.

The case: released at pi (the double) with omega0 = 1e-15 rad/s, ``rkn`` at tol 1e-8: a rotation
2e-32 (in 1 - m) beyond the separatrix. The exact solution creeps over the top, then goes round
once every 24 s; the numerical one reverses at the top after the first turn (t = 23.2 s) and
ends 25 rad away. Every solver at every tolerance from 1e-4 to 1e-10 reverses it. (Released at
rest at pi, rkn used to be carried over the top; since its stages take sin(x0 + d) from sin x0
and cos x0 (trig.h), every solver holds that libration, and only the certificate warns.)
"""

from __future__ import annotations

import csv
import os
import subprocess
import sys
from pathlib import Path

import pytest

PI_RAD = "3.141592653589793rad"
CREEP = "1e-15"   # rad/s: over the top, just


def run_cli(args: list[str], cwd: Path, fmu_path: Path) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PENDULUM_FMU=str(fmu_path.resolve()))
    return subprocess.run([sys.executable, "-m", "pendulum_fmu", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=300, check=False)


def test_simulate_prints_the_hard_case_warning(fmu_path: Path, tmp_path: Path) -> None:
    done = run_cli(["simulate", "-a", PI_RAD, "-w", CREEP, "-s", "rkn", "-t", "1e-8", "-T", "120"], tmp_path,
                   fmu_path)
    assert done.returncode == 0, done.stderr
    lines = [line for line in (done.stdout + done.stderr).splitlines() if "hard case:" in line]
    assert len(lines) == 1 and lines[0].startswith("warning"), done.stdout + done.stderr   # the summary's line
    assert "Traceback" not in done.stderr


def test_a_harmless_run_prints_no_warning(fmu_path: Path, tmp_path: Path) -> None:
    done = run_cli(["simulate", "-a", "170", "-s", "rkn", "-t", "1e-8", "-p", "3"], tmp_path, fmu_path)
    assert done.returncode == 0, done.stderr
    assert "hard case" not in done.stdout + done.stderr


@pytest.mark.slow
def test_sweep_table_carries_the_warning(fmu_path: Path, tmp_path: Path) -> None:
    out = tmp_path / "sweep"
    done = run_cli(["sweep", "-a", "170,180", "-w", CREEP, "-s", "rkn", "-t", "1e-8", "-p", "3", "-j", "1", "-q",
                    "-o", str(out)], tmp_path, fmu_path)
    assert done.returncode == 0, done.stderr
    with open(out / "sweep.csv", newline="") as table:
        rows = {round(float(row["amplitude_deg"])): row["fmu_warning"] for row in csv.DictReader(table)}
    assert rows[170] == ""
    # the certificate's message at its first crossing comes first, the hard case's once it reverses
    assert rows[180].startswith("certificate:") and "hard case:" in rows[180]
    assert "certificate:" in done.stderr
