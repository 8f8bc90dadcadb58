"""The suite's Pendulum cases in the FMI cross-check repository's layout, one model folder a case.

``fmus/<FMI version>/<cs|me>/<platform>/PendulumFMU/<version>/<case>/`` holding ``<case>.fmu``
(Pendulum.fmu as built), ``<case>_ref.opt`` (the case's start and stop time, output interval
and tolerance), ``<case>_ref.csv`` (the case's exact solution, the FMU's own
``extra/org.fmi-standard.fmi-ls-ref/suite/<case>_ref.csv``) and ``ReadMe.txt`` (what the case
catches and the start values to set, which the cross-check's files have no place for).
"""

from __future__ import annotations

import shutil
import zipfile
from pathlib import Path

from pendulum_fmu import __version__
from pendulum_fmu.fmu.cross_check import LS_REF, TOOL_NAME, describe, platforms
from pendulum_fmu.suite.cases import Case

README = """{case} ({suite}, {tool} {version}, FMI {fmi}, {interface})

What this case catches: {catches}.

Pendulum.fmu (theta'' + (g/L) sin(theta) = 0) run from {start:g} s to {stop:g} s with an output
every {interval:g} s at relative tolerance {tolerance:g} ({case}_ref.opt), after setting these
start values before initialization (the cross-check has no file for them):

{start_values}

{case}_ref.csv is the exact solution at times of that output grid. Judge a result with
'pendulum-fmu judge RESULT.csv --start {start_words} --cross-check-verdict DIR', or run the
whole suite with 'pendulum-fmu suite run --command TEMPLATE --out DIR'.
"""


def _opt(case: Case) -> str:
    return (f"StartTime, {case.start!r}\nStopTime, {case.stop!r}\nStepSize, {case.interval!r}\n"
            f"RelTol, {case.tolerance!r}\nOutputIntervalLength, {case.interval!r}\n")


def export_case(case: Case, fmu: Path, root: Path, suite: str) -> list[Path]:
    """Write the case's model folder for each platform ``fmu`` carries; return the folders.

    Raises
    ------
    ValueError
        The FMU is not of the case's FMI version, or does not carry the case's reference result.
    """
    described = describe(fmu)
    if described.fmi_version != case.fmi:
        raise ValueError(f"{fmu}: FMI {described.fmi_version}, but {case.name} is an FMI {case.fmi} case")
    member = f"{LS_REF}suite/{case.name}_ref.csv"
    try:
        with zipfile.ZipFile(fmu) as archive:
            reference = archive.read(member)
    except KeyError:
        raise ValueError(f"{fmu}: no {member} (built without the suite, or from another suite version?)") from None
    carried, _ = platforms(fmu, described)
    folders = []
    for platform in carried:
        folder = root / "fmus" / case.fmi / case.interface / platform / TOOL_NAME / __version__ / case.name
        folder.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(fmu, folder / f"{case.name}.fmu")
        (folder / f"{case.name}_ref.csv").write_bytes(reference)
        (folder / f"{case.name}_ref.opt").write_text(_opt(case))
        (folder / "ReadMe.txt").write_text(README.format(
            case=case.name, suite=suite, tool=TOOL_NAME, version=__version__, fmi=case.fmi,
            interface="Model Exchange" if case.interface == "me" else "Co-Simulation", catches=case.catches,
            start=case.start, stop=case.stop, interval=case.interval, tolerance=case.tolerance,
            start_values="\n".join(f"  {name} = {value!r}" for name, value in case.start_values.items()),
            start_words=" ".join(f"{name}={value!r}" for name, value in case.start_values.items())))
        folders.append(folder)
    return folders
