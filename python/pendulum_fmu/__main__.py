"""``python -m pendulum_fmu``: the command line."""

from pendulum_fmu.cli.main import main

raise SystemExit(main())
