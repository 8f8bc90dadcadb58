"""The judge: is an importer's result of Pendulum.fmu right, and if not, what is wrong?

::

    import math
    from pendulum_fmu.judge import judge
    verdict = judge("result.csv", start={"theta": math.radians(80), "tolerance": 1e-6}, interface="ME")
    print(verdict.line)          # PASS: ... or FAIL (...): ...
    for check in verdict.checks:
        print(check.name, check.status, check.line)

Read top-down: ``judge`` (the one entry: read, build the experiment, decide the step, check,
explain, return the verdict); ``reading`` (CSV, Parquet, tables) with ``print_format`` (each
cell's rounding); ``experiment`` (the caller's values over a file's over the defaults) with
``experiment_files`` (the result's record, a cross-check ``_ref.opt``, an FMI-LS-REF ``.exp``);
``checks`` (grid, exact columns, errors, isolated values, bound) with ``sensitivity`` (the
Model Exchange bound's growth); ``explain/`` (what a failing file is right for instead:
``alternatives``, ``inference``, ``fixed_step``, ``diagnosis``); ``fmpy_validation`` (fmpy's
cross-check band, reported, never deciding); ``verdict`` (the dataclasses); ``report`` (text,
JSON, plot); ``cross_check_verdict`` (the cross-check's passed/failed/rejected file).
"""

from pendulum_fmu.judge.experiment_files import ExperimentFile
from pendulum_fmu.judge.judge import judge
from pendulum_fmu.judge.reading import ReadError
from pendulum_fmu.judge.verdict import Check, Experiment, Series, Verdict

__all__ = ["Check", "Experiment", "ExperimentFile", "ReadError", "Series", "Verdict", "judge"]
