"""The ``pendulum-fmu`` command: one module per subcommand (argument parsing and printing only)."""

import sys

from pendulum_fmu.interrupt import default_dispositions

default_dispositions()  # before the heavy imports below: an early Ctrl-C must not be lost in them
try:
    from pendulum_fmu.cli.main import main
except KeyboardInterrupt:  # Ctrl-C while the command starts: one line, as later
    sys.stderr.write("\npendulum-fmu: interrupted\n")
    raise SystemExit(130) from None

__all__ = ["main"]
