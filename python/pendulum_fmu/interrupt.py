"""Ctrl-C (SIGINT) that is never lost inside a call into the FMU.

Python runs a signal handler between two bytecodes of the main thread. During an FMU run
those bytecodes are often inside a ctypes callback (the FMU's logger, or fmpy's CVODE
right-hand side called back from C): a ``KeyboardInterrupt`` raised there cannot cross the
C frames, so ctypes prints "Exception ignored on calling ctypes callback" and drops it.
The interrupt is then lost, or the solver sees a failed callback and reports a misleading
error.

:func:`deferred_interrupt` therefore replaces, for the duration of a run, the default
SIGINT handler by one that only sets a flag; the run's loops look at the flag between steps
(:func:`pending`, :func:`check`) and the flag becomes a ``KeyboardInterrupt`` as soon as
the run leaves the block, whatever else the run raised on the way.
"""

from __future__ import annotations

import _signal
import atexit
import os
import signal
import sys
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from types import FrameType
from typing import Any

_flag: list[bool] = [False]
"""``[True]`` once SIGINT arrived inside :func:`deferred_interrupt` (a list: cheap to test in a loop)."""


def _note(signum: int, frame: FrameType | None) -> None:
    """The SIGINT handler inside :func:`deferred_interrupt`: remember, raise nothing."""
    _flag[0] = True


def _sticky(signum: int, frame: FrameType | None) -> None:
    """The command's SIGINT handler outside runs: raise ``KeyboardInterrupt`` and remember it.

    Should a library swallow the exception (a bare ``except:`` while a module is imported),
    the flag stays set and the next run (:func:`deferred_interrupt`) or :func:`check`
    raises it again: the interrupt is not lost.
    """
    _flag[0] = True
    raise KeyboardInterrupt


def flag() -> list[bool]:
    """The flag itself, ``[bool]``, for a loop that tests ``flag[0]`` between steps."""
    return _flag


def pending() -> bool:
    """True when SIGINT arrived inside :func:`deferred_interrupt` and was not raised yet."""
    return _flag[0]


def check() -> None:
    """Raise ``KeyboardInterrupt`` now if SIGINT arrived (call it between steps, never in a callback)."""
    if _flag[0]:
        _flag[0] = False
        raise KeyboardInterrupt


def forget() -> None:
    """Clear the flag: the interrupt it stands for has been reported."""
    _flag[0] = False


@contextmanager
def deferred_interrupt() -> Iterator[None]:
    """SIGINT inside the block sets a flag; leaving the block raises it as ``KeyboardInterrupt``.

    Only in the main thread and only where SIGINT raises ``KeyboardInterrupt`` (Python's
    default handler): a worker thread, a process that ignores SIGINT on purpose (a sweep's
    worker) or a handler of the caller's own are left alone. Nested blocks are one block.

    Raises
    ------
    KeyboardInterrupt
        On leaving the block when SIGINT arrived in it, in place of any exception the body
        raised (a solver that stopped because of the interrupt is not a failure); a
        ``KeyboardInterrupt`` the body raises itself on seeing the flag (one that carries the
        finished part of a run) passes unchanged.
    """
    # The C module's calls: signal.signal and signal.getsignal convert every handler they return
    # to an enum member, which for a Python function raises and catches a ValueError; four such
    # calls were 20 us of a 0.55 ms run (bench speed).
    previous = _signal.getsignal(signal.SIGINT)
    if threading.current_thread() is not threading.main_thread() \
            or (previous is not signal.default_int_handler and previous is not _sticky):
        yield
        return
    check()  # an interrupt that arrived before, and was swallowed on its way
    _signal.signal(signal.SIGINT, _note)
    try:
        yield
    except KeyboardInterrupt:  # raised by the body itself on seeing the flag (it may carry a partial result)
        _signal.signal(signal.SIGINT, previous)
        _flag[0] = False
        raise
    except BaseException:
        _signal.signal(signal.SIGINT, previous)
        if _flag[0]:
            _flag[0] = False
            raise KeyboardInterrupt from None
        raise
    _signal.signal(signal.SIGINT, previous)
    check()


def default_dispositions() -> None:
    """Make SIGINT raise ``KeyboardInterrupt`` in this process, whatever it inherited.

    A program started in the background by a non-interactive shell inherits SIGINT as
    ignored, and Python then installs no handler: such a command could not be stopped with
    Ctrl-C or ``kill -INT``. The handler installed also remembers the interrupt (see
    ``_sticky``). Called by the command line as soon as its package is imported, before
    the heavy imports, and again by ``main`` (main thread only).
    """
    if threading.current_thread() is not threading.main_thread():
        return
    if spawned_child():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        return
    signal.signal(signal.SIGINT, _sticky)
    if not getattr(sys.unraisablehook, "_pendulum_fmu", False):
        sys.unraisablehook = _quiet_unraisable(sys.unraisablehook)
        atexit.register(_leave)  # first registered, last run (see exit_quietly_on_interrupt)


def _quiet_unraisable(previous: Callable[[Any], object]) -> Callable[[Any], object]:
    """``sys.unraisablehook`` that says nothing of a ``KeyboardInterrupt``.

    Ctrl-C can arrive while the garbage collector runs a weak reference's callback or a
    ``__del__``: Python cannot raise the ``KeyboardInterrupt`` there and printed "Exception
    ignored in: ..." with its traceback. ``_sticky`` has set the flag, which the command
    raises at its next check (at the latest as its subcommand returns): one line, exit 130.
    Any other error goes to the hook it replaces.
    """
    def hook(unraisable: Any) -> None:
        if not isinstance(unraisable.exc_value, KeyboardInterrupt):
            previous(unraisable)

    hook._pendulum_fmu = True  # type: ignore[attr-defined]
    return hook


def exit_quietly_on_interrupt(line: str) -> None:
    """From now on SIGINT only sets the flag, and the program exits with 130 and ``line`` if it is set.

    For the command after its work is done: an interrupt while the interpreter shuts down
    (threads joined, modules torn down) would raise where nothing can catch it. The exit
    hook, registered when the command set its handler and so run after every later one
    (the FMU runners' clean-up included), writes ``line`` and ends the process with 130:
    such an interrupt is neither lost nor a traceback. Main thread only.
    """
    if threading.current_thread() is not threading.main_thread():
        return
    _signal.signal(signal.SIGINT, _note)
    _last_words[:] = [line]


_last_words: list[str] = []
"""The line :func:`_leave` writes; empty until :func:`exit_quietly_on_interrupt`."""


def _leave() -> None:
    """The exit hook of :func:`exit_quietly_on_interrupt`."""
    if _last_words and _flag[0]:
        sys.stdout.flush()
        sys.stderr.write(_last_words[0])
        sys.stderr.flush()
        os._exit(130)


def spawned_child() -> bool:
    """True in a process started by ``multiprocessing`` (a local Dask worker), false in the command.

    Such a process imports the command's main module again, the console script's too (its
    ``import pendulum_fmu.cli`` calls :func:`default_dispositions`): the command's handler must
    not be set there. A sweep's worker leaves Ctrl-C to the command, which shuts it down: a
    ``KeyboardInterrupt`` in a starting worker made the cluster fail with "Nanny failed to
    start", and in a running one printed its traceback.
    """
    return "--multiprocessing-fork" in getattr(sys, "orig_argv", sys.argv)
