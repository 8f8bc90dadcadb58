"""The suite's reports: ``summary.json`` and the self-contained ``report.html`` (the table, then a
figure per case; no file or network fetched when it opens)."""

from __future__ import annotations

import base64
import html
import json
import math
import os
import platform
from pathlib import Path
from typing import Any

from pendulum_fmu.output.atomic import write_whole
from pendulum_fmu.suite.figures import case_png
from pendulum_fmu.suite.runner import CaseResult


def machine() -> str:
    """The machine in words: processor, cores usable, system, Python."""
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return (f"{platform.processor() or platform.machine()}, {cores} cores, {platform.system()} "
            f"{platform.release()}, Python {platform.python_version()}")


def _finite(value: float | None) -> float | None:
    return value if value is not None and math.isfinite(value) else None


def summary(results: list[CaseResult], suite: str, engine: str) -> dict[str, Any]:
    """What ``summary.json`` holds: the suite, the engine, the counts and one entry per case."""
    counts = {status: sum(r.status == status for r in results) for status in ("passed", "failed", "error")}
    return {"suite": suite, "engine": engine, "machine": machine(), "passed": counts["passed"] == len(results),
            "counts": counts, "seconds": round(sum(r.run_seconds + r.judge_seconds for r in results), 3),
            "cases": [{"name": r.case.name, "fmi_version": r.case.fmi, "interface": r.case.interface,
                       "kind": r.case.kind, "catches": r.case.catches, "status": r.status, "line": r.line,
                       "error_rad": _finite(r.judged.error) if r.judged else None,
                       "bound_ratio": _finite(r.judged.ratio) if r.judged else None,
                       "run_seconds": round(r.run_seconds, 3), "judge_seconds": round(r.judge_seconds, 3),
                       "folder": str(r.folder), "result": str(r.result) if r.result else None,
                       "output_tail": r.output} for r in results]}


def write_summary(path: Path, data: dict[str, Any]) -> Path:
    """Write ``summary.json`` whole."""
    return write_whole(path, lambda target: target.write_text(json.dumps(data, indent=1) + "\n"))


STYLE = """
body { font-family: system-ui, sans-serif; margin: 1.5em; color: #1f2328; max-width: 70em; }
table { border-collapse: collapse; font-size: 0.9em; }
th, td { border: 1px solid #d0d7de; padding: 0.25em 0.5em; text-align: left; vertical-align: top; }
th { background: #f6f8fa; }
.passed { color: #1a7f37; font-weight: bold; } .failed { color: #cf222e; font-weight: bold; }
.error { color: #9a6700; font-weight: bold; }
.case { margin: 1.2em 0; border-top: 1px solid #d0d7de; padding-top: 0.6em; }
pre { background: #f6f8fa; padding: 0.5em; white-space: pre-wrap; font-size: 0.85em; }
"""


def _figure(value: float | None, digits: int = 3) -> str:
    return "" if value is None or not math.isfinite(value) else f"{value:.{digits}g}"


def report_html(results: list[CaseResult], suite: str, engine: str) -> str:
    """The page: heading with the verdict and engine, the table of cases, a section per case."""
    data = summary(results, suite, engine)
    counts = data["counts"]
    verdict = "every case passed" if data["passed"] else \
        f"{counts['failed']} failed, {counts['error']} could not be run or read"
    rows, sections = [], []
    for result in results:
        case, judged = result.case, result.judged
        anchor = html.escape(case.name)
        rows.append(f"<tr><td><a href=\"#{anchor}\">{anchor}</a></td><td>{case.fmi}</td>"
                    f"<td>{case.interface.upper()}</td><td class=\"{result.status}\">{result.status}</td>"
                    f"<td>{_figure(judged.error if judged else None)}</td>"
                    f"<td>{_figure(judged.ratio if judged else None, 2)}</td>"
                    f"<td>{html.escape(case.catches)}</td></tr>")
        png = case_png(result)
        image = (f"<img alt=\"theta's error against time for {anchor}\" src=\"data:image/png;base64,"
                 f"{base64.b64encode(png).decode()}\">") if png else "<p>(no result to draw)</p>"
        shown_tail = result.status == "error" and result.output.strip() and result.output.strip() not in result.line
        tail = f"<pre>{html.escape(result.output)}</pre>" if shown_tail else ""
        sections.append(f"<div class=\"case\" id=\"{anchor}\"><h3>{anchor} <span class=\"{result.status}\">"
                        f"{result.status}</span></h3><p>{html.escape(case.catches)}</p>"
                        f"<p><code>{html.escape(result.line)}</code></p>{image}{tail}</div>")
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{html.escape(suite)}: "
            f"{html.escape(engine)}</title><style>{STYLE}</style></head><body>\n"
            f"<h1>{html.escape(suite)}</h1><p>Engine: <b>{html.escape(engine)}</b>. {len(results)} cases: "
            f"<span class=\"{'passed' if data['passed'] else 'failed'}\">{verdict}</span>. "
            f"{data['seconds']:.1f} s on {html.escape(data['machine'])}.</p>\n"
            "<table><tr><th>case</th><th>FMI</th><th>interface</th><th>verdict</th><th>max |theta error| (rad)</th>"
            "<th>error / bound</th><th>what it catches</th></tr>\n" + "\n".join(rows) + "</table>\n"
            + "\n".join(sections) + "\n</body></html>\n")


def write_report(path: Path, results: list[CaseResult], suite: str, engine: str) -> Path:
    """Write ``report.html`` whole."""
    text = report_html(results, suite, engine)
    return write_whole(path, lambda target: target.write_text(text))
