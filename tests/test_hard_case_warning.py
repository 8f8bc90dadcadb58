"""A hard case never passes silently, end to end: the FMU's fmi2Warning ("hard case: ...") when
its numerical solution goes over the top while the exact one does not reaches the user of the
``pendulum-fmu`` commands as one line, and the sweep's table as its ``fmu_warning`` column.

The case: released at rest at pi (the double), ``rkn`` at tol 1e-8. The exact solution stays
within ulps of the top for dozens of seconds, then swings back; the numerical one is carried
over the top and ends about 4 pi away.
"""

from __future__ import annotations

import csv
import os
import subprocess
import sys
from pathlib import Path

PI_RAD = "3.141592653589793rad"


def run_cli(args: list[str], cwd: Path, fmu_path: Path) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, PENDULUM_FMU=str(fmu_path.resolve()))
    return subprocess.run([sys.executable, "-m", "pendulum_fmu", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=300, check=False)


def test_simulate_prints_the_hard_case_warning(fmu_path: Path, tmp_path: Path) -> None:
    done = run_cli(["simulate", "-a", PI_RAD, "-s", "rkn", "-t", "1e-8", "-T", "120"], tmp_path, fmu_path)
    assert done.returncode == 0, done.stderr
    lines = [line for line in (done.stdout + done.stderr).splitlines() if "hard case:" in line]
    assert len(lines) == 1 and lines[0].startswith("warning"), done.stdout + done.stderr   # the summary's line
    assert "Traceback" not in done.stderr


def test_a_harmless_run_prints_no_warning(fmu_path: Path, tmp_path: Path) -> None:
    done = run_cli(["simulate", "-a", "170", "-s", "rkn", "-t", "1e-8", "-p", "3"], tmp_path, fmu_path)
    assert done.returncode == 0, done.stderr
    assert "hard case" not in done.stdout + done.stderr


def test_sweep_table_carries_the_warning(fmu_path: Path, tmp_path: Path) -> None:
    out = tmp_path / "sweep"
    done = run_cli(["sweep", "-a", "170,180", "-s", "rkn", "-t", "1e-8", "-p", "3", "-j", "1", "-q",
                    "-o", str(out)], tmp_path, fmu_path)
    assert done.returncode == 0, done.stderr
    with open(out / "sweep.csv", newline="") as table:
        rows = {round(float(row["amplitude_deg"])): row["fmu_warning"] for row in csv.DictReader(table)}
    assert rows[170] == ""
    # the certificate's message at its first crossing comes first, the hard case's once it goes over
    assert rows[180].startswith("certificate:") and "hard case:" in rows[180]
    assert "certificate:" in done.stderr
