"""A sweep's local workers leave Ctrl-C to the command: SIGINT blocked in every
worker from its start, and the command's own handler never set in a spawned process."""

from __future__ import annotations

import signal
import subprocess
import sys
from pathlib import Path

import pytest

from pendulum_fmu.sweep.cluster import dask_client, sigint_blocked

pytestmark = pytest.mark.skipif(not hasattr(signal, "pthread_sigmask"), reason="no signal masks on this platform")


def sigint_state() -> tuple[bool, str]:
    """In a worker: is SIGINT blocked, and which handler is set."""
    blocked = signal.SIGINT in signal.pthread_sigmask(signal.SIG_BLOCK, [])
    handler = signal.getsignal(signal.SIGINT)
    return blocked, getattr(handler, "__name__", str(handler))


def test_local_workers_start_with_sigint_blocked() -> None:
    with dask_client(None, 2) as client:
        states = list(client.run(sigint_state).values())
    assert len(states) == 2 and all(blocked for blocked, _ in states), states
    assert all(handler != "_sticky" for _, handler in states), states
    assert signal.SIGINT not in signal.pthread_sigmask(signal.SIG_BLOCK, [])   # the caller's mask is back


def test_the_block_holds_an_interrupt_and_delivers_it_after() -> None:
    caught: list[int] = []
    previous = signal.signal(signal.SIGINT, lambda signum, frame: caught.append(signum))
    try:
        with sigint_blocked():
            signal.raise_signal(signal.SIGINT)
            assert caught == []
        assert caught == [signal.SIGINT]
    finally:
        signal.signal(signal.SIGINT, previous)


CHILD = """
import multiprocessing, signal, sys
import pendulum_fmu.cli  # sets the command's SIGINT handler, as the console script's import does

def handler_name(_):
    import pendulum_fmu.cli  # what a spawned worker does: import the command's main module again
    handler = signal.getsignal(signal.SIGINT)
    return "SIG_IGN" if handler is signal.SIG_IGN else getattr(handler, "__name__", repr(handler))

if __name__ == "__main__":
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        print(handler_name(0), pool.map(handler_name, [0])[0])
"""


def test_the_commands_handler_is_never_set_in_a_spawned_process(tmp_path: Path) -> None:
    script = tmp_path / "child.py"
    script.write_text(CHILD)
    done = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["_sticky", "SIG_IGN"]


LATE = """
import os, signal, sys
import pendulum_fmu.cli  # the command's handler, its quiet unraisable hook and exit hook
from pendulum_fmu.interrupt import exit_quietly_on_interrupt

class Finalized:
    def __del__(self):
        raise KeyboardInterrupt  # what Ctrl-C during a garbage collector's callback does

Finalized()  # collected at once: 'Exception ignored in' would be printed without the hook
print("work done", flush=True)
if sys.argv[1] == "late":
    exit_quietly_on_interrupt("pendulum-fmu x: interrupted\\n")
    os.kill(os.getpid(), signal.SIGINT)  # after the work, while the program ends
"""


@pytest.mark.parametrize("when", ["late", "never"])
def test_an_interrupt_as_the_command_ends_is_one_line_and_130(tmp_path: Path, when: str) -> None:
    script = tmp_path / "late.py"
    script.write_text(LATE)
    done = subprocess.run([sys.executable, str(script), when], capture_output=True, text=True, timeout=120)
    assert done.stdout == "work done\n"
    if when == "late":
        assert (done.returncode, done.stderr) == (130, "pendulum-fmu x: interrupted\n")
    else:
        assert (done.returncode, done.stderr) == (0, "")
