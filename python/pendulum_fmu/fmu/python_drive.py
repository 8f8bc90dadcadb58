"""``pendulum_drive`` in plain Python: the output loop where the C library is not installed.

The same calls as ``fmu_src/libs/driver_lib/pendulum_driver.c``, in the same order, through ctypes
prototypes of the FMU's own functions, so that a run gives the same numbers bit for bit
(``tests/fmu/test_driver.py`` checks it): per point, DoStep from the previous time (none at point
0) and one GetReal (FMI 2.0) or GetFloat64 (FMI 3.0) of every recorded output straight into
the row. Every status is checked as the C loop checks it; :class:`PythonStretch` answers
what ``pendulum_drive`` writes into its outcome. The arguments of each call are plain
integers and floats (the instance, the addresses of the value references, of the row and of
FMI 3.0's flags), so ctypes converts nothing per call: about a third of the C loop's speed
(``pendulum-fmu bench speed`` measures both).
"""

from __future__ import annotations

import ctypes

import numpy as np

NONE, DO_STEP, GET, TERMINATE, EARLY = 0, 1, 2, 3, 4
"""How a stretch ended: ``enum pendulum_drive_call`` of ``pendulum_driver.h``."""
WARNING = 1
"""fmi2Warning == fmi3Warning: it goes on; OK is 0, the worse statuses are larger."""

_FMI2_DO_STEP = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_int)
"""fmi2DoStep(c, currentCommunicationPoint, communicationStepSize, noSetFMUStatePriorToCurrentPoint)."""
_FMI2_GET_REAL = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p)
"""fmi2GetReal(c, vr[], nvr, value[])."""
_FMI3_DO_STEP = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_double, ctypes.c_double, ctypes.c_bool,
                                 ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p)
"""fmi3DoStep(instance, currentCommunicationPoint, communicationStepSize, noSetFMUStatePriorToCurrentPoint,
&eventHandlingNeeded, &terminateSimulation, &earlyReturn, &lastSuccessfulTime)."""
_FMI3_GET_FLOAT64 = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t, ctypes.c_void_p,
                                     ctypes.c_size_t)
"""fmi3GetFloat64(instance, vr[], nvr, values[], nValues)."""

Ending = tuple[int, int, int, float]
"""How a stretch ended: (call, rows done, the failing call's status, its communication point)."""


class PythonStretch:
    """Runs a stretch of the output grid like ``pendulum_drive``, from Python.

    Parameters
    ----------
    fmi_version : {2, 3}
        The instance's FMI version.
    instance : int
        The address of the fmi2Component / fmi3Instance.
    do_step, get_values : int
        The addresses of the FMU's DoStep and GetReal (2.0) or GetFloat64 (3.0).
    vrs : int
        The address of the ``uint32`` value references of the recorded outputs.
    nvr : int
        How many.
    """

    def __init__(self, fmi_version: int, instance: int, do_step: int, get_values: int, vrs: int, nvr: int) -> None:
        self._fmi3 = fmi_version == 3
        self._instance, self._vrs, self._nvr = instance, vrs, nvr
        if self._fmi3:
            self._do_step = _FMI3_DO_STEP(do_step)
            self._get = _FMI3_GET_FLOAT64(get_values)
        else:
            self._do_step = _FMI2_DO_STEP(do_step)
            self._get = _FMI2_GET_REAL(get_values)
        self._flags = (ctypes.c_bool * 3)()   # eventHandlingNeeded, terminateSimulation, earlyReturn
        self._reached = ctypes.c_double()

    def __call__(self, times: np.ndarray, first: int, last: int, rows: int, row_bytes: int) -> Ending:
        """Run points ``first .. last - 1`` of ``times``; row k is at address ``rows + k * row_bytes``.

        Point 0 is read without a step (the FMU stands at ``times[0]``); every later point k
        steps from ``times[k - 1]`` by ``times[k] - times[k - 1]``.

        Returns
        -------
        tuple
            (call, done, status, time) as ``pendulum_drive`` leaves its outcome.
        """
        if first == last:
            return NONE, first, 0, float(times[first - 1]) if first > 0 else 0.0
        points = times[max(first - 1, 0):last].tolist()   # Python floats: doubles, as C reads them
        offset = max(first - 1, 0)
        if self._fmi3:
            return self._fmi3_stretch(points, offset, first, last, rows, row_bytes)
        instance, vrs, nvr, do_step, get = self._instance, self._vrs, self._nvr, self._do_step, self._get
        for k in range(first, last):
            if k > 0:
                t0 = points[k - 1 - offset]
                status = do_step(instance, t0, points[k - offset] - t0, 1)
                if status > WARNING:
                    return DO_STEP, k, status, t0
            status = get(instance, vrs, nvr, rows + k * row_bytes)
            if status > WARNING:
                return GET, k, status, points[k - offset]
        return NONE, last, 0, points[-1]

    def _fmi3_stretch(self, points: list[float], offset: int, first: int, last: int, rows: int,
                      row_bytes: int) -> Ending:
        """:meth:`__call__` for FMI 3.0: DoStep's terminate and early-return flags stop it too."""
        instance, vrs, nvr, do_step, get = self._instance, self._vrs, self._nvr, self._do_step, self._get
        flags, reached = self._flags, self._reached
        base = ctypes.addressof(flags)
        event, terminate, early = base, base + ctypes.sizeof(ctypes.c_bool), base + 2 * ctypes.sizeof(ctypes.c_bool)
        reached_at = ctypes.addressof(reached)
        for k in range(first, last):
            if k > 0:
                t0 = points[k - 1 - offset]
                flags[0] = flags[1] = flags[2] = False
                reached.value = t0
                status = do_step(instance, t0, points[k - offset] - t0, True, event, terminate, early, reached_at)
                if status > WARNING:
                    return DO_STEP, k, status, t0
                if flags[1]:
                    return TERMINATE, k, status, reached.value
                if flags[2]:
                    return EARLY, k, status, reached.value
            status = get(instance, vrs, nvr, rows + k * row_bytes, nvr)
            if status > WARNING:
                return GET, k, status, points[k - offset]
        return NONE, last, 0, points[-1]
