"""A disk cache for slow, deterministic reference computations of the tests (mpmath's odefun).

The references stay independent of the code under test; only their cost is paid once. A
value is stored as text (mpmath numbers at full working precision, floats by repr) under
``build/test-cache/`` (``$PENDULUM_TEST_CACHE`` overrides), keyed by the name of the
computation, its inputs and the mpmath version, so a changed input or library computes anew.
Deleting ``build/`` empties it.
"""

from __future__ import annotations

import hashlib
import json
import os
from collections.abc import Callable
from pathlib import Path

import mpmath

CACHE_DIR = Path(os.environ.get("PENDULUM_TEST_CACHE") or Path(__file__).resolve().parents[2] / "build" / "test-cache")


def cached(name: str, key: object, compute: Callable[[], list[list[str]]]) -> list[list[str]]:
    """``compute()`` once per (name, key, mpmath version); later calls read the stored result.

    Parameters
    ----------
    name : str
        What is computed (part of the file name).
    key : object
        Its inputs; ``repr(key)`` must determine the result.
    compute : callable
        Returns lists of strings (numbers as text at full precision).

    Returns
    -------
    list of list of str
        The computed or stored result.
    """
    digest = hashlib.sha256(repr((name, key, mpmath.__version__)).encode()).hexdigest()[:24]
    path = CACHE_DIR / f"{name}-{digest}.json"
    if path.is_file():
        return json.loads(path.read_text())
    result = compute()
    CACHE_DIR.mkdir(parents=True, exist_ok=True)
    temporary = path.with_suffix(f".{os.getpid()}.tmp")
    temporary.write_text(json.dumps(result))
    temporary.replace(path)
    return result
