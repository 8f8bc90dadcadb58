"""Speed against error for co-simulation masters on the split pendulum (``pendulum-fmu bench masters``).

For each macro step H (default 1e-3, 5e-4, 2.5e-4 and 1.25e-4 s: where every reference master's
error means something, 0.29 rad for Jacobi with hold at 1e-3 down to 8e-12 for Gauss-Seidel with
interpolation at 1.25e-4; at the SSP's H = 0.01 Jacobi with hold is 3.56 rad off, a phase lost,
and at 1e-5 the best master is at round-off) and the pendulum from 75 deg over 10 s: each
reference master of :mod:`pendulum_fmu.split.masters` (FMI 2.0 FMUs through fmpy; the wall
time is its stepping loop) and each engine of :mod:`pendulum_fmu.split.engines` that runs here
(the wall time is the engine's whole run: unpacking, a child process for libcosim and Ecos,
writing its CSV). The error is the largest |theta - theta_exact| at the communication points
(for a file whose rows are labelled one step early, at the times they belong to); the observed
order compares consecutive H; each engine's file is judged (conformance and which master it
behaves as; a reference master is the yardstick, conformant by construction); a work-precision
figure draws error against wall time, one line per master or engine. ``--judge-rows N`` also
times one judge call on a file of N macro steps (Gauss-Seidel with interpolation at H = 10 / N).
"""

from __future__ import annotations

import math
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from pendulum_fmu.split.diagnosis import label_shift
from pendulum_fmu.split.engines import EngineError, engine_names, engine_version, missing, run_engine
from pendulum_fmu.split.masters import MASTERS, observed_orders, run_master
from pendulum_fmu.split.pair import DEFAULT_PROBLEM
from pendulum_fmu.split.reading import read_coupled

STEPS: tuple[float, ...] = (1e-3, 5e-4, 2.5e-4, 1.25e-4)
STOP = 10.0


@dataclass(frozen=True)
class MasterRun:
    """One run: a reference master or an engine at one H.

    Attributes
    ----------
    name : str
        The master's name or ``engine (FMI n)``.
    kind : str
        ``"master"`` or ``"engine"``.
    H : float
        The macro step (s).
    error : float
        Largest |theta - theta_exact| (rad); NaN when the run failed.
    seconds : float
        Wall time (s).
    note : str
        For an engine: the judge's conformance and identification, or why it could not run.
    """

    name: str
    kind: str
    H: float
    error: float
    seconds: float
    note: str = ""


def engine_error(path: Path, H: float) -> float:
    """Largest |theta - exact| of an engine's file, at the times its rows belong to."""
    from pendulum_fmu import exact

    result = read_coupled(path)
    problem = DEFAULT_PROBLEM
    time = result.time + label_shift(result.time, result.values, result.resolution, problem, H) * H
    theta = exact(problem.theta0, problem.omega0, problem.L, problem.g, time)[0]
    return float(np.max(np.abs(result.values["theta"] - theta)))


def _judged(path: Path) -> str:
    from pendulum_fmu.split.judge import judge_split

    verdict = judge_split(path)
    return verdict.summary.rsplit("; error", 1)[0]


def measure(steps: tuple[float, ...] = STEPS, stop: float = STOP, engines: bool = True,
            fmi_versions: tuple[int, ...] = (2, 3)) -> list[MasterRun]:
    """Run every reference master and engine at every H (see the module's docstring).

    Parameters
    ----------
    steps : tuple of float
        Macro steps (s).
    stop : float
        End time (s).
    engines : bool
        Also run the engines installed here.
    fmi_versions : tuple of int
        The engines' FMU versions.

    Returns
    -------
    list of MasterRun
    """
    points = []
    for master in MASTERS:
        for H in steps:
            run = run_master(master, H, stop)
            points.append(MasterRun(master.name, "master", H, run.error, run.seconds))
    if not engines:
        return points
    with tempfile.TemporaryDirectory(prefix="pendulum-bench-masters-") as folder:
        for engine in engine_names():
            if missing(engine):
                continue
            for version in fmi_versions:
                name = f"{engine} (FMI {version})"
                for H in steps:
                    path = Path(folder) / f"{engine}-{version}-{H:g}.csv"
                    try:
                        engine_run = run_engine(engine, H, stop, path, version)
                    except (EngineError, Exception) as error:  # noqa: BLE001 (any engine's own failure)
                        points.append(MasterRun(name, "engine", H, math.nan, math.nan, f"cannot: {error}"))
                        break
                    note = _judged(path)
                    points.append(MasterRun(name, "engine", H, engine_error(path, H), engine_run.seconds, note))
    return points


def orders(points: list[MasterRun]) -> dict[str, list[float]]:
    """The observed orders of each master or engine over its consecutive H."""
    found: dict[str, list[float]] = {}
    for name in dict.fromkeys(p.name for p in points):
        mine = [p for p in points if p.name == name and math.isfinite(p.error) and p.error > 0]
        if len(mine) > 1:
            found[name] = observed_orders([p.H for p in mine], [p.error for p in mine])
    return found


def table(points: list[MasterRun]) -> list[str]:
    """The Markdown table: one row per master or engine and H: conformance, error, order, wall time."""
    found = orders(points)
    lines = ["| master or engine | H (s) | conformance; identification | error in theta (rad) | order | wall s |",
             "|---|---:|---|---:|---:|---:|"]
    position: dict[str, int] = {}
    for p in points:
        index = position.get(p.name, 0)
        position[p.name] = index + 1
        order = found.get(p.name, [])
        shown = f"{order[index - 1]:.2f}" if 0 < index <= len(order) else ""
        if math.isnan(p.error):
            note = p.note if len(p.note) <= 140 else p.note[:137] + "..."
            lines.append(f"| {p.name} | {p.H:g} | {note} | | | |")
            continue
        note = p.note or ("reference master" if p.kind == "master" else "")
        lines.append(f"| {p.name} | {p.H:g} | {note} | {p.error:.3g} | {shown} | {p.seconds:.3g} |")
    return lines


def versions() -> str:
    """The engines' package versions, one line."""
    return ", ".join(f"{e} {engine_version(e) or 'not installed'}" for e in engine_names())


def figure(points: list[MasterRun], path: Path) -> Path:
    """Error against wall time, log-log, one line per master or engine; written to ``path`` (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 5.5))
    for name in dict.fromkeys(p.name for p in points):
        mine = [p for p in points if p.name == name and math.isfinite(p.error) and p.error > 0]
        if not mine:
            continue
        style = "-o" if mine[0].kind == "master" else "--s"
        ax.loglog([p.seconds for p in mine], [p.error for p in mine], style, label=name, markersize=4)
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("largest |theta - theta_exact| (rad)")
    ax.set_title("Split pendulum, 75 deg, 10 s: H = " + ", ".join(f"{h:g}" for h in
                                                                   sorted({p.H for p in points}, reverse=True)))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def judge_seconds(rows: int) -> tuple[float, float, str]:
    """Wall time of one judge call on a file of ``rows`` macro steps (``rows`` + 1 rows:
    Gauss-Seidel with interpolation at H = 10 / rows, 0..10 s, every output in full precision),
    warm: a small file is judged first. Returns (wall seconds, CPU seconds of this process, the
    summary line): on a shared machine the CPU time is the call's own cost."""
    import time

    from pendulum_fmu.split.columns import write_columns
    from pendulum_fmu.split.judge import judge_split
    from pendulum_fmu.split.masters import master_named

    H = STOP / rows
    with tempfile.TemporaryDirectory(prefix="pendulum-bench-split-judge-") as folder:
        paths = []
        for name, step in (("small", 0.01), ("large", H)):
            run = run_master(master_named("gauss-seidel-interpolation"), step, STOP)
            columns = {"Body.theta": run.theta, "Body.omega": run.omega, "Body.theta_exact": run.theta_exact,
                       "Body.omega_exact": run.omega_exact, "Gravity.alpha": run.alpha}
            path = Path(folder) / f"{name}.csv"
            write_columns(path, list(run.time), {k: list(v) for k, v in columns.items()})
            paths.append(path)
        judge_split(paths[0])
        began, cpu = time.perf_counter(), time.process_time()
        verdict = judge_split(paths[1])
        return time.perf_counter() - began, time.process_time() - cpu, verdict.summary
