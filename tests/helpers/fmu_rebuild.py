"""Rebuilding an FMU's binary from its sources/ with fmpy, as an importer that builds from source
does (FMI 2.0: the SourceFiles of modelDescription.xml; FMI 3.0: sources/buildDescription.xml)."""

from __future__ import annotations

import posixpath
import re
import shutil
import zipfile
from pathlib import Path

from fmpy.build import build_platform_binary


def rebuild_from_sources(fmu: Path, tmp_path: Path) -> Path:
    """Unzips ``fmu`` into ``tmp_path/unzipped`` without its binaries and builds them again.

    Parameters
    ----------
    fmu : Path
        The packed FMU.
    tmp_path : Path
        An empty scratch folder.

    Returns
    -------
    Path
        The unzipped FMU folder with the rebuilt binary (fmpy simulates it as it is).
    """
    unzipped = tmp_path / "unzipped"
    with zipfile.ZipFile(fmu) as archive:
        archive.extractall(unzipped)
    shutil.rmtree(unzipped / "binaries")
    (tmp_path / "cmake-build").mkdir()
    build_platform_binary(unzipped, build_dir=tmp_path / "cmake-build")
    return unzipped


INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def included_closure(archive: zipfile.ZipFile, sources: list[str]) -> set[str]:
    """The files of ``archive`` that compiling ``sources`` (names under ``sources/``) reads.

    A quoted include is looked up beside the including file, then in ``sources/`` (the
    include directory fmpy gives the compiler), as a C compiler does.
    """
    names = set(archive.namelist())
    todo = [f"sources/{name}" for name in sources]
    seen: set[str] = set()
    while todo:
        name = todo.pop()
        if name in seen or name not in names:
            continue
        seen.add(name)
        for included in INCLUDE.findall(archive.read(name).decode("utf-8", errors="replace")):
            beside = posixpath.normpath(posixpath.join(posixpath.dirname(name), included))
            todo.append(beside if beside in names else f"sources/{included}")
    return seen
