"""Shared fixtures: the FMU under test (``$PENDULUM_FMU`` or the default build)."""

from __future__ import annotations

from pathlib import Path

import pytest

from pendulum_fmu.fmu.build import find_fmu


@pytest.fixture(scope="session")
def fmu_path() -> Path:
    """Path of the built ``Pendulum.fmu``."""
    path = find_fmu()
    assert path.exists(), f"no FMU at {path}"
    return path


@pytest.fixture(scope="session")
def fmu3_path(fmu_path: Path) -> Path:
    """Path of the FMI 3.0 ``Pendulum.fmu`` built beside the FMI 2.0 one (``build/fmi3/``)."""
    path = fmu_path.parent / "fmi3" / "Pendulum.fmu"
    assert path.exists(), f"no FMI 3.0 FMU at {path}: cmake --build build packs it (cmake/Fmi3.cmake)"
    return path


@pytest.fixture(scope="session", params=["2.0", "3.0"])
def fmu_any(request: pytest.FixtureRequest, fmu_path: Path) -> Path:
    """Each FMU in turn, FMI 2.0 then FMI 3.0: for the tests both must pass alike."""
    if request.param == "2.0":
        return fmu_path
    return request.getfixturevalue("fmu3_path")
