"""The split pendulum: co-simulation masters judged against the exact pendulum (docs/masters.md).

``PendulumBody`` (theta' = omega, omega' = alpha) and ``PendulumGravity`` (alpha = -(g/L) sin theta)
coupled by a master are the pendulum, so a master's error is measured exactly:

- :mod:`~pendulum_fmu.split.locate`: where the two FMUs and ``PendulumSplit.ssp`` are;
- :mod:`~pendulum_fmu.split.pair`: both FMUs through fmpy, extracted once;
- :mod:`~pendulum_fmu.split.masters`: the reference masters (Jacobi, Gauss-Seidel; zero-order
  hold, extrapolation, input interpolation) and their measured orders;
- :mod:`~pendulum_fmu.split.reading`: a coupled result file, as engines write it;
- :mod:`~pendulum_fmu.split.judge`: which master a file behaves as, what is wrong, the verdict;
- :mod:`~pendulum_fmu.split.engines`: the SSP in the engines that install here.
"""

from __future__ import annotations

import importlib
from typing import Any

_EXPORTS: dict[str, str] = {
    "judge_split": "judge", "SplitVerdict": "judge", "MASTERS": "masters", "Master": "masters",
    "run_master": "masters", "Problem": "pair", "split_path": "locate", "run_engine": "engines",
}


def __getattr__(name: str) -> Any:
    """The package's main names, imported on first use (fmpy loads only when a master runs)."""
    if name in _EXPORTS:
        return getattr(importlib.import_module(f".{_EXPORTS[name]}", __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = list(_EXPORTS)
