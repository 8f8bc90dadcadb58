"""One ``suite run``: the cases through an adapter, then ``junit.xml``, ``report.html`` and
``summary.json`` in the output folder."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from pendulum_fmu.suite.adapters import Adapter
from pendulum_fmu.suite.cases import Case, suite_version
from pendulum_fmu.suite.junit import write_junit
from pendulum_fmu.suite.reports import summary, write_report, write_summary
from pendulum_fmu.suite.runner import DEFAULT_JOBS, DEFAULT_TIMEOUT, CaseResult, run_suite


def suite_name() -> str:
    """``pendulum-suite-<version>``: the JUnit test suite's name."""
    return f"pendulum-suite-{suite_version()}"


def run_and_report(adapter: Adapter, cases: list[Case], out: Path, timeout: float = DEFAULT_TIMEOUT,
                   progress: Callable[[int, int, CaseResult], None] | None = None,
                   fmus: dict[int, Path] | None = None, jobs: int = DEFAULT_JOBS) -> list[CaseResult]:
    """Run ``cases`` with ``adapter`` under ``out`` (``jobs`` runs side by side) and write the three reports there."""
    out.mkdir(parents=True, exist_ok=True)
    results = run_suite(adapter, cases, out, timeout, progress, fmus, jobs)
    engine = adapter.version()
    write_junit(out / "junit.xml", results, suite_name(), engine)
    write_summary(out / "summary.json", summary(results, suite_name(), engine))
    write_report(out / "report.html", results, suite_name(), engine)
    return results
