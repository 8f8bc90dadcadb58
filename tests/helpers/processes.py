"""Stopping the processes a test started (the Dask schedulers and workers of the sweep tests)."""

from __future__ import annotations

import subprocess


def stop(processes: list[subprocess.Popen[bytes]]) -> None:
    """Terminate the processes (kill what is left after 20 s)."""
    for process in processes:
        if process.poll() is None:
            process.terminate()
    for process in processes:
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
