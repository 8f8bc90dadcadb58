"""The compatibility table: every built-in engine against every case, measured here, in Markdown.

Each engine runs the whole suite (:func:`pendulum_fmu.suite.session.run_and_report`); a cell is
the verdict (``PASS``, ``FAIL``: the failed checks) or why the engine could not run the case,
in its own words. Below the table: each cell's full line, the engines' versions, the machine
and the command that wrote the table.
"""

from __future__ import annotations

import re
import tempfile
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

from pendulum_fmu.output.atomic import write_whole
from pendulum_fmu.suite import adapters
from pendulum_fmu.suite.cases import all_cases
from pendulum_fmu.suite.reports import machine
from pendulum_fmu.suite.runner import CaseResult
from pendulum_fmu.suite.session import run_and_report, suite_name

COMMAND = "pendulum-fmu suite table --out docs/suite-compatibility.md"


def cell(result: CaseResult) -> str:
    """The table's cell: ``PASS``, ``FAIL (checks)`` or ``cannot: <short reason>``."""
    if result.status == "passed":
        return "PASS"
    if result.status == "failed":
        found = re.match(r"FAIL \(([^)]*)\)", result.line)
        return f"FAIL ({found.group(1)})" if found else "FAIL"
    text = result.line.removeprefix("ERROR: ").removeprefix("cannot run: ")
    return "cannot: " + (text if len(text) <= 90 else text[:87] + "...")


def _escape(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def table_markdown(runs: dict[str, list[CaseResult]], versions: dict[str, str]) -> str:
    """The page: the table (cases down, engines across), then every cell's full line."""
    engines = list(runs)
    names = [case.name for case in all_cases()]
    by_engine = {engine: {r.case.name: r for r in results} for engine, results in runs.items()}
    lines = [f"<!-- written by '{COMMAND}'; do not edit by hand -->", "",
             f"# Compatibility: {suite_name()} in the engines that install here", "",
             f"Measured {datetime.now(UTC):%Y-%m-%d} on {machine()} by `{COMMAND}`.",
             "Engines: " + ", ".join(f"`{engine}` ({versions[engine]})" for engine in engines) + ".",
             "A cell is the judge's verdict on the engine's result, or why the engine could not run the case",
             "(its own error). The split cases are judged against the master the engine claims",
             "([Suite](suite.md#the-split-pendulums-cases)).", "",
             "| case | " + " | ".join(engines) + " |", "|---|" + "---|" * len(engines)]
    for name in names:
        row = [cell(by_engine[e][name]) if name in by_engine[e] else "n/a: runs one FMU" for e in engines]
        lines.append(f"| `{name}` | " + " | ".join(_escape(c) for c in row) + " |")
    totals = [sum(r.status == "passed" for r in runs[e]) for e in engines]
    counts = [f"**{t} of {len(runs[e])}**" for t, e in zip(totals, engines, strict=True)]
    lines.append("| **passed** | " + " | ".join(counts) + " |")
    lines += ["", "## Every cell's line", ""]
    for engine in engines:
        lines += [f"### {engine}", ""]
        for result in runs[engine]:
            if result.status != "passed":
                lines.append(f"- `{result.case.name}`: {_escape(result.line)}")
        if all(r.status == "passed" for r in runs[engine]):
            lines.append("- every case passed")
        lines.append("")
    return "\n".join(lines)


def write_table(out: Path, engines: tuple[str, ...], work: Path | None, timeout: float,
                say: Callable[[str], None] = lambda line: None) -> Path:
    """Run each engine over every case it runs (under ``work``), then write the table at ``out``."""
    folder = work or Path(tempfile.mkdtemp(prefix="pendulum-suite-table-"))
    runs: dict[str, list[CaseResult]] = {}
    versions: dict[str, str] = {}
    for name in engines:
        adapter = adapters.engine(name)
        versions[name] = adapter.version()
        cases = [case for case in all_cases() if case.kind in adapter.kinds]
        say(f"{name}: {len(cases)} cases")
        runs[name] = run_and_report(adapter, cases, folder / name, timeout,
                                    lambda k, n, r: say(f"  [{k}/{n}] {r.case.name}: {r.status}"))
    return write_whole(out, lambda target: target.write_text(table_markdown(runs, versions) + "\n"))
