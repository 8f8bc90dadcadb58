"""``pendulum-fmu animate``: the swinging pendulum, numerical and exact side by side (GIF or MP4)."""

from __future__ import annotations

import argparse

from pendulum_fmu.cli.arguments import (
    add_fmu_argument,
    add_method_arguments,
    add_pendulum_arguments,
    integer,
    method_from,
    output_file,
    positive,
    problem_from,
)
from pendulum_fmu.cli.extras import require_extra
from pendulum_fmu.spec import StopUnit

NAME = "animate"
HELP = "the swinging pendulum, numerical and exact side by side, as a GIF or MP4"
DESCRIPTION = """\
Simulate the pendulum and draw it swinging: on the left the FMU's numerical solution, on the
right its exact (Jacobi elliptic) solution, with the bob's recent path, the angle, the time
and the current error. One frame per output point, 960 x 480 pixels; the file type follows
the suffix of --out (.gif through Pillow, .mp4 H.264 through the ffmpeg that imageio-ffmpeg
ships).
"""
EPILOG = """\
examples:
  pendulum-fmu animate --amplitude 90 --out pendulum.gif
  pendulum-fmu animate -a 179 --periods 1 --speed 2 --out top.mp4
  pendulum-fmu animate -a 0 -w 7 --stop-time 4 --out rotation.gif      # it goes over the top
  pendulum-fmu animate -a 80 --solver rk4 --tolerance 1e-2 --periods 4 --out drift.gif
"""


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``animate``."""
    add_pendulum_arguments(parser, default_amplitude="80")
    add_method_arguments(parser)
    group = parser.add_argument_group("film")
    stop = group.add_mutually_exclusive_group()
    stop.add_argument("-p", "--periods", type=positive("periods", 1000), default=None,
                      help="simulated time in exact periods (default 2)")
    stop.add_argument("-T", "--stop-time", type=positive("s", 1e4), default=None, metavar="SECONDS",
                      help="simulated time in seconds")
    group.add_argument("--fps", type=integer(1, 60), default=25, help="frames per second, 1-60 (default 25)")
    group.add_argument("--speed", type=positive("x real time", 100.0), default=1.0,
                       help="simulated seconds per second of film, in (0, 100] (default 1: real time)")
    group.add_argument("-o", "--out", type=output_file(".gif", ".mp4"), default="pendulum.gif",
                       metavar="FILE", help="FILE.gif or FILE.mp4 (default pendulum.gif)")
    add_fmu_argument(parser)


def run(args: argparse.Namespace) -> int:
    """Run ``animate`` with parsed arguments."""
    require_extra("animate", "animate", ("PIL", "imageio_ffmpeg") if args.out.suffix.lower() == ".mp4" else ("PIL",))
    from pendulum_fmu.cli.summary import summary_lines
    from pendulum_fmu.figures.animation import animate

    problem, method = problem_from(args), method_from(args)
    unit: StopUnit = "s" if args.stop_time is not None else "periods"
    stop = args.stop_time if unit == "s" else args.periods or 2.0
    trajectory = animate(args.fmu, problem, method, stop, unit, args.out, args.fps, args.speed)
    print("\n".join(summary_lines(trajectory)))
    print(f"written   {args.out} ({trajectory.result.size} frames at {args.fps} frames/s)")
    return 0
