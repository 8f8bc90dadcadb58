"""The swinging pendulum, numerical and exact side by side, as a GIF or MP4."""

from __future__ import annotations

import logging
import math
import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from pendulum_fmu.errors import UsageError
from pendulum_fmu.fmu.runner import FmuRunner, Trajectory
from pendulum_fmu.spec import InitialValueProblem, Method, StopUnit, TimeGrid

_log = logging.getLogger(__name__)
"""The frames' progress (INFO): the command line shows it on stderr."""

MAX_FRAMES = 1500
"""Most frames an animation may have (a minute at 25 frames/s; a GIF is assembled in memory)."""


class _GifFrames:
    """Collect frames (128 colours each, no dithering) and write an endless-loop GIF."""

    def __init__(self, path: Path, fps: int) -> None:
        self.path, self.fps = path, fps
        self.frames: list[Any] = []

    def add(self, rgb: np.ndarray) -> None:
        from PIL import Image

        self.frames.append(Image.fromarray(rgb).quantize(colors=128, method=Image.Quantize.FASTOCTREE,
                                                         dither=Image.Dither.NONE))

    def close(self) -> None:
        first, *rest = self.frames
        first.save(self.path, save_all=True, append_images=rest, duration=round(1000 / self.fps), loop=0)

    def abort(self) -> None:
        """Drop the frames: nothing is written."""
        self.frames.clear()


class _Mp4Frames:
    """Stream frames to ffmpeg (the binary imageio-ffmpeg ships): H.264, yuv420p."""

    def __init__(self, path: Path, fps: int, size: tuple[int, int]) -> None:
        import imageio_ffmpeg

        self._writer = imageio_ffmpeg.write_frames(str(path), size, fps=fps, codec="libx264", quality=7,
                                                   macro_block_size=16)
        self._writer.send(None)

    def add(self, rgb: np.ndarray) -> None:
        self._writer.send(np.ascontiguousarray(rgb))

    def close(self) -> None:
        self._writer.close()

    def abort(self) -> None:
        """Stop ffmpeg (the caller deletes its unfinished file)."""
        try:
            self._writer.close()
        except Exception:  # noqa: BLE001 -- ffmpeg may already be gone; the file is deleted anyway
            pass


def render(trajectory: Trajectory, out: Path, fps: int, trail: float = 1.0,
           progress: Callable[[int, int], None] | None = None) -> Path:
    """Draw every output point of ``trajectory`` as one frame and write the GIF or MP4.

    The axes, labels and legends are drawn once; each frame restores them and draws only
    the rods, bobs, paths and texts (blitting), so a frame costs a few milliseconds.

    Parameters
    ----------
    trajectory : Trajectory
        A run whose output points are the frames.
    out : Path
        ``.gif`` or ``.mp4``.
    fps : int
        Frames per second of the file.
    trail : float
        Seconds of simulated time of the bob's path drawn behind it.
    progress : callable, optional
        Called with (frames drawn, frames in all) after each quarter of the frames.

    Returns
    -------
    Path
        ``out``.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    r, p, m = trajectory.result, trajectory.problem, trajectory.method
    time = r["time"]
    theta = {"numeric": r["theta"], "exact": r["theta_exact"]}
    xy = {name: (p.L * np.sin(angle), -p.L * np.cos(angle)) for name, angle in theta.items()}
    dt = float(time[1] - time[0]) if time.size > 1 else 1.0
    trail_points = max(2, round(trail / dt))
    period = trajectory.period if math.isfinite(trajectory.period) else p.small_angle_period
    error = np.abs(theta["numeric"] - theta["exact"])

    # 960 x 480 pixels: both multiples of 16, so H.264 needs no rescaling.
    fig, axes = plt.subplots(1, 2, figsize=(9.6, 4.8), dpi=100)
    # The bob's circle fills each square panel: the readouts sit above the panels (under their
    # titles) and one legend below them, so neither the bob nor its trail ever crosses them.
    fig.subplots_adjust(left=0.075, right=0.985, bottom=0.2, top=0.79, wspace=0.22)
    titles = {"numeric": f"numerical: FMU, {m.label}", "exact": "exact: Jacobi elliptic (theta_exact, in the FMU)"}
    colors = {"numeric": "tab:blue", "exact": "tab:orange"}
    moving: dict[str, tuple[Any, Any, Any, Any]] = {}
    limit = 1.22 * p.L
    for ax, name in zip(axes, ("numeric", "exact"), strict=True):
        ax.set_xlim(-limit, limit)
        ax.set_ylim(-limit, limit)
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        ax.set_title(titles[name], fontsize=10, pad=18)
        ax.grid(alpha=0.25)
        ax.plot([0], [0], "ks", ms=5)
        path, = ax.plot([], [], "-", color=colors[name], lw=1.4, alpha=0.5, animated=True)
        rod, = ax.plot([], [], "-", color="0.35", lw=2.2, animated=True)
        bob, = ax.plot([], [], "o", color=colors[name], ms=15, mec="k", animated=True)
        text = ax.text(0.5, 1.015, "", transform=ax.transAxes, ha="center", va="bottom", fontsize=9,
                       family="monospace", animated=True)
        moving[name] = (path, rod, bob, text)
    key = [(plt.Line2D([], [], ls="none", marker="s", color="k", ms=5), "pivot"),
           (plt.Line2D([], [], color="0.35", lw=2.2), "rod"),
           (plt.Line2D([], [], ls="none", marker="o", color=colors["numeric"], mec="k", ms=9), "bob, numerical"),
           (plt.Line2D([], [], ls="none", marker="o", color=colors["exact"], mec="k", ms=9), "bob, exact"),
           (plt.Line2D([], [], color="0.5", lw=1.4, alpha=0.6), f"path, last {trail:g} s")]
    fig.legend(*zip(*key, strict=True), loc="lower center", ncol=len(key), fontsize=8, frameon=False)
    heading = fig.text(0.5, 0.965, "", ha="center", va="top", fontsize=10, animated=True)
    canvas = fig.canvas
    canvas.draw()
    background = canvas.copy_from_bbox(fig.bbox)  # type: ignore[attr-defined]
    width, height = canvas.get_width_height()
    # Written under a temporary name beside ``out`` and renamed when complete: an interrupted
    # film leaves no truncated file at ``out`` (and an older complete one stays as it was).
    partial = out.with_name(f".{out.stem}.{os.getpid()}.partial{out.suffix}")
    frames: _GifFrames | _Mp4Frames = (_Mp4Frames(partial, fps, (width, height)) if out.suffix.lower() == ".mp4"
                                       else _GifFrames(partial, fps))
    finished = False
    quarters = {round(time.size * q / 4) for q in (1, 2, 3)} - {0, time.size}
    try:
        for k in range(time.size):
            canvas.restore_region(background)  # type: ignore[attr-defined]
            start = max(0, k - trail_points)
            for ax, name in zip(axes, ("numeric", "exact"), strict=True):
                path, rod, bob, text = moving[name]
                x, y = xy[name]
                path.set_data(x[start:k + 1], y[start:k + 1])
                rod.set_data([0.0, x[k]], [0.0, y[k]])
                bob.set_data([x[k]], [y[k]])
                line = f"theta = {math.degrees(theta[name][k]):8.2f} deg"
                if name == "numeric":
                    line += f",  |theta - theta_exact| = {error[k]:.1e} rad"
                text.set_text(line)
                for artist in (path, rod, bob, text):
                    ax.draw_artist(artist)
            heading.set_text(f"theta0 = {p.theta0_deg:.6g} deg, omega0 = {p.omega0:g} rad/s, L = {p.L:g} m, "
                             f"g = {p.g:g} m/s^2        t = {time[k]:6.2f} s  ({time[k] / period:5.2f} periods)")
            fig.draw_artist(heading)
            frames.add(np.asarray(canvas.buffer_rgba())[:, :, :3])  # type: ignore[attr-defined]
            if progress is not None and (k + 1) in quarters:
                progress(k + 1, time.size)
        frames.close()
        os.replace(partial, out)
        finished = True
    finally:
        plt.close(fig)
        if not finished:
            frames.abort()
            partial.unlink(missing_ok=True)
    return out


def animate(fmu: Path, problem: InitialValueProblem, method: Method, stop: float, unit: StopUnit, out: Path,
            fps: int = 25, speed: float = 1.0) -> Trajectory:
    """Simulate one frame per 1/fps s of film and write the animation.

    Parameters
    ----------
    fmu : Path
        ``Pendulum.fmu``.
    problem, method
        What to run.
    stop : float
        Simulated time span, in seconds or periods (``unit``).
    unit : {"s", "periods"}
        Unit of ``stop``.
    out : Path
        ``.gif`` or ``.mp4``.
    fps : int
        Frames per second of film.
    speed : float
        Simulated seconds per second of film (2 plays twice as fast as life).

    Returns
    -------
    Trajectory
        The run drawn.

    Raises
    ------
    UsageError
        If the film would have more than :data:`MAX_FRAMES` frames.

    Notes
    -----
    It logs its progress at INFO (logger ``pendulum_fmu.figures.animation``): the frames to
    draw, then each quarter drawn.
    """
    grid = TimeGrid(stop, unit, output_interval=speed / fps)
    counted: list[int] = []

    def plan(period: float) -> None:
        frames = grid.point_count(period)
        counted.append(frames)
        if frames > MAX_FRAMES:
            raise UsageError("periods" if unit == "periods" else "stop_time",
                             f"the animation would have {frames} frames, at most {MAX_FRAMES} are allowed: "
                             "shorten it, lower `fps` or raise `speed`")

    with FmuRunner(fmu) as runner:
        trajectory = runner.run(problem, method, grid, plan)   # refused before the first frame
    frames = counted[0]
    _log.info("animate: drawing %d frames into %s ...", frames, out)

    def drawn(done: int, total: int) -> None:
        _log.info("animate: %d of %d frames drawn", done, total)

    render(trajectory, out, fps, progress=drawn)
    return trajectory
