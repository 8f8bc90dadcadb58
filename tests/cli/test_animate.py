"""``animate``: a GIF and an MP4 with one frame per output point, the bob moving in both panels."""

from __future__ import annotations

import math
from pathlib import Path

import imageio_ffmpeg
import numpy as np
import pytest
from PIL import Image
from scipy.special import ellipk

from pendulum_fmu.cli.main import main


def test_gif_has_one_frame_per_step_of_film_time(fmu_path: Path, tmp_path: Path) -> None:
    out = tmp_path / "pendulum.gif"
    assert main(["animate", "-a", "120", "--periods", "0.5", "--fps", "10", "--out", str(out),
                 "--fmu", str(fmu_path)]) == 0
    period = 4.0 * float(ellipk(math.sin(math.radians(60.0)) ** 2)) / math.sqrt(9.81)
    frames = math.ceil(0.5 * period / 0.1 - 1e-9) + 1
    with Image.open(out) as gif:
        count: int = gif.n_frames  # type: ignore[attr-defined]
        assert count == frames
        assert gif.size == (960, 480)
        assert gif.info["duration"] == 100 and gif.info["loop"] == 0
        gif.seek(0)
        first = np.asarray(gif.convert("RGB"), dtype=int)
        gif.seek(count - 1)
        last = np.asarray(gif.convert("RGB"), dtype=int)
    changed = np.any(first != last, axis=2)
    # after half a period the bob has swung from one side to the other, in both panels
    assert changed[:, :480].sum() > 500 and changed[:, 480:].sum() > 500


def test_mp4_is_h264_at_the_requested_rate(fmu_path: Path, tmp_path: Path) -> None:
    out = tmp_path / "pendulum.mp4"
    assert main(["animate", "-a", "0", "-w", "7", "--stop-time", "0.5", "--fps", "10", "--out", str(out),
                 "--fmu", str(fmu_path)]) == 0
    reader = imageio_ffmpeg.read_frames(str(out))
    meta = next(reader)
    frames = sum(1 for _ in reader)
    assert meta["codec"] == "h264" and meta["size"] == (960, 480) and meta["fps"] == 10.0
    assert frames == 6


def test_too_long_an_animation_is_refused_with_the_limit(fmu_path: Path, tmp_path: Path,
                                                         capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        main(["animate", "--periods", "900", "--fps", "60", "--out", str(tmp_path / "long.gif"),
              "--fmu", str(fmu_path)])
    assert stop.value.code == 2
    # the option as argparse names it in its own refusals of -p/--periods
    assert "argument -p/--periods: the animation would have" in capsys.readouterr().err
    assert not (tmp_path / "long.gif").exists()


def test_rendering_says_how_far_and_nothing_moving_crosses_the_readouts_or_the_legend(
        fmu_path: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    """Going over the top, the bob sweeps the whole circle of radius L, which fills each panel: the
    readouts sit above the panels and the legend below them. The film says its frames as it draws."""
    import matplotlib.pyplot as plt
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figures: list[Figure] = []
    close = plt.close
    monkeypatch.setattr(plt, "close", lambda figure=None: (figures.append(figure), close(figure)))
    out = tmp_path / "rotation.gif"
    assert main(["animate", "-a", "0", "-w", "7", "--stop-time", "0.8", "--fps", "10", "--out", str(out),
                 "--fmu", str(fmu_path)]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err == [f"animate: drawing 9 frames into {out} ...", "animate: 2 of 9 frames drawn",
                   "animate: 4 of 9 frames drawn", "animate: 7 of 9 frames drawn"]
    figure, = figures
    canvas = FigureCanvasAgg(figure)
    canvas.draw()
    renderer = canvas.get_renderer()
    panels = [ax.get_window_extent(renderer) for ax in figure.axes]
    legend, = figure.legends
    assert legend.get_window_extent(renderer).y1 < min(panel.y0 for panel in panels)
    for ax, panel in zip(figure.axes, panels, strict=True):
        readout, = [text for text in ax.texts if text.get_animated()]
        readout.set_text("theta =   186.20 deg,  |theta - theta_exact| = 1.3e-15 rad")
        assert readout.get_window_extent(renderer).y0 >= panel.y1
        assert ax.get_legend() is None
