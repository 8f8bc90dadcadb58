"""The ``pendulum-fmu`` command: one module per subcommand (argument parsing and printing only)."""

from pendulum_fmu.cli.main import main

__all__ = ["main"]
