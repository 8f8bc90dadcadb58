"""What a result is judged against: start values and parameters (``--start NAME=VALUE``),
the interface and the tolerance, with the model description's defaults for the rest."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path
from typing import Literal

from pendulum_fmu.errors import UsageError
from pendulum_fmu.judge.verdict import Experiment

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
    from pendulum_fmu.errors import BuildError  # noqa: PLC0415
    from pendulum_fmu.fmu.build import REPO_ROOT  # noqa: PLC0415
    from pendulum_fmu.fmu.locate import locate_fmu  # noqa: PLC0415

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
            raise UsageError("--fmu", f"cannot read its modelDescription.xml: {error}") from None
    source = REPO_ROOT / "modelDescription.xml"
    if source.is_file():
        return {**FALLBACK, **model_description_defaults(source.read_bytes())}, str(source)
    return dict(FALLBACK), "the FMU's documented defaults"


def parse_start(pairs: list[str] | dict[str, float | str] | None) -> dict[str, float | str]:
    """``["theta=1.4", "L=2"]`` (or a dict) to checked values by name.

    ``theta`` also takes degrees (``theta=80deg``); ``tolerance`` must be > 0, ``L`` and ``g``
    finite and > 0; ``startTime`` is when the start values hold; ``solver`` is any name
    (informational for Model Exchange runs).

    Raises
    ------
    UsageError
        For an unknown name or a bad value, naming ``--start``.
    """
    if pairs is None:
        return {}
    items = list(pairs.items()) if isinstance(pairs, dict) else []
    if not isinstance(pairs, dict):
        for pair in pairs:
            name, sep, value = pair.partition("=")
            if not sep:
                raise UsageError("--start", f"expected NAME=VALUE, got {pair!r}")
            items.append((name.strip(), value.strip()))
    values: dict[str, float | str] = {}
    for name, raw in items:
        if name not in NAMES:
            raise UsageError("--start", f"unknown name {name!r} (known: {', '.join(NAMES)})")
        if name == "solver":
            values[name] = str(raw)
            continue
        text = str(raw)
        scale = 1.0
        if name == "theta" and text.endswith("deg"):
            text, scale = text[:-3], math.pi / 180.0
        try:
            number = float(text) * scale
        except ValueError:
            raise UsageError("--start", f"{name}={raw!r} is not a number") from None
        if not math.isfinite(number) or (name in ("L", "g", "tolerance") and number <= 0):
            raise UsageError("--start", f"{name}={raw!r}: must be finite{' and > 0' if name in ('L', 'g', 'tolerance') else ''}")
        values[name] = number
    return values


def make_experiment(start: list[str] | dict[str, float | str] | None = None,
                    interface: Literal["CS", "ME"] = "CS", fmu: Path | None = None) -> tuple[Experiment, str]:
    """The :class:`Experiment` for the given start values over the defaults, and the defaults' source."""
    if interface not in ("CS", "ME"):
        raise UsageError("--interface", f"must be CS or ME, got {interface!r}")
    given = parse_start(start)
    base, where = defaults(fmu)
    merged = {**base, **given}
    return Experiment(theta0=float(merged["theta"]), omega0=float(merged["omega"]), L=float(merged["L"]),
                      g=float(merged["g"]), interface=interface, tolerance=float(merged["tolerance"]),
                      tolerance_stated="tolerance" in given,
                      solver=str(given["solver"]) if "solver" in given else (str(base["solver"]) if interface == "CS" else None),
                      given=tuple(sorted(given)), start_time=float(merged["startTime"])), where
