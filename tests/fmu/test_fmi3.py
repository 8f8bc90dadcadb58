"""The FMI 3.0 Pendulum.fmu through fmpy: validation, the same numbers as FMI 2.0 bit for bit,
the exact port against mpmath in every regime, a rebuild from its sources/buildDescription.xml.

The seed study's accuracy targets (CS, ME, grid independence) run on both FMUs in
test_seed_study.py (fixture fmu_any)."""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import zipfile
from pathlib import Path
from xml.etree import ElementTree

import fmpy
import mpmath as mp
import numpy as np
import pytest
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi3 import FMU3Slave
from fmpy.validation import validate_fmu

from fmu_rebuild import included_closure, rebuild_from_sources
from pendulum_fmu.bench.reference import closed_form, exact_frequency, max_abs_diff

SOLVERS = {"dopri5": 1, "rk4": 2, "rkn": 3, "symplectic": 4}
OUTPUTS = ["theta", "omega", "theta_exact", "omega_exact", "x", "y"]

# (theta0, omega0): libration small and large, within 1e-9 of the separatrix on both sides,
# rotation; L = 1, g = 9.81 (w0 = 3.132...)
W0 = math.sqrt(9.81)
REGIMES = {
    "libration_small": (0.1, 0.0),
    "libration_seed_90deg": (math.pi / 2, 0.0),
    "libration_near_top": (math.pi - 1e-3, 0.0),
    "below_separatrix": (0.0, 2 * W0 * (1 - 1e-9)),
    "above_separatrix": (0.0, 2 * W0 * (1 + 1e-9)),
    "rotation": (0.3, 3 * W0),
}


def _run(fmu: Path, start: dict[str, float], interface: str = "CoSimulation", stop: float = 5.0,
         step: float = 0.05) -> np.ndarray:
    return simulate_fmu(str(fmu), fmi_type=interface, start_time=0.0, stop_time=stop, output_interval=step,
                        start_values=start, output=OUTPUTS, validate=False)


def test_validate_fmu_finds_nothing(fmu3_path: Path) -> None:
    assert validate_fmu(str(fmu3_path)) == []


def test_model_description_declares_the_chosen_features(fmu3_path: Path) -> None:
    root = ElementTree.fromstring(zipfile.ZipFile(fmu3_path).read("modelDescription.xml"))
    assert root.get("fmiVersion") == "3.0"
    for interface in (root.find("CoSimulation"), root.find("ModelExchange")):
        assert interface is not None and interface.get("modelIdentifier") == "Pendulum"
        for flag in ("providesDirectionalDerivatives", "providesAdjointDerivatives", "canGetAndSetFMUState",
                     "canSerializeFMUState"):
            assert interface.get(flag) == "true", flag
    cs = root.find("CoSimulation")
    assert cs is not None and cs.get("maxOutputDerivativeOrder") == "3"
    assert cs.get("providesIntermediateUpdate") == "false" and cs.get("hasEventMode") == "false"


def test_archive_layout(fmu3_path: Path) -> None:
    names = set(zipfile.ZipFile(fmu3_path).namelist())
    assert {"modelDescription.xml", "binaries/x86_64-linux/Pendulum.so", "sources/buildDescription.xml",
            "documentation/index.html", "documentation/math.html"} <= names
    assert "sources/fmi2_api.h" not in names and "sources/layer.h" in names


def test_sources_carry_only_what_the_build_reads(fmu3_path: Path) -> None:
    """sources/ holds buildDescription.xml, the C files it lists and the headers they include."""
    with zipfile.ZipFile(fmu3_path) as archive:
        build = ElementTree.fromstring(archive.read("sources/buildDescription.xml"))
        listed = [f.get("name") for f in build.iter("SourceFile")]
        carried = {n for n in archive.namelist() if n.startswith("sources/") and not n.endswith("/")}
        read = included_closure(archive, listed)
    assert carried == read | {"sources/buildDescription.xml"}


@pytest.mark.parametrize("solver", sorted(SOLVERS))
@pytest.mark.parametrize("regime", sorted(REGIMES))
def test_co_simulation_is_bit_identical_to_fmi2(fmu_path: Path, fmu3_path: Path, solver: str, regime: str) -> None:
    theta0, omega0 = REGIMES[regime]
    start = {"theta": theta0, "omega": omega0, "solver": SOLVERS[solver]}
    fmi2 = _run(fmu_path, start, step=0.5)
    fmi3 = _run(fmu3_path, start, step=0.5)
    for name in ["time", *OUTPUTS]:
        assert np.array_equal(fmi2[name], fmi3[name]), name


def test_model_exchange_is_bit_identical_to_fmi2(fmu_path: Path, fmu3_path: Path) -> None:
    start = {"theta": math.radians(85.0)}
    fmi2 = _run(fmu_path, start, "ModelExchange")
    fmi3 = _run(fmu3_path, start, "ModelExchange")
    for name in ["time", *OUTPUTS]:
        assert np.array_equal(fmi2[name], fmi3[name]), name


@pytest.mark.parametrize("regime", sorted(REGIMES))
def test_exact_port_against_mpmath_in_every_regime(fmu3_path: Path, regime: str) -> None:
    theta0, omega0 = REGIMES[regime]
    result = _run(fmu3_path, {"theta": theta0, "omega": omega0}, step=0.25)
    theta, omega, _ = closed_form(theta0, omega0, exact_frequency(1.0, 9.81), list(result["time"]))
    with mp.workdps(50):
        scale = max(1.0, max(float(abs(t)) for t in theta))
    # the exact port's claim (README, bench accuracy): a few ulps of max(1, |theta|)
    assert max_abs_diff(result["theta_exact"], theta) <= 1e-14 * scale
    assert max_abs_diff(result["omega_exact"], omega) <= 1e-13 * max(1.0, float(max(abs(o) for o in omega)))


@pytest.mark.slow
def test_rebuilt_from_its_build_description_gives_the_same_results(fmu3_path: Path, tmp_path: Path) -> None:
    unzipped = rebuild_from_sources(fmu3_path, tmp_path)
    assert (unzipped / "binaries/x86_64-linux/Pendulum.so").exists()
    start = {"theta": math.radians(80.0)}
    original = _run(fmu3_path, start)
    rebuilt = _run(unzipped, start)
    for name in OUTPUTS:  # bit for bit: contraction is off in both
        assert np.array_equal(rebuilt[name], original[name]), (name, np.max(np.abs(rebuilt[name] - original[name])))


FMI3_BINARIES = {"x86_64-linux": "Pendulum.so", "x86_64-windows": "Pendulum.dll",
                  "x86_64-darwin": "Pendulum.dylib", "aarch64-darwin": "Pendulum.dylib", "aarch64-linux": "Pendulum.so"}
"""The FMI 3.0 platform folders (one per architecture) that scripts/build-fmu.sh fills."""


def exported_names(library: Path, folder: str) -> set[str]:
    """Names a loader can bind to: the dynamic symbols (ELF), the export table (PE), the
    export trie without the leading _ (Mach-O), read with llvm's tools."""
    objdump, nm = shutil.which("llvm-objdump-14") or "llvm-objdump", shutil.which("llvm-nm-14") or "llvm-nm"
    if shutil.which(objdump) is None:
        pytest.skip("llvm-objdump not found: install llvm (bash scripts/install-system-packages.sh)")
    if folder.endswith("linux"):
        text = subprocess.run([nm, "-D", "-g", "--defined-only", str(library)], capture_output=True, text=True,
                              check=True).stdout
        return {line.split()[-1] for line in text.splitlines()}
    if folder.endswith("windows"):
        text = subprocess.run([objdump, "-p", str(library)], capture_output=True, text=True, check=True).stdout
        table = text.split("Export Table:", 1)[1].split("\n\n", 1)[0]
        return set(re.findall(r"^\s+\d+\s+0x[0-9a-f]+\s+(\S+)$", table, re.MULTILINE))
    text = subprocess.run([objdump, "--macho", "--exports-trie", str(library)], capture_output=True, text=True,
                          check=True).stdout
    return {name[1:] for name in re.findall(r"^0x[0-9A-Fa-f]+\s+(\S+)", text, re.MULTILINE)}


@pytest.mark.parametrize("folder", sorted(FMI3_BINARIES))
def test_exports_exactly_the_fmi3_functions(fmu3_path: Path, tmp_path: Path, folder: str) -> None:
    """Every function the FMI 3.0 header declares, and nothing else (the core stays hidden), in
    every platform folder; on macOS zig's linker also exports its two image-header labels."""
    header = (Path(fmpy.__file__).parent / "c-code" / "fmi3Functions.h").read_text()
    declared = set(re.findall(r"#define (fmi3\w+)\s+fmi3FullName", header))
    member = f"binaries/{folder}/{FMI3_BINARIES[folder]}"
    with zipfile.ZipFile(fmu3_path) as archive:
        if member not in archive.namelist():
            pytest.fail(f"{member} missing: scripts/build-fmu.sh builds every platform")
        archive.extract(member, tmp_path)
    exported = exported_names(tmp_path / member, folder)
    extra = {"_mh_dylib_header", "__dso_handle"} if folder.endswith("darwin") else set()
    assert len(declared) == 75 and exported == declared | extra


def test_start_values_of_the_binary_match_its_xml(fmu3_path: Path) -> None:
    md = read_model_description(str(fmu3_path))
    instance = FMU3Slave(guid=md.instantiationToken, unzipDirectory=extract(str(fmu3_path)),
                         modelIdentifier="Pendulum", instanceName="start-values")
    instance.instantiate()
    instance.enterInitializationMode(startTime=0.0)
    checked = 0
    for variable in md.modelVariables:
        if variable.start is None:
            continue
        if variable.type == "Float64":
            assert instance.getFloat64([variable.valueReference])[0] == float(variable.start), variable.name
        else:
            assert instance.getInt64([variable.valueReference])[0] == int(variable.start), variable.name
        checked += 1
    assert checked == 5
    instance.freeInstance()


def test_project_header_declares_exactly_the_standards_functions() -> None:
    """fmu_src/fmi3/fmi3_api.h (the project's own declarations, written from the standard) declares
    the same 75 functions as the standard's fmi3Functions.h that fmpy installs."""
    standard = (Path(fmpy.__file__).parent / "c-code" / "fmi3Functions.h").read_text()
    declared = set(re.findall(r"#define (fmi3\w+)\s+fmi3FullName", standard))
    ours = (Path(__file__).resolve().parents[2] / "fmu_src" / "fmi3" / "fmi3_api.h").read_text()
    exported = re.findall(r"FMI3_EXPORT\s+[\w\s\*]*?\b(fmi3\w+)\(", ours)
    assert len(exported) == len(set(exported)) == 75
    assert set(exported) == declared
