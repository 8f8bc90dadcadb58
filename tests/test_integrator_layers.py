"""The integrator's files call each other in layers, never in a circle (issue 20): integrator.c
(init, dispatch) calls the four methods, the methods call integrator_core.c, and integrator_core.c
calls neither. Read from the symbols each file defines and uses, as the compiler leaves them
(each file compiled alone, ``nm``), so an inline or a macro cannot hide a call."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
FILES = ("integrator.c", "integrator_core.c", "dopri5.c", "rk4.c", "rkn.c", "symplectic.c")
METHODS = ("dopri5.c", "rk4.c", "rkn.c", "symplectic.c")


def _symbols(source: Path, out: Path) -> tuple[set[str], set[str]]:
    """(defined, undefined) global symbols of one compiled source file."""
    compiler = shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")
    assert compiler, "no C compiler on PATH (the FMU's build needs one too)"
    obj = out / (source.stem + ".o")
    subprocess.run([compiler, "-std=c11", "-O1", "-c", str(source), "-I", str(REPO / "fmu_src"), "-o", str(obj)],
                   check=True)
    listing = subprocess.run(["nm", str(obj)], check=True, capture_output=True, text=True).stdout
    defined, undefined = set(), set()
    for line in listing.splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[0] == "U":
            undefined.add(parts[1])
        elif len(parts) == 3 and parts[1] in "TDBR":
            defined.add(parts[2])
    return defined, undefined


def test_the_integrator_files_form_layers_without_a_cycle(tmp_path: Path) -> None:
    table = {name: _symbols(REPO / "fmu_src" / name, tmp_path) for name in FILES}
    calls = {name: {other for other in FILES if other != name and table[name][1] & table[other][0]}
             for name in FILES}
    assert calls["integrator_core.c"] == set(), calls
    for method in METHODS:
        assert calls[method] == {"integrator_core.c"}, (method, calls[method])
    assert calls["integrator.c"] == {"integrator_core.c", *METHODS}, calls["integrator.c"]
    # no cycle: a depth-first search finds no file on its own call path
    def reaches(start: str, goal: str, seen: frozenset[str] = frozenset()) -> bool:
        return any(nxt == goal or (nxt not in seen and reaches(nxt, goal, seen | {nxt})) for nxt in calls[start])
    assert not any(reaches(name, name) for name in FILES)
