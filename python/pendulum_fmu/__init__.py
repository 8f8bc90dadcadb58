"""Build, simulate and check the Pendulum FMU (FMI 2.0, Co-Simulation and Model Exchange).

The typed API, imported on first use (so ``import pendulum_fmu`` stays quick)::

    from pendulum_fmu import FmuRunner, Method, Pendulum, TimeGrid, fmu_path

    with FmuRunner(fmu_path()) as runner:
        run = runner.run(Pendulum.from_degrees(85), Method("rkn", 1e-10), TimeGrid(10, "periods"))
    print(run.period, run.max_error)

Sweeps: :class:`SweepGrid` and :func:`run_sweep`; figures: ``pendulum_fmu.compare.compare``
and ``pendulum_fmu.animate.animate``; the seed's study: ``pendulum-fmu study``.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

_EXPORTS: dict[str, str] = {
    "Pendulum": "spec", "Method": "spec", "TimeGrid": "spec", "SOLVERS": "spec",
    "FmuRunner": "runner", "Trajectory": "runner",
    "SweepGrid": "sweep_grid", "SweepPoint": "sweep_grid", "run_sweep": "sweep",
    "UsageError": "errors", "SimulationError": "errors", "BuildError": "errors",
    "locate_fmu": "locate",
}

if TYPE_CHECKING:
    from .errors import BuildError, SimulationError, UsageError
    from .locate import locate_fmu
    from .runner import FmuRunner, Trajectory
    from .spec import SOLVERS, Method, Pendulum, TimeGrid
    from .sweep import run_sweep
    from .sweep_grid import SweepGrid, SweepPoint


def fmu_path() -> Path:
    """The ``Pendulum.fmu`` matching this package (see :func:`pendulum_fmu.locate.locate_fmu`)."""
    from .locate import locate_fmu

    return locate_fmu()


def __getattr__(name: str) -> Any:
    if name in _EXPORTS:
        module = importlib.import_module(f".{_EXPORTS[name]}", __name__)
        return getattr(module, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = ["SOLVERS", "BuildError", "FmuRunner", "Method", "Pendulum", "SimulationError", "SweepGrid", "SweepPoint",
           "TimeGrid", "Trajectory", "UsageError", "__version__", "fmu_path", "locate_fmu", "run_sweep"]
