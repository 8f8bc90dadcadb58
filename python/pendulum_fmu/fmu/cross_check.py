"""Export the FMUs in the layout of the FMI cross-check repository.

For each FMU, each interface its model description declares (``cs``, ``me``) and each platform
it carries a binary for, one folder
``fmus/<FMI version>/<cs|me>/<platform>/PendulumFMU/<version>/Pendulum/`` (the cross-check
rules, 9.1.4 and 9.1.5) holding

- ``Pendulum.fmu``, the FMU as built;
- ``Pendulum_ref.csv``, the FMU's own FMI-LS-REF reference result (the exact solution of the
  default experiment, the file its manifest names with the role ``result``): time and the
  outputs, names quoted as the rules' CSV appendix asks;
- ``Pendulum_ref.opt``, the default experiment of the model description: StartTime,
  StopTime, StepSize, RelTol, and OutputIntervalLength, the reference's spacing;
- ``ReadMe.txt``, what the files are and what a correct importer reproduces.

Platforms: FMI 2.0's ``linux64``, ``win64``, ``darwin64`` as they are; FMI 3.0's
``x86_64-linux``, ``x86_64-windows``, ``x86_64-darwin`` as ``linux64``, ``win64``,
``darwin64``, and ``aarch64-linux`` under its own name. A binary for another platform
(``aarch64-darwin``) has no cross-check name and is left out (:func:`platforms` says which).
"""

from __future__ import annotations

import posixpath
import shutil
import xml.etree.ElementTree as ET
import zipfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from pendulum_fmu import __version__

TOOL_NAME = "PendulumFMU"
MODEL_NAME = "Pendulum"
LS_REF = "extra/org.fmi-standard.fmi-ls-ref/"
PLATFORMS: dict[str, dict[str, str]] = {
    "2.0": {"linux64": "linux64", "win64": "win64", "darwin64": "darwin64"},
    "3.0": {"x86_64-linux": "linux64", "x86_64-windows": "win64", "x86_64-darwin": "darwin64",
            "aarch64-linux": "aarch64-linux"},
}
"""The FMU's ``binaries/`` folder name to the cross-check platform, by FMI version."""
INTERFACES: dict[str, str] = {"cs": "CoSimulation", "me": "ModelExchange"}

README = """Pendulum ({tool} {version}, FMI {fmi_version}, {interface_name}, {platform})

The nonlinear simple pendulum theta'' + (g/L) sin(theta) = 0, with its start values
L = {L} m, g = {g} m/s2, theta(0) = {theta} rad, omega(0) = {omega} rad/s, and beside
the numerical solution (theta, omega) the exact one (theta_exact, omega_exact, from Jacobi
elliptic functions) computed inside the FMU. No inputs: there is no Pendulum_in.csv.

The experiment (Pendulum_ref.opt) is the model description's DefaultExperiment:
{start} s to {stop} s, step size {step} s, relative tolerance {tolerance}.

Pendulum_ref.csv is the exact solution at {rows} equally spaced times, the FMU's own reference
result (extra/org.fmi-standard.fmi-ls-ref/ inside the FMU, FMI-LS-REF). A correct importer
reproduces theta_exact and omega_exact to rounding, and theta and omega to its solver's
accuracy: in Co-Simulation, with the FMU's own solver at this tolerance, within 1e-6 rad.
The cross-check's validation band (10 % of each signal's range) is far looser;
'pendulum-fmu judge OUT.csv --cross-check-verdict DIR' checks a result against the exact
solution itself and writes DIR/passed, DIR/failed or DIR/rejected.

Exported by 'pendulum-fmu cross-check' of {tool} {version}.
"""


@dataclass(frozen=True)
class Described:
    """What an FMU's model description says that the export needs."""

    fmi_version: str
    interfaces: tuple[str, ...]
    model_identifier: str
    experiment: dict[str, float]
    start: dict[str, str]


def describe(fmu: Path) -> Described:
    """Read the FMI version, the interfaces, the DefaultExperiment and the start values.

    Raises
    ------
    ValueError
        An FMU that is not FMI 2.0 or 3.0, declares no interface, or has no complete
        DefaultExperiment.
    """
    with zipfile.ZipFile(fmu) as archive:
        root = ET.fromstring(archive.read("modelDescription.xml"))
    version = root.get("fmiVersion", "")
    fmi_version = "2.0" if version == "2.0" else "3.0" if version.startswith("3.") else ""
    if not fmi_version:
        raise ValueError(f"{fmu}: FMI version {version!r}: the export knows 2.0 and 3.0")
    found = [(key, root.find(element)) for key, element in INTERFACES.items()]
    interfaces = tuple(key for key, element in found if element is not None)
    identifiers = {element.get("modelIdentifier", "") for _, element in found if element is not None}
    if not interfaces or len(identifiers) != 1:
        raise ValueError(f"{fmu}: no interface, or interfaces with different model identifiers")
    default = root.find("DefaultExperiment")
    names = ("startTime", "stopTime", "stepSize", "tolerance")
    if default is None or any(default.get(name) is None for name in names):
        raise ValueError(f"{fmu}: the DefaultExperiment must give {', '.join(names)}")
    experiment = {name: float(default.get(name, "nan")) for name in names}
    start: dict[str, str] = {}
    for element in root.iter():
        name = element.get("name")
        if name in ("theta", "omega", "L", "g"):
            typed = element if element.get("start") is not None else next(iter(element), None)
            if typed is not None and typed.get("start") is not None:
                start[name] = typed.get("start", "")
    return Described(fmi_version, interfaces, identifiers.pop(), experiment, start)


def platforms(fmu: Path, described: Described) -> tuple[list[str], list[str]]:
    """The cross-check platforms the FMU carries a binary for, and the binaries' folders left out."""
    known = PLATFORMS[described.fmi_version]
    with zipfile.ZipFile(fmu) as archive:
        folders = sorted({name.split("/")[1] for name in archive.namelist()
                          if name.startswith("binaries/") and name.count("/") == 2
                          and posixpath.splitext(name.split("/")[2])[0] == described.model_identifier})
    return [known[f] for f in folders if f in known], [f for f in folders if f not in known]


def reference_csv(fmu: Path) -> bytes:
    """The FMU's FMI-LS-REF reference result: the file its manifest names with the role ``result``.

    Raises
    ------
    ValueError
        No manifest, no result named, or the file missing.
    """
    with zipfile.ZipFile(fmu) as archive:
        try:
            manifest = ET.fromstring(archive.read(LS_REF + "fmi-ls-manifest.xml"))
        except KeyError:
            raise ValueError(f"{fmu}: no {LS_REF}fmi-ls-manifest.xml (built without the reference result?)") from None
        sources = [r.get("source", "") for r in manifest.iter("Related")
                   if r.get("role") == "result" and r.get("type", "text/csv") == "text/csv"]
        if not sources:
            raise ValueError(f"{fmu}: the manifest names no result")
        member = posixpath.normpath(posixpath.join(LS_REF, sources[0]))
        try:
            return archive.read(member)
        except KeyError:
            raise ValueError(f"{fmu}: the manifest names {member}, which the FMU does not hold") from None


def _opt_text(experiment: dict[str, float], spacing: float) -> str:
    return (f"StartTime, {experiment['startTime']!r}\nStopTime, {experiment['stopTime']!r}\n"
            f"StepSize, {experiment['stepSize']!r}\nRelTol, {experiment['tolerance']!r}\n"
            f"OutputIntervalLength, {spacing!r}\n")


def export_fmu(fmu: Path, root: Path) -> list[Path]:
    """Export one FMU under ``root`` for each interface and platform it carries; return the model folders.

    Raises
    ------
    ValueError
        The FMU lacks what the export needs (:func:`describe`, :func:`reference_csv`).
    """
    described = describe(fmu)
    carried, _ = platforms(fmu, described)
    reference = reference_csv(fmu)
    lines = reference.decode().strip().splitlines()
    times = [float(line.split(",", 1)[0]) for line in (lines[1], lines[-1])]
    spacing = (times[1] - times[0]) / (len(lines) - 2)
    folders = []
    for interface in described.interfaces:
        for platform in carried:
            folder = (root / "fmus" / described.fmi_version / interface / platform / TOOL_NAME / __version__
                      / MODEL_NAME)
            folder.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(fmu, folder / f"{MODEL_NAME}.fmu")
            (folder / f"{MODEL_NAME}_ref.csv").write_bytes(reference)
            (folder / f"{MODEL_NAME}_ref.opt").write_text(_opt_text(described.experiment, spacing))
            experiment = described.experiment
            (folder / "ReadMe.txt").write_text(README.format(
                tool=TOOL_NAME, version=__version__, fmi_version=described.fmi_version,
                interface_name=INTERFACES[interface], platform=platform, rows=len(lines) - 1,
                start=f"{experiment['startTime']:g}", stop=f"{experiment['stopTime']:g}",
                step=f"{experiment['stepSize']!r}", tolerance=f"{experiment['tolerance']:g}",
                **{name: described.start.get(name, "?") for name in ("L", "g", "theta", "omega")}))
            folders.append(folder)
    return folders


def export(fmus: Path | Sequence[Path], root: Path) -> list[Path]:
    """Export each FMU (FMI 2.0 and 3.0) under ``root``; return the model folders, FMU by FMU."""
    paths = [fmus] if isinstance(fmus, Path) else list(fmus)
    folders: list[Path] = []
    for fmu in paths:
        folders += export_fmu(fmu, root)
    return folders
