"""PendulumSplit.ssp (or its two FMUs) in every co-simulation engine that installs here, judged.

Each engine runs the split pendulum at H = 0.02, 0.01 and 0.005 s for 2 s and writes a CSV
(pendulum_fmu.split.engines); the judge (pendulum_fmu.split.judge) names the master each engine
is, or its defects; halving H halves every engine's error (order 1 within 0.2: they all hold
their inputs), so each converges to the exact pendulum. Where an engine cannot run the system,
the test holds the engine's own error (docs/masters.md lists them).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from pendulum_fmu.split.engines import EngineError, missing, run_engine
from pendulum_fmu.split.judge import judge_split
from pendulum_fmu.split.masters import observed_orders

pytestmark = pytest.mark.engines

STEPS = (0.02, 0.01, 0.005)
STOP = 2.0
BEHAVES = {
    ("fmpy-ssp", 2): None,  # rows one step early, Gravity's input started at 0
    ("libcosim", 2): "jacobi-zoh",
    ("ecos", 2): "jacobi-zoh",
    ("ecos", 3): "jacobi-zoh",
    ("fmucontainer", 2): "jacobi-zoh",
    ("fmucontainer", 3): "jacobi-zoh",
    ("fmpy-container", 3): "gauss-seidel-zoh",
}
CANNOT = {
    ("fmpy-ssp", 3): "Cannot find shared library",  # fmpy.ssp loads binaries/linux64: FMI 2.0 only
    ("libcosim", 3): "runs FMI 2.0 only",  # libcosim 0.0.6 segfaults on an FMI 3.0 FMU: not started
    ("fmpy-container", 2): "unknown variant `Real`",  # fmpy writes FMI 2.0 connections as 'Real'
}


def _skip_unless_installed(engine: str) -> None:
    reason = missing(engine)
    if reason is not None:
        pytest.skip(reason)


@pytest.mark.parametrize(("engine", "version"), sorted(BEHAVES), ids=lambda v: str(v))
def test_engine_runs_is_judged_and_converges(engine: str, version: int, tmp_path: Path) -> None:
    _skip_unless_installed(engine)
    verdicts = []
    for H in STEPS:
        run = run_engine(engine, H, STOP, tmp_path / f"{engine}-{H}.csv", version)
        verdicts.append(judge_split(run.csv))
    expected = BEHAVES[(engine, version)]
    for verdict in verdicts:
        assert verdict.master == expected, verdict.lines
        if expected is None:
            assert [f.kind for f in verdict.findings] == ["labels", "start-dropped"], verdict.lines
            assert not verdict.passed
        else:
            assert verdict.passed and not verdict.findings, verdict.lines
            assert verdict.error == pytest.approx(verdict.reference_errors[expected], rel=1e-9)
    errors = [v.error for v in verdicts]
    for order in observed_orders(list(STEPS), errors):
        assert abs(order - 1.0) < 0.2, errors
    # 11 H (Jacobi), 3.7 H (Gauss-Seidel), 17 H (fmpy.ssp)
    assert math.isfinite(errors[-1]) and errors[-1] < 20 * STEPS[-1]


@pytest.mark.parametrize(("engine", "version"), sorted(CANNOT), ids=lambda v: str(v))
def test_engine_that_cannot_says_why(engine: str, version: int, tmp_path: Path) -> None:
    _skip_unless_installed(engine)
    with pytest.raises((EngineError, Exception), match=CANNOT[(engine, version)]):
        run_engine(engine, 0.01, 0.1, tmp_path / "cannot.csv", version)


LIBCOSIM_OBSERVER = """
import sys
from libcosimpy.CosimExecution import CosimExecution
from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
from libcosimpy.CosimObserver import CosimObserver
log_output_level(CosimLogLevel.ERROR)
execution = CosimExecution.from_ssp_file(sys.argv[1], step_size=10_000_000)
execution.add_observer(CosimObserver.create_to_dir(sys.argv[2]))
sys.exit(0 if execution.simulate_until(2_000_000_000) else 3)
"""
ECOS_WRITER = """
import sys
from ecospy import EcosSimulation
simulation = EcosSimulation(ssp_path=sys.argv[1], step_size=0.01)
simulation.add_csv_writer(sys.argv[2] + "/ecos.csv")
sys.exit(0 if simulation.init() and simulation.step(200) else 3)
"""


@pytest.mark.parametrize("engine", ["libcosim", "ecos"])
def test_engines_own_csv_writers_are_judged(engine: str, tmp_path: Path) -> None:
    """The recipe of docs/masters.md: the engine's own CSV (libcosim: one file per instance, 6
    significant digits, bare names; Ecos: Body::theta ...) judged as it is."""
    import subprocess
    import sys

    from pendulum_fmu import split_path
    from pendulum_fmu.split.engines import ecos_environment

    _skip_unless_installed(engine)
    script, env = (LIBCOSIM_OBSERVER, None) if engine == "libcosim" else (ECOS_WRITER, ecos_environment())
    done = subprocess.run([sys.executable, "-c", script, str(split_path()), str(tmp_path)], capture_output=True,
                          text=True, timeout=300, env=env)
    assert done.returncode == 0, done.stderr[-2000:]
    written = sorted(tmp_path.glob("Body_*.csv")) if engine == "libcosim" else [tmp_path / "ecos.csv"]
    verdict = judge_split(written[0])
    assert verdict.master == "jacobi-zoh" and verdict.passed, verdict.lines
    assert "theta0 = 1.308996939 rad (75 deg)" in verdict.lines[1]


def test_fmi2_messages_after_a_container_run(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """fmpy's FMI 2.0 logging proxy has one target, which the container run's own logger takes:
    after the run, a message of another FMI 2.0 FMU (a refused call through ``Pair``) still
    reaches fmpy's logger, not freed memory (which crashed the process)."""
    from fmpy.fmi1 import FMICallException

    from pendulum_fmu.split.pair import ALPHA, DEFAULT_PROBLEM, Pair

    _skip_unless_installed("fmucontainer")
    run_engine("fmucontainer", 0.01, 0.2, tmp_path / "container.csv", 2)
    import gc

    gc.collect()
    with Pair(DEFAULT_PROBLEM, 2) as pair, pytest.raises(FMICallException, match="status 3"):
        pair.set(pair.body, ALPHA, math.nan)
    assert "alpha (value reference 16) = nan: must be a finite number" in capsys.readouterr().out
