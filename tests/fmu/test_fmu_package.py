"""The FMU as a file: XML validity, archive layout, exported symbols, docs, start values."""

from __future__ import annotations

import re
import subprocess
import zipfile
from pathlib import Path
from xml.etree import ElementTree

from fmpy import read_model_description
from fmpy.fmi2 import FMU2Slave
from fmpy.validation import validate_fmu

from fmu_rebuild import included_closure
from pendulum_fmu.fmu.build import REPO_ROOT


def test_validate_fmu_reports_no_problem(fmu_path: Path) -> None:
    assert validate_fmu(str(fmu_path)) == []


def test_archive_holds_xml_binary_sources_and_documentation(fmu_path: Path) -> None:
    names = set(zipfile.ZipFile(fmu_path).namelist())
    root = ElementTree.fromstring(zipfile.ZipFile(fmu_path).read("modelDescription.xml"))
    listed = [f.get("name") for f in root.findall("CoSimulation/SourceFiles/File")]
    assert listed == [f.get("name") for f in root.findall("ModelExchange/SourceFiles/File")]
    expected = {"modelDescription.xml", "binaries/linux64/Pendulum.so", "documentation/index.html",
                "sources/pendulum_vrs.h", "sources/fmi2_api.h"}
    expected |= {f"sources/{name}" for name in listed}
    assert expected <= names
    # every C file shipped is one the XML lists, so a rebuild compiles exactly those
    assert {n for n in names if n.endswith(".c")} == {f"sources/{name}" for name in listed}


def test_sources_carry_only_what_the_build_reads(fmu_path: Path) -> None:
    """Every file in sources/ is a listed C file or a header one of them includes (so no
    FMI 3.0 layer in the FMI 2.0 FMU), and every header they include is there."""
    with zipfile.ZipFile(fmu_path) as archive:
        root = ElementTree.fromstring(archive.read("modelDescription.xml"))
        listed = [f.get("name") for f in root.findall("CoSimulation/SourceFiles/File")]
        carried = {n for n in archive.namelist() if n.startswith("sources/") and not n.endswith("/")}
        read = included_closure(archive, listed)
    assert carried == read
    assert "sources/layer.h" not in carried


def test_only_fmi_functions_are_exported(fmu_path: Path, tmp_path: Path) -> None:
    with zipfile.ZipFile(fmu_path) as archive:
        archive.extract("binaries/linux64/Pendulum.so", tmp_path)
    nm = subprocess.run(["nm", "-D", "--defined-only", str(tmp_path / "binaries/linux64/Pendulum.so")],
                        capture_output=True, text=True, check=True).stdout
    symbols = {line.split()[-1] for line in nm.splitlines() if line.split()[1] in "TtDdBbRr"}
    assert symbols, "no exported symbol found"
    assert all(s.startswith("fmi2") for s in symbols), sorted(s for s in symbols if not s.startswith("fmi2"))
    assert {"fmi2Instantiate", "fmi2DoStep", "fmi2GetDerivatives", "fmi2SerializeFMUstate"} <= symbols


def test_documentation_names_every_variable() -> None:
    html = (REPO_ROOT / "fmu_src/models/pendulum/documentation/index.html").read_text()
    md = read_model_description(str(REPO_ROOT / "modelDescription.xml"))
    cells = set(re.findall(r"<tr><td>([^<]+)</td>", html))
    assert cells == {v.name for v in md.modelVariables}


def test_generated_value_references_match_the_xml(fmu_path: Path) -> None:
    header = zipfile.ZipFile(fmu_path).read("sources/pendulum_vrs.h").decode()
    pairs = dict(re.findall(r'VARIABLE\((\d+)u, "([^"]+)"\)', header))
    md = read_model_description(str(fmu_path))
    assert {int(vr): name for vr, name in pairs.items()} == {v.valueReference: v.name for v in md.modelVariables}
    assert f'PENDULUM_GUID "{md.guid}"' in header


def test_start_values_of_the_binary_match_the_xml(fmu_path: Path, tmp_path: Path) -> None:
    """Read every variable with a start value during initialization, before any is set."""
    md = read_model_description(str(fmu_path))
    slave = FMU2Slave(guid=md.guid, unzipDirectory=_extract(fmu_path, tmp_path),
                      modelIdentifier="Pendulum", instanceName="start-values")
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    for v in md.modelVariables:
        if v.start is None:
            continue
        if v.type == "Real":
            assert slave.getReal([v.valueReference])[0] == float(v.start), v.name
        else:
            assert slave.getInteger([v.valueReference])[0] == int(v.start), v.name
    slave.freeInstance()


def _extract(fmu_path: Path, target: Path) -> str:
    with zipfile.ZipFile(fmu_path) as archive:
        archive.extractall(target)
    return str(target)
