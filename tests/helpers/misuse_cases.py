"""Misuse scenarios of the FMU through fmpy, one per process (run by test_misuse.py).

Usage: ``python misuse_cases.py CASE FMU_PATH``. Prints the FMU's log lines (fmpy's default
logger) and a final line ``RESULT <exception text or OK>``; a crash shows as a bad exit code.
The FMI 3.0 FMU runs the same scenarios through :class:`Fmi3Calls`, which speaks 3.0 in the
words of 2.0 (setReal is fmi3SetFloat64, setupExperiment's arguments go to
fmi3EnterInitializationMode, ...).
"""

from __future__ import annotations

import math
import sys
import zipfile
from collections.abc import Callable
from pathlib import Path
from tempfile import mkdtemp

from fmpy import read_model_description
from fmpy.fmi2 import FMU2Model, FMU2Slave
from fmpy.fmi3 import FMU3Model, FMU3Slave

VR = {"L": 1, "g": 2, "theta": 3, "omega": 5, "theta_exact": 7, "period": 9, "solver": 12}


class Fmi3Calls:
    """An fmpy FMI 3.0 instance with the FMI 2.0 method names the scenarios use."""

    def __init__(self, instance: FMU3Slave | FMU3Model) -> None:
        self.instance = instance
        self.experiment: dict[str, float | None] = {"tolerance": None, "startTime": 0.0}

    def setupExperiment(self, tolerance: float | None = None, startTime: float = 0.0) -> None:
        self.experiment = {"tolerance": tolerance, "startTime": startTime}

    def enterInitializationMode(self) -> None:
        self.instance.enterInitializationMode(**self.experiment)

    def setReal(self, vr: list[int], values: list[float]) -> None:
        self.instance.setFloat64(vr, values)

    def getReal(self, vr: list[int]) -> list[float]:
        return self.instance.getFloat64(vr)

    def setInteger(self, vr: list[int], values: list[int]) -> None:
        self.instance.setInt64(vr, values)  # the Enumeration solver is an Int64 in FMI 3.0

    def __getattr__(self, name: str) -> object:
        return getattr(self.instance, name)


def _slave(fmu: str, cls: type = FMU2Slave) -> FMU2Slave:
    directory = mkdtemp()
    zipfile.ZipFile(fmu).extractall(directory)
    md = read_model_description(fmu)
    if md.fmiVersion == "3.0":
        cls3 = FMU3Model if cls is FMU2Model else FMU3Slave
        instance3 = cls3(guid=md.instantiationToken, unzipDirectory=directory, modelIdentifier="Pendulum",
                         instanceName="misuse")
        instance3.instantiate()
        return Fmi3Calls(instance3)  # type: ignore[return-value]
    instance = cls(guid=md.guid, unzipDirectory=directory, modelIdentifier="Pendulum", instanceName="misuse")
    instance.instantiate()
    return instance


def _initialized(fmu: str) -> FMU2Slave:
    slave = _slave(fmu)
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.exitInitializationMode()
    return slave


def _set_before_init(name: str, value: float) -> Callable[[str], None]:
    def case(fmu: str) -> None:
        slave = _slave(fmu)
        slave.setReal([VR[name]], [value])
    return case


def _length_zero_at_exit(fmu: str) -> None:
    slave = _slave(fmu)
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.setReal([VR["g"]], [1e-320])  # positive, but g / L underflows to 0
    slave.setReal([VR["L"]], [1e10])
    slave.exitInitializationMode()


def _parameter_after_init(fmu: str) -> None:
    _initialized(fmu).setReal([VR["L"]], [2.0])


def _step_zero(fmu: str) -> None:
    _initialized(fmu).doStep(0.0, 0.0)


def _step_negative(fmu: str) -> None:
    _initialized(fmu).doStep(0.0, -0.1)


def _step_wrong_time(fmu: str) -> None:
    _initialized(fmu).doStep(1.0, 0.1)


def _step_after_terminate(fmu: str) -> None:
    slave = _initialized(fmu)
    slave.doStep(0.0, 0.1)
    slave.terminate()
    slave.doStep(0.1, 0.1)


def _step_before_init(fmu: str) -> None:
    _slave(fmu).doStep(0.0, 0.1)


def _unknown_reference(fmu: str) -> None:
    _initialized(fmu).getReal([4242])


def _bad_solver(fmu: str) -> None:
    _slave(fmu).setInteger([VR["solver"]], [99])


def _bad_tolerance(fmu: str) -> None:
    slave = _slave(fmu)
    slave.setupExperiment(tolerance=-1.0, startTime=0.0)  # FMI 2.0 refuses here
    slave.enterInitializationMode()  # FMI 3.0 here (it takes the experiment)


def _wrong_guid(fmu: str) -> None:
    directory = mkdtemp()
    zipfile.ZipFile(fmu).extractall(directory)
    cls = FMU3Slave if read_model_description(fmu).fmiVersion == "3.0" else FMU2Slave
    cls(guid="{00000000-0000-0000-0000-000000000000}", unzipDirectory=directory,
        modelIdentifier="Pendulum", instanceName="misuse").instantiate()


def _me_nan_state(fmu: str) -> None:
    model = _slave(fmu, FMU2Model)
    model.setupExperiment(startTime=0.0)
    model.enterInitializationMode()
    model.exitInitializationMode()
    model.enterContinuousTimeMode()
    model.setContinuousStates(*_array([math.nan, 0.0]))


def _free_state_itself(fmu: str) -> None:
    """The FMU state itself passed to FreeFMUstate where its address belongs (as one importer
    did): refused with an error naming the pointer, never freed."""
    from ctypes import POINTER, c_void_p, cast
    slave = _initialized(fmu)
    if isinstance(slave, Fmi3Calls):
        state = slave.instance.getFMUState()
        slave.instance.fmi3FreeFMUState(slave.instance.component, cast(state, POINTER(c_void_p)))
    else:
        state = slave.getFMUstate()
        slave.fmi2FreeFMUstate(slave.component, cast(state, POINTER(c_void_p)))


def _array(values: list[float]) -> tuple[object, int]:
    from ctypes import c_double
    return (c_double * len(values))(*values), len(values)


CASES: dict[str, Callable[[str], None]] = {
    "L_negative": _set_before_init("L", -1.0),
    "L_zero": _set_before_init("L", 0.0),
    "g_negative": _set_before_init("g", -9.81),
    "L_nan": _set_before_init("L", math.nan),
    "theta_nan": _set_before_init("theta", math.nan),
    "omega_inf": _set_before_init("omega", math.inf),
    "theta_exact_set": _set_before_init("theta_exact", 1.0),
    "period_set": _set_before_init("period", 1.0),
    "g_over_L_underflow": _length_zero_at_exit,
    "parameter_after_init": _parameter_after_init,
    "step_zero": _step_zero,
    "step_negative": _step_negative,
    "step_wrong_time": _step_wrong_time,
    "step_after_terminate": _step_after_terminate,
    "step_before_init": _step_before_init,
    "unknown_reference": _unknown_reference,
    "bad_solver": _bad_solver,
    "bad_tolerance": _bad_tolerance,
    "wrong_guid": _wrong_guid,
    "me_nan_state": _me_nan_state,
    "free_state_itself": _free_state_itself,
}

if __name__ == "__main__":
    name, fmu_path = sys.argv[1], str(Path(sys.argv[2]))
    try:
        CASES[name](fmu_path)
        print("RESULT OK", flush=True)
    except Exception as error:  # noqa: BLE001 - the text is the result
        print(f"RESULT {error}", flush=True)
