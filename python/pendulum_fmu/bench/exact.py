"""Benchmark: the C exact solution (``tests/c/bench_exact``) against scipy's ``ellipj``.

Runs the C benchmark executable built by CMake and, in the same run, times the same work
done with scipy, vectorised over the same number of points: from N times t, the elliptic
argument u = w0 t + K(m) (release from rest), ``scipy.special.ellipj(u, m)``, then
theta = 2 arctan2(k sn, dn) and omega = 2 k w0 cn. Prints ns per point for both and
the ratio C / scipy, one human-readable line and one ``key=value`` line per amplitude.

Usage::

    python -m pendulum_fmu.bench.exact [--exe build/tests/c/bench_exact] [-n 1000000]
                                       [--amplitudes 10 90 170 179.9999]
"""

from __future__ import annotations

import argparse
import math
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.special import ellipj, ellipkm1

from pendulum_fmu.fmu.build import DEFAULT_BUILD_DIR, REPO_ROOT

DEFAULT_AMPLITUDES_DEG: tuple[float, ...] = (10.0, 90.0, 170.0, 179.9999)
"""Release angles (degrees, from rest, w0 = 1) benchmarked by default."""


@dataclass(frozen=True)
class BenchResult:
    """Timings for one amplitude.

    Attributes
    ----------
    amplitude_deg : float
        Release angle in degrees (omega0 = 0, w0 = 1).
    n : int
        Number of evaluation points.
    c_ns : float
        ns per point of ``pendulum_exact_eval`` (theta and omega), best of three.
    scipy_ns : float
        ns per point of the scipy pipeline, best of three.
    """

    amplitude_deg: float
    n: int
    c_ns: float
    scipy_ns: float

    @property
    def ratio(self) -> float:
        """C time over scipy time per point (the target is <= 0.2)."""
        return self.c_ns / self.scipy_ns


def find_bench_executable(build_dir: Path = DEFAULT_BUILD_DIR) -> Path:
    """Locate the ``bench_exact`` executable of a CMake build.

    Parameters
    ----------
    build_dir : Path
        The CMake build folder (default: ``build`` at the repository root).

    Returns
    -------
    Path
        The executable.

    Raises
    ------
    FileNotFoundError
        If no ``bench_exact`` is found under ``build_dir``.
    """
    for candidate in (build_dir / "tests" / "c" / "bench_exact", build_dir / "bench_exact"):
        if candidate.is_file():
            return candidate
    found = sorted(p for p in build_dir.rglob("bench_exact") if p.is_file())
    if not found:
        raise FileNotFoundError(
            f"no bench_exact under {build_dir}; build it with "
            f"cmake -S {REPO_ROOT} -B {build_dir} && cmake --build {build_dir}"
        )
    return found[0]


def run_c_benchmark(executable: Path, n: int, amplitudes_deg: tuple[float, ...]) -> dict[float, float]:
    """Run the C benchmark and parse its ``bench_exact key=value ...`` lines.

    Parameters
    ----------
    executable : Path
        The ``bench_exact`` program.
    n : int
        Number of fresh times per amplitude.
    amplitudes_deg : tuple of float
        Release angles in degrees.

    Returns
    -------
    dict of float to float
        ns per evaluation, keyed by the amplitude as the program printed it.
    """
    command = [str(executable), str(n), *(repr(a) for a in amplitudes_deg)]
    completed = subprocess.run(command, capture_output=True, text=True, check=True)
    timings: dict[float, float] = {}
    for line in completed.stdout.splitlines():
        fields = line.split()
        if not fields or fields[0] != "bench_exact":
            continue
        values = dict(field.split("=", 1) for field in fields[1:])
        timings[float(values["amplitude_deg"])] = float(values["ns_per_eval"])
    return timings


def time_scipy(amplitude_deg: float, n: int, repeats: int = 3, seed: int = 1) -> float:
    """Time the scipy pipeline for one amplitude.

    Parameters
    ----------
    amplitude_deg : float
        Release angle in degrees (from rest, w0 = 1).
    n : int
        Number of points (times drawn uniformly over 50 periods).
    repeats : int
        The best of this many runs is reported.
    seed : int
        Seed of the random times.

    Returns
    -------
    float
        ns per point of u = w0 t + K, ``ellipj``, theta = 2 arctan2(k sn, dn),
        omega = 2 k w0 cn.
    """
    w0 = 1.0
    half = math.radians(amplitude_deg) / 2.0
    m = math.sin(half) ** 2
    k = math.sqrt(m)
    quarter = float(ellipkm1(math.cos(half) ** 2))    # K(m) from m1: no cancellation
    times = np.random.default_rng(seed).uniform(0.0, 50.0 * 4.0 * quarter / w0, n)
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        u = w0 * times + quarter
        sn, cn, dn, _ = ellipj(u, m)
        theta = 2.0 * np.arctan2(k * sn, dn)
        omega = (2.0 * k * w0) * cn
        best = min(best, time.perf_counter() - start)
        del theta, omega
    return 1e9 * best / n


def run(executable: Path, n: int, amplitudes_deg: tuple[float, ...]) -> list[BenchResult]:
    """Run both benchmarks.

    Parameters
    ----------
    executable : Path
        The ``bench_exact`` program.
    n : int
        Number of points per amplitude.
    amplitudes_deg : tuple of float
        Release angles in degrees.

    Returns
    -------
    list of BenchResult
        One result per amplitude, in the given order.
    """
    c_timings = run_c_benchmark(executable, n, amplitudes_deg)
    results = []
    for amplitude in amplitudes_deg:
        c_ns = c_timings[float(f"{amplitude:.10g}")]
        results.append(BenchResult(amplitude, n, c_ns, time_scipy(amplitude, n)))
    return results


def main(argv: list[str] | None = None) -> int:
    """Command-line entry point: print the timings and the ratios.

    Parameters
    ----------
    argv : list of str, optional
        Arguments (default: ``sys.argv[1:]``).

    Returns
    -------
    int
        0 (the target ratio is reported, not enforced).
    """
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--exe", type=Path, default=None, help="bench_exact executable")
    parser.add_argument("-n", type=int, default=1_000_000, help="points per amplitude")
    parser.add_argument("--amplitudes", type=float, nargs="+", default=list(DEFAULT_AMPLITUDES_DEG),
                        help="release angles in degrees")
    args = parser.parse_args(argv)
    executable = args.exe if args.exe is not None else find_bench_executable()
    results = run(executable, args.n, tuple(args.amplitudes))
    print(f"{'amplitude':>14} {'C ns/pt':>9} {'scipy ns/pt':>12} {'C/scipy':>8}")
    for r in results:
        print(f"{r.amplitude_deg:>10.10g} deg {r.c_ns:>9.1f} {r.scipy_ns:>12.1f} {r.ratio:>8.3f}")
    for r in results:
        print(f"bench_exact_vs_scipy amplitude_deg={r.amplitude_deg:.10g} n={r.n} "
              f"c_ns_per_point={r.c_ns:.3f} scipy_ns_per_point={r.scipy_ns:.3f} ratio={r.ratio:.4f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
