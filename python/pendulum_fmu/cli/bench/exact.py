"""``pendulum-fmu bench exact``: the command line of :mod:`pendulum_fmu.bench.exact`."""

from __future__ import annotations

import argparse
import math
import os
from pathlib import Path

from pendulum_fmu.cli.arguments import integer

NAME = "exact"
HELP = "the exact solution per point: C, batch, GSL, from Python (pendulum_fmu.exact) and scipy"
DESCRIPTION = """\
Time the exact solution per point over the same number of random times, in interleaved rounds
(best and median): one state over many times in C (the test program tests/c/bench_exact of a
CMake build, given with --exe: the scalar loop, the lock-step batch and GSL's gsl_sf_elljac_e
when it was built with GSL; bash scripts/bench.sh exact builds it and gives it; without --exe
those columns are left out), from Python
through pendulum_fmu.exact (one call into the C library pendulum_exact, the FMU's own code)
and with scipy.special.ellipj plus arctan2, vectorised; and a new state per point (set-up and
one evaluation) in C, with GSL (gsl_sf_ellint_Kcomp_e + gsl_sf_elljac_e), through
pendulum_fmu.exact and with scipy's ellipkm1 + ellipj. Prints ns per point and the ratios side
by side.
"""
EPILOG = """\
examples:
  pendulum-fmu bench exact                          # 10^6 points at 10, 90, 170, 179.9999 deg
  pendulum-fmu bench exact -n 100000 --amplitudes 80 170
  bash scripts/bench.sh exact -n 200000             # in the repository: with the C columns
  pendulum-fmu bench exact --exe build/tests/c/bench_exact
"""


def executable(text: str) -> Path:
    """A type for an existing executable file."""
    path = Path(text)
    if not path.is_file() or not os.access(path, os.X_OK):
        raise argparse.ArgumentTypeError(f"no executable file {text!r}")
    return path


def amplitude(text: str) -> float:
    """A release angle in (0, 180) deg."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number") from None
    if not (math.isfinite(value) and 0.0 < value < 180.0):
        raise argparse.ArgumentTypeError(f"must be an angle in (0, 180) deg, got {text!r}")
    return value


def configure(parser: argparse.ArgumentParser) -> None:
    """Add the options of ``bench exact``."""
    parser.add_argument("--exe", type=executable, default=None, metavar="PATH",
                        help="the C benchmark program tests/c/bench_exact of a CMake build (default: none, "
                             "the C columns left out; bash scripts/bench.sh exact builds it and gives it)")
    parser.add_argument("-n", "--points", type=integer(1, 100_000_000), default=1_000_000, metavar="N",
                        help="points per amplitude, 1-10^8 (default 1000000)")
    parser.add_argument("--amplitudes", type=amplitude, nargs="+", default=[10.0, 90.0, 170.0, 179.9999],
                        metavar="DEG", help="release angles in (0, 180) deg (default 10 90 170 179.9999)")
    parser.add_argument("--rounds", type=integer(1, 100), default=5, metavar="R",
                        help="interleaved rounds of the Python-side timings, 1-100 (default 5)")


GSL_ABSENT = ("GSL: not timed, tests/c/bench_exact was built without GSL "
              "(apt-get install libgsl-dev, then cmake -S . -B build and bash scripts/bench.sh exact)")


def both(x_best: float, x_median: float, y_best: float, y_median: float) -> str:
    """The ratios x/y of the best and of the median figures, as ``best | median``
    (``-`` where a figure is NaN: a column that was not timed)."""
    if any(math.isnan(v) for v in (x_best, x_median, y_best, y_median)):
        return "-"
    return f"{x_best / y_best:6.2f} | {x_median / y_median:<6.2f}"


def figure(value: float, spec: str) -> str:
    """``value`` formatted by ``spec``, or ``-`` where it is NaN (a column that was not timed)."""
    return "-" if math.isnan(value) else format(value, spec)


def run(args: argparse.Namespace) -> int:
    """Run the benchmark and print the table."""
    from pendulum_fmu.bench.exact import run as run_benchmark

    program = args.exe
    if program is None:
        print("bench exact: the C benchmark (tests/c/bench_exact) is not installed with the package: "
              "timing Python and scipy only (the C columns: bash scripts/bench.sh exact in a source checkout)")
    results = run_benchmark(program, args.points, tuple(args.amplitudes), args.rounds)
    with_c = program is not None  # without the C benchmark its columns are left out, not printed as nan
    print("one state, many times (ns per point, best over the rounds):")
    c_head = f" {'C ns/pt':>9}" if with_c else ""
    c_tail = f" {'Python/C':>9} {'C/scipy':>8}" if with_c else f" {'Python/scipy':>13}"
    print(f"{'amplitude':>14}{c_head} {'Python ns/pt':>13} {'scipy ns/pt':>12}{c_tail}")
    for r in results:
        c_value = f" {r.c_ns:>9.1f}" if with_c else ""
        ratios = (f" {r.python_ns / r.c_ns:>9.2f} {r.ratio:>8.3f}" if with_c
                  else f" {r.python_ns / r.scipy_ns:>13.3f}")
        print(f"{r.amplitude_deg:>10.10g} deg{c_value} {r.python_ns:>13.1f} {r.scipy_ns:>12.1f}{ratios}")
    print("time ratios side by side (best | median over the rounds; > 1: the denominator is faster):")
    groups = (f" {'one state, many times':-^47} {'a new state per point':-^35}" if with_c
              else f" {'new state/point':-^15}")
    print(f"{'':>14}{groups}")
    c_heads = f" {'GSL/eval':>15} {'GSL/batch':>15} {'eval/batch':>15} {'scipy/(init+eval)':>19}" if with_c else ""
    print(f"{'amplitude':>14}{c_heads} {'scipy/exact()':>15}")
    for r in results:
        c = r.c
        c_ratios = (f" {both(c.gsl.best, c.gsl.median, c.eval.best, c.eval.median):>15}"
                    f" {both(c.gsl.best, c.gsl.median, c.batch.best, c.batch.median):>15}"
                    f" {both(c.eval.best, c.eval.median, c.batch.best, c.batch.median):>15}"
                    f" {both(r.scipy_states.best, r.scipy_states.median, c.init.best, c.init.median):>19}"
                    if with_c else "")
        print(f"{r.amplitude_deg:>10.10g} deg{c_ratios} "
              f"{both(r.scipy_states.best, r.scipy_states.median, r.python_states.best, r.python_states.median):>15}")
    print("a new state per point: set-up and one evaluation (ns per state, median over the rounds;"
          " C one: init + eval, C batch: pendulum_exact_once_gl_many, as exact() calls it):")
    new_heads = f" {'C one':>8} {'C batch':>8} {'GSL K+elljac':>13}" if with_c else ""
    print(f"{'amplitude':>14}{new_heads} {'exact()':>9} {'scipy':>9}"
          + (f" {'GSL/C one':>10} {'GSL/C batch':>12}" if with_c else "") + f" {'scipy/exact()':>14}")
    for r in results:
        c = r.c
        c_values = (f" {c.init.median:>8.1f} {figure(c.init_batch.median, '.1f'):>8}"
                    f" {figure(c.gsl_init.median, '.1f'):>13}" if with_c else "")
        c_ratios = (f" {figure(c.gsl_init.median / c.init.median, '.2f'):>10}"
                    f" {figure(c.gsl_init.median / c.init_batch.median, '.2f'):>12}" if with_c else "")
        print(f"{r.amplitude_deg:>10.10g} deg{c_values} {r.python_states.median:>9.1f} {r.scipy_states.median:>9.1f}"
              f"{c_ratios} {r.scipy_states.median / r.python_states.median:>14.2f}")
    if with_c and any(math.isnan(r.c.gsl.best) for r in results):
        print(GSL_ABSENT)
    for r in results:
        c_field = f" c_ns_per_point={r.c_ns:.3f}" if with_c else ""
        print(f"bench_exact amplitude_deg={r.amplitude_deg:.10g} n={r.n}{c_field} "
              f"python_ns_per_point={r.python_ns:.3f} scipy_ns_per_point={r.scipy_ns:.3f}")
    for r in results:
        fields = ({"eval": r.c.eval, "batch": r.c.batch, "gsl": r.c.gsl, "init_eval": r.c.init,
                   "init_eval_batch": r.c.init_batch, "gsl_init_eval": r.c.gsl_init} if with_c else {})
        fields.update({"python": r.python, "scipy": r.scipy, "python_states": r.python_states,
                       "scipy_states": r.scipy_states})
        text = " ".join(f"{name}_best={t.best:.3f} {name}_median={t.median:.3f}" for name, t in fields.items())
        print(f"bench_exact_all amplitude_deg={r.amplitude_deg:.10g} n={r.n} {text}")
    return 0
