"""``pendulum_fmu.fmu_path``: the FMI 2.0 FMU by default, the FMI 3.0 one with ``fmi_version=3``."""

from __future__ import annotations

from pathlib import Path

import pytest

import pendulum_fmu
from pendulum_fmu.fmu.identity import fmi_version_of


def test_fmu_path_gives_the_version_asked(fmu_path: Path, fmu3_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("PENDULUM_FMU", str(fmu3_path))
    assert pendulum_fmu.fmu_path() == fmu3_path == pendulum_fmu.fmu_path(fmi_version=3)
    assert fmi_version_of(pendulum_fmu.fmu_path(fmi_version=3)) == 3
    monkeypatch.setenv("PENDULUM_FMU", str(fmu_path))
    assert pendulum_fmu.fmu_path(fmi_version=2) == fmu_path == pendulum_fmu.fmu_path()
    assert fmi_version_of(pendulum_fmu.fmu_path()) == 2
