"""Is this FMU the project's Pendulum? Its model description, checked once, in one line.

The package drives the FMU by its variables' names (``theta``, ``theta_exact``, ``solver``,
``stats.steps`` ...) in both FMI versions. An FMU of another model would fail later with a
message about a missing variable, or run and record nonsense; so every entry point
(:func:`~pendulum_fmu.fmu.locate.locate_fmu`, :class:`~pendulum_fmu.fmu.runner.FmuRunner`,
:func:`~pendulum_fmu.sweep.run.run_sweep`) asks :func:`pendulum_problem` first.

fmpy reads a file's model description once (:func:`read_description`): the check of the
command line, the FMI version asked and the runner that loads the FMU share that reading, as
long as the file is not changed on disk.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path
from typing import Any

MODEL_NAME = "Pendulum"
FMI_VERSIONS: dict[str, int] = {"2.0": 2, "3.0": 3}
"""The ``fmiVersion`` attributes the package runs, and their major version."""

REAL_VARIABLES: tuple[str, ...] = ("L", "g", "theta", "omega", "theta_exact", "omega_exact", "period", "x", "y")
"""Variables the package sets or records, of type Real (FMI 2.0) or Float64 (FMI 3.0)."""
INTEGER_VARIABLES: tuple[str, ...] = ("solver", "stats.steps", "stats.rejected_steps", "stats.rhs_evaluations")
"""The solver choice (an Enumeration) and the solver's counters (Integer / Int32)."""

_REAL_TYPES = ("Real", "Float64")
_INTEGER_TYPES = ("Integer", "Enumeration", "Int32")


def description_problem(description: Any) -> str | None:
    """What makes a read model description not this project's Pendulum, or None.

    Parameters
    ----------
    description : fmpy.model_description.ModelDescription
        As read by fmpy.

    Returns
    -------
    str or None
        The first thing that differs, in a few words.
    """
    version = str(description.fmiVersion)
    if version not in FMI_VERSIONS:
        return f"it is an FMI {version} FMU (the package runs FMI 2.0 and 3.0)"
    if description.modelName != MODEL_NAME:
        return f"its model is {description.modelName!r}, not {MODEL_NAME!r}"
    if description.coSimulation is None or description.modelExchange is None:
        return "it lacks Co-Simulation or Model Exchange"
    types = {variable.name: variable.type for variable in description.modelVariables}
    for names, allowed in ((REAL_VARIABLES, _REAL_TYPES), (INTEGER_VARIABLES, _INTEGER_TYPES)):
        for name in names:
            if name not in types:
                return f"it has no variable {name!r}"
            if types[name] not in allowed:
                return f"its variable {name!r} is of type {types[name]}, not {' or '.join(allowed)}"
    return None


def pendulum_problem(path: Path) -> str | None:
    """Why the FMU at ``path`` cannot be run by this package, in one line; None if it can.

    Parameters
    ----------
    path : Path
        An FMU file (a zip archive) or an extracted FMU's folder.

    Returns
    -------
    str or None
        ``'X.fmu' is not the Pendulum FMU of pendulum-fmu: ...`` when the model description
        cannot be read or describes another model.
    """
    def refused(problem: str) -> str:
        return (f"{str(path)!r} is not the Pendulum FMU of pendulum-fmu: {problem}; the package runs only its own "
                "Pendulum.fmu (FMI 2.0 or 3.0)")

    try:
        version = _root_attribute(Path(path), "fmiVersion")
        if version not in FMI_VERSIONS:   # fmpy would read it by the rules of its version, or fail oddly
            return refused(f"it is an FMI {version} FMU (the package runs FMI 2.0 and 3.0)")
        description = read_description(path)
    except Exception as error:  # noqa: BLE001 (lxml, zipfile and fmpy raise many kinds)
        reason = " ".join(str(error).split()) or type(error).__name__
        return f"{str(path)!r} is not a usable FMU: its modelDescription.xml cannot be read ({reason})"
    problem = description_problem(description)
    return None if problem is None else refused(problem)


def _root_attribute(path: Path, name: str) -> str:
    """An attribute of modelDescription.xml's root element (an FMU file or an extracted folder)."""
    import xml.etree.ElementTree as ElementTree
    import zipfile

    if path.is_dir():
        root = ElementTree.parse(path / "modelDescription.xml").getroot()
    else:
        with zipfile.ZipFile(path) as archive, archive.open("modelDescription.xml") as xml:
            root = ElementTree.parse(xml).getroot()
    return str(root.get(name))


def fmi_version_of(path: Path) -> int:
    """The major FMI version (2 or 3) of a Pendulum FMU that :func:`pendulum_problem` accepted."""
    return FMI_VERSIONS[str(read_description(path).fmiVersion)]


def file_key(path: Path) -> tuple[str, int, int]:
    """``path`` as given, with the modification time (ns) and size of its model description's file.

    Raises
    ------
    OSError
        If there is no such file.
    """
    path = Path(path)
    stat = (path / "modelDescription.xml" if path.is_dir() else path).stat()
    return str(path), stat.st_mtime_ns, stat.st_size


def read_description(path: Path) -> Any:
    """fmpy's model description of an FMU file or extracted folder, read once per version of the file.

    Raises
    ------
    Exception
        Whatever reading it raises (OSError, zipfile's, lxml's and fmpy's errors).
    """
    return _read_description(*file_key(path))


@lru_cache(maxsize=16)
def _read_description(path: str, mtime_ns: int, size: int) -> Any:
    """The reading behind :func:`read_description`; the time and size make a changed file a new key."""
    from fmpy import read_model_description

    return read_model_description(path, validate=False)
