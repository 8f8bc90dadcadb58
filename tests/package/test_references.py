"""What the docs and the sources' comments name exists, and they cite no tracker by number.

Every repository path written in the docs, the front pages and the sources' comments and
docstrings (``fmu_src/math/exact.c``, ``docs/certificate.md``; braces such as
``fmu_src/math/exact.{h,c}`` and globs such as ``tests/fmu/test_*.py`` expanded) names a file or
folder of this checkout; so does every Markdown page named by its bare name (``certificate.md``).
No text points into one machine's own folders (an absolute path under /work or /home), and no
text says "issue 12" or "the issue's case": a reader has no tracker to look the number up in, so
the text states the requirement itself.
"""

from __future__ import annotations

import ast
import io
import re
import tokenize
from functools import cache
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]

SKIPPED_FOLDERS = {".git", ".venv", "out", "site", "__pycache__", ".mypy_cache", ".ruff_cache", ".pytest_cache",
                   ".hypothesis", "img"}
TEXT_SUFFIXES = {".md", ".py", ".c", ".h", ".sh", ".txt", ".cmake", ".yml", ".yaml", ".toml", ".in", ".cfg", ".xml",
                 ".css", ".ssd"}
# Generated folders and files: named by the text, made by a build or a run, not kept in the repository.
GENERATED = ("build", "out/", ".venv/", "site/")
BUILT_SUFFIXES = (".fmu", ".ssp", ".so", ".o")
# Pages named that are not this repository's: what a run writes, what another repository holds.
OTHER_PAGES = {"report.md": "pendulum-fmu study and bench solvers write it",
               "FMI-CROSS-CHECK-RULES.md": "the rules of the modelica/fmi-cross-check repository"}
# The top-level folders a path may start with: today's, and those a move may leave behind in a text.
TOP = sorted({p.name for p in REPO.iterdir() if p.is_dir() and p.name not in SKIPPED_FOLDERS
              and not p.name.startswith(("build", "."))}
             | {"fmu_src", "python", "tests", "docs", "scripts", "cmake", "exact_lib", "driver_lib", "reference",
                "fmi3", "split", ".ci"})
PATH = re.compile(r"(?<![\w./~$-])((?:" + "|".join(re.escape(t) for t in TOP) + r")/[\w./{},*-]*[\w}*])")
MARKDOWN_NAME = re.compile(r"(?<![\w./-])([\w-]+\.md)\b")
OUTSIDE = re.compile(r"(?<![\w.-])/(?:work|home)/[\w.-]+")
TRACKER = re.compile(r"\biss" r"ues?\s*#?\s*\d|\biss" r"ue's\b|\(iss" r"ue\b|\bthe (?:[\w-]+ )?iss" r"ue\b",
                     re.IGNORECASE)


def text_files() -> list[Path]:
    """The repository's text files: sources, scripts, build files and docs."""
    found = []
    for path in sorted(REPO.rglob("*")):
        parts = path.relative_to(REPO).parts
        if any(p in SKIPPED_FOLDERS or p.startswith("build") or p.endswith(".egg-info") for p in parts[:-1]):
            continue
        if path.is_file() and (path.suffix in TEXT_SUFFIXES or path.name in ("run", "MANIFEST.in")):
            found.append(path)
    return found


@cache
def prose(path: Path) -> str:
    """What a reader reads in ``path``: a page whole; of a source, its comments and docstrings
    (its code and strings name build outputs and temporary files, which need not exist)."""
    text = path.read_text(encoding="utf-8", errors="replace")
    if path.suffix in (".md", ".txt") and path.name != "CMakeLists.txt":
        return text
    if path.suffix == ".py":
        comments = [t.string for t in tokenize.generate_tokens(io.StringIO(text).readline)
                    if t.type == tokenize.COMMENT]
        nodes = [n for n in ast.walk(ast.parse(text))
                 if isinstance(n, ast.Module | ast.ClassDef | ast.FunctionDef | ast.AsyncFunctionDef)]
        docstrings = [d for d in (ast.get_docstring(n, clean=False) for n in nodes) if d]
        # a string alone on its line after an assignment documents it (the attribute docstrings)
        documented = [n.value.value for n in ast.walk(ast.parse(text)) if isinstance(n, ast.Expr)
                      and isinstance(n.value, ast.Constant) and isinstance(n.value.value, str)]
        return "\n".join(comments + docstrings + documented)
    if path.suffix in (".c", ".h"):
        return "\n".join(re.findall(r"/\*.*?\*/|//[^\n]*", text, re.DOTALL))
    return "\n".join(re.findall(r"(?:^|\s)#([^\n]*)", text))


def expand(written: str) -> list[str]:
    """``written`` with each ``{a,b}`` replaced by each of its choices (nested braces are not used)."""
    match = re.search(r"\{([^{}]*)\}", written)
    if match is None:
        return [written]
    return [x for choice in match.group(1).split(",")
            for x in expand(written[:match.start()] + choice + written[match.end():])]


def exists(written: str, where: Path = REPO) -> bool:
    """Whether ``written`` is there (a glob: whether it matches), read from the repository's
    root, from fmu_src/ (the C sources' root, as their comments write paths) or from the
    folder ``where`` of the text; a program (no suffix) exists when its C source does."""
    relative = written.rstrip(".")
    for root in (REPO, REPO / "fmu_src", where):
        if any(c in relative for c in "*?[") and any(root.glob(relative)):
            return True
        if (root / relative).exists() or (Path(relative).suffix == "" and (root / f"{relative}.c").exists()):
            return True
    return False


def named_paths(text: str) -> list[str]:
    """The repository paths ``text`` names, each brace choice apart."""
    return [choice for written in PATH.findall(text) if not written.startswith(GENERATED)
            for choice in expand(written) if not choice.endswith(BUILT_SUFFIXES)]


FILES = text_files()
MARKDOWN_PAGES = {p.name for p in FILES if p.suffix == ".md"}
SCANNED = [p for p in FILES if p != Path(__file__).resolve()]
"""Every text file but this one, whose examples must name what is not there."""


def test_the_scan_sees_the_sources_and_the_docs() -> None:
    names = {p.relative_to(REPO).as_posix() for p in FILES}
    assert {"README.md", "CONTRIBUTING.md", "docs/index.md", "fmu_src/math/exact.c", "scripts/test.sh",
            "python/pendulum_fmu/cli/main.py", "CMakeLists.txt"} <= names
    assert not any(n.startswith(("build/", ".venv/")) for n in names)


def test_the_finders_catch_what_they_must() -> None:
    """Each finder on the kinds of text it must catch, and on text it must let pass."""
    assert named_paths("see fmu_src/exact.{h,c}, tests/fmu/test_*.py and `docs/math.md`.") == [
        "fmu_src/exact.h", "fmu_src/exact.c", "tests/fmu/test_*.py", "docs/math.md"]
    assert named_paths("build/Pendulum.fmu, python/pendulum_fmu/__init__.py") == ["python/pendulum_fmu/__init__.py"]
    assert not exists("fmu_src/exact.h") and exists("fmu_src/math/exact.h") and exists("tests/fmu/test_*.py")
    assert exists("fmi3/common.c") and exists("tests/c/test_fmi_api") and not exists("tests/c/test_nothing")
    assert not exists("tests/test_nothing_*.py")
    assert MARKDOWN_NAME.findall("the bound (BOUND.md), docs/math.md") == ["BOUND.md"]
    assert OUTSIDE.findall("(/work/shared/reference/engines.md), /tmp/x, python/work/x") == ["/work/shared"]
    said = "as the issue asks; issue 26, item 5; Issue #3; (issue 11); the solver issue; the issue's case"
    assert len(TRACKER.findall(said)) == 6
    assert TRACKER.findall("no tracker: issues a warning, an issued call") == []


def test_every_named_repository_path_exists() -> None:
    missing = [f"{p.relative_to(REPO)}: {name}" for p in SCANNED
               for name in named_paths(prose(p)) if not exists(name, p.parent)]
    assert missing == [], "paths named but not in the repository:\n" + "\n".join(missing)


def test_every_named_markdown_page_exists() -> None:
    missing = [f"{p.relative_to(REPO)}: {name}" for p in SCANNED
               for name in MARKDOWN_NAME.findall(prose(p))
               if name not in MARKDOWN_PAGES and name not in OTHER_PAGES]
    assert missing == [], "Markdown pages named but not in the repository:\n" + "\n".join(missing)


def test_no_path_points_outside_the_repository() -> None:
    found = [f"{p.relative_to(REPO)}: {m}" for p in SCANNED
             for m in OUTSIDE.findall(prose(p))]
    assert found == [], "absolute paths of one machine:\n" + "\n".join(found)


def test_no_text_cites_a_tracker_by_number() -> None:
    """State the requirement itself: there is no tracker to look "issue 12" up in."""
    found = [f"{p.relative_to(REPO)}:{k}: {line.strip()}" for p in SCANNED
             for k, line in enumerate(p.read_text(encoding="utf-8", errors="replace").splitlines(), 1)
             if TRACKER.search(line)]
    assert found == [], "\n".join(found)
