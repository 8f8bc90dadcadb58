"""The judge's test corpus: honest runs that must pass and wrong runs that must fail, each
wrong one with the reason its verdict line must name.

Generated, deterministic from a seed, into a folder: one CSV file a run, as the engine writes
it, and ``manifest.json`` with each run's truth (what ``judge(..., start=..., interface=...)``
is told, and how the run was made). Two parts, each from its own seed: ``tuning`` (what the
judge may be tuned on) and ``held-out`` (about a quarter of the size; never tuned on).

Honest runs: fmpy on both FMUs (FMI 2.0 and 3.0) in Co-Simulation (the FMU's four solvers,
the tolerance passed as ``relative_tolerance``) and Model Exchange (fmpy's CVODE at the
tolerance); Model Exchange importers emulated with scipy's ``solve_ivp`` (DOP853, LSODA,
Radau, RK45 at rtol = tol, atol = tol times a scale); libcosim and Ecos (their own
processes, tests/helpers/engine_runs.py). Random states in every regime, L, g, tolerances, output
intervals, lengths, a few start times other than 0 and files with extra columns.

Wrong runs: one kind a row of :data:`WRONG_KINDS`, each with its expected keywords.

As a script (generates, judges with the judge of this checkout, prints the confusion table
and writes every miss to ``OUTDIR/misses.txt``)::

    .venv/bin/python tests/helpers/judge_corpus.py OUTDIR [--part tuning|held-out] [--judge-only]

``--judge-only`` judges a corpus generated before into OUTDIR again; tests/judge/test_judge_corpus.py
does the same with ``PENDULUM_JUDGE_CORPUS=OUTDIR``.
"""

from __future__ import annotations

import argparse
import json
import math
import multiprocessing
import shutil
import sys
import time
from collections import Counter, defaultdict
from collections.abc import Callable, Iterable
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, ClassVar

import numpy as np

REPO = Path(__file__).resolve().parents[2]
FMUS: dict[str, Path] = {"2.0": REPO / "build" / "Pendulum.fmu", "3.0": REPO / "build" / "fmi3" / "Pendulum.fmu"}
OUTPUTS = ("theta", "omega", "theta_exact", "omega_exact")
SOLVERS: dict[int, str] = {1: "dopri5", 2: "rk4", 3: "rkn", 4: "symplectic"}
SCIPY_METHODS = ("DOP853", "LSODA", "Radau", "RK45")
SCIPY_PERIODS = {"DOP853": 10.0, "LSODA": 10.0, "Radau": 1.0, "RK45": 10.0}
"""The longest span of a scipy run in small-angle periods: Radau (implicit, in Python) takes
about a second a period at rtol 1e-12."""
DEFAULT_THETA = math.radians(75.0)
"""The FMU's start value of theta (modelDescription.xml)."""
DEFAULT_TOLERANCE = 1e-8
PROCESSES = 2

PARTS: dict[str, dict[str, int]] = {
    "tuning": {"seed": 26_0001, "honest": 1600, "engines": 24, "wrong_per_kind": 8},
    "held-out": {"seed": 26_0003, "honest": 540, "engines": 8, "wrong_per_kind": 3},
}
"""Each part's seed and sizes: the held-out part is a quarter of the whole, from its own seed.
The held-out seed was never judged before the judge was settled (an earlier one, 26_0002, was
seen while the judge was still changing, and is retired)."""

WRONG_KINDS: dict[str, tuple[str, ...]] = {
    "fixed step: explicit Euler": ("fixed step", "explicit Euler"),
    "fixed step: symplectic Euler": ("fixed step", "symplectic Euler"),
    "fixed step: Heun": ("fixed step", "Heun"),
    "fixed step: RK4": ("fixed step", "RK4"),
    "tolerance not passed on": ("tolerance",),
    "edited value (CS)": ("mangled",),
    "edited value (ME)": ("mangled",),
    "time lag": ("shifted",),
    "values one step early": ("shifted",),
    "scaled clock": ("clock",),
    "drifting clock": ("drift",),
    "missing rows": ("missing",),
    "duplicated rows": ("duplicate",),
    "g = 9.80665 not told": ("g = ",),
    "L = 2 not told": ("L = ",),
    "g = 1.62 not told": ("g = ",),
    "wrong theta": ("theta = ",),
    "wrong omega": ("omega = ",),
    "startTime 5 not told": ("startTime",),
    "degrees for radians": ("degrees",),
    "no theta or omega": ("no theta or omega",),
}
"""Every kind of wrong run and the keywords its verdict line must contain (case-insensitive)."""


@dataclass(frozen=True)
class Case:
    """One run of the corpus: its file, how it was made and what the judge is told."""

    name: str
    """The CSV file, relative to the corpus folder."""
    corpus: str
    """``"honest"`` or ``"wrong"``."""
    engine: str
    """What wrote it, for example ``"fmpy CS FMI 2.0"``, ``"scipy DOP853"``, ``"Ecos FMI 3.0"``."""
    kind: str
    """``"honest"`` or a key of :data:`WRONG_KINDS`."""
    start: dict[str, float | str]
    """What ``judge(..., start=...)`` is told."""
    interface: str
    """``"CS"`` or ``"ME"``: what ``judge(..., interface=...)`` is told."""
    solver: str
    """The solver of the run: the FMU's (CS) or the importer's (ME)."""
    regime: str
    """The state's regime (:func:`regime`)."""
    rows: int
    truth: dict[str, Any] = field(default_factory=dict)
    """How the run was really made (start values, parameters, tolerance, the edit made)."""

    @property
    def expected(self) -> tuple[str, ...]:
        """The keywords the verdict line must contain (none for an honest run)."""
        return WRONG_KINDS.get(self.kind, ())


@dataclass(frozen=True)
class Outcome:
    """The judge's verdict on one case and how it compares with the case's truth."""

    MISSES: ClassVar[tuple[str, ...]] = ("false alarm", "false pass", "wrong reason")

    case: Case
    passed: bool
    line: str
    seconds: float

    @property
    def status(self) -> str:
        """``"right"``, ``"false alarm"`` (honest, failed), ``"false pass"`` (wrong, passed),
        ``"wrong reason"`` (wrong, failed without its keywords), or for an honest run whose FMU
        said that a step was beyond its certificate (neither verdict is a miss) ``"warned,
        passed"`` or ``"warned, failed"``."""
        if self.case.kind == "FMU warned":
            return "warned, passed" if self.passed else "warned, failed"
        if self.case.corpus == "honest":
            return "right" if self.passed else "false alarm"
        if self.passed:
            return "false pass"
        text = self.line.lower()
        return "right" if all(k.lower() in text for k in self.case.expected) else "wrong reason"


# --- drawing --------------------------------------------------------------------------------------

def log_uniform(rng: np.random.Generator, low: float, high: float) -> float:
    """A number between ``low`` and ``high``, uniform in its logarithm."""
    return float(10 ** rng.uniform(math.log10(low), math.log10(high)))


def log_between(u: float, low: float, high: float) -> float:
    """The number between ``low`` and ``high`` at the share ``u`` (0..1) of the way in logarithm."""
    return float(10 ** (math.log10(low) + u * (math.log10(high) - math.log10(low))))


def regime(theta0: float, omega0: float, L: float, g: float) -> str:
    """The regime of a start state, by its energy: ``"libration <90 deg"`` and so on by
    amplitude, ``"rotation near separatrix"`` (k - 1 < 1e-3, k^2 the energy over the
    separatrix's), ``"rotation"``."""
    w0 = math.sqrt(g / L)
    k2 = math.sin(theta0 / 2) ** 2 + (omega0 / (2 * w0)) ** 2
    if k2 < 1.0:
        amplitude = math.degrees(2 * math.asin(math.sqrt(k2)))
        for limit, label in ((90.0, "libration <90 deg"), (170.0, "libration 90-170 deg"),
                             (179.9, "libration 170-179.9 deg")):
            if amplitude < limit:
                return label
        return "libration >=179.9 deg"
    return "rotation near separatrix" if math.sqrt(k2) - 1 < 1e-3 else "rotation"


def draw_state(rng: np.random.Generator, w0: float) -> tuple[float, float]:
    """theta0, omega0 in one of the regimes: libration from rest (1..179.99 deg, a third of
    them above 170 deg), libration in motion, a rotation near the separatrix
    (omega0 = 2 w0 (1 + c) at theta0 = 0, c = 1e-6..1e-1, or the same energy elsewhere),
    a rotation far from it; both directions."""
    pick = rng.random()
    sign = 1.0 if rng.random() < 0.5 else -1.0
    if pick < 0.45:
        degrees = rng.uniform(1.0, 170.0) if rng.random() < 0.67 else 180.0 - log_uniform(rng, 0.01, 10.0)
        return sign * math.radians(degrees), 0.0
    if pick < 0.6:
        amplitude = math.radians(rng.uniform(1.0, 179.9))
        k = math.sin(amplitude / 2)
        theta0 = rng.uniform(-0.99, 0.99) * amplitude
        return theta0, sign * 2 * w0 * math.sqrt(max(k * k - math.sin(theta0 / 2) ** 2, 0.0))
    if pick < 0.9:
        c = log_uniform(rng, 1e-6, 1e-1)
        if rng.random() < 0.5:
            return 0.0, sign * 2 * w0 * (1 + c)
        theta0 = rng.uniform(-math.pi, math.pi)
        return theta0, sign * 2 * w0 * math.sqrt((1 + c) ** 2 - math.sin(theta0 / 2) ** 2)
    theta0 = rng.uniform(-math.pi, math.pi)
    k = rng.uniform(1.1, 4.0)
    return theta0, sign * 2 * w0 * math.sqrt(k * k - math.sin(theta0 / 2) ** 2)


def draw_moderate_state(rng: np.random.Generator, w0: float) -> tuple[float, float]:
    """A state away from the separatrix (libration 10..170 deg, or rotation with k 1.05..2):
    the base of most wrong runs, where the fault and not the state is what is judged."""
    sign = 1.0 if rng.random() < 0.5 else -1.0
    if rng.random() < 0.75:
        return sign * math.radians(rng.uniform(10.0, 170.0)), 0.0 if rng.random() < 0.7 else sign * 0.3 * w0
    k = rng.uniform(1.05, 2.0)
    return 0.0, sign * 2 * w0 * k


def draw_grid(rng: np.random.Generator, w0: float, most_periods: float) -> tuple[float, int]:
    """An output interval (1e-3..0.5 s, uniform in its logarithm) and a length (10..2,000
    rows, likewise), the span held to ``most_periods`` small-angle periods by a shorter
    interval (not below 1e-3 s)."""
    interval = float(f"{log_uniform(rng, 1e-3, 0.5):.3g}")
    rows = int(round(log_uniform(rng, 10, 2000)))
    period = 2 * math.pi / w0
    if (rows - 1) * interval > most_periods * period:
        interval = max(1e-3, float(f"{most_periods * period / (rows - 1):.3g}"))
    return interval, rows


def draw_parameters(rng: np.random.Generator) -> tuple[float, float]:
    """L in [0.1, 10] m (uniform in its logarithm) and g in [1, 25] m/s^2."""
    return float(f"{log_uniform(rng, 0.1, 10.0):.6g}"), float(f"{rng.uniform(1.0, 25.0):.6g}")


def honest_specs(rng: np.random.Generator, count: int) -> list[dict[str, Any]]:
    """``count`` honest runs of fmpy (CS and ME, FMI 2.0 and 3.0) and scipy, drawn from ``rng``."""
    specs = []
    for index in range(count):
        L, g = draw_parameters(rng)
        w0 = math.sqrt(g / L)
        theta0, omega0 = draw_state(rng, w0)
        pick = rng.random()
        tol = log_uniform(rng, 1e-12, 1e-4)
        spec: dict[str, Any] = {"index": index, "L": L, "g": g, "theta": theta0, "omega": omega0, "tolerance": tol,
                                "startTime": 0.0}
        if rng.random() < 0.03:
            spec["startTime"] = float(f"{log_uniform(rng, 0.1, 1000.0):.4g}")
        if pick < 0.48:
            spec.update(engine="fmpy", interface="CS", fmi="2.0" if pick < 0.32 else "3.0",
                        solver=SOLVERS[int(rng.integers(1, 5))], extra=bool(rng.random() < 0.1))
            spec["interval"], spec["rows"] = draw_grid(rng, w0, 200.0)
        elif pick < 0.68:
            spec.update(engine="fmpy", interface="ME", fmi="2.0" if pick < 0.62 else "3.0", solver="CVODE",
                        extra=bool(rng.random() < 0.1))
            spec["interval"], spec["rows"] = draw_grid(rng, w0, 30.0)
        else:
            method = SCIPY_METHODS[int(rng.integers(0, len(SCIPY_METHODS)))]
            spec.update(engine="scipy", interface="ME", solver=method, scale="w0" if rng.random() < 0.5 else "1",
                        digits="repr" if rng.random() < 0.75 else "%.16e")
            spec["interval"], spec["rows"] = draw_grid(rng, w0, SCIPY_PERIODS[method])
        specs.append(spec)
    return specs


def engine_specs(rng: np.random.Generator, count: int) -> list[dict[str, Any]]:
    """``count`` honest runs of libcosim (FMI 2.0) and Ecos (FMI 2.0 and 3.0), alternating."""
    specs = []
    for index in range(count):
        L, g = draw_parameters(rng)
        theta0, omega0 = draw_state(rng, math.sqrt(g / L))
        engine = "libcosim" if index % 2 == 0 else "Ecos"
        specs.append({"index": index, "engine": engine,
                      "fmi": "2.0" if engine == "libcosim" or index % 4 == 1 else "3.0",
                      "L": L, "g": g, "theta": theta0, "omega": omega0, "tolerance": DEFAULT_TOLERANCE,
                      "startTime": 0.0, "interface": "CS", "solver": "rkn",
                      "interval": float(f"{log_uniform(rng, 1e-3, 0.1):.2g}"),
                      "rows": int(round(log_uniform(rng, 10, 1000)))})
    return specs


def wrong_specs(rng: np.random.Generator, per_kind: int) -> list[dict[str, Any]]:
    """``per_kind`` wrong runs of every kind of :data:`WRONG_KINDS`, drawn from ``rng``."""
    specs = []
    index = 0
    for kind in WRONG_KINDS:
        for _ in range(per_kind):
            L, g = draw_parameters(rng)
            if kind.startswith(("g = ", "L = ")):
                L, g = 1.0, 9.81
            w0 = math.sqrt(g / L)
            theta0, omega0 = draw_moderate_state(rng, w0)
            interval = float(f"{log_uniform(rng, 2e-3, 0.1):.3g}")
            periods = rng.uniform(3.0, 15.0)
            rows = int(min(2000, max(100, round(periods * 2 * math.pi / w0 / interval))))
            specs.append({"index": index, "kind": kind, "L": L, "g": g, "theta": theta0, "omega": omega0,
                          "interval": interval, "rows": rows, "fmi": "2.0" if rng.random() < 0.75 else "3.0",
                          "u": rng.random(8).tolist()})
            index += 1
    return specs


# --- running ---------------------------------------------------------------------------------------

_EXTRACTED: dict[str, tuple[str, Any]] = {}


def _fmu(version: str, unpacked: Path) -> tuple[str, Any]:
    """The extracted FMU's folder and its model description, read once a process."""
    if version not in _EXTRACTED:
        from fmpy import read_model_description

        folder = unpacked / version
        _EXTRACTED[version] = (str(folder), read_model_description(str(folder)))
    return _EXTRACTED[version]


def unpack_fmus(folder: Path) -> Path:
    """Copy both FMUs to ``folder/fmus/Pendulum-<version>.fmu`` (the engines load the copy:
    the corpus stays one build's, whatever happens to ``build/`` meanwhile) and extract each
    once into ``folder/fmus/<version>`` for every fmpy run to share."""
    from fmpy import extract

    unpacked = folder / "fmus"
    unpacked.mkdir(parents=True, exist_ok=True)
    for version, path in FMUS.items():
        if not path.exists():
            raise FileNotFoundError(f"no FMU at {path}: build it first (bash scripts/study.sh)")
        copy = unpacked / f"Pendulum-{version}.fmu"
        shutil.copyfile(path, copy)
        target = unpacked / version
        if not (target / "modelDescription.xml").exists():
            extract(str(copy), unzipdir=str(target))
    return unpacked


def fmpy_run(unpacked: Path, version: str, interface: str, starts: dict[str, float], tolerance: float | None,
             start_time: float, interval: float, rows: int, extra: bool = False,
             warnings: list[str] | None = None) -> np.ndarray:
    """fmpy's ``simulate_fmu`` on the extracted FMU: ``rows`` rows every ``interval`` s from
    ``start_time``; Co-Simulation with the tolerance passed as ``relative_tolerance``, or
    Model Exchange with CVODE at it; the four outputs, or every output when ``extra``. The
    FMU's messages of status Warning or worse are appended to ``warnings``."""
    from fmpy import simulate_fmu

    folder, description = _fmu(version, unpacked)
    found = warnings if warnings is not None else []

    def logger(*args: Any) -> None:
        # FMI 2.0 (environment, instance, status, category, message); FMI 3.0 (environment, status, category, message)
        if args[-3] >= 1:
            message = args[-1]
            found.append(message.decode("utf-8", "replace") if isinstance(message, bytes) else str(message))

    return simulate_fmu(folder, model_description=description, validate=False, logger=logger,
                        fmi_type="CoSimulation" if interface == "CS" else "ModelExchange",
                        relative_tolerance=tolerance, start_time=start_time,
                        stop_time=start_time + (rows - 1) * interval, output_interval=interval,
                        start_values=starts, output=None if extra else list(OUTPUTS))


def exact_columns(theta0: float, omega0: float, L: float, g: float, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The exact solution at the times ``t`` (counted from the start)."""
    from pendulum_fmu import exact

    return exact(theta0, omega0, L, g, t)


def scipy_run(spec: dict[str, Any]) -> dict[str, np.ndarray]:
    """A Model Exchange importer emulated by ``scipy.integrate.solve_ivp`` on the pendulum's
    ODE: rtol = tol, atol = tol times the scale (1, or (1, w0)), dense output at the grid; the
    exact columns as the FMU gives them at the same times."""
    from scipy.integrate import solve_ivp

    c = spec["g"] / spec["L"]
    start = spec["startTime"]
    t = start + spec["interval"] * np.arange(spec["rows"])
    tol = spec["tolerance"]
    atol = tol * np.array([1.0, math.sqrt(c)]) if spec.get("scale") == "w0" else tol

    def rhs(_: float, y: np.ndarray) -> np.ndarray:
        return np.array([y[1], -c * math.sin(y[0])])

    def jacobian(_: float, y: np.ndarray) -> np.ndarray:
        return np.array([[0.0, 1.0], [-c * math.cos(y[0]), 0.0]])

    options = {"jac": jacobian} if spec["solver"] in ("Radau", "LSODA") else {}
    solved = solve_ivp(rhs, (t[0], t[-1]), [spec["theta"], spec["omega"]], method=spec["solver"], t_eval=t,
                       rtol=tol, atol=atol, **options)
    if not solved.success:
        raise RuntimeError(f"solve_ivp {spec['solver']}: {solved.message}")
    theta_e, omega_e = exact_columns(spec["theta"], spec["omega"], spec["L"], spec["g"], t - start)
    return {"time": t, "theta": solved.y[0], "omega": solved.y[1], "theta_exact": theta_e, "omega_exact": omega_e}


def write_table(path: Path, columns: dict[str, np.ndarray], digits: str = "repr", quoted: bool = True) -> None:
    """A CSV file: a header of the column names (quoted as fmpy's ``write_csv`` quotes them),
    one row a line, each number as Python's repr (as fmpy writes) or with ``digits`` as a
    %-format."""
    names = list(columns)
    values = [np.asarray(columns[n], dtype=float) for n in names]
    rows = len(values[0]) if values else 0
    lines = [",".join(f'"{n}"' if quoted else n for n in names)]
    for k in range(rows):
        if digits == "repr":
            lines.append(",".join(repr(float(v[k])) for v in values))
        else:
            lines.append(",".join(digits % float(v[k]) for v in values))
    path.write_text("\n".join(lines) + "\n")


def table(result: np.ndarray) -> dict[str, np.ndarray]:
    """A structured array's columns by name."""
    return {name: np.array(result[name], dtype=float) for name in result.dtype.names}


def told(spec: dict[str, Any], interface: str, solver: bool = True) -> dict[str, float | str]:
    """What the judge is told of a run made as ``spec`` says: start values, L, g, the
    tolerance, the startTime when not 0, and (CS) the solver."""
    start: dict[str, float | str] = {"theta": spec["theta"], "omega": spec["omega"], "L": spec["L"], "g": spec["g"],
                                     "tolerance": spec["tolerance"]}
    if spec.get("startTime", 0.0) != 0.0:
        start["startTime"] = spec["startTime"]
    if interface == "CS" and solver:
        start["solver"] = spec["solver"]
    return start


def make_honest(job: tuple[dict[str, Any], str]) -> Case | str:
    """Run one honest spec and write its file; the case, or a line saying why the run failed."""
    spec, folder_text = job
    folder = Path(folder_text)
    name = f"honest/{spec['index']:05d}"
    try:
        if spec["engine"] == "fmpy":
            starts: dict[str, float] = {k: spec[k] for k in ("theta", "omega", "L", "g")}
            if spec["interface"] == "CS":
                starts["solver"] = next(k for k, v in SOLVERS.items() if v == spec["solver"])
            warned: list[str] = []
            result = fmpy_run(folder / "fmus", spec["fmi"], spec["interface"], starts, spec["tolerance"],
                              spec["startTime"], spec["interval"], spec["rows"], spec["extra"], warned)
            if warned:
                spec = dict(spec, warnings=len(warned), warning=warned[0])
            grid = spec["startTime"] + spec["interval"] * np.arange(spec["rows"])
            if len(result) != spec["rows"] or np.max(np.abs(result["time"] - grid)) > 1e-9 * max(1.0, grid[-1]):
                return f"{name}: fmpy returned {len(result)} rows, not {spec['rows']} at the asked times"
            from fmpy.util import write_csv

            engine = f"fmpy {spec['interface']} FMI {spec['fmi']}"
            write_csv(folder / f"{name}.csv", result)
            rows = len(result)
        else:
            columns = scipy_run(spec)
            engine = f"scipy {spec['solver']}"
            write_table(folder / f"{name}.csv", columns, spec["digits"], quoted=False)
            rows = len(columns["time"])
    except Exception as error:  # noqa: BLE001 - a failed run is reported, not raised
        return f"{name}: {type(error).__name__}: {error}"
    kind = "FMU warned" if spec.get("warnings") else "honest"
    return Case(f"{name}.csv", "honest", engine, kind, told(spec, spec["interface"]), spec["interface"],
                spec["solver"], regime(spec["theta"], spec["omega"], spec["L"], spec["g"]), rows, spec)


def make_engine_run(job: tuple[dict[str, Any], str]) -> Case | str:
    """One libcosim or Ecos run in its own process (tests/helpers/engine_runs.py): libcosim's time
    series samples (full precision), Ecos's own CSV writer."""
    from engine_runs import missing, run_ecos, run_libcosim

    spec, folder_text = job
    folder = Path(folder_text)
    name = f"honest/e{spec['index']:03d}"
    module = "libcosimpy" if spec["engine"] == "libcosim" else "ecospy"
    why_not = missing(module)
    if why_not:
        return f"{name}: {why_not}"
    starts = {k: spec[k] for k in ("theta", "omega", "L", "g")}
    out = folder / "engines" / name.split("/")[1]
    runner = run_libcosim if spec["engine"] == "libcosim" else run_ecos
    run = runner(folder / "fmus" / f"Pendulum-{spec['fmi']}.fmu", out, starts, spec["interval"], spec["rows"])
    key = "samples" if spec["engine"] == "libcosim" else "observer"
    if run.returncode != 0 or key not in run.files:
        return f"{name}: {spec['engine']} exit {run.returncode}: {run.stderr[-300:]}"
    shutil.copyfile(run.files[key], folder / f"{name}.csv")
    shutil.rmtree(out, ignore_errors=True)
    rows = sum(1 for _ in (folder / f"{name}.csv").open()) - 1
    return Case(f"{name}.csv", "honest", f"{spec['engine']} FMI {spec['fmi']}", "honest",
                told(spec, "CS", solver=False),
                "CS", "rkn", regime(spec["theta"], spec["omega"], spec["L"], spec["g"]), rows, spec)


# --- wrong runs ------------------------------------------------------------------------------------

def fixed_step(method: str, c: float, theta0: float, omega0: float, h: float, parts: int, rows: int) -> np.ndarray:
    """theta, omega of a fixed-step ``method`` (explicit Euler, symplectic Euler, Heun, RK4)
    at step ``h``, ``parts`` steps between rows, as an importer's Model Exchange loop makes them."""

    def f(theta: float, omega: float) -> tuple[float, float]:
        return omega, -c * math.sin(theta)

    out = np.empty((rows, 2))
    x, v = theta0, omega0
    out[0] = x, v
    for k in range(1, rows):
        for _ in range(parts):
            if method == "explicit Euler":
                dx, dv = f(x, v)
                x, v = x + h * dx, v + h * dv
            elif method == "symplectic Euler":
                v = v + h * f(x, v)[1]
                x = x + h * v
            elif method == "Heun":
                k1 = f(x, v)
                k2 = f(x + h * k1[0], v + h * k1[1])
                x, v = x + 0.5 * h * (k1[0] + k2[0]), v + 0.5 * h * (k1[1] + k2[1])
            else:
                k1 = f(x, v)
                k2 = f(x + 0.5 * h * k1[0], v + 0.5 * h * k1[1])
                k3 = f(x + 0.5 * h * k2[0], v + 0.5 * h * k2[1])
                k4 = f(x + h * k3[0], v + h * k3[1])
                x, v = (x + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
                        v + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]))
        out[k] = x, v
    return out


FIXED_STEP_SIZES = {"explicit Euler": (1e-3, 5e-2), "symplectic Euler": (3e-3, 0.2), "Heun": (1e-2, 0.2),
                    "RK4": (0.05, 0.4)}
"""The range of w0 h drawn for each fixed-step method: its error then exceeds the Model
Exchange bound within a few periods."""


def stated_tolerance(drawn: float, error: float) -> float:
    """The tolerance a wrong Model Exchange run is judged at: ``drawn``, or a decade at most
    1e-6 of the run's ``error`` when that is smaller (not below 1e-12), so that the error is
    1e6 tol or more: far beyond ME_FACTOR tol, the Model Exchange bound's local error a
    period."""
    if not (error > 0 and math.isfinite(error)):
        return drawn
    return max(1e-12, min(drawn, 10.0 ** math.floor(math.log10(error / 1e6))))


def _interior(u: float, rows: int) -> int:
    """A row from 1 to rows - 2, from a uniform number ``u``."""
    return 1 + int(u * (rows - 2)) % max(1, rows - 2)


def make_wrong(job: tuple[dict[str, Any], str]) -> Case | str:
    """Make one wrong run of ``spec["kind"]`` and write its file; the case, or why it failed."""
    spec, folder_text = job
    folder = Path(folder_text)
    kind, u = spec["kind"], spec["u"]
    name = f"wrong/{spec['index']:04d}"
    spec = dict(spec, startTime=0.0, tolerance=DEFAULT_TOLERANCE, solver="rkn")
    c = spec["g"] / spec["L"]
    w0 = math.sqrt(c)
    interface = "CS"
    truth: dict[str, Any] = {}
    unpacked = folder / "fmus"

    def cs(**changes: Any) -> dict[str, np.ndarray]:
        run = dict(spec, **changes)
        starts = {k: run[k] for k in ("theta", "omega", "L", "g")}
        starts["solver"] = next(k for k, v in SOLVERS.items() if v == run["solver"])
        return table(fmpy_run(unpacked, run["fmi"], "CS", starts, run["tolerance"], run["startTime"],
                              run["interval"], run["rows"]))

    try:
        columns: dict[str, np.ndarray]
        start = told(spec, "CS")
        if kind.startswith("fixed step"):
            method = kind.split(": ")[1]
            parts = (1, 2, 4, 10)[int(u[0] * 4)]
            low, high = FIXED_STEP_SIZES[method]
            interval = min(0.5, max(1e-3, float(f"{log_between(u[5], low, high) * parts / w0:.3g}")))
            h = interval / parts
            rows = int(min(1500, max(50, round((3 + 12 * u[1]) * 2 * math.pi / w0 / interval))))
            t = interval * np.arange(rows)
            states = fixed_step(method, c, spec["theta"], spec["omega"], h, parts, rows)
            theta_e, omega_e = exact_columns(spec["theta"], spec["omega"], spec["L"], spec["g"], t)
            columns = {"time": t, "theta": states[:, 0], "omega": states[:, 1], "theta_exact": theta_e,
                       "omega_exact": omega_e}
            interface = "ME"
            error = float(np.max(np.abs(states[:, 0] - theta_e)))
            spec["tolerance"] = stated_tolerance((1e-6, 1e-8, 1e-10)[int(u[2] * 3)], error)
            start = told(spec, "ME")
            if u[3] < 0.3 and spec["tolerance"] == DEFAULT_TOLERANCE:
                start.pop("tolerance")
            truth = {"method": method, "h": h, "interval": interval, "theta error": error}
        elif kind == "tolerance not passed on":
            interface = "ME"
            stated = (1e-8, 1e-9, 1e-10)[int(u[0] * 3)]
            if u[1] < 0.5:
                run_tol = 1e-4 if u[2] < 0.5 else 1e-5
                starts = {k: spec[k] for k in ("theta", "omega", "L", "g")}
                columns = table(fmpy_run(unpacked, spec["fmi"], "ME", starts, run_tol, 0.0, spec["interval"],
                                         spec["rows"]))
                truth = {"solver": "CVODE", "run tolerance": run_tol}
            else:
                method = ("RK45", "LSODA", "DOP853")[int(u[2] * 3)]
                run_tol = 1e-3 if method != "DOP853" else 1e-4
                columns = scipy_run(dict(spec, solver=method, tolerance=run_tol, scale="1"))
                truth = {"solver": method, "run tolerance": run_tol}
            error = float(np.max(np.abs(columns["theta"] - columns["theta_exact"])))
            spec["tolerance"] = stated_tolerance(stated, error)
            truth["theta error"] = error
            start = told(spec, "ME")
        elif kind == "edited value (CS)":
            spec["solver"] = "rkn" if u[0] < 0.5 else "dopri5"
            spec["tolerance"] = (1e-10, 1e-11, 1e-12)[int(u[1] * 3)]
            columns = cs()
            column = OUTPUTS[int(u[2] * 4)]
            row = _interior(u[3], len(columns["time"]))
            delta = 1e-9 if u[4] < 0.5 else -1e-9
            columns[column][row] += delta
            start = told(spec, "CS")
            truth = {"column": column, "row": row + 1, "delta": delta}
        elif kind == "edited value (ME)":
            interface = "ME"
            spec["tolerance"] = (1e-6, 1e-8, 1e-10)[int(u[1] * 3)]
            starts = {k: spec[k] for k in ("theta", "omega", "L", "g")}
            columns = table(fmpy_run(unpacked, spec["fmi"], "ME", starts, spec["tolerance"], 0.0, spec["interval"],
                                     spec["rows"]))
            column = ("theta", "omega", "omega_exact")[int(u[2] * 3)]
            row = _interior(u[3], len(columns["time"]))
            if column.endswith("_exact"):
                delta = 1e-9
            else:
                delta = 100 * float(np.max(np.abs(columns[column] - columns[f"{column}_exact"])))
            delta = delta if u[4] < 0.5 else -delta
            columns[column][row] += delta
            start = told(spec, "ME")
            truth = {"column": column, "row": row + 1, "delta": delta}
        elif kind == "time lag":
            columns = cs()
            lag = 1e-4 if u[0] < 0.5 else -1e-4
            columns["time"] = columns["time"] + lag
            truth = {"lag": lag}
        elif kind == "values one step early":
            columns = cs()
            columns = {k: (v[:-1] if k == "time" else v[1:]) for k, v in columns.items()}
            truth = {"early": 1}
        elif kind == "scaled clock":
            columns = cs()
            columns["time"] = columns["time"] * 1.001
            truth = {"scale": 1.001}
        elif kind == "drifting clock":
            columns = cs()
            t = columns["time"]
            if u[0] < 0.5:
                step = np.float32(spec["interval"])
                summed = np.zeros(t.size, dtype=np.float32)
                for k in range(1, t.size):
                    summed[k] = np.float32(summed[k - 1] + step)
                columns["time"] = summed.astype(float)
                truth = {"clock": "float32 sum"}
            else:
                drift = log_between(u[5], 1e-7, 1e-5)
                columns["time"] = t + drift * (t / t[-1]) ** 2
                truth = {"clock": "quadratic", "drift at the end": drift}
            truth["largest drift"] = float(np.max(np.abs(columns["time"] - t)))
        elif kind == "missing rows":
            columns = cs()
            count = 1 + int(u[0] * 5)
            rows = sorted({_interior(x, len(columns["time"])) for x in u[1:1 + count]})
            columns = {k: np.delete(v, rows) for k, v in columns.items()}
            truth = {"rows removed": [r + 1 for r in rows]}
        elif kind == "duplicated rows":
            columns = cs()
            count = 1 + int(u[0] * 3)
            rows = sorted({_interior(x, len(columns["time"])) for x in u[1:1 + count]})
            order = np.sort(np.concatenate([np.arange(len(columns["time"])), rows]))
            columns = {k: v[order] for k, v in columns.items()}
            truth = {"rows duplicated": [r + 1 for r in rows]}
        elif kind in ("g = 9.80665 not told", "L = 2 not told", "g = 1.62 not told"):
            parameter, value = kind.split(" not told")[0].split(" = ")
            columns = cs(**{parameter: float(value)})
            start = {k: v for k, v in told(spec, "CS").items() if k != parameter}
            truth = {parameter: float(value)}
        elif kind == "wrong theta":
            if u[0] < 0.4:
                columns = cs(theta=DEFAULT_THETA)
                spec["theta"] = DEFAULT_THETA + math.copysign(math.radians(5 + 60 * u[1]), u[2] - 0.5)
                truth = {"theta run": DEFAULT_THETA, "cause": "the importer did not set theta"}
            else:
                columns = cs()
                truth = {"theta run": spec["theta"]}
                spec["theta"] = spec["theta"] + math.copysign(log_between(u[5], 1e-4, 0.1), u[2] - 0.5)
            start = told(spec, "CS")
        elif kind == "wrong omega":
            if u[0] < 0.4:
                if spec["theta"] == 0.0:
                    spec["theta"] = math.radians(30.0)  # not the rest state, which a frozen FMU also gives
                columns = cs(omega=0.0)
                spec["omega"] = math.copysign((0.05 + 0.5 * u[1]) * w0, u[2] - 0.5)
                truth = {"omega run": 0.0, "cause": "the importer did not set omega"}
            else:
                columns = cs()
                truth = {"omega run": spec["omega"]}
                spec["omega"] = spec["omega"] + math.copysign(log_between(u[5], 1e-4, 0.1) * w0, u[2] - 0.5)
            start = told(spec, "CS")
        elif kind == "startTime 5 not told":
            columns = cs(startTime=5.0)
            truth = {"startTime": 5.0}
        elif kind == "degrees for radians":
            columns = cs()
            columns["theta"] = np.degrees(columns["theta"])
            if u[0] < 0.5:
                columns["theta_exact"] = np.degrees(columns["theta_exact"])
                truth = {"degrees": ["theta", "theta_exact"]}
            else:
                truth = {"degrees": ["theta"]}
        elif kind == "no theta or omega":
            columns = cs()
            keep = ("time", "theta_exact", "omega_exact") if u[0] < 0.5 else ("time",)
            columns = {k: columns[k] for k in keep}
            truth = {"columns": list(keep)}
        else:
            raise ValueError(f"unknown kind {kind!r}")
        write_table(folder / f"{name}.csv", columns)
    except Exception as error:  # noqa: BLE001 - a failed run is reported, not raised
        return f"{name} ({kind}): {type(error).__name__}: {error}"
    engine = "fixed step (ME loop)" if kind.startswith("fixed step") else f"fmpy {interface} FMI {spec['fmi']}"
    if "solver" in truth:
        engine = f"{truth['solver']} ME"
    solver = truth.get("method", spec["solver"] if interface == "CS" else truth.get("solver", "CVODE"))
    return Case(f"{name}.csv", "wrong", engine, kind, start, interface, str(solver),
                regime(spec["theta"], spec["omega"], spec["L"], spec["g"]), len(columns["time"]),
                {**spec, **truth})


# --- the corpus ------------------------------------------------------------------------------------

def _pool_map(function: Callable[[Any], Any], jobs: list[Any], processes: int) -> list[Any]:
    """``function`` over ``jobs`` in ``processes`` processes (in this one when 1), in order."""
    if processes <= 1:
        return [function(job) for job in jobs]
    with multiprocessing.get_context("fork").Pool(processes) as pool:
        return pool.map(function, jobs, chunksize=4)


def generate(folder: Path, part: str = "tuning", processes: int = PROCESSES, engines: bool = True,
             fraction: float = 1.0) -> tuple[list[Case], list[str]]:
    """Generate one part of the corpus into ``folder``: honest and wrong runs, ``manifest.json``.

    Parameters
    ----------
    folder : Path
        Where the files go (``honest/``, ``wrong/``, ``manifest.json``; the FMUs extracted in
        ``fmus/``).
    part : {"tuning", "held-out"}
        Which part: its seed and sizes are :data:`PARTS`'s.
    processes : int
        How many processes run the engines.
    engines : bool
        Whether to include the libcosim and Ecos runs (each a process of its own, about a second).
    fraction : float
        The share of the part's runs to make (1: all); the first runs of the same draws.

    Returns
    -------
    cases : list of Case
        Every run made, honest first.
    failures : list of str
        The runs that could not be made, one line each (an engine not installed, a solver
        that gave up).
    """
    sizes = PARTS[part]
    rng = np.random.default_rng(sizes["seed"])
    folder.mkdir(parents=True, exist_ok=True)
    for sub in ("honest", "wrong"):
        (folder / sub).mkdir(exist_ok=True)
    unpack_fmus(folder)
    honest = honest_specs(rng, sizes["honest"])
    machines = engine_specs(rng, sizes["engines"])
    wrong = wrong_specs(rng, sizes["wrong_per_kind"])
    if fraction < 1.0:
        honest = honest[: max(1, round(fraction * len(honest)))]
        machines = machines[: max(1, round(fraction * len(machines)))]
        per_kind = sizes["wrong_per_kind"]
        wrong = [s for s in wrong if s["index"] % per_kind < max(1, round(fraction * per_kind))]
    where = str(folder)
    made = _pool_map(make_honest, [(s, where) for s in honest], processes)
    if engines:
        made += _pool_map(make_engine_run, [(s, where) for s in machines], processes)
    made += _pool_map(make_wrong, [(s, where) for s in wrong], processes)
    cases = [m for m in made if isinstance(m, Case)]
    failures = [m for m in made if isinstance(m, str)]
    manifest = {"part": part, "seed": sizes["seed"], "failures": failures, "cases": [asdict(c) for c in cases]}
    (folder / "manifest.json").write_text(json.dumps(manifest, indent=1))
    return cases, failures


def load(folder: Path) -> list[Case]:
    """The cases of a corpus folder's ``manifest.json``."""
    manifest = json.loads((folder / "manifest.json").read_text())
    return [Case(**c) for c in manifest["cases"]]


def judge_one(job: tuple[Case, str]) -> Outcome:
    """The judge's verdict on one case; a file the judge cannot read fails with the reason it
    gives, and an exception fails with its type and message."""
    from pendulum_fmu.judge import ReadError, judge

    case, folder = job
    began = time.perf_counter()
    try:
        verdict = judge(Path(folder) / case.name, start=case.start, interface=case.interface)  # type: ignore[arg-type]
        passed, line = verdict.passed, verdict.line
    except ReadError as error:
        passed, line = False, f"unreadable: {error}"
    except Exception as error:  # noqa: BLE001 - a crash is a verdict too: a miss
        passed, line = False, f"crash: {type(error).__name__}: {error}"
    return Outcome(case, passed, line.splitlines()[0] if line else line, time.perf_counter() - began)


def judge_all(folder: Path, cases: Iterable[Case], processes: int = PROCESSES) -> list[Outcome]:
    """The judge's verdict on every case, in ``processes`` processes."""
    return _pool_map(judge_one, [(c, str(folder)) for c in cases], processes)


# --- the report ------------------------------------------------------------------------------------

def _rows(title: str, counts: dict[str, Counter[str]], columns: tuple[str, ...]) -> list[str]:
    width = max([len(title)] + [len(k) for k in counts]) + 2
    lines = [f"{title:<{width}}" + "".join(f"{c:>16}" for c in ("runs",) + columns)]
    for key in sorted(counts):
        counter = counts[key]
        lines.append(f"{key:<{width}}" + f"{sum(counter.values()):>16}" + "".join(f"{counter[c]:>16}" for c in columns))
    return lines


def confusion(outcomes: list[Outcome]) -> str:
    """The confusion table: honest runs by engine, solver and regime (passed, false alarms);
    wrong runs by kind (right reason, wrong reason, false pass)."""
    honest = [o for o in outcomes if o.case.corpus == "honest"]
    wrong = [o for o in outcomes if o.case.corpus == "wrong"]
    lines = [f"honest runs: {len(honest)} ({sum(o.case.kind == 'FMU warned' for o in honest)} where the FMU warned), "
             f"false alarms: {sum(o.status == 'false alarm' for o in honest)}; "
             f"wrong runs: {len(wrong)}, false passes: {sum(o.status == 'false pass' for o in wrong)}, "
             f"wrong reasons: {sum(o.status == 'wrong reason' for o in wrong)}", ""]
    for title, key in (("engine", lambda c: c.engine), ("solver", lambda c: f"{c.interface} {c.solver}"),
                       ("regime", lambda c: c.regime)):
        counts: dict[str, Counter[str]] = defaultdict(Counter)
        for o in honest:
            counts[key(o.case)][o.status] += 1
        lines += _rows(f"honest by {title}", counts, ("right", "false alarm", "warned, passed", "warned, failed"))
        lines.append("")
    counts = defaultdict(Counter)
    for o in wrong:
        counts[o.case.kind][o.status] += 1
    lines += _rows("wrong by kind", counts, ("right", "wrong reason", "false pass"))
    return "\n".join(lines)


def misses(outcomes: list[Outcome], limit: int | None = None) -> str:
    """Every miss, one line each: file, engine, kind (with the expected keywords), status,
    the verdict line."""
    lines = []
    for o in outcomes:
        if o.status not in Outcome.MISSES:
            continue
        expected = f" [expects {' + '.join(repr(k) for k in o.case.expected)}]" if o.case.expected else ""
        lines.append(f"{o.case.name} | {o.case.engine} | {o.case.kind}{expected} | {o.case.solver} | "
                     f"{o.case.regime} | {o.status} | {o.line}")
    if limit is not None and len(lines) > limit:
        lines = lines[:limit] + [f"... and {len(lines) - limit} more"]
    return "\n".join(lines)


def examples(outcomes: list[Outcome], each: int = 2) -> str:
    """A few verdict lines of each class of miss: false alarms by engine and the checks that
    failed, wrong runs by kind and status."""
    classes: dict[str, list[Outcome]] = defaultdict(list)
    for o in outcomes:
        if o.status not in Outcome.MISSES:
            continue
        if o.case.corpus == "honest":
            failed = o.line.split(":", 1)[0] if o.line.startswith("FAIL") else o.line.split(":", 1)[0]
            classes[f"false alarm, {o.case.engine}, {failed}"].append(o)
        else:
            classes[f"{o.status}, {o.case.kind}"].append(o)
    lines = []
    for key in sorted(classes):
        lines.append(f"{key} ({len(classes[key])}):")
        lines += [f"    {o.case.name} ({o.case.solver}, {o.case.regime}): {o.line[:400]}" for o in classes[key][:each]]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """``judge_corpus.py OUTDIR [--part tuning|held-out]``: generate, judge, print the table."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("outdir", type=Path)
    parser.add_argument("--part", choices=("tuning", "held-out", "both"), default="both")
    parser.add_argument("--processes", type=int, default=PROCESSES)
    parser.add_argument("--judge-only", action="store_true",
                        help="judge the corpus already in OUTDIR (its manifest.json) without generating it again")
    args = parser.parse_args(argv)
    parts = ("tuning", "held-out") if args.part == "both" else (args.part,)
    report: list[str] = []
    all_outcomes: list[Outcome] = []
    total = time.perf_counter()
    for part in parts:
        folder = args.outdir / part
        began = time.perf_counter()
        if args.judge_only:
            cases = load(folder)
            failures = json.loads((folder / "manifest.json").read_text())["failures"]
        else:
            cases, failures = generate(folder, part, args.processes)
        generated = time.perf_counter() - began
        began = time.perf_counter()
        outcomes = judge_all(folder, cases, args.processes)
        judged = time.perf_counter() - began
        all_outcomes += outcomes
        slowest = max(outcomes, key=lambda o: o.seconds)
        how = "loaded" if args.judge_only else "generated"
        report += [f"== part {part}: {len(cases)} runs {how} in {generated:.1f} s, judged in {judged:.1f} s "
                   f"({args.processes} processes; slowest verdict {slowest.seconds:.2f} s, {slowest.case.name})",
                   *(f"not made: {f}" for f in failures), confusion(outcomes), "",
                   "examples of each class of miss:", examples(outcomes), ""]
    report.append(f"total {time.perf_counter() - total:.1f} s")
    text = "\n".join(report)
    print(text)
    args.outdir.mkdir(parents=True, exist_ok=True)
    (args.outdir / "misses.txt").write_text(misses(all_outcomes) + "\n")
    (args.outdir / "report.txt").write_text(text + "\n")
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    sys.exit(main())
