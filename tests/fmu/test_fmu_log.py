"""The FMU's log: warnings kept per run, routed by instance name, through one logger for the process."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from pendulum_fmu.cli.summary import summary_lines
from pendulum_fmu.fmu import log as fmu_log
from pendulum_fmu.fmu.runner import FmuRunner, Trajectory
from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid
from pendulum_fmu.sweep.grid import SweepPoint
from pendulum_fmu.sweep.worker import row_of


def test_warnings_are_routed_to_their_instance_and_kept_once_in_order() -> None:
    mine, other = fmu_log.FmuLog(), fmu_log.FmuLog()
    fmu_log.register("pendulum_cs_1001", mine)
    fmu_log.register("pendulum_cs_1002", other)
    try:
        for message in (b"hard case: theta0 within 1e-9 of pi", b"hard case: theta0 within 1e-9 of pi", b"second"):
            fmu_log._dispatch(None, b"pendulum_cs_1001", 1, b"logStatusWarning", message)
        fmu_log._dispatch(None, b"pendulum_cs_1001", 0, b"logCalls", b"fmi2DoStep")
        fmu_log._dispatch(None, b"pendulum_cs_1001", 3, b"logStatusError", b"fmi2DoStep: step <= 0")
    finally:
        fmu_log.unregister("pendulum_cs_1001")
        fmu_log.unregister("pendulum_cs_1002")
    assert mine.warnings() == ("hard case: theta0 within 1e-9 of pi", "second")
    assert mine.last_error() == "fmi2DoStep: step <= 0"
    assert other.entries == []


def test_a_run_without_warnings_has_none_and_a_warned_run_says_so(fmu_path: Path) -> None:
    with FmuRunner(fmu_path) as runner:
        run = runner.run(InitialValueProblem.from_degrees(80.0), Method(), TimeGrid(1, "periods"))
    assert run.warnings == ()
    assert not any(line.startswith("warning") for line in summary_lines(run))
    warned = Trajectory(run.problem, run.method, run.grid, run.period, run.result, run.steps, run.rejected_steps,
                        run.rhs_evaluations, run.wall_time, ("hard case: near the top",))
    assert summary_lines(warned)[-1] == "warning   the FMU: hard case: near the top"
    point = SweepPoint(80.0, 0.0, 1.0, 9.81, "rkn", 1e-8, 1.0, 50)
    assert row_of(point, warned)["fmu_warning"] == "hard case: near the top"
    assert row_of(point, run)["fmu_warning"] == ""
    assert math.isfinite(run.max_error) and np.all(np.isfinite(run.result["theta"]))


def test_a_run_keeps_its_warnings_after_fmpy_took_the_logging_proxy(fmu_path: Path) -> None:
    """fmpy formats FMI 2.0 messages in one native proxy with one target for the process; a
    ``simulate_fmu(logger=...)`` call points it at that call's logger. A runner's later run
    must still receive its warnings (the creep over the top warns at every solver)."""
    from fmpy import simulate_fmu

    elsewhere: list[object] = []
    with FmuRunner(fmu_path) as runner:  # the package's callbacks exist before fmpy's call
        runner.run(InitialValueProblem.from_degrees(80.0), Method(), TimeGrid(1, "periods"))
        simulate_fmu(str(fmu_path), stop_time=0.1, logger=lambda *message: elsewhere.append(message))
        run = runner.run(InitialValueProblem(math.pi, 1e-15), Method("rkn", 1e-8), TimeGrid(1, "periods"))
    assert any(w.startswith("certificate:") or "hard case:" in w for w in run.warnings), run.warnings
