"""Read the FMU's exact solution (``theta_exact``, ``omega_exact``, ``period``) at any times.

The exact solution in the FMU depends only on the start values and the time, so in Model
Exchange no integration is needed: after initialization, ``fmi2SetTime(t)`` followed by
``fmi2GetReal`` returns theta(t) and omega(t) of the analytic solution. :class:`ExactPort`
extracts the FMU once, instantiates it once, and re-initializes it (``fmi2Reset``) for each
new initial state.

Example::

    with ExactPort(fmu_path) as port:
        port.initialize(theta0=1.0, omega0=0.0, length=1.0, gravity=9.81)
        theta, omega = port.evaluate(np.linspace(0.0, 10.0, 101))
"""

from __future__ import annotations

import shutil
from pathlib import Path
from types import TracebackType

import numpy as np
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Model
from fmpy.fmi3 import FMU3Model

VARIABLE_NAMES: tuple[str, ...] = ("L", "g", "theta", "omega", "theta_exact", "omega_exact", "period")
"""The model variables this port uses (value references are looked up by name)."""


class ExactPort:
    """Model Exchange instance of ``Pendulum.fmu`` used as an evaluator of the exact solution.

    Parameters
    ----------
    fmu_path : Path or str
        The ``Pendulum.fmu`` archive.
    instance_name : str
        FMI instance name.

    Attributes
    ----------
    value_references : dict of str to int
        Value reference of each name in :data:`VARIABLE_NAMES`, from modelDescription.xml.
    """

    def __init__(self, fmu_path: Path | str, instance_name: str = "exact_port") -> None:
        self._fmu_path = Path(fmu_path)
        description = read_model_description(str(self._fmu_path))
        if description.modelExchange is None:
            raise ValueError(f"{self._fmu_path} does not support Model Exchange")
        by_name = {variable.name: variable.valueReference for variable in description.modelVariables}
        missing = [name for name in VARIABLE_NAMES if name not in by_name]
        if missing:
            raise ValueError(f"{self._fmu_path} lacks the variables {missing}")
        self.value_references: dict[str, int] = {name: by_name[name] for name in VARIABLE_NAMES}
        self._unzip_dir = Path(extract(str(self._fmu_path)))
        self._fmi3 = str(description.fmiVersion) == "3.0"   # the FMI 3.0 Pendulum.fmu works alike
        self._model = (FMU3Model if self._fmi3 else FMU2Model)(
            guid=description.guid,
            unzipDirectory=str(self._unzip_dir),
            modelIdentifier=description.modelExchange.modelIdentifier,
            instanceName=instance_name,
        )
        self._model.instantiate()
        self._fresh = True          # no call since instantiate: no reset needed
        self._initialized = False
        self._closed = False

    def initialize(
        self,
        theta0: float,
        omega0: float,
        length: float,
        gravity: float,
        start_time: float = 0.0,
    ) -> None:
        """Pose the initial value problem and enter Continuous-Time Mode.

        Parameters
        ----------
        theta0 : float
            Start value of ``theta`` (rad).
        omega0 : float
            Start value of ``omega`` (rad/s).
        length : float
            ``L`` (m), > 0.
        gravity : float
            ``g`` (m/s^2), > 0.
        start_time : float
            Time at which the initial state is posed (``fmi2SetupExperiment``'s start time).

        Raises
        ------
        fmpy.fmi2.FMICallException
            If the FMU rejects the values (e.g. ``L <= 0``).
        """
        self._check_open()
        if not self._fresh:
            self._model.reset()     # back to the instantiated state (also after a failure)
        self._fresh = False
        self._initialized = False
        model = self._model
        vr = self.value_references
        references = [vr["L"], vr["g"], vr["theta"], vr["omega"]]
        values = [float(length), float(gravity), float(theta0), float(omega0)]
        if self._fmi3:
            model.setFloat64(references, values)
            model.enterInitializationMode(startTime=start_time)
            model.exitInitializationMode()
            while model.updateDiscreteStates()[0]:   # Event Mode after initialization, as in 2.0
                pass
        else:
            model.setupExperiment(startTime=start_time)
            model.setReal(references, values)
            model.enterInitializationMode()
            model.exitInitializationMode()
            # Event Mode after initialization: iterate the (trivial) event loop, then leave it.
            while model.newDiscreteStates()[0]:
                pass
        model.enterContinuousTimeMode()
        self._initialized = True

    def evaluate(self, times: np.ndarray | list[float] | float) -> tuple[np.ndarray, np.ndarray]:
        """Exact theta and omega at the given times.

        Parameters
        ----------
        times : array_like
            Times (s); any order, any values (also before the start time).

        Returns
        -------
        theta : numpy.ndarray
            ``theta_exact`` at each time (rad), same shape as ``times``.
        omega : numpy.ndarray
            ``omega_exact`` at each time (rad/s).
        """
        self._check_initialized()
        t = np.asarray(times, dtype=float)
        theta = np.empty(t.shape)
        omega = np.empty(t.shape)
        refs = [self.value_references["theta_exact"], self.value_references["omega_exact"]]
        model = self._model
        get = model.getFloat64 if self._fmi3 else model.getReal
        for index, value in np.ndenumerate(t):
            model.setTime(float(value))
            theta[index], omega[index] = get(refs)
        return theta, omega

    def period(self) -> float:
        """The ``period`` variable: 4 K / w0, the revolution time, or +inf on the separatrix.

        Returns
        -------
        float
            Period in seconds.
        """
        self._check_initialized()
        get = self._model.getFloat64 if self._fmi3 else self._model.getReal
        return float(get([self.value_references["period"]])[0])

    def close(self) -> None:
        """Terminate and free the instance and delete the extracted files (idempotent)."""
        if self._closed:
            return
        self._closed = True
        try:
            if self._initialized:
                self._model.terminate()
            self._model.freeInstance()
        finally:
            shutil.rmtree(self._unzip_dir, ignore_errors=True)

    def __enter__(self) -> ExactPort:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.close()

    def _check_open(self) -> None:
        if self._closed:
            raise RuntimeError("ExactPort is closed")

    def _check_initialized(self) -> None:
        self._check_open()
        if not self._initialized:
            raise RuntimeError("call initialize() first")
