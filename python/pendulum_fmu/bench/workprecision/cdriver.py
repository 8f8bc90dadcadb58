"""The C half of the speed-against-error study: the repository's ``tests/c/bench_solvers``.

The driver loads the FMU's ``Pendulum.so`` and calls the FMI functions directly (no
Python in the loop), for the FMU's four solvers and, as the floor, for the exact solution
at the same points through Model Exchange. It is a test program of a CMake build, which an
installed package neither carries nor looks for: the caller hands it in (``bash
scripts/bench.sh solvers`` builds it and passes it as ``--driver``). This module runs it and
turns its ``key=value`` lines into :class:`~pendulum_fmu.bench.workprecision.runs.Run` and
:class:`Floor` records.
"""

from __future__ import annotations

import platform
import subprocess
from dataclasses import dataclass
from pathlib import Path

from pendulum_fmu.bench.workprecision.runs import Run


@dataclass(frozen=True)
class Floor:
    """The cost of evaluating the exact solution at a case's grid points.

    Attributes
    ----------
    problem : str
        ``"P1"``, ``"P2"`` or ``"P3"``.
    amplitude_deg : float
        Release angle.
    periods : float
        Simulated periods.
    points : int
        Grid points (periods * points a period + 1).
    wall_s : float
        Best wall time of fmi2SetTime + fmi2GetReal(theta_exact) over the points, in s.
    """

    problem: str
    amplitude_deg: float
    periods: float
    points: int
    wall_s: float


def shared_library(unzipped: Path) -> Path:
    """The FMU's binary for this platform inside the extracted FMU."""
    folder = {"Linux": "linux64", "Darwin": "darwin64", "Windows": "win64"}[platform.system()]
    suffix = {"Linux": ".so", "Darwin": ".dylib", "Windows": ".dll"}[platform.system()]
    return unzipped / "binaries" / folder / f"Pendulum{suffix}"


def _fields(line: str) -> dict[str, str]:
    return dict(item.split("=", 1) for item in line.split()[1:] if "=" in item)


def parse(output: str) -> tuple[list[Run], list[Floor]]:
    """Turns the driver's output into records.

    Parameters
    ----------
    output : str
        The driver's standard output.

    Returns
    -------
    tuple of (list of Run, list of Floor)
        One Run per ``run`` line (runner ``"c"``), one Floor per ``floor`` line.
    """
    runs: list[Run] = []
    floors: list[Floor] = []
    for line in output.splitlines():
        kind = line.split(" ", 1)[0]
        f = _fields(line)
        if kind == "floor":
            floors.append(Floor(problem=f["problem"], amplitude_deg=float(f["amplitude_deg"]),
                                periods=float(f["periods"]), points=int(f["points"]), wall_s=float(f["wall_s"])))
        elif kind == "run":
            run = Run(problem=f["problem"], amplitude_deg=float(f["amplitude_deg"]), periods=float(f["periods"]),
                      runner="c", method=f["solver"], tol=float(f["tol"]), status=f["status"])
            if run.status == "ok":
                run.rhs_evaluations = int(f["rhs_evaluations"])
                run.steps = int(f["steps"])
                run.rejected = int(f["rejected"])
                run.max_err = float(f["max_err"])
                run.energy_err_max = float(f["energy_err_max"])
                run.energy_err_first = float(f["energy_err_first"])
                run.energy_err_last = float(f["energy_err_last"])
                run.max_abs_theta = float(f["max_abs_theta"])
                run.wall_s = float(f["wall_s"])
            runs.append(run)
    return runs, floors


def run_driver(driver: Path, library: Path, problems: list[str], tols: list[float], p3_periods: float,
               points: int, repeat: int | None = None) -> tuple[list[Run], list[Floor]]:
    """Runs the C driver and parses its output.

    Parameters
    ----------
    driver : Path
        The ``bench_solvers`` executable.
    library : Path
        The FMU's shared library.
    problems : list of str
        Problems to run (``P1``, ``P2``, ``P3``).
    tols : list of float
        Tolerances.
    p3_periods : float
        Length of P3 in periods.
    points : int
        Output points a period.
    repeat : int, optional
        Repetitions per timing (the driver's default: 5, 2 for P3).

    Returns
    -------
    tuple of (list of Run, list of Floor)
        The runs and floors.

    Raises
    ------
    RuntimeError
        If the driver cannot run the FMU (exit status 2), dies, or prints no run.
    """
    command = [str(driver), str(library), "--problems", ",".join(problems),
               "--tols", ",".join(f"{t:g}" for t in tols), "--p3-periods", f"{p3_periods:g}",
               "--points", str(points)]
    if repeat is not None:
        command += ["--repeat", str(repeat)]
    completed = subprocess.run(command, capture_output=True, text=True, check=False)
    # exit 1 is a run that failed, listed with its status; anything else but 0 is the driver's own
    # failure (bad usage, a signal), and so is a run of the driver that lists no run at all
    if completed.returncode not in (0, 1):
        raise RuntimeError(f"{' '.join(command)} failed (exit {completed.returncode}):\n{completed.stderr}")
    runs, floors = parse(completed.stdout)
    if not runs:
        raise RuntimeError(f"{' '.join(command)} printed no run (exit {completed.returncode}):\n{completed.stderr}")
    return runs, floors
