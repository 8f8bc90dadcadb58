"""The study's figures read at a glance: one time axis (t/T0) for Figures 3-5 with L, g and T0
stated, both interfaces' exact zeros visible at t = 0, and the period figure's note clear of
the curve and inside the axes. Each figure is caught as the study closes it, and measured."""

from __future__ import annotations

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.text import Text

from pendulum_fmu.cli.main import main

CONSTANTS = r"L = 1 m, g = 9.81 m/s$^2$, $T_0 = 2\pi\sqrt{L/g}$ = 2.006 s"


@pytest.fixture(scope="module")
def figures(fmu_path: Path, tmp_path_factory: pytest.TempPathFactory) -> list[Figure]:
    """Figures 3, 4, 5, the period ratio and speed against error, in the order the study draws them."""
    kept: list[Figure] = []
    close = plt.close
    patch = pytest.MonkeyPatch()
    patch.setattr(plt, "close", lambda figure=None: (kept.append(figure), close(figure)))
    try:
        out = tmp_path_factory.mktemp("study")
        assert main(["study", "--out", str(out), "--fmu", str(fmu_path), "--periods", "2"]) == 0
    finally:
        patch.undo()
    assert len(kept) == 5
    return kept


def test_figures_3_to_5_share_t_over_t0_and_state_l_g_t0(figures: list[Figure]) -> None:
    fig3, fig4, fig5, _, _ = figures
    for figure in (fig3, fig4):
        assert "$t / T_0$" in figure.axes[-1].get_xlabel() and CONSTANTS in figure.axes[-1].get_xlabel()
    assert CONSTANTS in fig5.get_suptitle()
    assert all(ax.get_xlabel() == "$t / T_0$" for ax in fig5.axes)


def test_figure_5_shows_both_interfaces_zero_at_t0_in_their_colours(figures: list[Figure]) -> None:
    fig5 = figures[2]
    bottom = fig5.axes[len(fig5.axes) // 2]
    ticks = [line for line in bottom.get_lines() if line.get_marker() == "|"]
    at_start = {(line.get_color(), float(np.asarray(line.get_ydata())[0])) for line in ticks
                if float(np.asarray(line.get_xdata())[0]) == 0.0}
    assert {color for color, _ in at_start} == {"tab:purple", "tab:orange"}
    assert len({height for _, height in at_start}) == 2, "one interface's tick at t = 0 hides the other's"
    legend_colors = {handle.get_color() for handle in fig5.legends[-1].legend_handles  # type: ignore[union-attr]
                     if handle is not None and handle.get_marker() == "|"}  # type: ignore[union-attr]
    assert legend_colors == {"tab:purple", "tab:orange"}


def test_the_period_notes_sit_inside_the_axes_clear_of_the_curve(figures: list[Figure]) -> None:
    figure = figures[3]
    left, right = figure.axes
    canvas = FigureCanvasAgg(figure)
    canvas.draw()
    renderer = canvas.get_renderer()
    note, = left.texts
    box = Text.get_window_extent(note, renderer)  # the words alone: its arrow points to the top edge
    assert left.get_window_extent(renderer).contains(box.x0, box.y0)
    assert left.get_window_extent(renderer).contains(box.x1, box.y1), "the note runs off the axes"
    curve = left.get_lines()[0]
    points = left.transData.transform(np.column_stack([curve.get_xdata(), curve.get_ydata()]))
    inside = (points[:, 0] >= box.x0) & (points[:, 0] <= box.x1) & (points[:, 1] >= box.y0) & (points[:, 1] <= box.y1)
    assert not inside.any(), "the note overlaps the FMU's curve"
    assert any(r"$\theta_0$ in rad" in str(line.get_label()) for line in left.get_lines())
    assert not any(tick.gridline.get_visible() for tick in right.xaxis.get_minor_ticks()), "a minor grid"
    assert any(tick.gridline.get_visible() for tick in right.xaxis.get_major_ticks())


def test_speed_against_error_has_every_method_the_floor_and_the_error_axis_reversed(figures: list[Figure]) -> None:
    """Both panels: log axes, the error growing to the left (more accurate to the right), the
    five methods in their colours; the floor only where it means something, on wall time."""
    figure = figures[4]
    evaluations, wall = figure.axes
    for ax in (evaluations, wall):
        assert ax.get_xscale() == ax.get_yscale() == "log"
        low, high = ax.get_xlim()
        assert low > high, "the error axis is not reversed"
        curves = {line.get_color() for line in ax.get_lines() if len(np.asarray(line.get_xdata())) >= 5}
        assert {"tab:blue", "tab:red", "tab:green", "tab:purple", "tab:orange"} <= curves
    floors = [line for line in wall.get_lines() if line.get_linestyle() == "-." and "floor" in str(line.get_label())]
    assert len(floors) == 1 and float(np.asarray(floors[0].get_ydata())[0]) > 0
    assert not [line for line in evaluations.get_lines() if "floor" in str(line.get_label())]
    labels = [text.get_text() for text in figure.legends[0].get_texts()]
    assert labels[:5] == ["dopri5 (CS, FMU)", "rk4 (CS, FMU)", "rkn (CS, FMU)", "symplectic (CS, FMU)",
                          "CVODE (ME, fmpy)"]
