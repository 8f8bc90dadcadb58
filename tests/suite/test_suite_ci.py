"""The CI recipe of docs/suite.md, run as written: the GitHub Actions workflow's ``run`` steps and
the GitLab CI job's ``script``, in a fresh folder, with the package's ``pendulum-fmu`` and fmpy
on PATH. The install line is checked (it installs the wheel), not run: there is no network here,
and the package is already importable."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import yaml

from junit_schema import check as check_junit
from pendulum_fmu.suite.cases import all_cases

REPO = Path(__file__).resolve().parents[2]


def _blocks() -> list[dict]:
    page = (REPO / "docs" / "suite.md").read_text()
    return [yaml.safe_load(block) for block in re.findall(r"```yaml\n(.*?)```", page, flags=re.DOTALL)]


def _github_commands() -> list[str]:
    workflow = next(b for b in _blocks() if "jobs" in b)
    (job,) = workflow["jobs"].values()
    return [step["run"] for step in job["steps"] if "run" in step]


def _gitlab_commands() -> list[str]:
    job = next(b for b in _blocks() if "pendulum-suite" in b)["pendulum-suite"]
    assert job["artifacts"]["reports"]["junit"] == "suite-out/junit.xml"
    return list(job["script"])


def _environment() -> dict[str, str]:
    env = dict(os.environ)
    env["PATH"] = os.pathsep.join([str(Path(sys.executable).parent), env.get("PATH", "")])
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(REPO / "python"), env.get("PYTHONPATH", "")) if p)
    return env


@pytest.mark.parametrize("commands", [_github_commands, _gitlab_commands], ids=["github-actions", "gitlab-ci"])
def test_the_recipe_runs_as_written(tmp_path: Path, commands) -> None:  # type: ignore[no-untyped-def]
    lines = commands()
    installs = [line for line in lines if line.startswith("pip install")]
    assert installs == ["pip install pendulum_fmu-*.whl"]
    for line in lines:
        if line in installs:
            continue
        done = subprocess.run(["bash", "-e", "-c", line], cwd=tmp_path, env=_environment(), capture_output=True,
                              text=True, timeout=900, check=False)
        assert done.returncode == 0, (line, done.stdout[-2000:], done.stderr[-4000:])
    cases = check_junit(ET.parse(tmp_path / "suite-out" / "junit.xml").getroot())
    assert list(cases) == [c.name for c in all_cases() if c.kind == "pendulum"]
    assert all(case.find("failure") is None and case.find("error") is None for case in cases.values())
    assert (tmp_path / "suite-out" / "report.html").is_file()
