"""``Pendulum.fmu`` inside a container FMU, the container run by fmpy: the FMU Manipulation
Toolbox's ``fmucontainer`` and fmpy's ``container_fmu``. A container is a Co-Simulation FMU that
steps its inner FMU at a fixed step, so it runs the Co-Simulation cases only; the start values
go in as the container's own (``START`` rules; container parameters mapped onto the inner
variables)."""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
import uuid
from collections.abc import Callable
from pathlib import Path
from typing import Any

from pendulum_fmu.suite.experiment import OUTPUTS, CannotRun, write_csv


def _cannot(message: str) -> CannotRun:
    return CannotRun(message)


def _simulate(container: Path, e: dict[str, Any], start_values: dict[str, float], names: dict[str, str]) -> None:
    from fmpy import simulate_fmu

    messages: list[str] = []

    def collect(*arguments: object) -> None:
        text = arguments[-1]
        messages.append(text.decode(errors="replace") if isinstance(text, bytes) else str(text))

    try:
        rows = simulate_fmu(str(container), start_time=e["start"], stop_time=e["stop"],
                            relative_tolerance=e["tolerance"], step_size=e["interval"], output_interval=e["interval"],
                            start_values=start_values, output=list(names.values()), logger=collect)
    except Exception as error:  # noqa: BLE001 (the engine's own words: its last logged message)
        told = f" ({messages[-1].strip()})" if messages else ""
        raise _cannot(f"{container.name} in fmpy: {error}{told}") from None
    write_csv(Path(e["output"]), list(rows["time"]), {ours: list(rows[theirs]) for ours, theirs in names.items()})


def _fmucontainer(e: dict[str, Any]) -> None:
    if e["interface"] != "cs":
        raise _cannot("a container FMU is Co-Simulation: no Model Exchange")
    tool = Path(sys.executable).parent / "fmucontainer"
    if not tool.exists():
        tool = Path(shutil.which("fmucontainer") or "fmucontainer")
    folder = Path(tempfile.mkdtemp(prefix="pendulum-suite-fmucontainer-"))
    try:
        inner = folder / "Pendulum.fmu"
        shutil.copy(e["fmu"], inner)
        lines = ["rule;from_fmu;from_port;to_fmu;to_port"]
        lines += [f"START;{inner.name};{name};{value!r};" for name, value in e["start_values"].items()]
        lines += [f"OUTPUT;{inner.name};{name};;{name}" for name in OUTPUTS]
        (folder / "PendulumContainer.csv").write_text("\n".join(lines) + "\n")
        command = [str(tool), "-fmu-directory", str(folder), "-container", f"PendulumContainer.csv:{e['interval']!r}"]
        if e["fmi_version"] == "3.0":
            command += ["-fmi", "3"]
        done = subprocess.run(command, capture_output=True, text=True, timeout=300, check=False, cwd=folder)
        built = folder / "PendulumContainer.fmu"
        if done.returncode != 0 or not built.exists():
            said = (done.stdout + done.stderr).splitlines()
            errors = [line for line in said if "ERROR" in line.upper()]
            raise _cannot(f"fmucontainer: {(errors or said or ['no output'])[-1].strip()}")
        _simulate(built, e, {}, {name: name for name in OUTPUTS})
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _fmpy_container(e: dict[str, Any]) -> None:
    if e["interface"] != "cs":
        raise _cannot("a container FMU is Co-Simulation: no Model Exchange")
    from fmpy import read_model_description
    from fmpy.container_fmu.cli import create_container_fmu
    from fmpy.container_fmu.config import Component, Configuration
    from fmpy.model_description import CoSimulation, DefaultExperiment, ModelDescription, ModelVariable

    inner = Component(name="Pendulum", filename=Path(e["fmu"]),
                      modelDescription=read_model_description(e["fmu"]))
    by_name = {v.name: v for v in inner.modelDescription.modelVariables}
    variables = [ModelVariable(name="time", valueReference=0, type="Float64", causality="independent",
                               variability="continuous")]
    mappings: dict[Any, list[tuple[Any, Any]]] = {}
    for name, value in e["start_values"].items():  # parameters of the container, set into the inner FMU
        outer = ModelVariable(name=f"start_{name}", valueReference=len(variables), type="Float64",
                              causality="parameter", variability="fixed", initial="exact", start=repr(value))
        variables.append(outer)
        mappings[outer] = [(inner, by_name[name])]
    for name in OUTPUTS:
        outer = ModelVariable(name=name, valueReference=len(variables), type="Float64", causality="output",
                              variability="continuous")
        variables.append(outer)
        mappings[outer] = [(inner, by_name[name])]
    description = ModelDescription(fmiVersion="3.0", modelName="PendulumContainer",
                                   instantiationToken="{" + str(uuid.uuid4()) + "}",
                                   coSimulation=CoSimulation(modelIdentifier="container_fmu",
                                                             fixedInternalStepSize=e["interval"]),
                                   defaultExperiment=DefaultExperiment(startTime=repr(e["start"]),
                                                                       stopTime=repr(e["stop"]),
                                                                       stepSize=repr(e["interval"])))
    description.modelVariables = variables
    config = Configuration(parallelDoStep=False, modelDescription=description, components=[inner], connections=[],
                           variableMappings=mappings)
    scratch = Path(tempfile.mkdtemp(prefix="pendulum-suite-container-"))
    target = Path(e["output"]).with_suffix(".fmu")
    try:
        create_container_fmu(config, scratch, target)
    except Exception as error:  # noqa: BLE001 (the engine's own error, told as it is)
        raise _cannot(f"fmpy container_fmu: {type(error).__name__}: {error}") from None
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    try:
        _simulate(target, e, {}, {name: name for name in OUTPUTS})
    finally:
        target.unlink(missing_ok=True)


CONTAINERS: dict[str, Callable[[dict[str, Any]], None]] = {"fmucontainer": _fmucontainer,
                                                           "fmpy-container": _fmpy_container}
