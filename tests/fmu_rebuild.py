"""Rebuilding an FMU's binary from its sources/ with fmpy, as an importer that builds from source
does (FMI 2.0: the SourceFiles of modelDescription.xml; FMI 3.0: sources/buildDescription.xml)."""

from __future__ import annotations

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
