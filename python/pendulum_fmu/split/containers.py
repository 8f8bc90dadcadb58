"""The split pendulum as one container FMU: fmpy's ``container_fmu`` and the FMU Manipulation
Toolbox's ``fmucontainer``; each container is then run by fmpy's ``simulate_fmu`` at the macro step.

A container is a master compiled into an FMU: it steps the inner FMUs at its own fixed step
and moves the connected values between them. The container exposes Body's outputs and
Gravity's alpha, named as :data:`pendulum_fmu.split.columns.COLUMNS` say.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
import uuid
from collections.abc import Callable
from pathlib import Path

from pendulum_fmu.fmu.log import route_fmi2_messages
from pendulum_fmu.split.columns import COLUMNS, EngineError, write_columns
from pendulum_fmu.split.locate import split_fmus


def _simulate(container: Path, H: float, stop: float, out: Path, names: dict[str, str]) -> Path:
    """Run ``container`` with fmpy at output interval H; write its outputs under our names."""
    from fmpy import simulate_fmu

    messages: list[str] = []

    def collect(*arguments: object) -> None:
        text = arguments[-1]
        messages.append(text.decode(errors="replace") if isinstance(text, bytes) else str(text))

    try:
        rows = simulate_fmu(str(container), start_time=0.0, stop_time=stop, step_size=H, output_interval=H,
                            output=list(names.values()), logger=collect)
    except Exception as error:  # the engine's own words: its last logged message
        told = f" ({messages[-1].strip()})" if messages else ""
        raise EngineError(f"{container.name} in fmpy: {error}{told}") from error
    finally:
        # the call's logger is freed with it: fmpy's one FMI 2.0 logging proxy must not point there
        route_fmi2_messages()
    write_columns(out, list(rows["time"]), {ours: list(rows[theirs]) for ours, theirs in names.items()})
    return out


def build_fmpy_container(H: float, fmi_version: int, target: Path) -> Path:
    """Body and Gravity in fmpy's container FMU (an FMI 3.0 FMU whatever the inner FMUs' version),
    stepped in sequence (``parallelDoStep`` false) at fixed step ``H``."""
    from fmpy import read_model_description
    from fmpy.container_fmu.cli import create_container_fmu
    from fmpy.container_fmu.config import Component, Configuration, Connection
    from fmpy.model_description import CoSimulation, DefaultExperiment, ModelDescription, ModelVariable

    components = []
    for name, path in zip(("Body", "Gravity"), split_fmus(fmi_version), strict=True):
        components.append(Component(name=name, filename=path, modelDescription=read_model_description(str(path))))
    body, gravity = components

    def variable(component: Component, name: str) -> ModelVariable:
        return next(v for v in component.modelDescription.modelVariables if v.name == name)

    exposed: dict[ModelVariable, list[tuple[Component, ModelVariable]]] = {}
    variables = [ModelVariable(name="time", valueReference=0, type="Float64", causality="independent",
                               variability="continuous")]
    for column in COLUMNS:
        instance, name = column.split(".")
        component = body if instance == "Body" else gravity
        outer = ModelVariable(name=column, valueReference=len(variables), type="Float64", causality="output",
                              variability="continuous")
        variables.append(outer)
        exposed[outer] = [(component, variable(component, name))]
    description = ModelDescription(fmiVersion="3.0", modelName="PendulumSplitContainer",
                                   instantiationToken="{" + str(uuid.uuid4()) + "}",
                                   coSimulation=CoSimulation(modelIdentifier="container_fmu", fixedInternalStepSize=H),
                                   defaultExperiment=DefaultExperiment(startTime="0", stopTime="10", stepSize=str(H)))
    description.modelVariables = variables
    connections = [Connection(startElement=body, startConnectors=[variable(body, "theta")], endElement=gravity,
                              endConnectors=[variable(gravity, "theta")]),
                   Connection(startElement=gravity, startConnectors=[variable(gravity, "alpha")], endElement=body,
                              endConnectors=[variable(body, "alpha")])]
    config = Configuration(parallelDoStep=False, modelDescription=description, components=components,
                           connections=connections, variableMappings=exposed)
    scratch = Path(tempfile.mkdtemp(prefix="pendulum-container-"))
    try:
        create_container_fmu(config, scratch, target)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return target


def run_fmpy_container(H: float, stop: float, out: Path, fmi_version: int = 2) -> Path:
    """fmpy's container FMU of Body and Gravity at step H, run by fmpy."""
    container = out.with_suffix(".fmu")
    try:
        build_fmpy_container(H, fmi_version, container)
        return _simulate(container, H, stop, out, {c: c for c in COLUMNS})
    except EngineError as error:
        raise EngineError(f"fmpy container_fmu: {error}") from error
    except Exception as error:  # the engine's own error, told as it is
        raise EngineError(f"fmpy container_fmu: {type(error).__name__}: {error}") from error


def _fmucontainer_rules(folder: Path, fmi_version: int) -> Path:
    body, gravity = split_fmus(fmi_version)
    for path in (body, gravity):
        shutil.copy(path, folder / path.name)
    rules = folder / "PendulumSplitContainer.csv"
    lines = ["rule;from_fmu;from_port;to_fmu;to_port",
             f"LINK;{body.name};theta;{gravity.name};theta",
             f"LINK;{gravity.name};alpha;{body.name};alpha"]
    for column in COLUMNS:
        instance, name = column.split(".")
        lines.append(f"OUTPUT;{(body if instance == 'Body' else gravity).name};{name};;{instance}_{name}")
    rules.write_text("\n".join(lines) + "\n")
    return rules


def run_fmucontainer(H: float, stop: float, out: Path, fmi_version: int = 2) -> Path:
    """The FMU Manipulation Toolbox's ``fmucontainer`` of Body and Gravity at step H, run by fmpy."""
    tool = Path(sys.executable).parent / "fmucontainer"
    if not tool.exists():
        tool = Path(shutil.which("fmucontainer") or "fmucontainer")
    folder = Path(tempfile.mkdtemp(prefix="pendulum-fmucontainer-"))
    try:
        rules = _fmucontainer_rules(folder, fmi_version)
        command = [str(tool), "-fmu-directory", str(folder), "-container", f"{rules.name}:{H!r}"]
        if fmi_version == 3:
            command.append("-fmi")
            command.append("3")
        done = subprocess.run(command, capture_output=True, text=True, timeout=300, check=False, cwd=folder)
        built = folder / "PendulumSplitContainer.fmu"
        if done.returncode != 0 or not built.exists():
            lines = [line for line in (done.stdout + done.stderr).splitlines() if "ERROR" in line.upper()]
            last = (lines or (done.stdout + done.stderr).splitlines() or ["no output"])[-1]
            raise EngineError(f"fmucontainer: {last}")
        return _simulate(built, H, stop, out, {c: c.replace(".", "_") for c in COLUMNS})
    finally:
        shutil.rmtree(folder, ignore_errors=True)


CONTAINERS: dict[str, Callable[[float, float, Path, int], Path]] = {
    "fmpy-container": run_fmpy_container, "fmucontainer": run_fmucontainer}
