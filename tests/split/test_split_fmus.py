"""The split pendulum's FMUs and SSP packages (docs/split.md, cmake/Split.cmake).

``PendulumBody`` and ``PendulumGravity``, FMI 2.0 and FMI 3.0, built beside ``Pendulum.fmu``:
fmpy's ``validate_fmu`` and the FMU Manipulation Toolbox's checker accept each; the model
descriptions say what the C code does; a plain Gauss-Seidel master (written here, with fmpy's
``FMU2Slave``/``FMU3Slave``) converges to the exact pendulum with order 1 under zero-order hold,
and with a higher order when it passes the output derivatives on as input derivatives (FMI 2.0);
both ``PendulumSplit.ssp`` open with ``fmpy.ssp.ssd.read_ssd`` (validated against the SSP 1.0
schema) and name both components, both connections and the parameter bindings.
"""

from __future__ import annotations

import math
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path
from typing import Any

import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave
from fmpy.ssp.ssd import read_ssd
from fmpy.validation import validate_fmu

from engine_runs import FMUTOOL_INSTALL

THETA0 = 1.3089969389957472  # 75 deg, the start value of both model descriptions
VR = {"L": 1, "g": 2, "theta": 3, "omega": 5, "theta_exact": 7, "omega_exact": 8, "alpha": 16}
MODELS = ["PendulumBody", "PendulumGravity"]


@pytest.fixture(scope="session")
def split_dirs(fmu_path: Path) -> dict[str, Path]:
    """The folders of each FMI version's split FMUs and SSP: beside ``Pendulum.fmu``."""
    dirs = {"2.0": fmu_path.parent, "3.0": fmu_path.parent / "fmi3"}
    for folder in dirs.values():
        for name in [*(f"{m}.fmu" for m in MODELS), "PendulumSplit.ssp"]:
            assert (folder / name).exists(), f"no {folder / name}: cmake --build build makes it (cmake/Split.cmake)"
    return dirs


def split_fmu(split_dirs: dict[str, Path], version: str, model: str) -> Path:
    return split_dirs[version] / f"{model}.fmu"


@pytest.mark.parametrize("version", ["2.0", "3.0"])
@pytest.mark.parametrize("model", MODELS)
def test_fmpy_validates(split_dirs: dict[str, Path], version: str, model: str) -> None:
    path = split_fmu(split_dirs, version, model)
    assert validate_fmu(str(path)) == []
    md = read_model_description(str(path))
    assert md.fmiVersion == version and md.coSimulation is not None and md.modelExchange is None
    assert md.coSimulation.modelIdentifier == model


@pytest.mark.parametrize("version", ["2.0", "3.0"])
@pytest.mark.parametrize("model", MODELS)
def test_fmu_manipulation_toolbox_checker(split_dirs: dict[str, Path], version: str, model: str) -> None:
    fmutool = Path(sys.executable).parent / "fmutool"
    if not fmutool.exists():
        fmutool = Path(shutil.which("fmutool") or "fmutool")
    if not fmutool.exists():
        pytest.skip(f"fmutool not found: {FMUTOOL_INSTALL}")
    run = subprocess.run([str(fmutool), "-input", str(split_fmu(split_dirs, version, model)), "-check"],
                         capture_output=True, text=True, timeout=300)
    out = run.stdout + run.stderr
    assert run.returncode == 0, out
    assert f"compliant with FMI-{version}" in out, out
    assert f"No semantic error against the FMI-{version[0]} standard" in out, out


@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_model_descriptions(split_dirs: dict[str, Path], version: str) -> None:
    """Variables, causalities, units, start values and the capability flags the C code keeps."""
    body = read_model_description(str(split_fmu(split_dirs, version, "PendulumBody")))
    gravity = read_model_description(str(split_fmu(split_dirs, version, "PendulumGravity")))
    token = "guid" if version == "2.0" else "instantiationToken"
    assert body.guid != gravity.guid, token
    for md in (body, gravity):
        assert md.defaultExperiment.startTime in ("0", 0, 0.0) or float(md.defaultExperiment.startTime) == 0
        assert float(md.defaultExperiment.stopTime) == 10 and float(md.defaultExperiment.stepSize) == 0.01
        assert md.coSimulation.canHandleVariableCommunicationStepSize
        # FMU states, for a master that rolls a step back (tests/split/test_split_states.py)
        assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    v = {var.name: var for var in body.modelVariables}
    assert (v["alpha"].causality, v["alpha"].valueReference, float(v["alpha"].start)) == ("input", 16, 0.0)
    assert v["alpha"].unit == "rad/s2" and v["theta"].unit == "rad" and v["L"].unit == "m"
    assert (v["theta"].causality, v["theta"].initial, float(v["theta"].start)) == ("output", "exact", THETA0)
    assert (v["omega"].causality, float(v["omega"].start)) == ("output", 0.0)
    assert v["theta_exact"].causality == v["omega_exact"].causality == "output"
    assert [u.variable.name for u in body.derivatives] == ["der(theta)", "der(omega)"]
    w = {var.name: var for var in gravity.modelVariables}
    assert (w["theta"].causality, w["theta"].valueReference, float(w["theta"].start)) == ("input", 3, THETA0)
    assert (w["alpha"].causality, w["alpha"].valueReference) == ("output", 16)
    assert [u.variable.name for u in gravity.outputs] == ["alpha"]
    # FMI 2.0: input derivatives, so Gravity can give d alpha / dt; FMI 3.0 has none in Co-Simulation
    assert body.coSimulation.maxOutputDerivativeOrder == 3
    if version == "2.0":
        assert body.coSimulation.canInterpolateInputs and gravity.coSimulation.canInterpolateInputs
        assert gravity.coSimulation.maxOutputDerivativeOrder == 2
    else:
        assert gravity.coSimulation.maxOutputDerivativeOrder == 0


class Slaves:
    """Body and Gravity of one FMI version, instantiated and initialized with fmpy."""

    def __init__(self, split_dirs: dict[str, Path], version: str, tmp: Path) -> None:
        self.v3 = version == "3.0"
        self.fmus: list[Any] = []
        for model in MODELS:
            path = split_fmu(split_dirs, version, model)
            md = read_model_description(str(path))
            cls = FMU3Slave if self.v3 else FMU2Slave
            kwargs = {"guid": md.guid}
            fmu = cls(unzipDirectory=extract(str(path), str(tmp / f"{model}{version}")),
                      modelIdentifier=model, instanceName=model, **kwargs)
            fmu.instantiate()
            if self.v3:
                fmu.enterInitializationMode(startTime=0.0)
            else:
                fmu.setupExperiment(startTime=0.0)
                fmu.enterInitializationMode()
            fmu.exitInitializationMode()
            self.fmus.append(fmu)
        self.body, self.gravity = self.fmus

    def get(self, fmu: Any, *vrs: int) -> list[float]:
        return list(fmu.getFloat64(list(vrs)) if self.v3 else fmu.getReal(list(vrs)))

    def set(self, fmu: Any, vr: int, value: float) -> None:
        if self.v3:
            fmu.setFloat64([vr], [value])
        else:
            fmu.setReal([vr], [value])

    def close(self) -> None:
        for fmu in self.fmus:
            fmu.terminate()
            fmu.freeInstance()


def gauss_seidel(slaves: Slaves, H: float, stop: float = 10.0, extrapolate: bool = False) -> tuple[float, float]:
    """Gauss-Seidel with Body first: alpha from Gravity at the communication point, held over the
    step (or, with ``extrapolate``, passed on with its first two derivatives from Gravity's output
    derivatives, which get theta's derivatives from Body's). Returns the largest errors of theta
    and omega against Body's exact outputs over the communication points."""
    body, gravity = slaves.body, slaves.gravity
    n = round(stop / H)
    theta, omega = slaves.get(body, VR["theta"], VR["omega"])
    err_theta = err_omega = 0.0
    for k in range(n):
        t = k * H
        slaves.set(gravity, VR["theta"], theta)
        if extrapolate:
            d_theta = body.getRealOutputDerivatives([VR["theta"]] * 2, [1, 2])
            gravity.setRealInputDerivatives([VR["theta"]] * 2, [1, 2], list(d_theta))
        alpha = slaves.get(gravity, VR["alpha"])[0]
        slaves.set(body, VR["alpha"], alpha)
        if extrapolate:
            d_alpha = gravity.getRealOutputDerivatives([VR["alpha"]] * 2, [1, 2])
            body.setRealInputDerivatives([VR["alpha"]] * 2, [1, 2], list(d_alpha))
        body.doStep(currentCommunicationPoint=t, communicationStepSize=H)
        gravity.doStep(currentCommunicationPoint=t, communicationStepSize=H)
        theta, omega, theta_exact, omega_exact = slaves.get(body, VR["theta"], VR["omega"], VR["theta_exact"],
                                                            VR["omega_exact"])
        err_theta = max(err_theta, abs(theta - theta_exact))
        err_omega = max(err_omega, abs(omega - omega_exact))
    return err_theta, err_omega


def run(split_dirs: dict[str, Path], version: str, tmp: Path, H: float,
        extrapolate: bool = False) -> tuple[float, float]:
    slaves = Slaves(split_dirs, version, tmp)
    try:
        return gauss_seidel(slaves, H, extrapolate=extrapolate)
    finally:
        slaves.close()


def test_gauss_seidel_zero_order_hold_converges_with_order_one(split_dirs: dict[str, Path], tmp_path: Path) -> None:
    """H = 2e-3 and 1e-3 over 10 s from 75 deg: the error is about 93 H (theta) and halves with H."""
    coarse = run(split_dirs, "2.0", tmp_path, 2e-3)
    fine = run(split_dirs, "2.0", tmp_path, 1e-3)
    for e_coarse, e_fine in zip(coarse, fine, strict=True):
        assert abs(math.log2(e_coarse / e_fine) - 1.0) < 0.2, (coarse, fine)
    assert 50 * 1e-3 < fine[0] < 150 * 1e-3, fine
    # FMI 3.0 holds the input the same way: the same closed-form steps, the same numbers
    assert run(split_dirs, "3.0", tmp_path, 1e-3) == fine


def test_gauss_seidel_with_derivatives_has_higher_order(split_dirs: dict[str, Path], tmp_path: Path) -> None:
    """FMI 2.0 only: output derivatives passed on as input derivatives (both FMUs interpolate)."""
    coarse = run(split_dirs, "2.0", tmp_path, 2e-2, extrapolate=True)
    fine = run(split_dirs, "2.0", tmp_path, 1e-2, extrapolate=True)
    order = math.log2(coarse[0] / fine[0])
    held = run(split_dirs, "2.0", tmp_path, 1e-2)
    assert order > 2.5, (coarse, fine)
    assert fine[0] < held[0] / 100, (fine, held)


@pytest.mark.parametrize("version", ["2.0", "3.0"])
def test_ssp_package(split_dirs: dict[str, Path], version: str) -> None:
    ssp = split_dirs[version] / "PendulumSplit.ssp"
    ssd = read_ssd(str(ssp))  # validates SystemStructure.ssd against the SSP 1.0 schema
    system = ssd.system
    components = {e.name: e for e in system.elements}
    assert set(components) == {"Body", "Gravity"}
    assert components["Body"].source == "resources/PendulumBody.fmu"
    assert components["Gravity"].source == "resources/PendulumGravity.fmu"
    connections = {(c.startElement, c.startConnector, c.endElement, c.endConnector) for c in system.connections}
    assert connections == {("Body", "theta", "Gravity", "theta"), ("Gravity", "alpha", "Body", "alpha")}
    bound = {name: {p.name: float(p.value) for p in e.parameterBindings[0].parameterValues[0].parameters}
             for name, e in components.items()}
    assert bound == {"Body": {"L": 1.0, "g": 9.81, "theta": THETA0, "omega": 0.0},
                     "Gravity": {"L": 1.0, "g": 9.81, "theta": THETA0}}
    with zipfile.ZipFile(ssp) as zf:
        names = set(zf.namelist())
        assert {"SystemStructure.ssd", "resources/PendulumBody.fmu", "resources/PendulumGravity.fmu"} <= names
        text = zf.read("SystemStructure.ssd").decode()
        assert '<ssd:DefaultExperiment startTime="0" stopTime="10"/>' in text
        for model in MODELS:
            inner = zf.read(f"resources/{model}.fmu")
            assert inner == split_fmu(split_dirs, version, model).read_bytes(), \
                f"{model}.fmu in the SSP is not the built one"


@pytest.mark.parametrize("model", MODELS)
def test_fmi2_and_fmi3_descriptions_agree(split_dirs: dict[str, Path], model: str) -> None:
    """Name, value reference, causality, variability, initial, start and unit of every variable
    (FMI 3.0's `time` aside), and the token: the FMI 3.0 template takes the FMI 2.0 guid."""
    two = read_model_description(str(split_fmu(split_dirs, "2.0", model)))
    three = read_model_description(str(split_fmu(split_dirs, "3.0", model)))

    def table(md: Any) -> dict[str, tuple[Any, ...]]:
        return {v.name: (v.valueReference, v.causality, v.variability, v.initial,
                         None if v.start is None else float(v.start), v.unit)
                for v in md.modelVariables if v.name != "time"}

    assert table(two) == table(three)
    assert two.guid == three.guid
