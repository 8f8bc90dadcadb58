"""Load the FMU once and run many initial value problems on it.

:class:`FmuRunner` extracts ``Pendulum.fmu`` once, instantiates one Co-Simulation slave
and (if needed) one Model Exchange model, and resets them between runs: a sweep worker
pays the unzip and ``dlopen`` once, not once per run.

Co-Simulation runs are driven by :class:`~pendulum_fmu.fmu.fast_cs.FastStepper`: the
FMU's own ``fmi2DoStep`` and one ``fmi2GetReal`` of every recorded output per point, called
through ctypes prototypes with prebuilt arguments, the values landing straight in the result
array (the fastest path that stays inside the FMI API). Model Exchange runs go through fmpy's
``simulate_fmu`` with its CVODE solver, on the already instantiated model.

Every message the FMU logs with status fmi2Warning during a run (for example its
"hard case:" warning) is kept in :attr:`Trajectory.warnings`.
"""

from __future__ import annotations

import math
import shutil
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from types import TracebackType
from typing import Self

import numpy as np
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi2 import FMU2Model, FMU2Slave

from pendulum_fmu.errors import SimulationError
from pendulum_fmu.fmu.fast_cs import FastStepper
from pendulum_fmu.interrupt import deferred_interrupt
from pendulum_fmu.interrupt import pending as interrupt_pending
from pendulum_fmu.fmu.log import FmuLog, register, shared_callbacks, unique_instance_name, unregister
from pendulum_fmu.spec import CS_SOLVERS, Method, Pendulum, TimeGrid

RECORDED: tuple[str, ...] = ("theta", "omega", "theta_exact", "omega_exact", "x", "y")
"""Outputs recorded at every output point, besides time."""

STATS: tuple[str, ...] = ("stats.steps", "stats.rejected_steps", "stats.rhs_evaluations")

DEFAULT_METHOD = Method()
"""The FMU's default solver (rkn) at its default tolerance."""
DEFAULT_GRID = TimeGrid()
"""Ten exact periods, 50 output points a period."""


@dataclass
class Trajectory:
    """One run: its inputs, the recorded outputs and what it cost.

    Attributes
    ----------
    pendulum, method, grid
        What was run.
    period : float
        The FMU's exact ``period`` output, s (``inf`` on the separatrix).
    result : numpy.ndarray
        Structured array with ``time`` and the fields of :data:`RECORDED`.
    steps, rejected_steps, rhs_evaluations : int or None
        The Co-Simulation solver's counters; None in Model Exchange.
    wall_time : float
        Seconds spent in the run (initialization to the last output).
    warnings : tuple of str
        The messages the FMU logged with status fmi2Warning during the run, in order.
    """

    pendulum: Pendulum
    method: Method
    grid: TimeGrid
    period: float
    result: np.ndarray = field(repr=False)
    steps: int | None
    rejected_steps: int | None
    rhs_evaluations: int | None
    wall_time: float
    warnings: tuple[str, ...] = ()

    @property
    def theta_error(self) -> np.ndarray:
        """theta - theta_exact at the output points, rad."""
        return self.result["theta"] - self.result["theta_exact"]

    @property
    def max_error(self) -> float:
        """max |theta - theta_exact| over the output points, rad."""
        return float(np.max(np.abs(self.theta_error)))

    @property
    def max_omega_error(self) -> float:
        """max |omega - omega_exact| over the output points, rad/s."""
        return float(np.max(np.abs(self.result["omega"] - self.result["omega_exact"])))


def reference_period(period: float, pendulum: Pendulum) -> float:
    """The period a time grid counts in: the exact one, or T0 where that is infinite or 0."""
    return period if math.isfinite(period) and period > 0 else pendulum.small_angle_period


class FmuRunner:
    """An extracted, instantiated FMU that runs one problem after another.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.

    Notes
    -----
    Not thread-safe: use one runner per thread. Use it as a context manager, or call
    :meth:`close`, to free the instances and delete the extracted files.
    """

    def __init__(self, fmu: Path) -> None:
        self.fmu = Path(fmu)
        self._tempdir = tempfile.mkdtemp(prefix="pendulum-fmu-")
        try:
            self._unzipdir = extract(str(self.fmu), unzipdir=self._tempdir)
            self.model_description = read_model_description(self._unzipdir, validate=False)
        except BaseException as error:  # nothing left behind: not even on Ctrl-C
            shutil.rmtree(self._tempdir, ignore_errors=True)
            if isinstance(error, Exception):  # a broken archive or modelDescription.xml (lxml, KeyError, ...)
                raise SimulationError(f"cannot read {self.fmu} as an FMU: {error}") from error
            raise
        self.vr: dict[str, int] = {v.name: v.valueReference for v in self.model_description.modelVariables}
        self._slave: FMU2Slave | None = None
        self._model: FMU2Model | None = None
        self._slave_used = False
        self._model_used = False
        self._log = FmuLog()

    def __enter__(self) -> Self:
        return self

    def __exit__(self, kind: type[BaseException] | None, error: BaseException | None,
                 trace: TracebackType | None) -> None:
        self.close()

    def close(self) -> None:
        """Free the FMU instances and delete the extracted files."""
        for instance in (self._slave, self._model):
            if instance is not None:
                unregister(instance.instanceName)
                instance.freeInstance()
        self._slave = self._model = None
        shutil.rmtree(self._tempdir, ignore_errors=True)

    # -- instances ---------------------------------------------------------------------------
    def _fresh_slave(self) -> FMU2Slave:
        if self._slave is None:
            md = self.model_description
            self._slave = FMU2Slave(guid=md.guid, unzipDirectory=self._unzipdir,
                                    modelIdentifier=md.coSimulation.modelIdentifier,
                                    instanceName=unique_instance_name("pendulum_cs"))
            register(self._slave.instanceName, self._log)   # before instantiate: it may log already
            self._slave.instantiate(callbacks=shared_callbacks())
        elif self._slave_used:
            self._slave.reset()
        self._slave_used = True
        return self._slave

    def _fresh_model(self) -> FMU2Model:
        if self._model is None:
            md = self.model_description
            self._model = FMU2Model(guid=md.guid, unzipDirectory=self._unzipdir,
                                    modelIdentifier=md.modelExchange.modelIdentifier,
                                    instanceName=unique_instance_name("pendulum_me"))
            register(self._model.instanceName, self._log)
            self._model.instantiate(callbacks=shared_callbacks())
        elif self._model_used:
            self._model.reset()
        self._model_used = True
        return self._model

    def _initialize(self, instance: FMU2Slave | FMU2Model, pendulum: Pendulum, method: Method) -> float:
        """setupExperiment, start values, initialization; returns the FMU's ``period``."""
        instance.setupExperiment(tolerance=method.effective_tolerance, startTime=0.0)
        values = pendulum.start_values()
        instance.setReal([self.vr[name] for name in values], list(values.values()))
        if method.interface == "CS":
            instance.setInteger([self.vr["solver"]], [CS_SOLVERS.index(method.solver) + 1])
        instance.enterInitializationMode()
        instance.exitInitializationMode()
        return float(instance.getReal([self.vr["period"]])[0])

    # -- runs --------------------------------------------------------------------------------
    def period(self, pendulum: Pendulum) -> float:
        """The FMU's exact ``period`` for this problem, s (``inf`` on the separatrix)."""
        try:
            with deferred_interrupt():
                slave = self._fresh_slave()  # loading the binary may fail too (another model, another platform)
                value = self._initialize(slave, pendulum, DEFAULT_METHOD)
                slave.terminate()
        except Exception as error:  # fmpy raises FMICallException, ctypes may raise OSError
            raise SimulationError(f"the FMU failed to initialize {pendulum}: {self._reason(error)}") from error
        return value

    def run(self, pendulum: Pendulum, method: Method = DEFAULT_METHOD, grid: TimeGrid = DEFAULT_GRID) -> Trajectory:
        """Simulate one problem.

        Parameters
        ----------
        pendulum : Pendulum
            Parameters and initial state.
        method : Method
            Solver and tolerance (``cvode`` runs in Model Exchange).
        grid : TimeGrid
            Output points and stop time.

        Returns
        -------
        Trajectory
            Outputs at every point of the grid and the solver's cost.

        Raises
        ------
        SimulationError
            If an FMI call fails.
        """
        try:
            with deferred_interrupt():  # Ctrl-C inside a ctypes callback would be lost
                if method.interface == "CS":
                    return self._run_cs(pendulum, method, grid)
                return self._run_me(pendulum, method, grid)
        except SimulationError:
            raise
        except MemoryError:
            raise SimulationError(f"{method.label} on {pendulum}: not enough memory for the output points "
                                  "of this run: fewer periods or points per period") from None
        except Exception as error:  # fmpy raises FMICallException or a plain Exception
            raise SimulationError(f"{method.label} failed on {pendulum}: {self._reason(error)}") from error

    def _reason(self, error: Exception) -> str:
        """The error's text, followed by what the FMU logged as its reason (one line)."""
        text = str(error).strip() or type(error).__name__
        logged = self._log.last_error()
        if logged and logged not in text:
            call, _, rest = logged.partition(": ")  # "fmi2ExitInitializationMode: why", the call named already
            text = f"{text.rstrip('.')}: {rest if rest and call in text else logged}"
        return " ".join(text.split())

    def _run_cs(self, pendulum: Pendulum, method: Method, grid: TimeGrid) -> Trajectory:
        start = time.perf_counter()
        slave = self._fresh_slave()
        self._log.clear()
        period = self._initialize(slave, pendulum, method)
        times = grid.times(reference_period(period, pendulum))
        values = FastStepper(slave, [self.vr[name] for name in RECORDED]).run(times, self._log)
        steps, rejected, rhs = slave.getInteger([self.vr[name] for name in STATS])
        slave.terminate()
        wall = time.perf_counter() - start
        result = np.empty(len(times), dtype=[("time", float)] + [(name, float) for name in RECORDED])
        result["time"] = times
        for column, name in enumerate(RECORDED):
            result[name] = values[:, column]
        return Trajectory(pendulum, method, grid, period, result, int(steps), int(rejected), int(rhs), wall,
                          self._log.warnings())

    def _run_me(self, pendulum: Pendulum, method: Method, grid: TimeGrid) -> Trajectory:
        start = time.perf_counter()
        model = self._fresh_model()
        self._log.clear()
        # The grid needs the period before the run: ask the FMU, then start afresh.
        period = self._initialize(model, pendulum, method)
        model.terminate()
        model.reset()
        times = grid.times(reference_period(period, pendulum))
        interval = times[1] - times[0]
        recorded = simulate_fmu(
            self._unzipdir, model_description=self.model_description, fmu_instance=model,
            fmi_type="ModelExchange", solver="CVode", start_time=0.0, stop_time=times[-1],
            output_interval=interval, relative_tolerance=method.effective_tolerance,
            start_values=pendulum.start_values(), output=list(RECORDED), validate=False,
            record_events=False, step_finished=lambda *_: not interrupt_pending())
        wall = time.perf_counter() - start
        result = np.empty(recorded.size, dtype=[("time", float)] + [(name, float) for name in RECORDED])
        for name in result.dtype.names or ():
            result[name] = recorded[name]
        return Trajectory(pendulum, method, grid, period, result, None, None, None, wall, self._log.warnings())
