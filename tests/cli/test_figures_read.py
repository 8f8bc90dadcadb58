"""Figures that read at a glance: legends off the curves, exact zeros marked instead of plunging,
one unit per axis, units in the titles. Each figure is caught as it is closed and measured."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import matplotlib.pyplot as plt
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from pendulum_fmu.cli.main import main

matplotlib.use("Agg")


@pytest.fixture
def closed(monkeypatch: pytest.MonkeyPatch) -> list[Figure]:
    """Every figure the code under test closes, kept for measuring."""
    figures: list[Figure] = []
    close = plt.close

    def keep(figure: Figure | None = None) -> None:
        if isinstance(figure, Figure):
            figures.append(figure)
        close(figure)

    monkeypatch.setattr(plt, "close", keep)
    return figures


def legends_clear_of_their_axes(figure: Figure) -> None:
    """Every axes legend lies above its panel (touching at most its top edge), never over the curves."""
    canvas = FigureCanvasAgg(figure)  # pyplot's own canvas is gone once the figure is closed
    canvas.draw()
    renderer = canvas.get_renderer()
    for ax in figure.axes:
        legend = ax.get_legend()
        if legend is not None:
            assert legend.get_window_extent(renderer).y0 >= ax.get_window_extent(renderer).y1 - 2, ax.get_ylabel()


def test_compare_has_an_axis_per_unit_and_no_tolerance_line(fmu_path: Path, tmp_path: Path,
                                                           closed: list[Figure]) -> None:
    assert main(["compare", "-a", "170", "--solver", "rk4", "--tolerance", "1e-6", "-p", "2",
                 "--out", str(tmp_path / "c.png"), "--fmu", str(fmu_path)]) == 0
    figure, = closed
    top, theta, omega = figure.axes
    assert "(rad)" in theta.get_ylabel() and "(rad/s)" in omega.get_ylabel() and "rad/s" not in theta.get_ylabel()
    for ax in (theta, omega):
        assert ax.get_yscale() == "log" and ax.get_ylim()[0] > 1e-17
        assert not [line for line in ax.get_lines() if "tolerance" in str(line.get_label())]
    # the error at t = 0 is exactly 0: a tick on the bottom edge, said in the legend above the panel
    assert [line.get_label() for line in theta.get_lines() if line.get_marker() == "|"]
    legends_clear_of_their_axes(figure)


def test_judge_plot_marks_zeros_and_gives_g_a_unit(fmu_path: Path, tmp_path: Path, closed: list[Figure],
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    run = tmp_path / "run.csv"
    assert main(["simulate", "-a", "80", "-p", "2", "-o", str(run), "--fmu", str(fmu_path)]) == 0
    assert main(["judge", str(run), "--start", "theta=80deg", "--plot", str(tmp_path / "j.png")]) == 0
    figure, = closed
    assert "g 9.81 m/s$^2$" in figure.get_suptitle()
    for ax in figure.axes:
        error, *_ = ax.get_lines()
        positive = error.get_ydata()[error.get_ydata() > 0]  # type: ignore[operator]
        assert ax.get_ylim()[0] > positive.min() / 100, "an exact zero plunges the axis"
        assert [line for line in ax.get_lines() if line.get_marker() == "|"]
    legends_clear_of_their_axes(figure)
