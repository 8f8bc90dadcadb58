"""Build, simulate and check the Pendulum FMU (FMI 2.0 and 3.0, Co-Simulation and Model Exchange).

The typed API, imported on first use (so ``import pendulum_fmu`` stays quick)::

    from pendulum_fmu import FmuRunner, InitialValueProblem, Method, TimeGrid, fmu_path

    with FmuRunner(fmu_path()) as runner:
        run = runner.run(InitialValueProblem.from_degrees(85), Method("rkn", 1e-10), TimeGrid(10, "periods"))
    print(run.period, run.max_error)

Sweeps: :class:`SweepGrid` and :func:`run_sweep`; figures: ``pendulum_fmu.figures.comparison.compare``
and ``pendulum_fmu.figures.animation.animate``; the seed's study: ``pendulum-fmu study``.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

_EXPORTS: dict[str, str] = {
    "InitialValueProblem": "spec", "Method": "spec", "TimeGrid": "spec", "SOLVERS": "spec",
    "FmuRunner": "fmu.runner", "Trajectory": "fmu.runner",
    "SweepGrid": "sweep.grid", "SweepPoint": "sweep.grid", "run_sweep": "sweep.run",
    "UsageError": "errors", "SimulationError": "errors", "BuildError": "errors",
    "locate_fmu": "fmu.locate", "exact": "fmu.library",
}

if TYPE_CHECKING:
    from pendulum_fmu.errors import BuildError, SimulationError, UsageError
    from pendulum_fmu.fmu.library import exact
    from pendulum_fmu.fmu.locate import locate_fmu
    from pendulum_fmu.fmu.runner import FmuRunner, Trajectory
    from pendulum_fmu.spec import SOLVERS, InitialValueProblem, Method, TimeGrid
    from pendulum_fmu.sweep.grid import SweepGrid, SweepPoint
    from pendulum_fmu.sweep.run import run_sweep


def fmu_path(fmi_version: int | None = None) -> Path:
    """The ``Pendulum.fmu`` matching this package: FMI 2.0, or 3.0 with ``fmi_version=3``
    (None: ``$PENDULUM_FMU``'s version if set, else 2.0; see
    :func:`pendulum_fmu.fmu.locate.locate_fmu`)."""
    from pendulum_fmu.fmu.locate import locate_fmu

    return locate_fmu(fmi_version=fmi_version)


def split_path(fmi_version: int = 2) -> Path:
    """The split pendulum's ``PendulumSplit.ssp`` (FMI 2.0 FMUs inside, or 3.0: ``fmi_version=3``);
    see :func:`pendulum_fmu.split.locate.split_path`."""
    from pendulum_fmu.split.locate import split_path as locate_split

    return locate_split(fmi_version)


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        module = importlib.import_module(f".{_EXPORTS[name]}", __name__)
        return getattr(module, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["SOLVERS", "BuildError", "exact", "FmuRunner", "InitialValueProblem", "Method", "SimulationError",
           "SweepGrid", "SweepPoint",
           "TimeGrid", "Trajectory", "UsageError", "__version__", "fmu_path", "locate_fmu", "run_sweep",
           "split_path"]
