"""The command line: help that reads well, and bad arguments named with their range, exit 2."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from pendulum_fmu.cli.arguments import grid, positive
from pendulum_fmu.cli.main import main
from pendulum_fmu.errors import UsageError
from pendulum_fmu.fmu import locate
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid

SUBCOMMANDS = ("simulate", "compare", "study", "animate", "sweep", "bench")

BAD_ARGUMENTS = [
    (["simulate", "--length", "-1"], "argument -L/--length: must be a finite number > 0 m, got '-1'"),
    (["simulate", "-L", "0"], "argument -L/--length: must be a finite number > 0 m"),
    (["simulate", "--amplitude", "nan"], "argument -a/--amplitude: must be a finite angle in [-180, 180] deg"),
    (["simulate", "--amplitude", "181"], "argument -a/--amplitude: must be a finite angle in [-180, 180] deg"),
    (["simulate", "--amplitude", "4rad"], "(or [-pi, pi] rad), got '4rad'"),
    (["simulate", "--amplitude", "80 degrees"], "argument -a/--amplitude: '80 degrees' is not an angle"),
    (["simulate", "--omega0", "inf"], "argument -w/--omega0: must be a finite number (rad/s)"),
    (["simulate", "--gravity", "-9.81"], "argument -g/--gravity: must be a finite number > 0 m/s^2"),
    (["simulate", "--tolerance", "1.5"], "argument -t/--tolerance: must be a relative tolerance in (0, 1)"),
    (["simulate", "--tolerance", "0"], "argument -t/--tolerance: must be a relative tolerance in (0, 1)"),
    (["simulate", "--interface", "ME", "--solver", "rk4"],
     "argument -s/--solver: rk4 is a Co-Simulation method: with --interface ME choose from cvode"),
    (["simulate", "--interface", "CS", "--solver", "cvode"], "cvode is a Model Exchange method"),
    (["simulate", "--solver", "euler"], "argument -s/--solver: invalid choice: 'euler'"),
    (["simulate", "--periods", "0"], "argument -p/--periods: must be a finite number in (0, 100000] periods"),
    (["simulate", "--periods", "2", "--stop-time", "3"], "not allowed with argument"),
    (["simulate", "--stop-time", "-3"], "argument -T/--stop-time: must be a finite number in (0, 1e+06] s"),
    (["simulate", "--points-per-period", "0"], "argument -n/--points-per-period: must be an integer in [1, 10000]"),
    (["simulate", "--out", "run.txt"], "argument -o/--out: the file name must end in .csv or .csv.gz or .parquet"),
    (["simulate", "--fmu", "/no/such/Pendulum.fmu"], "argument --fmu: no such file: '/no/such/Pendulum.fmu'"),
    (["compare", "--out", "error.jpg"], "argument -o/--out: the file name must end in .png"),
    (["animate", "--fps", "0"], "argument --fps: must be an integer in [1, 60], got '0'"),
    (["animate", "--speed", "nan"], "argument --speed: must be a finite number in (0, 100]"),
    (["animate", "--out", "film.avi"], "argument -o/--out: the file name must end in .gif or .mp4"),
    (["sweep", "--amplitudes", "75:90"], "argument -a/--amplitudes: '75:90': a range is start:stop:count"),
    (["sweep", "--amplitudes", "75,nan"], "argument -a/--amplitudes: must be a finite angle in [-180, 180] deg"),
    (["sweep", "--amplitudes", "75:90:0"], "must be an integer in [1, 100000], got '0'"),
    (["sweep", "--lengths", "1,-2"], "argument -L/--lengths: must be a finite number > 0 m, got '-2'"),
    (["sweep", "--solvers", "dopri5,euler"], "argument -s/--solvers: 'euler' is not a solver: choose from dopri5"),
    (["sweep", "--tolerances", "1e-6,2"], "argument -t/--tolerances: must be a relative tolerance in (0, 1)"),
    (["sweep", "--scheduler", "localhost:8786"], "argument --scheduler: must be a Dask scheduler address"),
    (["sweep", "--workers", "0"], "argument -j/--workers: must be an integer in [1, 256]"),
    (["sweep", "--scheduler", "tcp://127.0.0.1:1", "--workers", "2"],
     "argument --workers: sets the size of the local cluster: not allowed with --scheduler"),
    (["sweep", "--format", "xlsx"], "argument -f/--format: invalid choice: 'xlsx'"),
    (["study", "--periods", "-1"], "argument --periods: must be a finite number in (0, 1000] periods"),
    (["bench", "sweep", "--runs", "0"], "argument --runs: must be an integer in [1, 1000000]"),
    (["frobnicate"], "argument COMMAND: invalid choice: 'frobnicate'"),
]


@pytest.mark.parametrize(("argv", "message"), BAD_ARGUMENTS, ids=[" ".join(a) for a, _ in BAD_ARGUMENTS])
def test_bad_argument_exits_2_naming_the_argument_and_its_range(argv: list[str], message: str,
                                                                capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert message in err, err
    assert err.startswith("pendulum-fmu") and len(err.splitlines()) == 1, err
    assert "Traceback" not in err


def test_a_bad_argument_in_a_real_process_gives_exit_2_and_no_traceback() -> None:
    done = subprocess.run([sys.executable, "-m", "pendulum_fmu", "simulate", "--length", "-1"],
                          capture_output=True, text=True, timeout=60, check=False)
    assert done.returncode == 2
    assert "pendulum-fmu simulate: error: argument -L/--length: must be a finite number > 0 m" in done.stderr
    assert "Traceback" not in done.stderr and done.stdout == ""


def test_a_missing_fmu_named_by_the_environment_is_a_usage_error() -> None:
    env = dict(os.environ, PENDULUM_FMU="/no/such/Pendulum.fmu")
    done = subprocess.run([sys.executable, "-m", "pendulum_fmu", "simulate"], capture_output=True, text=True,
                          timeout=60, check=False, env=env)
    assert done.returncode == 2
    assert "error: environment variable PENDULUM_FMU: no such file: '/no/such/Pendulum.fmu'" in done.stderr
    assert "Traceback" not in done.stderr


def test_a_missing_build_without_cmake_is_a_usage_error(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.delenv("PENDULUM_FMU", raising=False)
    monkeypatch.setattr(locate, "PACKAGED_FMU", tmp_path / "packaged" / "Pendulum.fmu")
    monkeypatch.setattr(locate, "DEFAULT_BUILD_DIR", tmp_path / "build")
    monkeypatch.setattr(locate.shutil, "which", lambda name: None)
    with pytest.raises(UsageError, match=r"argument fmu: .*is missing or out of date and cmake is not on PATH"):
        locate.locate_fmu()
    with pytest.raises(UsageError, match=r"argument fmu: .*is missing: build it") as refused:
        locate.locate_fmu(build=False)
    assert refused.value.field == "fmu" and refused.value.message.endswith("pass `fmu` PATH or set PENDULUM_FMU")


def test_a_missing_build_without_cmake_names_the_fmu_flag_on_the_command_line(
        monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.delenv("PENDULUM_FMU", raising=False)
    monkeypatch.setattr(locate, "PACKAGED_FMU", tmp_path / "packaged" / "Pendulum.fmu")
    monkeypatch.setattr(locate, "DEFAULT_BUILD_DIR", tmp_path / "build")
    monkeypatch.setattr(locate.shutil, "which", lambda name: None)
    with pytest.raises(SystemExit) as stop:
        main(["simulate", "-p", "1"])
    assert stop.value.code == 2
    line, = capsys.readouterr().err.splitlines()
    assert line.startswith("pendulum-fmu simulate: error: argument --fmu: ")
    assert "is missing or out of date and cmake is not on PATH to build it: install cmake, pass --fmu PATH or set " \
           "PENDULUM_FMU" in line


@pytest.mark.parametrize("command", SUBCOMMANDS)
def test_every_subcommand_has_help(command: str, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        main([command, "--help"])
    assert stop.value.code == 0
    out = capsys.readouterr().out
    assert out.startswith(f"usage: pendulum-fmu {command}")
    assert "examples:" in out


def test_top_level_help_lists_the_subcommands(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["--help"])
    out = capsys.readouterr().out
    for command in SUBCOMMANDS:
        assert f"    {command}" in out


def test_help_gives_units_and_ranges(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["simulate", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    for text in ("in [-180, 180] deg", "length L > 0, m", "m/s^2", "relative tolerance in (0, 1)", "rad/s",
                 "stop time in seconds", "FILE.csv, FILE.csv.gz or FILE.parquet"):
        assert text in out


def test_grid_expands_ranges_and_lists() -> None:
    assert grid(positive("m"))("1:2:5") == [1.0, 1.25, 1.5, 1.75, 2.0]
    assert grid(positive("m"))("0.5,1:3:3") == [0.5, 1.0, 2.0, 3.0]
    assert grid(positive("m"))("2:2:1") == [2.0]


def test_the_api_raises_usage_errors_too() -> None:
    with pytest.raises(UsageError, match="argument L: must be a finite number > 0") as refused:
        InitialValueProblem(1.0, L=-1.0)
    assert refused.value.field == "L"
    with pytest.raises(UsageError, match="argument theta0: must be a finite angle"):
        InitialValueProblem(float("nan"))
    with pytest.raises(UsageError, match="argument solver: must be one of dopri5, rk4, rkn, symplectic, cvode"):
        Method("euler")
    with pytest.raises(UsageError, match="argument tolerance: must be in"):
        Method("dopri5", 0.0)
    with pytest.raises(UsageError, match="argument stop"):
        TimeGrid(-1.0)
