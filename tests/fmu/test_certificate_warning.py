"""The certificate's warning reaches the user end to end: a Co-Simulation step beyond
its bound (|theta - theta_exact| <= 100 tol max(1, |theta_exact|), the same for omega with the
scale w0) returns fmi2Warning, and its message arrives in the sweep's table (column
``fmu_warning``) and on the command line, while a run within the bound carries none.

The case, from the measured table (docs/certificate.md): theta0 = 0, omega0 = 2 w0 (1 + 1e-11)
(1 - m = -2e-11), tol 1e-10, 10 revolutions at 20 points a revolution. rk4 is beyond its reach
there (tol |1 - m| = 2e-21 < 1e-19) and ends 4.7 times beyond the bound; rkn holds it (0.22 of
the bound, tests/c/test_certificate.c).
"""

from __future__ import annotations

import csv
import math
import os
import subprocess
import sys
from pathlib import Path

OMEGA0 = repr(2.0 * math.sqrt(9.81) * (1.0 + 1e-11))


def test_sweep_table_carries_the_certificate(fmu_path: Path, tmp_path: Path) -> None:
    out = tmp_path / "sweep"
    env = dict(os.environ, PENDULUM_FMU=str(fmu_path.resolve()))
    done = subprocess.run([sys.executable, "-m", "pendulum_fmu", "sweep", "-a", "0", "-w", OMEGA0,
                           "-s", "rk4,rkn", "-t", "1e-10", "-p", "10", "-n", "20", "-j", "1", "-q",
                           "--no-plots", "-o", str(out)],
                          cwd=tmp_path, env=env, capture_output=True, text=True, timeout=600, check=False)
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr
    with open(out / "sweep.csv", newline="") as table:
        rows = {row["solver"]: row for row in csv.DictReader(table)}
    warning = rows["rk4"]["fmu_warning"]
    assert warning.startswith("certificate: at t = "), warning
    assert "times beyond its bound" in warning and "solver rk4, tolerance 1e-10" in warning
    assert "1 - m = -2e-11" in warning and "rkn, dopri5 or symplectic at this tolerance can" in warning
    assert rows["rkn"]["fmu_warning"] == ""
    # the largest errors the sweep itself measured (theta, omega): rk4's omega error is beyond
    # 100 tol max(w0, |omega_exact|) somewhere, rkn's errors are within the bound everywhere
    w0 = math.sqrt(9.81)
    assert float(rows["rk4"]["max_omega_error_rad_s"]) > 100 * 1e-10 * w0
    assert float(rows["rkn"]["max_error_rad"]) < 100 * 1e-10
    assert float(rows["rkn"]["max_omega_error_rad_s"]) < 100 * 1e-10 * w0
    assert "certificate:" in done.stderr
