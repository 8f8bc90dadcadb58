"""Run the selected cases with one adapter: each in its folder, with a time limit, judged; one
failure or crash never stops the others."""

from __future__ import annotations

import os
import time
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Literal

from pendulum_fmu.judge.cross_check_verdict import Outcome
from pendulum_fmu.suite.adapters import Adapter
from pendulum_fmu.suite.cases import Case
from pendulum_fmu.suite.experiment import Run
from pendulum_fmu.suite.judging import Judged, judge_pendulum, judge_split_result
from pendulum_fmu.suite.process import run_command

Status = Literal["passed", "failed", "error"]
OUTCOMES: dict[Status, Outcome] = {"passed": "passed", "failed": "failed", "error": "rejected"}
"""The cross-check verdict file of each status: a run that went wrong, or a result that could not
be read, is ``rejected``."""
CANNOT_RUN = 3
"""The exit status of a built-in engine's child that cannot run a case (:mod:`pendulum_fmu.suite.engine_child`)."""
DEFAULT_JOBS = 2
"""Engine processes run side by side by default (the judging is one at a time)."""
DEFAULT_TIMEOUT = 120.0
"""Seconds a case's run may take before it is killed and reported as an error."""


@dataclass
class CaseResult:
    """One case's outcome.

    Attributes
    ----------
    case : Case
    status : {"passed", "failed", "error"}
        ``error``: the run crashed, hung past its time limit, wrote nothing, or its result
        could not be read (the cross-check's ``rejected``).
    line : str
        The verdict line, or what went wrong with the run.
    folder : Path
        The case's folder: ``experiment.json``, the result, the verdict file.
    result : Path or None
        The result file judged.
    run_seconds, judge_seconds : float
    output : str
        The tail of what the run printed.
    judged : Judged or None
    """

    case: Case
    status: Status
    line: str
    folder: Path
    result: Path | None = None
    run_seconds: float = 0.0
    judge_seconds: float = 0.0
    output: str = ""
    judged: Judged | None = None
    extra: dict[str, Any] = field(default_factory=dict)


def _fmu_for(case: Case, fmus: dict[int, Path]) -> Path:
    if case.kind == "pendulum" and case.fmi_major in fmus:
        return fmus[case.fmi_major]
    if case.kind == "split":
        from pendulum_fmu.split.locate import split_path

        return split_path(case.fmi_major)
    from pendulum_fmu.fmu.locate import locate_fmu

    return locate_fmu(None, fmi_version=case.fmi_major)


def _result_file(adapter: Adapter, case: Case, folder: Path) -> Path | None:
    """For ``results``: ``DIR/<case>.csv``, else the one CSV in ``DIR/<case>/``."""
    assert adapter.results is not None
    direct = adapter.results / f"{case.name}.csv"
    if direct.is_file():
        return direct
    inside = sorted((adapter.results / case.name).glob("*.csv")) if (adapter.results / case.name).is_dir() else []
    return inside[0] if len(inside) == 1 else None


def _environment(adapter: Adapter) -> dict[str, str]:
    env = dict(os.environ)
    if adapter.name in ("ecos",):
        from pendulum_fmu.split.engines import ecos_environment

        env = ecos_environment()
    python = str(Path(__file__).resolve().parents[2])  # the engine's child imports this package
    env["PYTHONPATH"] = os.pathsep.join(p for p in (python, env.get("PYTHONPATH", "")) if p)
    return {**env, **adapter.environment}


@dataclass(frozen=True)
class _Executed:
    """A run that left a result file, to be judged."""

    case: Case
    folder: Path
    output: Path
    fmu: Path
    seconds: float
    said: str


def _execute(adapter: Adapter, case: Case, out: Path, timeout: float, fmu: Path) -> CaseResult | _Executed:
    """Run (or find) one case's result; a run that went wrong is already its :class:`CaseResult`."""
    folder = out / "cases" / case.name
    folder.mkdir(parents=True, exist_ok=True)
    if case.kind not in adapter.kinds:
        return CaseResult(case, "error", f"ERROR: {adapter.name} runs one FMU, not the split pendulum's SSP", folder)
    output = folder / "result.csv"
    output.unlink(missing_ok=True)
    run = Run(case, fmu, output)
    experiment = run.write(folder / "experiment.json")
    if adapter.name == "results":
        found = _result_file(adapter, case, folder)
        if found is None:
            return CaseResult(case, "error", f"ERROR: no result file {case.name}.csv (or one CSV in {case.name}/) "
                              f"in {adapter.results}", folder)
        return _Executed(case, folder, found, fmu, 0.0, "")
    finished = run_command(adapter.command(run, experiment), timeout, _environment(adapter))
    said, seconds = finished.tail, finished.seconds
    (folder / "output.txt").write_text(said + "\n")
    last = said.strip().splitlines()[-1] if said.strip() else "no output"
    if finished.returncode == CANNOT_RUN and last.startswith("cannot run: "):  # a built-in engine's refusal
        return CaseResult(case, "error", f"ERROR: {last}", folder, None, seconds, output=said)
    if finished.timed_out or finished.returncode != 0:
        return CaseResult(case, "error", f"ERROR: {finished.describe()}: {last}", folder, None, seconds, output=said)
    if not output.is_file() or output.stat().st_size == 0:
        return CaseResult(case, "error", f"ERROR: {finished.describe()} but no result at {output}: {last}",
                          folder, None, seconds, output=said)
    return _Executed(case, folder, output, fmu, seconds, said)


def _judge(adapter: Adapter, executed: _Executed) -> CaseResult:
    from pendulum_fmu.errors import UsageError
    from pendulum_fmu.judge import ReadError

    case, folder, output, fmu, seconds, said = (executed.case, executed.folder, executed.output, executed.fmu,
                                                executed.seconds, executed.said)
    began = time.perf_counter()
    try:
        judged = judge_pendulum(case, output, fmu) if case.kind == "pendulum" else \
            judge_split_result(output, adapter.master)
    except (ReadError, UsageError, OSError, ValueError) as error:
        return CaseResult(case, "error", f"ERROR: the result cannot be read: {error}", folder, output, seconds,
                          time.perf_counter() - began, said)
    return CaseResult(case, "passed" if judged.passed else "failed", judged.line, folder, output, seconds,
                      time.perf_counter() - began, said, judged)


def run_suite(adapter: Adapter, cases: list[Case], out: Path, timeout: float = DEFAULT_TIMEOUT,
              progress: Callable[[int, int, CaseResult], None] | None = None,
              fmus: dict[int, Path] | None = None, jobs: int = DEFAULT_JOBS) -> list[CaseResult]:
    """Every case; ``progress(k, n, result)`` after each, in the cases' order.

    ``jobs`` engine processes run side by side (each case's run is a process of its own); the
    results are judged one by one, in order, in this process. ``fmus``: ``Pendulum.fmu`` by FMI
    major version, instead of the one the package finds.
    """
    from pendulum_fmu.judge.cross_check_verdict import write_verdict_file

    found = {key: _fmu_for(case, fmus or {}) for case in cases
             for key in [(case.kind, case.fmi_major)]}  # found (or built) once, before any run starts
    results = []
    with ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = [pool.submit(_execute, adapter, case, out, timeout, found[(case.kind, case.fmi_major)])
                   for case in cases]
        for k, future in enumerate(futures, 1):
            executed = future.result()
            result = executed if isinstance(executed, CaseResult) else _judge(adapter, executed)
            write_verdict_file(result.folder, OUTCOMES[result.status])
            results.append(result)
            if progress is not None:
                progress(k, len(cases), result)
    return results
