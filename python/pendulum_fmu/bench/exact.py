"""Benchmark: the exact solution per point, in C, from Python through ``pendulum_fmu.exact``,
and with scipy's ``ellipj``, all over the same number of points in the same run.

Two workloads, each timed in interleaved rounds (best and median), in processor time of the
process (``time.process_time``; the C benchmark's ``clock()``), so that waiting for a core on a
shared machine does not count:

- one state, many times: an evaluation per point (C scalar loop, C batch, GSL, Python,
  scipy);
- a new state per point (a phase portrait, an ensemble): ``pendulum_exact_init`` (from w0)
  and one evaluation in C, GSL's ``gsl_sf_ellint_Kcomp_e`` + ``gsl_sf_elljac_e`` per state
  in C, :func:`pendulum_fmu.exact` over arrays of release angles (a
  ``pendulum_exact_init_gl`` set-up from g and L per angle, as the FMU's), and scipy's
  ``ellipkm1`` + ``ellipj`` over the same arrays.

- C: the test program ``tests/c/bench_exact`` of a CMake build (``pendulum_exact_eval`` in a
  loop), run only when the caller hands it in (``bash scripts/bench.sh exact`` builds it and
  passes it as ``--exe``); an installed package carries none and looks for none, and these
  columns are then left out;
- Python: :func:`pendulum_fmu.exact` over a numpy array of times (one call into the C library
  ``pendulum_exact``, the same code);
- scipy: from the same number of times, u = w0 t + K(m) (release from rest),
  ``scipy.special.ellipj(u, m)``, then theta = 2 arctan2(k sn, dn) and omega = 2 k w0 cn.
"""

from __future__ import annotations

import math
import subprocess
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.special import ellipj, ellipkm1

from pendulum_fmu.errors import SimulationError

DEFAULT_AMPLITUDES_DEG: tuple[float, ...] = (10.0, 90.0, 170.0, 179.9999)
"""Release angles (degrees, from rest, w0 = 1) benchmarked by default."""


@dataclass(frozen=True)
class BestMedian:
    """Best and median of one timing over interleaved rounds, ns per point (NaN: not measured)."""

    best: float
    median: float

    @staticmethod
    def of(samples: list[float]) -> BestMedian:
        """The best and the median of ``samples`` (NaN, NaN when there are none)."""
        if not samples:
            return BestMedian(math.nan, math.nan)
        return BestMedian(min(samples), float(np.median(samples)))


NOT_MEASURED = BestMedian(math.nan, math.nan)


@dataclass(frozen=True)
class CTimings:
    """The C benchmark's figures for one amplitude (ns per point, best and median).

    Attributes
    ----------
    eval : BestMedian
        ``pendulum_exact_eval`` in a loop.
    batch : BestMedian
        ``pendulum_exact_eval_many`` (lock-step) over the same times.
    gsl : BestMedian
        GSL's ``gsl_sf_elljac_e`` plus atan2 (NaN when the benchmark was built without GSL).
    init : BestMedian
        ``pendulum_exact_init`` (from w0 = 1) for a new release angle and one evaluation.
    gsl_init : BestMedian
        GSL for the same new states: ``gsl_sf_ellint_Kcomp_e`` and one ``gsl_sf_elljac_e`` plus
        atan2 (NaN without GSL, or from an older program that did not time it).
    init_batch : BestMedian
        The same new states set up and evaluated in blocks by ``pendulum_exact_once_gl_many``
        (what :func:`pendulum_fmu.exact` calls with a state per point; NaN from an older
        program).
    """

    eval: BestMedian
    batch: BestMedian
    gsl: BestMedian
    init: BestMedian
    gsl_init: BestMedian = NOT_MEASURED
    init_batch: BestMedian = NOT_MEASURED


NO_C = CTimings(NOT_MEASURED, NOT_MEASURED, NOT_MEASURED, NOT_MEASURED)


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
        ns per point of ``pendulum_exact_eval`` (theta and omega) in C, best over the rounds;
        NaN without the C benchmark.
    python_ns : float
        ns per point of :func:`pendulum_fmu.exact` over a numpy array, best over the rounds.
    scipy_ns : float
        ns per point of the scipy pipeline, best over the rounds.
    c : CTimings
        All figures of the C benchmark (best and median).
    python : BestMedian
        :func:`pendulum_fmu.exact`, one state over many times.
    scipy : BestMedian
        scipy, one state over many times.
    python_states : BestMedian
        :func:`pendulum_fmu.exact` with a new state per point.
    scipy_states : BestMedian
        scipy's ``ellipkm1`` + ``ellipj`` with a new state per point.
    """

    amplitude_deg: float
    n: int
    c_ns: float
    python_ns: float
    scipy_ns: float
    c: CTimings = NO_C
    python: BestMedian = NOT_MEASURED
    scipy: BestMedian = NOT_MEASURED
    python_states: BestMedian = NOT_MEASURED
    scipy_states: BestMedian = NOT_MEASURED

    @property
    def ratio(self) -> float:
        """C time over scipy time per point."""
        return self.c_ns / self.scipy_ns


def run_c_benchmark(executable: Path, n: int, amplitudes_deg: tuple[float, ...]) -> dict[float, CTimings]:
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
    dict of float to CTimings
        The figures, keyed by the amplitude as the program printed it. An older program that
        prints only ``ns_per_eval`` gives that as the best eval time and NaN elsewhere.
    """
    command = [str(executable), str(n), *(repr(a) for a in amplitudes_deg)]
    try:
        completed = subprocess.run(command, capture_output=True, text=True, check=True)
    except (OSError, subprocess.CalledProcessError) as error:
        raise SimulationError(f"the C benchmark {executable} failed: {error}") from None
    timings: dict[float, CTimings] = {}
    for line in completed.stdout.splitlines():
        fields = line.split()
        if not fields or fields[0] != "bench_exact":
            continue
        values = dict(field.split("=", 1) for field in fields[1:])

        def pair(kind: str, values: dict[str, str] = values) -> BestMedian:
            return BestMedian(float(values.get(f"{kind}_best", "nan")), float(values.get(f"{kind}_median", "nan")))

        eval_timing = pair("eval") if "eval_best" in values else BestMedian(float(values["ns_per_eval"]), math.nan)
        timings[float(values["amplitude_deg"])] = CTimings(eval_timing, pair("batch"), pair("gsl"), pair("init"),
                                                           pair("gsl_init"), pair("once"))
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
        start = time.process_time()
        u = w0 * times + quarter
        sn, cn, dn, _ = ellipj(u, m)
        theta = 2.0 * np.arctan2(k * sn, dn)
        omega = (2.0 * k * w0) * cn
        best = min(best, time.process_time() - start)
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
        start = time.process_time()
        exact(theta0, 0.0, 1.0, 1.0, times)
        best = min(best, time.process_time() - start)
    return 1e9 * best / n


def release_angles(amplitude_deg: float, n: int) -> np.ndarray:
    """n different release angles around ``amplitude_deg`` (rad): theta0 (1 + 1e-9 j), j < 1024."""
    return math.radians(amplitude_deg) * (1.0 + 1e-9 * (np.arange(n) % 1024))


def time_library_states(amplitude_deg: float, n: int, seed: int = 1) -> float:
    """ns per point of :func:`pendulum_fmu.exact` with a new state per point (one timing).

    The release angles of :func:`release_angles` (from rest, L = g = 1), each evaluated once
    at a random time within 50 periods.
    """
    from pendulum_fmu.fmu.library import exact

    theta0 = release_angles(amplitude_deg, n)
    quarter = float(ellipkm1(math.cos(math.radians(amplitude_deg) / 2.0) ** 2))
    times = np.random.default_rng(seed).uniform(0.0, 50.0 * 4.0 * quarter, n)
    start = time.process_time()
    exact(theta0, 0.0, 1.0, 1.0, times)
    return 1e9 * (time.process_time() - start) / n


def wrapper_overhead(points: int, rounds: int) -> tuple[float, float, bool]:
    """:func:`pendulum_fmu.exact` with one state per point against the C call it wraps.

    The release angles of :func:`release_angles` around 80 degrees (from rest, L = g = 1), each
    at a random time within 100 s; the C call is ``pendulum_exact_many`` on arrays already
    contiguous, the wrapper is ``exact()`` given the scalars and the two arrays (what it
    broadcasts and copies is its own cost), on one thread.

    Parameters
    ----------
    points : int
        The number of states, one time each.
    rounds : int
        Interleaved rounds of the two; the best of each counts.

    Returns
    -------
    tuple of (float, float, bool)
        The best processor time (``time.process_time``, s) of the C call and of ``exact()``,
        and whether the two gave the same bits.
    """
    from pendulum_fmu.fmu.library import _library, exact

    library = _library()
    theta0 = release_angles(80.0, points)
    times = np.random.default_rng(27).uniform(0.0, 100.0, points)
    arrays = [theta0, np.zeros(points), np.ones(points), np.ones(points), times]
    theta, omega = np.empty(points), np.empty(points)
    c_best = wrapped_best = math.inf
    same = True
    for _ in range(rounds):
        start = time.process_time()
        library.pendulum_exact_many(points, *arrays, np.ones(5, dtype=np.uintp), theta, omega)
        c_best = min(c_best, time.process_time() - start)
        start = time.process_time()
        values = exact(theta0, 0.0, 1.0, 1.0, times, workers=1)
        wrapped_best = min(wrapped_best, time.process_time() - start)
        same = same and values[0].tobytes() == theta.tobytes() and values[1].tobytes() == omega.tobytes()
    return c_best, wrapped_best, same


def time_scipy_states(amplitude_deg: float, n: int, seed: int = 1) -> float:
    """ns per point of scipy with a new state per point (one timing).

    The same states and times as :func:`time_library_states`: per point m = sin^2(theta0/2),
    K = ``ellipkm1(cos^2(theta0/2))``, u = t + K, ``ellipj(u, m)``, theta = 2 arctan2(k sn, dn),
    omega = 2 k cn.
    """
    theta0 = release_angles(amplitude_deg, n)
    quarter = float(ellipkm1(math.cos(math.radians(amplitude_deg) / 2.0) ** 2))
    times = np.random.default_rng(seed).uniform(0.0, 50.0 * 4.0 * quarter, n)
    start = time.process_time()
    half = 0.5 * theta0
    k = np.sin(half)
    m = k * k
    quarters = ellipkm1(np.cos(half) ** 2)
    sn, cn, dn, _ = ellipj(times + quarters, m)
    theta = 2.0 * np.arctan2(k * sn, dn)
    omega = 2.0 * k * cn
    elapsed = time.process_time() - start
    del theta, omega
    return 1e9 * elapsed / n


def run(executable: Path | None, n: int, amplitudes_deg: tuple[float, ...], rounds: int = 5) -> list[BenchResult]:
    """Run every timing per amplitude.

    The C benchmark runs first (its own interleaved rounds); then the Python-side timings
    (the library and scipy, one state over many times and a new state per point) run in
    ``rounds`` interleaved rounds, each timing every kind and amplitude once.

    Parameters
    ----------
    executable : Path or None
        The ``bench_exact`` program; None leaves the C figures out (NaN).
    n : int
        Number of points per amplitude.
    amplitudes_deg : tuple of float
        Release angles in degrees.
    rounds : int
        Interleaved rounds of the Python-side timings.

    Returns
    -------
    list of BenchResult
        One result per amplitude, in the given order.
    """
    c_timings = run_c_benchmark(executable, n, amplitudes_deg) if executable is not None else {}
    kinds: dict[str, Callable[..., float]]
    kinds = {"python": time_library, "scipy": time_scipy, "python_states": time_library_states,
             "scipy_states": time_scipy_states}
    samples: dict[tuple[float, str], list[float]] = {(a, k): [] for a in amplitudes_deg for k in kinds}
    for _ in range(rounds):
        for amplitude in amplitudes_deg:
            for kind, timer in kinds.items():
                samples[(amplitude, kind)].append(timer(amplitude, n, 1) if kind in ("python", "scipy")
                                                  else timer(amplitude, n))
    results = []
    for amplitude in amplitudes_deg:
        c = c_timings.get(float(f"{amplitude:.10g}"), NO_C)
        timing = {kind: BestMedian.of(samples[(amplitude, kind)]) for kind in kinds}
        results.append(BenchResult(amplitude, n, c.eval.best, timing["python"].best, timing["scipy"].best, c,
                                   timing["python"], timing["scipy"], timing["python_states"],
                                   timing["scipy_states"]))
    return results
