"""Why theta and omega are beyond the bound: what reproduces them.

In order: a frozen FMU, a print too coarse for the bound, a fixed-step method (Model Exchange),
an alternative question the values answer (:mod:`pendulum_fmu.judge.explain.alternatives`), for a
file judged as Co-Simulation a Model Exchange run that reproduces it (a fixed-step method,
CVODE at the tolerance), a tolerance other than the experiment's (the FMU's own solver or
CVODE rerun at decades of tolerance).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from pendulum_fmu.fmu.library import exact
from pendulum_fmu.judge import checks
from pendulum_fmu.judge.explain import alternatives, inference
from pendulum_fmu.judge.reading import Result
from pendulum_fmu.judge.verdict import Check, Experiment

TOLERANCES = [10.0 ** -k for k in range(2, 13)]
"""The decades at which the FMU's solver or CVODE is rerun to find the tolerance of a file."""


def frozen(result: Result, names: list[str]) -> str:
    """"theta stays at 1.3963 in all 1001 rows: ..." when some of ``names`` never change, else ""."""
    still = [n for n in names if result.rows > 2 and np.ptp(result.values[n]) == 0]
    if not still:
        return ""
    values = ", ".join(f"{n} stays at {result.values[n][0]:.6g}" for n in still)
    return (f"{values} in all {result.rows} rows: the FMU never advanced (an importer that went on after the FMU "
            "refused a value?)")


def state_fits(ref: checks.Reference, experiment: Experiment, errors: dict[str, np.ndarray]) -> alternatives.Fits:
    """theta and omega fit an alternative when, against it, they are within the bound, and
    their largest error in units of the bound is at most half of what it is against the
    experiment."""
    limits = {name: checks.bound(name, ref, experiment) for name in errors}
    before = max(float(np.max(np.abs(e) / limits[n])) for n, e in errors.items())

    def fits(residuals: alternatives.Columns) -> bool:
        after = max(float(np.max(np.abs(r) / limits[n])) for n, r in residuals.items())
        return after <= min(1.0, 0.5 * before)  # a NaN compares False: no fit
    return fits


def diagnose(result: Result, ref: checks.Reference, experiment: Experiment, errors: dict[str, np.ndarray],
               explained: alternatives.Explanation | None, h: float | None, fmu: Path | None) -> Check | None:
    """Why theta and omega are beyond the bound: what reproduces them."""
    if not errors or not all(np.all(np.isfinite(e)) for e in errors.values()):
        return None
    worst = max(float(np.max(np.abs(e))) for e in errors.values())
    theta_growth = checks.describe_growth(checks.growth(ref.t, next(iter(errors.values()))))
    if explained is not None and explained.cause == "parameters":
        f = explained.numbers
        refit = checks.Reference(ref.t, *exact(f["theta0"], f["omega0"], f["L"], f["g"], ref.t), ref.accumulation)
        against = max(float(np.max(np.abs(e))) for e in checks.state_errors(result, refit).values())
        return Check("diagnosis", "info", f"a different problem, solved to {against:.1e} against its own exact "
                     f"solution: {', '.join(f['changed'])}", {"cause": "parameters", "error_against_fit": against})
    if explained is not None:
        return None  # the exact columns' check names the cause
    still = frozen(result, list(errors))
    if still:
        return Check("diagnosis", "info", still, {"cause": "frozen"})
    if result.formats is not None:
        rounding = {n: checks.print_rounding(result, ref, experiment, n) for n in errors}
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
                                             state_fits(ref, experiment, errors),
                                             max(1e-6, _largest_resolution(result)))
    if found_alternative is not None:
        explanation, _ = found_alternative
        return Check("diagnosis", "info", f"theta and omega: {explanation.line}",
                     {"cause": explanation.cause, **explanation.numbers})
    if experiment.interface == "CS":
        as_me = _model_exchange_run(result, experiment, errors, h, fmu, worst)
        if as_me is not None:
            return as_me
    if fmu is not None and "theta" in errors:
        return _tolerance(result, experiment, errors, fmu, theta_growth)
    return Check("diagnosis", "info", f"no known cause reproduces the error (largest {worst:.1e}, {theta_growth})",
                 {"cause": None})


REPRODUCED = 0.1
"""A rerun reproduces a file when it agrees with its values to this fraction of their largest error."""


def _model_exchange_run(result: Result, experiment: Experiment, errors: dict[str, np.ndarray], h: float | None,
                        fmu: Path | None, worst: float) -> Check | None:
    """A file judged as Co-Simulation that a Model Exchange run reproduces: a fixed-step method
    at the file's step (rerun row for row), or CVODE at the experiment's tolerance (its values
    within :data:`REPRODUCED` of the error). None when neither does."""
    import dataclasses

    as_me = dataclasses.replace(experiment, interface="ME", solver=None)
    if h is not None:
        found = inference.identify_fixed_step(result, as_me, h, worst)
        if found is not None:
            return Check("diagnosis", "info", f"this is a Model Exchange run of {found.method} at h = {found.step:g} "
                         f"(reproduced to {found.agreement:.1e}), judged as Co-Simulation: {found.method} with a "
                         "fixed step ignores the tolerance; judge it with --interface ME",
                         {"cause": "model exchange", "method": found.method, "step": found.step,
                          "agreement": found.agreement})
    if fmu is None or "theta" not in errors:
        return None
    theta_error = float(np.max(np.abs(errors["theta"])))
    agreement = inference.cvode_agreement(fmu, result, as_me)
    if agreement is None or not agreement <= REPRODUCED * theta_error:
        return None
    return Check("diagnosis", "info", f"this is a Model Exchange run of CVODE at tolerance {experiment.tolerance:g} "
                 f"(fmpy's CVODE reproduces theta to {agreement:.1e}, its error is {theta_error:.1e}), judged as "
                 "Co-Simulation, whose bound is the FMU's certificate: judge it with --interface ME",
                 {"cause": "model exchange", "method": "CVODE", "agreement": agreement})


def fixed_step_within_bound(result: Result, experiment: Experiment, errors: dict[str, np.ndarray],
                             h: float | None) -> list[Check]:
    """A fixed-step method that reproduces a Model Exchange file whose error is far beyond what
    the tolerance asks of one period (ME_FACTOR tol), though within the bound's growth: the
    importer's solver ignores the tolerance, however near the separatrix the bound is loose."""
    if h is None or not errors:
        return []
    worst = max(float(np.max(np.abs(e))) for e in errors.values())
    if not worst > checks.ME_FACTOR * experiment.tolerance * max(1.0, abs(experiment.problem.theta0)):
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
