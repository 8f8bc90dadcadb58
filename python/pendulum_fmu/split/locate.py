"""Find the split pendulum's files: ``PendulumBody.fmu``, ``PendulumGravity.fmu``, ``PendulumSplit.ssp``.

Order: ``$PENDULUM_SPLIT_DIR`` (a folder holding the FMI 2.0 files, with the FMI 3.0 ones in its
``fmi3/``), then the package's own folder (a wheel carries them beside ``Pendulum.fmu``), then the
checkout's CMake build ``build/``.
"""

from __future__ import annotations

import os
from pathlib import Path

from pendulum_fmu.errors import UsageError
from pendulum_fmu.fmu.build import DEFAULT_BUILD_DIR, PACKAGED_FMU

FILES: tuple[str, ...] = ("PendulumBody.fmu", "PendulumGravity.fmu", "PendulumSplit.ssp")
"""What a folder of the split pendulum holds, for one FMI version."""


def _version_folder(folder: Path, fmi_version: int) -> Path:
    return folder / "fmi3" if fmi_version == 3 else folder


def _holds(folder: Path, fmi_version: int) -> bool:
    return all((_version_folder(folder, fmi_version) / name).is_file() for name in FILES)


def candidate_folders() -> list[Path]:
    """The folders searched, in order (see the module's docstring)."""
    override = os.environ.get("PENDULUM_SPLIT_DIR")
    folders = [Path(override)] if override else []
    return folders + [PACKAGED_FMU.parent, DEFAULT_BUILD_DIR]


def split_folder(fmi_version: int = 2) -> Path:
    """The folder holding the split pendulum's files of ``fmi_version``.

    Parameters
    ----------
    fmi_version : {2, 3}
        The FMI version of the FMUs.

    Returns
    -------
    Path
        A folder with ``PendulumBody.fmu``, ``PendulumGravity.fmu`` and ``PendulumSplit.ssp``.

    Raises
    ------
    UsageError
        If the version is not 2 or 3, ``$PENDULUM_SPLIT_DIR`` lacks the files, or none is found.
    """
    if fmi_version not in (2, 3):
        raise UsageError("fmi_version", f"{fmi_version!r}: the split pendulum is built for FMI 2 and 3")
    override = os.environ.get("PENDULUM_SPLIT_DIR")
    if override and not _holds(Path(override), fmi_version):
        raise UsageError("$PENDULUM_SPLIT_DIR", f"{override!r} does not hold "
                         f"{', '.join(str(_version_folder(Path(override), fmi_version) / n) for n in FILES)}")
    for folder in candidate_folders():
        if _holds(folder, fmi_version):
            return _version_folder(folder, fmi_version)
    raise UsageError("system", "no PendulumSplit.ssp found: build it (cmake -S . -B build && cmake --build build) "
                                "or set PENDULUM_SPLIT_DIR")


def split_path(fmi_version: int = 2) -> Path:
    """The SSP package ``PendulumSplit.ssp`` of the split pendulum (FMI 2.0 FMUs, or 3.0 ones).

    Parameters
    ----------
    fmi_version : {2, 3}
        The FMI version of the FMUs inside.

    Returns
    -------
    Path
        An existing ``PendulumSplit.ssp``.
    """
    return split_folder(fmi_version) / "PendulumSplit.ssp"


def split_fmus(fmi_version: int = 2) -> tuple[Path, Path]:
    """``PendulumBody.fmu`` and ``PendulumGravity.fmu`` of ``fmi_version``."""
    folder = split_folder(fmi_version)
    return folder / "PendulumBody.fmu", folder / "PendulumGravity.fmu"
