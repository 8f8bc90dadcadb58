"""``judge(...)``: read a result, run every check, infer what went wrong, return the verdict."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

import numpy as np

from pendulum_fmu.judge import alternatives, band, checks, diagnosis
from pendulum_fmu.judge.experiment import make_experiment
from pendulum_fmu.judge.reading import ReadError, Result, describe_digits, read_result
from pendulum_fmu.judge.verdict import Check, Experiment, Verdict

MANGLED_ROWS = 3
"""At most this many rows (or 1 % of them) off in the exact columns: mangled values, not a
different problem (which moves every row)."""
FIT_AGREEMENT = 1e-10
"""A parameter fit explains the exact columns when it reproduces them to this."""


def _reading_check(result: Result) -> Check:
    used = ", ".join(result.columns[v] for v in ("theta", "omega", "theta_exact", "omega_exact") if v in result.columns)
    instance = f" of instance {result.instance!r}" if result.instance else ""
    return Check("read", "info", f"{Path(result.source).name}: {result.rows} rows; {used}{instance}; "
                 f"{describe_digits(result)}", {"rows": result.rows, "columns": dict(result.columns),
                                                "instance": result.instance,
                                                "formats": None if result.formats is None else
                                                {k: f.describe() for k, f in result.formats.items()}})


def _experiment_check(experiment: Experiment, where: str, stated_by: tuple[str, tuple[str, ...]] | None) -> Check:
    """The experiment judged against, and where each of its values came from: given (``--start``),
    stated by a file (the result's record, a ``_ref.opt``, the FMU's ``.exp``), or the defaults."""
    from_file = set(stated_by[1]) if stated_by else set()
    own = [name for name in experiment.given if name not in from_file]
    given = ", ".join(own) if own else "nothing"
    stated = (f"; from {Path(stated_by[0]).name}: {', '.join(n for n in experiment.given if n in from_file)}"
              if stated_by and from_file else "")
    solver = f", solver {experiment.solver}" if experiment.solver else ""
    return Check("experiment", "info", f"{experiment.interface}, theta0 = {experiment.theta0:.10g} rad, "
                 f"omega0 = {experiment.omega0:.10g} rad/s, L = {experiment.L:g} m, g = {experiment.g:g} m/s^2, "
                 f"tol = {experiment.tolerance:g}{solver} (given: {given}{stated}; the rest from {Path(where).name})",
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


def _exact_columns(result: Result, ref: checks.Reference, experiment: Experiment,
                   h: float | None, grid_failed: bool) -> tuple[Check, alternatives.Explanation | None]:
    mismatch = checks.exact_mismatch(result, ref, experiment)
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
        figures[explanation.cause] = explanation.figures
        if explanation.cause == "parameters":
            figures["fit"] = explanation.figures
        return Check("exact columns", "fail", f"{head}: {explanation.line}", figures), explanation
    return Check("exact columns", "fail", f"{head}: no other start values, g/L, start time, time shift or clock "
                 "reproduces them: mangled values", figures), None


def judge(data: Any, *, start: list[str] | dict[str, float | str] | None = None,
          interface: Literal["CS", "ME"] = "CS", instance: str | None = None, step: float | None = None,
          fmu: Path | None = None, stated_by: tuple[str, tuple[str, ...]] | None = None) -> Verdict:
    """Judge an importer's result of Pendulum.fmu against the exact solution.

    Parameters
    ----------
    data : str, Path, pandas.DataFrame, numpy structured array or mapping
        The result: a CSV or Parquet file, or a table (see :mod:`pendulum_fmu.judge.reading`).
    start : list of "NAME=VALUE" or dict, optional
        theta, omega, L, g, solver, tolerance as the run set them; the rest are the model
        description's defaults.
    interface : {"CS", "ME"}
        Co-Simulation (the bound of the FMU's certificate) or Model Exchange.
    instance : str, optional
        Which instance's columns, when the result holds several.
    step : float, optional
        The communication step the run was asked for (default: inferred from the times).
    fmu : Path, optional
        The FMU whose model description gives the defaults (and, for Model Exchange, runs
        CVODE to infer a tolerance).
    stated_by : (str, tuple of str), optional
        The file that stated part of ``start`` (the result's experiment record, an experiment
        file) and the names it stated, for the experiment's line (what the caller gave, what
        the file, what the defaults).

    Returns
    -------
    Verdict

    Raises
    ------
    ReadError
        The input cannot be read (one line).
    UsageError
        A bad ``start``, ``interface`` or ``fmu``.
    """
    result = read_result(data, instance)
    if result.rows < 2:
        raise ReadError(f"{result.source}: {result.rows} row: a result needs at least two")
    experiment, where = make_experiment(start, interface, fmu)
    found: list[Check] = [_reading_check(result), _experiment_check(experiment, where, stated_by)]
    grid, h = checks.time_grid(result, step)
    found.append(grid)
    ref = checks.reference(result, experiment)
    exact_check, explained = _exact_columns(result, ref, experiment, h, grid.status == "fail")
    found.append(exact_check)
    errors = checks.state_errors(result, ref)
    if not errors:
        found.append(Check("importer's values", "fail", "no theta or omega column: the file holds nothing of the "
                           "importer's to judge (theta_exact and omega_exact are the FMU's own outputs)"))
    found += [checks.error_check(result, ref, name, e) for name, e in errors.items()]
    found.append(checks.isolated_values(result, ref, errors, experiment.interface))
    bound = checks.bound_check(result, ref, experiment, errors)
    found.append(bound)
    if bound.status == "pass" and experiment.interface == "ME":
        found += diagnosis.fixed_step_within_bound(result, experiment, errors, h)
    cause = None
    if bound.status == "fail":
        runner = fmu if fmu is not None else (Path(where) if where.endswith(".fmu") else None)
        cause = diagnosis.diagnose(result, ref, experiment, errors, explained, h, runner)
    if cause is not None:
        found.append(cause)
    found.append(band.band_check(result, ref))
    failed = [c for c in found if c.status == "fail"]
    if failed:
        first = failed[0]
        named = cause is not None and cause.figures.get("cause") is not None and first.name == "bound"
        reason = cause.line if named and cause is not None else first.line
        line = f"FAIL ({', '.join(c.name for c in failed)}): {reason}"
    else:
        line = f"PASS: {bound.line}" if bound.status == "pass" else f"PASS: {exact_check.line}"
    return Verdict(not failed, line, tuple(found), experiment, result.source, dict(result.columns), result.instance)
