"""The library names fields, the command names flags: each field a subcommand's library code
raises a UsageError for comes out under the flag that sets it, with the flags of the fields its
message names, in one line and exit code 2.

The library side (``UsageError.field``, backquoted fields in the message) is checked on the
same errors, so that a message which reads right on the command line cannot hide a flag in
the library's own text (tests/package/test_library_names_fields.py reads the code for that).
"""

from __future__ import annotations

import argparse
from pathlib import Path

import pytest

from pendulum_fmu import sizing
from pendulum_fmu.cli.fields import command_line_message
from pendulum_fmu.cli.main import main
from pendulum_fmu.errors import UsageError


def _refused(argv: list[str], capsys: pytest.CaptureFixture[str]) -> str:
    """The one stderr line of a command that must exit with 2."""
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code == 2
    lines = capsys.readouterr().err.splitlines()
    assert len(lines) == 1, lines
    return lines[0]


def test_the_message_names_flags_where_the_library_named_fields() -> None:
    parser = argparse.ArgumentParser(prog="demo")
    parser.add_argument("-p", "--periods")
    parser.add_argument("-n", "--points-per-period")
    parser.add_argument("-L", "--length")
    parser.add_argument("--fmu")
    error = UsageError("periods", "lower `periods` or `points_per_period`, or `workers`")
    assert str(error) == "argument periods: lower `periods` or `points_per_period`, or `workers`"
    assert command_line_message(error, parser) == ("argument -p/--periods: lower -p/--periods or "
                                                   "-n/--points-per-period, or workers")
    assert command_line_message(UsageError("L", "must be > 0"), parser) == "argument -L/--length: must be > 0"
    assert command_line_message(UsageError("$PENDULUM_FMU", "pass `fmu`"), parser) == \
        "environment variable PENDULUM_FMU: pass --fmu"
    assert command_line_message(UsageError("start_time", "finite"), parser) == "argument start_time: finite"


def test_an_fmu_of_the_other_fmi_version_names_fmu_and_fmi_version(fmu_path: Path,
                                                                   capsys: pytest.CaptureFixture[str]) -> None:
    line = _refused(["simulate", "-p", "1", "--fmu", str(fmu_path), "--fmi-version", "3"], capsys)
    assert line.startswith("pendulum-fmu simulate: error: argument --fmu: ")
    assert line.endswith(f"{str(fmu_path)!r} is an FMI 2.0 FMU, but --fmi-version 3 was given: drop one of the two "
                         "(see 'pendulum-fmu simulate --help')")


@pytest.mark.parametrize(("argv", "flag", "advice"), [
    (["-p", "10000", "-n", "10000", "-j", "2", "-a", "10"], "-p/--periods",
     "lower -p/--periods or -n/--points-per-period, or use fewer -j/--workers"),
    (["-a", "1:179:100000", "-t", "1e-4,1e-5,1e-6,1e-7,1e-8,1e-9,1e-10,1e-11,1e-12,1e-13"], "-a/--amplitudes",
     "use fewer values on its axes (at most about 976,562 runs fit)"),  # 4 GB / 4096 B a run
])
def test_a_sweep_too_big_names_the_flag_to_change(argv: list[str], flag: str, advice: str, fmu_path: Path,
                                                  tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setattr(sizing, "available_memory", lambda: 8 * 10 ** 9)
    line = _refused(["sweep", *argv, "--out", str(tmp_path / "sweep"), "--fmu", str(fmu_path)], capsys)
    assert line.startswith(f"pendulum-fmu sweep: error: argument {flag}: ")
    assert advice in line and "`" not in line
    assert not (tmp_path / "sweep").exists()  # refused before anything is written


def test_an_unreachable_scheduler_names_scheduler(fmu_path: Path, tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    line = _refused(["sweep", "-a", "10", "-p", "1", "--scheduler", "tcp://127.0.0.1:1", "--out",
                     str(tmp_path / "sweep"), "--fmu", str(fmu_path)], capsys)
    assert line.startswith("pendulum-fmu sweep: error: argument --scheduler: cannot reach a Dask scheduler at "
                           "tcp://127.0.0.1:1: "), line


def test_a_film_too_long_names_its_length_fps_and_speed(fmu_path: Path, tmp_path: Path,
                                                        capsys: pytest.CaptureFixture[str]) -> None:
    line = _refused(["animate", "-T", "100", "--fps", "60", "--out", str(tmp_path / "f.gif"), "--fmu", str(fmu_path)],
                    capsys)
    assert line.startswith("pendulum-fmu animate: error: argument -T/--stop-time: the animation would have 6001 "
                           "frames, at most 1500 are allowed: shorten it, lower --fps or raise --speed"), line
    assert not (tmp_path / "f.gif").exists()


@pytest.mark.parametrize(("argv", "expected"), [
    (["suite", "list", "--cases", "no-such-case"],
     "argument --cases: 'no-such-case' matches no case (see 'pendulum-fmu suite list')"),
    (["suite", "run", "--engine", "nope", "--out", "{out}"], "argument --engine: no engine 'nope' (one of fmpy, "),
    (["suite", "run", "--command", "run {bogus}", "--out", "{out}"],
     "argument --command: unknown placeholder {bogus} (known: "),
    (["suite", "run", "--command", "run {", "--out", "{out}"],
     "argument --command: Single '{' encountered in format string (write a literal brace as {{ or }})"),
])
def test_the_suite_names_cases_engine_and_command(argv: list[str], expected: str, tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    line = _refused([word.replace("{out}", str(tmp_path / "out")) for word in argv], capsys)
    assert f"error: {expected}" in line, line
