"""Files written whole or not at all: through a temporary sibling, then a rename."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path


def write_whole(path: Path, write: Callable[[Path], object]) -> Path:
    """Call ``write`` on ``path``'s temporary sibling ``<name>.tmp``, then rename it to ``path``.

    An error or Ctrl-C during the write deletes the temporary file: nothing half-written is
    left, under either name.

    Parameters
    ----------
    path : Path
        The file to write (replaced if it exists); its folder must exist.
    write : callable
        Writes the whole file to the path it is given.

    Returns
    -------
    Path
        ``path``.
    """
    temporary = path.with_name(path.name + ".tmp")
    try:
        write(temporary)
        temporary.replace(path)
    finally:
        temporary.unlink(missing_ok=True)
    return path
