"""Benchmark: the whole Pendulum suite (every ``Pendulum.fmu`` case, FMI 2.0 and 3.0, CS and
ME) through fmpy, judging included, as ``pendulum-fmu suite run --engine fmpy`` does it, with
fmpy's command line (``--engine fmpy-cli``) as the peer measured in the same run.

Each engine runs every case in a process of its own (the suite's way: a crash or a hang ends
that case only), then the judge judges it; the wall time covers the runs, the judging and the
three reports (the judge and matplotlib are imported before the first engine is timed).
"""

from __future__ import annotations

import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from pendulum_fmu.suite import adapters, cases
from pendulum_fmu.suite.session import run_and_report

ENGINES: tuple[str, ...] = ("fmpy", "fmpy-cli")


@dataclass(frozen=True)
class SuiteTiming:
    """One engine's pass over the Pendulum cases.

    Attributes
    ----------
    engine : str
    cases, passed : int
    wall_s : float
        The whole pass: runs, judging, reports.
    run_s, judge_s : float
        The sums over the cases of the engine's process and of the judging.
    """

    engine: str
    cases: int
    passed: int
    wall_s: float
    run_s: float
    judge_s: float


def measure(engines: tuple[str, ...] = ENGINES, timeout: float = 120.0) -> list[SuiteTiming]:
    """Run the Pendulum cases through each engine in turn; return the timings."""
    chosen = cases.select(None, ("pendulum",))
    import matplotlib.figure  # noqa: F401 (warm: the first engine timed pays no import the second does not)

    import pendulum_fmu.judge  # noqa: F401
    timings = []
    with tempfile.TemporaryDirectory(prefix="pendulum-bench-suite-") as folder:
        for name in engines:
            began = time.perf_counter()
            results = run_and_report(adapters.engine(name), chosen, Path(folder) / name, timeout)
            wall = time.perf_counter() - began
            timings.append(SuiteTiming(name, len(results), sum(r.status == "passed" for r in results), wall,
                                       sum(r.run_seconds for r in results), sum(r.judge_seconds for r in results)))
    return timings
