"""The wheel, installed into a fresh virtual environment, runs every subcommand from an empty folder.

The wheel is built with ``pip wheel . --no-deps`` (CMake builds the FMU and the exact
solution's library into ``build/wheel-cmake/``, incrementally); the environment gets the
pinned dependencies of ``python/requirements.lock`` once (kept in ``build/wheel-venv`` while
the lock is unchanged, so a second run only reinstalls the wheel) and the wheel itself. Every
command then runs in an empty temporary folder with no ``PENDULUM_FMU``: it must use the FMU
and library inside the installed package and write under that folder.
"""

from __future__ import annotations

import io
import os
import subprocess
import zipfile
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

REPO = Path(__file__).resolve().parents[2]


def _run(command: list[str], cwd: Path, env: dict[str, str] | None = None,
         timeout: float = 600) -> subprocess.CompletedProcess[str]:
    return subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout, check=False)


COMMANDS: list[tuple[list[str], list[str]]] = [  # arguments, files it must write under the folder
    (["simulate", "-a", "85", "-p", "2", "-o", "run.csv"], ["run.csv"]),
    (["compare", "-a", "170", "-p", "2"], ["compare.png"]),
    (["study", "--periods", "2"], ["out/study/report.html", "out/study/fig5_overlay.png", "out/study/runs.csv"]),
    (["animate", "-a", "120", "-p", "0.5", "--fps", "10"], ["pendulum.gif"]),
    (["sweep", "-a", "10:170:4", "-p", "2", "-j", "1", "-q"], ["out/sweep/sweep.csv", "out/sweep/sweep_cost.png"]),
    (["bench", "accuracy", "--points", "11"], []),
    (["bench", "exact", "-n", "20000", "--amplitudes", "80"], []),
    (["bench", "speed", "--repeat", "1"], []),
    (["bench", "sweep", "--runs", "8", "--periods", "1", "--workers", "1", "--repeat", "1"], []),
    (["cross-check", "xc"], ["xc/fmus/2.0/cs/linux64/PendulumFMU/0.1.0/Pendulum/Pendulum_ref.csv",
                             "xc/fmus/3.0/me/linux64/PendulumFMU/0.1.0/Pendulum/Pendulum_ref.opt"]),
]


@pytest.mark.parametrize(("argv", "files"), COMMANDS, ids=[" ".join(a[:2]) for a, _ in COMMANDS])
def test_every_subcommand_runs_from_an_empty_folder(installed: Path, argv: list[str], files: list[str],
                                                    tmp_path: Path) -> None:
    env = {key: value for key, value in os.environ.items() if not key.startswith("PENDULUM_")}
    done = _run([str(installed), *argv], tmp_path, env, timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
    assert "Traceback" not in done.stderr
    for name in files:
        assert (tmp_path / name).is_file(), f"{name} missing; folder holds {sorted(tmp_path.rglob('*'))}"
    site = installed.parent.parent / "lib"
    assert not any(site.rglob("out")), "a command wrote into the installed package"


def test_what_is_not_installed_says_so_in_one_line(installed: Path, tmp_path: Path) -> None:
    env = {key: value for key, value in os.environ.items() if not key.startswith("PENDULUM_")}
    done = _run([str(installed), "bench", "solvers", "--quick"], tmp_path, env)
    assert done.returncode == 2
    assert done.stderr.splitlines() == [
        "pendulum-fmu bench solvers: error: the study times the FMU's solvers with the C driver tests/c/bench_solvers, "
        "a test program of the repository that the package does not carry: run bash scripts/bench.sh solvers in a "
        "source checkout, or give --driver"]
    exact = _run([str(installed), "bench", "exact", "-n", "1000", "--amplitudes", "80"], tmp_path, env)
    assert exact.returncode == 0 and "the C benchmark (tests/c/bench_exact) is not installed" in exact.stdout
    assert list(tmp_path.iterdir()) == []


def _clean_env() -> dict[str, str]:
    return {key: value for key, value in os.environ.items() if not key.startswith("PENDULUM_")}


def test_the_installed_package_runs_its_shipped_c_loop(installed: Path, tmp_path: Path) -> None:
    """FmuRunner of the installed wheel drives its runs with the wheel's pendulum_driver library
    (not the checkout's build/), for the FMI 2.0 and the FMI 3.0 FMU it carries."""
    python = installed.parent / "python"
    script = ("from pendulum_fmu.fmu import driver; from pendulum_fmu.fmu.build import PACKAGED_FMU, PACKAGED_FMU3; "
              "from pendulum_fmu import FmuRunner, InitialValueProblem, Method, TimeGrid; "
              "print(driver.library_path()); "
              "[print(r.loop, r.fmi_version, r.run(InitialValueProblem.from_degrees(80), Method('rkn', 1e-9), "
              "TimeGrid(2, 'periods', 20)).max_error) for r in (FmuRunner(PACKAGED_FMU), FmuRunner(PACKAGED_FMU3))]")
    private_tmp = tmp_path / "tmp"
    private_tmp.mkdir()
    done = _run([str(python), "-c", script], tmp_path, {**_clean_env(), "TMPDIR": str(private_tmp)})
    assert done.returncode == 0, done.stderr[-3000:]
    # the two runners are never closed: their extracted FMUs go when the interpreter exits
    assert list(private_tmp.iterdir()) == []
    library, *runs = done.stdout.splitlines()
    site = installed.parent.parent / "lib"
    assert Path(library).is_relative_to(site) and library.endswith("pendulum_fmu/lib/linux64/libpendulum_driver.so")
    assert [run.split()[:2] for run in runs] == [["c", "2"], ["c", "3"]]
    assert all(float(run.split()[2]) < 1e-9 for run in runs)


def test_the_installed_package_finds_the_split_pendulum(installed: Path, tmp_path: Path) -> None:
    """split_path gives the wheel's own PendulumSplit.ssp for FMI 2.0 and 3.0 (not the checkout's build/)."""
    python = installed.parent / "python"
    script = ("import pendulum_fmu; print(pendulum_fmu.split_path(fmi_version=2)); "
              "print(pendulum_fmu.split_path(fmi_version=3))")
    done = _run([str(python), "-c", script], tmp_path, _clean_env())
    assert done.returncode == 0, done.stderr[-3000:]
    site = installed.parent.parent / "lib"
    two, three = (Path(line) for line in done.stdout.splitlines())
    assert two.is_relative_to(site) and two.name == "PendulumSplit.ssp" and two.is_file()
    assert three.is_relative_to(site) and three.parent.name == "fmi3" and three.is_file()
    for ssp in (two, three):
        assert {"PendulumBody.fmu", "PendulumGravity.fmu"} <= {p.name for p in ssp.parent.iterdir()}


FMI3_COMMANDS: list[list[str]] = [
    ["simulate", "-a", "85", "-p", "2", "-o", "run.csv"],
    ["compare", "-a", "170", "-p", "1"],
    ["sweep", "-a", "10:170:3", "-p", "1", "-j", "1", "-q"],
    ["bench", "speed", "--repeat", "1"],
]


@pytest.mark.parametrize("argv", FMI3_COMMANDS, ids=[" ".join(a[:2]) for a in FMI3_COMMANDS])
def test_fmi_version_3_runs_the_packaged_fmi3_fmu(installed: Path, argv: list[str], tmp_path: Path) -> None:
    done = _run([str(installed), *argv, "--fmi-version", "3"], tmp_path, _clean_env(), timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
    assert "Traceback" not in done.stderr
    if argv[:2] == ["bench", "speed"]:
        assert "pendulum_fmu/fmi3/Pendulum.fmu" in done.stdout and "pendulum_fmu/lib/linux64" in done.stdout


def test_another_model_is_refused_in_one_line_by_every_command(installed: Path, tmp_path: Path) -> None:
    site = installed.parent.parent / "lib"
    packaged, = site.rglob("pendulum_fmu/Pendulum.fmu")
    other = tmp_path / "Other.fmu"
    with zipfile.ZipFile(packaged) as source, zipfile.ZipFile(other, "w") as target:
        for item in source.infolist():
            data = source.read(item)
            if item.filename == "modelDescription.xml":
                data = data.replace(b'modelName="Pendulum"', b'modelName="Bouncer"')
            target.writestr(item, data)
    work = tmp_path / "work"
    work.mkdir()
    for argv, _ in COMMANDS:
        if argv[:2] == ["bench", "exact"]:   # no FMU in it: the exact library only
            continue
        done = _run([str(installed), *argv, "--fmu", str(other)], work, _clean_env(), timeout=120)
        lines = done.stderr.strip().splitlines()
        assert done.returncode == 2 and len(lines) == 1, (argv, done.stderr)
        assert f"'{other}' is not the Pendulum FMU of pendulum-fmu: its model is 'Bouncer'" in lines[0], lines[0]
    assert list(work.iterdir()) == []


def test_pip_show_describes_the_package(installed: Path, tmp_path: Path) -> None:
    """The wheel's metadata: summary, licence, authors, its core requirements, the docs paths."""
    done = _run([str(installed.parent / "python"), "-m", "pip", "show", "--verbose", "pendulum-fmu"], tmp_path)
    assert done.returncode == 0, done.stderr
    fields = dict(line.partition(": ")[::2] for line in done.stdout.splitlines() if ": " in line and line[0] != " ")
    assert fields["Summary"].startswith("Build, simulate and check the Pendulum FMU")
    # pip shows License-Expression from pip 25 on (the venv's pip may be older): read it directly
    licence = _run([str(installed.parent / "python"), "-c", "import importlib.metadata as m; "
                    "d = m.metadata('pendulum-fmu'); print(d['License-Expression'], d['License-File'])"], tmp_path)
    assert licence.stdout.split() == ["MIT", "LICENSE"], licence.stdout + licence.stderr
    assert fields["Author"] == "The Pendulum FMU contributors"
    assert fields["Requires"].split(", ") == ["fmpy", "matplotlib", "numpy", "pyarrow", "scipy"]
    assert "Documentation, docs/index.md" in done.stdout and "Typing :: Typed" in done.stdout


FMU_FILES = ("Pendulum.fmu", "PendulumBody.fmu", "PendulumGravity.fmu", "PendulumSplit.ssp")
"""The FMUs and the SSP a build makes, in its folder and in its fmi3/ folder."""


def _platforms(archive: zipfile.ZipFile) -> set[str]:
    """The platform folders under an FMU's binaries/."""
    return {n.split("/")[1] for n in archive.namelist() if n.startswith("binaries/") and n.count("/") > 1}


def _same_content(wheel_copy: zipfile.ZipFile, built: zipfile.ZipFile, name: str) -> None:
    """The same members outside binaries/, byte for byte (an FMU inside an SSP compared as an
    FMU), and every platform the build's binaries/ holds."""
    ours = {n for n in wheel_copy.namelist() if not n.startswith("binaries/") and not n.endswith("/")}
    theirs = {n for n in built.namelist() if not n.startswith("binaries/") and not n.endswith("/")}
    assert ours == theirs, f"{name}: wheel only {sorted(ours - theirs)}, built only {sorted(theirs - ours)}"
    for member in sorted(ours):
        if member.endswith(".fmu"):
            with zipfile.ZipFile(io.BytesIO(wheel_copy.read(member))) as inner_ours, \
                    zipfile.ZipFile(io.BytesIO(built.read(member))) as inner_theirs:
                _same_content(inner_ours, inner_theirs, f"{name}/{member}")
        else:
            assert wheel_copy.read(member) == built.read(member), f"{name}: {member} differs"
    assert _platforms(built) <= _platforms(wheel_copy), name


def test_the_installed_fmus_are_the_built_fmus(installed: Path, fmu_path: Path) -> None:
    """Every FMU and SSP the installed package carries holds the files a plain ``cmake --build``
    puts into it (the checkout's build/, ``fmu_path``'s folder), byte for byte, the FMI-LS-REF
    reference result, experiment and manifest under extra/ included; only the binaries differ,
    the wheel carrying every platform's."""
    package = next((installed.parent.parent / "lib").glob("python3*/site-packages/pendulum_fmu"))
    carried = sorted(str(p.relative_to(package)) for p in package.rglob("*") if p.suffix in (".fmu", ".ssp"))
    expected = sorted([*FMU_FILES, *(f"fmi3/{name}" for name in FMU_FILES)])
    assert carried == expected
    for name in expected:
        with zipfile.ZipFile(package / name) as wheel_copy, zipfile.ZipFile(fmu_path.parent / name) as built:
            _same_content(wheel_copy, built, name)
            if name.endswith("Pendulum.fmu"):
                for member in ("fmi-ls-manifest.xml", "Pendulum.exp", "Pendulum_ref.csv"):
                    assert f"extra/org.fmi-standard.fmi-ls-ref/{member}" in wheel_copy.namelist(), f"{name}: {member}"


def test_simulate_then_judge_from_the_installed_package(installed: Path, tmp_path: Path) -> None:
    """The two main commands compose from a pip install: a run's file judged with the experiment
    it records, and the FMU's own FMI-LS-REF experiment found (judge reads the package's FMU)."""
    env = _clean_env()
    for argv in (["-a", "179.99", "-p", "3", "-o", "a.csv"],
                 ["--fmi-version", "3", "-a", "85", "-s", "cvode", "-o", "b.parquet"]):
        done = _run([str(installed), "simulate", *argv], tmp_path, env, timeout=300)
        assert done.returncode == 0, done.stderr
        judged = _run([str(installed), "judge", argv[-1]], tmp_path, env, timeout=300)
        assert judged.returncode == 0, judged.stdout[-3000:] + judged.stderr
        assert "verdict         PASS" in judged.stdout
