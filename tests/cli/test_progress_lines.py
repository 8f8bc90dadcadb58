"""The library says what it is doing through ``logging``; the command prints those lines.

Library code prints nothing: a CMake build of the FMU starting and a long run's estimate are
INFO records of the ``pendulum_fmu`` logger. Called from Python they reach the log and leave
stderr alone; the command shows each on stderr, one line, as it always has.
"""

from __future__ import annotations

import logging
import shutil
from pathlib import Path
from typing import Any

import pytest

from pendulum_fmu import sizing
from pendulum_fmu.cli.main import main
from pendulum_fmu.fmu import locate
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid


def _missing_build(monkeypatch: pytest.MonkeyPatch, tmp_path: Path, fmu_path: Path) -> list[Path]:
    """No packaged FMU and no build: ``locate_fmu`` builds into ``tmp_path/build`` (a copy of the real one)."""
    builds: list[Path] = []

    def build(build_dir: Path) -> None:
        builds.append(build_dir)
        (build_dir).mkdir(parents=True)
        shutil.copy(fmu_path, build_dir / "Pendulum.fmu")

    monkeypatch.delenv("PENDULUM_FMU", raising=False)
    monkeypatch.setattr(locate, "PACKAGED_FMU", tmp_path / "packaged" / "Pendulum.fmu")
    monkeypatch.setattr(locate, "DEFAULT_BUILD_DIR", tmp_path / "build")
    monkeypatch.setattr(locate.shutil, "which", lambda name: "/usr/bin/cmake")
    monkeypatch.setattr(locate, "build_fmu", build)
    return builds


def test_a_build_is_logged_by_the_library_and_printed_by_the_command(
        fmu_path: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str],
        caplog: pytest.LogCaptureFixture) -> None:
    builds = _missing_build(monkeypatch, tmp_path, fmu_path)
    fmu = tmp_path / "build" / "Pendulum.fmu"
    line = f"pendulum-fmu: {fmu} is missing: building it with CMake (a minute or more) ..."
    with caplog.at_level(logging.INFO, logger="pendulum_fmu"):
        assert locate.locate_fmu() == tmp_path / "build" / "Pendulum.fmu"
    assert [r.getMessage() for r in caplog.records if r.name == "pendulum_fmu.fmu.locate"] == [line]
    assert capsys.readouterr().err == ""     # the library itself prints nothing
    shutil.rmtree(tmp_path / "build")
    assert main(["simulate", "-p", "1", "-n", "4"]) == 0
    assert capsys.readouterr().err.splitlines() == [line]
    assert builds == [tmp_path / "build"] * 2
    shutil.rmtree(tmp_path / "build")
    with caplog.at_level(logging.INFO, logger="pendulum_fmu"):
        locate.locate_fmu()       # after the command, the library is quiet again
    assert capsys.readouterr().err == ""


def test_a_long_run_is_announced_in_the_log_not_on_stderr(monkeypatch: pytest.MonkeyPatch,
                                                          capsys: pytest.CaptureFixture[str],
                                                          caplog: pytest.LogCaptureFixture) -> None:
    class Runner:   # stands for FmuRunner: calls the size check with the period, runs nothing
        def run(self, problem: InitialValueProblem, method: Method, grid: TimeGrid, plan: Any) -> str:
            plan(2.0)
            return "ran"

    monkeypatch.setattr(sizing, "available_memory", lambda: 64 * 10 ** 9)
    grid = TimeGrid(10_000, "periods", 500)          # 5 million points at 3 us each: 15 s
    with caplog.at_level(logging.INFO, logger="pendulum_fmu"):
        assert sizing.planned_run(Runner(), InitialValueProblem(1.0), Method(), grid) == "ran"  # type: ignore[arg-type]
    assert [r.getMessage() for r in caplog.records] == ["simulating 5 million output points: about 15 s ..."]
    assert capsys.readouterr().err == ""
