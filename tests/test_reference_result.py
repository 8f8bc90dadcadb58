"""The reference result in extra/org.fmi-standard.fmi-ls-ref/ of both FMUs (built at build time
by reference/write_reference_result.c): declared by its manifest, the FMU's own exact port on
the default experiment's grid, independent mpmath agrees, and the FMU's Co-Simulation run
stays within the stated 1e-6 rad of it."""

from __future__ import annotations

import io
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


def _reference(fmu: Path) -> np.ndarray:
    archive = zipfile.ZipFile(fmu)
    manifest = ElementTree.fromstring(archive.read(FOLDER + "fmi-ls-manifest.xml"))
    assert manifest.tag == "fmiReferences"
    assert manifest.get(LS + "fmi-ls-name") == "org.fmi-standard.fmi-ls-ref"
    (related,) = manifest.findall("Related")
    assert (related.get("role"), related.get("type")) == ("result", "text/csv")
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
    assert len(reference) == 1001
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
