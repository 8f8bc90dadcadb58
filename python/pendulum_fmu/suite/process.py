"""Run one command with a time limit and keep the tail of what it said."""

from __future__ import annotations

import os
import signal
import subprocess
import time
from dataclasses import dataclass

TAIL_LINES = 15
"""How many of a command's last lines the reports keep."""


@dataclass(frozen=True)
class Finished:
    """What a command left: its exit status (None when killed at the time limit), its tail, its time."""

    returncode: int | None
    tail: str
    seconds: float

    @property
    def timed_out(self) -> bool:
        """True when the command was killed at the time limit."""
        return self.returncode is None

    def describe(self) -> str:
        """``exit status 3``, ``killed by signal 11 (SIGSEGV)`` or ``no answer within 30 s``."""
        if self.returncode is None:
            return f"no answer within {self.seconds:.3g} s: killed"
        if self.returncode < 0:
            return f"killed by signal {-self.returncode} ({signal.Signals(-self.returncode).name})"
        return f"exit status {self.returncode}"


def run_command(command: list[str] | str, timeout: float, env: dict[str, str] | None = None) -> Finished:
    """Run ``command`` (words, or a line for ``bash -c``) in its own process group; kill the group at ``timeout``."""
    began = time.perf_counter()
    words = ["bash", "-c", command] if isinstance(command, str) else command
    process = subprocess.Popen(words, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, env=env, start_new_session=True)
    try:
        said, _ = process.communicate(timeout=timeout)
        code: int | None = process.returncode
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        said, _ = process.communicate()
        code = None
    text = said.decode(errors="replace").rstrip()
    return Finished(code, "\n".join(text.splitlines()[-TAIL_LINES:]), time.perf_counter() - began)
