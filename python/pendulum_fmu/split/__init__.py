"""The split pendulum: co-simulation masters judged against the exact pendulum (docs/masters.md).

``PendulumBody`` (theta' = omega, omega' = alpha) and ``PendulumGravity`` (alpha = -(g/L) sin theta)
coupled by a master are the pendulum, so a master's error is measured exactly:

- :mod:`~pendulum_fmu.split.locate`: where the two FMUs and ``PendulumSplit.ssp`` are;
- :mod:`~pendulum_fmu.split.pair`: both FMUs through fmpy, extracted once;
- :mod:`~pendulum_fmu.split.masters`: the reference masters (Jacobi, Gauss-Seidel; zero-order
  hold, extrapolation, input interpolation) and their measured orders;
- :mod:`~pendulum_fmu.split.reading`: a coupled result file, as engines write it;
- :mod:`~pendulum_fmu.split.judge`: three answers for a coupled result: conformance (the defects
  found, :mod:`~pendulum_fmu.split.grid`, :mod:`~pendulum_fmu.split.diagnosis`,
  :mod:`~pendulum_fmu.split.inputs`), identification (:mod:`~pendulum_fmu.split.identify`) and
  accuracy (:mod:`~pendulum_fmu.split.accuracy`); :mod:`~pendulum_fmu.split.report` writes
  them as JSON and a figure;
- :mod:`~pendulum_fmu.split.engines`: the SSP in the engines that install here.
"""

from __future__ import annotations

import importlib
from typing import Any

_EXPORTS: dict[str, str] = {
    "judge_split": "judge", "judge_runs": "judge", "SplitVerdict": "judge", "MASTERS": "masters", "Master": "masters",
    "run_master": "masters", "DEFAULT_PROBLEM": "pair", "split_path": "locate", "run_engine": "engines",
}


def __getattr__(name: str) -> Any:
    """The package's main names, imported on first use (fmpy loads only when a master runs)."""
    if name in _EXPORTS:
        return getattr(importlib.import_module(f".{_EXPORTS[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = list(_EXPORTS)
