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
