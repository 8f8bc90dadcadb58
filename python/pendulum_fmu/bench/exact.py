"""Benchmark: the exact solution per point, in C, from Python through ``pendulum_fmu.exact``,
and with scipy's ``ellipj``, all over the same number of points in the same run.

- C: the executable ``tests/c/bench_exact`` of a CMake build (``pendulum_exact_eval`` in a
  loop); a pip-installed package has none, and this column is then left out;
- Python: :func:`pendulum_fmu.exact` over a numpy array of times (one call into the C library
  ``pendulum_exact``, the same code);
- scipy: from the same number of times, u = w0 t + K(m) (release from rest),
  ``scipy.special.ellipj(u, m)``, then theta = 2 arctan2(k sn, dn) and omega = 2 k w0 cn.
"""

from __future__ import annotations

import math
import subprocess
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.special import ellipj, ellipkm1

from pendulum_fmu.errors import SimulationError
from pendulum_fmu.fmu.build import DEFAULT_BUILD_DIR

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
        ns per point of ``pendulum_exact_eval`` (theta and omega) in C, best of three; NaN
        without the C benchmark.
    python_ns : float
        ns per point of :func:`pendulum_fmu.exact` over a numpy array, best of three.
    scipy_ns : float
        ns per point of the scipy pipeline, best of three.
    """

    amplitude_deg: float
    n: int
    c_ns: float
    python_ns: float
    scipy_ns: float

    @property
    def ratio(self) -> float:
        """C time over scipy time per point."""
        return self.c_ns / self.scipy_ns


def find_bench_executable(build_dir: Path = DEFAULT_BUILD_DIR) -> Path | None:
    """Locate the ``bench_exact`` executable of a CMake build.

    Parameters
    ----------
    build_dir : Path
        The CMake build folder (default: ``build`` at the repository root).

    Returns
    -------
    Path
        The executable.

    Returns None when there is none (a pip-installed package has no C benchmark).
    """
    for candidate in (build_dir / "tests" / "c" / "bench_exact", build_dir / "bench_exact"):
        if candidate.is_file():
            return candidate
    return None


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
    try:
        completed = subprocess.run(command, capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError) as error:
        raise SimulationError(f"the C benchmark {executable} failed: {error}") from None
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


def time_library(amplitude_deg: float, n: int, repeats: int = 3, seed: int = 1) -> float:
    """ns per point of :func:`pendulum_fmu.exact` (the C library from Python), best of ``repeats``.

    The same times as :func:`time_scipy`: uniform over 50 periods, from rest, w0 = 1.
    """
    from pendulum_fmu.fmu.library import exact

    theta0 = math.radians(amplitude_deg)
    half = theta0 / 2.0
    quarter = float(ellipkm1(math.cos(half) ** 2))
    times = np.random.default_rng(seed).uniform(0.0, 50.0 * 4.0 * quarter, n)
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        exact(theta0, 0.0, 1.0, 1.0, times)
        best = min(best, time.perf_counter() - start)
    return 1e9 * best / n


def run(executable: Path | None, n: int, amplitudes_deg: tuple[float, ...]) -> list[BenchResult]:
    """Run the three timings per amplitude.

    Parameters
    ----------
    executable : Path or None
        The ``bench_exact`` program; None leaves the C column out (NaN).
    n : int
        Number of points per amplitude.
    amplitudes_deg : tuple of float
        Release angles in degrees.

    Returns
    -------
    list of BenchResult
        One result per amplitude, in the given order.
    """
    c_timings = run_c_benchmark(executable, n, amplitudes_deg) if executable is not None else {}
    results = []
    for amplitude in amplitudes_deg:
        c_ns = c_timings.get(float(f"{amplitude:.10g}"), math.nan)
        results.append(BenchResult(amplitude, n, c_ns, time_library(amplitude, n), time_scipy(amplitude, n)))
    return results
