"""Both FMUs from a plain CMake build, as an importer's "build from sources" or a packager runs
it: ``cmake -S . -B build && cmake --build build`` with a Python on PATH that has no fmpy. The
FMI 3.0 declarations are the project's own (fmu_src/fmi3/fmi3_api.h); fmpy is a test dependency only.
"""

from __future__ import annotations

import shutil
import stat
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu

pytestmark = pytest.mark.slow

REPO = Path(__file__).resolve().parents[2]


def _python_without_fmpy(folder: Path) -> Path:
    """A ``python3``/``python`` on a PATH of its own that runs the system interpreter without
    site-packages (-S -I): whatever is installed, it cannot import fmpy."""
    folder.mkdir()
    real = shutil.which("python3", path="/usr/bin:/bin") or sys.executable
    for name in ("python3", "python"):
        shim = folder / name
        shim.write_text(f'#!/bin/sh\nexec "{real}" -S -I "$@"\n')
        shim.chmod(shim.stat().st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
    return folder


def test_both_fmus_build_from_cmake_alone(tmp_path: Path) -> None:
    shims = _python_without_fmpy(tmp_path / "bin")
    cmake = shutil.which("cmake")
    assert cmake is not None
    env = {"PATH": f"{shims}:{Path(cmake).parent}:/usr/bin:/bin", "HOME": str(tmp_path)}
    probe = subprocess.run(["python3", "-c", "import fmpy"], env=env, capture_output=True, text=True, check=False)
    assert probe.returncode != 0, "the build's python must not have fmpy"
    build = tmp_path / "build"
    configured = subprocess.run([cmake, "-S", str(REPO), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release"], env=env,
                                capture_output=True, text=True, timeout=300, check=False)
    assert configured.returncode == 0, configured.stdout[-3000:] + configured.stderr[-3000:]
    assert "not built" not in configured.stderr, configured.stderr
    built = subprocess.run([cmake, "--build", str(build), "--target", "fmu", "fmu3", "--parallel", "2"], env=env,
                           capture_output=True, text=True, timeout=900, check=False)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    fmi2, fmi3 = build / "Pendulum.fmu", build / "fmi3" / "Pendulum.fmu"
    assert read_model_description(str(fmi2)).fmiVersion == "2.0"
    assert read_model_description(str(fmi3)).fmiVersion == "3.0"
    # the FMI 3.0 FMU of the plain build runs, and gives the FMI 2.0 FMU's numbers bit for bit
    runs = [simulate_fmu(str(fmu), stop_time=1.0, output_interval=0.1, output=["theta", "theta_exact"],
                         validate=False) for fmu in (fmi2, fmi3)]
    assert np.array_equal(runs[0]["theta"], runs[1]["theta"]) and np.isfinite(runs[1]["theta"]).all()
    assert abs(runs[1]["theta"][-1] - runs[1]["theta_exact"][-1]) < 1e-6
