"""A time series written with its experiment, so that a result says what it is.

Every time series the package writes (``simulate -o``, ``compare --data``, the study's
``runs.csv``) goes through :func:`write_series`, which stores the experiment of the run(s)
beside the numbers, and :func:`read_record` gives it back (``pendulum-fmu judge`` reads it):

- **Parquet**: in the file's schema metadata, under the key :data:`PARQUET_KEY`, as JSON
  (the file stays one file);
- **CSV** (``.csv``, and gzipped ``.csv.gz``): in a *sidecar file* beside it, the file's name
  plus :data:`SIDECAR_SUFFIX` (``run.csv`` -> ``run.csv.experiment.json``). The CSV itself
  stays plain: one header line, then numbers, which fmpy's ``read_csv``, pandas'
  ``read_csv`` and a spreadsheet read as they are. (A commented first line would not do:
  numpy's ``genfromtxt(names=True)``, under fmpy's ``read_csv``, takes the names from a
  commented first line, and pandas and spreadsheets show it as a row.)

The JSON is one object: ``{"format": FORMAT, "file": NAME, "experiment": {...}}`` for one run,
or ``{"format": FORMAT, "file": NAME, "runs": [{"select": {column: value}, "experiment":
{...}}, ...]}`` for a file of several runs, each picked out by the values of some columns.
An experiment's fields are those of :class:`ExperimentRecord` (docs/results.md).

Usage::

    from pendulum_fmu.output.experiment_record import record_of, write_series, read_record
    write_series(columns, Path("run.csv"), record_of(trajectory, fmu_path, 2, "simulate"))
    found = read_record(Path("run.csv"))      # FoundRecord(record, source) or None
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass, fields
from pathlib import Path
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
import pyarrow as pa
import pyarrow.csv as pa_csv
import pyarrow.parquet as pq

from pendulum_fmu.output.atomic import write_whole
from pendulum_fmu.output.tables import to_arrow

if TYPE_CHECKING:
    from pendulum_fmu.fmu.runner import Trajectory

FORMAT = "pendulum-fmu experiment record 1"
"""The ``format`` of the JSON: its name and version."""
PARQUET_KEY = "pendulum_fmu.experiment"
"""The Parquet schema metadata key that holds the JSON."""
SIDECAR_SUFFIX = ".experiment.json"
"""Appended to a CSV file's name for its sidecar."""
SERIES_FORMATS: tuple[str, ...] = (".csv", ".csv.gz", ".parquet")
"""The formats :func:`write_series` writes, by the end of the file's name."""


@dataclass(frozen=True)
class ExperimentRecord:
    """The experiment of one run: what an importer or the judge needs to repeat or check it.

    Attributes
    ----------
    theta0, omega0 : float
        Start values, rad and rad/s.
    length, gravity : float
        L (m) and g (m/s^2).
    interface : {"CS", "ME"}
        Co-Simulation (the FMU's solver) or Model Exchange (the importer's).
    solver : str
        The solver's name (``rkn``, ``cvode``, ...).
    tolerance : float
        The relative tolerance the run used.
    tolerance_asked : float or None
        The tolerance asked for, when it is not the one used (one below the FMU's floor).
    start_time, stop_time : float
        The first and last output time, s.
    step : float or None
        The communication (output) step, s; None when the times are not a uniform grid.
    fmi_version : str
        ``"2.0"`` or ``"3.0"``.
    fmu : str
        The FMU's identity: its file name, model name and GUID (FMI 2.0) or
        instantiationToken (FMI 3.0), ``"Pendulum.fmu (Pendulum, {guid})"``.
    writer : str
        What wrote the file, e.g. ``"pendulum-fmu 0.1.0 simulate"``.
    """

    theta0: float
    omega0: float
    length: float
    gravity: float
    interface: Literal["CS", "ME"]
    solver: str
    tolerance: float
    start_time: float
    stop_time: float
    step: float | None
    fmi_version: str
    fmu: str
    writer: str
    tolerance_asked: float | None = None

    def __post_init__(self) -> None:
        for name in ("theta0", "omega0", "length", "gravity", "tolerance", "start_time", "stop_time"):
            value = getattr(self, name)
            if not isinstance(value, (int, float)) or not math.isfinite(value):
                raise ValueError(f"experiment record: {name} must be a finite number, got {value!r}")
        if self.interface not in ("CS", "ME"):
            raise ValueError(f"experiment record: interface must be CS or ME, got {self.interface!r}")
        if self.length <= 0 or self.gravity <= 0 or self.tolerance <= 0:
            raise ValueError("experiment record: length, gravity and tolerance must be > 0")
        if self.step is not None and not (math.isfinite(self.step) and self.step > 0):
            raise ValueError(f"experiment record: step must be > 0 or absent, got {self.step!r}")

    def to_json(self) -> dict[str, Any]:
        """The fields as a JSON object (floats as numbers, full precision)."""
        return asdict(self)

    @classmethod
    def from_json(cls, data: Mapping[str, Any]) -> ExperimentRecord:
        """The record of a JSON object written by :meth:`to_json`.

        Raises
        ------
        ValueError
            A field missing, unknown, or of the wrong kind.
        """
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(data) - known)
        if unknown:
            raise ValueError(f"experiment record: unknown field(s) {', '.join(unknown)}")
        required = {f.name for f in fields(cls)} - {"tolerance_asked"}
        missing = sorted(required - set(data))
        if missing:
            raise ValueError(f"experiment record: no {', '.join(missing)}")
        values = dict(data)
        try:
            for name in ("theta0", "omega0", "length", "gravity", "tolerance", "start_time", "stop_time"):
                values[name] = float(values[name])
            for name in ("step", "tolerance_asked"):
                values[name] = None if values.get(name) is None else float(values[name])
        except (TypeError, ValueError):
            raise ValueError(f"experiment record: {name} is not a number: {values.get(name)!r}") from None
        for name in ("interface", "solver", "fmi_version", "fmu", "writer"):
            values[name] = str(values[name])
        return cls(**values)

    def describe(self) -> str:
        """One line for people: the problem, the method and the FMU."""
        asked = f" (asked {self.tolerance_asked:g})" if self.tolerance_asked is not None else ""
        step = f"step {self.step:.10g} s" if self.step is not None else "variable output step"
        return (f"theta0 {self.theta0:.17g} rad, omega0 {self.omega0:.17g} rad/s, L {self.length:g} m, "
                f"g {self.gravity:g} m/s^2; {self.interface} {self.solver}, tolerance {self.tolerance:g}{asked}; "
                f"{self.start_time:g} to {self.stop_time:.10g} s, {step}; FMI {self.fmi_version} {self.fmu}")


@dataclass(frozen=True)
class FoundRecord:
    """An experiment read back, and where from (the sidecar's path, or ``FILE.parquet (metadata)``)."""

    record: ExperimentRecord
    source: str


def fmu_identity(fmu: Path, description: Any) -> str:
    """``"Pendulum.fmu (Pendulum, {guid})"`` from an fmpy model description."""
    token = getattr(description, "guid", None) or getattr(description, "instantiationToken", None) or "?"
    return f"{Path(fmu).name} ({description.modelName}, {token})"


def record_of(trajectory: Trajectory, fmu: Path, command: str, description: Any = None) -> ExperimentRecord:
    """The record of a run of :class:`pendulum_fmu.fmu.runner.FmuRunner`.

    Parameters
    ----------
    trajectory : Trajectory
        The run.
    fmu : Path
        The FMU it ran.
    command : str
        What wrote it (``"simulate"``, ``"compare"``, ``"study"``).
    description : fmpy ModelDescription, optional
        The FMU's model description, for its identity (read from ``fmu`` when not given).
    """
    from pendulum_fmu import __version__
    from pendulum_fmu.fmu.identity import read_description
    from pendulum_fmu.fmu.runner import reference_period

    description = description if description is not None else read_description(Path(fmu))
    p, m = trajectory.problem, trajectory.method
    times = np.asarray(trajectory.result["time"], dtype=float)
    # the FMU's own solver runs at its floor at most; an importer's (Model Exchange) as asked
    used, asked = tolerance_used(m.effective_tolerance) if m.interface == "CS" else (m.effective_tolerance, None)
    return ExperimentRecord(
        theta0=float(p.theta0), omega0=float(p.omega0), length=float(p.L), gravity=float(p.g),
        interface=m.interface, solver=m.solver, tolerance=used, tolerance_asked=asked,
        start_time=float(times[0]), stop_time=float(times[-1]),
        step=trajectory.grid.step(reference_period(trajectory.period, p)),
        fmi_version=str(description.fmiVersion), fmu=fmu_identity(fmu, description),
        writer=f"pendulum-fmu {__version__} {command}")


TOLERANCE_FLOOR = 1e-14
"""The smallest relative tolerance the FMU runs at (``instance/``: a smaller one runs at this
floor, with a warning)."""


def tolerance_used(asked: float) -> tuple[float, float | None]:
    """(the tolerance a run uses, the one asked for when different): a tolerance below
    :data:`TOLERANCE_FLOOR` runs at the floor."""
    return (TOLERANCE_FLOOR, asked) if asked < TOLERANCE_FLOOR else (asked, None)


# --- writing and reading ------------------------------------------------------------------------

def series_format(path: Path) -> str:
    """``.csv``, ``.csv.gz`` or ``.parquet`` from the end of the name; ValueError for another."""
    name = path.name.lower()
    for suffix in sorted(SERIES_FORMATS, key=len, reverse=True):
        if name.endswith(suffix):
            return suffix
    raise ValueError(f"{path}: the name must end in {', '.join(SERIES_FORMATS)}")


def sidecar_of(path: Path) -> Path:
    """The sidecar of a CSV file: ``run.csv`` -> ``run.csv.experiment.json``."""
    return path.with_name(path.name + SIDECAR_SUFFIX)


def _document(path: Path, record: ExperimentRecord | Sequence[tuple[Mapping[str, str], ExperimentRecord]]
              ) -> dict[str, Any]:
    head: dict[str, Any] = {"format": FORMAT, "file": path.name}
    if isinstance(record, ExperimentRecord):
        return {**head, "experiment": record.to_json()}
    return {**head, "runs": [{"select": {str(k): str(v) for k, v in select.items()}, "experiment": r.to_json()}
                             for select, r in record]}


def write_series(columns: Mapping[str, Sequence[Any] | np.ndarray], path: Path,
                 record: ExperimentRecord | Sequence[tuple[Mapping[str, str], ExperimentRecord]],
                 metadata: Mapping[str, str] | None = None, kinds: Mapping[str, str] | None = None) -> Path:
    """Write a time series and its experiment, whole or not at all.

    Parameters
    ----------
    columns : mapping of str to sequence
        Equal-length columns, in output order (the time first).
    path : Path
        Ends in ``.csv``, ``.csv.gz`` or ``.parquet``.
    record : ExperimentRecord, or sequence of (select, ExperimentRecord)
        The run's experiment; for a file of several runs, each run's with the column values
        that select its rows (``{"interface": "CS", "amplitude_deg": "75"}``).
    metadata : mapping of str to str, optional
        More key-value notes for the Parquet schema (a CSV gets only the sidecar).
    kinds : mapping of str to str, optional
        Column types (:func:`pendulum_fmu.output.tables.to_arrow`).

    Returns
    -------
    Path
        ``path``. For a CSV the sidecar :func:`sidecar_of` is written first; if the CSV then
        cannot be written, the sidecar is removed again.
    """
    kind = series_format(path)
    document = json.dumps(_document(path, record), indent=1, allow_nan=False) + "\n"
    if kind == ".parquet":
        table = to_arrow(columns, {**(metadata or {}), PARQUET_KEY: document}, kinds)
        return write_whole(path, lambda temporary: pq.write_table(table, temporary))
    table = to_arrow(columns, None, kinds)
    sidecar = sidecar_of(path)
    write_whole(sidecar, lambda temporary: temporary.write_text(document))
    try:
        if kind == ".csv.gz":
            def write(temporary: Path) -> None:
                with pa.CompressedOutputStream(str(temporary), "gzip") as stream:
                    pa_csv.write_csv(table, stream)
            return write_whole(path, write)
        return write_whole(path, lambda temporary: pa_csv.write_csv(table, temporary))
    except BaseException:
        sidecar.unlink(missing_ok=True)
        raise


def write_record(path: Path, record: ExperimentRecord | Sequence[tuple[Mapping[str, str], ExperimentRecord]]) -> Path:
    """Write only the sidecar of a CSV file written otherwise (a file of several runs, such as
    the study's ``runs.csv``); see :func:`write_series` for ``record``.

    Returns
    -------
    Path
        The sidecar, :func:`sidecar_of` ``path``.
    """
    series_format(path)
    document = json.dumps(_document(path, record), indent=1, allow_nan=False) + "\n"
    return write_whole(sidecar_of(path), lambda temporary: temporary.write_text(document))


def parse_document(text: str | bytes, source: str, file_name: str | None = None) -> list[
        tuple[dict[str, str], ExperimentRecord]]:
    """The runs of a record's JSON: ``[({}, record)]`` for one run, ``[(select, record), ...]``.

    Raises
    ------
    ValueError
        Not JSON, not this format, or a bad experiment (naming ``source``).
    """
    try:
        document = json.loads(text)
    except (ValueError, UnicodeDecodeError) as error:
        raise ValueError(f"{source}: not JSON ({error})") from None
    if not isinstance(document, dict) or document.get("format") != FORMAT:
        raise ValueError(f"{source}: not a {FORMAT!r} document")
    if file_name is not None and document.get("file") not in (None, file_name):
        raise ValueError(f"{source}: it describes {document.get('file')!r}, not {file_name!r}")
    try:
        if "experiment" in document:
            return [({}, ExperimentRecord.from_json(document["experiment"]))]
        return [({str(k): str(v) for k, v in run.get("select", {}).items()},
                 ExperimentRecord.from_json(run["experiment"])) for run in document["runs"]]
    except (KeyError, TypeError, AttributeError) as error:
        raise ValueError(f"{source}: malformed ({error})") from None
    except ValueError as error:
        raise ValueError(f"{source}: {error}") from None


def read_runs(path: Path) -> tuple[list[tuple[dict[str, str], ExperimentRecord]], str] | None:
    """Every run's experiment of a file written by :func:`write_series`, and where it was read;
    None when the file carries none (no sidecar, no metadata key).

    Raises
    ------
    ValueError
        The record exists but cannot be read.
    """
    path = Path(path)
    try:
        with path.open("rb") as handle:
            parquet = handle.read(4) == b"PAR1"
    except OSError:
        return None
    if parquet:
        try:
            metadata = pq.read_schema(path).metadata or {}
        except (OSError, pa.ArrowException):
            return None
        text = metadata.get(PARQUET_KEY.encode())
        if text is None:
            return _earlier_parquet(path, metadata)
        where = f"{path.name} (Parquet metadata)"
        return parse_document(text, where), where
    sidecar = sidecar_of(path)
    if not sidecar.is_file():
        return None
    return parse_document(sidecar.read_bytes(), str(sidecar), path.name), str(sidecar)


EARLIER_KEYS: tuple[str, ...] = ("amplitude_rad", "omega0_rad_s", "length_m", "gravity_m_s2", "interface", "solver",
                                 "tolerance")
"""The flat keys ``simulate`` wrote into Parquet metadata before records (and still writes beside one)."""


def _earlier_parquet(path: Path, metadata: Mapping[bytes, bytes]) -> tuple[
        list[tuple[dict[str, str], ExperimentRecord]], str] | None:
    """The experiment of a Parquet file ``simulate`` wrote before records: its flat keys, and
    its time column's first and last value; None when the keys are not all there."""
    values = {key: metadata.get(key.encode(), b"").decode() for key in EARLIER_KEYS}
    if not all(values.values()):
        return None
    where = f"{path.name} (Parquet metadata: {', '.join(EARLIER_KEYS)})"
    try:
        times = pq.read_table(path, columns=["time_s"]).column("time_s").to_numpy()
        record = ExperimentRecord(
            theta0=float(values["amplitude_rad"]), omega0=float(values["omega0_rad_s"]),
            length=float(values["length_m"]), gravity=float(values["gravity_m_s2"]),
            interface=values["interface"], solver=values["solver"],  # type: ignore[arg-type]
            tolerance=float(values["tolerance"]), start_time=float(times[0]), stop_time=float(times[-1]), step=None,
            fmi_version="?", fmu="?", writer="pendulum-fmu simulate (before records)")
    except (KeyError, IndexError, ValueError, OSError, pa.ArrowException) as error:
        raise ValueError(f"{where}: {error}") from None
    return [({}, record)], where


def read_record(path: Path) -> FoundRecord | None:
    """The experiment of a one-run file written by :func:`write_series`; None when it carries
    none, or several runs (use :func:`read_runs`).

    Raises
    ------
    ValueError
        The record exists but cannot be read.
    """
    found = read_runs(path)
    if found is None or len(found[0]) != 1 or found[0][0][0]:
        return None
    return FoundRecord(found[0][0][1], found[1])


__all__ = ["FORMAT", "PARQUET_KEY", "SERIES_FORMATS", "SIDECAR_SUFFIX", "TOLERANCE_FLOOR", "ExperimentRecord",
           "FoundRecord", "fmu_identity", "read_record", "read_runs", "record_of", "series_format", "sidecar_of",
           "tolerance_used", "write_record", "write_series"]
