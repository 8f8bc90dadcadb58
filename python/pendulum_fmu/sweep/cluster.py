"""Dask for a sweep: a client on a local cluster or a running scheduler, and the runs dealt out to it."""

from __future__ import annotations

import logging
import math
import signal
import sys
import time
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pendulum_fmu import interrupt
from pendulum_fmu.errors import UsageError
from pendulum_fmu.sweep.grid import SweepPoint

if TYPE_CHECKING:
    from distributed import Client

TASKS_PER_THREAD = 8
MAX_BATCH = 64
POLL_SECONDS = 0.02
"""How often the client looks for finished tasks and for Ctrl-C."""


@contextmanager
def dask_client(scheduler: str | None = None, workers: int = 2) -> Iterator[Client]:
    """A Dask client: on ``scheduler`` if given, else on a new local cluster of processes.

    Parameters
    ----------
    scheduler : str, optional
        Address of a running scheduler (``tcp://host:port``).
    workers : int
        Worker processes of the local cluster (one thread each: fmpy's loop holds the GIL).

    Yields
    ------
    distributed.Client
        Connected, with at least one worker.

    Raises
    ------
    UsageError
        If the scheduler cannot be reached or has no worker.
    """
    from distributed import Client, LocalCluster

    if scheduler is None:
        # Ctrl-C at a terminal goes to the whole process group: the worker processes start with
        # SIGINT ignored (inherited through exec), so only this process sees it and shuts them down.
        previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
        try:
            cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                                   silence_logs=logging.ERROR)
        finally:
            signal.signal(signal.SIGINT, previous)
        client = None
        interrupted = False
        try:
            with interrupt.deferred_interrupt():  # see execute: no interrupt inside the client's calls
                client = Client(cluster)
            yield client
        except KeyboardInterrupt:
            interrupted = True
            quiet_shutdown()
            raise
        finally:
            if client is not None:
                client.close(timeout=2 if interrupted else 10)
            cluster.close(timeout=3 if interrupted else 30)
            if interrupted:
                stop_worker_processes()
        return
    try:
        client = Client(scheduler, timeout="10s")
    except (OSError, TimeoutError) as error:
        raise UsageError("--scheduler", f"cannot reach a Dask scheduler at {scheduler}: {error}") from None
    try:
        try:
            client.wait_for_workers(1, timeout=30)
        except TimeoutError:
            raise UsageError("--scheduler", f"the scheduler at {scheduler} has no worker (waited 30 s)") from None
        yield client
    finally:
        client.close()


def quiet_shutdown() -> None:
    """Silence Dask's loggers: after an interrupt, closing the cluster logs only noise."""
    for name in ("distributed", "tornado", "asyncio"):
        logging.getLogger(name).setLevel(logging.CRITICAL + 1)


def stop_worker_processes(grace: float = 1.0) -> None:
    """Terminate (then kill) any child process the local cluster left behind after an interrupt."""
    import psutil

    children = psutil.Process().children(recursive=True)
    for child in children:
        try:
            child.terminate()
        except psutil.NoSuchProcess:
            pass
    _, alive = psutil.wait_procs(children, timeout=grace)
    for child in alive:
        try:
            child.kill()
        except psutil.NoSuchProcess:
            pass


def worker_threads(client: Client) -> int:
    """Total worker threads behind a client."""
    return max(1, sum(client.nthreads().values()))


def batches(points: Sequence[SweepPoint], threads: int, batch_size: int | None = None) -> list[list[SweepPoint]]:
    """Split points into tasks of about equal cost: about 8 per worker thread, at most 64 runs each.

    The points are dealt out like cards (task i gets points i, i + n, i + 2n, ...), so each
    task holds amplitudes from the whole range, costs about the same as the others, and the
    last tasks of a sweep finish together instead of one straggler holding it up.

    Parameters
    ----------
    points : sequence of SweepPoint
        The runs.
    threads : int
        Worker threads that will run them.
    batch_size : int, optional
        Runs per task instead of the default.

    Returns
    -------
    list of list of SweepPoint
        Every point exactly once; the tasks' sizes differ by at most one.
    """
    if not points:
        return []
    size = batch_size or MAX_BATCH
    tasks = max(math.ceil(len(points) / size), 1 if batch_size else min(len(points), TASKS_PER_THREAD * threads))
    return [list(points[i::tasks]) for i in range(tasks)]


def execute(client: Client, fmu: Path, points: Sequence[SweepPoint],
            on_rows: Callable[[list[dict[str, Any]]], None] = lambda rows: None, progress: bool = True,
            batch_size: int | None = None) -> float:
    """Run points on the client's workers; hand each finished batch's rows to ``on_rows``.

    Parameters
    ----------
    client : distributed.Client
        Connected client.
    fmu : Path
        The FMU, sent to every worker once.
    points : sequence of SweepPoint
        The runs.
    on_rows : callable
        Called in the client with every batch's rows as it finishes (any order).
    progress : bool
        Show a progress bar (runs done, rate, time left) on stderr.
    batch_size : int, optional
        Runs per task (default: about 8 tasks per worker thread, at most 64 runs each).

    Returns
    -------
    float
        Seconds from the first submission to the last result.
    """
    from distributed import as_completed
    from tqdm import tqdm

    from pendulum_fmu.sweep.worker import run_points, warm

    data = fmu.read_bytes()
    # Ctrl-C only sets a flag (deferred_interrupt) and the loop below raises it between results:
    # a KeyboardInterrupt raised inside one of the client's blocking calls breaks Dask's own
    # clean-up (distributed 2026.8 then logs a NameError traceback from its event loop thread).
    with interrupt.deferred_interrupt():
        client.run(warm, data)  # every worker loads the FMU now, not inside the timed first task
        # A key of its own (hash=False): a second sweep on the same client must not reuse the key
        # of the first one's data, which the scheduler may be releasing at that moment.
        shared = client.scatter(data, broadcast=True, hash=False)
        interrupt.check()
        start = time.perf_counter()
        futures = [client.submit(run_points, shared, batch, pure=False)
                   for batch in batches(points, worker_threads(client), batch_size)]
        # with_results: the client's event loop fetches each result; this thread only polls.
        finished = as_completed(futures, with_results=True)
        bar = tqdm(total=len(points), unit="run", desc="sweep", disable=not progress, file=sys.stderr,
                   dynamic_ncols=True, smoothing=0.05)
        try:
            while not finished.is_empty():
                interrupt.check()
                if not finished.has_ready():
                    time.sleep(POLL_SECONDS)
                    continue
                _, rows = next(finished)  # ready: returns at once, or raises the task's error
                on_rows(rows)
                bar.update(len(rows))
        except BaseException:
            client.cancel(futures)
            raise
        finally:
            bar.close()
    return time.perf_counter() - start
