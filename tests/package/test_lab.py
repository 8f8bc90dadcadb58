"""The lab's scripts (``tests/lab/``): each imports, answers ``--help``, and uses only the
package's public API (no name of ``pendulum_fmu`` that starts with an underscore)."""

from __future__ import annotations

import ast
import importlib.util
import sys
from pathlib import Path
from types import ModuleType

import pytest

LAB = Path(__file__).resolve().parents[1] / "lab"
SCRIPTS = sorted(LAB.glob("*.py"))


def _load(path: Path) -> ModuleType:
    spec = importlib.util.spec_from_file_location(f"lab_{path.stem}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def test_the_lab_holds_the_three_target_scripts() -> None:
    assert [p.name for p in SCRIPTS] == ["judge_targets.py", "solver_targets.py", "suite_target.py"]
    readme = (LAB / "README.md").read_text()
    assert all(f"`{p.name}`" in readme for p in SCRIPTS)


@pytest.mark.parametrize("path", SCRIPTS, ids=[p.stem for p in SCRIPTS])
def test_a_lab_script_imports_and_answers_help(path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    module = _load(path)
    with pytest.raises(SystemExit) as stop:
        module.main(["--help"])
    assert stop.value.code == 0
    assert capsys.readouterr().out.startswith(f"usage: python tests/lab/{path.name}")


@pytest.mark.parametrize("path", SCRIPTS, ids=[p.stem for p in SCRIPTS])
def test_a_lab_script_uses_only_the_public_api(path: Path) -> None:
    private = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("pendulum_fmu"):
            parts = (node.module or "").split(".") + [alias.name for alias in node.names]
            private += [f"{node.module}.{alias.name}" for alias in node.names if any(p.startswith("_") for p in parts)]
        elif isinstance(node, ast.Import):
            private += [a.name for a in node.names if a.name.startswith("pendulum_fmu")
                        and any(p.startswith("_") for p in a.name.split("."))]
        elif isinstance(node, ast.Attribute) and node.attr.startswith("_") and not node.attr.startswith("__"):
            private.append(node.attr)
    assert not private, f"{path.name} reaches into the package's private names: {private}"
