"""``sweep``'s cost plot: the FMU's exact counts on the axis, Model Exchange marked and apart."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import matplotlib.pyplot as plt
import pytest
from matplotlib.figure import Figure

from pendulum_fmu.sweep.plots import plot_cost


def row(solver: str, tolerance: float, error: float, rhs: int | None, wall: float) -> dict[str, Any]:
    """One sweep row, as the journal gives it back."""
    return {"status": "ok", "solver": solver, "interface": "ME" if solver == "cvode" else "CS",
            "tolerance": tolerance, "max_error_rad": error, "rhs_evaluations": rhs, "steps": None,
            "wall_time_s": wall, "amplitude_deg": 80.0, "periods": 2.0}


@pytest.fixture
def closed(monkeypatch: pytest.MonkeyPatch) -> list[Figure]:
    figures: list[Figure] = []
    close = plt.close
    monkeypatch.setattr(plt, "close", lambda figure=None: (figures.append(figure), close(figure)))
    return figures


def test_the_cost_axis_is_the_fmus_count_and_cvode_has_its_own_panel(tmp_path: Path, closed: list[Figure]) -> None:
    rows = [row("rkn", 1e-8, 1e-14, 900, 0.02), row("dopri5", 1e-8, 1e-11, 2500, 0.001),
            row("cvode", 1e-8, 1e-7, None, 0.015)]
    plot_cost(rows, tmp_path / "cost.png")
    figure, = closed
    counted, timed = figure.axes
    assert "right-hand-side evaluations" in counted.get_xlabel() and "Co-Simulation" in counted.get_title()
    assert sorted(x for line in counted.get_lines() for x in line.get_xdata()) == [900, 2500]  # type: ignore[union-attr]
    assert "Model Exchange" in timed.get_title() and "wall time" in timed.get_xlabel()
    assert [list(line.get_xdata()) for line in timed.get_lines()] == [[15.0]]  # type: ignore[arg-type]
    labels = [text.get_text() for text in figure.legends[0].get_texts()]
    assert labels == ["dopri5 (CS), tol 1e-08", "rkn (CS), tol 1e-08", "cvode (ME), tol 1e-08"]


def test_without_model_exchange_there_is_one_panel(tmp_path: Path, closed: list[Figure]) -> None:
    plot_cost([row("rkn", 1e-8, 1e-14, 900, 0.02), row("rk4", 1e-6, 1e-7, 1200, 0.02)], tmp_path / "cost.png")
    figure, = closed
    assert len(figure.axes) == 1 and "the FMU's count" in figure.axes[0].get_xlabel()
