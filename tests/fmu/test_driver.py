"""The C output loop (``pendulum_driver``, :mod:`pendulum_fmu.fmu.driver`) behind every run.

- Results bit for bit those of its Python port (:mod:`pendulum_fmu.fmu.python_drive`, the loop
  where the C library is missing), FMI 2.0 and 3.0, for every Co-Simulation solver, on a
  libration, a rotation and the hard case; the port stops where the C loop stops.
- Every status checked: a DoStep at the wrong time and a GetReal of an unknown value
  reference stop the loop with the call, the time, the status and the FMU's logged reason.
- The FMU's warnings still arrive while the loop runs in C (FMI 2.0 and 3.0).
- Ctrl-C (SIGINT) stops a long run after the stretch that was running; the run's finished
  points are handed back, equal to the same points of an uninterrupted run. The command line
  prints one line and exits 130.
"""

from __future__ import annotations

import math
import os
import signal
import subprocess
import sys
import threading
from pathlib import Path

import numpy as np
import pytest

from pendulum_fmu.errors import SimulationError
from pendulum_fmu.fmu import driver
from pendulum_fmu.fmu.runner import RECORDED, RESULT_DTYPE, FmuRunner, RunInterrupted
from pendulum_fmu.spec import CS_SOLVERS, InitialValueProblem, Method, TimeGrid

HARD_CASE = InitialValueProblem(math.pi, 1e-15)   # a rotation the solvers reverse at the top (test_hard_case_warning)
CASES = [InitialValueProblem.from_degrees(80.0), InitialValueProblem(0.5, 9.0),
         InitialValueProblem.from_degrees(179.0, 0.3)]


def test_the_c_loop_is_built_and_used(fmu_path: Path) -> None:
    assert driver.library_path() is not None and driver.available()
    with FmuRunner(fmu_path) as runner:
        assert runner.loop == "c"


@pytest.mark.parametrize("solver", CS_SOLVERS)
def test_c_loop_is_bit_identical_to_the_python_loop(fmu_path: Path, solver: str) -> None:
    grid = TimeGrid(3, "periods", 37)
    with FmuRunner(fmu_path, loop="c") as c_runner, FmuRunner(fmu_path, loop="python") as python_runner:
        for pendulum in CASES:
            method = Method(solver, 1e-7)
            ours, before = c_runner.run(pendulum, method, grid), python_runner.run(pendulum, method, grid)
            assert ours.result.tobytes() == before.result.tobytes(), (solver, pendulum)
            assert (ours.steps, ours.rejected_steps, ours.rhs_evaluations) == \
                   (before.steps, before.rejected_steps, before.rhs_evaluations)
            assert ours.max_error < 1e-3   # and the run is a solution, not just equal garbage
            np.testing.assert_array_equal(ours.result["time"], grid.times(ours.period))


def test_fmi3_c_loop_is_bit_identical_to_the_python_loop(fmu3_path: Path) -> None:
    grid = TimeGrid(2, "periods", 25)
    method = Method("rkn", 1e-8)
    with FmuRunner(fmu3_path, loop="c") as c_runner, FmuRunner(fmu3_path, loop="python") as python_runner:
        assert c_runner.fmi_version == 3
        for pendulum in CASES:
            ours, in_python = c_runner.run(pendulum, method, grid), python_runner.run(pendulum, method, grid)
            assert ours.result.tobytes() == in_python.result.tobytes()
            assert ours.steps == in_python.steps > 0


def test_fmi2_and_fmi3_give_the_same_numbers(fmu_path: Path, fmu3_path: Path) -> None:
    """One model core behind both FMI layers: the same run, bit for bit, through either FMU."""
    grid = TimeGrid(2, "periods", 25)
    with FmuRunner(fmu_path) as two, FmuRunner(fmu3_path) as three:
        for method in (Method("rkn", 1e-9), Method("dopri5", 1e-6)):
            a, b = two.run(CASES[0], method, grid), three.run(CASES[0], method, grid)
            assert a.result.tobytes() == b.result.tobytes() and a.period == b.period


def _initialized(runner: FmuRunner, pendulum: InitialValueProblem) -> object:
    return runner.initialized(pendulum, Method("rkn", 1e-8))


@pytest.mark.parametrize("fixture", ["fmu_path", "fmu3_path"])
def test_a_loop_of_ones_own_on_the_initialized_instance_gives_the_runs_numbers(
        fixture: str, request: pytest.FixtureRequest) -> None:
    """FmuRunner.initialized hands out the instance run() uses, initialized alike: a caller's own
    loop over it gives run()'s outputs bit for bit, and the FMU's warnings reach runner.log."""
    fmu: Path = request.getfixturevalue(fixture)
    with FmuRunner(fmu, loop="c") as runner:
        method = Method("rkn", 1e-8)
        for pendulum, grid in ((CASES[1], TimeGrid(3, "periods", 40)), (HARD_CASE, TimeGrid(120.0, "s", 10))):
            trajectory = runner.run(pendulum, method, grid)
            slave = runner.initialized(pendulum, method)
            loop = driver.OutputLoop(slave, runner.fmi_version, [runner.vr[name] for name in RECORDED])
            rows = np.empty(trajectory.result.size, dtype=RESULT_DTYPE)
            rows["time"] = trajectory.result["time"]
            loop.run(rows["time"], rows, RECORDED[0], runner.log)
            slave.terminate()
            assert rows.tobytes() == trajectory.result.tobytes()
            assert runner.log.warnings() == trajectory.warnings
        assert trajectory.warnings   # the hard case warned, through the caller's loop too
        with pytest.raises(ValueError, match="not a Co-Simulation solver"):
            runner.initialized(CASES[0], Method("cvode", 1e-8))


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("fixture", ["fmu_path", "fmu3_path"])
def test_a_failing_do_step_stops_the_loop_with_its_reason(fixture: str, request: pytest.FixtureRequest,
                                                          backend: driver.Backend) -> None:
    fmu: Path = request.getfixturevalue(fixture)
    with FmuRunner(fmu, loop="c") as runner:
        slave = _initialized(runner, CASES[0])
        loop = driver.OutputLoop(slave, runner.fmi_version, [runner.vr[name] for name in RECORDED], backend)
        rows = np.zeros(3, dtype=RESULT_DTYPE)
        loop.run(np.array([0.0, 0.1, 0.2]), rows, "theta", runner.log)
        assert np.all(rows["theta"] != 0.0) and np.all(rows["y"] != 0.0)
        # The FMU stands at 0.2; a DoStep announced from 0.3 breaks the standard's rule that
        # currentCommunicationPoint is the FMU's time (FMI 2.0.x 4.2.2, FMI 3.0 4.2.1).
        later = np.zeros(2, dtype=RESULT_DTYPE)
        with pytest.raises(SimulationError, match=r"^DoStep at t = 0\.3 s returned (Error|Discard): \S"):
            loop.run(np.array([0.3, 0.4]), later, "theta", runner.log)
        assert later["theta"][1] == 0.0   # the failed point is not written


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("fixture", ["fmu_path", "fmu3_path"])
def test_a_failing_get_stops_the_loop_at_its_point(fixture: str, request: pytest.FixtureRequest,
                                                   backend: driver.Backend) -> None:
    fmu: Path = request.getfixturevalue(fixture)
    with FmuRunner(fmu, loop="c") as runner:
        slave = _initialized(runner, CASES[0])
        loop = driver.OutputLoop(slave, runner.fmi_version, [runner.vr["theta"], 999], backend)
        rows = np.zeros(4, dtype=[("theta", np.float64), ("bad", np.float64)])
        with pytest.raises(SimulationError, match=r"^GetReal at t = 0 s returned Error: .+"):
            loop.run(np.array([0.0, 0.1, 0.2, 0.3]), rows, "theta", runner.log)


def test_the_loop_checks_the_layout_it_writes_into(fmu_path: Path) -> None:
    with FmuRunner(fmu_path, loop="c") as runner:
        slave = _initialized(runner, CASES[0])
        loop = driver.OutputLoop(slave, 2, [runner.vr["theta"], runner.vr["omega"]])
        gap = np.zeros(3, dtype=[("theta", np.float64), ("n", np.int64), ("omega", np.float64)])
        with pytest.raises(ValueError, match="not the float64 right after"):
            loop.run(np.array([0.0, 0.1, 0.2]), gap, "theta", runner.log)
        with pytest.raises(ValueError, match="one record per time"):
            loop.run(np.array([0.0, 0.1, 0.2]), np.zeros(2, dtype=RESULT_DTYPE), "theta", runner.log)


@pytest.mark.parametrize("fixture", ["fmu_path", "fmu3_path"])
def test_warnings_arrive_through_the_c_loop(fixture: str, request: pytest.FixtureRequest) -> None:
    fmu: Path = request.getfixturevalue(fixture)
    with FmuRunner(fmu, loop="c") as c_runner, FmuRunner(fmu, loop="python") as python_runner:
        method, grid = Method("rkn", 1e-8), TimeGrid(120.0, "s", 10)
        ours, before = c_runner.run(HARD_CASE, method, grid), python_runner.run(HARD_CASE, method, grid)
        assert ours.warnings == before.warnings
        kinds = [w.split(":")[0] for w in ours.warnings]
        assert kinds[0] == "certificate" and "hard case" in kinds and set(kinds) == {"certificate", "hard case"}
        assert c_runner.run(CASES[0], method, TimeGrid(1, "periods", 10)).warnings == ()


def _interrupt_after(seconds: float) -> threading.Timer:
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_ctrl_c_returns_the_finished_points(fmu_path: Path) -> None:
    if signal.getsignal(signal.SIGINT) is not signal.default_int_handler:
        signal.signal(signal.SIGINT, signal.default_int_handler)   # pytest run with SIGINT ignored
    grid = TimeGrid(100_000, "periods", 4)   # 4e5 points, dopri5 at 1e-12: about 10 s uninterrupted
    method = Method("dopri5", 1e-12)
    with FmuRunner(fmu_path) as runner:
        timer = _interrupt_after(0.5)
        with pytest.raises(RunInterrupted) as stop:
            runner.run(CASES[0], method, grid)
        timer.join()
        part = stop.value.trajectory.result
        assert 0 < part.size < 400_001
        assert signal.getsignal(signal.SIGINT) is signal.default_int_handler   # handler restored
        # The finished points are those of an uninterrupted run, bit for bit.
        whole = runner.run(CASES[0], method, TimeGrid(float(part["time"][-1] + 1.0), "s", 50,
                                                      output_interval=float(part["time"][1])))
        assert whole.result[:part.size].tobytes() == part.tobytes()


def test_cli_ctrl_c_is_one_line_and_exit_130(fmu_path: Path, tmp_path: Path) -> None:
    env = dict(os.environ, PENDULUM_FMU=str(fmu_path.resolve()))
    script = ("import signal, sys; signal.signal(signal.SIGINT, signal.default_int_handler); "
              "from pendulum_fmu.cli.main import main; sys.exit(main(sys.argv[1:]))")
    argv = ["simulate", "-p", "1e5", "-n", "4", "-s", "dopri5", "-t", "1e-12", "-o", "x.csv"]   # about 10 s
    process = subprocess.Popen([sys.executable, "-c", script, *argv], cwd=tmp_path, env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        process.wait(timeout=2.0)
    except subprocess.TimeoutExpired:
        process.send_signal(signal.SIGINT)
    out, err = process.communicate(timeout=60)
    assert process.returncode == 130, err
    assert err.strip().splitlines() == ["pendulum-fmu simulate: interrupted"], err
    assert "Traceback" not in err and not (tmp_path / "x.csv").exists()


# --- the C loop against a scripted stand-in FMU: every branch of its status handling ------------

class _ScriptedFmu:
    """DoStep / GetReal (FMI 2.0) or DoStep / GetFloat64 (FMI 3.0) as ctypes callbacks that
    answer from a script: DoStep number k returns ``statuses[k]`` (and, in 3.0, the flags)."""

    def __init__(self, version: int, statuses: list[int], terminate_at: int = -1, early_at: int = -1) -> None:
        import ctypes

        self.calls: list[tuple[float, float]] = []
        self.component = ctypes.c_void_p(1234)

        def do_step2(_c, t, h, _no_set):  # type: ignore[no-untyped-def]
            self.calls.append((t, h))
            return statuses[len(self.calls) - 1]

        def do_step3(_c, t, h, _no_set, _event, terminate, early, reached):  # type: ignore[no-untyped-def]
            self.calls.append((t, h))
            k = len(self.calls) - 1
            terminate[0] = k == terminate_at
            early[0] = k == early_at
            reached[0] = t + h / 2
            return statuses[k]

        def get(_c, _vrs, nvr, values, *_):  # type: ignore[no-untyped-def]
            for i in range(nvr):
                values[i] = float(len(self.calls) * 10 + i)
            return 0

        pointer = ctypes.POINTER
        if version == 2:
            step_type = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_int)
            get_type = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t,
                                        pointer(ctypes.c_double))
            self.step, self.get = step_type(do_step2), get_type(get)
            names = ("fmi2DoStep", "fmi2GetReal")
        else:
            step_type = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_bool,
                                         pointer(ctypes.c_bool), pointer(ctypes.c_bool), pointer(ctypes.c_bool),
                                         pointer(ctypes.c_double))
            get_type = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t,
                                        pointer(ctypes.c_double), ctypes.c_size_t)
            self.step, self.get = step_type(do_step3), get_type(get)
            names = ("fmi3DoStep", "fmi3GetFloat64")
        self.dll = type("Dll", (), {names[0]: self.step, names[1]: self.get})()


@pytest.mark.parametrize("backend", ["c", "python"])
@pytest.mark.parametrize("version", [2, 3])
def test_warnings_go_on_and_worse_statuses_stop_the_loop(version: int, backend: driver.Backend) -> None:
    from pendulum_fmu.fmu.log import FmuLog

    times = np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0])
    rows = np.zeros(6, dtype=[("a", np.float64), ("b", np.float64)])
    fmu = _ScriptedFmu(version, [1, 0, 1, 2, 0])   # Warning, OK, Warning, then Discard
    log = FmuLog()
    log.entries.append((3, "logStatusError", "step rejected: the reason"))
    with pytest.raises(SimulationError, match=r"^DoStep at t = 3 s returned Discard: step rejected: the reason$"):
        driver.OutputLoop(fmu, version, [7, 8], backend).run(times, rows, "a", log)
    assert fmu.calls == [(0.0, 1.0), (1.0, 1.0), (2.0, 1.0), (3.0, 1.0)]
    assert rows["a"].tolist() == [0.0, 10.0, 20.0, 30.0, 0.0, 0.0] and rows["b"][3] == 31.0
    for status, name in ((3, "Error"), (4, "Fatal")):
        fmu = _ScriptedFmu(version, [status])
        with pytest.raises(SimulationError, match=rf"^DoStep at t = 0 s returned {name}$"):
            driver.OutputLoop(fmu, version, [7], backend).run(times, np.zeros(6, dtype=[("a", np.float64)]), "a",
                                                              FmuLog())


@pytest.mark.parametrize("backend", ["c", "python"])
def test_fmi3_terminate_and_early_return_stop_the_loop(backend: driver.Backend) -> None:
    from pendulum_fmu.fmu.log import FmuLog

    times = np.array([0.0, 1.0, 2.0, 3.0])
    rows = np.zeros(4, dtype=[("a", np.float64)])
    # each stand-in named while its loop runs: the loop keeps only its callbacks' addresses, and a
    # stand-in left to the garbage collector would free them under the running loop
    terminating = _ScriptedFmu(3, [0, 0, 0], terminate_at=1)
    with pytest.raises(SimulationError, match=r"^fmi3DoStep asked to terminate the simulation at t = 1\.5 s$"):
        driver.OutputLoop(terminating, 3, [1], backend).run(times, rows, "a", FmuLog())
    returning = _ScriptedFmu(3, [0, 0, 0], early_at=0)
    with pytest.raises(SimulationError, match=r"^fmi3DoStep returned early at t = 0\.5 s"):
        driver.OutputLoop(returning, 3, [1], backend).run(times, rows, "a", FmuLog())
