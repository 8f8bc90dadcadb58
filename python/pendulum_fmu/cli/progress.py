"""The library's progress lines on stderr: what the command says while it works.

Library code does not print: it logs one INFO line where a person waiting would want to know
what is going on (a CMake build starting, a long run's estimate, an animation's frames, a sweep
resuming). The command shows those records on stderr as they are, one line each, flushed.
"""

from __future__ import annotations

import logging
import sys
from collections.abc import Iterator
from contextlib import contextmanager

LOGGER = "pendulum_fmu"
"""The package's logger: every module logs under it (``logging.getLogger(__name__)``)."""


class _Stderr(logging.Handler):
    """Each record's message on the ``sys.stderr`` of the moment (a test's capture included)."""

    def emit(self, record: logging.LogRecord) -> None:
        try:
            print(self.format(record), file=sys.stderr, flush=True)
        except Exception:  # noqa: BLE001 -- logging's own rule: a handler never raises
            self.handleError(record)


@contextmanager
def progress_on_stderr() -> Iterator[None]:
    """While the command runs, print the package's INFO records (and worse) on stderr, each once.

    The logger is as it was afterwards: a program that calls :func:`pendulum_fmu.cli.main`
    and then the library gets no lines on stderr from the library.
    """
    logger = logging.getLogger(LOGGER)
    handler, level, propagate = _Stderr(), logger.level, logger.propagate
    logger.addHandler(handler)
    logger.setLevel(logging.INFO)
    logger.propagate = False  # the line once, whatever the root logger does
    try:
        yield
    finally:
        logger.removeHandler(handler)
        logger.setLevel(level)
        logger.propagate = propagate
