"""fmpy's CVODE on the FMU's Model Exchange interface with and without the FMU's Jacobian.

fmpy's :class:`~fmpy.sundials.CVodeSolver` (BDF, dense linear solver) approximates the
Jacobian by difference quotients of the right-hand side. This module runs that same solver
twice on the same FMU instance's equations: as fmpy sets it up, and with a Jacobian function
(``CVodeSetJacFn``) that asks the FMU for its exact partial derivatives
(fmi3GetDirectionalDerivative / fmi2GetDirectionalDerivative, one column per state). It
prints CVODE's counts (steps, right-hand-side evaluations, of which for difference-quotient
Jacobians, Jacobian evaluations) and the largest deviation of theta from theta_exact.

``pendulum-fmu bench fmi-versions`` prints the table for the FMI 2.0 and the FMI 3.0 FMU.
"""

from __future__ import annotations

import math
from ctypes import CFUNCTYPE, POINTER, byref, c_double, c_int, c_long, c_void_p
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Model
from fmpy.fmi3 import FMU3Model
from fmpy.sundials import CVodeSolver
from fmpy.sundials.libraries import sundials_cvode, sundials_sunmatrixdense
from fmpy.sundials.nvector_serial import NV_DATA_S
from fmpy.sundials.sundials_nvector import N_Vector

THETA, DER_THETA, OMEGA, DER_OMEGA, THETA_EXACT = 3, 4, 5, 6, 7

# int (*CVLsJacFn)(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix Jac, void *user_data,
#                  N_Vector tmp1, N_Vector tmp2, N_Vector tmp3)   (CVODE's cvode_ls.h)
JacobianFunction = CFUNCTYPE(c_int, c_double, N_Vector, N_Vector, c_void_p, c_void_p, N_Vector, N_Vector,
                             N_Vector)
sundials_cvode.CVodeSetJacFn.argtypes = [c_void_p, JacobianFunction]
sundials_sunmatrixdense.SUNDenseMatrix_Data.argtypes = [c_void_p]
sundials_sunmatrixdense.SUNDenseMatrix_Data.restype = POINTER(c_double)
COUNTERS = ("CVodeGetNumSteps", "CVodeGetNumRhsEvals", "CVodeGetNumLinRhsEvals", "CVodeGetNumJacEvals")


@dataclass
class CvodeRun:
    """One CVODE run's counts and error.

    Attributes
    ----------
    jacobian : bool
        Whether the FMU's Jacobian was used.
    steps, rhs_evaluations, difference_quotient_evaluations, jacobian_evaluations : int
        CVODE's counters (right-hand sides for the integration, for difference quotients,
        and Jacobian set-ups).
    max_error : float
        max |theta - theta_exact| over the output points, in rad.
    """

    jacobian: bool
    steps: int
    rhs_evaluations: int
    difference_quotient_evaluations: int
    jacobian_evaluations: int
    max_error: float


class _Problem:
    """The FMU instance in Continuous-Time Mode and the callbacks CVODE calls."""

    def __init__(self, fmu: Path, theta0: float, tolerance: float) -> None:
        md = read_model_description(str(fmu))
        self.fmi3 = md.fmiVersion == "3.0"
        cls = FMU3Model if self.fmi3 else FMU2Model
        token = md.instantiationToken if self.fmi3 else md.guid
        self.model = cls(guid=token, unzipDirectory=extract(str(fmu)), modelIdentifier="Pendulum",
                         instanceName="cvode")
        self.model.instantiate()
        if self.fmi3:
            self.model.enterInitializationMode(tolerance=tolerance, startTime=0.0)
            self.model.setFloat64([THETA], [theta0])
        else:
            self.model.setupExperiment(tolerance=tolerance, startTime=0.0)
            self.model.enterInitializationMode()
            self.model.setReal([THETA], [theta0])
        self.model.exitInitializationMode()
        self.model.enterContinuousTimeMode()

    def get(self, vrs: list[int]) -> list[float]:
        return self.model.getFloat64(vrs) if self.fmi3 else self.model.getReal(vrs)

    def derivatives(self, dx: object, nx: int) -> None:
        if self.fmi3:
            self.model.getContinuousStateDerivatives(dx, nx)
        else:
            self.model.getDerivatives(dx, nx)

    def jacobian(self, t: float, y: object, fy: object, matrix: int, *_: object) -> int:
        """Fills CVODE's dense matrix (column-major) with d der(x) / d x from the FMU."""
        self.model.setTime(t)
        self.model.setContinuousStates(NV_DATA_S(y), 2)
        data = sundials_sunmatrixdense.SUNDenseMatrix_Data(matrix)
        for column, known in enumerate((THETA, OMEGA)):
            partials = self.model.getDirectionalDerivative([DER_THETA, DER_OMEGA], [known], [1.0])
            data[2 * column], data[2 * column + 1] = partials
        return 0


class _NoInput:
    def apply(self, time: float) -> None:  # fmpy's solver calls it; the model has no inputs
        pass


def run_cvode(fmu: Path, use_jacobian: bool, amplitude_deg: float = 85.0, tolerance: float = 1e-8,
              periods: int = 10, points_per_period: int = 50) -> CvodeRun:
    """Integrates the seed case with fmpy's CVODE and returns its counts and error.

    Parameters
    ----------
    fmu : Path
        An FMI 2.0 or FMI 3.0 ``Pendulum.fmu``.
    use_jacobian : bool
        Give CVODE the FMU's exact Jacobian instead of difference quotients.
    amplitude_deg : float
        theta(0) in degrees (omega(0) = 0, L = 1 m, g = 9.81 m/s^2).
    tolerance : float
        CVODE's relative tolerance (absolute: tolerance times the states' nominals, 1).
    periods, points_per_period : int
        Time span and output grid.

    Returns
    -------
    CvodeRun
        CVODE's counters and max |theta - theta_exact|.
    """
    problem = _Problem(fmu, math.radians(amplitude_deg), tolerance)
    model = problem.model
    nominals = model.getNominalsOfContinuousStates
    solver = CVodeSolver(nx=2, nz=0, get_x=model.getContinuousStates, set_x=model.setContinuousStates,
                         get_dx=problem.derivatives, get_z=lambda z, nz: None, get_nominals=nominals,
                         set_time=model.setTime, input=_NoInput(), startTime=0.0, relativeTolerance=tolerance,
                         maxNumSteps=100000)
    if use_jacobian:
        callback = JacobianFunction(problem.jacobian)
        solver.jacobian_ = callback  # kept alive as long as the solver
        assert sundials_cvode.CVodeSetJacFn(solver.cvode_mem, callback) == 0
    period = problem.get([9])[0]
    grid = np.arange(1, periods * points_per_period + 1) * (period / points_per_period)
    error = 0.0
    for t_next in grid:
        _, _, reached = solver.step(0.0, t_next)
        model.setTime(reached)
        theta, theta_exact = problem.get([THETA, THETA_EXACT])
        error = max(error, abs(theta - theta_exact))
    counts = []
    for name in COUNTERS:
        value = c_long(0)
        getattr(sundials_cvode, name)(c_void_p(solver.cvode_mem), byref(value))
        counts.append(value.value)
    model.terminate()
    steps, rhs_evaluations, difference_quotient_evaluations, jacobian_evaluations = counts
    return CvodeRun(use_jacobian, steps, rhs_evaluations, difference_quotient_evaluations, jacobian_evaluations,
                    max_error=error)


def table(fmus: list[Path]) -> list[str]:
    """The lines of the CVODE figure of docs/fmi.md: each FMU without and with its Jacobian."""
    lines = ["FMU                         Jacobian          steps  RHS evals  of which for J  J evals"
             "  max|theta-exact|"]
    for fmu in fmus:
        version = read_model_description(str(fmu)).fmiVersion
        for use_jacobian in (False, True):
            run = run_cvode(fmu, use_jacobian)
            label = "FMU (exact)" if use_jacobian else "difference q."
            lines.append(f"FMI {version:23} {label:15} {run.steps:7} {run.rhs_evaluations:10} "
                         f"{run.difference_quotient_evaluations:15} {run.jacobian_evaluations:8} {run.max_error:17.2e}")
    return lines
