"""``pendulum_fmu.exact``: the exact solution over numpy arrays, from the FMU's own C code.

The C library ``pendulum_exact`` (``fmu_src/libs/exact_lib/`` of the repository, built by CMake beside
the FMU from the same ``exact.c`` and ``elliptic.c``) is called once per array through
ctypes: no FMU instance, no round trip per point. A large array is split over threads
(``workers``), each running the C code on its chunk with the GIL released. Its theta equals the FMU's
``theta_exact`` bit for bit (same code, same w0 = sqrt(g/L), initial state at t = 0).

Where the library is looked for: ``$PENDULUM_EXACT_LIB``, then the package's
``lib/<platform>/`` (a wheel carries the host's, and the cross-built ones when present),
then the repository's ``build/`` in a source checkout.
"""

from __future__ import annotations

import ctypes
import os
import platform
import sys
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from pendulum_fmu.errors import BuildError
from pendulum_fmu.fmu.build import DEFAULT_BUILD_DIR

if TYPE_CHECKING:
    from _ctypes import CFuncPtr

ABI = 2
"""The interface version this module speaks (``PENDULUM_EXACT_ABI`` in the C header)."""
PACKAGE_LIB_DIR = Path(__file__).resolve().parents[1] / "lib"


def platform_folder() -> tuple[str, str]:
    """The FMI-style platform folder and the library file name of this machine.

    Returns
    -------
    tuple of str
        (``linux64``, ``libpendulum_exact.so``), (``win64``, ``pendulum_exact.dll``) or
        (``darwin64``, ``libpendulum_exact.dylib``); other machines get a descriptive folder
        name, for which no library is shipped.
    """
    machine = platform.machine().lower()
    bits64 = machine in ("x86_64", "amd64", "arm64", "aarch64")
    if sys.platform.startswith("win"):
        return ("win64" if bits64 else f"win-{machine}"), "pendulum_exact.dll"
    if sys.platform == "darwin":
        return "darwin64", "libpendulum_exact.dylib"
    folder = "linux64" if machine in ("x86_64", "amd64") else f"linux-{machine}"
    return folder, "libpendulum_exact.so"


def c_address(function: CFuncPtr) -> int:
    """The C address of a ctypes function of a loaded library (0 for a NULL pointer)."""
    return ctypes.cast(function, ctypes.c_void_p).value or 0


def library_file(stem: str) -> str:
    """The file name of the shipped library ``stem`` (``pendulum_exact``, ``pendulum_driver``) here."""
    _, exact_name = platform_folder()
    return exact_name.replace("pendulum_exact", stem)


def find_library(stem: str) -> Path | None:
    """The shipped library ``stem`` for this platform, or None when there is none.

    Looked for in ``$<STEM>_LIB`` (``$PENDULUM_EXACT_LIB``, ``$PENDULUM_DRIVER_LIB``), then the
    package's ``lib/<platform>/``, then the checkout's ``build/``.

    Raises
    ------
    BuildError
        If the environment variable names no file.
    """
    variable = f"{stem.upper()}_LIB"
    override = os.environ.get(variable)
    if override:
        if not Path(override).is_file():
            raise BuildError(f"${variable} names no file: {override!r}")
        return Path(override)
    folder, _ = platform_folder()
    for candidate in (PACKAGE_LIB_DIR / folder / library_file(stem), DEFAULT_BUILD_DIR / library_file(stem)):
        if candidate.is_file():
            return candidate
    return None


def load_library(path: Path, stem: str, abi: int) -> ctypes.CDLL:
    """Load the library at ``path`` and check that ``<stem>_abi()`` returns ``abi``.

    Raises
    ------
    BuildError
        With one line, when it cannot be loaded or speaks another interface.
    """
    try:
        library = ctypes.CDLL(str(path))
    except OSError as error:
        raise BuildError(f"cannot load {path}: {error}") from None
    version = getattr(library, f"{stem}_abi")
    version.restype = ctypes.c_int
    if version() != abi:
        raise BuildError(f"{path} speaks interface {version()}, this package {abi}: rebuild it")
    return library


def library_path() -> Path:
    """The ``pendulum_exact`` library for this platform.

    Raises
    ------
    BuildError
        With one line, when no library for this platform is installed or built.
    """
    path = find_library("pendulum_exact")
    if path is None:
        raise BuildError(f"no pendulum_exact library for this platform ({platform_folder()[0]}): this installation "
                         f"ships none; build it with cmake (target pendulum_exact) and set PENDULUM_EXACT_LIB")
    return path


@lru_cache(maxsize=1)
def _library() -> ctypes.CDLL:
    """Load the library once and declare the signature of ``pendulum_exact_many``."""
    library = load_library(library_path(), "pendulum_exact", ABI)
    pointer = np.ctypeslib.ndpointer(dtype=np.float64, flags="C_CONTIGUOUS")
    library.pendulum_exact_many.restype = ctypes.c_size_t
    strides = np.ctypeslib.ndpointer(dtype=np.uintp, flags="C_CONTIGUOUS")
    library.pendulum_exact_many.argtypes = [ctypes.c_size_t] + [pointer] * 5 + [strides] + [pointer] * 2
    library.pendulum_exact_times.restype = ctypes.c_size_t
    library.pendulum_exact_times.argtypes = [ctypes.c_double] * 4 + [ctypes.c_size_t] + [pointer] * 3
    return library


MIN_POINTS_PER_THREAD = 65_536
"""The default splits an array over threads only in chunks of at least this many points
(about 15 ms of work: a thread's start and hand-over cost microseconds)."""
MAX_THREADS = 64
"""The default uses at most this many threads."""
ALIGN = 64
"""Chunk boundaries fall on multiples of this many points."""


def usable_cores() -> int:
    """The cores this process may run on (its CPU affinity where the platform has one)."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return max(1, os.cpu_count() or 1)


def thread_count(points: int, workers: int | None = None) -> int:
    """Threads :func:`exact` uses for ``points`` points.

    Parameters
    ----------
    points : int
        Points to evaluate.
    workers : int, optional
        Threads asked for (at most one per point); default the usable cores, at most
        :data:`MAX_THREADS`, and one per :data:`MIN_POINTS_PER_THREAD` points (1 for small arrays).

    Returns
    -------
    int
        At least 1.

    Raises
    ------
    ValueError
        If ``workers`` is given and is not a positive integer.
    """
    if workers is not None:
        if isinstance(workers, bool) or not isinstance(workers, int) or workers < 1:
            raise ValueError(f"workers must be a positive integer, got {workers!r}")
        return max(1, min(workers, points))
    return max(1, min(usable_cores(), MAX_THREADS, points // MIN_POINTS_PER_THREAD))


def chunks(points: int, threads: int) -> list[tuple[int, int]]:
    """``threads`` contiguous ranges ``[start, stop)`` covering ``points``, near-equal, aligned to :data:`ALIGN`."""
    bounds = [min(points, (points * k // threads) // ALIGN * ALIGN) for k in range(threads)] + [points]
    return [(a, b) for a, b in zip(bounds, bounds[1:], strict=False) if b > a]


_pool: list[ThreadPoolExecutor] = []
# a forked child inherits the pool without its threads: it makes its own
os.register_at_fork(after_in_child=_pool.clear)


def _in_threads(evaluate: Callable[[int, int], object], points: int, threads: int) -> None:
    """Call ``evaluate(start, stop)`` over :func:`chunks`, the first in this thread, the others in a pool.

    The C calls release the GIL (ctypes does for a ``CDLL``), so the chunks run at once.
    """
    parts = chunks(points, threads)
    if len(parts) == 1:
        evaluate(*parts[0])
        return
    if not _pool:
        _pool.append(ThreadPoolExecutor(max_workers=MAX_THREADS, thread_name_prefix="pendulum-exact"))
    futures = [_pool[0].submit(evaluate, start, stop) for start, stop in parts[1:]]
    evaluate(*parts[0])
    for future in futures:
        future.result()


def exact(theta0: ArrayLike, omega0: ArrayLike, L: ArrayLike, g: ArrayLike,
          t: ArrayLike, workers: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    """theta(t) and omega(t) of the pendulum theta'' + (g/L) sin(theta) = 0, exactly.

    The inputs broadcast against each other like numpy arrays; the initial state
    (theta0, omega0) is posed at t = 0. Every regime: libration, separatrix, rotation
    (theta winds up continuously).

    Parameters
    ----------
    theta0 : array_like
        Initial angle from the downward vertical, rad.
    omega0 : array_like
        Initial angular velocity, rad/s.
    L : array_like
        Length, m (> 0).
    g : array_like
        Gravitational acceleration, m/s^2 (> 0).
    t : array_like
        Times, s.
    workers : int, optional
        Threads to split the points over (each point is computed alone, so the values are
        the same bit for bit on any number). Default: one per usable core, at most 64,
        and one per 65536 points, so a small array is evaluated in the calling thread.

    Returns
    -------
    theta, omega : numpy.ndarray
        Arrays of the broadcast shape, rad and rad/s; NaN where an input was refused
        (not finite, L or g not > 0).

    Raises
    ------
    BuildError
        When no ``pendulum_exact`` library for this platform is available.
    ValueError
        If ``workers`` is not a positive integer.

    Examples
    --------
    >>> import numpy as np
    >>> from pendulum_fmu import exact
    >>> theta, omega = exact(np.radians(80.0), 0.0, 1.0, 9.81, np.linspace(0.0, 10.0, 1001))
    """
    library = _library()
    state = [np.asarray(x, dtype=np.float64) for x in (theta0, omega0, L, g)]
    if all(x.ndim == 0 for x in state):  # one problem over many times: no copies of the state
        shape = np.shape(t)
        times = np.ascontiguousarray(t, dtype=np.float64).reshape(-1)
        theta = np.empty(times.size)
        omega = np.empty(times.size)
        values = [float(x) for x in state]
        threads = thread_count(times.size, workers)
        if threads == 1:
            library.pendulum_exact_times(*values, times.size, times, theta, omega)
        else:
            _in_threads(lambda a, b: library.pendulum_exact_times(*values, b - a, times[a:b], theta[a:b], omega[a:b]),
                        times.size, threads)
        return theta.reshape(shape), omega.reshape(shape)
    inputs = [*state, np.asarray(t, dtype=np.float64)]
    shape = np.broadcast_shapes(*(x.shape for x in inputs))
    # a single value goes to C as itself with stride 0, anything else broadcast to a full array
    flat = [np.ascontiguousarray(x, dtype=np.float64).reshape(1) if x.size == 1
            else np.ascontiguousarray(np.broadcast_to(x, shape), dtype=np.float64).reshape(-1) for x in inputs]
    strides = np.array([0 if x.size == 1 else 1 for x in flat], dtype=np.uintp)
    theta = np.empty(shape).reshape(-1)
    omega = np.empty(shape).reshape(-1)

    def part(x: np.ndarray, a: int, b: int) -> np.ndarray:
        return x if x.size == 1 else x[a:b]

    threads = thread_count(theta.size, workers)
    if threads == 1:
        library.pendulum_exact_many(theta.size, *flat, strides, theta, omega)
    else:
        _in_threads(lambda a, b: library.pendulum_exact_many(b - a, *(part(x, a, b) for x in flat), strides,
                                                             theta[a:b], omega[a:b]),
                    theta.size, threads)
    return theta.reshape(shape), omega.reshape(shape)
