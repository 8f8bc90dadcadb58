"""Output destinations checked before any work starts.

A command that would run for a minute and then fail to write its result wastes the minute:
each check here proves that the destination can be written (by creating and deleting a
probe file in its folder) and raises :class:`OutputError` with one line naming the path.
Missing parent folders are an error, never created in silence.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path


class OutputError(ValueError):
    """An output destination that cannot be written; the message names it."""


def _probe(folder: Path) -> None:
    """Create and delete a file in ``folder``; OutputError if that fails."""
    try:
        handle, name = tempfile.mkstemp(prefix=".pendulum-fmu-probe-", dir=folder)
    except OSError as error:
        raise OutputError(f"cannot write in the folder {str(folder)!r}: {error.strerror}") from None
    os.close(handle)
    os.unlink(name)


def _existing_folder(folder: Path, what: str) -> None:
    """``folder`` must exist and be a folder."""
    if not folder.exists():
        raise OutputError(f"the folder {str(folder)!r} of {what} does not exist: create it first")
    if not folder.is_dir():
        raise OutputError(f"{str(folder)!r} (in {what}) is a file, not a folder")


def check_output_file(path: Path) -> Path:
    """Check that ``path`` can be written as a file: its folder exists and is writable.

    Parameters
    ----------
    path : Path
        The file to be written (it may exist; it is replaced).

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    OutputError
        If ``path`` is a folder, its parent is missing or a file, or the parent is not writable.
    """
    if path.is_dir():
        raise OutputError(f"{str(path)!r} is a folder, not a file")
    parent = path.parent
    _existing_folder(parent, repr(str(path)))
    _probe(parent)
    return path


def check_output_folder(path: Path) -> Path:
    """Check that ``path`` is, or can be made, a writable folder.

    A folder that does not exist yet is created later, with its missing parents, by
    :func:`make_output_folder` (``out/study`` works in an empty folder); the nearest existing
    ancestor must be a writable folder.

    Parameters
    ----------
    path : Path
        The output folder.

    Returns
    -------
    Path
        ``path``.

    Raises
    ------
    OutputError
        If ``path`` or one of its ancestors is a file, or nothing can be written there.
    """
    if path.exists():
        if not path.is_dir():
            raise OutputError(f"{str(path)!r} is a file: give a folder")
        _probe(path)
        return path
    ancestor = path.absolute().parent
    while not ancestor.exists():
        ancestor = ancestor.parent
    if not ancestor.is_dir():
        raise OutputError(f"{str(ancestor)!r} (in {str(path)!r}) is a file, not a folder")
    _probe(ancestor)
    return path


def make_output_folder(path: Path) -> Path:
    """Create the checked folder ``path`` and its missing parents; return it."""
    path.mkdir(parents=True, exist_ok=True)
    return path
