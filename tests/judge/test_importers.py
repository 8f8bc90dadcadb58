"""Other importers than fmpy's simulate_fmu: two container FMUs, and the cross-check layout."""

from __future__ import annotations

import copy
import math
import shutil
from pathlib import Path

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.container_fmu import Configuration
from fmpy.container_fmu.cli import create_container_fmu
from fmpy.container_fmu.config import Component
from fmpy.cross_check.validate_vendor_repo import validate_test_fmu
from fmpy.model_description import CoSimulation, ModelDescription, ModelVariable, Unknown

from pendulum_fmu.fmu.cross_check import export

pytestmark = pytest.mark.engines

THETA0 = math.radians(80.0)
OUTPUTS = ["theta", "omega", "theta_exact", "omega_exact"]


def _alone(fmu: Path) -> np.ndarray:
    return simulate_fmu(str(fmu), stop_time=2.0, output_interval=0.01, start_values={"theta": THETA0},
                        output=OUTPUTS)


def _assert_same(inside: np.ndarray, alone: np.ndarray) -> None:
    """Same results; a container may sum its communication times differently (an ulp of t)."""
    assert inside.size == alone.size
    assert np.allclose(inside["time"], alone["time"], rtol=0, atol=1e-12)
    for name in OUTPUTS:
        assert np.max(np.abs(inside[name] - alone[name])) <= 1e-12, name


def test_inside_an_fmpy_container_fmu(fmu_path: Path, tmp_path: Path) -> None:
    inner = read_model_description(str(fmu_path))
    component = Component(name="pendulum", filename=fmu_path, modelDescription=inner)
    outer = ModelDescription()
    outer.fmiVersion = "2.0"
    outer.modelName = "PendulumInContainer"
    outer.guid = "{6c2f3a0e-4b7d-4f0a-9a51-5d2b8e7c1f00}"
    outer.coSimulation = CoSimulation(modelIdentifier="container_fmu")
    outer.coSimulation.fixedInternalStepSize = 0.01
    outer.unitDefinitions = inner.unitDefinitions
    # the container binary reserves value reference 0 for time
    outer.modelVariables.append(ModelVariable(name="time", causality="independent", variability="continuous",
                                              type="Real"))
    mappings = {}
    for variable in inner.modelVariables:
        if variable.type == "Real" and variable.causality in ("parameter", "output"):
            exposed = copy.copy(variable)
            outer.modelVariables.append(exposed)
            mappings[exposed] = [(component, variable)]
    by_name = {v.name: v for v in outer.modelVariables}
    outer.outputs = [Unknown(index=0, variable=by_name[u.variable.name]) for u in inner.outputs]
    config = Configuration(parallelDoStep=False, modelDescription=outer, components=[component],
                           connections=[], variableMappings=mappings)
    (tmp_path / "unzipped").mkdir()
    create_container_fmu(config, tmp_path / "unzipped", tmp_path / "Container.fmu")
    _assert_same(_alone(tmp_path / "Container.fmu"), _alone(fmu_path))


def test_inside_an_fmu_manipulation_toolbox_container(fmu_path: Path, tmp_path: Path) -> None:
    from fmu_manipulation_toolbox.assembly import Assembly

    shutil.copyfile(fmu_path, tmp_path / "Pendulum.fmu")
    (tmp_path / "wrapped.csv").write_text("rule;from_fmu;from_port;to_fmu;to_port\n"
                                          "FMU;Pendulum.fmu;;;\n"
                                          f"START;Pendulum.fmu;theta;{THETA0!r};\n")
    Assembly("wrapped.csv", default_step_size=0.01, fmu_directory=tmp_path).make_fmu(fmi_version=2)
    wrapped = simulate_fmu(str(tmp_path / "wrapped.fmu"), stop_time=2.0, output_interval=0.01, output=OUTPUTS)
    _assert_same(wrapped, _alone(fmu_path))


def test_cross_check_export_validates_and_reference_is_reproduced(fmu_path: Path, tmp_path: Path) -> None:
    folders = export(fmu_path, tmp_path)
    assert {f.parts[-5] for f in folders} == {"cs", "me"}
    for folder in folders:
        assert validate_test_fmu(str(folder)) == []
        assert {p.name for p in folder.iterdir()} == {"Pendulum.fmu", "Pendulum_ref.csv", "Pendulum_ref.opt",
                                                      "ReadMe.txt"}
    reference = np.genfromtxt(folders[0] / "Pendulum_ref.csv", delimiter=",", names=True)
    experiment = read_model_description(str(fmu_path)).defaultExperiment  # the reference's own grid
    simulated = simulate_fmu(str(fmu_path), stop_time=float(experiment.stopTime),
                             output_interval=float(experiment.stepSize), output=["theta"])
    assert np.allclose(reference["time"], simulated["time"], atol=1e-12)
    assert np.max(np.abs(reference["theta"] - simulated["theta"])) < 1e-6
