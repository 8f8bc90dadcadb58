"""The cross-check's verdict file: the empty ``passed``, ``failed`` or ``rejected`` an importer
publishes beside its result (the cross-check rules, 9.2.3)."""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pendulum_fmu.judge.verdict import Verdict
from pendulum_fmu.output.atomic import write_whole

Outcome = Literal["passed", "failed", "rejected"]
OUTCOMES: tuple[Outcome, ...] = ("passed", "failed", "rejected")
"""The files an importer publishes in its cross-check result folder (the cross-check rules,
9.2.3): one of them, empty; none at all counts as ``failed``."""


def outcome(verdict: Verdict | None) -> Outcome:
    """``passed`` or ``failed`` for a verdict; ``rejected`` for None, a result that could not be read."""
    if verdict is None:
        return "rejected"
    return "passed" if verdict.passed else "failed"


def write_verdict_file(folder: Path, result: Outcome) -> Path:
    """Write the cross-check verdict file ``folder/<result>``, and nothing else.

    The file is empty, as the cross-check repository's are, and written whole
    (:func:`pendulum_fmu.output.atomic.write_whole`); then the other two verdict files, left by
    an earlier run, are removed, so the folder states one verdict. The folder is created when
    missing.

    Returns
    -------
    Path
        The file written.
    """
    if result not in OUTCOMES:
        raise ValueError(f"a cross-check verdict is one of {', '.join(OUTCOMES)}, not {result!r}")
    folder.mkdir(parents=True, exist_ok=True)
    written = write_whole(folder / result, lambda path: path.write_bytes(b""))
    for other in OUTCOMES:
        if other != result:
            (folder / other).unlink(missing_ok=True)
    return written
