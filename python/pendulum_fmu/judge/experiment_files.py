"""The experiment a result's files state: the result's own record (what this package writes
with every time series), a cross-check ``<Model>_ref.opt`` beside (or, for a ``results/``
folder, across from) the result, else the FMU's FMI-LS-REF ``.exp``."""

from __future__ import annotations

import math
import posixpath
import xml.etree.ElementTree as ET
import zipfile
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

from pendulum_fmu.errors import UsageError

LS_REF = "extra/org.fmi-standard.fmi-ls-ref/"
"""The FMI-LS-REF folder of an FMU; its manifest is ``fmi-ls-manifest.xml``."""
EXPERIMENTS_TYPE = "application/x-ma-hs-experiments"
OPT_REQUIRED: tuple[str, ...] = ("StartTime", "StopTime", "StepSize", "RelTol")
"""The elements a cross-check ``_ref.opt`` must have (the cross-check rules, 9.1.4)."""
SPAN_SLACK = 1e-9
"""Relative slack, of the experiment's length, in comparing a file's first and last time with it."""


@dataclass(frozen=True)
class ExperimentFile:
    """An experiment as a file states it.

    Attributes
    ----------
    source : str
        The file, e.g. ``.../Pendulum_ref.opt`` or ``Pendulum.fmu:extra/.../Pendulum.exp``.
    start_time, stop_time : float
        The experiment's span, s.
    step : float or None
        The communication step (None: not given, or 0, a variable-step run).
    tolerance : float or None
        The relative tolerance.
    interface : {"CS", "ME"} or None
        From a cross-check folder's ``cs`` / ``me``, or the result's own record; None when the
        file does not say.
    values : tuple of (name, value)
        Start values and parameters the file states (names of
        :data:`pendulum_fmu.judge.experiment.NAMES`: a result's own record states theta, omega,
        L, g and the solver); empty for the FMU's experiment.
    note : str
        More of what the file says (a record's FMI version and FMU), for :meth:`describe`.

    The step applies only to a result that is a run of the experiment (:meth:`covers`): a file
    on another grid (the cross-check reference, at its own output interval) keeps its own.
    """

    source: str
    start_time: float
    stop_time: float
    step: float | None
    tolerance: float | None
    interface: Literal["CS", "ME"] | None = None
    values: tuple[tuple[str, float | str], ...] = ()
    note: str = ""

    def covers(self, first: float, last: float, rows: int) -> bool:
        """True when a result with these first and last times and rows is a run of this experiment.

        It is when it starts at the start time, ends at the stop time and has the experiment's
        number of steps (one more for a short last step).
        """
        length = self.stop_time - self.start_time
        slack = SPAN_SLACK * max(length, abs(self.stop_time))
        if abs(first - self.start_time) > slack or abs(last - self.stop_time) > slack:
            return False
        if self.step is None:
            return True
        steps = length / self.step
        return rows - 1 in (math.floor(steps + 1e-9), math.ceil(steps - 1e-9))

    def stated(self) -> dict[str, float | str]:
        """What the file states, by the judge's start names: its values, ``startTime`` and
        ``tolerance`` (when it gives one)."""
        found: dict[str, float | str] = dict(self.values)
        found["startTime"] = self.start_time
        if self.tolerance is not None:
            found["tolerance"] = self.tolerance
        return found

    def describe(self) -> str:
        """One line: the file, and the experiment it states."""
        parts = [f"{name} {value!r}" if isinstance(value, float) else f"{name} {value}"
                 for name, value in self.values]
        parts += [f"startTime {self.start_time:g}", f"stopTime {self.stop_time:g}",
                 f"step {self.step:g}" if self.step is not None else "variable step",
                 f"tolerance {self.tolerance:g}" if self.tolerance is not None else "no tolerance"]
        if self.interface is not None:
            parts.append(self.interface)
        if self.note:
            parts.append(self.note)
        return f"{self.source}: {', '.join(parts)}"


def _number(text: str | None, what: str, source: str) -> float | None:
    """A finite float from an attribute or cell, None when absent; ValueError naming it when bad."""
    if text is None or not text.strip():
        return None
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{source}: {what} {text.strip()!r} is not a number") from None
    if not math.isfinite(value):
        raise ValueError(f"{source}: {what} {text.strip()!r} is not finite")
    return value


def read_experiments(xml_text: str | bytes, source: str) -> ExperimentFile:
    """The first experiment of an ma-hs-experiments ``.exp`` file.

    The times and the step are read from the ``<Experiment>`` element's attributes, as the
    format's text lays them out, or from its ``<TransientSimulation>`` child, as its newer
    schema does; the tolerance from ``<Experiment>``.

    Raises
    ------
    ValueError
        Not an ``<Experiments>`` file, no experiment, or a start and stop time missing or out of order.
    """
    try:
        root = ET.fromstring(xml_text)
    except ET.ParseError as error:
        raise ValueError(f"{source}: not XML ({error})") from None
    if root.tag != "Experiments":
        raise ValueError(f"{source}: the root element is <{root.tag}>, not <Experiments>")
    experiment = root.find("Experiment")
    if experiment is None:
        raise ValueError(f"{source}: no <Experiment>")
    transient = experiment.find("TransientSimulation")

    def attribute(name: str) -> float | None:
        where = transient if transient is not None and transient.get(name) is not None else experiment
        return _number(where.get(name), name, source)

    start, stop, step = attribute("startTime"), attribute("stopTime"), attribute("stepSize")
    if start is None or stop is None or not stop > start:
        raise ValueError(f"{source}: the experiment needs a startTime and a later stopTime")
    return ExperimentFile(source, start, stop, step if step else None,
                    _number(experiment.get("tolerance"), "tolerance", source))


def fmu_experiment(fmu: Path) -> ExperimentFile | None:
    """The FMU's FMI-LS-REF experiment, None when its manifest names none.

    Of the manifest's ``<Related>`` files in the experiments format, the one with the role
    ``experiment/validation`` is taken, else the first with the role ``experiment``.

    Raises
    ------
    ValueError
        The manifest or the experiments file it names cannot be read.
    """
    with zipfile.ZipFile(fmu) as archive:
        try:
            manifest_text = archive.read(LS_REF + "fmi-ls-manifest.xml")
        except KeyError:
            return None
        try:
            manifest = ET.fromstring(manifest_text)
        except ET.ParseError as error:
            raise ValueError(f"{fmu.name}: {LS_REF}fmi-ls-manifest.xml is not XML ({error})") from None
        related = [r for r in manifest.iter("Related")
                   if r.get("role", "").split("/")[0] == "experiment"
                   and (r.get("type") == EXPERIMENTS_TYPE or r.get("source", "").endswith(".exp"))]
        if not related:
            return None
        chosen = next((r for r in related if r.get("role") == "experiment/validation"), related[0])
        member = posixpath.normpath(posixpath.join(LS_REF, chosen.get("source", "")))
        try:
            text = archive.read(member)
        except KeyError:
            raise ValueError(f"{fmu.name}: the manifest names {member}, which the FMU does not hold") from None
    return read_experiments(text, f"{fmu.name}:{member}")


def read_ref_opt(path: Path) -> ExperimentFile:
    """A cross-check ``<Model>_ref.opt``: ``Name, value`` lines, as the cross-check rules lay them out.

    The interface is the folder's ``cs`` or ``me`` when the file sits in the cross-check layout
    (``fmus/<version>/<cs|me>/<platform>/<tool>/<version>/<Model>/``).

    Raises
    ------
    ValueError
        A required element missing or not a number, or StartTime >= StopTime.
    """
    values: dict[str, float] = {}
    for line in path.read_text(errors="replace").splitlines():
        name, comma, value = line.partition(",")
        if comma and name.strip() in OPT_REQUIRED:
            number = _number(value.split("//")[0], name.strip(), path.name)
            if number is not None:
                values[name.strip()] = number
    missing = [name for name in OPT_REQUIRED if name not in values]
    if missing:
        raise ValueError(f"{path.name}: no {', '.join(missing)}")
    if not values["StopTime"] > values["StartTime"]:
        raise ValueError(f"{path.name}: StartTime must be before StopTime")
    kind = path.parts[-6] if len(path.parts) >= 8 and path.parts[-8] == "fmus" else ""
    interface: Literal["CS", "ME"] | None = "CS" if kind == "cs" else "ME" if kind == "me" else None
    return ExperimentFile(str(path), values["StartTime"], values["StopTime"], values["StepSize"] or None,
                    values["RelTol"], interface)


def cross_check_opt(result: Path) -> Path | None:
    """The ``<Model>_ref.opt`` that belongs to a result file, None when it sits in no cross-check folder.

    Beside the file (``.../<Model>/<Model>_ref.opt``), or, for an importer's
    ``results/<version>/<type>/<platform>/<importer>/<version>/<exporter>/<version>/<Model>/``,
    the exporter's ``fmus/<version>/<type>/<platform>/<exporter>/<version>/<Model>/`` of the same
    repository.
    """
    folder = result.resolve().parent
    beside = folder / f"{folder.name}_ref.opt"
    if beside.is_file():
        return beside
    parts = folder.parts
    if len(parts) >= 10 and parts[-9] == "results":
        version, kind, platform, _, _, exporter, exporter_version, model = parts[-8:]
        across = Path(*parts[:-9], "fmus", version, kind, platform, exporter, exporter_version, model,
                      f"{model}_ref.opt")
        if across.is_file():
            return across
    return None


def recorded_experiment(result: Path) -> ExperimentFile | None:
    """The experiment a result of this package records about itself
    (:mod:`pendulum_fmu.output.experiment_record`: a CSV's sidecar, a Parquet file's metadata),
    None when it records none.

    Raises
    ------
    UsageError
        The record exists but cannot be read (naming ``result``).
    """
    from pendulum_fmu.output.experiment_record import read_record

    try:
        found = read_record(result)
    except (OSError, ValueError) as error:
        raise UsageError("result", f"its experiment record is unreadable: {error}") from None
    if found is None:
        return None
    r = found.record
    if not r.stop_time > r.start_time:
        return None
    asked = f", asked {r.tolerance_asked:g}" if r.tolerance_asked is not None else ""
    return ExperimentFile(found.source, r.start_time, r.stop_time, r.step, r.tolerance, r.interface,
                    (("theta", r.theta0), ("omega", r.omega0), ("L", r.length), ("g", r.gravity), ("solver", r.solver)),
                    f"FMI {r.fmi_version} {r.fmu}{asked}, written by {r.writer}")


def experiment_file(result: object, fmu: Path | None = None) -> ExperimentFile | None:
    """The experiment a result was run with, as a file states it; None when no file does.

    The result's own record (:func:`recorded_experiment`: what this package writes with every
    time series); else a cross-check ``_ref.opt`` for a result in a cross-check folder
    (:func:`cross_check_opt`); else the FMI-LS-REF experiment of ``fmu``, or of the FMU
    :func:`pendulum_fmu.fmu.locate.locate_fmu` finds without building.

    Raises
    ------
    UsageError
        The record or the ``_ref.opt`` (naming ``result``) or the FMU's experiment (naming
        ``fmu``) is unreadable.
    """
    from pendulum_fmu.errors import BuildError
    from pendulum_fmu.fmu.locate import locate_fmu

    if isinstance(result, (str, Path)):
        recorded = recorded_experiment(Path(result))
        if recorded is not None:
            return recorded
        opt = cross_check_opt(Path(result))
        if opt is not None:
            try:
                return read_ref_opt(opt)
            except (OSError, ValueError) as error:
                raise UsageError("result", f"its cross-check options file is unreadable: {error}") from None
    path = fmu
    if path is None:
        try:
            path = locate_fmu(None, build=False)
        except (UsageError, BuildError):
            return None
    try:
        return fmu_experiment(path)
    except (OSError, ValueError, zipfile.BadZipFile) as error:
        raise UsageError("fmu", f"its FMI-LS-REF experiment is unreadable: {error}") from None
