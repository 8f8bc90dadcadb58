"""Find the ``Pendulum.fmu`` that matches this package, building it when needed.

Order: an explicit path (``fmu``, the command's ``--fmu``), then ``$PENDULUM_FMU``, then the FMU installed inside
the package (a wheel built by ``setup.py`` carries one), then, in a source checkout, the
CMake build in ``build/``, rebuilt incrementally when a source is newer than it. Asked for
FMI 3.0 (``fmi_version=3``), the same order with the FMI 3.0 FMU: ``$PENDULUM_FMU`` when it
is one, the package's ``fmi3/Pendulum.fmu``, the checkout's ``build/fmi3/Pendulum.fmu``.
An explicit path or ``$PENDULUM_FMU`` must be this project's Pendulum FMU
(:func:`pendulum_fmu.fmu.identity.pendulum_problem`).
"""

from __future__ import annotations

import logging
import os
import shutil
import zipfile
from functools import lru_cache
from pathlib import Path
from xml.etree import ElementTree

from pendulum_fmu.errors import BuildError, UsageError
from pendulum_fmu.fmu.build import DEFAULT_BUILD_DIR, PACKAGED_FMU, PACKAGED_FMU3, REPO_ROOT, build_fmu, fmu3_in, fmu_in
from pendulum_fmu.fmu.identity import file_key, fmi_version_of, pendulum_problem

_log = logging.getLogger(__name__)
"""Says that a build starts (INFO): ``pendulum-fmu`` shows it on stderr, a program sees it if it logs."""

SOURCES: tuple[str, ...] = ("fmu_src", "modelDescription.xml", "CMakeLists.txt", "cmake")
"""What the FMUs (FMI 2.0 and 3.0) are built from, relative to the repository root: the C code, each
model's folder (``fmu_src/models/``), the C libraries and the reference writer (``fmu_src/libs/``)."""


def newest_source_time(root: Path = REPO_ROOT) -> float:
    """Latest modification time (epoch s) of any file the FMU is built from."""
    newest = 0.0
    for name in SOURCES:
        path = root / name
        files = path.rglob("*") if path.is_dir() else [path]
        newest = max([newest] + [f.stat().st_mtime for f in files if f.is_file()])
    return newest


def is_source_checkout(root: Path = REPO_ROOT) -> bool:
    """True when the package runs from the repository (an editable install)."""
    return (root / "CMakeLists.txt").is_file() and (root / "modelDescription.xml").is_file()


def fmu_problem(path: Path) -> str | None:
    """What makes ``path`` unusable as an FMU (not a zip, no modelDescription.xml), or None.

    Parameters
    ----------
    path : Path
        An existing file.

    Returns
    -------
    str or None
        One line naming the file and the problem; None when it looks like an FMU.
    """
    if path.is_dir():
        return f"{str(path)!r} is a folder, not an FMU file"
    try:
        with zipfile.ZipFile(path) as archive:
            names = set(archive.namelist())
            if "modelDescription.xml" not in names:
                return f"{str(path)!r} is not an FMU: the archive has no modelDescription.xml"
            text = archive.read("modelDescription.xml")
    except (zipfile.BadZipFile, OSError, RuntimeError, ValueError) as error:  # RuntimeError: encrypted
        return f"{str(path)!r} is not an FMU (not a zip archive: {error})"
    try:
        root = ElementTree.fromstring(text)
    except ElementTree.ParseError as error:
        return f"{str(path)!r} is not an FMU: its modelDescription.xml is not well-formed XML ({error})"
    if root.tag != "fmiModelDescription":
        return f"{str(path)!r} is not an FMU: the root of its modelDescription.xml is <{root.tag}>, " \
               "not <fmiModelDescription>"
    return None


def runnable_problem(path: Path) -> str | None:
    """Why the package cannot run ``path``: not an FMU file (:func:`fmu_problem`), or not this
    project's Pendulum (:func:`~pendulum_fmu.fmu.identity.pendulum_problem`); None if it can.

    Checked once per version of the file: the command line's ``--fmu`` and :func:`locate_fmu`
    ask again for free.
    """
    try:
        key = file_key(path)
    except OSError:
        return fmu_problem(path) or pendulum_problem(path)
    return _runnable_problem(*key)


@lru_cache(maxsize=16)
def _runnable_problem(path: str, mtime_ns: int, size: int) -> str | None:
    """The check behind :func:`runnable_problem`; the time and size make a changed file a new key."""
    return fmu_problem(Path(path)) or pendulum_problem(Path(path))


def locate_fmu(explicit: Path | None = None, build: bool = True, fmi_version: int | None = None) -> Path:
    """Return the FMU to run.

    Parameters
    ----------
    explicit : Path, optional
        A path the user gave (the command's ``--fmu``); it must exist.
    build : bool
        In a source checkout, (re)build ``build/Pendulum.fmu`` when it is missing or older
        than its sources.
    fmi_version : {None, 2, 3}
        The FMI version wanted; None: the explicit or ``$PENDULUM_FMU`` file's, else 2.

    Returns
    -------
    Path
        An existing ``Pendulum.fmu``.

    Raises
    ------
    UsageError
        If the given path or ``$PENDULUM_FMU`` does not exist or is not the Pendulum FMU (or
        not of the FMI version asked), or no FMU can be found.
    BuildError
        If CMake fails.

    Notes
    -----
    Before a CMake build it logs one INFO line (logger ``pendulum_fmu.fmu.locate``) saying
    so; the command line prints it on stderr.
    """
    if explicit is not None:
        if not Path(explicit).exists():
            raise UsageError("fmu", f"no such file: {str(explicit)!r}")
        problem = runnable_problem(Path(explicit))
        if problem is not None:
            raise UsageError("fmu", problem)
        _check_version(Path(explicit), fmi_version)
        return Path(explicit)
    override = os.environ.get("PENDULUM_FMU")
    if override:
        if not Path(override).is_file():
            raise UsageError("$PENDULUM_FMU", f"no such file: {override!r}: build the FMU "
                             "(cmake -S . -B build && cmake --build build) or unset PENDULUM_FMU")
        problem = runnable_problem(Path(override))
        if problem is not None:
            raise UsageError("$PENDULUM_FMU", problem)
        if fmi_version is None or fmi_version_of(Path(override)) == fmi_version:
            return Path(override)
    fmi3 = fmi_version == 3
    packaged = PACKAGED_FMU3 if fmi3 else PACKAGED_FMU
    if packaged.is_file():
        return packaged
    if not is_source_checkout():
        raise UsageError("fmu", f"no {'FMI 3.0 ' if fmi3 else ''}Pendulum.fmu installed with the package and no "
                                "source checkout to build one from: pass `fmu` PATH or set PENDULUM_FMU")
    fmu = (fmu3_in if fmi3 else fmu_in)(DEFAULT_BUILD_DIR)
    if fmu.is_file() and (not build or fmu.stat().st_mtime >= newest_source_time()):
        return fmu
    if not build:
        raise UsageError("fmu", f"{fmu} is missing: build it (cmake -S . -B build && cmake --build build), "
                                "pass `fmu` PATH or set PENDULUM_FMU")
    if shutil.which("cmake") is None:
        raise UsageError("fmu", f"{fmu} is missing or out of date and cmake is not on PATH to build it: "
                                "install cmake, pass `fmu` PATH or set PENDULUM_FMU")
    # a build takes from seconds to minutes: say so before it starts (the command line shows it on stderr)
    _log.info("pendulum-fmu: %s is %s: building it with CMake (a minute or more) ...",
              fmu.relative_to(REPO_ROOT) if fmu.is_relative_to(REPO_ROOT) else fmu,
              "out of date" if fmu.is_file() else "missing")
    try:
        build_fmu(DEFAULT_BUILD_DIR)
    except RuntimeError as error:
        tail = "\n".join(str(error).strip().splitlines()[-15:])
        raise BuildError(f"building {fmu} with CMake failed:\n{tail}") from error
    if not fmu.is_file():
        raise BuildError(f"CMake built no {fmu} (the FMI 3.0 FMU needs fmpy's FMI 3.0 headers; see CMake's output)")
    return fmu


def _check_version(path: Path, wanted: int | None) -> None:
    """UsageError when the FMU at ``path`` is not of the FMI version ``wanted`` (None: any)."""
    if wanted is None:
        return
    actual = fmi_version_of(path)
    if actual != wanted:
        raise UsageError("fmu", f"{str(path)!r} is an FMI {actual}.0 FMU, but `fmi_version` {wanted} was given: "
                                "drop one of the two")
