"""The judge among the FMI world's own files: the experiment a run states (a cross-check
``_ref.opt``, an FMU's FMI-LS-REF ``.exp``) and the cross-check's verdict file."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

from pendulum_fmu.judge.experiment import Settings, apply_settings, experiment_settings
from pendulum_fmu.judge.judge import judge
from pendulum_fmu.judge.verdict import Verdict
from pendulum_fmu.output.atomic import write_whole

Outcome = Literal["passed", "failed", "rejected"]
OUTCOMES: tuple[Outcome, ...] = ("passed", "failed", "rejected")
"""The files an importer publishes in its cross-check result folder (the cross-check rules,
9.2.3): one of them, empty; none at all counts as ``failed``."""


def judge_with_experiment(data: Any, *, start: list[str] | None = None, interface: Literal["CS", "ME"] | None = None,
                          instance: str | None = None, step: float | None = None,
                          fmu: Path | None = None) -> tuple[Verdict, Settings | None]:
    """:func:`pendulum_fmu.judge.judge` with the experiment a file states beneath the arguments.

    The experiment is the result's own record (what this package writes with every time
    series: its start values, parameters, solver, interface, tolerance and step), else the
    ``_ref.opt`` of a result in a cross-check folder, else the FMI-LS-REF ``.exp`` of ``fmu``
    (or of the FMU found): its values, start time and tolerance unless ``start`` gives them,
    its interface (a cross-check folder's ``cs``/``me``, the record's) unless ``interface`` does,
    and its step unless ``step`` does, for a result that is a run of the experiment (its span
    and its number of steps, :meth:`Settings.covers`): when the step read from such a file's
    times (rounded to 6 digits) is not the experiment's, the file is judged again with the
    experiment's step. Such a file has the experiment's number of rows, so the second judging
    costs little.

    Returns
    -------
    Verdict, and the settings used (None when no file states an experiment).
    """
    settings = experiment_settings(data, fmu)
    pairs = apply_settings(settings, start)
    chosen: Literal["CS", "ME"] = interface or (settings.interface if settings is not None else None) or "CS"
    stated_by = None
    if settings is not None:
        named = {pair.partition("=")[0].strip() for pair in start or []}
        stated = tuple(name for name, _ in settings.values) + ("startTime",) + (
            ("tolerance",) if settings.tolerance is not None else ())
        stated_by = (settings.source, tuple(name for name in stated if name not in named))
    verdict = judge(data, start=pairs, interface=chosen, instance=instance, step=step, fmu=fmu, stated_by=stated_by)
    if settings is None or step is not None or settings.step is None:
        return verdict, settings
    grid = next((check.figures for check in verdict.checks if check.name == "time grid"), {})
    if {"start", "end", "rows", "step"} <= grid.keys() and settings.covers(grid["start"], grid["end"], grid["rows"]) \
            and grid["step"] != settings.step:
        verdict = judge(data, start=pairs, interface=chosen, instance=instance, step=settings.step, fmu=fmu,
                        stated_by=stated_by)
    return verdict, settings


def outcome(verdict: Verdict | None) -> Outcome:
    """``passed`` or ``failed`` for a verdict; ``rejected`` for None, a result that could not be read."""
    if verdict is None:
        return "rejected"
    return "passed" if verdict.passed else "failed"


def write_verdict_file(folder: Path, result: Outcome) -> Path:
    """Write the cross-check verdict file ``folder/<result>``, and nothing else.

    The file is empty, as the cross-check repository's are, and written whole
    (:func:`pendulum_fmu.output.atomic.write_whole`); then the other two verdict files, left by
    an earlier run, are removed, so the folder states one verdict. The folder is created when
    missing.

    Returns
    -------
    Path
        The file written.
    """
    if result not in OUTCOMES:
        raise ValueError(f"a cross-check verdict is one of {', '.join(OUTCOMES)}, not {result!r}")
    folder.mkdir(parents=True, exist_ok=True)
    written = write_whole(folder / result, lambda path: path.write_bytes(b""))
    for other in OUTCOMES:
        if other != result:
            (folder / other).unlink(missing_ok=True)
    return written
