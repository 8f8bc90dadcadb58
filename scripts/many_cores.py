"""Print the sweep's and exact()'s scaling tables on this machine, from the installed ``pendulum-fmu`` package.

Run by ``scripts/measure-many-cores.sh`` (which builds and installs the wheel first) with the
installed package's interpreter; the worker counts go up to the usable cores, doubling. Each
table is printed as Markdown with the machine and the command behind it:

1. ``pendulum-fmu bench sweep --loop c`` with runs of about 1 ms (10 periods) and about 7 ms
   (100 periods): runs/s, speed-up over 1 worker, efficiency, scheduler cost per task;
2. ``exact()`` over 16 million times with ``workers`` = 1, 2, 4, ...: ns a point and speed-up,
   each result compared bit for bit with one thread's;
3. ``exact()`` with one state per point against its C call (the wrapper's share);
4. ``pendulum-fmu sweep -a 1:179:4000 -j N``: wall time against the sweep's own compute time,
   and whether anything was logged on stderr.

``--quick`` shrinks every size (a check of the script, not a measurement).
"""

from __future__ import annotations

import argparse
import math
import os
import platform
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np


def machine() -> str:
    """The CPU model and the core counts."""
    import psutil

    model = platform.processor() or platform.machine()
    cpuinfo = Path("/proc/cpuinfo")
    if cpuinfo.is_file():
        names = re.findall(r"^model name\s*:\s*(.+)$", cpuinfo.read_text(), re.MULTILINE)
        model = names[0] if names else model
    usable = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return (f"{model}; {psutil.cpu_count(logical=False)} physical cores, {psutil.cpu_count(logical=True)} logical, "
            f"{usable} usable; Python {platform.python_version()}, {platform.system()} {platform.release()}")


def counts(limit: int) -> list[int]:
    """1, 2, 4, ... up to ``limit``, and ``limit`` itself."""
    values = [1]
    while values[-1] * 2 <= limit:
        values.append(values[-1] * 2)
    return values if values[-1] == limit else [*values, limit]


def command(argv: list[str]) -> str:
    """``argv`` as one would type it."""
    return " ".join(argv)


def bench_sweep(script: str, runs: int, periods: int, workers: list[int], repeat: int) -> None:
    """Table 1: ``bench sweep`` at these worker counts."""
    argv = [script, "bench", "sweep", "--runs", str(runs), "--periods", str(periods), "--loop", "c",
            "--repeat", str(repeat), "--workers", *map(str, workers)]
    done = subprocess.run(argv, capture_output=True, text=True, check=False)
    print(f"\n`{command(['pendulum-fmu', *argv[1:]])}`\n")
    if done.returncode != 0:
        print(f"failed (exit {done.returncode}): {done.stderr.strip().splitlines()[-1:]}")
        return
    found = re.findall(r"^bench_sweep loop=c workers=(\d+) runs=\d+ rate=([0-9.]+) per_worker=[0-9.]+ "
                       r"task_ms=([0-9.]+)", done.stdout, re.MULTILINE)
    rates = {int(w): (float(rate), float(task)) for w, rate, task in found}
    print("| workers | runs/s | speed-up | efficiency | scheduler ms/task |\n|---|---|---|---|---|")
    base = rates[workers[0]][0]
    for count in workers:
        rate, task = rates[count]
        print(f"| {count} | {rate:.0f} | {rate / base:.2f} | {rate / base * workers[0] / count:.2f} | {task:.2f} |")
    cores = re.search(r"^cores: .*$", done.stdout, re.MULTILINE)
    if cores:
        print(f"\n({cores.group(0)})")


def exact_threads(points: int, workers: list[int], repeat: int) -> None:
    """Table 2: ``exact()`` over ``points`` times, split over threads."""
    from pendulum_fmu import exact

    times = np.random.default_rng(27).uniform(0.0, 100.0, points)
    reference = exact(1.4, 0.0, 1.0, 9.81, times, workers=1)
    print(f"\n`exact(1.4, 0.0, 1.0, 9.81, t, workers=N)`, t: {points:,} random times; best of {repeat}\n")
    print("| workers | ns a point | speed-up | same bits as 1 thread |\n|---|---|---|---|")
    base = 0.0
    for count in workers:
        best = math.inf
        for _ in range(repeat):
            start = time.perf_counter()
            values = exact(1.4, 0.0, 1.0, 9.81, times, workers=count)
            best = min(best, time.perf_counter() - start)
        same = all(a.tobytes() == b.tobytes() for a, b in zip(reference, values))
        base = base or best
        print(f"| {count} | {1e9 * best / points:.2f} | {base / best:.2f} | {'yes' if same else 'NO'} |")
    start = time.perf_counter()
    exact(1.4, 0.0, 1.0, 9.81, times)
    seconds = time.perf_counter() - start
    print(f"\nthe default (workers=None): {1e9 * seconds / points:.2f} ns a point, {base / seconds:.2f}x one thread")


def exact_wrapper(points: int, repeat: int) -> None:
    """Table 3: one state per point, ``exact()`` against its C call (CPU time, one thread)."""
    from pendulum_fmu.bench.exact import wrapper_overhead

    c_best, wrapped_best, _ = wrapper_overhead(points, repeat)
    print(f"\none state per point, {points:,} points, one thread, best of {repeat} (CPU time)\n")
    print("| `pendulum_exact_many` (C) | `exact()` | the wrapper adds |\n|---|---|---|")
    print(f"| {1e9 * c_best / points:.0f} ns | {1e9 * wrapped_best / points:.0f} ns | "
          f"{100 * (wrapped_best / c_best - 1):+.1f} % |")


def sweep_wall(script: str, amplitudes: int, workers: list[int]) -> None:
    """Table 4: ``pendulum-fmu sweep`` wall time against its compute time, and its stderr."""
    print(f"\n`pendulum-fmu sweep -a 1:179:{amplitudes} -j N -q --no-plots -o DIR`\n")
    print("| workers | wall s | compute s (its own line) | stderr lines |\n|---|---|---|---|")
    for count in workers:
        with tempfile.TemporaryDirectory() as folder:
            argv = [script, "sweep", "-a", f"1:179:{amplitudes}", "-j", str(count), "-q", "--no-plots",
                    "-o", str(Path(folder) / "out")]
            start = time.perf_counter()
            done = subprocess.run(argv, capture_output=True, text=True, check=False)
            wall = time.perf_counter() - start
        found = re.search(r"in ([0-9.]+) s on", done.stdout)
        compute = found.group(1) if found else f"exit {done.returncode}"
        print(f"| {count} | {wall:.2f} | {compute} | {len([x for x in done.stderr.splitlines() if x.strip()])} |")


def main() -> int:
    """Parse the options and print the tables."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small sizes: check the script, measure nothing")
    parser.add_argument("--max-workers", type=int, default=0, help="highest worker count (default: usable cores)")
    args = parser.parse_args()
    script = str(Path(sys.executable).parent / "pendulum-fmu")
    usable = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    workers = counts(args.max_workers or usable)
    quick = args.quick
    print(f"# scaling tables\n\nmachine: {machine()}\n")
    bench_sweep(script, 100 if quick else 1600, 10, workers, 1 if quick else 3)
    bench_sweep(script, 40 if quick else 800, 100, workers, 1 if quick else 3)
    exact_threads(200_000 if quick else 16_000_000, workers, 1 if quick else 3)
    exact_wrapper(100_000 if quick else 2_000_000, 2 if quick else 5)
    sweep_wall(script, 200 if quick else 4000, sorted({1, workers[-1]}))
    return 0


if __name__ == "__main__":
    try:
        raise SystemExit(main())
    except KeyboardInterrupt:
        print("\nmany_cores.py: interrupted", file=sys.stderr)
        raise SystemExit(130) from None
