"""Shared fixtures: the FMU under test (``$PENDULUM_FMU`` or the default build), and the wheel."""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import zipfile
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


REPO = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="session")
def built_wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The wheel as a user builds it: ``pip wheel . --no-deps`` (isolated build environment),
    built once per session, with the test environment's zig (``$PENDULUM_ZIG``).

    CMake builds into ``build/wheel-cmake/`` (incremental: the cmake on PATH may differ from the
    one that configured ``build/``, and CMake refuses a folder another version configured).
    """
    wheels = tmp_path_factory.mktemp("wheels")
    for scratch in [REPO / "build" / "lib", *(REPO / "build").glob("bdist.*")]:  # setuptools' staging
        shutil.rmtree(scratch, ignore_errors=True)
    env = dict(os.environ, PENDULUM_FMU_BUILD_DIR=str(REPO / "build" / "wheel-cmake"))
    # The same pinned zig as the test environment's (python/requirements.lock), at a path that
    # stays, with the caches of build/ (scripts/build-fmu.sh, the same zig): the C runtimes
    # it compiled for every target are not compiled again (80 s and more saved a run).
    import ziglang
    env["PENDULUM_ZIG"] = str(Path(ziglang.__file__).with_name("zig"))
    env["PENDULUM_ZIG_CACHE"] = str(REPO / "build" / "zig-cache")
    env.pop("PENDULUM_FMU", None)
    built = subprocess.run([sys.executable, "-m", "pip", "wheel", ".", "--no-deps", "-v", "-w", str(wheels)],
                           cwd=REPO, env=env, capture_output=True, text=True, timeout=1200, check=False)
    assert built.returncode == 0, built.stdout[-6000:] + built.stderr[-3000:]
    wheel, = wheels.glob("pendulum_fmu-*.whl")
    return wheel


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """A test that needs the wheel (built by ``pip wheel``, minutes) is ``slow``, whatever its file:
    ``bash scripts/test.sh --fast`` leaves it out."""
    for item in items:
        if "built_wheel" in getattr(item, "fixturenames", ()):
            item.add_marker(pytest.mark.slow)


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item: pytest.Item, call: pytest.CallInfo[None]):  # type: ignore[no-untyped-def]
    """With ``PENDULUM_NO_SKIP=1`` (set by ``.ci/run``, whose install script provides every tool),
    a skipped test fails instead: CI must never pass a test it did not run."""
    outcome = yield
    report = outcome.get_result()
    if os.environ.get("PENDULUM_NO_SKIP") == "1" and report.skipped:
        report.outcome = "failed"
        report.longrepr = f"skipped, but PENDULUM_NO_SKIP=1 requires every test to run: {report.longrepr}"


LOCK = REPO / "python" / "requirements.lock"
VENV = REPO / "build" / "wheel-venv"


def _run_quietly(command: list[str], cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=600, check=False)


@pytest.fixture(scope="session")
def installed(built_wheel: Path) -> Path:
    """The ``pendulum-fmu`` program of a fresh environment with the wheel installed."""
    wheel = built_wheel
    assert wheel.name.endswith("-py3-none-any.whl")
    names = zipfile.ZipFile(wheel).namelist()
    assert "pendulum_fmu/Pendulum.fmu" in names and "pendulum_fmu/lib/linux64/libpendulum_exact.so" in names
    assert "pendulum_fmu/fmi3/Pendulum.fmu" in names and "pendulum_fmu/lib/linux64/libpendulum_driver.so" in names
    stamp = hashlib.sha256(LOCK.read_bytes()).hexdigest()
    python = VENV / "bin" / "python"
    stamp_file = VENV / ".lock"
    if not python.is_file() or not stamp_file.is_file() or stamp_file.read_text() != stamp:
        created = _run_quietly([sys.executable, "-m", "venv", "--clear", str(VENV)], REPO)
        assert created.returncode == 0, created.stderr
        deps = _run_quietly([str(python), "-m", "pip", "install", "-q", "-r", str(LOCK)], REPO)
        assert deps.returncode == 0, deps.stderr[-3000:]
        stamp_file.write_text(stamp)
    done = _run_quietly([str(python), "-m", "pip", "install", "-q", "--no-deps", "--force-reinstall", str(wheel)], REPO)
    assert done.returncode == 0, done.stderr[-3000:]
    return VENV / "bin" / "pendulum-fmu"
