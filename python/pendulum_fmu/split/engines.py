"""Run the split pendulum in the co-simulation engines that install with pip; each writes a CSV.

Each engine runs ``PendulumSplit.ssp`` (or its two FMUs) with a fixed macro step H from 0 to a
stop time and leaves ``time, Body.theta, Body.omega, Body.theta_exact, Body.omega_exact,
Gravity.alpha`` (the columns the engine itself names; its own times). libcosim and Ecos run in
a child process: libcosim aborts the process on an FMU error, Ecos needs tbb's library folder
on ``LD_LIBRARY_PATH`` before the interpreter starts (docs/importers.md).

Engines: ``fmpy-ssp`` (``fmpy.ssp.simulation.simulate_ssp``), ``libcosim``
(``CosimExecution.from_ssp_file``, FMI 2.0 only), ``ecos`` (``EcosSimulation(ssp_path=...)``),
``fmpy-container`` (``fmpy.container_fmu``: the two FMUs in one container FMU, run by fmpy) and
``fmucontainer`` (the FMU Manipulation Toolbox's container, run by fmpy).
"""

from __future__ import annotations

import importlib.metadata
import importlib.util
import os
import subprocess
import sys
import textwrap
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from pendulum_fmu.split.columns import COLUMNS, EngineError, write_columns
from pendulum_fmu.split.containers import CONTAINERS
from pendulum_fmu.split.locate import split_path

INSTALL = "pip install -r python/requirements.lock (fmpy, libcosimpy==0.0.6, ecospy==0.7.2, tbb==2023.2.0, " \
          "fmu-manipulation-toolbox)"
PACKAGES = {"fmpy-ssp": "fmpy", "libcosim": "libcosimpy", "ecos": "ecospy", "fmpy-container": "fmpy",
            "fmucontainer": "fmu_manipulation_toolbox"}
DISTRIBUTIONS = {"fmpy": "fmpy", "libcosimpy": "libcosimpy", "ecospy": "ecospy",
                 "fmu_manipulation_toolbox": "fmu-manipulation-toolbox"}


@dataclass(frozen=True)
class EngineRun:
    """An engine's result file and the wall time of the run (s, the engine's whole process)."""

    engine: str
    csv: Path
    seconds: float


def engine_version(engine: str) -> str:
    """The installed version of the package behind ``engine`` ("" when not installed)."""
    try:
        return importlib.metadata.version(DISTRIBUTIONS[PACKAGES[engine]])
    except importlib.metadata.PackageNotFoundError:
        return ""


def missing(engine: str) -> str | None:
    """Why ``engine`` cannot run here (with the install command), or None."""
    module = PACKAGES[engine]
    if importlib.util.find_spec(module) is None:
        return f"{module} is not installed: {INSTALL}"
    if engine == "ecos" and _tbb_folder() is None:
        return f"ecospy needs libtbb.so.12: {INSTALL}"
    return None


def run_fmpy_ssp(H: float, stop: float, out: Path, fmi_version: int = 2) -> Path:
    """fmpy's own SSP master (``simulate_ssp``) on ``PendulumSplit.ssp``; its rows as it returns them."""
    from fmpy.ssp.simulation import simulate_ssp

    rows = simulate_ssp(str(split_path(fmi_version)), start_time=0.0, stop_time=stop, step_size=H)
    write_columns(out, list(rows["time"]), {name: list(rows[name]) for name in COLUMNS})
    return out


_LIBCOSIM = textwrap.dedent("""
    import csv, sys
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver
    ssp, out, nanoseconds, steps = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    log_output_level(CosimLogLevel.ERROR)
    execution = CosimExecution.from_ssp_file(ssp, step_size=nanoseconds)
    series = CosimObserver.create_time_series(buffer_size=steps + 10)
    execution.add_observer(series)
    wanted = [("Body", "theta"), ("Body", "omega"), ("Body", "theta_exact"), ("Body", "omega_exact"),
              ("Gravity", "alpha")]
    refs = []
    for instance, name in wanted:
        index = execution.slave_index_from_instance_name(instance)
        vr = [v.reference for v in execution.slave_variables(index) if v.name == name.encode()][0]
        refs.append((index, vr))
        series.start_time_series(index, vr, CosimVariableType.REAL)
    if not execution.simulate_until(steps * nanoseconds):
        sys.exit(3)
    columns = []
    for index, vr in refs:
        times, _, values = series.time_series_real_samples(index, vr, from_step=1, sample_count=steps)
        columns.append(list(values))
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time"] + [i + "." + n for i, n in wanted])
        for k, t in enumerate(times):
            w.writerow([repr(t * 1e-9)] + [repr(c[k]) for c in columns])
""")


_ECOS = textwrap.dedent("""
    import csv, sys
    from ecospy import EcosSimulation
    ssp, out, step, steps = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
    wanted = ["Body::theta", "Body::omega", "Body::theta_exact", "Body::omega_exact", "Gravity::alpha"]
    simulation = EcosSimulation(ssp_path=ssp, step_size=step)
    if not simulation.init():
        sys.exit(3)
    rows = [[simulation.get_time()] + [simulation.get_real(n) for n in wanted]]
    for _ in range(steps):
        simulation.step(1)
        rows.append([simulation.get_time()] + [simulation.get_real(n) for n in wanted])
    simulation.terminate()
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time"] + [n.replace("::", ".") for n in wanted])
        w.writerows([[repr(v) for v in row] for row in rows])
""")


def _tbb_folder() -> Path | None:
    for folder in (Path(sys.prefix) / "lib", Path(sys.base_prefix) / "lib"):
        if (folder / "libtbb.so.12").exists():
            return folder
    return None


def _child(script: str, arguments: list[str], engine: str, env: dict[str, str] | None = None) -> None:
    done = subprocess.run([sys.executable, "-c", script, *arguments], capture_output=True, text=True,
                          timeout=600, check=False, env=env)
    if done.returncode != 0:
        tail = (done.stderr.strip() or done.stdout.strip() or "no output").splitlines()[-1]
        raise EngineError(f"{engine} exited with status {done.returncode}: {tail}")


def run_libcosim(H: float, stop: float, out: Path, fmi_version: int = 2) -> Path:
    """libcosim's fixed-step master on ``PendulumSplit.ssp`` (its time series observer, from step 1)."""
    if fmi_version != 2:
        raise EngineError("libcosim 0.0.6 runs FMI 2.0 only (an FMI 3.0 FMU crashes it: 'Unsupported FMI version')")
    nanoseconds = round(H * 1e9)
    _child(_LIBCOSIM, [str(split_path(2)), str(out), str(nanoseconds), str(round(stop / H))], "libcosim")
    return out


def ecos_environment() -> dict[str, str]:
    """The environment of an ecospy process: tbb's library folder first on ``LD_LIBRARY_PATH``."""
    env = dict(os.environ)
    folder = _tbb_folder()
    if folder is not None:
        env["LD_LIBRARY_PATH"] = os.pathsep.join(p for p in (str(folder), env.get("LD_LIBRARY_PATH", "")) if p)
    return env


def run_ecos(H: float, stop: float, out: Path, fmi_version: int = 2) -> Path:
    """Ecos on ``PendulumSplit.ssp`` (``EcosSimulation(ssp_path=...)``), sampled after every step."""
    _child(_ECOS, [str(split_path(fmi_version)), str(out), repr(H), str(round(stop / H))], "ecos",
           ecos_environment())
    return out


ENGINES: dict[str, Callable[[float, float, Path, int], Path]] = {
    "fmpy-ssp": run_fmpy_ssp, "libcosim": run_libcosim, "ecos": run_ecos}
"""The engines that run the SSP by name; the containers are in :mod:`pendulum_fmu.split.containers`."""


def run_engine(engine: str, H: float, stop: float, out: Path, fmi_version: int = 2) -> EngineRun:
    """Run ``engine`` at macro step ``H`` to ``stop``, writing ``out`` (CSV); EngineError if it cannot."""
    runner = {**ENGINES, **CONTAINERS}[engine]
    began = time.perf_counter()
    runner(H, stop, out, fmi_version)
    return EngineRun(engine, out, time.perf_counter() - began)


def engine_names() -> tuple[str, ...]:
    """Every engine this module knows, installed or not."""
    return tuple(PACKAGES)
