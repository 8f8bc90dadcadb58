"""No silent minutes: the scripts' long steps say what they do, and CMake's stages come through."""

from __future__ import annotations

import re
import runpy
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
import setuptools

REPO = Path(__file__).resolve().parents[2]
BUILD_OUTPUT = ("[  3%] Building C object fmu_src/math/dd.c.o", "[ 40%] zig cc -target x86_64-windows-gnu: win64/x.dll",
                "[ 41%] Linking C shared library libPendulum.so", "[ 90%] Packing Pendulum.fmu",
                "[100%] Built target fmu", "build/Pendulum.fmu: binaries/linux64/Pendulum.so")
STAGES = ["[ 40%] zig cc -target x86_64-windows-gnu: win64/x.dll", "[ 90%] Packing Pendulum.fmu",
          "[100%] Built target fmu"]


def run_step(command: str) -> subprocess.CompletedProcess[str]:
    """``run_step "$CMAKE_STAGES" <command>`` of scripts/progress.sh, in bash."""
    bash = shutil.which("bash")
    if bash is None:
        pytest.skip("bash not found: apt-get install bash")
    script = f'source scripts/progress.sh; run_step "$CMAKE_STAGES" {command}'
    return subprocess.run([bash, "-c", script, "study.sh"], cwd=REPO, capture_output=True, text=True, timeout=60,
                          check=False)


def test_a_build_shows_its_stages_not_each_object_file() -> None:
    printed = "; ".join(f"echo '{line}'" for line in BUILD_OUTPUT)
    done = run_step(f"bash -c \"{printed}\"")
    assert done.returncode == 0 and done.stdout == ""
    assert done.stderr.splitlines() == [f"    {line}" for line in STAGES]


def test_a_failed_step_shows_its_output_and_names_the_command() -> None:
    done = run_step("bash -c \"echo '[ 40%] zig cc'; echo 'error: zig failed'; exit 3\"")
    assert done.returncode == 1
    assert done.stderr.splitlines()[-2:] == ["error: zig failed",
                                             "study.sh: failed: bash -c echo '[ 40%] zig cc'; echo 'error: zig "
                                             "failed'; exit 3 (the last lines of its output are above)"]


def test_every_long_step_of_the_scripts_says_what_it_does() -> None:
    """Each pip install and each build runs through run_step, after a line that says what it is."""
    for name in ("setup-env.sh", "study.sh", "test.sh"):
        lines = (REPO / "scripts" / name).read_text().splitlines()
        for k, line in enumerate(lines):
            command = not re.match(r"\s*(#|say |echo )", line)
            if command and re.search(r"pip install|build-fmu\.sh|cmake --build", line):
                assert "run_step" in "\n".join(lines[max(0, k - 3):k + 1]), (name, line)
                said = "\n".join(lines[max(0, k - 4):k])
                assert "say " in said or "echo \"==" in said, (name, line)


def test_setup_py_says_each_stage_of_the_cmake_build(monkeypatch: pytest.MonkeyPatch,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setattr(setuptools, "setup", lambda **kwargs: None)
    run_saying_stages = runpy.run_path(str(REPO / "setup.py"), run_name="setup_under_test")["run_saying_stages"]
    printed = "\n".join(BUILD_OUTPUT)
    code, tail = run_saying_stages([sys.executable, "-c", f"print({printed!r})"])
    assert code == 0 and tail == printed + "\n"
    assert capsys.readouterr().err.splitlines() == [f"pendulum-fmu build: {line}" for line in STAGES]
