"""Both of the project's FMUs in every command, and any other FMU refused in one line.

``--fmu build/fmi3/Pendulum.fmu`` and ``--fmi-version 3`` work in every
command that takes ``--fmu`` (and in :class:`FmuRunner` and :func:`run_sweep`); an FMU of
another model (another ``modelName``, a variable missing, or FMI 1.0) is refused before any
run, in one line that names the file and says what differs, with exit code 2, no traceback
and no temporary folder left behind. (The installed wheel runs the same from an empty folder:
tests/package/test_wheel_install.py.)
"""

from __future__ import annotations

import re
import tempfile
import zipfile
from pathlib import Path

import pytest

from pendulum_fmu.cli.main import main
from pendulum_fmu.errors import UsageError
from pendulum_fmu.fmu.identity import pendulum_problem
from pendulum_fmu.fmu.runner import FmuRunner
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid
from pendulum_fmu.sweep.grid import SweepGrid
from pendulum_fmu.sweep.run import run_sweep

COMMANDS: list[list[str]] = [
    ["simulate", "-a", "85", "-p", "1"],
    ["compare", "-a", "170", "-p", "1", "-o", "c.png"],
    ["animate", "-a", "120", "-p", "0.2", "--fps", "5", "-o", "a.gif"],
    ["sweep", "-a", "10,170", "-p", "1", "-j", "1", "-q", "-o", "sw"],
    ["study", "--periods", "1", "--out", "st"],
    ["bench", "accuracy", "--points", "5"],
    ["bench", "speed", "--repeat", "1"],
    ["bench", "sweep", "--runs", "2", "--periods", "1", "--workers", "1", "--repeat", "1", "--loop", "c"],
]


def rewritten(fmu: Path, out: Path, old: str, new: str) -> Path:
    """A copy of ``fmu`` whose modelDescription.xml has ``old`` replaced by ``new`` (once)."""
    with zipfile.ZipFile(fmu) as source, zipfile.ZipFile(out, "w") as target:
        for item in source.infolist():
            data = source.read(item)
            if item.filename == "modelDescription.xml":
                text = data.decode()
                assert old in text
                data = text.replace(old, new, 1).encode()
            target.writestr(item, data)
    return out


@pytest.fixture(scope="module")
def foreign(fmu_path: Path, fmu3_path: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    folder = tmp_path_factory.mktemp("foreign")
    return {
        "another model": rewritten(fmu_path, folder / "Other.fmu", 'modelName="Pendulum"', 'modelName="Bouncer"'),
        "a variable missing": rewritten(fmu3_path, folder / "NoOmega.fmu", 'name="omega_exact"', 'name="w_exact"'),
        "FMI 1.0": rewritten(fmu_path, folder / "Old.fmu", 'fmiVersion="2.0"', 'fmiVersion="1.0"'),
        "malformed XML": rewritten(fmu_path, folder / "Broken.fmu", "<ModelVariables>", "<ModelVariables"),
    }


def _temp_folders() -> set[str]:
    return {p.name for p in Path(tempfile.gettempdir()).glob("pendulum-fmu-*")}


@pytest.mark.slow
@pytest.mark.parametrize("argv", COMMANDS, ids=[" ".join(a[:2]) for a in COMMANDS])
def test_every_command_runs_the_fmi3_fmu(argv: list[str], fmu3_path: Path, tmp_path: Path,
                                         monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("PENDULUM_FMU", raising=False)
    assert main([*argv, "--fmi-version", "3"]) == 0, capsys.readouterr().err
    out, err = capsys.readouterr()
    assert "Traceback" not in err
    if argv[0] == "simulate":
        assert re.search(r"max \|theta - theta_exact\|", out) or "error" in out
    if argv[:2] == ["bench", "speed"]:
        assert str(fmu3_path) in out and "| package, C loop (FmuRunner) |" in out


@pytest.mark.parametrize("argv", COMMANDS, ids=[" ".join(a[:2]) for a in COMMANDS])
def test_every_command_refuses_another_model_in_one_line(argv: list[str], foreign: dict[str, Path], tmp_path: Path,
                                                         monkeypatch: pytest.MonkeyPatch,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    before = _temp_folders()
    for kind, fmu in foreign.items():
        with pytest.raises(SystemExit) as stop:
            main([*argv, "--fmu", str(fmu)])
        assert stop.value.code == 2, kind
        lines = capsys.readouterr().err.strip().splitlines()
        assert len(lines) == 1, (kind, lines)
        reason = "is not an FMU" if kind == "malformed XML" else "is not the Pendulum FMU of pendulum-fmu"
        assert f"argument --fmu: '{fmu}'" in lines[0] and reason in lines[0], lines[0]
    assert list(tmp_path.iterdir()) == [] and _temp_folders() <= before


def test_the_reasons_say_what_differs(foreign: dict[str, Path], fmu_path: Path, fmu3_path: Path) -> None:
    assert pendulum_problem(fmu_path) is None and pendulum_problem(fmu3_path) is None
    assert "its model is 'Bouncer', not 'Pendulum'" in (pendulum_problem(foreign["another model"]) or "")
    assert "it has no variable 'omega_exact'" in (pendulum_problem(foreign["a variable missing"]) or "")
    assert "it is an FMI 1.0 FMU" in (pendulum_problem(foreign["FMI 1.0"]) or "")


def test_fmi_version_and_fmu_must_agree(fmu_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        main(["simulate", "-p", "1", "--fmu", str(fmu_path), "--fmi-version", "3"])
    assert stop.value.code == 2
    assert "is an FMI 2.0 FMU, but --fmi-version 3 was given" in capsys.readouterr().err


def test_runner_and_sweep_take_fmi3_and_refuse_others(fmu3_path: Path, foreign: dict[str, Path],
                                                      tmp_path: Path) -> None:
    with FmuRunner(fmu3_path) as runner:
        run = runner.run(InitialValueProblem.from_degrees(80.0), Method("rkn", 1e-9), TimeGrid(2, "periods", 20))
        assert runner.fmi_version == 3 and run.max_error < 1e-9 and run.steps and run.steps > 0
    for fmu in foreign.values():
        with pytest.raises(UsageError, match="argument fmu: '.*' (is not the Pendulum FMU|cannot be read)"):
            FmuRunner(fmu)
    with pytest.raises(UsageError, match="is not the Pendulum FMU"):
        run_sweep(foreign["another model"], SweepGrid((80.0,), periods=1), tmp_path / "s", progress=False)
    assert not (tmp_path / "s").exists()
