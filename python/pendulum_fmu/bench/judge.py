"""Benchmark: how fast ``pendulum-fmu judge`` reads and judges a file, and its memory, by size.

Each file is an honest run of the FMU's own solver (rkn at the default tolerance 1e-8,
75 deg from rest, L = 1 m, g = 9.81 m/s^2, an output every 0.01 s), written as CSV with
the four outputs ``time, theta, omega, theta_exact, omega_exact`` in the shortest digits
that round-trip (as fmpy's and most tools' full-precision prints). The same file is judged
as Co-Simulation (the certificate's bound) and as Model Exchange (the ME bound; no CVODE
rerun, since it passes).

Every case runs in a child process of its own, warm: the child imports the judge and judges
a 1,000-row file first, then times ``read_result`` on the file, then ``judge`` on it (which
reads it again: "judge s" is the whole verdict), and reports its peak resident memory
(``ru_maxrss``, the imports included).
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

ROWS: tuple[int, ...] = (1_000, 200_000, 2_000_000)
INTERFACES: tuple[str, ...] = ("CS", "ME")
OUTPUT_INTERVAL = 0.01
AMPLITUDE_DEG = 75.0
WARM_ROWS = 1_000
"""Rows of the file each child judges first, untimed."""


@dataclass(frozen=True)
class Timing:
    """One file judged once, warm, in a child process."""

    rows: int
    interface: str
    read_s: float
    judge_s: float
    peak_rss_mb: float
    passed: bool
    line: str


def write_run(fmu: Path, rows: int, path: Path) -> Path:
    """Run the FMU (rkn, tolerance 1e-8) for ``rows`` outputs and write them as CSV.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.
    rows : int
        Output rows, the first at t = 0.
    path : Path
        The CSV file to write.

    Returns
    -------
    Path
        ``path``.
    """
    import numpy as np
    import pyarrow as pa
    import pyarrow.csv as pacsv

    from pendulum_fmu.fmu.runner import FmuRunner
    from pendulum_fmu.spec import InitialValueProblem, Method, TimeGrid

    grid = TimeGrid(stop=(rows - 1) * OUTPUT_INTERVAL, unit="s", output_interval=OUTPUT_INTERVAL)
    with FmuRunner(fmu) as runner:
        problem = InitialValueProblem.from_degrees(AMPLITUDE_DEG)
        result = runner.run(problem, Method(), grid).result
    if result.size != rows:
        raise RuntimeError(f"the run gave {result.size} rows, not {rows}")
    names = ("time", "theta", "omega", "theta_exact", "omega_exact")
    pacsv.write_csv(pa.table({n: np.ascontiguousarray(result[n]) for n in names}), path,
                    pacsv.WriteOptions(quoting_style="none"))
    return path


CHILD = """\
import json, math, resource, sys, time
from pendulum_fmu.judge import judge
from pendulum_fmu.judge.reading import read_result
warm, path, interface, fmu = sys.argv[1:5]
judge(warm, start={"theta": math.radians(75.0)}, interface=interface, fmu=fmu, read_experiment_file=False)
began = time.perf_counter()
read_result(path)
read_s = time.perf_counter() - began
began = time.perf_counter()
verdict = judge(path, start={"theta": math.radians(75.0)}, interface=interface, fmu=fmu, read_experiment_file=False)
judge_s = time.perf_counter() - began
print(json.dumps({"read_s": read_s, "judge_s": judge_s, "passed": verdict.passed, "line": verdict.line,
                  "peak_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}))
"""
"""The child: warm up on the small file, then time the file (argv: warm file, file, interface, FMU)."""


def judge_in_child(warm: Path, path: Path, interface: str, fmu: Path, rows: int) -> Timing:
    """Judge ``path`` warm in a fresh Python process and collect its :class:`Timing`."""
    done = subprocess.run([sys.executable, "-c", CHILD, str(warm), str(path), interface, str(fmu)],
                          capture_output=True, text=True, check=False)
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["no message"])[-1]
        raise RuntimeError(f"judging {path.name} ({interface}) failed: {last}")
    figures = json.loads(done.stdout.strip().splitlines()[-1])
    return Timing(rows, interface, float(figures["read_s"]), float(figures["judge_s"]),
                  float(figures["peak_rss_mb"]), bool(figures["passed"]), str(figures["line"]))


def measure(fmu: Path, rows: tuple[int, ...] = ROWS, interfaces: tuple[str, ...] = INTERFACES) -> list[Timing]:
    """Write a file of each size to a temporary folder and judge it in each interface.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu`` (runs the files; its model description gives the judge's defaults).
    rows : tuple of int
        File sizes, rows each (at least 2).
    interfaces : tuple of str
        "CS" and/or "ME".

    Returns
    -------
    list of Timing
        Size by size, interface by interface.
    """
    out = []
    with tempfile.TemporaryDirectory(prefix="pendulum-bench-judge-") as folder:
        warm = write_run(fmu, WARM_ROWS, Path(folder) / "warm.csv")
        for n in rows:
            path = write_run(fmu, n, Path(folder) / f"run_{n}.csv")
            out += [judge_in_child(warm, path, interface, fmu, n) for interface in interfaces]
            path.unlink()
    return out


def describe_rows(rows: int) -> str:
    """1e3, 2e5, 2e6 and the like; plain digits otherwise."""
    exponent = int(math.floor(math.log10(rows)))
    mantissa = rows / 10 ** exponent
    return f"{mantissa:g}e{exponent}" if mantissa == int(mantissa) else str(rows)


__all__ = ["INTERFACES", "ROWS", "WARM_ROWS", "Timing", "describe_rows", "measure", "write_run"]
