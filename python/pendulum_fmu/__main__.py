"""``python -m pendulum_fmu``: the command line."""

from .cli import main

raise SystemExit(main())
