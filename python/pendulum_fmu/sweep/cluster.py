"""Dask for a sweep: a client on a local cluster or a running scheduler, and the runs dealt out to it."""

from __future__ import annotations

import logging
import math
import signal
import socket
import sys
import threading
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

TASK_SECONDS = 0.1
"""Work per Dask task the sweep aims at (see :func:`task_size`)."""
TASKS_PER_THREAD = 2
"""Fewest tasks per worker thread, when the runs are few."""
POLL_SECONDS = 0.02
"""How often the client looks for finished tasks and for Ctrl-C."""


@contextmanager
def sigint_blocked() -> Iterator[None]:
    """SIGINT held back from this thread (and every thread and process it starts) inside the block.

    A signal mask is inherited by new threads and kept across ``fork`` and ``exec``: the local
    cluster's event-loop thread, started inside the block, keeps SIGINT blocked for good, and so
    does every worker process it spawns (then or later, a restarted worker too), from its first
    instruction on. A terminal's Ctrl-C reaches every process of the group, and the workers must
    leave it to this process, which shuts them down. An interrupt that arrives meanwhile is not
    lost: it stays pending and is delivered to this thread as the block ends.
    """
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "pthread_sigmask"):
        yield   # Windows has no signal masks (nor process groups to send Ctrl-C to)
        return
    # multiprocessing starts its resource tracker from the first thread that spawns a process,
    # and then *unblocks* SIGINT in that thread: started here first, it leaves the mask alone
    from multiprocessing import resource_tracker

    resource_tracker.ensure_running()
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def check_scheduler(address: str, timeout: float = 2.0) -> None:
    """Refuse at once a ``tcp://host:port`` scheduler address where nothing listens.

    Dask itself retries a refused connection until its own timeout; this probe answers in at
    most ``timeout`` seconds, before the sweep writes anything.

    Raises
    ------
    UsageError
        If no TCP connection to the address can be opened.
    """
    if not address.startswith("tcp://"):
        return
    host, _, port = address.removeprefix("tcp://").rpartition(":")
    try:
        with socket.create_connection((host.strip("[]"), int(port)), timeout=timeout):
            pass
    except (OSError, ValueError) as error:
        reason = getattr(error, "strerror", None) or str(error) or type(error).__name__
        raise UsageError("scheduler", f"cannot reach a Dask scheduler at {address}: {reason}") from None


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
    KeyboardInterrupt
        On Ctrl-C, after the local cluster's processes are gone.
    """
    if scheduler is None:
        with _local_client(workers) as client:
            yield client
        return
    from distributed import Client

    check_scheduler(scheduler)
    try:
        with interrupt.deferred_interrupt():
            client = Client(scheduler, timeout="10s")
    except (OSError, TimeoutError) as error:
        raise UsageError("scheduler", f"cannot reach a Dask scheduler at {scheduler}: {error}") from None
    interrupted = False
    try:
        with interrupt.deferred_interrupt():
            try:
                client.wait_for_workers(1, timeout=30)
            except TimeoutError:
                raise UsageError("scheduler", f"the scheduler at {scheduler} has no worker (waited 30 s)") from None
        yield client
    except KeyboardInterrupt:
        interrupted = True
        quiet_shutdown()
        raise
    finally:
        with interrupt.deferred_interrupt():
            client.close(timeout=2 if interrupted else 10)


@contextmanager
def _local_client(workers: int) -> Iterator[Client]:
    """A client on a new local cluster, closed without a word on every way out (see dask_client)."""
    from distributed import Client, LocalCluster

    cluster: LocalCluster | None = None
    client: Client | None = None
    interrupted = False
    try:
        # No KeyboardInterrupt inside Dask's blocking calls (see execute): SIGINT sets a flag,
        # raised as the block ends; while the cluster starts it is held back (sigint_blocked).
        with interrupt.deferred_interrupt():
            with sigint_blocked():
                # the scheduler's HTTP server (health, metrics) on a free port: no "Port 8787 is
                # already in use" warning when another Dask cluster runs on this machine
                cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                                       dashboard_address=None, scheduler_kwargs={"dashboard_address": "127.0.0.1:0"},
                                       silence_logs=logging.ERROR)
            client = Client(cluster)
        yield client
    except KeyboardInterrupt:
        interrupted = True
        raise
    finally:
        _close_local(cluster, client, interrupted)


def _close_local(cluster: Any, client: Any, interrupted: bool) -> None:
    """Close a local cluster and its client; after an interrupt, at once and without a word.

    At a normal end the workers' loggers are silenced first: a worker whose heartbeat meets
    the closing scheduler logs a ``CommClosedError`` traceback, noise at the end of a sweep.
    After an interrupt the worker processes are killed first (their nannies told not to
    restart them), then the cluster closed with short timeouts and its errors ignored.
    """
    if cluster is None:
        return
    with interrupt.deferred_interrupt():  # a second Ctrl-C while closing: the same one line
        if interrupted:
            _abandon(cluster, client)
            return
        if client is not None:
            try:
                client.run(quiet_shutdown)
            except Exception:  # noqa: BLE001 -- a worker already gone has nothing to log
                pass
        quiet_shutdown()
        if client is not None:
            client.close(timeout=10)
        cluster.close(timeout=30)


def _abandon(cluster: Any, client: Any) -> None:
    """The interrupted path of :func:`_close_local`."""
    from distributed.core import Status

    quiet_shutdown()
    for nanny in list(getattr(cluster, "workers", {}).values()):
        nanny.status = Status.closing_gracefully  # a worker that exits now is not restarted
    stop_worker_processes(grace=0.5)
    for close in (lambda: client is not None and client.close(timeout=1), lambda: cluster.close(timeout=2)):
        try:
            close()
        except Exception:  # noqa: BLE001 -- the user asked to stop: what is left is killed below
            pass
    stop_worker_processes(grace=0.5)


def quiet_shutdown() -> None:
    """Silence Dask's loggers in this process: closing a cluster logs only noise."""
    for name in ("distributed", "tornado", "asyncio"):
        logging.getLogger(name).setLevel(logging.CRITICAL + 1)


def stop_worker_processes(grace: float = 1.0) -> None:
    """Terminate (then kill) this process's worker processes: a local cluster's after an interrupt.

    Only the processes ``multiprocessing`` spawned to run code (its resource tracker, which
    ignores SIGTERM, ends by itself with this process; killed, it would be relaunched with a
    warning).
    """
    import psutil

    children = []
    for child in psutil.Process().children(recursive=True):
        try:
            if "--multiprocessing-fork" in child.cmdline():
                children.append(child)
        except psutil.Error:
            pass
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


def task_size(runs: int, threads: int, run_seconds: float) -> int:
    """Runs per task: about :data:`TASK_SECONDS` of work, yet at least two tasks per worker thread.

    A Dask task costs the scheduler and the client about a millisecond whatever it does
    (``pendulum-fmu bench sweep`` measures it with empty tasks): one run of 1 ms per task
    spends as much on scheduling as on running, and 16 workers then wait on the scheduler.
    Tasks of 0.1 s make that cost about 1 % of the work; with few runs, smaller tasks keep
    every thread busy (two tasks per thread let the quick ones even out the slow).

    Parameters
    ----------
    runs : int
        Runs to deal out.
    threads : int
        Worker threads.
    run_seconds : float
        The cost of one run, measured or estimated.

    Returns
    -------
    int
        At least 1.
    """
    by_cost = math.ceil(TASK_SECONDS / max(run_seconds, 1e-6))
    by_balance = math.ceil(runs / (TASKS_PER_THREAD * max(threads, 1)))
    return max(1, min(by_cost, by_balance))


def batches(points: Sequence[SweepPoint], threads: int, batch_size: int | None = None,
            run_seconds: float | None = None) -> list[list[SweepPoint]]:
    """Split points into tasks of about equal cost, sized by :func:`task_size`.

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
        Runs per task instead of the sized one.
    run_seconds : float, optional
        The cost of one run (default: the estimate of :func:`pendulum_fmu.sizing.sweep_run_seconds`
        for the first point).

    Returns
    -------
    list of list of SweepPoint
        Every point exactly once; the tasks' sizes differ by at most one.
    """
    if not points:
        return []
    if batch_size is None:
        cost = run_seconds if run_seconds is not None else estimated_run_seconds(points[0])
        batch_size = task_size(len(points), threads, cost)
    tasks = math.ceil(len(points) / batch_size)
    return [list(points[i::tasks]) for i in range(tasks)]


def estimated_run_seconds(point: SweepPoint) -> float:
    """The sizing estimate of one run of ``point`` (before any run was measured)."""
    from pendulum_fmu.sizing import sweep_run_seconds

    return sweep_run_seconds(math.ceil(point.periods * point.points_per_period) + 1)


def measured_run_seconds(client: Client, data: Any, points: Sequence[SweepPoint]) -> float:
    """Load the FMU on every worker and time there one run of the sweep's middle point.

    A run estimated longer than :data:`TASK_SECONDS` is not timed (it is a task of its own
    anyway); the estimate is returned for it, and when every sample run failed.
    """
    from pendulum_fmu.sweep.worker import warm

    estimate = estimated_run_seconds(points[len(points) // 2]) if points else 0.0
    sample = points[len(points) // 2] if points and estimate < TASK_SECONDS else None
    times = sorted(seconds for _, seconds in client.run(warm, data, sample).values() if seconds > 0)
    return times[len(times) // 2] if times else estimate


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
        Runs per task (default: sized by the cost of a run measured on the workers, :func:`task_size`).

    Returns
    -------
    float
        Seconds from the first submission to the last result.
    """
    from distributed import as_completed
    from tqdm import tqdm

    from pendulum_fmu.sweep.worker import run_points

    data = fmu.read_bytes()
    # Ctrl-C only sets a flag (deferred_interrupt) and the loop below raises it between results:
    # a KeyboardInterrupt raised inside one of the client's blocking calls breaks Dask's own
    # clean-up (distributed 2026.8 then logs a NameError traceback from its event loop thread).
    with interrupt.deferred_interrupt():
        # every worker loads the FMU now, not inside the timed first task, and times one run
        run_seconds = measured_run_seconds(client, data, points)
        # A key of its own (hash=False): a second sweep on the same client must not reuse the key
        # of the first one's data, which the scheduler may be releasing at that moment.
        shared = client.scatter(data, broadcast=True, hash=False)
        interrupt.check()
        start = time.perf_counter()
        futures = [client.submit(run_points, shared, batch, pure=False)
                   for batch in batches(points, worker_threads(client), batch_size, run_seconds)]
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
