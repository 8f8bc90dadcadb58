"""The judge: is an importer's result of Pendulum.fmu right, and if not, what is wrong?

::

    from pendulum_fmu.judge import judge
    verdict = judge("result.csv", start=["theta=1.4", "tolerance=1e-6"], interface="ME")
    print(verdict.line)          # PASS: ... or FAIL (...): ...
    for check in verdict.checks:
        print(check.name, check.status, check.line)

Modules: ``reading`` (CSV, Parquet, tables) with ``print_format`` (each cell's rounding),
``experiment`` (start values and defaults) with ``standard_files`` (a cross-check ``_ref.opt``,
an FMI-LS-REF ``.exp``), ``checks`` (grid, exact columns, errors, isolated values, bound) with
``sensitivity`` (the Model Exchange bound's growth), ``alternatives`` (what else the values are
right for), ``fixed_step`` and ``inference`` (fixed-step methods, parameter fit, tolerance
reruns), ``diagnosis`` (why the bound failed), ``band`` (fmpy's cross-check rule), ``verdict``
(the dataclasses), ``report`` (text, JSON, plot), ``judge`` (the whole run).
"""

from pendulum_fmu.judge.judge import judge
from pendulum_fmu.judge.reading import ReadError
from pendulum_fmu.judge.verdict import Check, Experiment, Verdict

__all__ = ["Check", "Experiment", "ReadError", "Verdict", "judge"]
