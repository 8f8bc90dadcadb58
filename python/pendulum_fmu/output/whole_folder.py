"""A folder of outputs written whole or not at all: into a hidden folder inside it, then moved up.

An interrupted command (Ctrl-C, an error) leaves the folder as it was before: the previous
outputs if there were any, nothing if there were none, never a mix of old and new files or a
half-written set. The hidden folder sits inside the output folder, so the moves are renames on
one file system and need no write permission on its parent.
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path


@contextmanager
def whole_folder(out: Path) -> Iterator[Path]:
    """Yield a temporary folder to write into; on success move its files into ``out``.

    Parameters
    ----------
    out : Path
        The output folder (created with its missing parents if absent).

    Yields
    ------
    Path
        An empty folder ``out/.partial-<pid>``: write every output there.

    Notes
    -----
    On an exception (``KeyboardInterrupt`` included) the temporary folder is deleted, and so
    are ``out`` and the parents this call created, when they are still empty.
    """
    created = [folder for folder in (out, *out.parents) if not folder.exists()]  # innermost first
    out.mkdir(parents=True, exist_ok=True)
    partial = out / f".partial-{os.getpid()}"
    shutil.rmtree(partial, ignore_errors=True)
    partial.mkdir()
    try:
        yield partial
        for item in sorted(partial.iterdir()):
            target = out / item.name
            if target.is_dir() and not item.is_dir():
                shutil.rmtree(target)
            item.replace(target)
    except BaseException:
        shutil.rmtree(partial, ignore_errors=True)
        for folder in created:
            if any(folder.iterdir()):
                break
            folder.rmdir()
        raise
    partial.rmdir()
