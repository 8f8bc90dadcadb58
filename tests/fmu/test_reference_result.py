"""The reference result in extra/org.fmi-standard.fmi-ls-ref/ of both FMUs (built at build time
by fmu_src/libs/reference/write_reference_result.c): declared by its manifest, the FMU's own exact port on
the default experiment's grid, independent mpmath agrees, and the FMU's Co-Simulation run
stays within the stated 1e-6 rad of it. The manifest, the default experiment's ``.exp`` and
``documentation/fmi-ls-ref.html`` as FMI-LS-REF 1.0.0-beta.1 and the ma-hs-experiments format
lay them out."""

from __future__ import annotations

import hashlib
import io
import posixpath
import re
import zipfile
from pathlib import Path
from xml.etree import ElementTree

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu

from pendulum_fmu.bench.reference import closed_form, exact_frequency, max_abs_diff

FOLDER = "extra/org.fmi-standard.fmi-ls-ref/"
LS = "{http://fmi-standard.org/fmi-ls-manifest}"
STATED_CS_DEVIATION = 1e-6  # rad, as the manifest's description says
LS_VERSION = "1.0.0-beta.1"
LS_DESCRIPTION = "Layered Standard providing information on related files included in an FMU."
"""The value the standard's manifest schema fixes for fmi-ls-description."""
ROLE = re.compile(r"(document|requirement|specification|model|parameter|system|testcase"
                  r"|experiment(/(smoke-test|validation|uncertainty-analysis))?|result|method|rationale|report"
                  r"|request|delivery|configuration|signature|serialized-state(/.*)?|meta-data|other)")
"""The roles the standard's manifest schema allows (its pattern for the role attribute)."""


def _reference(fmu: Path) -> np.ndarray:
    archive = zipfile.ZipFile(fmu)
    manifest = ElementTree.fromstring(archive.read(FOLDER + "fmi-ls-manifest.xml"))
    assert manifest.tag == "fmiReferences"
    assert manifest.get(LS + "fmi-ls-name") == "org.fmi-standard.fmi-ls-ref"
    related = [r for r in manifest.findall("Related") if r.get("role") == "result"][0]  # the default's: first
    assert related.get("type") == "text/csv"
    text = archive.read(FOLDER + related.get("source", "")).decode()
    return np.genfromtxt(io.StringIO(text), delimiter=",", names=True, deletechars="")


def _default_run(fmu: Path, times: np.ndarray) -> np.ndarray:
    experiment = read_model_description(str(fmu)).defaultExperiment
    assert (float(experiment.startTime), float(experiment.stopTime)) == (times[0], times[-1])
    return simulate_fmu(str(fmu), fmi_type="CoSimulation", start_time=times[0], stop_time=times[-1],
                        output_interval=times[1] - times[0], output=["theta", "omega", "theta_exact"],
                        validate=False)


def test_reference_is_the_exact_port_and_mpmath(fmu_any: Path) -> None:
    reference = _reference(fmu_any)
    default = read_model_description(str(fmu_any)).defaultExperiment
    # the experiment's output grid: (stop - start) / stepSize intervals, 640 of 1/32 s
    assert len(reference) == round((float(default.stopTime) - float(default.startTime)) / float(default.stepSize)) + 1
    assert len(reference) == 641
    run = _default_run(fmu_any, reference["time"])
    assert np.allclose(run["time"], reference["time"], rtol=0, atol=1e-13)
    assert np.max(np.abs(run["theta_exact"] - reference["theta_exact"])) <= 1e-14
    assert np.array_equal(reference["theta"], reference["theta_exact"])
    md = read_model_description(str(fmu_any))
    start = {v.name: float(v.start) for v in md.modelVariables if v.start is not None and v.name != "solver"}
    sample = slice(0, None, 50)
    theta, omega, _ = closed_form(start["theta"], start["omega"], exact_frequency(start["L"], start["g"]),
                                  list(reference["time"][sample]))
    assert max_abs_diff(reference["theta"][sample], theta) <= 1e-14
    assert max_abs_diff(reference["omega"][sample], omega) <= 1e-13


def test_co_simulation_stays_within_the_stated_deviation(fmu_any: Path) -> None:
    reference = _reference(fmu_any)
    run = _default_run(fmu_any, reference["time"])
    deviation = float(np.max(np.abs(run["theta"] - reference["theta"])))
    print(f"\n{fmu_any}: max |theta_CS - theta_ref| = {deviation:.2e} rad over the default experiment")
    assert deviation <= STATED_CS_DEVIATION


def test_both_fmus_carry_the_same_reference(fmu_path: Path, fmu3_path: Path) -> None:
    read = [zipfile.ZipFile(f).read(FOLDER + "Pendulum_ref.csv") for f in (fmu_path, fmu3_path)]
    assert read[0] == read[1]
    with pytest.raises(KeyError):
        zipfile.ZipFile(fmu_path).read("Pendulum_ref.csv")  # only under extra/


def _related(archive: zipfile.ZipFile) -> dict[str, ElementTree.Element]:
    """The first file of each role: the default experiment's (the suite's files come after)."""
    manifest = ElementTree.fromstring(archive.read(FOLDER + "fmi-ls-manifest.xml"))
    first: dict[str, ElementTree.Element] = {}
    for entry in manifest.findall("Related"):
        first.setdefault(entry.get("role", ""), entry)
    return first


def test_manifest_follows_the_standard(fmu_any: Path) -> None:
    archive = zipfile.ZipFile(fmu_any)
    manifest = ElementTree.fromstring(archive.read(FOLDER + "fmi-ls-manifest.xml"))
    assert (manifest.get(LS + "fmi-ls-version"),
            manifest.get(LS + "fmi-ls-description")) == (LS_VERSION, LS_DESCRIPTION)
    names = set(archive.namelist())
    related = manifest.findall("Related")
    assert {r.get("role") for r in related} == {"result", "experiment/validation", "document"}
    for entry in related:
        assert ROLE.fullmatch(entry.get("role", "")), entry.get("role")
        member = posixpath.normpath(posixpath.join(FOLDER, entry.get("source", "")))
        assert member in names, member  # a relative source resolves against the manifest's folder
        assert entry.get("description")
        assert entry.get("checksumType", "SHA3-256") == "SHA3-256"
        assert entry.get("checksum") == hashlib.sha3_256(archive.read(member)).hexdigest(), member


def test_the_exp_file_is_the_default_experiment(fmu_any: Path) -> None:
    archive = zipfile.ZipFile(fmu_any)
    entry = _related(archive)["experiment/validation"]
    assert entry.get("type") == "application/x-ma-hs-experiments" and entry.get("source", "").endswith(".exp")
    root = ElementTree.fromstring(archive.read(FOLDER + entry.get("source", "")))
    assert root.tag == "Experiments" and root.get("name")
    (experiment,) = root.findall("Experiment")
    assert experiment.get("name")
    default = read_model_description(str(fmu_any)).defaultExperiment
    for name in ("startTime", "stopTime", "stepSize", "tolerance"):
        assert float(experiment.get(name, "nan")) == float(getattr(default, name)), name
    (references,) = experiment.findall("References")
    assert references.get("type", "text/csv") == "text/csv"
    assert FOLDER + references.get("source", "") == FOLDER + _related(archive)["result"].get("source", "")
    assert experiment.find("Parameters") is None  # the FMU's own start values: nothing to apply
    reference = _reference(fmu_any)
    assert (reference["time"][0], reference["time"][-1]) == (float(default.startTime), float(default.stopTime))
    # on the experiment's output grid: start + k stepSize, every row
    step = float(default.stepSize)
    assert np.array_equal(reference["time"], float(default.startTime) + np.arange(reference["time"].size) * step)


def test_the_documentation_page_is_there_and_linked(fmu_any: Path) -> None:
    archive = zipfile.ZipFile(fmu_any)
    assert FOLDER + "../../documentation/fmi-ls-ref.html" not in archive.namelist()
    assert posixpath.normpath(posixpath.join(FOLDER, _related(archive)["document"].get("source", ""))) == \
        "documentation/fmi-ls-ref.html"
    page = archive.read("documentation/fmi-ls-ref.html").decode()
    default = read_model_description(str(fmu_any)).defaultExperiment
    for text in ("Pendulum.exp", "experiment/validation", "Pendulum_ref.csv", LS_VERSION,
                 f"tolerance {default.tolerance}", f"step size {default.stepSize} s", "@"):
        assert (text in page) == (text != "@"), text  # every placeholder filled in
    assert 'href="fmi-ls-ref.html"' in archive.read("documentation/index.html").decode()
