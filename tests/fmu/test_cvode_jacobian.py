"""fmpy's CVODE takes the FMU's Jacobian (pendulum-fmu bench fmi-versions): with it,
CVODE evaluates no difference quotients and calls the FMU instead, and its solution is as
accurate as with difference quotients. The figures themselves are docs/fmi.md's, not asserted."""

from __future__ import annotations

from pathlib import Path

from pendulum_fmu.bench.cvode_jacobian import run_cvode


def test_cvode_uses_the_fmus_jacobian(fmu_any: Path) -> None:
    plain = run_cvode(fmu_any, use_jacobian=False, periods=2)
    exact = run_cvode(fmu_any, use_jacobian=True, periods=2)
    assert plain.difference_quotient_evaluations > 0 and exact.difference_quotient_evaluations == 0
    assert exact.jacobian_evaluations > 0
    assert exact.max_error <= 2 * plain.max_error + 1e-12
