"""What a result is judged against: the start values, parameters, interface and tolerance the
caller gives, over what a file states (:mod:`pendulum_fmu.judge.experiment_files`), over the
model description's defaults."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
import zipfile
from collections.abc import Mapping
from pathlib import Path
from typing import Literal

from pendulum_fmu.errors import UsageError
from pendulum_fmu.judge.experiment_files import ExperimentFile
from pendulum_fmu.judge.verdict import Experiment
from pendulum_fmu.spec import InitialValueProblem

NUMBERS: tuple[str, ...] = ("theta", "omega", "L", "g", "tolerance", "startTime")
NAMES: tuple[str, ...] = NUMBERS + ("solver",)
FALLBACK: dict[str, float | str] = {"theta": math.radians(75.0), "omega": 0.0, "L": 1.0, "g": 9.81,
                                    "tolerance": 1e-8, "solver": "rkn", "startTime": 0.0}
"""The FMU's defaults, used only when no model description can be found."""


def model_description_defaults(xml_text: str | bytes) -> dict[str, float | str]:
    """Start values of theta, omega, L, g, the solver's name, the default tolerance and start time.

    Parameters
    ----------
    xml_text : str or bytes
        An FMI 2.0 or FMI 3.0 ``modelDescription.xml``.

    Returns
    -------
    dict
        Keys among :data:`NAMES`; a key is missing when the description does not give it.
    """
    root = ET.fromstring(xml_text)
    found: dict[str, float | str] = {}
    experiment = root.find("DefaultExperiment")
    for key in ("tolerance", "startTime"):
        if experiment is not None and experiment.get(key):
            found[key] = float(experiment.get(key, "nan"))
    items: dict[str, str] = {}
    for item in root.iter("Item"):
        items[item.get("value", "")] = item.get("name", "")
    elements = list(root.iter("ScalarVariable")) + [e for e in root.iter() if e.tag in ("Float64", "Enumeration")]
    for element in elements:
        name = element.get("name")
        if name not in NAMES:
            continue
        if element.tag == "ScalarVariable":
            typed = next(iter(element), None)
            start = typed.get("start") if typed is not None else None
            kind = typed.tag if typed is not None else ""
        else:
            start, kind = element.get("start"), element.tag
        if start is None:
            continue
        found[name] = items.get(start, start) if kind == "Enumeration" else float(start)
    return found


def defaults(fmu: Path | None = None) -> tuple[dict[str, float | str], str]:
    """The defaults and where they came from.

    ``fmu`` when given; else the FMU :func:`pendulum_fmu.fmu.locate.locate_fmu` finds without
    building; else the repository's ``modelDescription.xml``; else :data:`FALLBACK`.
    """
    from pendulum_fmu.errors import BuildError
    from pendulum_fmu.fmu.build import REPO_ROOT
    from pendulum_fmu.fmu.locate import locate_fmu

    path: Path | None = fmu
    if path is None:
        try:
            path = locate_fmu(None, build=False)
        except (UsageError, BuildError):
            path = None
    try:
        if path is not None:
            with zipfile.ZipFile(path) as archive:
                found = model_description_defaults(archive.read("modelDescription.xml"))
            return {**FALLBACK, **found}, str(path)
    except (OSError, KeyError, zipfile.BadZipFile, ET.ParseError) as error:
        if fmu is not None:
            raise UsageError("fmu", f"cannot read its modelDescription.xml: {error}") from None
    source = REPO_ROOT / "modelDescription.xml"
    if source.is_file():
        return {**FALLBACK, **model_description_defaults(source.read_bytes())}, str(source)
    return dict(FALLBACK), "the FMU's documented defaults"


def start_value_fault(name: str, number: float) -> str | None:
    """What is wrong with ``number`` as the start value ``name``, None when nothing is.

    Every number must be finite; ``L``, ``g`` and ``tolerance`` also > 0.
    """
    positive = name in ("L", "g", "tolerance")
    if not math.isfinite(number) or (positive and number <= 0):
        return f"must be finite{' and > 0' if positive else ''}"
    return None


def check_start(start: Mapping[str, float | str] | None) -> dict[str, float | str]:
    """The start values and settings a run set, checked: numbers as floats, ``solver`` as a string.

    Parameters
    ----------
    start : mapping, optional
        Names of :data:`NAMES`: ``theta`` (rad) and ``omega`` (rad/s), the parameters ``L`` and
        ``g``, ``tolerance`` (> 0), ``startTime`` (when the start values hold), ``solver`` (any
        name; informational for Model Exchange runs).

    Raises
    ------
    UsageError
        For an unknown name or a bad value, naming ``start``.
    """
    if start is not None and not isinstance(start, Mapping):
        raise UsageError("start", f"a mapping of name to value, e.g. {{'theta': 1.4}}, not {type(start).__name__}")
    values: dict[str, float | str] = {}
    for name, value in (start or {}).items():
        if name not in NAMES:
            raise UsageError("start", f"unknown name {name!r} (known: {', '.join(NAMES)})")
        if name == "solver":
            values[name] = str(value)
            continue
        try:
            number = float(value)
        except (TypeError, ValueError):
            raise UsageError("start", f"{name}={value!r} is not a number") from None
        fault = start_value_fault(name, number)
        if fault is not None:
            raise UsageError("start", f"{name}={value!r}: {fault}")
        values[name] = number
    return values


def make_experiment(start: Mapping[str, float | str] | None = None, interface: Literal["CS", "ME"] | None = "CS",
                    fmu: Path | None = None, stated: ExperimentFile | None = None) -> tuple[Experiment, str]:
    """The :class:`Experiment` to judge against, and where its defaults came from.

    Each value is the first of: ``start`` (what the caller gave), ``stated`` (what a file
    states: :meth:`ExperimentFile.stated`), the defaults (:func:`defaults`). The interface is
    ``interface``, else the file's, else Co-Simulation.

    Raises
    ------
    UsageError
        A bad ``start`` or ``interface``, or an unreadable ``fmu``.
    """
    chosen = interface or (stated.interface if stated is not None else None) or "CS"
    if chosen not in ("CS", "ME"):
        raise UsageError("interface", f"must be CS or ME, got {chosen!r}")
    given = check_start(start)
    from_file = {name: value for name, value in stated.stated().items() if name not in given} if stated else {}
    base, where = defaults(fmu)
    chosen_values = {**check_start(from_file), **given}
    merged = {**base, **chosen_values}
    problem = InitialValueProblem(float(merged["theta"]), float(merged["omega"]), float(merged["L"]),
                                  float(merged["g"]))
    solver = (str(chosen_values["solver"]) if "solver" in chosen_values
              else (str(base["solver"]) if chosen == "CS" else None))
    return Experiment(problem, chosen, tolerance=float(merged["tolerance"]),
                      tolerance_stated="tolerance" in chosen_values, solver=solver,
                      given=tuple(sorted(chosen_values)), start_time=float(merged["startTime"])), where
