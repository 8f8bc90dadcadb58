"""Real co-simulation engines run Pendulum.fmu and write their own results; the judge decides.

libcosim (libcosimpy 0.0.6, FMI 2.0), Ecos (ecospy 0.7.2, FMI 2.0 and 3.0), FMU Manipulation
Toolbox 2.0 (its checker on both FMUs, and a container of two Pendulums run in fmpy). Each
engine runs in its own process (tests/engine_runs.py). Known defects are pinned: each test
that documents one fails the day the engine changes, so docs/importers.md stays true.
An engine that is not installed makes its tests SKIPPED with the install command (a failure
in CI, where PENDULUM_NO_SKIP=1).
"""

from __future__ import annotations

import math
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest
from fmpy import simulate_fmu
from fmpy.util import write_csv

from engine_runs import INSTALL, missing, run_ecos, run_libcosim
from pendulum_fmu.judge import ReadError, judge

THETA0 = math.radians(80.0)
STARTS = {"theta": THETA0, "L": 2.0}
JUDGED_AS = ["theta=80deg", "L=2"]


def require(module: str) -> None:
    why_not = missing(module)
    if why_not:
        pytest.skip(why_not)


# --- libcosim ------------------------------------------------------------------------------------

def test_libcosim_fmi2_time_series_pass(fmu_path: Path, tmp_path: Path) -> None:
    require("libcosimpy")
    run = run_libcosim(fmu_path, tmp_path, STARTS)
    assert run.returncode == 0, run.stderr[-2000:]
    verdict = judge(run.files["samples"], start=JUDGED_AS)
    assert verdict.passed, verdict.line
    grid = verdict.check("time grid").figures
    assert grid["start"] == 0.01 and grid["end"] == 10.0 and grid["rows"] == 1000
    assert verdict.check("theta error").figures["largest"] < 1e-11


def test_libcosim_file_observer_prints_six_digits(fmu_path: Path, tmp_path: Path) -> None:
    """libcosim's own CSV observer writes 6 significant digits: too coarse to show 1e-6."""
    require("libcosimpy")
    run = run_libcosim(fmu_path, tmp_path, STARTS)
    verdict = judge(run.files["observer"], start=JUDGED_AS)
    assert not verdict.passed
    assert verdict.check("diagnosis").figures["cause"] == "print precision"
    assert "6 significant digits" in verdict.check("read").line


def test_libcosim_aborts_the_process_on_an_fmu_error(fmu_path: Path, tmp_path: Path) -> None:
    """L = -1: the FMU refuses at initialization; libcosim aborts the process (no exception)."""
    require("libcosimpy")
    run = run_libcosim(fmu_path, tmp_path, {"L": -1.0})
    assert run.returncode in (-6, 134), (run.returncode, run.stderr[-2000:])
    assert "cosim::error" in run.stderr


def test_libcosim_has_no_fmi3(fmu3_path: Path, tmp_path: Path) -> None:
    """FMI 3.0: not supported by libcosim; libcosimpy then segfaults in add_local_slave. Run
    here in a subprocess to pin that behaviour (an FMI 3.0 libcosim would make this fail)."""
    require("libcosimpy")
    run = run_libcosim(fmu3_path, tmp_path, STARTS)
    assert run.returncode in (-11, 139), (run.returncode, run.stderr[-2000:])
    assert not run.files.get("samples")


# --- Ecos ------------------------------------------------------------------------------------------

def test_ecos_passes_both_fmus(fmu_any: Path, tmp_path: Path) -> None:
    require("ecospy")
    run = run_ecos(fmu_any, tmp_path, STARTS)
    assert run.returncode == 0, run.stderr[-2000:]
    verdict = judge(run.files["observer"], start=JUDGED_AS)
    assert verdict.passed, verdict.line
    assert verdict.columns["theta"] == "pend::theta[REAL]"
    assert "%.6f" in verdict.check("read").line  # Ecos writes fixed 6 decimals
    # Ecos sums its time: 1000 steps of 0.01 end at 9.999999999999831 (it prints "10")
    assert '"time": 9.999999999999831' in run.stdout


def test_ecos_swallows_an_fmu_error_and_the_judge_catches_it(fmu_path: Path, tmp_path: Path) -> None:
    """L = -1: the FMU refuses, Ecos logs it at debug level only, init() succeeds and theta
    stays frozen. The run looks normal; the judge fails it."""
    require("ecospy")
    run = run_ecos(fmu_path, tmp_path, {"L": -1.0, "theta": THETA0})
    assert run.returncode == 0, run.stderr[-2000:]
    verdict = judge(run.files["observer"], start=["theta=80deg"])
    assert not verdict.passed
    assert verdict.check("bound").status == "fail"
    assert verdict.check("diagnosis").figures["cause"] == "frozen"
    assert "the FMU never advanced" in verdict.line


def test_ecos_import_needs_tbb_on_the_loader_path(tmp_path: Path) -> None:
    """Without tbb's folder on LD_LIBRARY_PATH ``import ecospy`` fails: the workaround in
    engine_runs.ecos_environment is needed (remove it when this test fails)."""
    require("ecospy")
    import os

    env = {k: v for k, v in os.environ.items() if k != "LD_LIBRARY_PATH"}
    done = subprocess.run([sys.executable, "-c", "import ecospy"], capture_output=True, text=True, env=env,
                          timeout=120, check=False)
    assert done.returncode != 0 and "libtbb.so.12" in done.stderr


# --- FMU Manipulation Toolbox -----------------------------------------------------------------------

def fmutool() -> str:
    path = shutil.which("fmutool") or str(Path(sys.executable).with_name("fmutool"))
    if not Path(path).exists():
        pytest.skip(f"fmutool not found: {INSTALL}")
    return path


def test_fmutool_check_passes_both_fmus(fmu_any: Path) -> None:
    done = subprocess.run([fmutool(), "-input", str(fmu_any), "-check"], capture_output=True, text=True, timeout=120,
                          check=False)
    text = done.stdout + done.stderr
    version = "2.0" if zipfile.ZipFile(fmu_any).read("modelDescription.xml").find(b'fmiVersion="2.0"') >= 0 else "3.0"
    assert f"This FMU seems to be compliant with FMI-{version}." in text, text[-2000:]
    assert f"No semantic error against the FMI-{version[0]} standard." in text
    assert "ERROR" not in text


def test_fmutool_check_can_fail(fmu_path: Path, tmp_path: Path) -> None:
    """The same checker on the FMU with its guid removed reports the error."""
    with zipfile.ZipFile(fmu_path) as source, zipfile.ZipFile(tmp_path / "bad.fmu", "w") as target:
        for item in source.infolist():
            data = source.read(item)
            if item.filename == "modelDescription.xml":
                data = data.replace(b'guid="', b'notguid="', 1)
            target.writestr(item, data)
    done = subprocess.run([fmutool(), "-input", str(tmp_path / "bad.fmu"), "-check"], capture_output=True, text=True,
                          timeout=120, check=False)
    assert "This FMU does not validate with FMI standard." in done.stdout + done.stderr


def test_container_of_two_pendulums_in_fmpy(fmu_path: Path, tmp_path: Path) -> None:
    """fmucontainer joins two Pendulums (80 deg; L = 2) into one FMU; fmpy runs it; each
    instance is judged with its own start values."""
    fmucontainer = Path(fmutool()).with_name("fmucontainer")
    for name in ("p1", "p2"):
        shutil.copyfile(fmu_path, tmp_path / f"{name}.fmu")
    rules = ["rule;from_fmu;from_port;to_fmu;to_port", "FMU;p1.fmu;;;", "FMU;p2.fmu;;;"]
    rules += [f"OUTPUT;{p}.fmu;{v};;{p}.{v}" for p in ("p1", "p2") for v in ("theta", "omega", "theta_exact")]
    rules += [f"START;p1.fmu;theta;{THETA0!r};", "START;p2.fmu;L;2.0;"]
    (tmp_path / "two.csv").write_text("\n".join(rules) + "\n")
    done = subprocess.run([str(fmucontainer), "-container", "two.csv:0.01"], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300, check=False)
    assert (tmp_path / "two.fmu").exists(), done.stdout[-2000:] + done.stderr[-2000:]
    # the container's modelDescription fails fmpy's validation (engines.md): run without it
    result = simulate_fmu(str(tmp_path / "two.fmu"), stop_time=10.0, output_interval=0.01, validate=False)
    write_csv(tmp_path / "two_result.csv", result)
    with pytest.raises(ReadError, match="several instances"):
        judge(tmp_path / "two_result.csv")
    first = judge(tmp_path / "two_result.csv", instance="p1", start=["theta=80deg"])
    second = judge(tmp_path / "two_result.csv", instance="p2", start=["L=2"])
    assert first.passed, first.line
    assert second.passed, second.line
    assert first.columns["theta"] == "p1.theta" and second.columns["theta_exact"] == "p2.theta_exact"
    mixed_up = judge(tmp_path / "two_result.csv", instance="p2", start=["theta=80deg"])
    assert not mixed_up.passed
    assert np.isclose(mixed_up.check("exact columns").figures["fit"]["L"], 2.0, rtol=1e-9)
