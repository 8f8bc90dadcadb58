"""Both split FMUs through fmpy (``FMU2Slave``/``FMU3Slave``), extracted once per file and version.

A :class:`Pair` is one fresh instance of each, initialized with the problem's parameters and
start values; :meth:`Pair.close` frees them. Value references are the model descriptions'
(docs/split.md): L 1, g 2, theta 3, omega 5, theta_exact 7, omega_exact 8, alpha 16.
"""

from __future__ import annotations

import atexit
import shutil
import tempfile
from functools import lru_cache
from pathlib import Path
from typing import Any

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave
from fmpy.fmi3 import FMU3Slave

from pendulum_fmu.spec import InitialValueProblem
from pendulum_fmu.split.locate import split_fmus

L, G, THETA, OMEGA, THETA_EXACT, OMEGA_EXACT, ALPHA = 1, 2, 3, 5, 7, 8, 16
"""The value references both FMUs share."""
DEFAULT_PROBLEM = InitialValueProblem(theta0=1.3089969389957472, omega0=0.0, L=1.0, g=9.81)
"""The problem both FMUs and the SSP start with: 75 deg from rest, L = 1 m, g = 9.81 m/s^2
(the start values of their model descriptions)."""


@lru_cache(maxsize=8)
def _extracted(path: str, mtime_ns: int) -> tuple[str, str, str]:
    """The unzipped folder, model identifier and guid/instantiation token of an FMU file."""
    folder = tempfile.mkdtemp(prefix="pendulum-split-")
    atexit.register(shutil.rmtree, folder, True)
    md = read_model_description(path)
    return extract(path, folder), md.coSimulation.modelIdentifier, md.guid


class Pair:
    """``PendulumBody`` and ``PendulumGravity``, instantiated and initialized for ``problem``.

    Parameters
    ----------
    problem : InitialValueProblem
        Parameters (L, g, the same in both FMUs) and start values (Body's theta0 and omega0;
        Gravity's input starts at theta0).
    fmi_version : {2, 3}
        Which FMUs (:func:`pendulum_fmu.split.locate.split_fmus`).
    fmus : tuple of Path, optional
        Body's and Gravity's files instead of the ones found.
    """

    def __init__(self, problem: InitialValueProblem, fmi_version: int = 2,
                 fmus: tuple[Path, Path] | None = None) -> None:
        self.v3 = fmi_version == 3
        self.instances: list[Any] = []
        for name, path in zip(("Body", "Gravity"), fmus or split_fmus(fmi_version), strict=True):
            folder, identifier, token = _extracted(str(path), path.stat().st_mtime_ns)
            cls = FMU3Slave if self.v3 else FMU2Slave
            fmu = cls(unzipDirectory=folder, modelIdentifier=identifier, instanceName=name, guid=token)
            fmu.instantiate()
            self.instances.append(fmu)
            if self.v3:
                fmu.enterInitializationMode(startTime=0.0)
            else:
                fmu.setupExperiment(startTime=0.0)
                fmu.enterInitializationMode()
            self.set(fmu, L, problem.L)
            self.set(fmu, G, problem.g)
        self.body, self.gravity = self.instances
        self.set(self.body, THETA, problem.theta0)
        self.set(self.body, OMEGA, problem.omega0)
        self.set(self.gravity, THETA, problem.theta0)
        for fmu in self.instances:
            fmu.exitInitializationMode()

    def get(self, fmu: Any, vr: int) -> float:
        """One real value."""
        return float((fmu.getFloat64 if self.v3 else fmu.getReal)([vr])[0])

    def get_all(self, fmu: Any, vrs: list[int]) -> list[float]:
        """Several real values in one call (a master's row reads Body's four outputs so)."""
        return [float(v) for v in (fmu.getFloat64 if self.v3 else fmu.getReal)(vrs)]

    def set(self, fmu: Any, vr: int, value: float) -> None:
        """Set one real value."""
        (fmu.setFloat64 if self.v3 else fmu.setReal)([vr], [float(value)])

    def derivatives(self, fmu: Any, vr: int) -> list[float]:
        """The output's first and second time derivatives (FMI 2.0 only)."""
        return list(fmu.getRealOutputDerivatives([vr, vr], [1, 2]))

    def set_derivatives(self, fmu: Any, vr: int, first: float, second: float) -> None:
        """The input's first and second time derivatives at this communication point (FMI 2.0 only)."""
        fmu.setRealInputDerivatives([vr, vr], [1, 2], [float(first), float(second)])

    def step(self, fmu: Any, t: float, h: float, rollback: bool = False) -> None:
        """One communication step of one FMU; ``rollback``: the master may set a state from before it."""
        fmu.doStep(currentCommunicationPoint=t, communicationStepSize=h, noSetFMUStatePriorToCurrentPoint=not rollback)

    def save(self) -> list[Any]:
        """Both FMUs' states now (``GetFMUstate``), to :meth:`restore` and :meth:`free`."""
        return [fmu.getFMUState() for fmu in self.instances]

    def restore(self, states: list[Any]) -> None:
        """Both FMUs back to the states :meth:`save` took (``SetFMUstate``)."""
        for fmu, state in zip(self.instances, states, strict=True):
            fmu.setFMUState(state)

    def free(self, states: list[Any]) -> None:
        """Free the states :meth:`save` took (``FreeFMUstate``)."""
        for fmu, state in zip(self.instances, states, strict=True):
            fmu.freeFMUState(state)

    def close(self) -> None:
        """Terminate and free both instances (one in the Error state, which cannot terminate, is freed)."""
        from fmpy.fmi1 import FMICallException

        for fmu in self.instances:
            try:
                fmu.terminate()
            except FMICallException:
                pass
            finally:
                fmu.freeInstance()
        self.instances = []

    def __enter__(self) -> Pair:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
