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
    for H in STEPS:  # noqa: N806
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
    assert math.isfinite(errors[-1]) and errors[-1] < 20 * STEPS[-1]  # 11 H (Jacobi), 3.7 H (Gauss-Seidel), 17 H (fmpy.ssp)


@pytest.mark.parametrize(("engine", "version"), sorted(CANNOT), ids=lambda v: str(v))
def test_engine_that_cannot_says_why(engine: str, version: int, tmp_path: Path) -> None:
    _skip_unless_installed(engine)
    with pytest.raises((EngineError, Exception), match=CANNOT[(engine, version)]):
        run_engine(engine, 0.01, 0.1, tmp_path / "cannot.csv", version)
