"""The suite's results as JUnit XML, the format CI systems read (GitHub's and GitLab's test
reports, Jenkins): one ``<testcase>`` per case, the verdict line as the failure's message, the
measured error and its share of the bound as properties."""

from __future__ import annotations

import math
import platform
import xml.etree.ElementTree as ET
from datetime import UTC, datetime
from pathlib import Path

from pendulum_fmu.output.atomic import write_whole
from pendulum_fmu.suite.runner import CaseResult


def _number(value: float | None) -> str:
    return "" if value is None or not math.isfinite(value) else f"{value:.6g}"


def junit_tree(results: list[CaseResult], suite: str, engine: str) -> ET.ElementTree:
    """``<testsuites>`` holding one ``<testsuite>`` named ``suite``.

    A failed case has a ``<failure>``, a run that crashed, hung or wrote nothing an
    ``<error>``; both carry the verdict line as ``message`` and the run's last lines as text.
    """
    counts = {status: sum(r.status == status for r in results) for status in ("failed", "error")}
    seconds = sum(r.run_seconds + r.judge_seconds for r in results)
    root = ET.Element("testsuites", name=suite, tests=str(len(results)), failures=str(counts["failed"]),
                      errors=str(counts["error"]), time=f"{seconds:.3f}")
    testsuite = ET.SubElement(root, "testsuite", name=suite, tests=str(len(results)), failures=str(counts["failed"]),
                              errors=str(counts["error"]), skipped="0", time=f"{seconds:.3f}",
                              timestamp=datetime.now(UTC).strftime("%Y-%m-%dT%H:%M:%S"),
                              hostname=platform.node() or "localhost")
    properties = ET.SubElement(testsuite, "properties")
    ET.SubElement(properties, "property", name="engine", value=engine)
    for result in results:
        case = result.case
        element = ET.SubElement(testsuite, "testcase", name=case.name,
                                classname=f"{suite}.fmi{case.fmi[0]}.{case.interface}",
                                time=f"{result.run_seconds + result.judge_seconds:.3f}")
        own = ET.SubElement(element, "properties")
        judged = result.judged
        figures = {"catches": case.catches, "error_rad": _number(judged.error if judged else None),
                   "bound_ratio": _number(judged.ratio if judged else None), "tolerance": _number(case.tolerance),
                   "folder": str(result.folder)}
        for name, value in figures.items():
            ET.SubElement(own, "property", name=name, value=value)
        if result.status == "failed":
            ET.SubElement(element, "failure", message=result.line, type="verdict").text = result.line
        elif result.status == "error":
            ET.SubElement(element, "error", message=result.line, type="run").text = result.output or result.line
        if result.output:
            ET.SubElement(element, "system-out").text = result.output
    ET.indent(root)
    return ET.ElementTree(root)


def write_junit(path: Path, results: list[CaseResult], suite: str, engine: str) -> Path:
    """Write the JUnit XML whole at ``path``."""
    tree = junit_tree(results, suite, engine)
    return write_whole(path, lambda target: tree.write(target, encoding="utf-8", xml_declaration=True))
