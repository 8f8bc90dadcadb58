"""Run one case in one engine, in a process of its own: ``python -m pendulum_fmu.suite.engine_child
ENGINE EXPERIMENT.json``. The runner starts it, so a crash, an abort or a hang of the engine ends
that process only (libcosim aborts its process on an FMU error and segfaults on an FMI 3.0
FMU; docs/suite.md). Writes the experiment's ``output`` CSV; exits 3 with one line on stderr when the
engine cannot run the case."""

from __future__ import annotations

import json
import math
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from pendulum_fmu.suite.experiment import OUTPUTS, CannotRun, write_csv

VALUE_REFERENCES = {"L": 1, "g": 2, "theta": 3, "omega": 5, "theta_exact": 7, "omega_exact": 8}
"""Pendulum.fmu's FMI 2.0 value references (modelDescription.xml), for libcosim."""
SPLIT_ENGINES = {"fmpy": "fmpy-ssp", "libcosim": "libcosim", "ecos": "ecos", "fmpy-container": "fmpy-container",
                 "fmucontainer": "fmucontainer"}
"""The split pendulum's engine (:mod:`pendulum_fmu.split.engines`) behind each adapter name."""


def _fmpy(e: dict[str, Any]) -> None:
    from fmpy import simulate_fmu

    me = e["interface"] == "me"
    rows = simulate_fmu(e["fmu"], start_time=e["start"], stop_time=e["stop"], relative_tolerance=e["tolerance"],
                        output_interval=e["interval"], step_size=None if me else e["interval"],
                        start_values=e["start_values"], fmi_type="ModelExchange" if me else "CoSimulation",
                        solver="CVode", output=list(OUTPUTS))
    write_csv(Path(e["output"]), list(rows["time"]), {n: list(rows[n]) for n in OUTPUTS})


def _libcosim(e: dict[str, Any]) -> None:
    if e["interface"] != "cs":
        raise CannotRun("libcosim is a co-simulation master: no Model Exchange")
    if e["start"] != 0:
        raise CannotRun("libcosimpy 0.0.6 has no start time (CosimExecution.from_step_size starts at 0)")
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimSlave import CosimLocalSlave

    log_output_level(CosimLogLevel.ERROR)
    nanoseconds = round(e["interval"] * 1e9)
    steps = math.ceil(e["stop"] / e["interval"] - 1e-9)
    execution = CosimExecution.from_step_size(nanoseconds)
    index = execution.add_local_slave(CosimLocalSlave(fmu_path=e["fmu"], instance_name="Pendulum"))
    series = CosimObserver.create_time_series(buffer_size=steps + 10)
    execution.add_observer(series)
    for name, value in e["start_values"].items():
        execution.real_initial_value(index, VALUE_REFERENCES[name], value)
    for name in OUTPUTS:
        series.start_time_series(index, VALUE_REFERENCES[name], CosimVariableType.REAL)
    if not execution.simulate_until(steps * nanoseconds):
        raise CannotRun("libcosim: simulate_until returned false")
    columns: dict[str, list[float]] = {}
    times: list[float] = []
    for name in OUTPUTS:  # from step 1: libcosimpy 0.0.6 drops the last sample when read from step 0
        sampled, _, values = series.time_series_real_samples(index, VALUE_REFERENCES[name], from_step=1,
                                                             sample_count=steps)
        columns[name], times = list(values), [t * 1e-9 for t in sampled]
    write_csv(Path(e["output"]), times, columns)


def _ecos(e: dict[str, Any]) -> None:
    if e["interface"] != "cs":
        raise CannotRun("Ecos is a co-simulation master: no Model Exchange")
    from ecospy import EcosSimulation, EcosSimulationStructure

    structure = EcosSimulationStructure()
    structure.add_model("Pendulum", e["fmu"])
    structure.add_parameter_set("start", {f"Pendulum::{n}": v for n, v in e["start_values"].items()})
    simulation = EcosSimulation(structure=structure, step_size=e["interval"])
    if not simulation.init(start_time=e["start"], parameter_set="start"):
        raise CannotRun("Ecos: init() returned false")
    steps = math.ceil((e["stop"] - e["start"]) / e["interval"] - 1e-9)
    times = [simulation.get_time()]
    columns = {n: [simulation.get_real(f"Pendulum::{n}")] for n in OUTPUTS}
    for _ in range(steps):
        simulation.step(1)
        times.append(simulation.get_time())
        for n in OUTPUTS:
            columns[n].append(simulation.get_real(f"Pendulum::{n}"))
    simulation.terminate()
    write_csv(Path(e["output"]), times, columns)


def _split(engine: str, e: dict[str, Any]) -> None:
    from pendulum_fmu.split.columns import EngineError
    from pendulum_fmu.split.engines import run_engine

    try:
        run_engine(SPLIT_ENGINES[engine], e["interval"], e["stop"], Path(e["output"]), int(e["fmi_version"][0]))
    except EngineError as error:
        raise CannotRun(str(error)) from None


ENGINES: dict[str, Callable[[dict[str, Any]], None]] = {"fmpy": _fmpy, "libcosim": _libcosim, "ecos": _ecos}
"""The engines that run ``Pendulum.fmu`` in this process; the containers are in
:mod:`pendulum_fmu.suite.container_child`."""


def main(argv: list[str]) -> int:
    """``ENGINE EXPERIMENT.json``: run, write the output; 3 and one line when the engine cannot."""
    engine, experiment = argv[0], json.loads(Path(argv[1]).read_text())
    try:
        if experiment["kind"] == "split":
            _split(engine, experiment)
        else:
            from pendulum_fmu.suite.container_child import CONTAINERS

            runner = {**ENGINES, **CONTAINERS}.get(engine)
            if runner is None:
                raise CannotRun(f"no engine {engine!r}")
            runner(experiment)
    except CannotRun as error:
        print(f"cannot run: {error}", file=sys.stderr)
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
