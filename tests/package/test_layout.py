"""The code's layout: no import circles and no prefix-named file groups.

A circle (module A needs B and B needs A) means neither can be read, tested or replaced
alone; a group of files sharing a ``word_`` prefix in one folder is a folder written as
names. Checked here for the Python package ``python/pendulum_fmu`` (imports, including those
inside functions) and for the C sources ``fmu_src/`` (``#include`` lines, and which
compilation unit calls which: the symbols each object file of the build leaves undefined
against those another defines, read with ``nm``). Each checker is first run on a small
example with a circle, so that a checker which finds nothing cannot pass unnoticed. The
tests themselves keep one folder per thing tested and their shared modules in ``tests/helpers/``
(:func:`misplaced_test_files`, checked on an example too).
"""

from __future__ import annotations

import ast
import re
import shutil
import subprocess
from collections import defaultdict
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
PACKAGE = REPO / "python" / "pendulum_fmu"
FMU_SRC = REPO / "fmu_src"
BUILD = REPO / "build"


# --- generic helpers -----------------------------------------------------------------------
def circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of ``graph`` with more than one node or a self-loop."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    counter = 0

    def visit(node: str) -> None:
        nonlocal counter
        index[node] = low[node] = counter
        counter += 1
        stack.append(node)
        on_stack.add(node)
        for successor in sorted(graph.get(node, ())):
            if successor not in index:
                visit(successor)
                low[node] = min(low[node], low[successor])
            elif successor in on_stack:
                low[node] = min(low[node], index[successor])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on_stack.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1 or node in graph.get(node, ()):
                found.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    return found


def prefix_groups(root: Path, suffixes: tuple[str, ...]) -> list[str]:
    """Folders under ``root`` holding two or more files whose names share a ``word_`` prefix.

    ``a_x.c`` and ``a_y.c`` form the group ``a_``; so do ``a_x.c`` and ``a_x.h`` only with a
    second stem (one stem in two suffixes is one module). Files starting with ``_`` (such as
    ``__init__.py``) are not prefix-named.
    """
    groups: dict[tuple[Path, str], set[str]] = defaultdict(set)
    for path in root.rglob("*"):
        if path.suffix not in suffixes or path.name.startswith("_") or "_" not in path.stem:
            continue
        groups[(path.parent, path.stem.split("_", 1)[0])].add(path.stem)
    return sorted(f"{folder.relative_to(root) if folder != root else '.'}/{prefix}_*: {', '.join(sorted(stems))}"
                  for (folder, prefix), stems in groups.items() if len(stems) > 1)


# --- Python ----------------------------------------------------------------------------------
def python_modules(root: Path) -> dict[str, Path]:
    """Dotted module name -> file, for every ``.py`` under ``root`` (a package folder)."""
    modules = {}
    for path in root.rglob("*.py"):
        parts = path.relative_to(root.parent).with_suffix("").parts
        if parts[-1] == "__init__":
            parts = parts[:-1]
        modules[".".join(parts)] = path
    return modules


def python_import_graph(root: Path) -> dict[str, set[str]]:
    """Module -> the package's modules it imports, anywhere in its body (functions included).

    ``from a.b import c`` counts as an import of ``a.b.c`` when that is a module, else of
    ``a.b``; the implicit import of a module's parent packages is not counted.
    """
    modules = python_modules(root)
    graph: dict[str, set[str]] = {name: set() for name in modules}

    def known(name: str) -> str | None:
        while name and name not in modules:
            name = name.rpartition(".")[0]
        return name or None

    for name, path in modules.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            targets: list[str] = []
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    anchor = package.split(".")
                    anchor = anchor[:len(anchor) - node.level + 1]
                    base = ".".join([*anchor, base] if base else anchor)
                targets = [f"{base}.{alias.name}" if f"{base}.{alias.name}" in modules else base
                           for alias in node.names]
            for target in targets:
                resolved = known(target)
                if resolved is not None and resolved != name:
                    graph[name].add(resolved)
    return graph


def test_python_checker_finds_a_circle(tmp_path: Path) -> None:
    """The checker sees a circle through a function-level import, and a prefix group."""
    package = tmp_path / "pkg"
    (package / "sub").mkdir(parents=True)
    (package / "__init__.py").write_text("")
    (package / "sub" / "__init__.py").write_text("")
    (package / "sub" / "main.py").write_text("from pkg.sub import study\n")
    (package / "sub" / "study.py").write_text("def main():\n    from .main import x\n")
    (package / "sub" / "bench_a.py").write_text("")
    (package / "sub" / "bench_b.py").write_text("")
    assert circles(python_import_graph(package)) == [["pkg.sub.main", "pkg.sub.study"]]
    assert prefix_groups(package, (".py",)) == ["sub/bench_*: bench_a, bench_b"]


def test_python_package_has_no_import_circle() -> None:
    graph = python_import_graph(PACKAGE)
    assert len(graph) > 40, "the package was not found"
    assert circles(graph) == []


def test_python_package_has_no_prefix_named_file_group() -> None:
    assert prefix_groups(PACKAGE, (".py",)) == []


# --- C ---------------------------------------------------------------------------------------
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def include_graph(root: Path) -> dict[str, set[str]]:
    """Header or source (path relative to ``root``) -> the files of ``root`` it ``#include``s.

    A quoted name is looked up beside the including file, then from ``root`` (the include
    directory the build and the source FMUs use), then by its file name alone.
    """
    files = {path.relative_to(root).as_posix(): path for path in root.rglob("*") if path.suffix in (".c", ".h")}
    by_name = defaultdict(list)
    for relative in files:
        by_name[relative.rsplit("/", 1)[-1]].append(relative)
    graph: dict[str, set[str]] = {relative: set() for relative in files}
    for relative, path in files.items():
        for included in INCLUDE.findall(path.read_text(encoding="utf-8", errors="replace")):
            beside = (path.parent / included).resolve()
            candidates = [beside.relative_to(root).as_posix()] if beside.is_relative_to(root) else []
            candidates += [included, *by_name.get(included.rsplit("/", 1)[-1], [])]
            target = next((c for c in candidates if c in files), None)
            if target is not None and target != relative:
                graph[relative].add(target)
    return graph


def symbol_graph(objects: dict[str, Path]) -> dict[str, set[str]]:
    """Compilation unit -> the units whose external symbols it uses (``nm`` of the objects)."""
    defined: dict[str, str] = {}
    undefined: dict[str, set[str]] = {}
    for unit, obj in objects.items():
        listing = subprocess.run(["nm", "-P", str(obj)], capture_output=True, text=True, check=True).stdout
        undefined[unit] = set()
        for line in listing.splitlines():
            fields = line.split()
            if len(fields) < 2:
                continue
            symbol, kind = fields[0], fields[1]
            if kind == "U":
                undefined[unit].add(symbol)
            elif kind in "TDBRCV":
                defined[symbol] = unit
    return {unit: {defined[s] for s in needs if s in defined and defined[s] != unit}
            for unit, needs in undefined.items()}


def build_objects() -> dict[str, Path]:
    """``fmu_src`` source (relative path) -> its up-to-date object file in the CMake build.

    Every target's objects are looked at (the FMI 2.0 and 3.0 libraries between them compile
    every source); an object older than its source, or whose source is gone, is left out.
    """
    objects: dict[str, Path] = {}
    for obj in sorted(BUILD.glob("CMakeFiles/*.dir/**/*.c.o")):
        dotdir = next(p for p in obj.parents if p.name.endswith(".dir"))
        source = REPO / obj.relative_to(dotdir).as_posix()[:-len(".o")]
        if not source.is_relative_to(FMU_SRC) or not source.exists():
            continue
        if obj.stat().st_mtime < source.stat().st_mtime:
            continue
        objects.setdefault(source.relative_to(FMU_SRC).as_posix(), obj)
    return objects


def test_c_checkers_find_circles(tmp_path: Path) -> None:
    """Two units that call each other, and two headers that include each other, are found."""
    compiler = shutil.which("cc") or shutil.which("gcc")
    assert compiler is not None and shutil.which("nm") is not None, "cc and nm are needed"
    (tmp_path / "a.h").write_text('#include "b.h"\nint a(int);\n')
    (tmp_path / "b.h").write_text('#include "a.h"\nint b(int);\n')
    (tmp_path / "a.c").write_text('int b(int);\nint a(int x) { return x ? b(x - 1) : 0; }\n')
    (tmp_path / "b.c").write_text('int a(int);\nint b(int x) { return a(x); }\n')
    (tmp_path / "c.c").write_text('int a(int);\nint c(void) { return a(3); }\n')
    objects = {}
    for unit in ("a.c", "b.c", "c.c"):
        subprocess.run([compiler, "-c", unit, "-o", f"{unit}.o"], cwd=tmp_path, check=True)
        objects[unit] = tmp_path / f"{unit}.o"
    assert circles(symbol_graph(objects)) == [["a.c", "b.c"]]
    assert circles(include_graph(tmp_path)) == [["a.h", "b.h"]]


def test_fmu_src_includes_have_no_circle() -> None:
    graph = include_graph(FMU_SRC)
    assert len(graph) > 20, "fmu_src was not found"
    assert circles(graph) == []


def test_fmu_src_units_have_no_call_circle() -> None:
    """No two compilation units of ``fmu_src`` need each other's functions.

    Reads the objects of the CMake build in ``build/`` (``bash scripts/build-fmu.sh``).
    """
    objects = build_objects()
    sources = {p.relative_to(FMU_SRC).as_posix() for p in FMU_SRC.rglob("*.c")}
    missing = sources - objects.keys()
    assert not missing, f"no up-to-date object in build/ for {sorted(missing)}: run bash scripts/build-fmu.sh"
    assert circles(symbol_graph(objects)) == []


def test_fmu_src_has_no_prefix_named_file_group() -> None:
    assert prefix_groups(FMU_SRC, (".c", ".h")) == []


@pytest.mark.parametrize("layer", ["fmi2", "fmi3"])
def test_fmu_src_file_names_are_unique_within_an_fmu(layer: str) -> None:
    """A source FMU's sources/ is flat and every room is an include directory: no two files
    one FMU compiles (the shared rooms and its own FMI layer) may share a name."""
    other = "fmi3" if layer == "fmi2" else "fmi2"
    names = [p.name for p in FMU_SRC.glob("*/*") if p.suffix in (".c", ".h") and p.parent.name != other]
    assert len(names) > 20, "fmu_src was not found"
    assert sorted(n for n in set(names) if names.count(n) > 1) == []


# --- tests ---------------------------------------------------------------------------------------
TESTS = REPO / "tests"


def misplaced_test_files(root: Path) -> list[str]:
    """The Python files of ``root`` (a ``tests/`` folder) out of its layout: a file at the top
    other than ``conftest.py``, a test module in ``helpers/`` or ``lab/`` (the team's scripts,
    which pytest does not collect) or a helper outside ``helpers/``, a test module deeper than
    one folder, and test modules of one name in two folders (pytest imports each by its name:
    the second would not be collected)."""
    found = []
    seen: dict[str, str] = {}
    for path in sorted(root.rglob("*.py")):
        where = path.relative_to(root)
        folder = where.parts[0] if len(where.parts) > 1 else ""
        is_test = path.name.startswith("test_")
        if where.parts[0] == "c":
            continue
        if not folder and path.name != "conftest.py":
            found.append(f"{where}: at the top of tests/ (a test goes in a folder by what it tests)")
        elif folder in ("helpers", "lab") and is_test:
            found.append(f"{where}: a test module among the {'helpers' if folder == 'helpers' else 'lab scripts'}")
        elif folder and folder not in ("helpers", "lab") and not is_test:
            found.append(f"{where}: a shared module outside tests/helpers/")
        elif len(where.parts) > 2:
            found.append(f"{where}: more than one folder deep")
        if is_test and path.name in seen:
            found.append(f"{where}: the same name as {seen[path.name]}")
        seen.setdefault(path.name, str(where))
    return found


def test_tests_checker_finds_misplaced_files(tmp_path: Path) -> None:
    for name in ("conftest.py", "test_top.py", "helpers/cases.py", "helpers/test_in_helpers.py",
                 "fmu/test_a.py", "fmu/cases.py", "judge/test_a.py", "judge/deep/test_b.py", "c/x.py",
                 "lab/targets.py", "lab/test_in_lab.py"):
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text("")
    assert [line.split(":")[0] for line in misplaced_test_files(tmp_path)] == [
        "fmu/cases.py", "helpers/test_in_helpers.py", "judge/deep/test_b.py", "judge/test_a.py", "lab/test_in_lab.py",
        "test_top.py"]


def test_tests_are_in_folders_by_what_they_test() -> None:
    assert len(list(TESTS.glob("*/test_*.py"))) > 50, "tests/ was not found"
    assert misplaced_test_files(TESTS) == []
