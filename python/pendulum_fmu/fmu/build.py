"""Locate the repository and build ``Pendulum.fmu`` with CMake."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

REPO_ROOT: Path = Path(__file__).resolve().parents[3]
DEFAULT_BUILD_DIR: Path = REPO_ROOT / "build"
PACKAGED_FMU: Path = Path(__file__).resolve().parents[1] / "Pendulum.fmu"
"""Where a wheel built by ``setup.py`` carries the FMU (absent in an editable install)."""
PACKAGED_FMU3: Path = Path(__file__).resolve().parents[1] / "fmi3" / "Pendulum.fmu"
"""Where a wheel carries the FMI 3.0 FMU (CMake's ``build/fmi3/Pendulum.fmu``)."""


def fmu3_in(build_dir: Path) -> Path:
    """Where CMake packs the FMI 3.0 FMU in ``build_dir`` (it may not exist yet)."""
    return build_dir / "fmi3" / "Pendulum.fmu"


def fmu_in(build_dir: Path) -> Path:
    """Return where CMake packs the FMU in ``build_dir``.

    Parameters
    ----------
    build_dir : Path
        A CMake build folder of this repository.

    Returns
    -------
    Path
        ``build_dir / "Pendulum.fmu"`` (it may not exist yet).
    """
    return build_dir / "Pendulum.fmu"


def build_fmu(build_dir: Path = DEFAULT_BUILD_DIR, quiet: bool = True) -> Path:
    """Configure and build the FMU with CMake (incremental on a second call).

    Parameters
    ----------
    build_dir : Path
        The CMake build folder.
    quiet : bool
        Hide CMake's output unless it fails.

    Returns
    -------
    Path
        The packed ``Pendulum.fmu``.

    Raises
    ------
    RuntimeError
        If CMake fails; the message holds CMake's output.
    """
    jobs = str(os.cpu_count() or 1)
    commands = [
        ["cmake", "-S", str(REPO_ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release"],
        ["cmake", "--build", str(build_dir), "--parallel", jobs],
    ]
    for command in commands:
        completed = subprocess.run(command, capture_output=quiet, text=True, check=False)
        if completed.returncode != 0:
            raise RuntimeError(f"{' '.join(command)} failed:\n{completed.stdout}\n{completed.stderr}")
    return fmu_in(build_dir)


def find_fmu() -> Path:
    """Return the FMU to use: ``$PENDULUM_FMU`` if set, else the one installed with the package,
    else the default build (built if missing).

    Returns
    -------
    Path
        Path of an existing ``Pendulum.fmu``.
    """
    override = os.environ.get("PENDULUM_FMU")
    if override:
        return Path(override)
    if PACKAGED_FMU.is_file():
        return PACKAGED_FMU
    path = fmu_in(DEFAULT_BUILD_DIR)
    return path if path.exists() else build_fmu()
