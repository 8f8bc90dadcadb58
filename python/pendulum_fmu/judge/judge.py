"""``judge(...)``: read a result, run every check, infer what went wrong, return the verdict."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal

import numpy as np

from pendulum_fmu.fmu.library import exact
from pendulum_fmu.judge import alternatives, band, checks, inference
from pendulum_fmu.judge.experiment import make_experiment
from pendulum_fmu.judge.reading import ReadError, Result, describe_digits, read_result
from pendulum_fmu.judge.verdict import Check, Experiment, Verdict

MANGLED_ROWS = 3
"""At most this many rows (or 1 % of them) off in the exact columns: mangled values, not a
different problem (which moves every row)."""
FIT_AGREEMENT = 1e-10
"""A parameter fit explains the exact columns when it reproduces them to this."""
TOLERANCES = [10.0 ** -k for k in range(2, 13)]
"""The decades at which the FMU's solver or CVODE is rerun to find the tolerance of a file."""


def _reading_check(result: Result) -> Check:
    used = ", ".join(result.columns[v] for v in ("theta", "omega", "theta_exact", "omega_exact") if v in result.columns)
    instance = f" of instance {result.instance!r}" if result.instance else ""
    return Check("read", "info", f"{Path(result.source).name}: {result.rows} rows; {used}{instance}; "
                 f"{describe_digits(result)}", {"rows": result.rows, "columns": dict(result.columns),
                                                "instance": result.instance,
                                                "formats": None if result.formats is None else
                                                {k: f.describe() for k, f in result.formats.items()}})


def _experiment_check(experiment: Experiment, where: str) -> Check:
    given = ", ".join(experiment.given) if experiment.given else "nothing"
    solver = f", solver {experiment.solver}" if experiment.solver else ""
    return Check("experiment", "info", f"{experiment.interface}, theta0 = {experiment.theta0:.10g} rad, "
                 f"omega0 = {experiment.omega0:.10g} rad/s, L = {experiment.L:g} m, g = {experiment.g:g} m/s^2, "
                 f"tol = {experiment.tolerance:g}{solver} (given: {given}; the rest from {Path(where).name})",
                 {"defaults_from": where})


def _exact_fits(result: Result, ref: checks.Reference, experiment: Experiment) -> alternatives.Fits:
    """Exact columns fit an alternative when they equal it to FIT_AGREEMENT beyond the print."""
    rates = checks.slopes(ref, experiment)

    def fits(residuals: alternatives.Columns) -> bool:
        for name, r in residuals.items():
            key = name.removesuffix("_exact")
            allowed = (FIT_AGREEMENT * np.maximum(1.0, np.abs(result.values[name])) + 2 * result.resolution[name]
                       + np.abs(rates[key]) * result.resolution["time"])
            if not np.all(np.abs(r) <= allowed):
                return False
        return True
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
    frozen = _frozen(result, list(mismatch))
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


def _frozen(result: Result, names: list[str]) -> str:
    """"theta stays at 1.3963 in all 1001 rows: ..." when some of ``names`` never change, else ""."""
    still = [n for n in names if result.rows > 2 and np.ptp(result.values[n]) == 0]
    if not still:
        return ""
    values = ", ".join(f"{n} stays at {result.values[n][0]:.6g}" for n in still)
    return (f"{values} in all {result.rows} rows: the FMU never advanced (an importer that went on after the FMU "
            "refused a value?)")


def _state_fits(ref: checks.Reference, experiment: Experiment, errors: dict[str, np.ndarray]) -> alternatives.Fits:
    """theta and omega fit an alternative when, against it, they are within the bound, and
    their largest error in units of the bound is at most half of what it is against the
    experiment."""
    limits = {name: checks.bound(name, ref, experiment) for name in errors}
    before = max(float(np.max(np.abs(e) / limits[n])) for n, e in errors.items())

    def fits(residuals: alternatives.Columns) -> bool:
        after = max(float(np.max(np.abs(r) / limits[n])) for n, r in residuals.items())
        return after <= min(1.0, 0.5 * before)  # a NaN compares False: no fit
    return fits


def _diagnosis(result: Result, ref: checks.Reference, experiment: Experiment, errors: dict[str, np.ndarray],
               explained: alternatives.Explanation | None, h: float | None, fmu: Path | None) -> Check | None:
    """Why theta and omega are beyond the bound: what reproduces them."""
    if not errors or not all(np.all(np.isfinite(e)) for e in errors.values()):
        return None
    worst = max(float(np.max(np.abs(e))) for e in errors.values())
    theta_growth = checks.describe_growth(checks.growth(ref.t, next(iter(errors.values()))))
    if explained is not None and explained.cause == "parameters":
        f = explained.figures
        refit = checks.Reference(ref.t, *exact(f["theta0"], f["omega0"], f["L"], f["g"], ref.t), ref.accumulation)
        against = max(float(np.max(np.abs(e))) for e in checks.state_errors(result, refit).values())
        return Check("diagnosis", "info", f"a different problem, solved to {against:.1e} against its own exact "
                     f"solution: {', '.join(f['changed'])}", {"cause": "parameters", "error_against_fit": against})
    if explained is not None:
        return None  # the exact columns' check names the cause
    frozen = _frozen(result, list(errors))
    if frozen:
        return Check("diagnosis", "info", frozen, {"cause": "frozen"})
    if result.formats is not None:
        rates = checks.slopes(ref, experiment)
        rounding = {n: result.resolution[n] + np.abs(rates[n]) * result.resolution["time"] for n in errors}
        if all(np.all(np.abs(e) <= 1.01 * rounding[n] + 1e-12) for n, e in errors.items()):
            name = max(errors, key=lambda n: float(np.max(np.abs(errors[n]))))
            k = int(np.argmax(np.abs(errors[name])))
            coarse = float(rounding[name][k])
            formats = ", ".join(sorted({result.formats[n].describe() for n in errors}))
            return Check("diagnosis", "info", f"every error is within the print's rounding (values printed with "
                         f"{formats}: {coarse:.1e} at the largest error, {name} at t = {result.time[k]:.6g} s), "
                         "coarser than the bound: the file cannot show the accuracy; write 17 significant digits",
                         {"cause": "print precision", "rounding": coarse})
    if experiment.interface == "ME" and h is not None:
        found = inference.identify_fixed_step(result, experiment, h, worst)
        if found is not None:
            return Check("diagnosis", "info", f"{found.method} at h = {found.step:g} reproduces the file to "
                         f"{found.agreement:.1e}: the importer's solver is {found.method} with a fixed step "
                         f"(error {theta_growth})", {"cause": "fixed step", "method": found.method, "step": found.step})
    found_alternative = alternatives.explain({k: result.values[k] for k in errors}, experiment, result.time, h,
                                             _state_fits(ref, experiment, errors), max(1e-6, _largest_resolution(result)))
    if found_alternative is not None:
        explanation, _ = found_alternative
        return Check("diagnosis", "info", f"theta and omega: {explanation.line}",
                     {"cause": explanation.cause, **explanation.figures})
    if fmu is not None and "theta" in errors:
        return _tolerance(result, experiment, errors, fmu, theta_growth)
    return Check("diagnosis", "info", f"no known cause reproduces the error (largest {worst:.1e}, {theta_growth})",
                 {"cause": None})


def _fixed_step_within_bound(result: Result, experiment: Experiment, errors: dict[str, np.ndarray],
                             h: float | None) -> list[Check]:
    """A fixed-step method that reproduces a Model Exchange file whose error is far beyond what
    the tolerance asks of one period (ME_FACTOR tol), though within the bound's growth: the
    importer's solver ignores the tolerance, however near the separatrix the bound is loose."""
    if h is None or not errors:
        return []
    worst = max(float(np.max(np.abs(e))) for e in errors.values())
    if not worst > checks.ME_FACTOR * experiment.tolerance * max(1.0, abs(experiment.theta0)):
        return []
    found = inference.identify_fixed_step(result, experiment, h, worst)
    if found is None:
        return []
    return [Check("method", "fail", f"{found.method} at h = {found.step:g} reproduces the file to "
                  f"{found.agreement:.1e}: the importer's solver is {found.method} with a fixed step, which ignores "
                  f"the tolerance (its error {worst:.1e} is {worst / experiment.tolerance:.1e} tol)",
                  {"cause": "fixed step", "method": found.method, "step": found.step})]


def _tolerance(result: Result, experiment: Experiment, errors: dict[str, np.ndarray], fmu: Path,
               theta_growth: str) -> Check:
    """The tolerance at which the FMU's own solver (CS) or fmpy's CVODE (ME) makes the file's error."""
    theta_error = float(np.max(np.abs(errors["theta"])))
    if experiment.interface == "ME":
        solver = "CVODE"
        errs = inference.cvode_errors(fmu, result, experiment, TOLERANCES)
    else:
        solver = f"the FMU's {inference.solver_name(experiment.solver)}"
        errs = inference.fmu_errors(fmu, result, experiment, TOLERANCES)
    tol = inference.effective_tolerance(theta_error, TOLERANCES, errs)
    figures = {"cause": "tolerance" if tol is not None else None, "tolerances": TOLERANCES, "errors": errs,
               "effective_tolerance": tol, "solver": solver}
    if tol is None and theta_error > max(errs):
        figures["cause"] = "tolerance"
        return Check("diagnosis", "info", f"theta error {theta_error:.1e} ({theta_growth}) is larger than {solver}'s "
                     f"at every tolerance down to {TOLERANCES[0]:g}: the importer's solver ran far looser than the "
                     f"{'stated' if experiment.tolerance_stated else 'experiment'} tolerance {experiment.tolerance:g} "
                     "(a tolerance not passed on, or no error control)", figures)
    if tol is None:
        return Check("diagnosis", "info", f"theta error {theta_error:.1e} ({theta_growth}) is smaller than "
                     f"{solver}'s at every tolerance from {TOLERANCES[0]:g} to {TOLERANCES[-1]:g}: no known cause "
                     "reproduces it", figures)
    stated = experiment.tolerance
    decade = f"~{10 ** round(np.log10(tol)):.0e}".replace("e-0", "e-")
    if tol > 10 * stated:
        because = "not the stated" if experiment.tolerance_stated else "not the experiment's"
        return Check("diagnosis", "info", f"theta error {theta_error:.1e} fits {solver} at tolerance {decade}, "
                     f"{because} {stated:g}: the importer did not pass the experiment's tolerance to its solver",
                     figures)
    figures["cause"] = None  # at the stated tolerance: the tolerance explains nothing
    return Check("diagnosis", "info", f"theta error {theta_error:.1e} ({theta_growth}) fits {solver} at tolerance "
                 f"{decade}, which is the stated {stated:g}: no known cause reproduces the error", figures)


def _largest_resolution(result: Result) -> float:
    """The largest print resolution of the value columns, relative to max(1, |value|)."""
    return max((float(np.max(result.resolution[n] / np.maximum(1.0, np.abs(v)))) for n, v in result.values.items()),
               default=0.0)


def judge(data: Any, *, start: list[str] | dict[str, float | str] | None = None,
          interface: Literal["CS", "ME"] = "CS", instance: str | None = None, step: float | None = None,
          fmu: Path | None = None) -> Verdict:
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
    found: list[Check] = [_reading_check(result), _experiment_check(experiment, where)]
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
    found.append(checks.isolated_values(result, ref, errors))
    bound = checks.bound_check(result, ref, experiment, errors)
    found.append(bound)
    if bound.status == "pass" and experiment.interface == "ME":
        found += _fixed_step_within_bound(result, experiment, errors, h)
    diagnosis = None
    if bound.status == "fail":
        runner = fmu if fmu is not None else (Path(where) if where.endswith(".fmu") else None)
        diagnosis = _diagnosis(result, ref, experiment, errors, explained, h, runner)
    if diagnosis is not None:
        found.append(diagnosis)
    found.append(band.band_check(result, ref))
    failed = [c for c in found if c.status == "fail"]
    if failed:
        first = failed[0]
        known = diagnosis is not None and diagnosis.figures.get("cause") is not None
        reason = diagnosis.line if known and first.name == "bound" and diagnosis is not None else first.line
        line = f"FAIL ({', '.join(c.name for c in failed)}): {reason}"
    else:
        line = f"PASS: {bound.line}" if bound.status == "pass" else f"PASS: {exact_check.line}"
    return Verdict(not failed, line, tuple(found), experiment, result.source, dict(result.columns), result.instance)
