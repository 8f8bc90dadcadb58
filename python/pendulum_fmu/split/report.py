"""The split judge's verdict as JSON and as a figure (``judge --system split --json/--plot``)."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np

from pendulum_fmu.split.judge import SplitRuns, SplitVerdict


def _number(value: float | None) -> float | None:
    return None if value is None or not math.isfinite(value) else float(value)


def verdict_dict(verdict: SplitVerdict) -> dict[str, Any]:
    """One run's three answers, kept apart, as plain data."""
    who, acc = verdict.identification, verdict.accuracy
    return {
        "file": verdict.source,
        "rows": verdict.rows,
        "H": verdict.H,
        "uniform_grid": verdict.uniform,
        "problem": {"L": verdict.problem.L, "g": verdict.problem.g, "theta0": verdict.problem.theta0,
                    "omega0": verdict.problem.omega0},
        "conformance": {"passed": verdict.conformance.passed, "exchange": verdict.conformance.exchange,
                        "findings": [{"kind": f.kind, "text": f.line} for f in verdict.findings]},
        "identification": {"master": who.master, "text": who.text, "H": _number(who.H), "every": who.every,
                           "rows_compared": who.rows, "truncated": who.truncated,
                           "differences": {k: _number(v) for k, v in who.differences.items()}},
        "accuracy": {"error": _number(acc.error), "at": _number(acc.at), "growth": _number(acc.growth),
                     "rank": acc.rank, "error_compared": _number(acc.compared),
                     "reference_errors": {k: _number(v) for k, v in acc.reference_errors.items()},
                     "seconds": _number(verdict.seconds)},
        "criteria": [{"name": c.name, "passed": c.passed, "text": c.line} for c in verdict.criteria],
        "passed": verdict.passed,
        "summary": verdict.summary,
    }


def runs_dict(runs: SplitRuns) -> dict[str, Any]:
    """Several runs: each run's answers, the order over them, the criteria, the verdict."""
    order = runs.order
    return {
        "runs": [verdict_dict(v) for v in runs.verdicts],
        "order": None if order is None else {"order": order.order, "constant": order.constant, "runs": order.runs,
                                             "consecutive": order.pairs},
        "criteria": [{"name": c.name, "passed": c.passed, "text": c.line} for c in runs.criteria],
        "passed": runs.passed,
        "summary": runs.summary,
    }


def write_json(data: dict[str, Any], path: Path) -> Path:
    """``data`` to ``path``, indented."""
    Path(path).write_text(json.dumps(data, indent=2) + "\n")
    return Path(path)


def write_plot(sources: list[Any], verdicts: list[SplitVerdict], path: Path) -> Path:
    """|theta - theta_exact| against time for each run (log scale), each reference master's
    error at the run's H drawn as a dotted level; with several runs a second panel draws error
    against H (and against wall time when the engine reported it)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from pendulum_fmu.fmu.library import exact
    from pendulum_fmu.split.grid import read_grid
    from pendulum_fmu.split.reading import read_coupled

    several = len(verdicts) > 1
    fig, axes = plt.subplots(1, 2 if several else 1, figsize=(12 if several else 8, 5), squeeze=False)
    ax = axes[0][0]
    for source, verdict in zip(sources, verdicts, strict=True):
        result = read_coupled(source)
        grid = read_grid(result.time, result.resolution["time"])
        theta = result.values["theta"][grid.keep]
        p = verdict.problem
        errors = np.abs(theta - exact(p.theta0, p.omega0, p.L, p.g, grid.exact_times)[0])
        ax.semilogy(grid.time, np.maximum(errors, 1e-17), lw=1,
                    label=f"{Path(str(verdict.source)).name}: H = {verdict.identification.H or verdict.H:.3g}")
    if not several:
        for name, value in sorted(verdicts[0].accuracy.reference_errors.items(), key=lambda i: i[1]):
            ax.axhline(value, ls=":", lw=0.8, color="grey")
            ax.annotate(name, (ax.get_xlim()[1], value), fontsize=7, ha="right", va="bottom", color="dimgrey")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("|theta - theta_exact| (rad)")
    ax.set_title(verdicts[-1].summary if not several else "error of each run", fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    if several:
        right = axes[0][1]
        steps = [v.identification.H or v.H for v in verdicts]
        right.loglog(steps, [v.error for v in verdicts], "-o", label="error against H")
        right.set_xlabel("H (s)")
        right.set_ylabel("largest error (rad)")
        seconds = [v.seconds for v in verdicts]
        if all(s is not None for s in seconds):
            top = right.twiny()
            top.loglog(seconds, [v.error for v in verdicts], "--s", color="C1", label="error against wall time")
            top.set_xlabel("wall time as reported (s)")
        right.grid(True, which="both", alpha=0.3)
        from pendulum_fmu.split.accuracy import observed_order

        fit = observed_order(steps, [v.error for v in verdicts])
        right.set_title("order over the runs" + (f": error = {fit.constant:.3g} H^{fit.order:.2f}" if fit else ""),
                        fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return Path(path)
