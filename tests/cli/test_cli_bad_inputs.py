"""Every bad input of the commands: one line on stderr, a non-zero exit, no traceback, nothing written.

Each case runs from an empty working folder holding only what the case needs (a plain file
``afile``, a zip ``bad.fmu`` without ``modelDescription.xml``), and the folder must hold
exactly that afterwards.
"""

from __future__ import annotations

import zipfile
from pathlib import Path

import pytest

from pendulum_fmu.cli.main import main

CASES: list[tuple[list[str], str]] = [
    (["simulate", "-o", "afile/run.csv"], "'afile' (in 'afile/run.csv') is a file, not a folder"),
    (["simulate", "-o", "/proc/run.csv"], "cannot write in the folder '/proc'"),
    (["simulate", "-o", "/nonexistent/dir/run.csv"],
     "the folder '/nonexistent/dir' of '/nonexistent/dir/run.csv' does not exist"),
    (["compare", "-o", "/proc/x.png"], "cannot write in the folder '/proc'"),
    (["animate", "-o", "/proc/x.gif"], "cannot write in the folder '/proc'"),
    (["sweep", "-o", "afile/sw"], "is a file, not a folder"),
    (["study", "--out", "afile/study"], "is a file, not a folder"),
    (["simulate", "--fmu", "afile"], "'afile' is not an FMU (not a zip archive"),
    (["simulate", "--fmu", "bad.fmu"], "'bad.fmu' is not an FMU: the archive has no modelDescription.xml"),
    (["compare", "--fmu", "bad.fmu"], "'bad.fmu' is not an FMU: the archive has no modelDescription.xml"),
    (["sweep", "--fmu", "bad.fmu"], "'bad.fmu' is not an FMU: the archive has no modelDescription.xml"),
    (["bench", "exact", "--exe", "/nonexistent"], "argument --exe: no executable file '/nonexistent'"),
    (["bench", "exact", "-n", "-5"], "argument -n/--points: must be an integer in [1, 100000000], got '-5'"),
]


@pytest.mark.parametrize(("argv", "message"), CASES, ids=[" ".join(argv) for argv, _ in CASES])
def test_bad_input_is_one_line_and_writes_nothing(argv: list[str], message: str, tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "afile").write_text("not an FMU\n")
    with zipfile.ZipFile(tmp_path / "bad.fmu", "w") as archive:
        archive.writestr("binaries/readme.txt", "no model description here")
    before = sorted(p.name for p in tmp_path.iterdir())
    with pytest.raises(SystemExit) as stop:
        main(argv)
    assert stop.value.code not in (0, None)
    captured = capsys.readouterr()
    lines = captured.err.splitlines()
    assert len(lines) == 1 and message in lines[0], captured.err
    assert captured.out == ""
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    assert (tmp_path / "afile").read_text() == "not an FMU\n"
