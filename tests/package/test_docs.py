"""The documentation: it builds in strict mode, its counts are the programs' own, the README is short.

``mkdocs build --strict`` fails on a broken link or anchor, a page missing from the nav or a
nav entry without its page, and an API object (``::: pendulum_fmu...``) that no longer exists;
the command line reference is generated from the parsers during the build
(``docs/hooks/cli_reference.py``). The figures the pages quote that do not depend on the
machine (counts of checks, of forged states) are compared here with the output of the
program named beside them, so a change that moves them fails until the page says so.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
DOCS = REPO / "docs"
TESTS_C = REPO / "build" / "tests" / "c"


def words(text: str) -> str:
    """``text`` with every run of white space (line breaks of the Markdown) made one space."""
    return " ".join(text.split())


@pytest.mark.slow
def test_docs_build_strict(tmp_path: Path) -> None:
    """The site builds with no warning, and the generated references are filled in."""
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1")
    built = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--quiet", "-d", str(tmp_path)],
                           cwd=REPO, env=env, capture_output=True, text=True, timeout=300, check=False)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    cli = (tmp_path / "cli.html").read_text(encoding="utf-8")
    for text in ("pendulum-fmu simulate", "--amplitude", "pendulum-fmu bench solvers", "--problems",
                 "pendulum-fmu sweep", "--scheduler"):
        assert text in cli, f"the CLI reference lacks {text!r}"
    assert "cli-reference --" not in cli, "the hook did not fill in the reference"
    api = (tmp_path / "api.html").read_text(encoding="utf-8")
    for name in ("FmuRunner", "TimeGrid", "ExactPort", "run_sweep", "SweepGrid"):
        assert name in api, f"the API reference lacks {name}"


def run_program(name: str) -> str:
    """The standard output of the C test program ``build/tests/c/NAME`` (built by test.sh)."""
    program = TESTS_C / name
    assert program.exists(), f"{program} is missing: bash scripts/build-fmu.sh builds it"
    done = subprocess.run([str(program)], capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 0, done.stdout[-2000:] + done.stderr[-2000:]
    return done.stdout


# (program, what it prints, page, what the page says): each {n} of the page's text is the
# number the program printed in the same place (a count written with thousands separators).
FIGURES = [
    ("test_fmi_edges",
     r"Co-Simulation: (\d+) forged blobs refused, (\d+) accepted.*\nModel Exchange: (\d+) forged blobs refused, "
     r"(\d+) accepted",
     "conformance.md",
     "Co-Simulation {0} refused, {1} accepted (padding, unused stages, counts), Model Exchange {2} refused, "
     "{3} accepted"),
    ("test_fmi_api", r"test_fmi_api: (\d+) checks, 0 failed", "conformance.md",
     "`tests/c/test_fmi_api.c` ({0} checks)"),
    ("test_fmi_api", r"test_fmi_api: (\d+) checks, 0 failed", "platforms.md",
     "`tests/c/test_fmi_api.c` ({0} checks)"),
    ("test_fmi3_api", r"test_fmi3_api: (\d+) checks passed", "conformance.md",
     "`tests/c/fmi3/test_fmi3_api.c` ({0} checks)"),
    ("test_integrators", r"test_integrators: (\d+) checks passed", "solvers.md",
     "`tests/c/test_integrators.c`, {0} checks"),
    ("test_solver_tolerance",
     r"dopri5: worst .* = ([\d.]+)\nrk4: worst .* = ([\d.]+)\nrkn: worst .* = ([\d.]+)\n"
     r"symplectic: worst .* = ([\d.]+)\n",
     "solvers.md", "prints the worst error in units of tol: dopri5 {0}, rk4 {1}, rkn {2}, symplectic {3}"),
]


@pytest.mark.parametrize(("program", "printed", "page", "said"), FIGURES,
                         ids=[f"{f[0]}-{f[2]}" for f in FIGURES])
def test_quoted_counts_are_the_programs_output(program: str, printed: str, page: str, said: str) -> None:
    match = re.search(printed, run_program(program))
    assert match is not None, f"{program} no longer prints /{printed}/"
    expected = said.format(*(f"{int(n):,}" if n.isdigit() else n for n in match.groups()))
    assert expected in words((DOCS / page).read_text(encoding="utf-8")), \
        f"docs/{page} should say {expected!r}, as {program} prints"


LINK = re.compile(r"\]\(([^)#\s]+)(?:#[^)]*)?\)")


@pytest.mark.parametrize("name", ["README.md", "CONTRIBUTING.md"])
def test_front_pages_are_short_and_their_links_resolve(name: str) -> None:
    """README.md (at most 250 lines) and CONTRIBUTING.md link only to files that exist."""
    text = (REPO / name).read_text(encoding="utf-8")
    limit = 250 if name == "README.md" else 120
    assert len(text.splitlines()) <= limit, f"{name} has {len(text.splitlines())} lines, more than {limit}"
    targets = [t for t in LINK.findall(text) if not re.match(r"[a-z]+:", t)]
    assert targets or name != "README.md", f"{name} links to nothing"
    missing = [t for t in targets if not (REPO / t).exists()]
    assert missing == [], f"{name} links to missing files: {missing}"


def test_readme_keeps_the_two_commands() -> None:
    text = (REPO / "README.md").read_text(encoding="utf-8")
    assert "bash scripts/study.sh" in text and "bash scripts/test.sh" in text
