"""The Co-Simulation output loop in Python: the fallback of the C loop, and its reference.

:class:`~pendulum_fmu.fmu.runner.FmuRunner` uses the C library of :mod:`pendulum_fmu.fmu.driver`
when there is one (about 2.3x faster, the same results bit for bit); this loop runs where
there is none, with ``FmuRunner(fmu, loop="python")``, and in the tests as the reference.

Per output point: one ``fmi2DoStep`` and one ``fmi2GetReal`` for all recorded outputs, both
called through ctypes prototypes of the FMU's own functions whose arguments are plain
integers and floats (the component and the addresses of a prebuilt value-reference array and
of the result row), so that ctypes converts nothing per call; ``fmi2GetReal`` writes straight
into the numpy result. fmpy's wrappers add, per call, argument conversion, status checks and
logging in Python: about twice the cost (``pendulum-fmu bench speed`` measures both).
"""

from __future__ import annotations

import ctypes
from typing import Any

import numpy as np

from pendulum_fmu.errors import SimulationError
from pendulum_fmu.fmu.library import c_address
from pendulum_fmu.fmu.log import FMI2_WARNING, FmuLog
from pendulum_fmu.interrupt import check, flag

_DO_STEP = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_int)
"""fmi2DoStep(c, currentCommunicationPoint, communicationStepSize, noSetFMUStatePriorToCurrentPoint)."""
_GET_REAL = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p)
"""fmi2GetReal(c, vr[], nvr, value[])."""
STATUS_NAMES = ("fmi2OK", "fmi2Warning", "fmi2Discard", "fmi2Error", "fmi2Fatal", "fmi2Pending")


class FastStepper:
    """Steps an initialized fmpy ``FMU2Slave`` over a time grid and records outputs.

    Parameters
    ----------
    slave : fmpy.fmi2.FMU2Slave
        Instantiated and out of initialization mode.
    value_references : list of int
        The outputs to record at every point, in column order.
    """

    def __init__(self, slave: Any, value_references: list[int]) -> None:
        self._component = int(ctypes.cast(slave.component, ctypes.c_void_p).value or 0)
        self._do_step = _DO_STEP(c_address(slave.dll.fmi2DoStep))
        self._get_real = _GET_REAL(c_address(slave.dll.fmi2GetReal))
        self._vrs = np.ascontiguousarray(value_references, dtype=np.uint32)  # fmi2ValueReference
        self._count = len(value_references)

    def run(self, times: np.ndarray, log: FmuLog) -> np.ndarray:
        """Record the outputs at ``times[0]`` (the current time), then step to each later time.

        Parameters
        ----------
        times : numpy.ndarray
            Increasing communication points; ``times[0]`` is the FMU's current time.
        log : FmuLog
            The instance's log, for the reason of a failed call.

        Returns
        -------
        numpy.ndarray
            ``(len(times), len(value_references))`` values.

        Raises
        ------
        SimulationError
            If a call returns fmi2Discard or worse (fmi2Warning is kept in the log only).
        """
        values = np.empty((len(times), self._count))
        component, vrs, count = self._component, self._vrs.ctypes.data, self._count
        do_step, get_real = self._do_step, self._get_real
        row, stride = values.ctypes.data, values.strides[0]
        status = get_real(component, vrs, count, row)
        self._check(status, "fmi2GetReal", float(times[0]), log)
        previous = float(times[0])
        interrupted = flag()  # Ctrl-C during the run (pendulum_fmu.interrupt): stop at the next point
        for k in range(1, len(times)):
            if interrupted[0]:
                check()
            current = float(times[k])
            status = do_step(component, previous, current - previous, 1)
            if status > FMI2_WARNING:
                self._check(status, "fmi2DoStep", previous, log)
            status = get_real(component, vrs, count, row + k * stride)
            if status > FMI2_WARNING:
                self._check(status, "fmi2GetReal", current, log)
            previous = current
        return values

    @staticmethod
    def _check(status: int, call: str, at: float, log: FmuLog) -> None:
        """SimulationError naming the call, the time and the FMU's logged reason."""
        if status <= FMI2_WARNING:
            return
        name = STATUS_NAMES[status] if 0 <= status < len(STATUS_NAMES) else str(status)
        reason = log.last_error()
        raise SimulationError(f"{call} at t = {at:.9g} s returned {name}" + (f": {reason}" if reason else ""))
