"""The package installs like a library: ranges, a small core, and extras each command names.

Fast checks read ``pyproject.toml``, ``python/requirements.lock`` and this environment: the
core is not pinned, every pin of the lock lies in its range, the extras' modules are the
extras' distributions, and a command whose extra is missing (hidden here through
``sys.modules``) says in one line which to install, with exit code 2, before any work.

The slow checks install the wheel of ``tests/package/test_wheel_install.py`` (conftest's
``built_wheel``) with its core dependencies only, constrained to the lock's versions, into
``build/wheel-core-venv`` (kept while the lock and the wheel's requirements are unchanged), and
run ``judge``, ``simulate``, ``compare``, ``study`` and ``exact()`` there from an empty folder;
``sweep``, ``animate`` (MP4), ``bench accuracy`` and ``bench sweep`` answer with the extra to
install.
"""

from __future__ import annotations

import argparse
import hashlib
import importlib.metadata
import math
import os
import re
import subprocess
import sys
import tomllib
import zipfile
from pathlib import Path

import pytest
from packaging.requirements import Requirement
from packaging.utils import canonicalize_name

from pendulum_fmu import exact
from pendulum_fmu.cli.extras import EXTRAS, extra_line
from pendulum_fmu.cli.main import main

REPO = Path(__file__).resolve().parents[2]
PROJECT = tomllib.loads((REPO / "pyproject.toml").read_text(encoding="utf-8"))["project"]
LOCK = REPO / "python" / "requirements.lock"
CORE_VENV = REPO / "build" / "wheel-core-venv"


def _pins() -> dict[str, str]:
    """The lock's ``name==version`` lines, by canonical name."""
    pins = {}
    for line in LOCK.read_text(encoding="utf-8").splitlines():
        name, _, version = line.strip().partition("==")
        if version:
            pins[canonicalize_name(name)] = version
    return pins


def _requirements() -> list[tuple[str, Requirement]]:
    """Every requirement of the project, core and extras, with its group ("core" or the extra)."""
    groups = [("core", text) for text in PROJECT["dependencies"]]
    groups += [(extra, text) for extra, texts in PROJECT["optional-dependencies"].items() for text in texts]
    return [(group, Requirement(text)) for group, text in groups]


# --- the metadata ------------------------------------------------------------------------------

def test_the_core_is_ranges_and_the_lock_pins_within_them() -> None:
    core = [Requirement(text) for text in PROJECT["dependencies"]]
    assert {canonicalize_name(r.name) for r in core} == {"fmpy", "numpy", "scipy", "matplotlib", "pyarrow"}
    pins = _pins()
    for group, requirement in _requirements():
        if canonicalize_name(requirement.name) == "pendulum-fmu":  # an extra made of extras
            assert requirement.extras <= set(PROJECT["optional-dependencies"]), (group, requirement)
            continue
        assert not any(spec.operator in ("==", "===") for spec in requirement.specifier), (group, str(requirement))
        pinned = pins.get(canonicalize_name(requirement.name))
        assert pinned is not None, f"{requirement.name} ({group}) is not pinned in {LOCK.name}"
        assert requirement.specifier.contains(pinned, prereleases=True), \
            f"{LOCK.name} pins {requirement.name}=={pinned}, outside {group}'s {requirement.specifier}"


def test_the_extras_table_names_the_extras_distributions() -> None:
    """cli/extras.py's modules of each extra are exactly what pyproject's extra installs."""
    owners = importlib.metadata.packages_distributions()
    for extra, modules in EXTRAS.items():
        listed = {canonicalize_name(Requirement(text).name) for text in PROJECT["optional-dependencies"][extra]}
        provided = {canonicalize_name(owner) for module in modules for owner in owners.get(module, [])}
        assert provided == listed, (extra, provided, listed)
    everything = {extra for text in PROJECT["optional-dependencies"]["all"] for extra in Requirement(text).extras}
    assert everything == set(EXTRAS)


def test_the_metadata_describes_the_package() -> None:
    assert PROJECT["license"] == "MIT" and (REPO / "LICENSE").read_text().startswith("MIT License")
    assert PROJECT["readme"] == "README.md" and "[LICENSE](LICENSE)" in (REPO / "README.md").read_text()
    assert PROJECT["authors"] and PROJECT["keywords"] and PROJECT["classifiers"]
    for label, path in PROJECT["urls"].items():
        assert (REPO / path).is_file(), (label, path)


# --- a missing extra, hidden in this process -----------------------------------------------------

MISSING: list[tuple[list[str], str, str, str]] = [  # arguments, hidden module, command, extra
    (["sweep", "-a", "10:20:2", "-p", "1", "-q"], "distributed", "sweep", "sweep"),
    (["animate", "-o", "film.mp4"], "imageio_ffmpeg", "animate", "animate"),
    (["bench", "accuracy", "--points", "3"], "mpmath", "bench accuracy", "bench"),
    (["bench", "sweep", "--runs", "2", "--repeat", "1"], "tqdm", "bench sweep", "bench"),
]


@pytest.mark.parametrize(("argv", "module", "command", "extra"), MISSING, ids=[m[2] for m in MISSING])
def test_a_missing_extra_is_named_in_one_line(argv: list[str], module: str, command: str, extra: str,
                                              monkeypatch: pytest.MonkeyPatch, tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.chdir(tmp_path)
    monkeypatch.setitem(sys.modules, module, None)  # find_spec answers None: as if not installed
    with pytest.raises(SystemExit) as stopped:
        main(argv)
    assert stopped.value.code == 2
    captured = capsys.readouterr()
    assert captured.err.splitlines() == [
        f"pendulum-fmu {command}: needs the {extra} extra: pip install 'pendulum-fmu[{extra}]' "
        f"(not installed: {module})"]
    assert captured.out == "" and list(tmp_path.iterdir()) == []


def test_a_gif_needs_no_ffmpeg(monkeypatch: pytest.MonkeyPatch) -> None:
    """animate asks for ffmpeg only for an MP4: the check passes on to the run for a GIF."""
    import pendulum_fmu.cli.animate as animate_command

    monkeypatch.setitem(sys.modules, "imageio_ffmpeg", None)

    class Reached(Exception):
        pass

    def stop_here(*args: object) -> None:
        raise Reached

    monkeypatch.setattr(animate_command, "problem_from", stop_here)
    with pytest.raises(Reached):
        animate_command.run(argparse.Namespace(out=Path("film.gif")))
    with pytest.raises(SystemExit):
        animate_command.run(argparse.Namespace(out=Path("film.MP4")))


def test_the_command_and_its_help_start_without_the_extras() -> None:
    """pendulum-fmu imports no extra when it starts: --help of a benchmark whose module needs
    mpmath works without it (bench accuracy imported mpmath at start before)."""
    hidden = ", ".join(f"{name!r}: None" for name in ("mpmath", "distributed", "dask", "tqdm", "imageio_ffmpeg"))
    script = (f"import sys; sys.modules.update({{{hidden}}}); from pendulum_fmu.cli.main import main; "
              "sys.exit(main(['bench', 'accuracy', '--help']))")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "mpmath" in done.stdout and "--points" in done.stdout


def test_the_line_names_every_missing_module() -> None:
    assert extra_line("sweep", "sweep", ["distributed", "tqdm"]) == (
        "pendulum-fmu sweep: needs the sweep extra: pip install 'pendulum-fmu[sweep]' "
        "(not installed: distributed, tqdm)")


# --- the wheel with its core only ----------------------------------------------------------------

def _run(command: list[str], cwd: Path, timeout: float = 600, **extra_env: str) -> subprocess.CompletedProcess[str]:
    env = {key: value for key, value in os.environ.items() if not key.startswith("PENDULUM_")}
    return subprocess.run(command, cwd=cwd, env={**env, **extra_env}, capture_output=True, text=True,
                          timeout=timeout, check=False)


def _core_requirements(wheel: Path) -> str:
    """The wheel's ``Requires-Dist`` lines without an extra marker."""
    with zipfile.ZipFile(wheel) as archive:
        metadata, = (n for n in archive.namelist() if n.endswith(".dist-info/METADATA"))
        lines = archive.read(metadata).decode().splitlines()
    return "\n".join(line for line in lines if line.startswith("Requires-Dist:") and "extra ==" not in line)


@pytest.fixture(scope="module")
def core_venv(built_wheel: Path) -> Path:
    """A virtual environment with the wheel and its core dependencies (the lock's versions)."""
    python = CORE_VENV / "bin" / "python"
    stamp = hashlib.sha256(LOCK.read_bytes() + _core_requirements(built_wheel).encode()).hexdigest()
    stamp_file = CORE_VENV / ".core"
    if not python.is_file() or not stamp_file.is_file() or stamp_file.read_text() != stamp:
        created = _run([sys.executable, "-m", "venv", "--clear", str(CORE_VENV)], REPO)
        assert created.returncode == 0, created.stderr
        deps = _run([str(python), "-m", "pip", "install", "-q", "-c", str(LOCK), str(built_wheel)], REPO)
        assert deps.returncode == 0, deps.stderr[-3000:]
        stamp_file.write_text(stamp)
    done = _run([str(python), "-m", "pip", "install", "-q", "--no-deps", "--force-reinstall", str(built_wheel)], REPO)
    assert done.returncode == 0, done.stderr[-3000:]
    return CORE_VENV


def test_the_core_venv_lacks_the_extras(core_venv: Path, tmp_path: Path) -> None:
    modules = sorted({module for modules in EXTRAS.values() for module in modules} - {"PIL"})  # PIL: matplotlib's
    script = f"import importlib.util as u; print([m for m in {modules!r} if u.find_spec(m) is not None])"
    done = _run([str(core_venv / "bin" / "python"), "-c", script], tmp_path)
    assert done.returncode == 0 and done.stdout.strip() == "[]", done.stdout + done.stderr
    checked = _run([str(core_venv / "bin" / "python"), "-m", "pip", "check"], tmp_path)
    assert checked.returncode == 0, checked.stdout


CORE_COMMANDS: list[tuple[list[str], list[str]]] = [  # arguments, files it must write
    (["simulate", "-a", "85", "-p", "2", "-o", "run.csv"], ["run.csv"]),
    (["compare", "-a", "170", "-p", "2"], ["compare.png"]),
    (["study", "--periods", "2"], ["out/study/report.html", "out/study/runs.csv"]),
]


@pytest.mark.parametrize(("argv", "files"), CORE_COMMANDS, ids=[a[0] for a, _ in CORE_COMMANDS])
def test_the_core_runs_its_commands(core_venv: Path, argv: list[str], files: list[str], tmp_path: Path) -> None:
    done = _run([str(core_venv / "bin" / "pendulum-fmu"), *argv], tmp_path, timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
    for name in files:
        assert (tmp_path / name).is_file(), name


def test_the_core_runs_exact_and_judges_its_file(core_venv: Path, tmp_path: Path) -> None:
    script = ("import numpy as np; from pendulum_fmu import exact; t = np.round(np.arange(1001) * 0.01, 10); "
              "theta, omega = exact(np.radians(85.0), 0.0, 1.0, 9.81, t); "
              "np.savetxt('exact.csv', np.column_stack([t, theta, omega]), delimiter=',', "
              "header='time,theta,omega', comments='', fmt='%.17g'); print(repr(float(theta[100])))")
    made = _run([str(core_venv / "bin" / "python"), "-c", script], tmp_path)
    assert made.returncode == 0, made.stderr[-3000:]
    theta, _ = exact(math.radians(85.0), 0.0, 1.0, 9.81, 1.0)  # this checkout's, at t = 1 s
    assert abs(float(made.stdout) - float(theta)) < 1e-14
    judged = _run([str(core_venv / "bin" / "pendulum-fmu"), "judge", "exact.csv", "--start", "theta=85deg",
                   "--plot", "errors.png"], tmp_path)
    assert judged.returncode == 0, judged.stdout[-3000:] + judged.stderr[-3000:]
    assert judged.stdout.splitlines()[-1].startswith("verdict") and "PASS" in judged.stdout.splitlines()[-1]
    assert (tmp_path / "errors.png").is_file()


@pytest.mark.parametrize(("argv", "module", "command", "extra"), MISSING, ids=[m[2] for m in MISSING])
def test_the_core_names_the_extra_to_install(core_venv: Path, argv: list[str], module: str, command: str,
                                             extra: str, tmp_path: Path) -> None:
    done = _run([str(core_venv / "bin" / "pendulum-fmu"), *argv], tmp_path)
    assert done.returncode == 2, done.stderr[-3000:]
    line, = done.stderr.splitlines()
    assert re.fullmatch(rf"pendulum-fmu {command}: needs the {extra} extra: pip install 'pendulum-fmu\[{extra}\]' "
                        r"\(not installed: [a-z_, ]+\)", line), line
    assert module in line and list(tmp_path.iterdir()) == []
