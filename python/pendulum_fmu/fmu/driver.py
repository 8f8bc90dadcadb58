"""The Co-Simulation output loop of every run: ``pendulum_driver`` in C, shipped with the package.

fmpy loads and instantiates the FMU (and owns its logger); this module hands the C library
``pendulum_driver`` (``fmu_src/libs/driver_lib/`` of the repository) the instance and the addresses of the
FMU's own ``fmi2DoStep`` / ``fmi2GetReal`` (FMI 2.0) or ``fmi3DoStep`` / ``fmi3GetFloat64``
(FMI 3.0). The library steps from output point to output point and reads every recorded
output straight into the rows of the caller's numpy array, checking every status: no Python
per point. The FMU's log messages still arrive through fmpy's logger while the loop runs (a
ctypes call releases the GIL; the callback takes it back).

Ctrl-C: the loop runs in stretches of about :data:`STRETCH_SECONDS` each, inside
:func:`pendulum_fmu.interrupt.deferred_interrupt` (SIGINT only sets a flag, so that no
``KeyboardInterrupt`` can land inside the FMU's logger callback); after each stretch the flag
is looked at, and an interrupted loop raises :class:`LoopInterrupted` holding how many points
it finished.

Where the library is looked for: ``$PENDULUM_DRIVER_LIB``, the package's ``lib/<platform>/``
(a wheel carries linux64, win64 and darwin64), the repository's ``build/``. Without one the
same loop runs its stretches in Python (:mod:`pendulum_fmu.fmu.python_drive`, the same calls
in the same order), at about a third of the speed; :func:`library_path` says which.
"""

from __future__ import annotations

import ctypes
import time
from collections.abc import Mapping
from functools import lru_cache
from pathlib import Path
from typing import Any, Literal, Protocol

import numpy as np

from pendulum_fmu.errors import BuildError, SimulationError
from pendulum_fmu.fmu.library import c_address, find_library, library_file, load_library, platform_folder
from pendulum_fmu.fmu.log import FmuLog
from pendulum_fmu.fmu.python_drive import Ending, PythonStretch
from pendulum_fmu.interrupt import deferred_interrupt
from pendulum_fmu.interrupt import pending as interrupt_pending

ABI = 1
"""The interface version this module speaks (``PENDULUM_DRIVER_ABI`` in the C header)."""
STRETCH_SECONDS = 0.02
"""Aimed length of one stretch of the loop: how long Ctrl-C may wait."""
FIRST_STRETCH = 256
"""Points in the first stretch of a run (later ones are sized from its time)."""

CALLS = {1: "DoStep", 2: "GetReal", 3: "DoStep", 4: "DoStep", 5: "the loop's arguments"}
STATUS_NAMES = ("OK", "Warning", "Discard", "Error", "Fatal", "Pending")


class LoopInterrupted(KeyboardInterrupt):
    """Ctrl-C stopped the loop; ``done`` rows (from row 0) are filled."""

    def __init__(self, done: int) -> None:
        super().__init__(f"interrupted after {done} output points")
        self.done = done


class _Fmu(ctypes.Structure):
    _fields_ = [("fmi_version", ctypes.c_int), ("instance", ctypes.c_void_p), ("do_step", ctypes.c_void_p),
                ("get_values", ctypes.c_void_p), ("vrs", ctypes.c_void_p), ("nvr", ctypes.c_size_t)]


class _Outcome(ctypes.Structure):
    _fields_ = [("done", ctypes.c_size_t), ("call", ctypes.c_int), ("status", ctypes.c_int),
                ("time", ctypes.c_double)]


def library_name() -> str:
    """The library's file name on this platform."""
    return library_file("pendulum_driver")


def library_path() -> Path | None:
    """The ``pendulum_driver`` library for this platform, or None when there is none.

    Raises
    ------
    BuildError
        If ``$PENDULUM_DRIVER_LIB`` names no file.
    """
    return find_library("pendulum_driver")


@lru_cache(maxsize=1)
def _library() -> ctypes.CDLL | None:
    """The loaded library with its signatures, or None (no library for this platform)."""
    path = library_path()
    if path is None:
        return None
    library = load_library(path, "pendulum_driver", ABI)
    library.pendulum_drive.restype = ctypes.c_int
    library.pendulum_drive.argtypes = [ctypes.POINTER(_Fmu), ctypes.c_void_p, ctypes.c_size_t, ctypes.c_size_t,
                                       ctypes.c_void_p, ctypes.c_size_t, ctypes.POINTER(_Outcome)]
    return library


def available() -> bool:
    """True when the C loop is used (a library for this platform was found and loads)."""
    return _library() is not None


Backend = Literal["c", "python"]
"""Who runs the stretches of a loop: the C library ``pendulum_driver``, or its Python port."""


class Stretch(Protocol):
    """Runs points ``first .. last - 1`` of ``times`` into the rows at ``rows``, ``row_bytes`` apart."""

    def __call__(self, times: np.ndarray, first: int, last: int, rows: int, row_bytes: int) -> Ending: ...


class _CStretch:
    """``pendulum_drive`` of the C library, answering as :class:`PythonStretch` does."""

    def __init__(self, library: ctypes.CDLL, fmu: _Fmu) -> None:
        self._drive = library.pendulum_drive
        self._fmu_struct = fmu   # pendulum_drive reads it at every call
        self._fmu = ctypes.byref(fmu)
        self._outcome = _Outcome()

    def __call__(self, times: np.ndarray, first: int, last: int, rows: int, row_bytes: int) -> Ending:
        outcome = self._outcome
        self._drive(self._fmu, times.ctypes.data, first, last, rows, row_bytes // 8, ctypes.byref(outcome))
        return outcome.call, outcome.done, outcome.status, outcome.time


class OutputLoop:
    """Steps an initialized fmpy Co-Simulation instance (FMI 2.0 or 3.0) over a grid.

    Parameters
    ----------
    instance : fmpy.fmi2.FMU2Slave or fmpy.fmi3.FMU3Slave
        Instantiated and out of initialization mode.
    fmi_version : {2, 3}
        The instance's FMI version.
    value_references : list of int
        The outputs to record at every point, in column order.
    backend : {"c", "python"}
        Who runs the stretches: the C library (BuildError where there is none) or its port
        in Python, :mod:`pendulum_fmu.fmu.python_drive`; the numbers are the same.
    """

    def __init__(self, instance: Any, fmi_version: int, value_references: list[int], backend: Backend = "c") -> None:
        names = ("fmi2DoStep", "fmi2GetReal") if fmi_version == 2 else ("fmi3DoStep", "fmi3GetFloat64")
        self._vrs = np.ascontiguousarray(value_references, dtype=np.uint32)
        self._count = len(value_references)
        fields = (ctypes.cast(instance.component, ctypes.c_void_p).value or 0,
                  c_address(getattr(instance.dll, names[0])), c_address(getattr(instance.dll, names[1])))
        self._stretch: Stretch
        if backend == "python":
            self._stretch = PythonStretch(fmi_version, *fields, self._vrs.ctypes.data, self._count)
            return
        library = _library()
        if library is None:
            raise BuildError(f"no pendulum_driver library for this platform ({platform_folder()[0]})")
        self._stretch = _CStretch(library, _Fmu(fmi_version, *fields, self._vrs.ctypes.data, self._count))

    def run(self, times: np.ndarray, rows: np.ndarray, column: str, log: FmuLog) -> None:
        """Fill ``rows[column ...]`` at ``times[0]`` (the current time), then step to each later time.

        Parameters
        ----------
        times : numpy.ndarray
            Increasing communication points (float64, contiguous); ``times[0]`` is the FMU's time.
        rows : numpy.ndarray
            Structured array of ``len(times)`` records whose fields from ``column`` on are the
            recorded outputs, float64, one after the other.
        column : str
            The field of the first recorded output.
        log : FmuLog
            The instance's log, for the reason of a failed call.

        Raises
        ------
        SimulationError
            If a call returns Discard or worse, or FMI 3.0's DoStep asks to terminate.
        LoopInterrupted
            On Ctrl-C (SIGINT), after the stretch that was running; rows before ``done`` are filled.
        """
        times = np.ascontiguousarray(times, dtype=np.float64)
        offset = self._check_layout(rows, column, len(times))
        base = rows.ctypes.data + offset
        first, count, stretch = 0, len(times), FIRST_STRETCH
        with deferred_interrupt():
            while first < count:
                last = min(count, first + stretch)
                start = time.perf_counter()
                call, done, status, at = self._stretch(times, first, last, base, rows.itemsize)
                if interrupt_pending():   # Ctrl-C wins over a failure in the same stretch: it is what the user did
                    raise LoopInterrupted(done)
                if call:
                    self._fail(call, status, at, log)
                elapsed = time.perf_counter() - start
                stretch = max(16, min(1 << 22, int((last - first) * STRETCH_SECONDS / max(elapsed, 1e-7))))
                first = last

    def _check_layout(self, rows: np.ndarray, column: str, count: int) -> int:
        """Byte offset of ``column`` in a record, after checking the C loop may write there."""
        fields: Mapping[str, Any] = rows.dtype.fields or {}
        names = list(rows.dtype.names or ())
        if rows.shape != (count,) or not rows.flags.c_contiguous or column not in fields or rows.itemsize % 8:
            raise ValueError("rows must be a contiguous structured array of one record per time")
        start = names.index(column)
        offset = int(fields[column][1])
        for k, name in enumerate(names[start:start + self._count]):
            dtype, at = fields[name][:2]
            if dtype != np.float64 or at != offset + 8 * k:
                raise ValueError(f"field {name!r} is not the float64 right after the previous recorded one")
        if len(names) < start + self._count:
            raise ValueError("rows have fewer fields than recorded outputs")
        return offset

    @staticmethod
    def _fail(call: int, status: int, at: float, log: FmuLog) -> None:
        """SimulationError naming the call, the time and the FMU's logged reason."""
        if call == 3:
            raise SimulationError(f"fmi3DoStep asked to terminate the simulation at t = {at:.9g} s")
        if call == 4:
            raise SimulationError(f"fmi3DoStep returned early at t = {at:.9g} s (not allowed)")
        if call == 5:
            raise SimulationError("the C loop was given a bad argument")
        name = STATUS_NAMES[status] if 0 <= status < len(STATUS_NAMES) else str(status)
        reason = log.last_error()
        raise SimulationError(f"{CALLS[call]} at t = {at:.9g} s returned {name}" + (f": {reason}" if reason else ""))
