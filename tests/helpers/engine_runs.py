"""Run Pendulum.fmu in co-simulation engines that install with pip, each in its own process,
and let the engine write its result: libcosim (libcosimpy) and Ecos (ecospy).

Each run is a subprocess: libcosim aborts the whole process on an FMU error at
initialization (``terminate called after throwing an instance of 'cosim::error'``) and
segfaults on an FMI 3.0 FMU; ecospy needs tbb's library folder on the loader path before the
interpreter starts (``LD_LIBRARY_PATH``). Used by tests/judge/test_judge_engines.py; as a script::

    .venv/bin/python tests/helpers/engine_runs.py libcosim|ecos FMU OUT_DIR [NAME=VALUE ...]
"""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
import textwrap
from dataclasses import dataclass
from pathlib import Path

INSTALL = "pip install -r python/requirements.lock (libcosimpy==0.0.6, ecospy==0.7.2, tbb==2023.2.0)"
FMUTOOL_INSTALL = "pip install fmu_manipulation_toolbox==2.0 (python/requirements.lock)"
"""How to get fmutool, the FMU Manipulation Toolbox's checker."""
STEP = 0.01
STEPS = 1000
VALUE_REFERENCES = {"L": 1, "g": 2, "theta": 3, "omega": 5, "theta_exact": 7, "omega_exact": 8}
"""The FMU's value references (modelDescription.xml)."""
OUTPUTS = ("theta", "omega", "theta_exact", "omega_exact")


@dataclass(frozen=True)
class EngineRun:
    """What an engine run left: its exit status, its output, and the files it wrote."""

    returncode: int
    stdout: str
    stderr: str
    files: dict[str, Path]
    """Result files by kind (``"observer"``: the engine's own CSV writer; ``"samples"``: the
    engine's time series, written in full precision by the script)."""


def missing(module: str) -> str | None:
    """Why ``module`` cannot be used here (with the install command), or None."""
    if importlib.util.find_spec(module) is None:
        return f"{module} is not installed: {INSTALL}"
    return None


def tbb_library_folder() -> Path | None:
    """The folder of ``libtbb.so.12`` that pip's tbb package installs (``<prefix>/lib``)."""
    for folder in (Path(sys.prefix) / "lib", Path(sys.base_prefix) / "lib"):
        if (folder / "libtbb.so.12").exists():
            return folder
    return None


LIBCOSIM_SCRIPT = textwrap.dedent("""
    import json, sys
    from libcosimpy.CosimEnums import CosimVariableType
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver
    from libcosimpy.CosimSlave import CosimLocalSlave
    fmu, out, starts, vrs, step, steps = sys.argv[1], sys.argv[2], json.loads(sys.argv[3]), json.loads(sys.argv[4]), \\
        float(sys.argv[5]), int(sys.argv[6])
    log_output_level(CosimLogLevel.ERROR)
    nanoseconds = round(step * 1e9)
    execution = CosimExecution.from_step_size(nanoseconds)
    index = execution.add_local_slave(CosimLocalSlave(fmu_path=fmu, instance_name="pend"))
    execution.add_observer(CosimObserver.create_to_dir(out))
    series = CosimObserver.create_time_series(buffer_size=steps + 10)
    execution.add_observer(series)
    for name, value in starts.items():
        execution.real_initial_value(index, vrs[name], value)
    outputs = ["theta", "omega", "theta_exact", "omega_exact"]
    for name in outputs:
        series.start_time_series(index, vrs[name], CosimVariableType.REAL)
    if not execution.simulate_until(steps * nanoseconds):
        sys.exit(3)
    # from_step=0 drops the last sample (libcosimpy 0.0.6 trims by counting zero step numbers):
    # read from step 1 on, so the file starts at t = step
    columns = {}
    for name in outputs:
        times, step_numbers, values = series.time_series_real_samples(index, vrs[name], from_step=1,
                                                                      sample_count=steps)
        columns[name] = list(values)
        columns["time"] = [t * 1e-9 for t in times]
    with open(out + "/samples.csv", "w") as f:
        f.write("Time," + ",".join("pend." + n for n in outputs) + "\\n")
        for k, t in enumerate(columns["time"]):
            f.write(repr(t) + "," + ",".join(repr(columns[n][k]) for n in outputs) + "\\n")
""")

ECOS_SCRIPT = textwrap.dedent("""
    import json, sys
    from ecospy import EcosSimulation, EcosSimulationStructure
    fmu, out, starts, step, steps = sys.argv[1], sys.argv[2], json.loads(sys.argv[3]), float(sys.argv[4]), \\
        int(sys.argv[5])
    structure = EcosSimulationStructure()
    structure.add_model("pend", fmu)
    structure.add_parameter_set("start", {"pend::" + name: value for name, value in starts.items()})
    simulation = EcosSimulation(structure=structure, step_size=step)
    simulation.add_csv_writer(out + "/ecos.csv")
    if not simulation.init(parameter_set="start"):
        sys.exit(3)
    simulation.step(steps)
    print(json.dumps({"time": simulation.get_time(), "theta": simulation.get_real("pend::theta")}))
    simulation.terminate()
""")


def _run(command: list[str], env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(command, capture_output=True, text=True, timeout=300, check=False, env=env)


def run_libcosim(fmu: Path, out: Path, starts: dict[str, float], step: float = STEP, steps: int = STEPS) -> EngineRun:
    """libcosim on ``fmu`` (FMI 2.0 only) with ``starts`` set as initial values: its file
    observer's CSV (``observer``) and its time series samples (``samples``)."""
    out.mkdir(parents=True, exist_ok=True)
    done = _run([sys.executable, "-c", LIBCOSIM_SCRIPT, str(fmu), str(out), json.dumps(starts),
                 json.dumps(VALUE_REFERENCES), repr(step), str(steps)])
    files = {}
    observed = sorted(p for p in out.glob("pend_*.csv"))
    if observed:
        files["observer"] = observed[-1]
    if (out / "samples.csv").exists():
        files["samples"] = out / "samples.csv"
    return EngineRun(done.returncode, done.stdout, done.stderr, files)


def ecos_environment() -> dict[str, str]:
    """The environment for an ecospy process: tbb's library folder first on LD_LIBRARY_PATH."""
    folder = tbb_library_folder()
    env = dict(os.environ)
    if folder is not None:
        env["LD_LIBRARY_PATH"] = os.pathsep.join(p for p in (str(folder), env.get("LD_LIBRARY_PATH", "")) if p)
    return env


def run_ecos(fmu: Path, out: Path, starts: dict[str, float], step: float = STEP, steps: int = STEPS) -> EngineRun:
    """Ecos on ``fmu`` (FMI 2.0 or 3.0), its own CSV writer recording every variable."""
    out.mkdir(parents=True, exist_ok=True)
    done = _run([sys.executable, "-c", ECOS_SCRIPT, str(fmu), str(out), json.dumps(starts), repr(step), str(steps)],
                env=ecos_environment())
    files = {"observer": out / "ecos.csv"} if (out / "ecos.csv").exists() else {}
    return EngineRun(done.returncode, done.stdout, done.stderr, files)


def main(argv: list[str]) -> int:
    """``engine_runs.py libcosim|ecos FMU OUT_DIR [NAME=VALUE ...]``: run, print the files."""
    if len(argv) < 3 or argv[0] not in ("libcosim", "ecos"):
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    starts = {k: float(v) for k, v in (a.split("=", 1) for a in argv[3:])}
    run = (run_libcosim if argv[0] == "libcosim" else run_ecos)(Path(argv[1]), Path(argv[2]), starts)
    print(f"exit {run.returncode}; files: {', '.join(f'{k}={v}' for k, v in run.files.items())}")
    return run.returncode


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
