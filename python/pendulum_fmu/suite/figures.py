"""One small figure per case for the report: |theta - theta_exact| against time, with the
Co-Simulation bound where the case has one, as a PNG in memory."""

from __future__ import annotations

import io

import numpy as np

from pendulum_fmu.suite.runner import CaseResult

BUCKETS = 400
"""Points per curve at most (about one per pixel of the figure's width)."""
CS_FACTOR = 100.0
"""The certificate's bound is 100 tol max(1, |theta_e|) (the judge's Co-Simulation bound)."""


def _curve(result: CaseResult) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Times, theta's error and the exact theta of a result; None when it cannot be read."""
    if result.result is None:
        return None
    from pendulum_fmu.fmu.library import exact

    try:
        if result.case.kind == "split":
            from pendulum_fmu.split.reading import read_coupled

            coupled = read_coupled(result.result)
            return coupled.time, np.abs(coupled.values["theta"] - coupled.values["theta_exact"]), \
                coupled.values["theta_exact"]
        from pendulum_fmu.judge.reading import read_result

        read = read_result(result.result)
    except Exception:  # noqa: BLE001 (a figure is not drawn for a file the judge rejected)
        return None
    if "theta" not in read.values:
        return None
    v = result.case.start_values
    theta, _ = exact(v["theta"], v["omega"], v["L"], v["g"], read.time - result.case.start)
    return read.time, np.abs(read.values["theta"] - theta), theta


def envelope(time: np.ndarray, values: np.ndarray, buckets: int = BUCKETS) -> tuple[np.ndarray, np.ndarray]:
    """At most ``buckets`` points: each bucket of consecutive rows drawn as its largest value at
    its first time, so a long run's figure keeps every peak (a 10,000-row run in 400 points)."""
    if values.size <= buckets:
        return time, values
    edges = np.linspace(0, values.size, buckets + 1).astype(int)
    return time[edges[:-1]], np.fmax.reduceat(values, edges[:-1])


def case_png(result: CaseResult) -> bytes | None:
    """The case's figure as PNG bytes; None when there is no result to draw."""
    curve = _curve(result)
    if curve is None:
        return None
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    time, error, theta = curve
    shown = np.where(np.isfinite(error), np.maximum(error, 1e-17), np.nan)
    figure = Figure(figsize=(6.4, 2.3), dpi=80)
    FigureCanvasAgg(figure)
    figure.subplots_adjust(left=0.12, right=0.98, top=0.88, bottom=0.22)
    axes = figure.add_subplot()
    colour = {"passed": "#1a7f37", "failed": "#cf222e"}.get(result.status, "#9a6700")
    axes.semilogy(*envelope(time, shown), color=colour, linewidth=1.0, label="|theta - theta_exact|")
    if result.case.kind == "pendulum" and result.case.interface == "cs":
        bound = CS_FACTOR * result.case.tolerance * np.maximum(1.0, np.abs(theta))
        axes.semilogy(*envelope(time, bound), color="#57606a", linewidth=1.0, linestyle="--",
                      label="bound, 100 tol max(1, |theta|)")
    axes.set_xlabel("time (s)")
    axes.set_ylabel("error (rad)")
    axes.set_title(f"{result.case.name}: {result.status}", fontsize=10)
    axes.grid(True, which="major", alpha=0.3)
    axes.legend(fontsize=7, loc="best")
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png")
    return buffer.getvalue()
