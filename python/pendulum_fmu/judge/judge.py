"""``judge(result, ...)``: the one entry of the judge, read top-down.

1. Read the result once (:mod:`pendulum_fmu.judge.reading`).
2. Build the experiment once: the caller's values over what a file states (the result's own
   record, a cross-check ``_ref.opt``, the FMU's FMI-LS-REF ``.exp``:
   :mod:`pendulum_fmu.judge.experiment_files`) over the model description's defaults
   (:mod:`pendulum_fmu.judge.experiment`).
3. Decide the step once: the caller's, else the experiment file's for a result that is a run
   of it, else the one read from the times.
4. Run every check once (:mod:`pendulum_fmu.judge.checks`); when one fails, say what the
   numbers are right for instead (:mod:`pendulum_fmu.judge.explain`).
5. Return the :class:`Verdict`, with the series a plot draws.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any, Literal

import numpy as np

from pendulum_fmu.judge import checks
from pendulum_fmu.judge.experiment import make_experiment
from pendulum_fmu.judge.experiment_files import ExperimentFile, experiment_file
from pendulum_fmu.judge.explain import alternatives, diagnosis
from pendulum_fmu.judge.fmpy_validation import fmpy_validation_check
from pendulum_fmu.judge.reading import ReadError, Result, describe_digits, read_result
from pendulum_fmu.judge.verdict import Check, Experiment, Series, Verdict

MANGLED_ROWS = 3
"""At most this many rows (or 1 % of them) off in the exact columns: mangled values, not a
different problem (which moves every row)."""
FIT_AGREEMENT = 1e-10
"""A parameter fit explains the exact columns when it reproduces them to this."""


def judge(result: Any, *, start: Mapping[str, float | str] | None = None,
          interface: Literal["CS", "ME"] | None = None, instance: str | None = None, step: float | None = None,
          fmu: Path | None = None, read_experiment_file: bool = True) -> Verdict:
    """Judge an importer's result of Pendulum.fmu against the exact solution.

    Parameters
    ----------
    result : str, Path, pandas.DataFrame, numpy structured array or mapping
        The result: a CSV or Parquet file, or a table (see :mod:`pendulum_fmu.judge.reading`).
    start : mapping, optional
        What the run set, by the FMU's names: ``theta`` (rad), ``omega`` (rad/s), ``L`` (m),
        ``g`` (m/s^2), ``tolerance``, ``startTime`` (s), ``solver``; the rest come from the
        experiment file, else the model description's defaults.
    interface : {"CS", "ME"}, optional
        Co-Simulation (the bound of the FMU's certificate) or Model Exchange; default: the
        experiment file's, else CS.
    instance : str, optional
        Which instance's columns, when the result holds several.
    step : float, optional
        The communication step the run was asked for (default: the experiment file's, for a
        result that is a run of it, else inferred from the times).
    fmu : Path, optional
        The FMU whose model description gives the defaults and whose FMI-LS-REF experiment is
        the last experiment file looked for (and, for a diagnosis, reruns its solver or
        CVODE); default: the FMU found without building.
    read_experiment_file : bool
        Look for the file that states the experiment (the result's record, a ``_ref.opt``, the
        FMU's ``.exp``: :func:`pendulum_fmu.judge.experiment_files.experiment_file`); False
        judges against ``start`` over the defaults alone.

    Returns
    -------
    Verdict

    Raises
    ------
    ReadError
        The input cannot be read (one line).
    UsageError
        A bad ``start``, ``interface`` or ``fmu``, or an experiment file that cannot be read
        (naming ``result`` or ``fmu``).
    """
    stated = experiment_file(result, fmu) if read_experiment_file else None
    read = read_result(result, instance)
    if read.rows < 2:
        raise ReadError(f"{read.source}: {read.rows} row: a result needs at least two")
    experiment, defaults_from = make_experiment(start, interface, fmu, stated)
    found: list[Check] = [_reading_check(read), _experiment_check(experiment, defaults_from, stated, start)]
    grid, h = _time_grid(read, step, stated)
    found.append(grid)
    ref = checks.reference(read, experiment)
    exact_check, explained, differences = _exact_columns(read, ref, experiment, h, grid.status == "fail")
    found.append(exact_check)
    errors = checks.state_errors(read, ref)
    if not errors:
        found.append(Check("importer's values", "fail", "no theta or omega column: the file holds nothing of the "
                           "importer's to judge (theta_exact and omega_exact are the FMU's own outputs)"))
    found += [checks.error_check(read, ref, name, e) for name, e in errors.items()]
    found.append(checks.isolated_values(read, ref, errors, experiment.interface))
    bound = checks.bound_check(read, ref, experiment, errors)
    found.append(bound)
    if bound.status == "pass" and experiment.interface == "ME":
        found += diagnosis.fixed_step_within_bound(read, experiment, errors, h)
    cause = None
    if bound.status == "fail":
        runner = fmu if fmu is not None else (Path(defaults_from) if defaults_from.endswith(".fmu") else None)
        cause = diagnosis.diagnose(read, ref, experiment, errors, explained, h, runner)
    if cause is not None:
        found.append(cause)
    found.append(fmpy_validation_check(read, ref))
    series = Series(read.time, read.values, ref.theta, ref.omega, errors,
                    {name: checks.bound(name, ref, experiment) for name in errors}, differences)
    return Verdict(not any(c.status == "fail" for c in found), _verdict_line(found, cause, bound, exact_check),
                   tuple(found), experiment, read.source, dict(read.columns), read.instance, stated, series)


def _verdict_line(found: list[Check], cause: Check | None, bound: Check, exact_check: Check) -> str:
    """``FAIL (checks that failed): the first one's reason`` (the diagnosis' cause, when the
    bound failed first and a cause is named), else ``PASS: the bound's line`` (the exact
    columns' line when no bound applied)."""
    failed = [c for c in found if c.status == "fail"]
    if failed:
        first = failed[0]
        named = cause is not None and cause.numbers.get("cause") is not None and first.name == "bound"
        reason = cause.line if named and cause is not None else first.line
        return f"FAIL ({', '.join(c.name for c in failed)}): {reason}"
    return f"PASS: {bound.line}" if bound.status == "pass" else f"PASS: {exact_check.line}"


def _time_grid(result: Result, step: float | None, stated: ExperimentFile | None) -> tuple[Check, float | None]:
    """The time grid check at the step decided once: ``step`` when given; else the experiment
    file's step for a result that is a run of the experiment (:meth:`ExperimentFile.covers`)
    whose times read another (rounded to 6 digits); else the step read from the times."""
    read_off = checks.time_grid(result, step)
    if step is not None or stated is None or stated.step is None:
        return read_off
    grid = read_off[0].numbers
    if {"start", "end", "rows", "step"} <= grid.keys() and stated.covers(grid["start"], grid["end"], grid["rows"]) \
            and grid["step"] != stated.step:
        return checks.time_grid(result, stated.step)
    return read_off


def _reading_check(result: Result) -> Check:
    used = ", ".join(result.columns[v] for v in ("theta", "omega", "theta_exact", "omega_exact") if v in result.columns)
    instance = f" of instance {result.instance!r}" if result.instance else ""
    return Check("read", "info", f"{Path(result.source).name}: {result.rows} rows; {used}{instance}; "
                 f"{describe_digits(result)}", {"rows": result.rows, "columns": dict(result.columns),
                                                "instance": result.instance,
                                                "formats": None if result.formats is None else
                                                {k: f.describe() for k, f in result.formats.items()}})


def _experiment_check(experiment: Experiment, where: str, stated: ExperimentFile | None,
                      start: Mapping[str, float | str] | None) -> Check:
    """The experiment judged against, and where each of its values came from: given (``start``),
    stated by a file (the result's record, a ``_ref.opt``, the FMU's ``.exp``), or the defaults."""
    stated_by = (stated.source, tuple(n for n in stated.stated() if n not in (start or {}))) if stated else None
    from_file = set(stated_by[1]) if stated_by else set()
    own = [name for name in experiment.given if name not in from_file]
    given = ", ".join(own) if own else "nothing"
    from_which = (f"; from {Path(stated_by[0]).name}: {', '.join(n for n in experiment.given if n in from_file)}"
                  if stated_by and from_file else "")
    solver = f", solver {experiment.solver}" if experiment.solver else ""
    p = experiment.problem
    return Check("experiment", "info", f"{experiment.interface}, theta0 = {p.theta0:.10g} rad, "
                 f"omega0 = {p.omega0:.10g} rad/s, L = {p.L:g} m, g = {p.g:g} m/s^2, "
                 f"tol = {experiment.tolerance:g}{solver} (given: {given}{from_which}; "
                 f"the rest from {Path(where).name})",
                 {"defaults_from": where, "stated_by": stated_by[0] if stated_by else None,
                  "stated": sorted(from_file)})


def _exact_fits(result: Result, ref: checks.Reference, experiment: Experiment) -> alternatives.Fits:
    """Exact columns fit an alternative when they equal it to FIT_AGREEMENT beyond the print
    (its rounding, and half a unit more: the alternative's own value is not printed)."""
    allowed: dict[str, np.ndarray]
    allowed = {name: FIT_AGREEMENT * np.maximum(1.0, np.abs(result.values[name])) + result.resolution[name]
               + checks.print_rounding(result, ref, experiment, name) for name in ("theta_exact", "omega_exact")
               if name in result.values}

    def fits(residuals: alternatives.Columns) -> bool:
        return all(bool(np.all(np.abs(r) <= allowed[name])) for name, r in residuals.items())
    return fits


Differences = dict[str, tuple[np.ndarray, np.ndarray]]
"""|exact column - pendulum_fmu.exact| and what the print allows, by column (:func:`checks.exact_mismatch`)."""


def _exact_columns(result: Result, ref: checks.Reference, experiment: Experiment, h: float | None,
                   grid_failed: bool) -> tuple[Check, alternatives.Explanation | None, Differences]:
    """The exact columns' check, the alternative they answer when they are off, and their differences."""
    mismatch = checks.exact_mismatch(result, ref, experiment)
    check, explained = _exact_columns_check(result, ref, experiment, mismatch, h, grid_failed)
    return check, explained, mismatch


def _exact_columns_check(result: Result, ref: checks.Reference, experiment: Experiment, mismatch: Differences,
                         h: float | None, grid_failed: bool) -> tuple[Check, alternatives.Explanation | None]:
    if not mismatch:
        return Check("exact columns", "info", "no theta_exact or omega_exact column"), None
    names = ", ".join(mismatch)
    for name in mismatch:
        bad = np.flatnonzero(~np.isfinite(result.values[name]))
        if bad.size:
            k = int(bad[0])
            return Check("exact columns", "fail", f"{name} is {result.values[name][k]} at t = {result.time[k]:.6g} s "
                         f"(row {k + 1}; {bad.size} such rows): the exact solution is finite everywhere",
                         {"nonfinite_rows": int(bad.size), "first_nonfinite_time": float(result.time[k])}), None
    largest = {k: float(np.max(d)) for k, (d, _) in mismatch.items()}
    off = np.zeros(result.rows, dtype=bool)
    for d, allowed in mismatch.values():
        off |= d > allowed
    figures: dict[str, Any] = {"largest": largest, "rows_off": int(off.sum())}
    if not off.any():
        worst = max(largest.values())
        return Check("exact columns", "pass", f"{names} equal pendulum_fmu.exact at the file's times: "
                     f"largest difference {worst:.1e}", figures), None
    rows = np.flatnonzero(off)
    if rows.size <= max(MANGLED_ROWS, result.rows // 100):
        where = ", ".join(f"t = {result.time[k]:.6g} s (row {k + 1})" for k in rows[:5])
        figures["rows"] = [int(k) + 1 for k in rows]
        return Check("exact columns", "fail", f"{names}: {rows.size} value(s) off pendulum_fmu.exact (largest "
                     f"{max(largest.values()):.2e}) at {where}, the rest agree: mangled values", figures), None
    first = int(rows[0])
    frozen = diagnosis.frozen(result, list(mismatch))
    if frozen:
        return Check("exact columns", "fail", f"{names} differ from pendulum_fmu.exact: {frozen}", figures), None
    if grid_failed and h is not None:  # values computed at k h but written at other times (a drifting clock)
        on_grid = Result(np.arange(result.rows) * h + result.time[0], result.values, result.resolution,
                         result.columns, result.instance, result.source, result.formats)
        on_grid_ref = checks.reference(on_grid, experiment)
        if all(np.all(d <= a) for d, a in checks.exact_mismatch(on_grid, on_grid_ref, experiment).values()):
            return Check("exact columns", "fail", f"{names} differ from pendulum_fmu.exact at the written times "
                         f"(largest {max(largest.values()):.2e}) but equal it at t = k h: the values are right, "
                         "the times are written wrong (the clock drifts)", figures), None
    head = (f"{names} differ from pendulum_fmu.exact from t = {result.time[first]:.6g} s on (largest "
            f"{max(largest.values()):.2e}, {rows.size} rows)")
    print_allowance = 2 * max(float(np.max(a)) for _, a in mismatch.values())
    found = alternatives.explain({k: result.values[k] for k in mismatch}, experiment, result.time, h,
                                 _exact_fits(result, ref, experiment), print_allowance)
    if found is not None:
        explanation, _ = found
        figures[explanation.cause] = explanation.numbers
        if explanation.cause == "parameters":
            figures["fit"] = explanation.numbers
        return Check("exact columns", "fail", f"{head}: {explanation.line}", figures), explanation
    return Check("exact columns", "fail", f"{head}: no other start values, g/L, start time, time shift or clock "
                 "reproduces them: mangled values", figures), None
